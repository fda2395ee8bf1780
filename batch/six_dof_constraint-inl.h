// Six-DOF constraint across worlds (spec 3, SixDOF): per axis of the
// constraint frame fixed, free or limited, with translation limit springs,
// six drives (motor or friction) and Jolt's all-fixed shortcuts.
//
//   q1 c1 -> translation axes t_i = columns of R(q1 c1)
//   r1 = R1 r1_local, r2 = R2 r2_local, r1 + u = x2 + r2 - x1,
//   u = p2 - p1, d_i = t_i . u
// Translation, when every axis is fixed and none has a spring: a point part.
// Otherwise per non-free axis an axis row on t_i with lever arms r1 + u, r2:
//   fixed:   always on, C = d - min, impulse both ways;
//   limited: on where d <= min (C = d - min, impulse >= 0) or d >= max
//            (C = d - max, impulse <= 0), through the axis' limit spring.
// Translation drives per axis as the slider's (C = d - target).
// Rotation, when every axis is fixed: a rotation-Euler part; when some axis
// is constrained: the swing-twist part (limits as a swing-twist joint's);
// rotation drives about body 2's frame axes (batch/rotation_drive_rows-inl.h),
// the orientation error projected onto the position-driven axes.
// Velocity order: translation drives, rotation drives, rotation rows,
// translation rows. Position: rotation (Euler towards c2 (c1 euler(min))*, or
// the swing-twist step), then translation (the point part on the anchors
// moved by c1 min; or per hard axis, recomputed at the current poses, one
// axis step on its error: d - min fixed, the violated bound limited, none
// inside). Drives take no position steps.
//
// Each verb takes which rows it solves (SixDofRows): all of them
// (Gauss-Seidel), or all but the all-fixed shortcuts, which the exact joint
// solve factors as its point and rotation groups (batch/exact_plan.h) and
// solves the other rows around (batch/exact_inequality_rows-inl.h).

#if defined(MANYWORLDS_BATCH_SIX_DOF_CONSTRAINT_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef MANYWORLDS_BATCH_SIX_DOF_CONSTRAINT_INL_H_
#undef MANYWORLDS_BATCH_SIX_DOF_CONSTRAINT_INL_H_
#else
#define MANYWORLDS_BATCH_SIX_DOF_CONSTRAINT_INL_H_
#endif

#include "batch/constraint_block.h"
#include "batch/drive_and_limit_rows-inl.h"
#include "batch/rotation_drive_rows-inl.h"
#include "kernels/axis-inl.h"
#include "kernels/point-inl.h"
#include "kernels/rotation_euler-inl.h"
#include "kernels/swing_twist-inl.h"

