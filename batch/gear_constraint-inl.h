// Gear and rack-and-pinion constraints across worlds (spec 3, Gear and
// RackAndPinion): one coupling part each, with position correction through
// the hinges (and the rack's slider) when the scene names them.
//
// Gear:  a = q1 hinge1_local, b = q2 hinge2_local; C = theta1 + r theta2 with
//        the two hinges' current unwrapped angles (negated when the gear's
//        body is the hinge's body 1, so theta is always the gear's own
//        rotation, as in Jolt).
// Rack:  a = q1 hinge_local (pinion), b = q2 slider_local (rack);
//        C = theta - r d with the hinge's unwrapped angle and the slider's
//        position (each negated when the pinion / rack is the helper's body 1).
// Where we differ from Jolt (docs/constraint-parts.md, "Unwrapped angles"):
// Jolt measures the hinges' angles wrapped into (-pi, pi] and folds C with
// CenterAngleAroundZero(fmod(C, 2 pi)). With a non-integer ratio the gear's
// C then jumps by 2 pi r once gear 2 turns past +-pi, which the fold does not
// undo, and the position step drives the gears to a wrong coupling; the
// unwrapped angles (turns counted at every hinge setup, HingeCountTurns)
// make C the true coupling error, so there is nothing to fold.
// Setup computes the world axes and the part; the position step recomputes the
// part at the current rotations and takes one Baumgarte step on C.

#if defined(MANYWORLDS_BATCH_GEAR_CONSTRAINT_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef MANYWORLDS_BATCH_GEAR_CONSTRAINT_INL_H_
#undef MANYWORLDS_BATCH_GEAR_CONSTRAINT_INL_H_
#else
#define MANYWORLDS_BATCH_GEAR_CONSTRAINT_INL_H_
#endif

#include "batch/constraint_block.h"
#include "batch/hinge_constraint-inl.h"
#include "batch/slider_constraint-inl.h"
#include "kernels/gear-inl.h"
#include "kernels/rack_and_pinion-inl.h"

