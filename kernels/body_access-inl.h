// Reading and writing a body's lanes from part kernels, with Jolt's rules for
// static, kinematic and dynamic bodies (spec 1.5): static bodies read as zero
// velocity, only the bodies a part is allowed to move are ever stored.

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

// World-space inverse inertia at the body's current rotation (matrix form).
HWY_INLINE Sym33 BodyInverseInertia(const BodyLanes& body, std::size_t offset) {
  return WorldInverseInertia(LoadQuat(body.rotation, offset),
                             LoadQuat(body.inertia_rotation, offset),
                             LoadVec3(body.inv_inertia_diagonal, offset));
}

// I^-1 v at the body's current rotation (vector form, spec 1.4).
HWY_INLINE Vec3 BodyInverseInertiaTimes(const BodyLanes& body, const Vec3& v,
                                        std::size_t offset) {
  return MultiplyWorldInverseInertia(LoadQuat(body.rotation, offset),
                                     LoadQuat(body.inertia_rotation, offset),
                                     LoadVec3(body.inv_inertia_diagonal, offset),
                                     v);
}

// v += dv, w += dw (a velocity step; callers pass signed increments).
HWY_INLINE void AddVelocityStep(BodyLanes& body, const Vec3& linear_delta,
                                const Vec3& angular_delta, std::size_t offset) {
  StoreVec3(Add(LoadVec3(body.linear_velocity, offset), linear_delta),
            body.linear_velocity, offset);
  StoreVec3(Add(LoadVec3(body.angular_velocity, offset), angular_delta),
            body.angular_velocity, offset);
}
HWY_INLINE void AddAngularVelocityStep(BodyLanes& body, const Vec3& delta,
                                       std::size_t offset) {
  StoreVec3(Add(LoadVec3(body.angular_velocity, offset), delta),
            body.angular_velocity, offset);
}
HWY_INLINE void AddLinearVelocityStep(BodyLanes& body, const Vec3& delta,
                                      std::size_t offset) {
  StoreVec3(Add(LoadVec3(body.linear_velocity, offset), delta),
            body.linear_velocity, offset);
}

// x += dx (Jolt's AddPositionStep).
HWY_INLINE void AddPositionStep(BodyLanes& body, const Vec3& delta,
                                std::size_t offset) {
  StoreVec3(Add(LoadVec3(body.position, offset), delta), body.position, offset);
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
