// GearConstraintPart across worlds: couples the rotation of body 1 about world
// axis a to the rotation of body 2 about world axis b with ratio r (gears turn
// in opposite directions). Spec 2.10.
//
//   C = theta1 + r theta2              J = [0, a, 0, r b]  (both positive)
//   K = J M^-1 J^T = a . I1^-1 a + r^2 b . I2^-1 b;  K == 0 => Deactivate
//   Velocity: dL = -K^-1 (a.w1 + r b.w2), L += dL, w += M^-1 J^T dL:
//             w1 += dL I1^-1 a,  w2 += dL r I2^-1 b
//   Position: where C != 0: L = -K^-1 beta C, rotate body 1 by +L I1^-1 a,
//             body 2 by +L r I2^-1 b.
//
// Where we differ from Jolt (docs/constraint-parts.md): Jolt applies body 2's
// impulse as dL I2^-1 b, without the r that J^T requires. Its iterations still
// converge to J v = 0 for moderate r, but the torque transmitted to gear 2 is
// 1:1 instead of 1:r and the result is not the mass-weighted projection onto
// J v = 0. We apply J^T dL exactly: caching r I2^-1 b makes body 2 carry r in
// the velocity step, the warm start and the position step alike.
//
// Jolt quirks kept on purpose (spec 1.5), as in rack-and-pinion: the inertia of
// both bodies is always used and the velocity step writes both bodies whatever
// their motion type; the position step only rotates dynamic bodies. A static
// body is refused when the part is bound; the kernel would read it as zero
// velocity and never write it.

#if defined(MANYWORLDS_KERNELS_GEAR_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef MANYWORLDS_KERNELS_GEAR_INL_H_
#undef MANYWORLDS_KERNELS_GEAR_INL_H_
#else
#define MANYWORLDS_KERNELS_GEAR_INL_H_
#endif

#include <cstddef>

#include "kernels/body_access-inl.h"
#include "kernels/gear.h"
#include "kernels/lane_math-inl.h"

