// SpringPart across worlds (spec 2.1), and the one-row soft solve it drives in
// the Axis and Angle parts (spec 2.2, 2.8). Soft constraints after Catto,
// "Soft Constraints: Reinventing the Spring", GDC 2011: an implicit-Euler
// spring of stiffness k and damping c on the row's error C.
//
//   K = J M^-1 J^T (inverse effective mass, a scalar for one row)
//   mode FrequencyAndDamping:   m = 1/K, w = 2 pi f, k = m w^2, c = 2 m zeta w
//   mode StiffnessAndDamping:   k, c as given
//   mode MassNormalized...:     k = k'/K, c = c'/K  (k', c' per unit mass)
//   softness gamma = 1 / (dt (c + dt k))    (damping acts even with c = 0)
//   bias     b     = b0 + dt k gamma C
//   effective mass = 1 / (K + gamma);  hard row: gamma = 0, b = b0, 1/K
//
// Velocity step:  dL = m_eff (-J v - (gamma L + b)), clamped on the
//                 accumulated impulse: L' = clamp(L + dL, min, max), dL = L' - L.
// Position step:  only where C != 0 and the row is hard: L = -m_eff beta C
//                 (a soft row already corrects C through its velocity bias).
//
// Which lanes are soft (Jolt's CalculateConstraintProperties variants):
//   plain bias                    never
//   WithFrequencyAndDamping       f > 0
//   WithStiffnessAndDamping       k > 0 or c > 0
//   WithSettingsForLimit          HasStiffness: f (or k) > 0; damping only => hard
//   WithSettingsForMotor          always; Jolt asserts HasStiffnessOrDamping. A
//                                 lane that breaks it is hard here (the rule of
//                                 the two variants above), not NaN.
// The mode is a scene setting (template argument); the softness decision
// depends on per-world values and is a per-lane select.
// K == 0 exactly => Deactivate (m_eff = 0, L = 0) and, as in Jolt, the spring
// state of that lane is left as it was.

#if defined(MANYWORLDS_KERNELS_SPRING_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef MANYWORLDS_KERNELS_SPRING_INL_H_
#undef MANYWORLDS_KERNELS_SPRING_INL_H_
#else
#define MANYWORLDS_KERNELS_SPRING_INL_H_
#endif

#include <cstddef>
#include <type_traits>

#include "kernels/lane_math-inl.h"
#include "kernels/spring.h"

