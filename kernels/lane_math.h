// The lane maths of kernels/lane_math-inl.h exported per target, so tests can
// check every function lane by lane against the C library and Eigen.
#pragma once

#include "kernels/body_lanes.h"
#include "kernels/kernel_table.h"
#include "manyworlds/lanes.h"

namespace manyworlds {

struct LaneMathKernels {
  TargetInfo target;
  void (*sin_cos)(const LaneArray& x, LaneArray& sin, LaneArray& cos);
  void (*cross_dot)(const Vec3Lanes& a, const Vec3Lanes& b, Vec3Lanes& cross,
                    LaneArray& dot);
  void (*quat_multiply)(const QuatLanes& a, const QuatLanes& b, QuatLanes& product);
  void (*quat_rotate)(const QuatLanes& q, const Vec3Lanes& v, Vec3Lanes& rotated,
                      Vec3Lanes& inverse_rotated);
  void (*quat_normalize)(const QuatLanes& q, QuatLanes& normalized);
  void (*quat_from_axis_angle)(const Vec3Lanes& unit_axis, const LaneArray& angle,
                               QuatLanes& q);
  void (*add_rotation_step)(QuatLanes& q, const Vec3Lanes& theta);
  void (*world_inverse_inertia)(const BodyLanes& body, Sym33Lanes& matrix);
  void (*inverse_inertia_times)(const BodyLanes& body, const Vec3Lanes& v,
                                Vec3Lanes& product);
  void (*inverse_sym22)(const Sym22Lanes& k, Sym22Lanes& inverse,
                        LaneFlags& invertible);
  void (*inverse33)(const Mat33Lanes& k, Mat33Lanes& inverse, LaneFlags& invertible);
  // Angles (swing-twist): atan, atan2(y, x), CenterAngleAroundZero.
  void (*atan)(const LaneArray& x, LaneArray& angle);
  void (*atan2)(const LaneArray& y, const LaneArray& x, LaneArray& angle);
  void (*center_angle_around_zero)(const LaneArray& x, LaneArray& centered);
  // Jolt's GetTwist about principal axis 0, 1 or 2 (swing-twist and six-DOF drives).
  void (*twist_about_axis)(const QuatLanes& q, int axis, QuatLanes& twist);
};

MANYWORLDS_DECLARE_KERNEL_TABLE(LaneMathKernels)

}  // namespace manyworlds
