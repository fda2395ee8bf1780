// SpringPart: turns a hard one-row constraint into a soft one (spec 2.1). Lives
// inside the Axis and Angle parts; holds the bias b and the softness γ. Scalar
// reference, written from the formulas.
//
// Soft constraint (Catto, "Soft Constraints", GDC 2011): instead of J·v' + b0 = 0
// the velocity solve asks for
//
//   J·v' + γ·Λ + b = 0,   Λ = accumulated impulse of the part,
//
// which is one implicit-Euler step of a spring k and damper c acting on C:
//
//   γ = 1 / (dt·(c + dt·k)),   b = b0 + dt·k·γ·C,
//
// and the effective mass becomes 1/(K + γ) with K = J M⁻¹ Jᵀ the inverse effective
// mass. The scheme is unconditionally stable and damps even with c = 0. Each
// iteration then solves
//
//   Δλ = −(1/(K + γ))·(J·v + GetBias(Λ)),   GetBias(Λ) = γ·Λ + b.
//
// Ways to give k and c (SpringSettings::mode):
//   FrequencyAndDamping:  m = 1/K, ω = 2πf, k = m·ω², c = 2·m·ζ·ω   (needs f > 0)
//   StiffnessAndDamping:  k, c as given                               (needs k > 0 or c > 0)
//   MassNormalized...:    k = k'/K, c = c'/K (an acceleration spring: mass independent)
// A hard constraint is γ = 0, b = b0 (WithBias). Which one the Axis/Angle parts pick
// is their business (spec 2.1, table); the entry points here assume the caller has
// decided the spring is on and assert its preconditions.
//
// Decision (not in Jolt): Reset() sets γ = b = 0. The Axis/Angle parts call it on
// Deactivate, so a deactivated part has no stale softness left from an earlier
// step. It changes no velocity or position (m_eff = 0 makes every Δλ zero); only the
// "applied" flag of a position step on a deactivated part can differ from Jolt.
#pragma once

#include <cassert>
#include <cstdint>
#include <numbers>

namespace manyworlds::reference {

enum class SpringMode : std::uint8_t {
  kFrequencyAndDamping,                // frequency (Hz) and damping ratio ζ
  kStiffnessAndDamping,                // stiffness k and damping c
  kMassNormalizedStiffnessAndDamping,  // k' = k/m and c' = c/m (acceleration units)
};

// Jolt's SpringSettings. Jolt keeps frequency and stiffness in one union; here it
// is one field read under either name.
template <class T>
struct SpringSettings {
  SpringMode mode = SpringMode::kFrequencyAndDamping;
  T frequency_or_stiffness = T(0);  // f (Hz), or k, or k' depending on mode
  T damping = T(0);                 // ζ, or c, or c' depending on mode

  // "Stiffness" in any mode, because the union is read as a frequency (spec 2.1).
  // Constraints use it to decide whether a limit is soft.
  bool HasStiffness() const { return frequency_or_stiffness > T(0); }
  // Damping alone only counts outside FrequencyAndDamping (f = 0 means hard there).
  bool HasStiffnessOrDamping() const {
    return frequency_or_stiffness > T(0) ||
           (mode != SpringMode::kFrequencyAndDamping && damping > T(0));
  }
};

template <class T>
class SpringPart {
 public:
  // Hard constraint with velocity bias b0: γ = 0, b = b0.
  void WithBias(T bias) {
    softness_ = T(0);
    bias_ = bias;
  }

  // Implicit-Euler spring k, damper c on the error C; returns 1/(K + γ).
  T WithStiffnessAndDamping(T dt, T inv_effective_mass, T bias, T error_c, T stiffness,
                            T damping) {
    assert(stiffness > T(0) || damping > T(0));
    softness_ = T(1) / (dt * (damping + dt * stiffness));
    bias_ = bias + dt * stiffness * softness_ * error_c;
    return T(1) / (inv_effective_mass + softness_);
  }

