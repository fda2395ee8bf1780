// AxisConstraintPart across worlds: one linear row along a world axis, with
// clamped impulse (limits, motor force limits) and an optional spring. Used by
// distance, slider limits and motors, six-DOF translation and path
// constraints. Spec 2.2, springs 2.1 (kernels/spring-inl.h).
//
//   n = world axis (unit, from body 1 towards body 2), u = p2 - p1,
//   lever arms r1 + u = p2 - x1, r2 = p2 - x2, C = u . n (or the caller's)
//   J = [ -n, -((r1 + u) x n), n, r2 x n ]   (Chappuis 2.1.1, eq. 55)
//   a1 = (r1 + u) x n, a2 = r2 x n
//   K = [dyn1] (m1^-1 + a1 . I1^-1 a1) + [dyn2] (m2^-1 + a2 . I2^-1 a2)
//       (inertia at the current rotation, vector form);  K == 0 => Deactivate
//   m_eff = 1/K, or 1/(K + gamma) for a soft lane (spring-inl.h)
//
// Velocity step:  dL = m_eff (n.(v1 - v2) + a1.w1 - a2.w2 - (gamma L + b));
//                 clamp L + dL to [min, max];
//                 v1 -= dL m1^-1 n, w1 -= dL I1^-1 a1, v2 += dL m2^-1 n,
//                 w2 += dL I2^-1 a2.
// Position step:  where C != 0 and the lane is hard: L = -m_eff beta C,
//                 x1 -= L m1^-1 n, rotate body 1 by -L I1^-1 a1, body 2 +.
// Motion types (spec 1.5): a body's Jacobian terms exist unless it is static
// (a kinematic body's velocity counts), its mass terms only if it is dynamic,
// and only dynamic bodies are written.
//
// The *Chunk functions work on one chunk (`offset`) with the per-world inputs
// as values, for constraints that compute their axes per chunk; the block
// verbs below them load an AxisGeometry and loop over the chunks.

#if defined(MANYWORLDS_KERNELS_AXIS_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef MANYWORLDS_KERNELS_AXIS_INL_H_
#undef MANYWORLDS_KERNELS_AXIS_INL_H_
#else
#define MANYWORLDS_KERNELS_AXIS_INL_H_
#endif

#include <cstddef>

#include "kernels/axis.h"
#include "kernels/body_access-inl.h"
#include "kernels/lane_math-inl.h"
#include "kernels/spring-inl.h"

