// The four verbs of a constraint of any type on one block (spec 4.1):
// setup, warm start, a velocity step and a position step, dispatched on the
// plan's type to the constraint's own file. Used by the Gauss-Seidel step
// (batch/step_kernels.cc) and by the exact solve for the constraints it
// solves whole (batch/exact_inequality_rows-inl.h). The solves return true
// if any lane applied an impulse or a correction.

#if defined(MANYWORLDS_BATCH_CONSTRAINT_VERBS_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef MANYWORLDS_BATCH_CONSTRAINT_VERBS_INL_H_
#undef MANYWORLDS_BATCH_CONSTRAINT_VERBS_INL_H_
#else
#define MANYWORLDS_BATCH_CONSTRAINT_VERBS_INL_H_
#endif

#include "batch/cone_constraint-inl.h"
#include "batch/constraint_block.h"
#include "batch/distance_constraint-inl.h"
#include "batch/fixed_constraint-inl.h"
#include "batch/gear_constraint-inl.h"
#include "batch/hinge_constraint-inl.h"
#include "batch/path_constraint-inl.h"
#include "batch/point_constraint-inl.h"
#include "batch/pulley_constraint-inl.h"
#include "batch/six_dof_constraint-inl.h"
#include "batch/slider_constraint-inl.h"
#include "batch/swing_twist_constraint-inl.h"

HWY_BEFORE_NAMESPACE();
namespace manyworlds {
namespace HWY_NAMESPACE {

inline void SetupConstraint(const ConstraintBlock& c, const StepScalars& step) {
  switch (c.plan.type) {
    case ConstraintType::kPoint: return PointConstraintSetup(c, step);
    case ConstraintType::kFixed: return FixedConstraintSetup(c, step);
    case ConstraintType::kHinge: return HingeConstraintSetup(c, step);
    case ConstraintType::kSlider: return SliderConstraintSetup(c, step);
    case ConstraintType::kGear: return GearConstraintSetup(c, step);
    case ConstraintType::kRackAndPinion: return RackAndPinionConstraintSetup(c, step);
    case ConstraintType::kDistance: return DistanceConstraintSetup(c, step);
    case ConstraintType::kPulley: return PulleyConstraintSetup(c, step);
    case ConstraintType::kCone: return ConeConstraintSetup(c, step);
    case ConstraintType::kSwingTwist: return SwingTwistConstraintSetup(c, step);
    case ConstraintType::kSixDof: return SixDofConstraintSetup(c, step, SixDofRows::kAll);
    case ConstraintType::kPath: return PathConstraintSetup(c, step);
  }
}

inline void WarmStartConstraint(const ConstraintBlock& c, const StepScalars& step) {
  switch (c.plan.type) {
    case ConstraintType::kPoint: return PointConstraintWarmStart(c, step);
    case ConstraintType::kFixed: return FixedConstraintWarmStart(c, step);
    case ConstraintType::kHinge: return HingeConstraintWarmStart(c, step);
    case ConstraintType::kSlider: return SliderConstraintWarmStart(c, step);
    case ConstraintType::kGear: return GearConstraintWarmStart(c, step);
    case ConstraintType::kRackAndPinion: return RackAndPinionConstraintWarmStart(c, step);
    case ConstraintType::kDistance: return DistanceConstraintWarmStart(c, step);
    case ConstraintType::kPulley: return PulleyConstraintWarmStart(c, step);
    case ConstraintType::kCone: return ConeConstraintWarmStart(c, step);
    case ConstraintType::kSwingTwist: return SwingTwistConstraintWarmStart(c, step);
    case ConstraintType::kSixDof: return SixDofConstraintWarmStart(c, step, SixDofRows::kAll);
    case ConstraintType::kPath: return PathConstraintWarmStart(c, step);
  }
}

inline bool SolveConstraintVelocity(const ConstraintBlock& c) {
  switch (c.plan.type) {
    case ConstraintType::kPoint: return PointConstraintSolveVelocity(c);
    case ConstraintType::kFixed: return FixedConstraintSolveVelocity(c);
    case ConstraintType::kHinge: return HingeConstraintSolveVelocity(c);
    case ConstraintType::kSlider: return SliderConstraintSolveVelocity(c);
    case ConstraintType::kGear: return GearConstraintSolveVelocity(c);
    case ConstraintType::kRackAndPinion: return RackAndPinionConstraintSolveVelocity(c);
    case ConstraintType::kDistance: return DistanceConstraintSolveVelocity(c);
    case ConstraintType::kPulley: return PulleyConstraintSolveVelocity(c);
    case ConstraintType::kCone: return ConeConstraintSolveVelocity(c);
    case ConstraintType::kSwingTwist: return SwingTwistConstraintSolveVelocity(c);
    case ConstraintType::kSixDof: return SixDofConstraintSolveVelocity(c, SixDofRows::kAll);
    case ConstraintType::kPath: return PathConstraintSolveVelocity(c);
  }
  return false;
}

inline bool SolveConstraintPosition(const StepPlan& plan, const ConstraintBlock& c,
                                    const StepScalars& step) {
  switch (c.plan.type) {
    case ConstraintType::kPoint: return PointConstraintSolvePosition(c, step);
    case ConstraintType::kFixed: return FixedConstraintSolvePosition(c, step);
    case ConstraintType::kHinge: return HingeConstraintSolvePosition(c, step);
    case ConstraintType::kSlider: return SliderConstraintSolvePosition(c, step);
    case ConstraintType::kGear: return GearConstraintSolvePosition(plan, c, step);
    case ConstraintType::kRackAndPinion:
      return RackAndPinionConstraintSolvePosition(plan, c, step);
    case ConstraintType::kDistance: return DistanceConstraintSolvePosition(c, step);
    case ConstraintType::kPulley: return PulleyConstraintSolvePosition(c, step);
    case ConstraintType::kCone: return ConeConstraintSolvePosition(c, step);
    case ConstraintType::kSwingTwist: return SwingTwistConstraintSolvePosition(c, step);
    case ConstraintType::kSixDof: return SixDofConstraintSolvePosition(c, step, SixDofRows::kAll);
    case ConstraintType::kPath: return PathConstraintSolvePosition(c, step);
  }
  return false;
}

}  // namespace HWY_NAMESPACE
}  // namespace manyworlds
HWY_AFTER_NAMESPACE();

#endif  // MANYWORLDS_BATCH_CONSTRAINT_VERBS_INL_H_
