// Position error of every constraint of one world, for accuracy reports:
// computed on the host, in double, from the world's state and the
// constraint's per-world parameters in the block.
//
//   point      |p2 - p1|                                          (m)
//   fixed      max(|p2 - p1|, rotation angle of q2 r0^-1 q1*)      (m, rad)
//   hinge      max(|p2 - p1|, angle between the hinge axes,
//                  limit violation)                                (m, rad)
//   slider     max(|u - (u.s) s|, rotation angle, limit violation) (m, rad)
//   gear       |fold(theta1 + r theta2)| with the two hinges' angles (rad)
//   rack       |fold(theta - r d)| with the hinge angle and slider position
// (gear and rack only when the scene names their hinges / slider).
#pragma once

#include <cstddef>

#include "batch/plan.h"

namespace manyworlds {

// Largest error of any constraint in lane `lane` of `block`; mixes metres and
// radians as documented above.
float MaxConstraintErrorOfLane(const StepPlan& plan, const std::byte* block, std::size_t lane);

// The error of one constraint.
double ConstraintErrorOfLane(const StepPlan& plan, const std::byte* block, std::size_t lane,
                             std::size_t constraint);

}  // namespace manyworlds
