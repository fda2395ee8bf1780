// RackAndPinionConstraintPart across worlds: couples the rotation of body 1
// (pinion, about world axis a) to the translation of body 2 (rack, along
// world axis b) with ratio r. Spec 2.9.
//
//   C = theta1 - r d2              J = [0, a, -r b, 0]  (body 1 positive)
//   K = a . I1^-1 a + r^2 m2^-1    (b . b = 1);  K == 0 => Deactivate
//   Velocity: dL = K^-1 (r b.v2 - a.w1), L += dL,
//             w1 += dL I1^-1 a, v2 -= dL r m2^-1 b
//   Position: where C != 0: L = -K^-1 beta C, rotate body 1 by +L I1^-1 a,
//             move body 2 by -L r m2^-1 b.
//
// Jolt quirks kept on purpose (spec 1.5): the mass terms of both bodies are
// always used and the velocity step writes both bodies whatever their motion
// type, so a kinematic pinion or rack is pushed by the constraint within the
// step. The position step only moves dynamic bodies. A static body is invalid
// (the scene refuses it); the kernel reads a static body as zero velocity and
// never writes it.

#if defined(MANYWORLDS_KERNELS_RACK_AND_PINION_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef MANYWORLDS_KERNELS_RACK_AND_PINION_INL_H_
#undef MANYWORLDS_KERNELS_RACK_AND_PINION_INL_H_
#else
#define MANYWORLDS_KERNELS_RACK_AND_PINION_INL_H_
#endif

#include <cstddef>

#include "kernels/body_access-inl.h"
#include "kernels/lane_math-inl.h"
#include "kernels/rack_and_pinion.h"

