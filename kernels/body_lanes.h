// One body of one block of worlds, field by field ([field][lane]).
#pragma once

#include "manyworlds/lanes.h"
#include "manyworlds/motion_type.h"

namespace manyworlds {

// Everything the solver reads or writes of a body, for kLaneWidth worlds.
// Mass properties live next to the state so that per-world randomisation
// (domain randomisation) costs nothing extra.
struct BodyLanes {
  Vec3Lanes position;          // centre of mass, world space
  QuatLanes rotation;          // body to world, unit
  Vec3Lanes linear_velocity;   // world space
  Vec3Lanes angular_velocity;  // world space
  LaneArray inv_mass;
  Vec3Lanes inv_inertia_diagonal;  // principal inverse inertia
  QuatLanes inertia_rotation;      // principal axes to body space
};

// The two bodies a part acts on in one block, with their motion types (the
// same in every world of the batch, so kernels branch on them).
struct BodyPair {
  BodyLanes* body1;
  MotionType motion1;
  BodyLanes* body2;
  MotionType motion2;
};

}  // namespace manyworlds
