// The mass-range limit: a remedy for scenes whose masses span more decades
// than Jolt's Gauss-Seidel solver can pass an impulse through
// (docs/stability.md, "Masses spread over many decades").
//
// Each velocity iteration of the solver passes a joint's impulse on to the
// next joint by about the ratio of the two bodies' effective masses, so a
// load hanging from much lighter links is held only after about as many
// iterations as the heaviest-to-lightest mass ratio along the chain; with
// nine decades (mass-range-hanging) no count of substeps or iterations does
// it, and an exact (direct) solve of the linearised joints does not either:
// the light links then turn through more than a radian per step and the
// linearisation breaks. LimitMassRange changes the scene instead, as
// MuJoCo's armature does: it makes the lightest bodies heavier, which is a
// modelling error the user chooses and can measure (it returns what it
// changed; docs/accuracy.md measures how far the load's path moves).
#pragma once

#include <cstddef>
#include <vector>

#include "manyworlds/scene.h"

namespace manyworlds {

// One body whose mass LimitMassRange raised.
struct MassRaise {
  std::size_t body = 0;
  double factor = 1.0;  // new mass / old mass; its inertia got the same factor
};

// Within every group of dynamic bodies that constraints join, raises each
// body lighter than (the group's heaviest mass) / max_ratio to that mass, and
// multiplies its inertia by the same factor: as if its material were denser,
// so its centre of mass, principal axes and shape stay. Static and kinematic
// bodies join no group (they do not pass impulses on: every constraint to
// them is a constraint to the ground), so bodies of different groups never
// change each other; nor do dynamic bodies that allow no translation (their
// inverse mass is 0: to the joints they are the ground too). Returns the
// raised bodies in index order (none when the scene is already within the
// range).
//
// Throws std::invalid_argument naming max_ratio unless it is finite and >= 1.
// Bodies with a mass that is not finite and positive, and constraints with a
// body index out of range, are skipped: Batch refuses them, naming them, when
// the scene is built.
std::vector<MassRaise> LimitMassRange(Scene& scene, float max_ratio);

}  // namespace manyworlds
