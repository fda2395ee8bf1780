// Slider constraint across worlds (spec 3, Slider): one translational degree
// of freedom along the slider axis, rotation fixed, with optional limits
// (hard or soft), motor (velocity, position, both) or friction.
//
// Parts in solve order: axis (motor / friction) -> dual axis -> rotation
// Euler -> axis (limits).
//   r1 = q1 r1_local, r2 = q2 r2_local, u = x2 + r2 - x1 - r1
//   dual axis on n1 = q1 normal1, n2 = q1 (slider1 x normal1), lever r1 + u
//   slider axis s = q1 slider1, position d = u . s
// Limits [min <= 0, max >= 0] engage where d <= min or d >= max, C = d - min
// or d - max; impulse range both ways if min == max, [0, inf) below min,
// (-inf, 0] above max. Motor rows on s: friction bias 0 and range dt [-f, f];
// velocity bias -target and range dt [min, max]; position C = d - target
// through the motor spring; position-and-velocity both.
// Position phase: dual axis (recomputed) -> rotation Euler (recomputed) ->
// for hard limits r, u, s, d and the limit row recomputed (which may
// deactivate the limit and zero its impulse, spec 1.3) and one step on C.

#if defined(MANYWORLDS_BATCH_SLIDER_CONSTRAINT_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef MANYWORLDS_BATCH_SLIDER_CONSTRAINT_INL_H_
#undef MANYWORLDS_BATCH_SLIDER_CONSTRAINT_INL_H_
#else
#define MANYWORLDS_BATCH_SLIDER_CONSTRAINT_INL_H_
#endif

#include <cfloat>

#include "batch/constraint_block.h"
#include "batch/drive_and_limit_rows-inl.h"
#include "kernels/axis-inl.h"
#include "kernels/dual_axis-inl.h"
#include "kernels/rotation_euler-inl.h"