HWY_BEFORE_NAMESPACE();
namespace manyworlds {
namespace HWY_NAMESPACE {

// ------------------------------------------------------------ chunk helpers

// Applies the impulse lambda along the row: body 1 gets -J^T lambda, body 2
// +J^T lambda (dynamic bodies only). kVelocity = false makes it a position
// and rotation step.
template <bool kVelocity>
HWY_INLINE void AxisApplyImpulseChunk(const BodyPair& bodies, const Vec3& axis,
                                      const AxisProperties& properties, LaneVec lambda,
                                      std::size_t offset) {
  if (bodies.motion1 == MotionType::kDynamic) {
    const LaneVec minus_lambda = hn::Neg(lambda);
    const Vec3 linear =
        Scale(axis, hn::Mul(minus_lambda, Load(bodies.body1->inv_mass, offset)));
    const Vec3 angular =
        Scale(LoadVec3(properties.inv_i1_r1_plus_u_x_axis, offset), minus_lambda);
    if (kVelocity) {
      AddVelocityStep(*bodies.body1, linear, angular, offset);
    } else {
      AddPositionStep(*bodies.body1, linear, offset);
      AddRotationStep(*bodies.body1, angular, offset);
    }
  }
  if (bodies.motion2 == MotionType::kDynamic) {
    const Vec3 linear = Scale(axis, hn::Mul(lambda, Load(bodies.body2->inv_mass, offset)));
    const Vec3 angular = Scale(LoadVec3(properties.inv_i2_r2_x_axis, offset), lambda);
    if (kVelocity) {
      AddVelocityStep(*bodies.body2, linear, angular, offset);
    } else {
      AddPositionStep(*bodies.body2, linear, offset);
      AddRotationStep(*bodies.body2, angular, offset);
    }
  }
}

// Caches the angular Jacobian rows and I^-1 a and, from K, the effective mass
// and spring of one chunk. kUse / kMode pick Jolt's variant (spring-inl.h);
// K == 0 deactivates.
template <SpringUse kUse, SpringMode kMode>
HWY_INLINE void AxisCalculatePropertiesChunk(const BodyPair& bodies, const Vec3& r1_plus_u,
                                             const Vec3& r2, const Vec3& axis,
                                             const SpringInputs& spring, LaneVec delta_time,
                                             AxisProperties& properties,
                                             LaneArray& total_lambda, std::size_t offset) {
  // Unused caches stay zero so that 0 * cache is 0 in every later verb.
  Vec3 a1 = ZeroVec3(), a2 = ZeroVec3();
  Vec3 inv_i1_a1 = ZeroVec3(), inv_i2_a2 = ZeroVec3();
  LaneVec inv_effective_mass = Zero();
  if (bodies.motion1 != MotionType::kStatic) a1 = Cross(r1_plus_u, axis);
  if (bodies.motion2 != MotionType::kStatic) a2 = Cross(r2, axis);
  if (bodies.motion1 == MotionType::kDynamic) {
    inv_i1_a1 = BodyInverseInertiaTimes(*bodies.body1, a1, offset);
    inv_effective_mass = hn::Add(Load(bodies.body1->inv_mass, offset), Dot(a1, inv_i1_a1));
  }
  if (bodies.motion2 == MotionType::kDynamic) {
    inv_i2_a2 = BodyInverseInertiaTimes(*bodies.body2, a2, offset);
    inv_effective_mass = hn::Add(
        inv_effective_mass, hn::Add(Load(bodies.body2->inv_mass, offset), Dot(a2, inv_i2_a2)));
  }
  StoreVec3(a1, properties.r1_plus_u_x_axis, offset);
  StoreVec3(a2, properties.r2_x_axis, offset);
  StoreVec3(inv_i1_a1, properties.inv_i1_r1_plus_u_x_axis, offset);
  StoreVec3(inv_i2_a2, properties.inv_i2_r2_x_axis, offset);
  StoreEffectiveMassAndSpring<kUse, kMode>(inv_effective_mass, spring, delta_time,
                                           properties.effective_mass, properties.spring,
                                           total_lambda, offset);
}

// The plain variant: hard in every lane with velocity bias `bias`.
HWY_INLINE void AxisCalculatePropertiesChunk(const BodyPair& bodies, const Vec3& r1_plus_u,
                                             const Vec3& r2, const Vec3& axis, LaneVec bias,
                                             AxisProperties& properties,
                                             LaneArray& total_lambda, std::size_t offset) {
  const SpringInputs hard{bias, Zero(), Zero(), Zero()};
  AxisCalculatePropertiesChunk<SpringUse::kNever, SpringMode::kFrequencyAndDamping>(
      bodies, r1_plus_u, r2, axis, hard, Zero(), properties, total_lambda, offset);
}

// L *= ratio, then applies L.
HWY_INLINE void AxisWarmStartChunk(const BodyPair& bodies, const Vec3& axis, LaneVec ratio,
                                   const AxisProperties& properties,
                                   LaneArray& total_lambda, std::size_t offset) {
  const LaneVec lambda = hn::Mul(Load(total_lambda, offset), ratio);
  Store(lambda, total_lambda, offset);
  AxisApplyImpulseChunk<true>(bodies, axis, properties, lambda, offset);
}

// One velocity iteration; returns the lanes that applied a non-zero impulse.
HWY_INLINE LaneMask AxisSolveVelocityChunk(const BodyPair& bodies, const Vec3& axis,
                                           LaneVec min_lambda, LaneVec max_lambda,
                                           const AxisProperties& properties,
                                           LaneArray& total_lambda, std::size_t offset) {
  // -J v = n.(v1 - v2) + a1.w1 - a2.w2; a static body has no terms.
  LaneVec minus_jv = Zero();
  if (bodies.motion1 != MotionType::kStatic) {
    minus_jv = hn::Add(Dot(axis, LoadVec3(bodies.body1->linear_velocity, offset)),
                       Dot(LoadVec3(properties.r1_plus_u_x_axis, offset),
                           LoadVec3(bodies.body1->angular_velocity, offset)));
  }
  if (bodies.motion2 != MotionType::kStatic) {
    minus_jv = hn::Sub(minus_jv,
                       hn::Add(Dot(axis, LoadVec3(bodies.body2->linear_velocity, offset)),
                               Dot(LoadVec3(properties.r2_x_axis, offset),
                                   LoadVec3(bodies.body2->angular_velocity, offset))));
  }
  const LaneVec delta =
      SolveSpringRowImpulse(minus_jv, min_lambda, max_lambda, properties.effective_mass,
                            properties.spring, total_lambda, offset);
  AxisApplyImpulseChunk<true>(bodies, axis, properties, delta, offset);
  return hn::Ne(delta, Zero());
}

// One Baumgarte step on the error C; returns the lanes that took a step
// (C != 0 and hard).
HWY_INLINE LaneMask AxisSolvePositionChunk(const BodyPair& bodies, const Vec3& axis,
                                           LaneVec error, LaneVec baumgarte,
                                           const AxisProperties& properties,
                                           std::size_t offset) {
  LaneMask applies;
  const LaneVec lambda = SpringRowBaumgarteImpulse(
      error, baumgarte, properties.effective_mass, properties.spring, offset, applies);
  AxisApplyImpulseChunk<false>(bodies, axis, properties, lambda, offset);
  return applies;
}

// Deactivate where `off`: effective mass and impulse zero.
HWY_INLINE void AxisDeactivateChunk(LaneMask off, AxisProperties& properties,
                                    LaneArray& total_lambda, std::size_t offset) {
  DeactivateSpringRow(off, properties.effective_mass, total_lambda, offset);
}

// Jolt's IsActive: effective mass != 0.
HWY_INLINE LaneMask AxisIsActiveChunk(const AxisProperties& properties,
                                      std::size_t offset) {
  return hn::Ne(Load(properties.effective_mass, offset), Zero());
}

// ------------------------------------------------------------ block verbs

template <SpringUse kUse, SpringMode kMode>
inline void AxisCalculatePropertiesOfBlock(const BodyPair& bodies,
                                           const AxisGeometry& geometry, AxisLanes& part,
                                           float delta_time) {
  const LaneVec dt = Splat(delta_time);
  ForEachChunk([&](std::size_t offset) {
    AxisCalculatePropertiesChunk<kUse, kMode>(
        bodies, LoadVec3(geometry.r1_plus_u, offset), LoadVec3(geometry.r2, offset),
        LoadVec3(geometry.axis, offset),
        LoadSpringInputs(geometry.bias, geometry.error, geometry.spring, offset), dt,
        part.properties, part.persistent.total_lambda, offset);
  });
}

inline void AxisCalculateProperties(const BodyPair& bodies, const AxisGeometry& geometry,
                                    AxisLanes& part) {
  AxisCalculatePropertiesOfBlock<SpringUse::kNever, SpringMode::kFrequencyAndDamping>(
      bodies, geometry, part, 0.0f);
}

inline void AxisCalculatePropertiesWithFrequencyAndDamping(const BodyPair& bodies,
                                                           const AxisGeometry& geometry,
                                                           AxisLanes& part,
                                                           float delta_time) {
  AxisCalculatePropertiesOfBlock<SpringUse::kIfStiffnessOrDamping,
                                 SpringMode::kFrequencyAndDamping>(bodies, geometry, part,
                                                                   delta_time);
}

inline void AxisCalculatePropertiesWithStiffnessAndDamping(const BodyPair& bodies,
                                                           const AxisGeometry& geometry,
                                                           AxisLanes& part,
                                                           float delta_time) {
  AxisCalculatePropertiesOfBlock<SpringUse::kIfStiffnessOrDamping,
                                 SpringMode::kStiffnessAndDamping>(bodies, geometry, part,
                                                                   delta_time);
}

inline void AxisCalculatePropertiesForLimit(const BodyPair& bodies,
                                            const AxisGeometry& geometry, AxisLanes& part,
                                            float delta_time, SpringMode mode) {
  WithSpringMode(mode, [&](auto kMode) {
    AxisCalculatePropertiesOfBlock<SpringUse::kIfStiffness, decltype(kMode)::value>(
        bodies, geometry, part, delta_time);
  });
}

inline void AxisCalculatePropertiesForMotor(const BodyPair& bodies,
                                            const AxisGeometry& geometry, AxisLanes& part,
                                            float delta_time, SpringMode mode) {
  WithSpringMode(mode, [&](auto kMode) {
    AxisCalculatePropertiesOfBlock<SpringUse::kIfStiffnessOrDamping,
                                   decltype(kMode)::value>(bodies, geometry, part,
                                                           delta_time);
  });
}

inline void AxisWarmStart(const BodyPair& bodies, const AxisGeometry& geometry,
                          AxisLanes& part, float warm_start_ratio) {
  const LaneVec ratio = Splat(warm_start_ratio);
  ForEachChunk([&](std::size_t offset) {
    AxisWarmStartChunk(bodies, LoadVec3(geometry.axis, offset), ratio, part.properties,
                       part.persistent.total_lambda, offset);
  });
}

// Returns true if any lane applied a non-zero impulse.
inline bool AxisSolveVelocity(const BodyPair& bodies, const AxisGeometry& geometry,
                              AxisLanes& part) {
  bool applied = false;
  ForEachChunk([&](std::size_t offset) {
    applied |= AnyLane(AxisSolveVelocityChunk(
        bodies, LoadVec3(geometry.axis, offset), Load(geometry.min_lambda, offset),
        Load(geometry.max_lambda, offset), part.properties, part.persistent.total_lambda,
        offset));
  });
  return applied;
}

// Returns true if any lane took a position step.
inline bool AxisSolvePosition(const BodyPair& bodies, const AxisGeometry& geometry,
                              const AxisLanes& part, float baumgarte) {
  const LaneVec beta = Splat(baumgarte);
  bool applied = false;
  ForEachChunk([&](std::size_t offset) {
    applied |= AnyLane(AxisSolvePositionChunk(bodies, LoadVec3(geometry.axis, offset),
                                              Load(geometry.error, offset), beta,
                                              part.properties, offset));
  });
  return applied;
}

inline void AxisDeactivate(AxisLanes& part, const LaneFlags& lanes) {
  ForEachChunk([&](std::size_t offset) {
    AxisDeactivateChunk(LoadFlags(lanes, offset), part.properties,
                        part.persistent.total_lambda, offset);
  });
}

inline void AxisIsActive(const AxisLanes& part, LaneFlags& active) {
  ForEachChunk([&](std::size_t offset) {
    StoreFlags(AxisIsActiveChunk(part.properties, offset), active, offset);
  });
}

}  // namespace HWY_NAMESPACE
}  // namespace manyworlds
HWY_AFTER_NAMESPACE();

#endif  // MANYWORLDS_KERNELS_AXIS_INL_H_