  // k and c from the oscillation frequency f and damping ratio ζ of the effective
  // mass m = 1/K; returns 1/(K + γ).
  T WithFrequencyAndDamping(T dt, T inv_effective_mass, T bias, T error_c, T frequency,
                            T damping_ratio) {
    assert(frequency > T(0));
    const T mass = T(1) / inv_effective_mass;
    const T omega = T(2) * std::numbers::pi_v<T> * frequency;
    const T stiffness = mass * omega * omega;
    const T damping = T(2) * mass * damping_ratio * omega;
    return WithStiffnessAndDamping(dt, inv_effective_mass, bias, error_c, stiffness, damping);
  }

  // k = k'·m, c = c'·m with m = 1/K: the same response whatever the mass.
  T WithMassNormalizedStiffnessAndDamping(T dt, T inv_effective_mass, T bias, T error_c,
                                          T stiffness, T damping) {
    return WithStiffnessAndDamping(dt, inv_effective_mass, bias, error_c,
                                   stiffness / inv_effective_mass,
                                   damping / inv_effective_mass);
  }

  // Dispatches on settings.mode; returns 1/(K + γ).
  T WithSettings(T dt, T inv_effective_mass, T bias, T error_c,
                 const SpringSettings<T>& settings) {
    switch (settings.mode) {
      case SpringMode::kFrequencyAndDamping:
        return WithFrequencyAndDamping(dt, inv_effective_mass, bias, error_c,
                                       settings.frequency_or_stiffness, settings.damping);
      case SpringMode::kStiffnessAndDamping:
        return WithStiffnessAndDamping(dt, inv_effective_mass, bias, error_c,
                                       settings.frequency_or_stiffness, settings.damping);
      case SpringMode::kMassNormalizedStiffnessAndDamping:
        return WithMassNormalizedStiffnessAndDamping(dt, inv_effective_mass, bias, error_c,
                                                     settings.frequency_or_stiffness,
                                                     settings.damping);
    }
    assert(false && "unknown spring mode");
    return T(0);
  }

  // ---- Spring selection of the Axis/Angle part variants (spec 2.1, table) ----
  // Each sets γ and b and returns the effective mass: 1/K when hard, 1/(K + γ) when
  // soft. K != 0 is the caller's job (K == 0 deactivates before anything else).

  // Plain variant: always hard.
  T ForBias(T inv_effective_mass, T bias) {
    WithBias(bias);
    return T(1) / inv_effective_mass;
  }
  // Soft iff f > 0.
  T ForFrequencyAndDamping(T dt, T inv_effective_mass, T bias, T error_c, T frequency,
                           T damping_ratio) {
    if (frequency > T(0)) {
      return WithFrequencyAndDamping(dt, inv_effective_mass, bias, error_c, frequency,
                                     damping_ratio);
    }
    return ForBias(inv_effective_mass, bias);
  }
  // Soft iff k > 0 or c > 0.
  T ForStiffnessAndDamping(T dt, T inv_effective_mass, T bias, T error_c, T stiffness,
                           T damping) {
    if (stiffness > T(0) || damping > T(0)) {
      return WithStiffnessAndDamping(dt, inv_effective_mass, bias, error_c, stiffness,
                                     damping);
    }
    return ForBias(inv_effective_mass, bias);
  }
  // Limits: soft iff HasStiffness(); a damping-only limit is hard.
  T ForLimit(T dt, T inv_effective_mass, T bias, T error_c, const SpringSettings<T>& settings) {
    if (settings.HasStiffness()) {
      return WithSettings(dt, inv_effective_mass, bias, error_c, settings);
    }
    return ForBias(inv_effective_mass, bias);
  }
  // Motors: always soft; the motor must have stiffness or damping.
  T ForMotor(T dt, T inv_effective_mass, T bias, T error_c, const SpringSettings<T>& settings) {
    assert(settings.HasStiffnessOrDamping());
    return WithSettings(dt, inv_effective_mass, bias, error_c, settings);
  }

  // γ = b = 0 (see the decision in the header comment).
  void Reset() {
    softness_ = T(0);
    bias_ = T(0);
  }

  bool IsActive() const { return softness_ != T(0); }  // soft iff γ != 0

  // Total bias of one iteration: γ·Λ + b.
  T GetBias(T total_lambda) const { return softness_ * total_lambda + bias_; }

  T Softness() const { return softness_; }  // γ
  T Bias() const { return bias_; }          // b

 private:
  T bias_ = T(0);      // b
  T softness_ = T(0);  // γ
};

}  // namespace manyworlds::reference
