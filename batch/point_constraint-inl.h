// Point constraint (ball joint) across worlds: one point part (spec 3, Point).
//
//   C = p2 - p1 = (x2 + R2 r2_local) - (x1 + R1 r1_local)
// Setup: point part at the current rotations. Velocity: point part.
// Position: recompute the point part at the current rotations, one Baumgarte
// step.

#if defined(MANYWORLDS_BATCH_POINT_CONSTRAINT_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef MANYWORLDS_BATCH_POINT_CONSTRAINT_INL_H_
#undef MANYWORLDS_BATCH_POINT_CONSTRAINT_INL_H_
#else
#define MANYWORLDS_BATCH_POINT_CONSTRAINT_INL_H_
#endif

#include "batch/constraint_block.h"
#include "kernels/point-inl.h"

HWY_BEFORE_NAMESPACE();
namespace manyworlds {
namespace HWY_NAMESPACE {

inline void PointConstraintSetup(const ConstraintBlock& c, const StepScalars&) {
  PointCalculateProperties(c.bodies, c.Main<PointConstraintLanes>().anchors,
                           c.Scratch<PointConstraintScratch>().point);
}

inline void PointConstraintWarmStart(const ConstraintBlock& c, const StepScalars& step) {
  PointWarmStart(c.bodies, c.Scratch<PointConstraintScratch>().point, step.warm_start_ratio);
}

inline bool PointConstraintSolveVelocity(const ConstraintBlock& c) {
  return PointSolveVelocity(c.bodies, c.Scratch<PointConstraintScratch>().point);
}

inline bool PointConstraintSolvePosition(const ConstraintBlock& c, const StepScalars& step) {
  return PointRecomputeAndSolvePosition(c.bodies, c.Main<PointConstraintLanes>().anchors,
                                        c.Scratch<PointConstraintScratch>().point,
                                        step.baumgarte);
}

}  // namespace HWY_NAMESPACE
}  // namespace manyworlds
HWY_AFTER_NAMESPACE();

#endif  // MANYWORLDS_BATCH_POINT_CONSTRAINT_INL_H_
