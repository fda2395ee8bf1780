// One body of one world as plain numbers: what users read and write.
#pragma once

#include <array>

namespace manyworlds {

struct BodyState {
  std::array<float, 3> position{};                 // centre of mass, world
  std::array<float, 4> rotation{0.f, 0.f, 0.f, 1.f};  // (x, y, z, w), unit
  std::array<float, 3> linear_velocity{};
  std::array<float, 3> angular_velocity{};
  float inv_mass = 0.0f;
  std::array<float, 3> inv_inertia_diagonal{};     // principal inverse inertia
  std::array<float, 4> inertia_rotation{0.f, 0.f, 0.f, 1.f};  // principal axes
};

}  // namespace manyworlds
