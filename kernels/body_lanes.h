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
  // Allowed degrees of freedom (Jolt's EAllowedDOFs, spec 4.3), a property of
  // the scene's body, so the same in every lane. dof_restricted is 1 if any
  // world axis is locked, else 0: body_access-inl.h tests lane 0 (a uniform,
  // predictable branch) and only then reads the locks (BodyLockLanes), so
  // unrestricted bodies pay one scalar compare and store no locks.
  LaneArray dof_restricted;
};

// The locks of a body whose DOFs are restricted, stored right after its
// BodyLanes (the plan lays them out for such bodies only; Locks). Locks are
// 1 (locked) or 0 (free) per world axis, so that all-zero lanes are Jolt's
// default body: a lane whose locks are zero comes out bit-identical whether
// or not the masked path runs.
struct BodyLockLanes {
  Vec3Lanes translation_locked;  // linear velocity writes and position steps
  Vec3Lanes rotation_locked;     // rows and columns of the world inverse inertia
};
// Only for a body with dof_restricted set: its locks follow it in the block.
inline const BodyLockLanes& Locks(const BodyLanes& body) {
  return *reinterpret_cast<const BodyLockLanes*>(&body + 1);
}
inline BodyLockLanes& Locks(BodyLanes& body) {
  return *reinterpret_cast<BodyLockLanes*>(&body + 1);
}

// Per dynamic body: what the force step needs besides the state and mass
// properties, per world so that randomising it costs nothing extra.
struct BodyMotionLanes {
  Vec3Lanes force;   // N, world; cleared after every step
  Vec3Lanes torque;  // N m, world; cleared after every step
  LaneArray linear_damping, angular_damping;         // 1/s
  LaneArray max_linear_velocity, max_angular_velocity;  // m/s, rad/s
  LaneArray gravity_factor;
};

// Per block: the health check of each world for the Step being taken (the
// meaning of each flag is WorldHealthBits in manyworlds/batch.h). 1 where the
// condition was seen, 0 elsewhere; cleared at the start of every Step.
struct WorldHealthLanes {
  LaneArray velocity_overflow;  // |v|^2 or |w|^2 overflowed in a force step
  LaneArray non_finite;         // a body's state was NaN or infinite after the Step
  LaneArray out_of_range;       // a body's position was beyond the healthy coordinate
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
