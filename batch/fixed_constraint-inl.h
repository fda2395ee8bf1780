// Fixed constraint across worlds: rotation Euler, then point (spec 3, Fixed).
//
//   rotation: C = 2 xyz(q2 r0^-1 q1*) (w >= 0), r0^-1 from the two frames
//   point:    C = p2 - p1
// Setup: both parts at the current rotations; warm start and velocity
// iterations in the order rotation, point. Position: recompute the rotation
// part and step it; then recompute the point part (the rotations changed) and
// step it.

#if defined(MANYWORLDS_BATCH_FIXED_CONSTRAINT_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef MANYWORLDS_BATCH_FIXED_CONSTRAINT_INL_H_
#undef MANYWORLDS_BATCH_FIXED_CONSTRAINT_INL_H_
#else
#define MANYWORLDS_BATCH_FIXED_CONSTRAINT_INL_H_
#endif

#include "batch/constraint_block.h"
#include "kernels/point-inl.h"
#include "kernels/rotation_euler-inl.h"

HWY_BEFORE_NAMESPACE();
namespace manyworlds {
namespace HWY_NAMESPACE {

inline void FixedConstraintSetup(const ConstraintBlock& c, const StepScalars&) {
  auto& t = c.Scratch<FixedConstraintScratch>();
  RotationEulerCalculateProperties(c.bodies, t.rotation);
  PointCalculateProperties(c.bodies, c.Main<FixedConstraintLanes>().anchors, t.point);
}

inline void FixedConstraintWarmStart(const ConstraintBlock& c, const StepScalars& step) {
  auto& t = c.Scratch<FixedConstraintScratch>();
  RotationEulerWarmStart(c.bodies, t.rotation, step.warm_start_ratio);
  PointWarmStart(c.bodies, t.point, step.warm_start_ratio);
}

inline bool FixedConstraintSolveVelocity(const ConstraintBlock& c) {
  auto& t = c.Scratch<FixedConstraintScratch>();
  bool applied = RotationEulerSolveVelocity(c.bodies, t.rotation);
  applied |= PointSolveVelocity(c.bodies, t.point);
  return applied;
}

inline bool FixedConstraintSolvePosition(const ConstraintBlock& c, const StepScalars& step) {
  auto& s = c.Main<FixedConstraintLanes>();
  auto& t = c.Scratch<FixedConstraintScratch>();
  bool applied = RotationEulerRecomputeAndSolvePosition(c.bodies, s.inv_initial_orientation,
                                                        t.rotation, step.baumgarte);
  applied |= PointRecomputeAndSolvePosition(c.bodies, s.anchors, t.point, step.baumgarte);
  return applied;
}

}  // namespace HWY_NAMESPACE
}  // namespace manyworlds
HWY_AFTER_NAMESPACE();

#endif  // MANYWORLDS_BATCH_FIXED_CONSTRAINT_INL_H_
