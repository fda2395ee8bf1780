// The rows the exact solve leaves to Gauss-Seidel: hinge and slider motors,
// friction and limits, swing-twist limits and drives, the cone row, a
// six-DOF constraint's rows beside its all-fixed shortcuts, and every row of
// the distance, pulley and path constraints and of six-DOF constraints
// without a shortcut (ExactSolvePlan::inequality, ExactSolvePlan::SolvedWhole).
// Their impulses
// are bounded (a motor's force limits, a limit's one-sided push, a rope that
// only pulls), which a linear solve of K cannot respect, or soft (springs),
// so they are solved as Jolt does, one row at a
// time with clamping, around the exact solve of the equality rows: block
// Gauss-Seidel with one block holding every equality row (solved exactly by
// the factors of K, which do not change within a velocity phase) and one
// block per inequality row.
//
//   velocity:  setup and warm start of the inequality rows, then
//              E, (I, E) x (velocity_iterations - 1)
//              with E = the equality rows solved exactly for the current
//              velocities (J v = 0 after it) and I = every inequality row
//              once (motor then limit, constraint by constraint); the phase
//              ends with E, so the equality rows hold exactly. Always all
//              passes: E is not idempotent in float (a second E changes
//              rounding bits), so stopping when no lane applied an impulse
//              would make a world depend on the other worlds of its block.
//              A scene without groups (every constraint solved whole) has
//              no E: its passes stop as Gauss-Seidel's do.
//   position:  each Newton step of the equality rows is followed by one
//              Baumgarte step of every hard limit (as Gauss-Seidel takes);
//              the block stops when no world's equality rows are beyond the
//              tolerance and no limit moved any world in the last pass. A
//              pass then changes nothing (limit steps act only where a limit
//              is violated, Newton steps only in worlds still beyond the
//              tolerance), so stopping there gives every world what it would
//              get alone.
//
// The parts and their per-lane decisions are the Gauss-Seidel constraint's
// own (batch/hinge_constraint-inl.h, batch/slider_constraint-inl.h,
// batch/swing_twist_constraint-inl.h, batch/cone_constraint-inl.h,
// batch/six_dof_constraint-inl.h; the constraints solved whole call their
// constraint's verbs), so the rows behave as
// they do there; only their neighbours differ. A rod solved whole or a
// rigid pulley, or a six-DOF or path's locked axes around the solve, move
// the bodies in every position pass (their error is never exactly zero), so
// a scene with them takes all of the position phase's passes.

#if defined(MANYWORLDS_BATCH_EXACT_INEQUALITY_ROWS_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef MANYWORLDS_BATCH_EXACT_INEQUALITY_ROWS_INL_H_
#undef MANYWORLDS_BATCH_EXACT_INEQUALITY_ROWS_INL_H_
#else
#define MANYWORLDS_BATCH_EXACT_INEQUALITY_ROWS_INL_H_
#endif

#include <cstddef>

#include "batch/cone_constraint-inl.h"
#include "batch/constraint_block.h"
#include "batch/constraint_verbs-inl.h"
#include "batch/exact_plan.h"
#include "batch/hinge_constraint-inl.h"
#include "batch/six_dof_constraint-inl.h"
#include "batch/slider_constraint-inl.h"
#include "batch/swing_twist_constraint-inl.h"

