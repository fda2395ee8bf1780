// Storage of Jolt's SpringPart for one block of worlds: the per-world spring
// parameters a scene gives and the softness and bias the Axis and Angle parts
// cache. The maths is in spring-inl.h.
#pragma once

#include <cstdint>

#include "manyworlds/lanes.h"

namespace manyworlds {

// How a spring's two per-world numbers are read (Jolt's ESpringMode). A scene
// setting, the same in every world, so kernels take it as a uniform argument.
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

// Per-world spring parameters (Jolt's SpringSettings without the mode). As in
// Jolt, one field is the frequency or the stiffness depending on the mode, so
// "frequency_or_stiffness > 0" is Jolt's HasStiffness() in every mode.
struct SpringSettingsLanes {
  LaneArray frequency_or_stiffness;
  LaneArray damping;  // zeta, c or c / m by mode
};

// The SpringPart's state per world, recomputed in CalculateProperties:
// velocity bias = softness * total_lambda + bias; softness == 0 is a hard row.
struct SpringLanes {
  LaneArray softness;  // gamma
  LaneArray bias;      // b
};

}  // namespace manyworlds
