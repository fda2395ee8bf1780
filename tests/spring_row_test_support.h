// Shared by the tests of the two parts that own a SpringPart (axis_test.cc,
// angle_test.cc): what kind of row each world gets, the five
// CalculateProperties variants with their spring modes, and Jolt's
// implicit-Euler spring recursion for the analytic checks.
#pragma once

#include <cfloat>
#include <cstddef>
#include <string>
#include <vector>

#include "kernels/spring.h"
#include "reference/spring_part.h"
#include "tests/test_support.h"

namespace manyworlds::testing {

inline constexpr float kDeltaTime = 1.0f / 60.0f;

// What kind of row a world has. Lanes of every kind sit side by side in each
// block, so every per-lane select is exercised against its neighbours.
enum class RowKind {
  kHard,               // no spring, unclamped
  kSoft,               // spring in every spring variant, one-sided clamp
  kClamped,            // tight symmetric clamp (a motor's force limit x dt)
  kNearSingular,       // K ~ 1e-6 (nearly immovable bodies): m_eff ~ 1e5
  kDampingOnly,        // soft only where damping alone counts
  kSingular,           // K == 0 exactly: deactivated in CalculateProperties
  kDeactivatedByFlag,  // deactivated explicitly after CalculateProperties
  kZeroError,          // C == 0 exactly: the position step skips it
};

inline RowKind KindOfRowWorld(std::size_t world) { return RowKind(world % 8); }

// Jolt's CalculateConstraintProperties variants (spec 2.1 table).
enum class Variant { kBias, kFrequencyAndDamping, kStiffnessAndDamping, kForLimit, kForMotor };

struct VariantCase {
  Variant variant;
  SpringMode mode;  // the mode the variant reads the spring parameters in
  std::string name;
};

inline const std::vector<VariantCase>& AllVariants() {
  static const std::vector<VariantCase> variants = [] {
    std::vector<VariantCase> v = {
        {Variant::kBias, SpringMode::kFrequencyAndDamping, "bias"},
        {Variant::kFrequencyAndDamping, SpringMode::kFrequencyAndDamping,
         "with_frequency_and_damping"},
        {Variant::kStiffnessAndDamping, SpringMode::kStiffnessAndDamping,
         "with_stiffness_and_damping"}};
    for (const SpringMode mode : {SpringMode::kFrequencyAndDamping,
                                  SpringMode::kStiffnessAndDamping,
                                  SpringMode::kMassNormalizedStiffnessAndDamping}) {
      v.push_back({Variant::kForLimit, mode, std::string("for_limit_") + SpringModeName(mode)});
      v.push_back({Variant::kForMotor, mode, std::string("for_motor_") + SpringModeName(mode)});
    }
    return v;
  }();
  return variants;
}

inline reference::SpringMode ToReference(SpringMode mode) {
  switch (mode) {
    case SpringMode::kFrequencyAndDamping: return reference::SpringMode::kFrequencyAndDamping;
    case SpringMode::kStiffnessAndDamping: return reference::SpringMode::kStiffnessAndDamping;
    case SpringMode::kMassNormalizedStiffnessAndDamping:
      return reference::SpringMode::kMassNormalizedStiffnessAndDamping;
  }
  return reference::SpringMode::kFrequencyAndDamping;
}

// The per-world row settings both parts share, as float lanes.
struct RowSettingsLanes {
  LaneArray* error;
  LaneArray* bias;
  LaneArray* min_lambda;
  LaneArray* max_lambda;
  SpringSettingsLanes* spring;
};

template <class Geometry>
RowSettingsLanes RowSettingsOf(Geometry& g) {
  return {&g.error, &g.bias, &g.min_lambda, &g.max_lambda, &g.spring};
}

// Random settings of one world's row by kind. Spring parameters are read as
// f (Hz) and zeta, k and c, or k/m and c/m depending on the variant's mode;
// the ranges are sensible in all three readings.
inline void SetRandomRowSettings(Random& random, RowKind kind, const RowSettingsLanes& row,
                                 std::size_t lane) {
  (*row.error)[lane] = kind == RowKind::kZeroError ? 0.0f : float(random.Uniform(-0.3, 0.3));
  (*row.bias)[lane] = float(random.Uniform(-0.5, 0.5));
  float min_lambda = -FLT_MAX, max_lambda = FLT_MAX;
  if (kind == RowKind::kSoft) {  // a soft limit pushes one way only
    (random.Uniform(0, 1) < 0.5 ? min_lambda : max_lambda) = 0.0f;
  } else if (kind == RowKind::kClamped) {
    max_lambda = float(random.LogUniform(1e-3, 1e-1));
    min_lambda = -max_lambda;
  }
  (*row.min_lambda)[lane] = min_lambda;
  (*row.max_lambda)[lane] = max_lambda;
  const bool soft = kind == RowKind::kSoft || kind == RowKind::kDeactivatedByFlag ||
                    (kind == RowKind::kNearSingular && random.Uniform(0, 1) < 0.5);
  // Hard lanes: zero or negative parameters, which every variant reads as "off".
  (*row.spring).frequency_or_stiffness[lane] =
      soft ? float(random.LogUniform(0.5, 20.0)) : (random.Uniform(0, 1) < 0.5 ? 0.0f : -1.0f);
  (*row.spring).damping[lane] =
      soft ? float(random.Uniform(0.0, 1.5))
           : kind == RowKind::kDampingOnly ? float(random.Uniform(0.2, 2.0)) : 0.0f;
}

// Jolt's precondition of the motor variant: SpringSettings::HasStiffnessOrDamping.
inline bool HasStiffnessOrDamping(SpringMode mode, float frequency_or_stiffness,
                                  float damping) {
  return frequency_or_stiffness > 0.0f ||
         (mode != SpringMode::kFrequencyAndDamping && damping > 0.0f);
}

// Gives every lane that breaks the motor precondition a 1 Hz (or 1 N/m)
// spring, so kernel and reference are compared only where Jolt defines the
// motor variant.
inline void MeetMotorPrecondition(SpringMode mode, SpringSettingsLanes& spring) {
  for (std::size_t lane = 0; lane < kLaneWidth; ++lane) {
    if (!HasStiffnessOrDamping(mode, spring.frequency_or_stiffness[lane],
                               spring.damping[lane])) {
      spring.frequency_or_stiffness[lane] = 1.0f;
    }
  }
}

// Jolt's implicit-Euler spring recursion (spec 6, TestDistanceSpring):
//   v' = (v - dt k/m x) / (1 + dt c/m + dt^2 k/m),   x' = x + dt v'.
struct SpringTrajectoryPoint {
  double x, v;
};

inline SpringTrajectoryPoint ImplicitEulerSpringStep(SpringTrajectoryPoint p, double dt,
                                                     double k_over_m, double c_over_m) {
  const double v = (p.v - dt * k_over_m * p.x) /
                   (1.0 + dt * c_over_m + dt * dt * k_over_m);
  return {p.x + dt * v, v};
}

// The analytic checks' spring (TestDistanceSpring: f = 2 Hz, zeta = 0.1) in
// the parameters of `mode` for a row of mass `mass`: the same k/m and c/m in
// every mode.
inline constexpr double kSpringFrequency = 2.0;
inline constexpr double kSpringDampingRatio = 0.1;

inline void AnalyticSpringParameters(SpringMode mode, double mass,
                                     float& frequency_or_stiffness, float& damping) {
  const double omega = 2.0 * M_PI * kSpringFrequency;
  double scale = 1.0;  // per unit mass
  switch (mode) {
    case SpringMode::kFrequencyAndDamping:
      frequency_or_stiffness = float(kSpringFrequency);
      damping = float(kSpringDampingRatio);
      return;
    case SpringMode::kStiffnessAndDamping: scale = mass; break;
    case SpringMode::kMassNormalizedStiffnessAndDamping: break;
  }
  frequency_or_stiffness = float(scale * omega * omega);
  damping = float(scale * 2.0 * kSpringDampingRatio * omega);
}

// k/m and c/m of the spring the kernel sees: from the float parameters as
// stored (so the recursion and the kernel use the same spring, as in Jolt's
// test) and the row's inverse mass.
inline void SpringPerUnitMass(SpringMode mode, float frequency_or_stiffness, float damping,
                              double inv_mass, double& k_over_m, double& c_over_m) {
  switch (mode) {
    case SpringMode::kFrequencyAndDamping: {
      const double omega = 2.0 * M_PI * double(frequency_or_stiffness);
      k_over_m = omega * omega;
      c_over_m = 2.0 * double(damping) * omega;
      return;
    }
    case SpringMode::kStiffnessAndDamping:
      k_over_m = double(frequency_or_stiffness) * inv_mass;
      c_over_m = double(damping) * inv_mass;
      return;
    case SpringMode::kMassNormalizedStiffnessAndDamping:
      k_over_m = frequency_or_stiffness;
      c_over_m = damping;
      return;
  }
}

// The spring variants the analytic checks run: each dedicated variant in its
// own mode, and the limit and motor variants in all three.
inline std::vector<VariantCase> SpringVariants() {
  std::vector<VariantCase> spring;
  for (const VariantCase& v : AllVariants()) {
    if (v.variant != Variant::kBias) spring.push_back(v);
  }
  return spring;
}

}  // namespace manyworlds::testing
