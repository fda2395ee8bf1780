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
#include "manyworlds/batch.h"

namespace manyworlds {

// Largest error of any constraint in lane `lane` of `block`; mixes metres and
// radians as documented above (the larger of the split's two parts).
float MaxConstraintErrorOfLane(const StepPlan& plan, const std::byte* block, std::size_t lane);

// The same split by unit: the largest linear error (m: anchor separations,
// distances off a slider axis or a path, linear limit violations, distance
// and pulley length violations) and the largest angular error (rad: the
// rotation and axis angles, angular limit violations, and the gear and
// rack-and-pinion coupling errors, whose ratio makes them radians), each
// over every constraint of the lane.
ConstraintErrorSplit MaxConstraintErrorSplitOfLane(const StepPlan& plan, const std::byte* block,
                                                  std::size_t lane);

// The error of one constraint: max(linear, angular) of its split.
double ConstraintErrorOfLane(const StepPlan& plan, const std::byte* block, std::size_t lane,
                             std::size_t constraint);
ConstraintErrorSplit ConstraintErrorSplitOfLane(const StepPlan& plan, const std::byte* block,
                                               std::size_t lane, std::size_t constraint);

// Velocity residual |J v| of one constraint's equality rows, from the lane's
// current velocities (m/s for linear rows, rad/s for angular rows; the
// largest of the constraint's groups of rows, as the position error):
//
//   point      |v_p2 - v_p1|, v_p = v + w x r at the anchor
//   fixed      max(|v_p2 - v_p1|, |w2 - w1|)
//   hinge      max(|v_p2 - v_p1|, |(w2 - w1) x a1|)   (a1 the hinge axis)
//   slider     max(|P (v2 + w2 x r2 - v1 - w1 x (r1 + u))|, |w2 - w1|),
//              P = 1 - s s^T removes the free slider axis s
//   gear       |a1 . w1 + r a2 . w2|
//   rack       |a . w1 - r b . v2|   (a the pinion axis, b the rack axis)
//   distance   |d/dt |p2 - p1|| when min = max (a rod), else 0
//   pulley     |dL/dt| when min = max, else 0
//   cone, swing-twist   the anchor rows, |v_p2 - v_p1|
//   six-DOF    max(|w2 - w1| when every rotation is fixed, the slider's rows
//              along the hard fixed translation axes of body 1's frame, or
//              |v_p2 - v_p1| at the fixed anchors when every translation is)
//
// Limit rows, motors, friction and the cone and swing-twist angle limits are
// inequalities or drives, not equalities: a non-zero velocity along them is
// allowed, so they are left out.
double ConstraintVelocityErrorOfLane(const StepPlan& plan, const std::byte* block,
                                     std::size_t lane, std::size_t constraint);

}  // namespace manyworlds
