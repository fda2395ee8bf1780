// Swing-twist constraint across worlds (spec 3, SwingTwist), the ragdoll
// joint: optional rotation drives (batch/rotation_drive_rows-inl.h: twist
// motor about X, swing motors about Y and Z, or friction), the swing-twist
// part (kernels/swing_twist-inl.h: swing cone or pyramid and twist range as up
// to three angle rows) and a point part.
//
//   q = (q1 c1)* (q2 c2): body 2's constraint frame relative to body 1's,
//   decomposed into swing (about Y, Z) and twist (about X) and clamped to the
//   limits; the rows push back where a limit is exceeded.
// Solve order (Jolt's): twist drive, swing drives, swing Y, swing Z, twist
// limits, point.
// Position: the swing-twist part takes one rotation-Euler Baumgarte step
// towards the clamped orientation where a limit is violated, then the point
// part is recomputed at the new rotations and stepped. Drives take none.

#if defined(MANYWORLDS_BATCH_SWING_TWIST_CONSTRAINT_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef MANYWORLDS_BATCH_SWING_TWIST_CONSTRAINT_INL_H_
#undef MANYWORLDS_BATCH_SWING_TWIST_CONSTRAINT_INL_H_
#else
#define MANYWORLDS_BATCH_SWING_TWIST_CONSTRAINT_INL_H_
#endif

#include "batch/constraint_block.h"
#include "batch/rotation_drive_rows-inl.h"
#include "kernels/point-inl.h"
#include "kernels/swing_twist-inl.h"

HWY_BEFORE_NAMESPACE();
namespace manyworlds {
namespace HWY_NAMESPACE {

inline void SwingTwistConstraintSetup(const ConstraintBlock& c, const StepScalars& step) {
  auto& s = c.Main<SwingTwistConstraintLanes>();
  auto& t = c.Scratch<SwingTwistConstraintScratch>();
  PointCalculateProperties(c.bodies, s.anchors, t.point);
  SwingTwistCalculateProperties(c.bodies, c.plan.swing_twist, s.frames, s.limits,
                                t.swing_twist);
  if (c.plan.has_rotation_drives()) RotationDriveProperties(c, s.frames, s.limits, step);
}

inline void SwingTwistConstraintWarmStart(const ConstraintBlock& c, const StepScalars& step) {
  auto& t = c.Scratch<SwingTwistConstraintScratch>();
  if (c.plan.has_rotation_drives()) RotationDriveWarmStart(c, step.warm_start_ratio);
  SwingTwistWarmStart(c.bodies, c.plan.swing_twist, t.swing_twist, step.warm_start_ratio);
  PointWarmStart(c.bodies, t.point, step.warm_start_ratio);
}

inline bool SwingTwistConstraintSolveVelocity(const ConstraintBlock& c) {
  auto& t = c.Scratch<SwingTwistConstraintScratch>();
  bool applied = c.plan.has_rotation_drives() && RotationDriveSolveVelocity(c);
  applied |= SwingTwistSolveVelocity(c.bodies, c.plan.swing_twist, t.swing_twist);
  return PointSolveVelocity(c.bodies, t.point) || applied;
}

inline bool SwingTwistConstraintSolvePosition(const ConstraintBlock& c,
                                              const StepScalars& step) {
  auto& s = c.Main<SwingTwistConstraintLanes>();
  const bool limits = SwingTwistSolvePosition(c.bodies, c.plan.swing_twist, s.frames,
                                              s.limits, step.baumgarte);
  return PointRecomputeAndSolvePosition(c.bodies, s.anchors,
                                        c.Scratch<SwingTwistConstraintScratch>().point,
                                        step.baumgarte) ||
         limits;
}

}  // namespace HWY_NAMESPACE
}  // namespace manyworlds
HWY_AFTER_NAMESPACE();

#endif  // MANYWORLDS_BATCH_SWING_TWIST_CONSTRAINT_INL_H_
