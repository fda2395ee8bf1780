// Joint coordinates, the observations RL tasks are made of, from the body
// states and the constraint's frames in a block. Two implementations of the
// same formulas: JointCoordinateKernels, SIMD in float over a block's lanes
// (joint_coordinate_kernels.cc, what Batch reads), and JointCoordinatesOfLane,
// one lane in double (the reference the tests hold every target to, and the
// path's closest-point search, which the kernels call per lane):
//
//   hinge        angle (rad, (-pi, pi], Jolt's theta), unwrapped_angle (rad,
//                continuous over turns: theta + 2 pi turns, turns counted at
//                every substep's setup), angular_velocity ((w2 - w1) . a1, rad/s)
//   slider       position (d = u . s, m), velocity (d/dt d, m/s)
//   distance     distance (|p2 - p1|, m), velocity (its rate, m/s)
//   pulley       length (|p1 - f1| + r |p2 - f2|, m)
//   cone         cone_angle (between the twist axes, rad)
//   swing-twist  twist, swing_y, swing_z (rad, Jolt's decomposition of body
//                2's constraint frame in body 1's), angular_velocity_x/y/z
//                ((w2 - w1) in body 1's constraint frame, rad/s)
//   six-DOF      translation_x/y/z (u in body 1's constraint frame, m),
//                twist, swing_y, swing_z (rad), velocity_x/y/z (rates of the
//                translations, m/s), angular_velocity_x/y/z (rad/s)
//   path         fraction (the closest point's path fraction)
//   point, fixed, gear, rack-and-pinion: none (their bodies' poses, or the
//                hinges and sliders they couple, say everything)
//
// Motor forces: the accumulated impulse of each motor or friction row in the
// last substep divided by the substep's dt (N, or N m for angular rows): one
// for a hinge, slider or path drive, three for swing-twist rotation drives
// (twist, swing_y, swing_z), six for six-DOF (translation X, Y, Z, then
// rotation), 0 where an axis has no drive.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "batch/plan.h"
#include "kernels/kernel_table.h"

namespace manyworlds {

std::size_t JointCoordinateCount(const ConstraintPlan& c);
// JointCoordinateCount(c) names.
std::vector<std::string> JointCoordinateNames(const ConstraintPlan& c);
// Writes JointCoordinateNames(c).size() floats.
void JointCoordinatesOfLane(const StepPlan& plan, const std::byte* block, std::size_t lane,
                            std::size_t constraint, float* out);

struct JointCoordinateKernels {
  TargetInfo target;
  // The JointCoordinateCount(c) floats of constraint `constraint` for lanes
  // [0, lanes) of the block, lane l's at out + l * row_stride.
  void (*read_block)(const StepPlan& plan, const std::byte* block, std::size_t constraint,
                     std::size_t lanes, std::size_t row_stride, float* out);
};

MANYWORLDS_DECLARE_KERNEL_TABLE(JointCoordinateKernels)

std::size_t MotorForceCount(const ConstraintPlan& c);
// Writes MotorForceCount(c) floats; `substep_dt` 0 (no step yet) gives zeros.
void MotorForcesOfLane(const StepPlan& plan, const std::byte* block, std::size_t lane,
                       std::size_t constraint, float substep_dt, float* out);

}  // namespace manyworlds