HWY_BEFORE_NAMESPACE();
namespace manyworlds {
namespace HWY_NAMESPACE {

// A helper's reading of `body`'s motion: as measured when `body` is the
// helper's body 2, negated when it is body 1 (scene-uniform).
HWY_INLINE LaneVec AsSeenBy(const ConstraintBlock& helper, std::size_t body, LaneVec reading) {
  return helper.plan.body2 == body ? reading : hn::Neg(reading);
}

// The world axes of both bodies from their body-space axes.
HWY_INLINE void CouplingAxes(const BodyPair& bodies, const Vec3Lanes& axis1_local,
                             const Vec3Lanes& axis2_local, Vec3Lanes& axis1,
                             Vec3Lanes& axis2) {
  ForEachChunk([&](std::size_t offset) {
    StoreVec3(Rotate(LoadQuat(bodies.body1->rotation, offset), LoadVec3(axis1_local, offset)),
              axis1, offset);
    StoreVec3(Rotate(LoadQuat(bodies.body2->rotation, offset), LoadVec3(axis2_local, offset)),
              axis2, offset);
  });
}

// ---------------------------------------------------------------- gear

inline void GearConstraintSetup(const ConstraintBlock& c, const StepScalars&) {
  auto& s = c.Main<GearConstraintLanes>();
  auto& t = c.Scratch<GearConstraintScratch>();
  CouplingAxes(c.bodies, s.hinge_axis1_local, s.hinge_axis2_local, t.geometry.hinge_axis1,
               t.geometry.hinge_axis2);
  GearCalculateProperties(c.bodies, t.geometry, t.part);
}

inline void GearConstraintWarmStart(const ConstraintBlock& c, const StepScalars& step) {
  GearWarmStart(c.bodies, c.Scratch<GearConstraintScratch>().part, step.warm_start_ratio);
}

inline bool GearConstraintSolveVelocity(const ConstraintBlock& c) {
  auto& t = c.Scratch<GearConstraintScratch>();
  return GearSolveVelocity(c.bodies, t.geometry, t.part);
}

inline bool GearConstraintSolvePosition(const StepPlan& plan, const ConstraintBlock& c,
                                        const StepScalars& step) {
  if (c.plan.helper1 == kNoConstraint) return false;
  auto& s = c.Main<GearConstraintLanes>();
  auto& t = c.Scratch<GearConstraintScratch>();
  const ConstraintBlock hinge1 = ConstraintInBlock(plan, c.plan.helper1, c.block);
  const ConstraintBlock hinge2 = ConstraintInBlock(plan, c.plan.helper2, c.block);
  ForEachChunk([&](std::size_t offset) {
    const LaneVec theta1 = AsSeenBy(hinge1, c.plan.body1,
                                    HingeUnwrappedAngleOfChunk(
                                        hinge1.bodies, hinge1.Main<HingeConstraintLanes>(), offset));
    const LaneVec theta2 = AsSeenBy(hinge2, c.plan.body2,
                                    HingeUnwrappedAngleOfChunk(
                                        hinge2.bodies, hinge2.Main<HingeConstraintLanes>(), offset));
    Store(hn::MulAdd(Load(t.geometry.ratio, offset), theta2, theta1), t.error, offset);
  });
  CouplingAxes(c.bodies, s.hinge_axis1_local, s.hinge_axis2_local, t.geometry.hinge_axis1,
               t.geometry.hinge_axis2);
  GearCalculateProperties(c.bodies, t.geometry, t.part);
  return GearSolvePosition(c.bodies, t.error, t.part, step.baumgarte);
}

// ---------------------------------------------------------------- rack

inline void RackAndPinionConstraintSetup(const ConstraintBlock& c, const StepScalars&) {
  auto& s = c.Main<RackAndPinionConstraintLanes>();
  auto& t = c.Scratch<RackAndPinionConstraintScratch>();
  CouplingAxes(c.bodies, s.hinge_axis1_local, s.slider_axis2_local, t.geometry.hinge_axis,
               t.geometry.slider_axis);
  RackAndPinionCalculateProperties(c.bodies, t.geometry, t.part);
}

inline void RackAndPinionConstraintWarmStart(const ConstraintBlock& c,
                                             const StepScalars& step) {
  RackAndPinionWarmStart(c.bodies, c.Scratch<RackAndPinionConstraintScratch>().part,
                         step.warm_start_ratio);
}

inline bool RackAndPinionConstraintSolveVelocity(const ConstraintBlock& c) {
  auto& t = c.Scratch<RackAndPinionConstraintScratch>();
  return RackAndPinionSolveVelocity(c.bodies, t.geometry, t.part);
}

inline bool RackAndPinionConstraintSolvePosition(const StepPlan& plan,
                                                 const ConstraintBlock& c,
                                                 const StepScalars& step) {
  if (c.plan.helper1 == kNoConstraint) return false;
  auto& s = c.Main<RackAndPinionConstraintLanes>();
  auto& t = c.Scratch<RackAndPinionConstraintScratch>();
  const ConstraintBlock hinge = ConstraintInBlock(plan, c.plan.helper1, c.block);
  const ConstraintBlock slider = ConstraintInBlock(plan, c.plan.helper2, c.block);
  ForEachChunk([&](std::size_t offset) {
    const LaneVec theta = AsSeenBy(
        hinge, c.plan.body1,
        HingeUnwrappedAngleOfChunk(hinge.bodies, hinge.Main<HingeConstraintLanes>(), offset));
    const LaneVec d = AsSeenBy(slider, c.plan.body2,
                               SliderCurrentPositionOfChunk(
                                   slider.bodies, slider.Main<SliderConstraintLanes>(), offset));
    Store(hn::NegMulAdd(Load(t.geometry.ratio, offset), d, theta), t.error, offset);
  });
  CouplingAxes(c.bodies, s.hinge_axis1_local, s.slider_axis2_local, t.geometry.hinge_axis,
               t.geometry.slider_axis);
  RackAndPinionCalculateProperties(c.bodies, t.geometry, t.part);
  return RackAndPinionSolvePosition(c.bodies, t.error, t.part, step.baumgarte);
}

}  // namespace HWY_NAMESPACE
}  // namespace manyworlds
HWY_AFTER_NAMESPACE();

#endif  // MANYWORLDS_BATCH_GEAR_CONSTRAINT_INL_H_
