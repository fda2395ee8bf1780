// Storage of Jolt's SpringPart for one block of worlds: the per-world spring
// parameters a scene gives and the softness and bias the Axis and Angle parts
// cache. The maths is in spring-inl.h.
#pragma once

#include <cstdint>

#include "manyworlds/lanes.h"
#include "manyworlds/spring_settings.h"

namespace manyworlds {

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
