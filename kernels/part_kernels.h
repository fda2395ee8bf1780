// The SIMD kernels of every constraint part, one table per Highway target.
//
// Each entry processes one block of kLaneWidth worlds. The table of the best
// target this CPU supports is chosen at run time (DispatchedKernels); tests and
// benchmarks can also fetch the table of any compiled target the CPU supports,
// e.g. Highway's scalar target as the SIMD-efficiency baseline.
#pragma once

#include <cstdint>
#include <vector>

#include "kernels/body_lanes.h"
#include "kernels/dual_axis.h"
#include "kernels/rack_and_pinion.h"
#include "manyworlds/lanes.h"

namespace manyworlds {

struct PartKernels {
  std::int64_t target;      // Highway target bit (HWY_AVX2, HWY_SCALAR, ...)
  const char* target_name;  // Highway's name of it
  std::size_t vector_lanes;  // floats per vector on this target

  // ---- DualAxisConstraintPart (spec 2.3)
  void (*dual_axis_calculate_properties)(const BodyPair&, const DualAxisGeometry&,
                                         DualAxisLanes&);
  void (*dual_axis_warm_start)(const BodyPair&, const DualAxisGeometry&,
                               DualAxisLanes&, float warm_start_ratio);
  bool (*dual_axis_solve_velocity)(const BodyPair&, const DualAxisGeometry&,
                                   DualAxisLanes&);
  bool (*dual_axis_solve_position)(const BodyPair&, const DualAxisGeometry&,
                                   const Vec3Lanes& separation,
                                   const DualAxisLanes&, float baumgarte);
  void (*dual_axis_deactivate)(DualAxisLanes&, const LaneFlags& lanes);
  void (*dual_axis_is_active)(const DualAxisLanes&, LaneFlags& active);

  // ---- RackAndPinionConstraintPart (spec 2.9)
  void (*rack_and_pinion_calculate_properties)(const BodyPair&,
                                               const RackAndPinionGeometry&,
                                               RackAndPinionLanes&);
  void (*rack_and_pinion_warm_start)(const BodyPair&, RackAndPinionLanes&,
                                     float warm_start_ratio);
  bool (*rack_and_pinion_solve_velocity)(const BodyPair&,
                                         const RackAndPinionGeometry&,
                                         RackAndPinionLanes&);
  bool (*rack_and_pinion_solve_position)(const BodyPair&, const LaneArray& error,
                                         const RackAndPinionLanes&,
                                         float baumgarte);
  void (*rack_and_pinion_deactivate)(RackAndPinionLanes&, const LaneFlags& lanes);
  void (*rack_and_pinion_is_active)(const RackAndPinionLanes&, LaneFlags& active);

  // ---- Lane maths, exported so tests check it lane by lane against libm/Eigen.
  void (*math_sin_cos)(const LaneArray& x, LaneArray& sin, LaneArray& cos);
  void (*math_cross_dot)(const Vec3Lanes& a, const Vec3Lanes& b,
                         Vec3Lanes& cross, LaneArray& dot);
  void (*math_quat_multiply)(const QuatLanes& a, const QuatLanes& b,
                             QuatLanes& product);
  void (*math_quat_rotate)(const QuatLanes& q, const Vec3Lanes& v,
                           Vec3Lanes& rotated, Vec3Lanes& inverse_rotated);
  void (*math_quat_normalize)(const QuatLanes& q, QuatLanes& normalized);
  void (*math_quat_from_axis_angle)(const Vec3Lanes& unit_axis,
                                    const LaneArray& angle, QuatLanes& q);
  void (*math_add_rotation_step)(QuatLanes& q, const Vec3Lanes& theta);
  void (*math_world_inverse_inertia)(const BodyLanes& body, Sym33Lanes& matrix);
  void (*math_inverse_inertia_times)(const BodyLanes& body, const Vec3Lanes& v,
                                     Vec3Lanes& product);
  void (*math_inverse_sym22)(const Sym22Lanes& k, Sym22Lanes& inverse,
                             LaneFlags& invertible);
  void (*math_inverse33)(const Mat33Lanes& k, Mat33Lanes& inverse,
                         LaneFlags& invertible);
};

// Kernels of the best target this CPU supports (Highway's dynamic dispatch).
const PartKernels& DispatchedKernels();

// Kernels of every compiled target this CPU supports, best first.
const std::vector<const PartKernels*>& SupportedKernels();

// Kernels of one target, or nullptr if it is not compiled or not supported.
const PartKernels* KernelsForTarget(std::int64_t target);

}  // namespace manyworlds
