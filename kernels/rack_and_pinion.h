// Storage of the rack-and-pinion part (pinion rotation <-> rack translation)
// for one block of worlds. The maths is in rack_and_pinion-inl.h.
#pragma once

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

}  // namespace manyworlds
