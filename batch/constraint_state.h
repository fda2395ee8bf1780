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
  // friction rows, limits, rotation drives, as stored in the block.
  const auto angular_motor = [&]() -> LaneArray* {
    if (!c.plan.has_motor()) return nullptr;
    return &At<AngularMotorLanes>(c.block, c.plan.motor_offset).part.persistent.total_lambda;
  };
  const auto angular_limit = [&]() -> LaneArray* {
    if (!c.plan.has_limits()) return nullptr;
    return &At<AngularLimitLanes>(c.block, c.plan.limit_offset).part.persistent.total_lambda;
  };
  const auto linear_motor = [&](std::size_t i) -> LaneArray* {
    if (!c.plan.has_motor()) return nullptr;
    return &(&At<LinearMotorLanes>(c.block, c.plan.motor_offset))[i].part.persistent.total_lambda;
  };
  const auto linear_limit = [&](std::size_t i) -> LaneArray* {
    if (!c.plan.has_limits()) return nullptr;
    return &(&At<LinearLimitLanes>(c.block, c.plan.limit_offset))[i].part.persistent.total_lambda;
  };
  const auto rotation_drive = [&](std::size_t i) -> LaneArray* {
    if (!c.plan.has_rotation_drives()) return nullptr;
    RotationDriveLanes& drives = At<RotationDriveLanes>(c.block, c.plan.rotation_drive_offset);
    return &drives.rows[i].part.persistent.total_lambda;
  };
  const auto rotation_drives = [&] {
    for (std::size_t i = 0; i < 3; ++i) one(rotation_drive(i), "rotation drive impulse");
  };
  const auto swing_twist = [&](SwingTwistLanes::Persistent& state) {
    one(&state.swing_y_lambda, "swing y impulse");
    one(&state.swing_z_lambda, "swing z impulse");
    one(&state.twist_lambda, "twist impulse");
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
      three(s.point_state.total_lambda, "point impulse");
      one(&s.angle_state.total_lambda, "cone impulse");
      three(s.geometry.axis, "rotation axis");
      return;
    }
    case ConstraintType::kSwingTwist: {
      auto& s = c.Main<SwingTwistConstraintLanes>();
      rotation_drives();
      swing_twist(s.swing_twist_state);
      three(s.point_state.total_lambda, "point impulse");
      return;
    }
    case ConstraintType::kSixDof: {
      auto& s = c.Main<SixDofConstraintLanes>();
      for (std::size_t i = 0; i < 3; ++i) one(linear_motor(i), "translation drive impulse");
      rotation_drives();
      three(s.rotation_state.total_lambda, "rotation impulse");
      swing_twist(s.swing_twist_state);
      three(s.point_state.total_lambda, "point impulse");
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

// The motor or limit rows of a constraint, stored at `offset` and used from
// `scratch_offset`: angular for a hinge, else linear, one per translation
// axis for six-DOF (VisitCarriedState).
template <class AngularStored, class AngularRow, class LinearStored, class LinearRow,
          class Carry>
void CarryRows(const ConstraintBlock& c, std::size_t offset, std::size_t scratch_offset,
               Carry& carry) {
  if (c.plan.type == ConstraintType::kHinge) {
    CarryRow(At<AngularStored>(c.block, offset), At<AngularRow>(c.block, scratch_offset), carry);
    return;
  }
  for (std::size_t i = 0; i < c.plan.limit_and_motor_rows(); ++i) {
    CarryRow((&At<LinearStored>(c.block, offset))[i], (&At<LinearRow>(c.block, scratch_offset))[i],
             carry);
  }
}

// Calls carry(home, scratch) for everything a constraint keeps in the block
// and uses from its scratch during a step (constraint_lanes.h, CarryState
// and CarryRow): its parts' accumulated impulses, and its motor, limit and
// drive rows' parameters and impulses; nothing for a type without either.
template <class Carry>
void VisitCarriedState(const ConstraintBlock& c, Carry&& carry) {
  switch (c.plan.type) {
    case ConstraintType::kPoint:
      CarryState(c.Main<PointConstraintLanes>(), c.Scratch<PointConstraintScratch>(), carry);
      break;
    case ConstraintType::kFixed:
      CarryState(c.Main<FixedConstraintLanes>(), c.Scratch<FixedConstraintScratch>(), carry);
      break;
    case ConstraintType::kHinge:
      CarryState(c.Main<HingeConstraintLanes>(), c.Scratch<HingeConstraintScratch>(), carry);
      break;
    case ConstraintType::kSlider:
      CarryState(c.Main<SliderConstraintLanes>(), c.Scratch<SliderConstraintScratch>(), carry);
      break;
    case ConstraintType::kSwingTwist:
      CarryState(c.Main<SwingTwistConstraintLanes>(), c.Scratch<SwingTwistConstraintScratch>(),
                 carry);
      break;
    case ConstraintType::kSixDof:
      CarryState(c.Main<SixDofConstraintLanes>(), c.Scratch<SixDofConstraintScratch>(), carry);
      break;
    case ConstraintType::kCone:
      CarryState(c.Main<ConeConstraintLanes>(), c.Scratch<ConeConstraintScratch>(), carry);
      break;
    case ConstraintType::kGear:
      CarryState(c.Main<GearConstraintLanes>(), c.Scratch<GearConstraintScratch>(), carry);
      break;
    case ConstraintType::kRackAndPinion:
      CarryState(c.Main<RackAndPinionConstraintLanes>(),
                 c.Scratch<RackAndPinionConstraintScratch>(), carry);
      break;
    default:
      break;
  }
  // Motor, limit and drive rows (constraint_lanes.h, CarryRow).
  const ConstraintPlan& p = c.plan;
  if (p.has_motor()) {
    CarryRows<AngularMotorLanes, AngularMotorRow, LinearMotorLanes, LinearMotorRow>(
        c, p.motor_offset, p.motor_scratch_offset, carry);
  }
  if (p.has_limits()) {
    CarryRows<AngularLimitLanes, AngularLimitRow, LinearLimitLanes, LinearLimitRow>(
        c, p.limit_offset, p.limit_scratch_offset, carry);
  }
  if (p.has_rotation_drives()) {
    CarryRow(At<RotationDriveLanes>(c.block, p.rotation_drive_offset),
             At<RotationDriveRows>(c.block, p.rotation_drive_scratch_offset), carry);
  }
}

}  // namespace manyworlds
