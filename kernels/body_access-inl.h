// Reading and writing a body's lanes from part kernels, with Jolt's rules for
// static, kinematic and dynamic bodies (spec 1.5): static bodies read as zero
// velocity, only the bodies a part is allowed to move are ever stored.
//
// Allowed degrees of freedom (Jolt's EAllowedDOFs, spec 4.3 and 1.1): every
// linear velocity write is v <- lockT(v + dv) and every position step
// x <- x + lockT(dx), with lockT zeroing the locked world axes; the world
// inverse inertia has the rows and columns of locked rotation axes zeroed (the
// vector form masks its input and its output). Angular velocity and rotation
// steps are not masked again: they only ever come out of the masked inertia.
// The masks cost nothing for unrestricted bodies: body.dof_restricted is the
// same in every lane, so lane 0 decides a predictable scalar branch (and only
// restricted bodies store locks, BodyLockLanes). Masking is a select, so
// locked components are exactly +0 (as Jolt's bitwise AND).

#if defined(MANYWORLDS_KERNELS_BODY_ACCESS_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef MANYWORLDS_KERNELS_BODY_ACCESS_INL_H_
#undef MANYWORLDS_KERNELS_BODY_ACCESS_INL_H_
#else
#define MANYWORLDS_KERNELS_BODY_ACCESS_INL_H_
#endif

#include <cstddef>

#include "kernels/body_lanes.h"
#include "kernels/lane_math-inl.h"

