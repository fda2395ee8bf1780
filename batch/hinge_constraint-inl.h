// Hinge constraint across worlds (spec 3, Hinge): one rotational degree of
// freedom about the hinge axis, with optional limits (hard or soft), motor
// (velocity, position, both) or friction.
//
// Parts in solve order: angle (motor / friction) -> point -> hinge rotation
// -> angle (limits).
//   a1 = q1 hinge1_local, a2 = q2 hinge2_local (world hinge axes)
//   diff = q2 r0^-1 q1*,  theta = 2 atan((xyz(diff) . a1) / w(diff)) in (-pi, pi]
//   (pi where w = 0); r0^-1 from the (normal = X, hinge = Z) frames.
// Limits [min, max] (within [-pi, 0] and [0, pi]) engage where theta <= min or
// theta >= max, with C the smaller wrapped distance to a limit; impulse range
// both ways if min == max, [0, inf) if the min limit is nearer, else (-inf, 0].
// Motor rows on a1: friction bias 0 and range dt [-f, f]; velocity bias
// -target and range dt [min, max]; position C = wrap(theta - target) through
// the motor spring; position-and-velocity both.
// Position phase: point (recomputed) -> hinge rotation (recomputed at the new
// rotations) -> for hard limits, theta and the limit row recomputed (which may
// deactivate the limit and zero its impulse, spec 1.3) and one step on C.
// Motors never take position steps.

#if defined(MANYWORLDS_BATCH_HINGE_CONSTRAINT_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef MANYWORLDS_BATCH_HINGE_CONSTRAINT_INL_H_
#undef MANYWORLDS_BATCH_HINGE_CONSTRAINT_INL_H_
#else
#define MANYWORLDS_BATCH_HINGE_CONSTRAINT_INL_H_
#endif

#include <cfloat>

#include "batch/constraint_block.h"
#include "batch/drive_and_limit_rows-inl.h"
#include "kernels/angle-inl.h"
#include "kernels/hinge_rotation-inl.h"
#include "kernels/point-inl.h"