HWY_BEFORE_NAMESPACE();
namespace manyworlds {
namespace HWY_NAMESPACE {

struct SixDofTranslationFrame {
  Vec3 r1_plus_u, r2, separation;
  Mat33 axes;  // columns: the translation axes
};

// Lever arms, u and the translation axes at the current poses.
HWY_INLINE SixDofTranslationFrame SixDofTranslationFrameOfChunk(const BodyPair& bodies,
                                                                const SixDofConstraintLanes& s,
                                                                std::size_t offset) {
  const AnchorLeverArms arms = AnchorLeverArmsOfChunk(bodies, s.anchors, offset);
  return {arms.r1_plus_u, arms.r2, arms.separation,
          RotationMatrix(Mul(LoadQuat(bodies.body1->rotation, offset),
                             LoadQuat(s.frames.constraint_to_body1, offset)))};
}

// The translation rows' axes, lever arms and displacements of this step.
HWY_INLINE void SixDofTranslationGeometry(const ConstraintBlock& c) {
  const auto& s = c.Main<SixDofConstraintLanes>();
  auto& t = c.Scratch<SixDofConstraintScratch>();
  ForEachChunk([&](std::size_t offset) {
    const SixDofTranslationFrame frame = SixDofTranslationFrameOfChunk(c.bodies, s, offset);
    StoreVec3(frame.r1_plus_u, t.r1_plus_u, offset);
    StoreVec3(frame.r2, t.r2, offset);
    for (int i = 0; i < 3; ++i) {
      const Vec3 axis = Column(frame.axes, i);
      StoreVec3(axis, t.translation_axis[i], offset);
      Store(Dot(frame.separation, axis), t.displacement[i], offset);
    }
  });
}

HWY_INLINE void SixDofAxisRow(const SixDofConstraintScratch& t, int i, AxisGeometry& row,
                              std::size_t offset) {
  StoreAxisRow(t.r1_plus_u, t.r2, t.translation_axis[i], row, offset);
}

// The limit row of translation axis i from d_i; limited axes are off inside.
inline void SixDofTranslationLimitProperties(const ConstraintBlock& c, int i,
                                             const StepScalars& step) {
  const auto& t = c.Scratch<SixDofConstraintScratch>();
  auto& limit = (&c.Limit<LinearLimitRow>())[i];
  const bool fixed = c.plan.six_dof.translation[i] == AxisLimitKind::kLocked;
  LaneFlags inside;
  ForEachChunk([&](std::size_t offset) {
    SixDofAxisRow(t, i, limit.geometry, offset);
    const LaneVec d = Load(t.displacement[i], offset);
    const LaneVec min = Load(limit.min, offset);
    const LaneVec max = Load(limit.max, offset);
    const LaneMask below = fixed ? AllLanes() : hn::Le(d, min);
    Store(hn::Sub(d, hn::IfThenElse(below, min, max)), limit.geometry.error, offset);
    StoreLimitImpulseRange(below, fixed ? AllLanes() : hn::Eq(min, max), limit.geometry,
                           offset);
    StoreFlags(fixed ? NoLanes() : hn::Not(hn::Or(below, hn::Ge(d, max))), inside, offset);
  });
  AxisCalculatePropertiesForLimit(c.bodies, limit.geometry, limit.part, step.delta_time,
                                  c.plan.six_dof.translation_spring_modes[i]);
  if (!fixed) AxisDeactivate(limit.part, inside);
}

// The drive row of translation axis i from d_i and the per-world targets.
inline void SixDofTranslationDriveProperties(const ConstraintBlock& c, int i,
                                             const StepScalars& step) {
  const auto& t = c.Scratch<SixDofConstraintScratch>();
  auto& motor = (&c.Motor<LinearMotorRow>())[i];
  const DriveKind drive = c.plan.six_dof.translation_drives[i];
  const LaneVec dt = Splat(step.delta_time);
  LaneFlags no_spring;
  ForEachChunk([&](std::size_t offset) {
    SixDofAxisRow(t, i, motor.geometry, offset);
    StoreDriveRow(drive, dt, motor, no_spring, offset);
    Store(hn::Sub(Load(t.displacement[i], offset), Load(motor.target_position, offset)),
          motor.geometry.error, offset);
  });
  CalculateDriveRowProperties(c.bodies, drive, c.plan.six_dof.translation_drive_spring_modes[i],
                              step.delta_time, no_spring, motor.geometry, motor.part);
}

enum class SixDofRows : bool {
  kAll,              // Gauss-Seidel: every row
  kBesideShortcuts,  // the exact solve's: not the point and rotation-Euler shortcuts
};

HWY_INLINE bool SixDofHasTranslationRow(const SixDofConfig& config, int i) {
  return config.translation_rows && config.translation[i] != AxisLimitKind::kFree;
}

inline void SixDofConstraintSetup(const ConstraintBlock& c, const StepScalars& step,
                                  SixDofRows rows) {
  auto& s = c.Main<SixDofConstraintLanes>();
  auto& t = c.Scratch<SixDofConstraintScratch>();
  const SixDofConfig& config = c.plan.six_dof;
  const bool shortcuts = rows == SixDofRows::kAll;
  if (config.translation_point) {
    if (shortcuts) PointCalculateProperties(c.bodies, s.anchors, t.point);
  } else if (config.translation_rows || config.has_translation_drives()) {
    SixDofTranslationGeometry(c);
    for (int i = 0; i < 3; ++i) {
      if (SixDofHasTranslationRow(config, i)) SixDofTranslationLimitProperties(c, i, step);
      if (config.translation_drives[i] != DriveKind::kNone) {
        SixDofTranslationDriveProperties(c, i, step);
      }
    }
  }
  if (config.rotation_euler) {
    if (shortcuts) RotationEulerCalculateProperties(c.bodies, t.rotation);
  } else if (config.rotation_limits) {
    SwingTwistCalculateProperties(c.bodies, c.plan.swing_twist, s.frames, s.rotation_limits,
                                  t.swing_twist);
  }
  if (c.plan.has_rotation_drives()) RotationDriveProperties(c, s.frames, s.rotation_limits, step);
}

inline void SixDofConstraintWarmStart(const ConstraintBlock& c, const StepScalars& step,
                                      SixDofRows rows) {
  auto& t = c.Scratch<SixDofConstraintScratch>();
  const SixDofConfig& config = c.plan.six_dof;
  const bool shortcuts = rows == SixDofRows::kAll;
  const float ratio = step.warm_start_ratio;
  for (int i = 0; i < 3; ++i) {
    if (config.translation_drives[i] == DriveKind::kNone) continue;
    auto& motor = (&c.Motor<LinearMotorRow>())[i];
    AxisWarmStart(c.bodies, motor.geometry, motor.part, ratio);
  }
  if (c.plan.has_rotation_drives()) RotationDriveWarmStart(c, ratio);
  if (config.rotation_euler) {
    if (shortcuts) RotationEulerWarmStart(c.bodies, t.rotation, ratio);
  } else if (config.rotation_limits) {
    SwingTwistWarmStart(c.bodies, c.plan.swing_twist, t.swing_twist, ratio);
  }
  if (config.translation_point && shortcuts) PointWarmStart(c.bodies, t.point, ratio);
  for (int i = 0; i < 3; ++i) {
    if (!SixDofHasTranslationRow(config, i)) continue;
    auto& limit = (&c.Limit<LinearLimitRow>())[i];
    AxisWarmStart(c.bodies, limit.geometry, limit.part, ratio);
  }
}

inline bool SixDofConstraintSolveVelocity(const ConstraintBlock& c, SixDofRows rows) {
  auto& t = c.Scratch<SixDofConstraintScratch>();
  const SixDofConfig& config = c.plan.six_dof;
  const bool shortcuts = rows == SixDofRows::kAll;
  bool applied = false;
  for (int i = 0; i < 3; ++i) {
    if (config.translation_drives[i] == DriveKind::kNone) continue;
    auto& motor = (&c.Motor<LinearMotorRow>())[i];
    applied |= AxisSolveVelocity(c.bodies, motor.geometry, motor.part);
  }
  if (c.plan.has_rotation_drives()) applied |= RotationDriveSolveVelocity(c);
  if (config.rotation_euler) {
    if (shortcuts) applied |= RotationEulerSolveVelocity(c.bodies, t.rotation);
  } else if (config.rotation_limits) {
    applied |= SwingTwistSolveVelocity(c.bodies, c.plan.swing_twist, t.swing_twist);
  }
  if (config.translation_point && shortcuts) applied |= PointSolveVelocity(c.bodies, t.point);
  for (int i = 0; i < 3; ++i) {
    if (!SixDofHasTranslationRow(config, i)) continue;
    auto& limit = (&c.Limit<LinearLimitRow>())[i];
    applied |= AxisSolveVelocity(c.bodies, limit.geometry, limit.part);
  }
  return applied;
}

// One position step of hard translation axis i at the current poses: the
// error is d - min (fixed), the violated bound (limited) or zero (inside,
// where the step changes nothing).
inline bool SixDofTranslationPositionStep(const ConstraintBlock& c, int i,
                                          const StepScalars& step) {
  auto& s = c.Main<SixDofConstraintLanes>();
  auto& limit = (&c.Limit<LinearLimitRow>())[i];
  const bool fixed = c.plan.six_dof.translation[i] == AxisLimitKind::kLocked;
  ForEachChunk([&](std::size_t offset) {
    const SixDofTranslationFrame frame = SixDofTranslationFrameOfChunk(c.bodies, s, offset);
    const Vec3 axis = Column(frame.axes, i);
    const LaneVec d = Dot(frame.separation, axis);
    const LaneVec min = Load(limit.min, offset);
    const LaneVec max = Load(limit.max, offset);
    LaneVec error = hn::Sub(d, min);
    if (!fixed) {
      error = hn::IfThenElse(hn::Le(d, min), error,
                             hn::IfThenElseZero(hn::Ge(d, max), hn::Sub(d, max)));
    }
    StoreVec3(frame.r1_plus_u, limit.geometry.r1_plus_u, offset);
    StoreVec3(frame.r2, limit.geometry.r2, offset);
    StoreVec3(axis, limit.geometry.axis, offset);
    Store(error, limit.geometry.error, offset);
  });
  AxisCalculateProperties(c.bodies, limit.geometry, limit.part);
  return AxisSolvePosition(c.bodies, limit.geometry, limit.part, step.baumgarte);
}

inline bool SixDofConstraintSolvePosition(const ConstraintBlock& c, const StepScalars& step,
                                          SixDofRows rows) {
  auto& s = c.Main<SixDofConstraintLanes>();
  auto& t = c.Scratch<SixDofConstraintScratch>();
  const SixDofConfig& config = c.plan.six_dof;
  const bool shortcuts = rows == SixDofRows::kAll;
  bool applied = false;
  if (config.rotation_euler) {
    if (shortcuts) {
      applied |= RotationEulerRecomputeAndSolvePosition(c.bodies, s.inv_initial_orientation,
                                                        t.rotation, step.baumgarte);
    }
  } else if (config.rotation_limits) {
    applied |= SwingTwistSolvePosition(c.bodies, c.plan.swing_twist, s.frames,
                                       s.rotation_limits, step.baumgarte);
  }
  if (config.translation_point && shortcuts) {
    applied |= PointRecomputeAndSolvePosition(c.bodies, s.fixed_anchors, t.point, step.baumgarte);
  }
  for (int i = 0; i < 3; ++i) {
    if (!SixDofHasTranslationRow(config, i) || config.translation_soft[i]) continue;
    applied |= SixDofTranslationPositionStep(c, i, step);
  }
  return applied;
}

}  // namespace HWY_NAMESPACE
}  // namespace manyworlds
HWY_AFTER_NAMESPACE();

#endif  // MANYWORLDS_BATCH_SIX_DOF_CONSTRAINT_INL_H_
