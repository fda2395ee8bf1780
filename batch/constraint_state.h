// What a constraint carries from one step to the next besides the bodies
// (its accumulated impulses, turn counts, remembered directions), array by
// array in the solver-state layout's order (docs/stepping.md, "Solver state
// of one world"). Batch::GetSolverState / SetSolverState read and write one
// lane through it; the plan lists the arrays a velocity pass writes from it
// (StepPlan::velocity_pass_arrays, StepSettings::velocity_tolerance).
#pragma once

#include <cstddef>

#include "batch/constraint_block.h"
#include "batch/constraint_lanes.h"

namespace manyworlds {

// Calls visit(array, what) for every value of a constraint's solver state in
// the layout's order: the LaneArray holding it in the block, or nullptr for a
// row the constraint does not have (its value is 0). Reads and writes go
// through the same visitor, so the block is writable here; GetSolverState
// only reads through it.
template <class Visit>
void VisitConstraintState(const ConstraintBlock& c, Visit&& visit) {
  const auto one = [&](LaneArray* array, const char* what) { visit(array, what); };
  const auto two = [&](Vec2Lanes& v, const char* what) {
    visit(&v.x, what);
    visit(&v.y, what);
  };
  const auto three = [&](Vec3Lanes& v, const char* what) {
    visit(&v.x, what);
    visit(&v.y, what);
    visit(&v.z, what);
  };
  // Optional rows (allocated only when the scene uses them): motor or
  // friction rows, limits, rotation drives.
  const auto angular_motor = [&]() -> LaneArray* {
    if (!c.plan.has_motor()) return nullptr;
    return &c.Motor<AngularMotorLanes>().part.persistent.total_lambda;
  };
  const auto angular_limit = [&]() -> LaneArray* {
    if (!c.plan.has_limits()) return nullptr;
    return &c.Limit<AngularLimitLanes>().part.persistent.total_lambda;
  };
  const auto linear_motor = [&](std::size_t i) -> LaneArray* {
    if (!c.plan.has_motor()) return nullptr;
    return &(&c.Motor<LinearMotorLanes>())[i].part.persistent.total_lambda;
  };
  const auto linear_limit = [&](std::size_t i) -> LaneArray* {
    if (!c.plan.has_limits()) return nullptr;
    return &(&c.Limit<LinearLimitLanes>())[i].part.persistent.total_lambda;
  };
  const auto rotation_drive = [&](std::size_t i) -> LaneArray* {
    if (!c.plan.has_rotation_drives()) return nullptr;
    RotationDriveLanes& drives = At<RotationDriveLanes>(c.block, c.plan.rotation_drive_offset);
    return &drives.rows[i].part.persistent.total_lambda;
  };
  const auto rotation_drives = [&] {
    for (std::size_t i = 0; i < 3; ++i) one(rotation_drive(i), "rotation drive impulse");
  };
  const auto swing_twist = [&](SwingTwistLanes& part) {
    one(&part.persistent.swing_y_lambda, "swing y impulse");
    one(&part.persistent.swing_z_lambda, "swing z impulse");
    one(&part.persistent.twist_lambda, "twist impulse");
  };
  switch (c.plan.type) {
    case ConstraintType::kPoint: {
      auto& s = c.Main<PointConstraintLanes>();
      three(s.point_state.total_lambda, "point impulse");
      return;
    }
    case ConstraintType::kFixed: {
      auto& s = c.Main<FixedConstraintLanes>();
      three(s.rotation_state.total_lambda, "rotation impulse");
      three(s.point_state.total_lambda, "point impulse");
      return;
    }
    case ConstraintType::kHinge: {
      auto& s = c.Main<HingeConstraintLanes>();
      one(angular_motor(), "motor impulse");
      three(s.point_state.total_lambda, "point impulse");
      two(s.rotation_state.total_lambda, "hinge rotation impulse");
      one(angular_limit(), "limit impulse");
      one(&s.turn_reference_angle, "turn reference angle");
      one(&s.turns, "turns");
      return;
    }
    case ConstraintType::kSlider: {
      auto& s = c.Main<SliderConstraintLanes>();
      one(linear_motor(0), "motor impulse");
      two(s.dual_state.total_lambda, "dual axis impulse");
      three(s.rotation_state.total_lambda, "rotation impulse");
      one(linear_limit(0), "limit impulse");
      return;
    }
    case ConstraintType::kGear:
      one(&c.Main<GearConstraintLanes>().part.persistent.total_lambda, "gear impulse");
      return;
    case ConstraintType::kRackAndPinion:
      one(&c.Main<RackAndPinionConstraintLanes>().part.persistent.total_lambda,
          "rack and pinion impulse");
      return;
    case ConstraintType::kDistance:
      one(linear_limit(0), "distance impulse");
      three(c.Main<DistanceConstraintLanes>().normal, "normal");
      return;
    case ConstraintType::kPulley: {
      auto& s = c.Main<PulleyConstraintLanes>();
      one(&s.part.persistent.total_lambda, "pulley impulse");
      three(s.geometry.n1, "rope direction 1");
      three(s.geometry.n2, "rope direction 2");
      return;
    }
    case ConstraintType::kCone: {
      auto& s = c.Main<ConeConstraintLanes>();
      three(s.point.persistent.total_lambda, "point impulse");
      one(&s.angle.persistent.total_lambda, "cone impulse");
      three(s.geometry.axis, "rotation axis");
      return;
    }
    case ConstraintType::kSwingTwist: {
      auto& s = c.Main<SwingTwistConstraintLanes>();
      rotation_drives();
      swing_twist(s.swing_twist);
      three(s.point.persistent.total_lambda, "point impulse");
      return;
    }
    case ConstraintType::kSixDof: {
      auto& s = c.Main<SixDofConstraintLanes>();
      for (std::size_t i = 0; i < 3; ++i) one(linear_motor(i), "translation drive impulse");
      rotation_drives();
      three(s.rotation.persistent.total_lambda, "rotation impulse");
      swing_twist(s.swing_twist);
      three(s.point.persistent.total_lambda, "point impulse");
      for (std::size_t i = 0; i < 3; ++i) one(linear_limit(i), "translation limit impulse");
      return;
    }
    case ConstraintType::kPath: {
      auto& s = c.Main<PathConstraintLanes>();
      one(linear_motor(0), "motor impulse");
      two(s.dual.persistent.total_lambda, "dual axis impulse");
      one(&s.limit.persistent.total_lambda, "end limit impulse");
      two(s.hinge.persistent.total_lambda, "hinge rotation impulse");
      three(s.rotation.persistent.total_lambda, "rotation impulse");
      return;
    }
  }
}

// Calls carry(home, scratch) for every accumulated impulse of a constraint
// whose parts live in the scratch (constraint_lanes.h, CarryState): its home
// in the stored block and the part's Persistent struct it is used from
// during a step; nothing for a type without a scratch struct.
template <class Carry>
void VisitCarriedState(const ConstraintBlock& c, Carry&& carry) {
  switch (c.plan.type) {
    case ConstraintType::kPoint:
      CarryState(c.Main<PointConstraintLanes>(), c.Scratch<PointConstraintScratch>(), carry);
      return;
    case ConstraintType::kFixed:
      CarryState(c.Main<FixedConstraintLanes>(), c.Scratch<FixedConstraintScratch>(), carry);
      return;
    case ConstraintType::kHinge:
      CarryState(c.Main<HingeConstraintLanes>(), c.Scratch<HingeConstraintScratch>(), carry);
      return;
    case ConstraintType::kSlider:
      CarryState(c.Main<SliderConstraintLanes>(), c.Scratch<SliderConstraintScratch>(), carry);
      return;
    default:
      return;
  }
}

}  // namespace manyworlds
