// AngleConstraintPart across worlds: one angular row about a world axis, with
// clamped impulse (limits, motor force limits) and an optional spring. Used by
// hinge limits and motors, cone, swing-twist and six-DOF rotation motors.
// Spec 2.8, springs 2.1 (kernels/spring-inl.h).
//
//   a = world axis (unit), C = the caller's angle error (no wrapping here)
//   J = [0, -a, 0, a]
//   K = [dyn1] a . I1^-1 a + [dyn2] a . I2^-1 a  (inertia at the current
//       rotation, vector form, spec 1.4);  K == 0 => Deactivate
//   m_eff = 1/K, or 1/(K + gamma) for a soft lane (spring-inl.h)
//
// Velocity step:  dL = m_eff (a.(w1 - w2) - (gamma L + b)); clamp L + dL to
//                 [min, max]; w1 -= dL I1^-1 a, w2 += dL I2^-1 a.
// Position step:  where C != 0 and the lane is hard: L = -m_eff beta C;
//                 rotate body 1 by -L I1^-1 a, body 2 by +L I2^-1 a.
// Static bodies read as zero angular velocity; I^-1 a is zero unless the body
// is dynamic, and only dynamic bodies are written (spec 1.5).
//
// The *Chunk functions work on one chunk (`offset`) with the per-world inputs
// as values, so parts with several angle rows (swing-twist) call them with
// their own axes, errors and impulse arrays; the block verbs below them load
// an AngleGeometry and loop over the chunks.

#if defined(MANYWORLDS_KERNELS_ANGLE_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef MANYWORLDS_KERNELS_ANGLE_INL_H_
#undef MANYWORLDS_KERNELS_ANGLE_INL_H_
#else
#define MANYWORLDS_KERNELS_ANGLE_INL_H_
#endif

#include <cstddef>

#include "kernels/angle.h"
#include "kernels/body_access-inl.h"
#include "kernels/lane_math-inl.h"
#include "kernels/spring-inl.h"