HWY_BEFORE_NAMESPACE();
namespace manyworlds {
namespace HWY_NAMESPACE {

namespace gear {

// Velocity step w += M^-1 J^T lambda: w1 += lambda I1^-1 a, w2 += lambda r I2^-1 b.
HWY_INLINE void ApplyVelocityStep(const BodyPair& bodies, const GearLanes& part,
                                  LaneVec lambda, std::size_t offset) {
  if (bodies.motion1 != MotionType::kStatic) {
    AddAngularVelocityStep(
        *bodies.body1, Scale(LoadVec3(part.inv_i1_hinge_axis1, offset), lambda), offset);
  }
  if (bodies.motion2 != MotionType::kStatic) {
    AddAngularVelocityStep(
        *bodies.body2, Scale(LoadVec3(part.ratio_inv_i2_hinge_axis2, offset), lambda),
        offset);
  }
}

}  // namespace gear

inline void GearCalculateProperties(const BodyPair& bodies, const GearGeometry& geometry,
                                    GearLanes& part) {
  ForEachChunk([&](std::size_t offset) {
    const Vec3 hinge_axis1 = LoadVec3(geometry.hinge_axis1, offset);
    const Vec3 hinge_axis2 = LoadVec3(geometry.hinge_axis2, offset);
    const LaneVec ratio = Load(geometry.ratio, offset);
    const Vec3 inv_i1_a = BodyInverseInertiaTimes(*bodies.body1, hinge_axis1, offset);
    const Vec3 ratio_inv_i2_b = Scale(
        BodyInverseInertiaTimes(*bodies.body2, hinge_axis2, offset), ratio);
    // r^2 b.I2^-1 b = (r b).(r I2^-1 b)
    const LaneVec k = hn::MulAdd(ratio, Dot(hinge_axis2, ratio_inv_i2_b),
                                 Dot(hinge_axis1, inv_i1_a));
    LaneMask active;
    const LaneVec effective_mass = ReciprocalOrZero(k, active);
    StoreVec3(inv_i1_a, part.inv_i1_hinge_axis1, offset);
    StoreVec3(ratio_inv_i2_b, part.ratio_inv_i2_hinge_axis2, offset);
    Store(effective_mass, part.effective_mass, offset);
    LaneArray& lambda = part.persistent.total_lambda;
    Store(hn::IfThenElseZero(active, Load(lambda, offset)), lambda, offset);
  });
}

inline void GearWarmStart(const BodyPair& bodies, GearLanes& part,
                          float warm_start_ratio) {
  const LaneVec ratio = Splat(warm_start_ratio);
  ForEachChunk([&](std::size_t offset) {
    LaneArray& total = part.persistent.total_lambda;
    const LaneVec lambda = hn::Mul(Load(total, offset), ratio);
    Store(lambda, total, offset);
    gear::ApplyVelocityStep(bodies, part, lambda, offset);
  });
}

// Returns true if any lane applied a non-zero impulse.
inline bool GearSolveVelocity(const BodyPair& bodies, const GearGeometry& geometry,
                              GearLanes& part) {
  bool applied = false;
  ForEachChunk([&](std::size_t offset) {
    const Vec3 w1 = AngularVelocity(*bodies.body1, bodies.motion1, offset);
    const Vec3 w2 = AngularVelocity(*bodies.body2, bodies.motion2, offset);
    // J v = a.w1 + r b.w2
    const LaneVec jv = hn::MulAdd(Load(geometry.ratio, offset),
                                  Dot(LoadVec3(geometry.hinge_axis2, offset), w2),
                                  Dot(LoadVec3(geometry.hinge_axis1, offset), w1));
    const LaneVec delta = hn::Neg(hn::Mul(Load(part.effective_mass, offset), jv));
    LaneArray& total = part.persistent.total_lambda;
    Store(hn::Add(Load(total, offset), delta), total, offset);
    gear::ApplyVelocityStep(bodies, part, delta, offset);
    applied |= AnyLane(hn::Ne(delta, Zero()));
  });
  return applied;
}

// Baumgarte step for the caller's position error C (theta1 + r theta2, wrapped
// by the caller). Returns true if any lane had a non-zero error.
inline bool GearSolvePosition(const BodyPair& bodies, const LaneArray& error,
                              const GearLanes& part, float baumgarte) {
  const LaneVec minus_beta = Splat(-baumgarte);
  bool applied = false;
  ForEachChunk([&](std::size_t offset) {
    const LaneVec c = Load(error, offset);
    const LaneMask has_error = hn::Ne(c, Zero());
    const LaneVec lambda = hn::IfThenElseZero(
        has_error, hn::Mul(hn::Mul(minus_beta, Load(part.effective_mass, offset)), c));
    if (bodies.motion1 == MotionType::kDynamic) {
      AddRotationStep(*bodies.body1,
                      Scale(LoadVec3(part.inv_i1_hinge_axis1, offset), lambda), offset);
    }
    if (bodies.motion2 == MotionType::kDynamic) {
      AddRotationStep(*bodies.body2,
                      Scale(LoadVec3(part.ratio_inv_i2_hinge_axis2, offset), lambda),
                      offset);
    }
    applied |= AnyLane(has_error);
  });
  return applied;
}

// Jolt's Deactivate of the flagged lanes: K^-1 = 0 and accumulated impulse = 0.
inline void GearDeactivate(GearLanes& part, const LaneFlags& lanes) {
  DeactivateFlaggedLanes(part, lanes);
}

// flag = 1 where K^-1 != 0 (Jolt's IsActive), else 0.
inline void GearIsActive(const GearLanes& part, LaneFlags& active) {
  StoreActiveLanes(part, active);
}

}  // namespace HWY_NAMESPACE
}  // namespace manyworlds
HWY_AFTER_NAMESPACE();

#endif  // MANYWORLDS_KERNELS_GEAR_INL_H_
