// Motion types of a body. A batch shares one scene layout, so a body's motion
// type is the same in every world; kernels branch on it as ordinary control flow.
#pragma once

#include <cstdint>

namespace manyworlds {

enum class MotionType : std::uint8_t {
  kStatic,     // never moves; velocities read as zero; no mass properties used
  kKinematic,  // moved by the user's velocities; ignored by most parts (spec 1.5)
  kDynamic,    // moved by forces and constraint impulses
};

inline const char* MotionTypeName(MotionType type) {
  switch (type) {
    case MotionType::kStatic: return "static";
    case MotionType::kKinematic: return "kinematic";
    case MotionType::kDynamic: return "dynamic";
  }
  return "unknown";
}

}  // namespace manyworlds
