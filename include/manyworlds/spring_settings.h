// Spring and motor settings, modelled on Jolt's SpringSettings and
// MotorSettings (spec 2.1 and 3).
#pragma once

#include <cfloat>
#include <cstdint>

namespace manyworlds {

// How a spring's two numbers are read (Jolt's ESpringMode). A scene setting,
// the same in every world, so kernels take it as a uniform argument.
enum class SpringMode : std::uint8_t {
  kFrequencyAndDamping,  // f (Hz) and damping ratio zeta; k, c from the effective mass
  kStiffnessAndDamping,  // k (N/m or N m/rad) and c (N s/m or N m s/rad)
  kMassNormalizedStiffnessAndDamping,  // k / m and c / m: the same motion for any mass
};

inline const char* SpringModeName(SpringMode mode) {
  switch (mode) {
    case SpringMode::kFrequencyAndDamping: return "frequency_and_damping";
    case SpringMode::kStiffnessAndDamping: return "stiffness_and_damping";
    case SpringMode::kMassNormalizedStiffnessAndDamping:
      return "mass_normalized_stiffness_and_damping";
  }
  return "unknown";
}

// Jolt's SpringSettings. As in Jolt one number is the frequency or the
// stiffness depending on the mode; frequency_or_stiffness <= 0 on a limit
// means a hard limit.
struct SpringSettings {
  SpringMode mode = SpringMode::kFrequencyAndDamping;
  float frequency_or_stiffness = 0.0f;
  float damping = 0.0f;

  bool HasStiffness() const { return frequency_or_stiffness > 0.0f; }
  bool HasStiffnessOrDamping() const {
    return frequency_or_stiffness > 0.0f ||
           (mode != SpringMode::kFrequencyAndDamping && damping > 0.0f);
  }
};

// Jolt's EMotorState.
enum class MotorState : std::uint8_t {
  kOff,                  // no drive; friction if the constraint has a max friction
  kVelocity,             // drive to a target velocity
  kPosition,             // drive to a target position through the motor spring
  kPositionAndVelocity,  // both, through the motor spring
};

inline const char* MotorStateName(MotorState state) {
  switch (state) {
    case MotorState::kOff: return "off";
    case MotorState::kVelocity: return "velocity";
    case MotorState::kPosition: return "position";
    case MotorState::kPositionAndVelocity: return "position_and_velocity";
  }
  return "unknown";
}

// Jolt's MotorSettings: the spring of position drives (2 Hz, critically
// damped by default) and the force (linear) or torque (angular) limits. The
// impulse of one velocity iteration is clamped to [dt min, dt max].
struct MotorSettings {
  SpringSettings spring{SpringMode::kFrequencyAndDamping, 2.0f, 1.0f};
  float min_force_limit = -FLT_MAX;  // N, or N m for angular motors
  float max_force_limit = FLT_MAX;
};

}  // namespace manyworlds
