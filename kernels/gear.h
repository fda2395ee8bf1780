// Storage of the gear part (rotation of body 1 <-> rotation of body 2) for one
// block of worlds. The maths is in gear-inl.h.
#pragma once

#include "kernels/body_lanes.h"
#include "kernels/kernel_table.h"
#include "manyworlds/lanes.h"

namespace manyworlds {

// Per-step inputs from the owning constraint.
struct GearGeometry {
  Vec3Lanes hinge_axis1;  // a: gear 1's rotation axis, world, unit
  Vec3Lanes hinge_axis2;  // b: gear 2's rotation axis, world, unit
  LaneArray ratio;        // r: C = theta1 + r theta2 (Jolt: teeth2 / teeth1)
};

struct GearLanes {
  Vec3Lanes inv_i1_hinge_axis1;        // I1^-1 a
  Vec3Lanes ratio_inv_i2_hinge_axis2;  // r I2^-1 b: body 2's share of J^T, with r
  LaneArray effective_mass;            // 1 / K; zero when deactivated

  struct Persistent {
    LaneArray total_lambda;
  } persistent;
};

// The part's kernels on one target; each call processes one block.
struct GearKernels {
  TargetInfo target;
  void (*calculate_properties)(const BodyPair&, const GearGeometry&, GearLanes&);
  void (*warm_start)(const BodyPair&, GearLanes&, float warm_start_ratio);
  bool (*solve_velocity)(const BodyPair&, const GearGeometry&, GearLanes&);
  // `error` = theta1 + r theta2 per lane, wrapped by the caller.
  bool (*solve_position)(const BodyPair&, const LaneArray& error, const GearLanes&,
                         float baumgarte);
  void (*deactivate)(GearLanes&, const LaneFlags& lanes);
  void (*is_active)(const GearLanes&, LaneFlags& active);
};

MANYWORLDS_DECLARE_KERNEL_TABLE(GearKernels)

}  // namespace manyworlds