HWY_BEFORE_NAMESPACE();
namespace manyworlds {
namespace HWY_NAMESPACE {

// Quat::GetRotationAngle(axis) of diff = q2 r0^-1 q1* (Jolt's hinge angle).
HWY_INLINE LaneVec HingeAngleOfChunk(const BodyPair& bodies, const HingeConstraintLanes& s,
                                     const Vec3& a1, std::size_t offset) {
  const Quat q1 = LoadQuat(bodies.body1->rotation, offset);
  const Quat q2 = LoadQuat(bodies.body2->rotation, offset);
  const Quat diff = Mul(Mul(q2, LoadQuat(s.inv_initial_orientation, offset)), Conjugate(q1));
  const LaneVec along_axis = Dot(Vec3{diff.x, diff.y, diff.z}, a1);
  const LaneVec theta = hn::Mul(Splat(2.0f), Atan(hn::Div(along_axis, diff.w)));
  return hn::IfThenElse(hn::Eq(diff.w, Zero()), Splat(kPiHigh), theta);
}

// World hinge axes at the current rotations.
HWY_INLINE Vec3 HingeAxis1OfChunk(const BodyPair& bodies, const HingeConstraintLanes& s,
                                  std::size_t offset) {
  return Rotate(LoadQuat(bodies.body1->rotation, offset), LoadVec3(s.hinge_axis1_local, offset));
}

// The hinge's current angle, for the gear and rack-and-pinion position steps.
HWY_INLINE LaneVec HingeCurrentAngleOfChunk(const BodyPair& bodies,
                                            const HingeConstraintLanes& s,
                                            std::size_t offset) {
  return HingeAngleOfChunk(bodies, s, HingeAxis1OfChunk(bodies, s, offset), offset);
}

// The hinge's unwrapped angle now (theta + 2 pi turns, UnwrappedAngle), for
// the gear and rack-and-pinion position steps: continuous across +-pi.
HWY_INLINE LaneVec HingeUnwrappedAngleOfChunk(const BodyPair& bodies,
                                              const HingeConstraintLanes& s,
                                              std::size_t offset) {
  return UnwrappedAngle(HingeCurrentAngleOfChunk(bodies, s, offset),
                        Load(s.turn_reference_angle, offset), Load(s.turns, offset));
}

// Writes a1, a2 (and theta) of the current rotations into the hinge's lanes.
HWY_INLINE void HingeAxesAndAngle(const ConstraintBlock& c, bool with_angle) {
  const auto& s = c.Main<HingeConstraintLanes>();
  auto& t = c.Scratch<HingeConstraintScratch>();
  ForEachChunk([&](std::size_t offset) {
    const Vec3 a1 = HingeAxis1OfChunk(c.bodies, s, offset);
    const Vec3 a2 = Rotate(LoadQuat(c.bodies.body2->rotation, offset),
                           LoadVec3(s.hinge_axis2_local, offset));
    StoreVec3(a1, t.rotation_geometry.hinge_axis1, offset);
    StoreVec3(a2, t.rotation_geometry.hinge_axis2, offset);
    if (with_angle) Store(HingeAngleOfChunk(c.bodies, s, a1, offset), t.angle, offset);
  });
}

// Whole turns of theta: a jump of more than pi since the last setup is a wrap
// through +-pi (the hinge turned less than pi, the other way round).
HWY_INLINE void HingeCountTurns(HingeConstraintLanes& s, const HingeConstraintScratch& t) {
  ForEachChunk([&](std::size_t offset) {
    const LaneVec theta = Load(t.angle, offset);
    const LaneVec jump = hn::Sub(theta, Load(s.turn_reference_angle, offset));
    const LaneVec pi = Splat(kPiHigh);
    const LaneVec up = hn::IfThenElseZero(hn::Lt(jump, hn::Neg(pi)), Splat(1.0f));
    const LaneVec down = hn::IfThenElseZero(hn::Gt(jump, pi), Splat(1.0f));
    Store(hn::Add(Load(s.turns, offset), hn::Sub(up, down)), s.turns, offset);
    Store(theta, s.turn_reference_angle, offset);
  });
}

// The limit row from theta (setup and position phase); deactivates the lanes
// whose angle is inside the limits.
inline void HingeLimitProperties(const ConstraintBlock& c, const StepScalars& step) {
  const auto& t = c.Scratch<HingeConstraintScratch>();
  auto& limit = c.Limit<AngularLimitRow>();
  LaneFlags inside;
  ForEachChunk([&](std::size_t offset) {
    const LaneVec theta = Load(t.angle, offset);
    const LaneVec min = Load(limit.min, offset);
    const LaneVec max = Load(limit.max, offset);
    const LaneVec to_min = CenterAngleAroundZero(hn::Sub(theta, min));
    const LaneVec to_max = CenterAngleAroundZero(hn::Sub(theta, max));
    const LaneMask min_nearer = hn::Lt(hn::Abs(to_min), hn::Abs(to_max));
    Store(hn::IfThenElse(min_nearer, to_min, to_max), limit.geometry.error, offset);
    StoreLimitImpulseRange(min_nearer, hn::Eq(min, max), limit.geometry, offset);
    StoreVec3(LoadVec3(t.rotation_geometry.hinge_axis1, offset), limit.geometry.axis, offset);
    StoreFlags(hn::Not(hn::Or(hn::Le(theta, min), hn::Ge(theta, max))), inside, offset);
  });
  AngleCalculatePropertiesForLimit(c.bodies, limit.geometry, limit.part, step.delta_time,
                                   c.plan.limit_spring_mode);
  AngleDeactivate(limit.part, inside);
}

// The motor or friction row from theta and the per-world targets.
inline void HingeMotorProperties(const ConstraintBlock& c, const StepScalars& step) {
  const auto& t = c.Scratch<HingeConstraintScratch>();
  auto& motor = c.Motor<AngularMotorRow>();
  const DriveKind drive = c.plan.drive;
  const LaneVec dt = Splat(step.delta_time);
  LaneFlags no_spring;
  ForEachChunk([&](std::size_t offset) {
    StoreVec3(LoadVec3(t.rotation_geometry.hinge_axis1, offset), motor.geometry.axis, offset);
    StoreDriveRow(drive, dt, motor, no_spring, offset);
    Store(CenterAngleAroundZero(
              hn::Sub(Load(t.angle, offset), Load(motor.target_position, offset))),
          motor.geometry.error, offset);
  });
  CalculateDriveRowProperties(c.bodies, drive, c.plan.motor_spring_mode, step.delta_time,
                              no_spring, motor.geometry, motor.part);
}

inline void HingeConstraintSetup(const ConstraintBlock& c, const StepScalars& step) {
  auto& s = c.Main<HingeConstraintLanes>();
  auto& t = c.Scratch<HingeConstraintScratch>();
  // The angle every setup, also without limits or motor: it counts turns.
  HingeAxesAndAngle(c, true);
  HingeCountTurns(s, t);
  PointCalculateProperties(c.bodies, s.anchors, t.point);
  HingeRotationCalculateProperties(c.bodies, t.rotation_geometry, t.rotation);
  if (c.plan.has_limits()) HingeLimitProperties(c, step);
  if (c.plan.has_motor()) HingeMotorProperties(c, step);
}

inline void HingeConstraintWarmStart(const ConstraintBlock& c, const StepScalars& step) {
  auto& t = c.Scratch<HingeConstraintScratch>();
  const float ratio = step.warm_start_ratio;
  if (c.plan.has_motor()) AngleWarmStart(c.bodies, c.Motor<AngularMotorRow>().part, ratio);
  PointWarmStart(c.bodies, t.point, ratio);
  HingeRotationWarmStart(c.bodies, t.rotation, ratio);
  if (c.plan.has_limits()) AngleWarmStart(c.bodies, c.Limit<AngularLimitRow>().part, ratio);
}

inline bool HingeConstraintSolveVelocity(const ConstraintBlock& c) {
  auto& t = c.Scratch<HingeConstraintScratch>();
  bool applied = false;
  if (c.plan.has_motor()) {
    auto& motor = c.Motor<AngularMotorRow>();
    applied |= AngleSolveVelocity(c.bodies, motor.geometry, motor.part);
  }
  applied |= PointSolveVelocity(c.bodies, t.point);
  applied |= HingeRotationSolveVelocity(c.bodies, t.rotation);
  if (c.plan.has_limits()) {
    auto& limit = c.Limit<AngularLimitRow>();
    applied |= AngleSolveVelocity(c.bodies, limit.geometry, limit.part);
  }
  return applied;
}

inline bool HingeConstraintSolvePosition(const ConstraintBlock& c, const StepScalars& step) {
  auto& t = c.Scratch<HingeConstraintScratch>();
  bool applied = PointRecomputeAndSolvePosition(c.bodies, c.Main<HingeConstraintLanes>().anchors,
                                                t.point, step.baumgarte);
  HingeAxesAndAngle(c, false);
  // Where the axes are exactly aligned in every world (a planar mechanism
  // turning about its hinges only), the step would turn nothing: the
  // inverse inertias and K^-1 are not worth computing; an aligned lane is
  // left as it is either way (docs/stepping.md).
  if (!HingeRotationAxes(t.rotation_geometry, t.rotation)) {
    HingeRotationEffectiveMass(c.bodies, t.rotation, /*position_phase=*/true);
    applied |= HingeRotationSolvePosition(c.bodies, t.rotation, step.baumgarte);
  }
  if (c.plan.has_limits() && !c.plan.soft_limits) {
    HingeAxesAndAngle(c, true);
    HingeLimitProperties(c, step);
    auto& limit = c.Limit<AngularLimitRow>();
    applied |= AngleSolvePosition(c.bodies, limit.geometry, limit.part, step.baumgarte);
  }
  return applied;
}

}  // namespace HWY_NAMESPACE
}  // namespace manyworlds
HWY_AFTER_NAMESPACE();

#endif  // MANYWORLDS_BATCH_HINGE_CONSTRAINT_INL_H_
