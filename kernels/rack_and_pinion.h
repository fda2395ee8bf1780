// Storage of the rack-and-pinion part (pinion rotation <-> rack translation)
// for one block of worlds. The maths is in rack_and_pinion-inl.h.
#pragma once

#include "kernels/body_lanes.h"
#include "kernels/kernel_table.h"
#include "manyworlds/lanes.h"

namespace manyworlds {

// Per-step inputs from the owning constraint.
struct RackAndPinionGeometry {
  Vec3Lanes hinge_axis;   // a: pinion (body 1) rotation axis, world, unit
  Vec3Lanes slider_axis;  // b: rack (body 2) translation axis, world, unit
  LaneArray ratio;        // r: rack travel per radian of pinion rotation^-1
};

struct RackAndPinionLanes {
  Vec3Lanes inv_i1_hinge_axis;       // I1^-1 a
  Vec3Lanes ratio_inv_m2_slider_axis;  // r m2^-1 b
  LaneArray effective_mass;          // 1 / K; zero when deactivated

  struct Persistent {
    LaneArray total_lambda;
  } persistent;
};

// The part's kernels on one target; each call processes one block.
struct RackAndPinionKernels {
  TargetInfo target;
  void (*calculate_properties)(const BodyPair&, const RackAndPinionGeometry&,
                               RackAndPinionLanes&);
  void (*warm_start)(const BodyPair&, RackAndPinionLanes&, float warm_start_ratio);
  bool (*solve_velocity)(const BodyPair&, const RackAndPinionGeometry&,
                         RackAndPinionLanes&);
  // `error` = theta1 - r d2 per lane, wrapped by the caller.
  bool (*solve_position)(const BodyPair&, const LaneArray& error,
                         const RackAndPinionLanes&, float baumgarte);
  void (*deactivate)(RackAndPinionLanes&, const LaneFlags& lanes);
  void (*is_active)(const RackAndPinionLanes&, LaneFlags& active);
};

MANYWORLDS_DECLARE_KERNEL_TABLE(RackAndPinionKernels)

}  // namespace manyworlds