HWY_BEFORE_NAMESPACE();
namespace manyworlds {
namespace HWY_NAMESPACE {

// True if any axis of the body is locked (uniform across lanes).
HWY_INLINE bool DofRestricted(const BodyLanes& body) {
  return body.dof_restricted[0] != 0.0f;
}

// v with the components of locked axes (non-zero lock entries) set to +0.
HWY_INLINE Vec3 MaskAxes(const Vec3Lanes& locked, const Vec3& v, std::size_t offset) {
  return {hn::IfThenElseZero(hn::Eq(Load(locked.x, offset), Zero()), v.x),
          hn::IfThenElseZero(hn::Eq(Load(locked.y, offset), Zero()), v.y),
          hn::IfThenElseZero(hn::Eq(Load(locked.z, offset), Zero()), v.z)};
}

// Jolt's MotionProperties::LockTranslation: v without the locked axes.
HWY_INLINE Vec3 LockTranslation(const BodyLanes& body, const Vec3& v,
                                std::size_t offset) {
  if (!DofRestricted(body)) return v;
  return MaskAxes(Locks(body).translation_locked, v, offset);
}

// Velocities as Body::GetLinear/AngularVelocity return them: zero if static.
HWY_INLINE Vec3 LinearVelocity(const BodyLanes& body, MotionType motion,
                               std::size_t offset) {
  return motion == MotionType::kStatic ? ZeroVec3()
                                       : LoadVec3(body.linear_velocity, offset);
}
HWY_INLINE Vec3 AngularVelocity(const BodyLanes& body, MotionType motion,
                                std::size_t offset) {
  return motion == MotionType::kStatic ? ZeroVec3()
                                       : LoadVec3(body.angular_velocity, offset);
}

// World-space inverse inertia at the body's current rotation (matrix form),
// rows and columns of locked rotation axes zeroed (Jolt's
// GetInverseInertiaForRotation).
HWY_INLINE Sym33 BodyInverseInertia(const BodyLanes& body, std::size_t offset) {
  Sym33 inverse = WorldInverseInertia(LoadQuat(body.rotation, offset),
                                      LoadQuat(body.inertia_rotation, offset),
                                      LoadVec3(body.inv_inertia_diagonal, offset));
  if (!DofRestricted(body)) return inverse;
  const Vec3Lanes& locked = Locks(body).rotation_locked;
  const LaneMask x = hn::Eq(Load(locked.x, offset), Zero());
  const LaneMask y = hn::Eq(Load(locked.y, offset), Zero());
  const LaneMask z = hn::Eq(Load(locked.z, offset), Zero());
  inverse.xx = hn::IfThenElseZero(x, inverse.xx);
  inverse.xy = hn::IfThenElseZero(x, inverse.xy);
  inverse.xz = hn::IfThenElseZero(x, inverse.xz);
  inverse.yy = hn::IfThenElseZero(y, inverse.yy);
  inverse.yz = hn::IfThenElseZero(hn::And(y, z), inverse.yz);
  inverse.zz = hn::IfThenElseZero(z, inverse.zz);
  return inverse;
}

// I^-1 v at the body's current rotation (vector form, spec 1.4): mask(v),
// rotate into inertia space, scale, rotate back, mask (Jolt's
// MultiplyWorldSpaceInverseInertiaByVector).
HWY_INLINE Vec3 BodyInverseInertiaTimes(const BodyLanes& body, const Vec3& v,
                                        std::size_t offset) {
  const Quat rotation = LoadQuat(body.rotation, offset);
  const Quat inertia_rotation = LoadQuat(body.inertia_rotation, offset);
  const Vec3 diagonal = LoadVec3(body.inv_inertia_diagonal, offset);
  if (!DofRestricted(body)) {
    return MultiplyWorldInverseInertia(rotation, inertia_rotation, diagonal, v);
  }
  const Vec3Lanes& locked = Locks(body).rotation_locked;
  return MaskAxes(locked,
                  MultiplyWorldInverseInertia(rotation, inertia_rotation, diagonal,
                                              MaskAxes(locked, v, offset)),
                  offset);
}

// The lanes of a solve's chunk that take a step: those whose -J v (velocity
// phase) or C (position phase) is not exactly zero. A lane with a zero takes
// no step at all, which is what Jolt does up to the sign of a zero (it adds
// the zero impulse K^-1 0 to the accumulated one) and keeps a non-finite
// K^-1 from making a NaN of it; a chunk where no lane steps skips the rest
// of the solve (docs/stepping.md, "Work skipped where no world of a block
// needs it"). A chunk where every lane steps takes the step without selects
// (where = nullptr below).
struct SteppingLanes {
  LaneMask mask;
  bool every;
  bool none;
};
HWY_INLINE SteppingLanes LanesThatStep(LaneMask non_zero) {
  return {non_zero, hn::AllTrue(LaneTag(), non_zero), hn::AllFalse(LaneTag(), non_zero)};
}

// `stepped` in the lanes of *where (every lane for nullptr), `kept` elsewhere.
HWY_INLINE Vec3 KeepUnless(std::nullptr_t, const Vec3& stepped, const Vec3&) { return stepped; }
HWY_INLINE Vec3 KeepUnless(const LaneMask* where, const Vec3& stepped, const Vec3& kept) {
  return Select(*where, stepped, kept);
}

// v <- lockT(v + dv), w += dw (a velocity step; callers pass signed
// increments), in the lanes of *where only (every lane for nullptr): the
// others keep every bit.
template <class Where = std::nullptr_t>
HWY_INLINE void AddVelocityStep(BodyLanes& body, const Vec3& linear_delta,
                                const Vec3& angular_delta, std::size_t offset,
                                Where where = nullptr) {
  const Vec3 v = LoadVec3(body.linear_velocity, offset);
  const Vec3 w = LoadVec3(body.angular_velocity, offset);
  StoreVec3(KeepUnless(where, LockTranslation(body, Add(v, linear_delta), offset), v),
            body.linear_velocity, offset);
  StoreVec3(KeepUnless(where, Add(w, angular_delta), w), body.angular_velocity, offset);
}
template <class Where = std::nullptr_t>
HWY_INLINE void AddAngularVelocityStep(BodyLanes& body, const Vec3& delta, std::size_t offset,
                                       Where where = nullptr) {
  const Vec3 w = LoadVec3(body.angular_velocity, offset);
  StoreVec3(KeepUnless(where, Add(w, delta), w), body.angular_velocity, offset);
}
HWY_INLINE void AddLinearVelocityStep(BodyLanes& body, const Vec3& delta,
                                      std::size_t offset) {
  StoreVec3(LockTranslation(body, Add(LoadVec3(body.linear_velocity, offset), delta), offset),
            body.linear_velocity, offset);
}

// x += lockT(dx) (Jolt's AddPositionStep), in the lanes of *where only
// (every lane for nullptr).
template <class Where = std::nullptr_t>
HWY_INLINE void AddPositionStep(BodyLanes& body, const Vec3& delta, std::size_t offset,
                                Where where = nullptr) {
  const Vec3 x = LoadVec3(body.position, offset);
  StoreVec3(KeepUnless(where, Add(x, LockTranslation(body, delta, offset)), x), body.position,
            offset);
}

// q <- quat(theta) * q in lanes with |theta| > 1e-6 (Jolt's AddRotationStep).
HWY_INLINE void AddRotationStep(BodyLanes& body, const Vec3& theta,
                                std::size_t offset) {
  StoreQuat(AddRotationStep(LoadQuat(body.rotation, offset), theta),
            body.rotation, offset);
}

}  // namespace HWY_NAMESPACE
}  // namespace manyworlds
HWY_AFTER_NAMESPACE();

#endif  // MANYWORLDS_KERNELS_BODY_ACCESS_INL_H_