HWY_BEFORE_NAMESPACE();
namespace manyworlds {
namespace HWY_NAMESPACE {
namespace exact {

// Setup at the current poses and warm start (the hinge's angle and axes
// are those HingeTurns wrote), drives before limits as Gauss-Seidel.
inline void InequalitySetupAndWarmStart(const ConstraintBlock& c, const StepScalars& step) {
  if (ExactSolvePlan::SolvedWhole(c.plan)) {
    SetupConstraint(c, step);
    WarmStartConstraint(c, step);
    return;
  }
  if (c.plan.type == ConstraintType::kSixDof) {
    SixDofConstraintSetup(c, step, SixDofRows::kBesideShortcuts);
    SixDofConstraintWarmStart(c, step, SixDofRows::kBesideShortcuts);
    return;
  }
  const float ratio = step.warm_start_ratio;
  if (c.plan.type == ConstraintType::kCone) {  // the point part is the exact solve's
    ConeRotationProperties(c);
    AngleWarmStart(c.bodies, c.Scratch<ConeConstraintScratch>().angle, ratio);
    return;
  }
  if (c.plan.type == ConstraintType::kSwingTwist) {
    auto& s = c.Main<SwingTwistConstraintLanes>();
    auto& t = c.Scratch<SwingTwistConstraintScratch>();
    SwingTwistCalculateProperties(c.bodies, c.plan.swing_twist, s.frames, s.limits,
                                  t.swing_twist);
    if (c.plan.has_rotation_drives()) RotationDriveProperties(c, s.frames, s.limits, step);
    if (c.plan.has_rotation_drives()) RotationDriveWarmStart(c, ratio);
    SwingTwistWarmStart(c.bodies, c.plan.swing_twist, t.swing_twist, ratio);
    return;
  }
  if (c.plan.type == ConstraintType::kHinge) {
    if (c.plan.has_limits()) HingeLimitProperties(c, step);
    if (c.plan.has_motor()) HingeMotorProperties(c, step);
    if (c.plan.has_motor()) AngleWarmStart(c.bodies, c.Motor<AngularMotorRow>().part, ratio);
    if (c.plan.has_limits()) AngleWarmStart(c.bodies, c.Limit<AngularLimitRow>().part, ratio);
    return;
  }
  SliderGeometry(c);
  if (c.plan.has_limits()) SliderLimitProperties(c, step);
  if (c.plan.has_motor()) SliderMotorProperties(c, step);
  if (c.plan.has_motor()) {
    auto& motor = c.Motor<LinearMotorRow>();
    AxisWarmStart(c.bodies, motor.geometry, motor.part, ratio);
  }
  if (c.plan.has_limits()) {
    auto& limit = c.Limit<LinearLimitRow>();
    AxisWarmStart(c.bodies, limit.geometry, limit.part, ratio);
  }
}

// One velocity step of the motor (drives), then the limits; every row of a
// constraint solved whole. True if any lane applied an impulse.
inline bool InequalitySolveVelocity(const ConstraintBlock& c) {
  if (ExactSolvePlan::SolvedWhole(c.plan)) return SolveConstraintVelocity(c);
  if (c.plan.type == ConstraintType::kSixDof) {
    return SixDofConstraintSolveVelocity(c, SixDofRows::kBesideShortcuts);
  }
  if (c.plan.type == ConstraintType::kCone) {
    return AngleSolveVelocity(c.bodies, c.Main<ConeConstraintLanes>().geometry,
                              c.Scratch<ConeConstraintScratch>().angle);
  }
  bool applied = false;
  if (c.plan.type == ConstraintType::kSwingTwist) {
    if (c.plan.has_rotation_drives()) applied |= RotationDriveSolveVelocity(c);
    applied |= SwingTwistSolveVelocity(c.bodies, c.plan.swing_twist,
                                       c.Scratch<SwingTwistConstraintScratch>().swing_twist);
    return applied;
  }
  if (c.plan.type == ConstraintType::kHinge) {
    if (c.plan.has_motor()) {
      auto& motor = c.Motor<AngularMotorRow>();
      applied |= AngleSolveVelocity(c.bodies, motor.geometry, motor.part);
    }
    if (c.plan.has_limits()) {
      auto& limit = c.Limit<AngularLimitRow>();
      applied |= AngleSolveVelocity(c.bodies, limit.geometry, limit.part);
    }
    return applied;
  }
  if (c.plan.has_motor()) {
    auto& motor = c.Motor<LinearMotorRow>();
    applied |= AxisSolveVelocity(c.bodies, motor.geometry, motor.part);
  }
  if (c.plan.has_limits()) {
    auto& limit = c.Limit<LinearLimitRow>();
    applied |= AxisSolveVelocity(c.bodies, limit.geometry, limit.part);
  }
  return applied;
}

// One Baumgarte step of a hard limit at the current poses (every row of a
// constraint solved whole); true if any lane moved.
inline bool LimitSolvePosition(const StepPlan& plan, const ConstraintBlock& c,
                               const StepScalars& step) {
  if (ExactSolvePlan::SolvedWhole(c.plan)) return SolveConstraintPosition(plan, c, step);
  if (c.plan.type == ConstraintType::kSixDof) {
    return SixDofConstraintSolvePosition(c, step, SixDofRows::kBesideShortcuts);
  }
  if (c.plan.type == ConstraintType::kCone) {
    ConeRotationProperties(c);
    return AngleSolvePosition(c.bodies, c.Main<ConeConstraintLanes>().geometry,
                              c.Scratch<ConeConstraintScratch>().angle, step.baumgarte);
  }
  if (c.plan.type == ConstraintType::kSwingTwist) {
    auto& s = c.Main<SwingTwistConstraintLanes>();
    return SwingTwistSolvePosition(c.bodies, c.plan.swing_twist, s.frames, s.limits,
                                   step.baumgarte);
  }
  if (!c.plan.has_limits() || c.plan.soft_limits) return false;
  if (c.plan.type == ConstraintType::kHinge) {
    HingeAxesAndAngle(c, true);
    HingeLimitProperties(c, step);
    auto& limit = c.Limit<AngularLimitRow>();
    return AngleSolvePosition(c.bodies, limit.geometry, limit.part, step.baumgarte);
  }
  SliderGeometry(c);
  SliderLimitProperties(c, step);
  auto& limit = c.Limit<LinearLimitRow>();
  return AxisSolvePosition(c.bodies, limit.geometry, limit.part, step.baumgarte);
}

}  // namespace exact
}  // namespace HWY_NAMESPACE
}  // namespace manyworlds
HWY_AFTER_NAMESPACE();

#endif  // MANYWORLDS_BATCH_EXACT_INEQUALITY_ROWS_INL_H_