HWY_BEFORE_NAMESPACE();
namespace manyworlds {
namespace HWY_NAMESPACE {

namespace rack_and_pinion {

// Velocity step: w1 += lambda I1^-1 a, v2 -= lambda r m2^-1 b.
HWY_INLINE void ApplyVelocityStep(const BodyPair& bodies,
                                  const RackAndPinionLanes& part, LaneVec lambda,
                                  std::size_t offset) {
  if (bodies.motion1 != MotionType::kStatic) {
    AddAngularVelocityStep(
        *bodies.body1, Scale(LoadVec3(part.inv_i1_hinge_axis, offset), lambda),
        offset);
  }
  if (bodies.motion2 != MotionType::kStatic) {
    AddLinearVelocityStep(
        *bodies.body2,
        Scale(LoadVec3(part.ratio_inv_m2_slider_axis, offset), hn::Neg(lambda)),
        offset);
  }
}

}  // namespace rack_and_pinion

inline void RackAndPinionCalculateProperties(
    const BodyPair& bodies, const RackAndPinionGeometry& geometry,
    RackAndPinionLanes& part) {
  ForEachChunk([&](std::size_t offset) {
    const Vec3 hinge_axis = LoadVec3(geometry.hinge_axis, offset);
    const LaneVec ratio = Load(geometry.ratio, offset);
    const Vec3 inv_i1_a =
        BodyInverseInertiaTimes(*bodies.body1, hinge_axis, offset);
    const LaneVec inv_m2 = Load(bodies.body2->inv_mass, offset);
    const Vec3 ratio_inv_m2_b =
        Scale(LoadVec3(geometry.slider_axis, offset), hn::Mul(ratio, inv_m2));
    const LaneVec k =
        hn::MulAdd(hn::Mul(ratio, ratio), inv_m2, Dot(hinge_axis, inv_i1_a));
    LaneMask active;
    const LaneVec effective_mass = ReciprocalOrZero(k, active);
    StoreVec3(inv_i1_a, part.inv_i1_hinge_axis, offset);
    StoreVec3(ratio_inv_m2_b, part.ratio_inv_m2_slider_axis, offset);
    Store(effective_mass, part.effective_mass, offset);
    LaneArray& lambda = part.persistent.total_lambda;
    Store(hn::IfThenElseZero(active, Load(lambda, offset)), lambda, offset);
  });
}

inline void RackAndPinionWarmStart(const BodyPair& bodies,
                                       RackAndPinionLanes& part,
                                       float warm_start_ratio) {
  const LaneVec ratio = Splat(warm_start_ratio);
  ForEachChunk([&](std::size_t offset) {
    LaneArray& total = part.persistent.total_lambda;
    const LaneVec lambda = hn::Mul(Load(total, offset), ratio);
    Store(lambda, total, offset);
    rack_and_pinion::ApplyVelocityStep(bodies, part, lambda, offset);
  });
}

// Returns true if any lane applied a non-zero impulse.
inline bool RackAndPinionSolveVelocity(const BodyPair& bodies,
                                           const RackAndPinionGeometry& geometry,
                                           RackAndPinionLanes& part) {
  bool applied = false;
  ForEachChunk([&](std::size_t offset) {
    const Vec3 w1 = AngularVelocity(*bodies.body1, bodies.motion1, offset);
    const Vec3 v2 = LinearVelocity(*bodies.body2, bodies.motion2, offset);
    // -J v = r b.v2 - a.w1
    const LaneVec minus_jv =
        hn::MulSub(Load(geometry.ratio, offset),
                   Dot(LoadVec3(geometry.slider_axis, offset), v2),
                   Dot(LoadVec3(geometry.hinge_axis, offset), w1));
    const LaneVec delta = hn::Mul(Load(part.effective_mass, offset), minus_jv);
    LaneArray& total = part.persistent.total_lambda;
    Store(hn::Add(Load(total, offset), delta), total, offset);
    rack_and_pinion::ApplyVelocityStep(bodies, part, delta, offset);
    applied |= AnyLane(hn::Ne(delta, Zero()));
  });
  return applied;
}

// Baumgarte step for the caller's position error C (theta1 - r d2, wrapped by
// the caller). Returns true if any lane had a non-zero error.
inline bool RackAndPinionSolvePosition(const BodyPair& bodies,
                                           const LaneArray& error,
                                           const RackAndPinionLanes& part,
                                           float baumgarte) {
  const LaneVec minus_beta = Splat(-baumgarte);
  bool applied = false;
  ForEachChunk([&](std::size_t offset) {
    const LaneVec c = Load(error, offset);
    const LaneMask has_error = hn::Ne(c, Zero());
    const LaneVec lambda = hn::IfThenElseZero(
        has_error, hn::Mul(hn::Mul(minus_beta, Load(part.effective_mass, offset)), c));
    if (bodies.motion1 == MotionType::kDynamic) {
      AddRotationStep(*bodies.body1,
                      Scale(LoadVec3(part.inv_i1_hinge_axis, offset), lambda),
                      offset);
    }
    if (bodies.motion2 == MotionType::kDynamic) {
      AddPositionStep(*bodies.body2,
                      Scale(LoadVec3(part.ratio_inv_m2_slider_axis, offset),
                            hn::Neg(lambda)),
                      offset);
    }
    applied |= AnyLane(has_error);
  });
  return applied;
}

// Jolt's Deactivate of the flagged lanes: K^-1 = 0 and accumulated impulse = 0.
inline void RackAndPinionDeactivate(RackAndPinionLanes& part, const LaneFlags& lanes) {
  DeactivateFlaggedLanes(part, lanes);
}

// flag = 1 where K^-1 != 0 (Jolt's IsActive), else 0.
inline void RackAndPinionIsActive(const RackAndPinionLanes& part, LaneFlags& active) {
  StoreActiveLanes(part, active);
}

}  // namespace HWY_NAMESPACE
}  // namespace manyworlds
HWY_AFTER_NAMESPACE();

#endif  // MANYWORLDS_KERNELS_RACK_AND_PINION_INL_H_
