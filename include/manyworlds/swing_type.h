// How a swing-twist joint limits its swing when both swing axes have a range
// (Jolt's ESwingType): shared by the scene API and the kernels.
#pragma once

#include <cstdint>

namespace manyworlds {

enum class SwingType : std::uint8_t {
  kCone,     // ellipse in (sin(swing_y/2), sin(swing_z/2)); symmetric limits only
  kPyramid,  // box in half-angle space; asymmetric limits allowed
};

}  // namespace manyworlds