HWY_BEFORE_NAMESPACE();
namespace manyworlds {
namespace HWY_NAMESPACE {

// Which lanes of a CalculateProperties variant use the spring (see above).
enum class SpringUse {
  kNever,                  // plain bias: every lane hard
  kIfStiffness,            // WithSettingsForLimit
  kIfStiffnessOrDamping,   // WithFrequencyAndDamping, WithStiffnessAndDamping,
                           // WithSettingsForMotor
};

// Calls fn(std::integral_constant<SpringMode, mode>{}): turns the scene's
// spring mode into a template argument once per block, outside the lanes.
template <class Fn>
HWY_INLINE void WithSpringMode(SpringMode mode, Fn&& fn) {
  switch (mode) {
    case SpringMode::kFrequencyAndDamping:
      fn(std::integral_constant<SpringMode, SpringMode::kFrequencyAndDamping>{});
      return;
    case SpringMode::kStiffnessAndDamping:
      fn(std::integral_constant<SpringMode, SpringMode::kStiffnessAndDamping>{});
      return;
    case SpringMode::kMassNormalizedStiffnessAndDamping:
      fn(std::integral_constant<SpringMode,
                                SpringMode::kMassNormalizedStiffnessAndDamping>{});
      return;
  }
}

// The spring inputs of one chunk, as values (callers load them from lane
// arrays or compute them, e.g. swing-twist's errors).
struct SpringInputs {
  LaneVec bias;                    // b0, e.g. -target velocity of a motor
  LaneVec error;                   // C, the error the spring pulls to zero
  LaneVec frequency_or_stiffness;  // per SpringMode
  LaneVec damping;                 // per SpringMode
};

HWY_INLINE SpringInputs LoadSpringInputs(const LaneArray& bias, const LaneArray& error,
                                         const SpringSettingsLanes& settings,
                                         std::size_t offset) {
  return {Load(bias, offset), Load(error, offset),
          Load(settings.frequency_or_stiffness, offset), Load(settings.damping, offset)};
}

// Jolt's SpringSettings::HasStiffness (the union field > 0) and
// HasStiffnessOrDamping (damping alone counts except in frequency mode,
// where a zero frequency gives k = c = 0).
HWY_INLINE LaneMask SpringHasStiffness(const SpringInputs& in) {
  return hn::Gt(in.frequency_or_stiffness, Zero());
}
template <SpringMode kMode>
HWY_INLINE LaneMask SpringHasStiffnessOrDamping(const SpringInputs& in) {
  if constexpr (kMode == SpringMode::kFrequencyAndDamping) {
    return SpringHasStiffness(in);
  } else {
    return hn::Or(SpringHasStiffness(in), hn::Gt(in.damping, Zero()));
  }
}

template <SpringUse kUse, SpringMode kMode>
HWY_INLINE LaneMask SpringIsUsed(const SpringInputs& in) {
  if constexpr (kUse == SpringUse::kIfStiffness) {
    return SpringHasStiffness(in);
  } else {
    return SpringHasStiffnessOrDamping<kMode>(in);
  }
}

// Stiffness k and damping c in absolute units from the mode's parameters and
// the row's mass m = 1/K.
template <SpringMode kMode>
HWY_INLINE void SpringStiffnessAndDamping(LaneVec mass, const SpringInputs& in,
                                          LaneVec& stiffness, LaneVec& damping) {
  if constexpr (kMode == SpringMode::kStiffnessAndDamping) {
    stiffness = in.frequency_or_stiffness;
    damping = in.damping;
  } else {
    if constexpr (kMode == SpringMode::kFrequencyAndDamping) {
      const LaneVec omega = hn::Mul(Splat(6.28318530717958648f), in.frequency_or_stiffness);
      stiffness = hn::Mul(mass, hn::Mul(omega, omega));
      damping = hn::Mul(hn::Mul(Splat(2.0f), mass), hn::Mul(in.damping, omega));
    } else {  // mass normalised: k = k'/K, c = c'/K
      stiffness = hn::Mul(in.frequency_or_stiffness, mass);
      damping = hn::Mul(in.damping, mass);
    }
  }
}

// The end of every CalculateProperties variant: from this chunk's K, the
// effective mass and the spring state (hard or soft per lane), stored into the
// part's lanes. Lanes with K == 0 are deactivated (m_eff = 0, L = 0) with a
// zero spring state. Jolt's Deactivate leaves the SpringPart as it was, which
// changes nothing there (every impulse is 0 times the velocity error); but a
// part as a step uses it lives in its thread's scratch (docs/architecture.md,
// "Stored block and working block"), where "as it was" would be whatever
// another block left, possibly not finite (0 times infinity is NaN).
template <SpringUse kUse, SpringMode kMode>
HWY_INLINE void StoreEffectiveMassAndSpring(LaneVec inv_effective_mass,
                                            const SpringInputs& in, LaneVec delta_time,
                                            LaneArray& effective_mass, SpringLanes& spring,
                                            LaneArray& total_lambda, std::size_t offset) {
  const LaneMask active = hn::Ne(inv_effective_mass, Zero());
  // Inactive lanes compute with K = 1 so that no infinity or NaN is formed.
  const LaneVec k = hn::IfThenElse(active, inv_effective_mass, Splat(1.0f));
  const LaneVec hard_mass = hn::Div(Splat(1.0f), k);
  LaneVec mass = hard_mass;
  LaneVec softness = Zero();
  LaneVec bias = in.bias;
  if constexpr (kUse != SpringUse::kNever) {
    const LaneMask soft = SpringIsUsed<kUse, kMode>(in);
    LaneVec stiffness, damping;
    SpringStiffnessAndDamping<kMode>(hard_mass, in, stiffness, damping);
    // Hard lanes take a harmless denominator instead of dt * 0.
    const LaneVec denominator = hn::IfThenElse(
        soft, hn::Mul(delta_time, hn::MulAdd(delta_time, stiffness, damping)), Splat(1.0f));
    softness = hn::IfThenElseZero(soft, hn::Div(Splat(1.0f), denominator));
    const LaneVec bias_factor = hn::Mul(hn::Mul(delta_time, stiffness), softness);
    bias = hn::IfThenElse(soft, hn::MulAdd(bias_factor, in.error, in.bias), in.bias);
    mass = hn::IfThenElse(soft, hn::Div(Splat(1.0f), hn::Add(k, softness)), hard_mass);
  }
  Store(hn::IfThenElseZero(active, mass), effective_mass, offset);
  Store(hn::IfThenElseZero(active, softness), spring.softness, offset);
  Store(hn::IfThenElseZero(active, bias), spring.bias, offset);
  Store(hn::IfThenElseZero(active, Load(total_lambda, offset)), total_lambda, offset);
}

// One velocity iteration of a soft, clamped scalar row. `minus_jv` is -J v in
// Jolt's sign convention. Updates the accumulated impulse and returns the
// impulse to apply (zero where the clamp or a zero effective mass leaves
// nothing to do).
HWY_INLINE LaneVec SolveSpringRowImpulse(LaneVec minus_jv, LaneVec min_lambda,
                                         LaneVec max_lambda, const LaneArray& effective_mass,
                                         const SpringLanes& spring, LaneArray& total_lambda,
                                         std::size_t offset) {
  const LaneVec total = Load(total_lambda, offset);
  const LaneVec velocity_bias =
      hn::MulAdd(Load(spring.softness, offset), total, Load(spring.bias, offset));
  const LaneVec delta =
      hn::Mul(Load(effective_mass, offset), hn::Sub(minus_jv, velocity_bias));
  const LaneVec clamped = hn::Min(hn::Max(hn::Add(total, delta), min_lambda), max_lambda);
  Store(clamped, total_lambda, offset);
  return hn::Sub(clamped, total);
}

// The Baumgarte impulse of a scalar row, -m_eff beta C, in lanes where C != 0
// and the row is hard (`applies`); zero elsewhere, so those lanes stay exact.
HWY_INLINE LaneVec SpringRowBaumgarteImpulse(LaneVec error, LaneVec baumgarte,
                                             const LaneArray& effective_mass,
                                             const SpringLanes& spring, std::size_t offset,
                                             LaneMask& applies) {
  applies = hn::And(hn::Ne(error, Zero()), hn::Eq(Load(spring.softness, offset), Zero()));
  const LaneVec minus_mass_beta = hn::Neg(hn::Mul(Load(effective_mass, offset), baumgarte));
  return hn::IfThenElseZero(applies, hn::Mul(minus_mass_beta, error));
}

// Deactivate's writes for a scalar row: m_eff = 0 and L = 0 where `off`.
HWY_INLINE void DeactivateSpringRow(LaneMask off, LaneArray& effective_mass,
                                    LaneArray& total_lambda, std::size_t offset) {
  ClearWhere(off, effective_mass, offset);
  ClearWhere(off, total_lambda, offset);
}

}  // namespace HWY_NAMESPACE
}  // namespace manyworlds
HWY_AFTER_NAMESPACE();

#endif  // MANYWORLDS_KERNELS_SPRING_INL_H_