HWY_BEFORE_NAMESPACE();
namespace manyworlds {
namespace HWY_NAMESPACE {

// ------------------------------------------------------------ chunk helpers

// w1 -= lambda I1^-1 a, w2 += lambda I2^-1 a (dynamic bodies only).
HWY_INLINE void AngleApplyVelocityStepChunk(const BodyPair& bodies,
                                            const AngleProperties& properties,
                                            LaneVec lambda, std::size_t offset) {
  if (bodies.motion1 == MotionType::kDynamic) {
    AddAngularVelocityStep(
        *bodies.body1, Scale(LoadVec3(properties.inv_i1_axis, offset), hn::Neg(lambda)),
        offset);
  }
  if (bodies.motion2 == MotionType::kDynamic) {
    AddAngularVelocityStep(*bodies.body2,
                           Scale(LoadVec3(properties.inv_i2_axis, offset), lambda), offset);
  }
}

// Caches I^-1 a and, from K, the effective mass and spring of one chunk.
// kUse / kMode pick Jolt's variant (spring-inl.h); K == 0 deactivates.
template <SpringUse kUse, SpringMode kMode>
HWY_INLINE void AngleCalculatePropertiesChunk(const BodyPair& bodies, const Vec3& axis,
                                              const SpringInputs& spring,
                                              LaneVec delta_time,
                                              AngleProperties& properties,
                                              LaneArray& total_lambda, std::size_t offset) {
  // Non-dynamic bodies add nothing to K; their cached vectors stay zero so
  // that 0 * cache is 0 in every later verb.
  Vec3 inv_i1_axis = ZeroVec3(), inv_i2_axis = ZeroVec3();
  LaneVec inv_effective_mass = Zero();
  if (bodies.motion1 == MotionType::kDynamic) {
    inv_i1_axis = BodyInverseInertiaTimes(*bodies.body1, axis, offset);
    inv_effective_mass = Dot(axis, inv_i1_axis);
  }
  if (bodies.motion2 == MotionType::kDynamic) {
    inv_i2_axis = BodyInverseInertiaTimes(*bodies.body2, axis, offset);
    inv_effective_mass = hn::Add(inv_effective_mass, Dot(axis, inv_i2_axis));
  }
  StoreVec3(inv_i1_axis, properties.inv_i1_axis, offset);
  StoreVec3(inv_i2_axis, properties.inv_i2_axis, offset);
  StoreEffectiveMassAndSpring<kUse, kMode>(inv_effective_mass, spring, delta_time,
                                           properties.effective_mass, properties.spring,
                                           total_lambda, offset);
}

// The plain variant: hard in every lane with velocity bias `bias`.
HWY_INLINE void AngleCalculatePropertiesChunk(const BodyPair& bodies, const Vec3& axis,
                                              LaneVec bias, AngleProperties& properties,
                                              LaneArray& total_lambda, std::size_t offset) {
  const SpringInputs hard{bias, Zero(), Zero(), Zero()};
  AngleCalculatePropertiesChunk<SpringUse::kNever, SpringMode::kFrequencyAndDamping>(
      bodies, axis, hard, Zero(), properties, total_lambda, offset);
}

// L *= ratio, then applies L.
HWY_INLINE void AngleWarmStartChunk(const BodyPair& bodies, LaneVec ratio,
                                    const AngleProperties& properties,
                                    LaneArray& total_lambda, std::size_t offset) {
  const LaneVec lambda = hn::Mul(Load(total_lambda, offset), ratio);
  Store(lambda, total_lambda, offset);
  AngleApplyVelocityStepChunk(bodies, properties, lambda, offset);
}

// One velocity iteration; returns the lanes that applied a non-zero impulse.
HWY_INLINE LaneMask AngleSolveVelocityChunk(const BodyPair& bodies, const Vec3& axis,
                                            LaneVec min_lambda, LaneVec max_lambda,
                                            const AngleProperties& properties,
                                            LaneArray& total_lambda, std::size_t offset) {
  const Vec3 w1 = AngularVelocity(*bodies.body1, bodies.motion1, offset);
  const Vec3 w2 = AngularVelocity(*bodies.body2, bodies.motion2, offset);
  const LaneVec minus_jv = Dot(axis, Sub(w1, w2));
  const LaneVec delta =
      SolveSpringRowImpulse(minus_jv, min_lambda, max_lambda, properties.effective_mass,
                            properties.spring, total_lambda, offset);
  AngleApplyVelocityStepChunk(bodies, properties, delta, offset);
  return hn::Ne(delta, Zero());
}

// One Baumgarte step on the error C; returns the lanes that took a step
// (C != 0 and hard).
HWY_INLINE LaneMask AngleSolvePositionChunk(const BodyPair& bodies, LaneVec error,
                                            LaneVec baumgarte,
                                            const AngleProperties& properties,
                                            std::size_t offset) {
  LaneMask applies;
  const LaneVec lambda = SpringRowBaumgarteImpulse(
      error, baumgarte, properties.effective_mass, properties.spring, offset, applies);
  if (bodies.motion1 == MotionType::kDynamic) {
    AddRotationStep(*bodies.body1,
                    Scale(LoadVec3(properties.inv_i1_axis, offset), hn::Neg(lambda)), offset);
  }
  if (bodies.motion2 == MotionType::kDynamic) {
    AddRotationStep(*bodies.body2, Scale(LoadVec3(properties.inv_i2_axis, offset), lambda),
                    offset);
  }
  return applies;
}

// Deactivate where `off`: effective mass and impulse zero.
HWY_INLINE void AngleDeactivateChunk(LaneMask off, AngleProperties& properties,
                                     LaneArray& total_lambda, std::size_t offset) {
  DeactivateSpringRow(off, properties.effective_mass, total_lambda, offset);
}

// Jolt's IsActive: effective mass != 0.
HWY_INLINE LaneMask AngleIsActiveChunk(const AngleProperties& properties,
                                       std::size_t offset) {
  return hn::Ne(Load(properties.effective_mass, offset), Zero());
}

// ------------------------------------------------------------ block verbs

template <SpringUse kUse, SpringMode kMode>
inline void AngleCalculatePropertiesOfBlock(const BodyPair& bodies,
                                            const AngleGeometry& geometry,
                                            AngleLanes& part, float delta_time) {
  const LaneVec dt = Splat(delta_time);
  ForEachChunk([&](std::size_t offset) {
    AngleCalculatePropertiesChunk<kUse, kMode>(
        bodies, LoadVec3(geometry.axis, offset),
        LoadSpringInputs(geometry.bias, geometry.error, geometry.spring, offset), dt,
        part.properties, part.persistent.total_lambda, offset);
  });
}

inline void AngleCalculateProperties(const BodyPair& bodies, const AngleGeometry& geometry,
                                     AngleLanes& part) {
  AngleCalculatePropertiesOfBlock<SpringUse::kNever, SpringMode::kFrequencyAndDamping>(
      bodies, geometry, part, 0.0f);
}

inline void AngleCalculatePropertiesWithFrequencyAndDamping(const BodyPair& bodies,
                                                            const AngleGeometry& geometry,
                                                            AngleLanes& part,
                                                            float delta_time) {
  AngleCalculatePropertiesOfBlock<SpringUse::kIfStiffnessOrDamping,
                                  SpringMode::kFrequencyAndDamping>(bodies, geometry, part,
                                                                    delta_time);
}

inline void AngleCalculatePropertiesWithStiffnessAndDamping(const BodyPair& bodies,
                                                            const AngleGeometry& geometry,
                                                            AngleLanes& part,
                                                            float delta_time) {
  AngleCalculatePropertiesOfBlock<SpringUse::kIfStiffnessOrDamping,
                                  SpringMode::kStiffnessAndDamping>(bodies, geometry, part,
                                                                    delta_time);
}

inline void AngleCalculatePropertiesForLimit(const BodyPair& bodies,
                                             const AngleGeometry& geometry,
                                             AngleLanes& part, float delta_time,
                                             SpringMode mode) {
  WithSpringMode(mode, [&](auto kMode) {
    AngleCalculatePropertiesOfBlock<SpringUse::kIfStiffness, decltype(kMode)::value>(
        bodies, geometry, part, delta_time);
  });
}

inline void AngleCalculatePropertiesForMotor(const BodyPair& bodies,
                                             const AngleGeometry& geometry,
                                             AngleLanes& part, float delta_time,
                                             SpringMode mode) {
  WithSpringMode(mode, [&](auto kMode) {
    AngleCalculatePropertiesOfBlock<SpringUse::kIfStiffnessOrDamping,
                                    decltype(kMode)::value>(bodies, geometry, part,
                                                            delta_time);
  });
}

inline void AngleWarmStart(const BodyPair& bodies, AngleLanes& part,
                           float warm_start_ratio) {
  const LaneVec ratio = Splat(warm_start_ratio);
  ForEachChunk([&](std::size_t offset) {
    AngleWarmStartChunk(bodies, ratio, part.properties, part.persistent.total_lambda,
                        offset);
  });
}

// Returns true if any lane applied a non-zero impulse.
inline bool AngleSolveVelocity(const BodyPair& bodies, const AngleGeometry& geometry,
                               AngleLanes& part) {
  bool applied = false;
  ForEachChunk([&](std::size_t offset) {
    applied |= AnyLane(AngleSolveVelocityChunk(
        bodies, LoadVec3(geometry.axis, offset), Load(geometry.min_lambda, offset),
        Load(geometry.max_lambda, offset), part.properties, part.persistent.total_lambda,
        offset));
  });
  return applied;
}

// Returns true if any lane took a position step.
inline bool AngleSolvePosition(const BodyPair& bodies, const AngleGeometry& geometry,
                               const AngleLanes& part, float baumgarte) {
  const LaneVec beta = Splat(baumgarte);
  bool applied = false;
  ForEachChunk([&](std::size_t offset) {
    applied |= AnyLane(AngleSolvePositionChunk(bodies, Load(geometry.error, offset), beta,
                                               part.properties, offset));
  });
  return applied;
}

inline void AngleDeactivate(AngleLanes& part, const LaneFlags& lanes) {
  ForEachChunk([&](std::size_t offset) {
    AngleDeactivateChunk(LoadFlags(lanes, offset), part.properties,
                         part.persistent.total_lambda, offset);
  });
}

inline void AngleIsActive(const AngleLanes& part, LaneFlags& active) {
  ForEachChunk([&](std::size_t offset) {
    StoreFlags(AngleIsActiveChunk(part.properties, offset), active, offset);
  });
}

}  // namespace HWY_NAMESPACE
}  // namespace manyworlds
HWY_AFTER_NAMESPACE();

#endif  // MANYWORLDS_KERNELS_ANGLE_INL_H_