HWY_BEFORE_NAMESPACE();
namespace manyworlds {
namespace HWY_NAMESPACE {

struct SliderFrame {
  Vec3 r2, separation, r1_plus_u, slider_axis;
};

// Lever arms, separation and slider axis at the current poses.
HWY_INLINE SliderFrame SliderFrameOfChunk(const BodyPair& bodies,
                                          const SliderConstraintLanes& s,
                                          std::size_t offset) {
  const AnchorLeverArms arms = AnchorLeverArmsOfChunk(bodies, s.anchors, offset);
  const Vec3 slider_axis =
      Rotate(LoadQuat(bodies.body1->rotation, offset), LoadVec3(s.slider_axis1_local, offset));
  return {arms.r2, arms.separation, arms.r1_plus_u, slider_axis};
}

// The slider's current position d, for the rack-and-pinion position step.
HWY_INLINE LaneVec SliderCurrentPositionOfChunk(const BodyPair& bodies,
                                                const SliderConstraintLanes& s,
                                                std::size_t offset) {
  const SliderFrame frame = SliderFrameOfChunk(bodies, s, offset);
  return Dot(frame.separation, frame.slider_axis);
}

// Writes the dual-axis geometry, u, s and d of the current poses.
HWY_INLINE void SliderGeometry(const ConstraintBlock& c) {
  const auto& s = c.Main<SliderConstraintLanes>();
  auto& t = c.Scratch<SliderConstraintScratch>();
  ForEachChunk([&](std::size_t offset) {
    const SliderFrame frame = SliderFrameOfChunk(c.bodies, s, offset);
    const Quat q1 = LoadQuat(c.bodies.body1->rotation, offset);
    StoreVec3(frame.r1_plus_u, t.dual_geometry.r1_plus_u, offset);
    StoreVec3(frame.r2, t.dual_geometry.r2, offset);
    StoreVec3(Rotate(q1, LoadVec3(s.normal_axis1_local, offset)), t.dual_geometry.n1, offset);
    StoreVec3(Rotate(q1, LoadVec3(s.binormal_axis1_local, offset)), t.dual_geometry.n2,
              offset);
    StoreVec3(frame.separation, t.separation, offset);
    StoreVec3(frame.slider_axis, t.slider_axis, offset);
    Store(Dot(frame.separation, frame.slider_axis), t.position, offset);
  });
}

// An axis row along the slider axis with the lever arms of this step.
HWY_INLINE void SliderAxisRow(const SliderConstraintScratch& t, AxisGeometry& row,
                              std::size_t offset) {
  StoreAxisRow(t.dual_geometry.r1_plus_u, t.dual_geometry.r2, t.slider_axis, row, offset);
}

// The limit row from d; deactivates the lanes inside the limits.
inline void SliderLimitProperties(const ConstraintBlock& c, const StepScalars& step) {
  const auto& t = c.Scratch<SliderConstraintScratch>();
  auto& limit = c.Limit<LinearLimitRow>();
  LaneFlags inside;
  ForEachChunk([&](std::size_t offset) {
    SliderAxisRow(t, limit.geometry, offset);
    const LaneVec d = Load(t.position, offset);
    const LaneVec min = Load(limit.min, offset);
    const LaneVec max = Load(limit.max, offset);
    const LaneMask below = hn::Le(d, min);
    Store(hn::Sub(d, hn::IfThenElse(below, min, max)), limit.geometry.error, offset);
    StoreLimitImpulseRange(below, hn::Eq(min, max), limit.geometry, offset);
    StoreFlags(hn::Not(hn::Or(below, hn::Ge(d, max))), inside, offset);
  });
  AxisCalculatePropertiesForLimit(c.bodies, limit.geometry, limit.part, step.delta_time,
                                  c.plan.limit_spring_mode);
  AxisDeactivate(limit.part, inside);
}

// The motor or friction row from d and the per-world targets.
inline void SliderMotorProperties(const ConstraintBlock& c, const StepScalars& step) {
  const auto& t = c.Scratch<SliderConstraintScratch>();
  auto& motor = c.Motor<LinearMotorRow>();
  const DriveKind drive = c.plan.drive;
  const LaneVec dt = Splat(step.delta_time);
  LaneFlags no_spring;
  ForEachChunk([&](std::size_t offset) {
    SliderAxisRow(t, motor.geometry, offset);
    StoreDriveRow(drive, dt, motor, no_spring, offset);
    Store(hn::Sub(Load(t.position, offset), Load(motor.target_position, offset)),
          motor.geometry.error, offset);
  });
  CalculateDriveRowProperties(c.bodies, drive, c.plan.motor_spring_mode, step.delta_time,
                              no_spring, motor.geometry, motor.part);
}

inline void SliderConstraintSetup(const ConstraintBlock& c, const StepScalars& step) {
  auto& t = c.Scratch<SliderConstraintScratch>();
  SliderGeometry(c);
  DualAxisCalculateProperties(c.bodies, t.dual_geometry, t.dual);
  RotationEulerCalculateProperties(c.bodies, t.rotation);
  if (c.plan.has_limits()) SliderLimitProperties(c, step);
  if (c.plan.has_motor()) SliderMotorProperties(c, step);
}

inline void SliderConstraintWarmStart(const ConstraintBlock& c, const StepScalars& step) {
  auto& t = c.Scratch<SliderConstraintScratch>();
  const float ratio = step.warm_start_ratio;
  if (c.plan.has_motor()) {
    auto& motor = c.Motor<LinearMotorRow>();
    AxisWarmStart(c.bodies, motor.geometry, motor.part, ratio);
  }
  DualAxisWarmStart(c.bodies, t.dual_geometry, t.dual, ratio);
  RotationEulerWarmStart(c.bodies, t.rotation, ratio);
  if (c.plan.has_limits()) {
    auto& limit = c.Limit<LinearLimitRow>();
    AxisWarmStart(c.bodies, limit.geometry, limit.part, ratio);
  }
}

inline bool SliderConstraintSolveVelocity(const ConstraintBlock& c) {
  auto& t = c.Scratch<SliderConstraintScratch>();
  bool applied = false;
  if (c.plan.has_motor()) {
    auto& motor = c.Motor<LinearMotorRow>();
    applied |= AxisSolveVelocity(c.bodies, motor.geometry, motor.part);
  }
  applied |= DualAxisSolveVelocity(c.bodies, t.dual_geometry, t.dual);
  applied |= RotationEulerSolveVelocity(c.bodies, t.rotation);
  if (c.plan.has_limits()) {
    auto& limit = c.Limit<LinearLimitRow>();
    applied |= AxisSolveVelocity(c.bodies, limit.geometry, limit.part);
  }
  return applied;
}

inline bool SliderConstraintSolvePosition(const ConstraintBlock& c, const StepScalars& step) {
  auto& t = c.Scratch<SliderConstraintScratch>();
  SliderGeometry(c);
  bool applied = DualAxisRecomputeAndSolvePosition(c.bodies, t.dual_geometry, t.separation,
                                                   t.dual, step.baumgarte);
  applied |= RotationEulerRecomputeAndSolvePosition(
      c.bodies, c.Main<SliderConstraintLanes>().inv_initial_orientation, t.rotation,
      step.baumgarte);
  if (c.plan.has_limits() && !c.plan.soft_limits) {
    SliderGeometry(c);
    SliderLimitProperties(c, step);
    auto& limit = c.Limit<LinearLimitRow>();
    applied |= AxisSolvePosition(c.bodies, limit.geometry, limit.part, step.baumgarte);
  }
  return applied;
}

}  // namespace HWY_NAMESPACE
}  // namespace manyworlds
HWY_AFTER_NAMESPACE();

#endif  // MANYWORLDS_BATCH_SLIDER_CONSTRAINT_INL_H_
