// Shared pieces of the part benchmarks: random per-world inputs and the
// sanity check every batch runs after its benchmark.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <random>
#include <string>

#include "batch/world_blocks.h"
#include "manyworlds/body_state.h"
#include "manyworlds/lanes.h"

namespace manyworlds::bench {

inline constexpr float kBaumgarte = 0.2f;  // Jolt's default
// After a benchmark every body and impulse must be finite and below this.
inline constexpr float kSaneBound = 1.0e6f;
inline constexpr unsigned kSeed = 20240601;  // same inputs on every target

using Float3 = std::array<float, 3>;
using Float4 = std::array<float, 4>;

class Random {
 public:
  explicit Random(unsigned seed) : engine_(seed) {}

  float Uniform(float lo, float hi) {
    return std::uniform_real_distribution<float>(lo, hi)(engine_);
  }
  // Log-uniform in [lo, hi] (masses and inertias spanning decades).
  float LogUniform(float lo, float hi) {
    return std::exp(Uniform(std::log(lo), std::log(hi)));
  }
  float Sign() { return Uniform(0.0f, 1.0f) < 0.5f ? -1.0f : 1.0f; }

  Float3 UnitVector() {
    for (;;) {
      const Float3 v{Uniform(-1, 1), Uniform(-1, 1), Uniform(-1, 1)};
      const float length = Length(v);
      if (length > 0.1f && length <= 1.0f) return Scale(v, 1.0f / length);
    }
  }
  Float3 Vector(float min_length, float max_length) {
    return Scale(UnitVector(), Uniform(min_length, max_length));
  }
  // A unit vector perpendicular to the unit vector n.
  Float3 Perpendicular(const Float3& n) {
    for (;;) {
      const Float3 v = UnitVector();
      const float along = v[0] * n[0] + v[1] * n[1] + v[2] * n[2];
      const Float3 p{v[0] - along * n[0], v[1] - along * n[1], v[2] - along * n[2]};
      const float length = Length(p);
      if (length > 0.1f) return Scale(p, 1.0f / length);
    }
  }
  // A unit quaternion (x, y, z, w) of a random axis and angle.
  Float4 Rotation() {
    const Float3 axis = UnitVector();
    const float half = 0.5f * Uniform(-3.14159265f, 3.14159265f);
    const float s = std::sin(half);
    Float4 q{axis[0] * s, axis[1] * s, axis[2] * s, std::cos(half)};
    const float norm = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    for (float& c : q) c /= norm;
    return q;
  }

 private:
  static float Length(const Float3& v) {
    return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  }
  static Float3 Scale(const Float3& v, float s) { return {v[0] * s, v[1] * s, v[2] * s}; }

  std::mt19937 engine_;
};

inline BodyState RandomBody(Random& random) {
  BodyState s;
  s.position = random.Vector(0.0f, 5.0f);
  s.rotation = random.Rotation();
  s.linear_velocity = random.Vector(0.0f, 3.0f);
  s.angular_velocity = random.Vector(0.0f, 3.0f);
  s.inv_mass = random.LogUniform(0.1f, 10.0f);
  s.inv_inertia_diagonal = {random.LogUniform(0.1f, 10.0f),
                            random.LogUniform(0.1f, 10.0f),
                            random.LogUniform(0.1f, 10.0f)};
  s.inertia_rotation = random.Rotation();
  return s;
}

inline void SetLane(Vec3Lanes& v, std::size_t lane, const Float3& value) {
  v.x[lane] = value[0];
  v.y[lane] = value[1];
  v.z[lane] = value[2];
}

// "" if `value` is finite and within kSaneBound, else a description.
inline std::string InsaneValue(const std::string& what, float value) {
  if (std::isfinite(value) && std::fabs(value) <= kSaneBound) return "";
  return what + " = " + std::to_string(value) + " (must be finite and below " +
         std::to_string(kSaneBound) + ")";
}

// "" if every real world's bodies are finite, bounded and unit-rotated.
inline std::string InsaneBodies(const BodyBlocks& bodies) {
  for (std::size_t world = 0; world < bodies.world_count(); ++world) {
    for (std::size_t body = 0; body < bodies.body_count(); ++body) {
      const BodyState s = bodies.Get(world, body);
      const std::string where =
          " of body " + std::to_string(body) + " in world " + std::to_string(world);
      for (int i = 0; i < 3; ++i) {
        for (const auto& [what, value] :
             {std::pair{"position", s.position[i]},
              std::pair{"linear velocity", s.linear_velocity[i]},
              std::pair{"angular velocity", s.angular_velocity[i]}}) {
          const std::string problem = InsaneValue(what + where, value);
          if (!problem.empty()) return problem;
        }
      }
      float norm_squared = 0.0f;
      for (float c : s.rotation) norm_squared += c * c;
      if (!(std::fabs(std::sqrt(norm_squared) - 1.0f) < 1e-3f)) {
        return "|rotation|" + where + " = " + std::to_string(std::sqrt(norm_squared));
      }
    }
  }
  return "";
}

// The deactivate and is_active verbs of every part batch that holds, per
// block, `part` (the part's lanes), `deactivate_lanes` and `active` flags.
template <class Batch>
bool DeactivateVerb(Batch& b, std::size_t) {
  for (std::size_t i = 0; i < b.part.block_count(); ++i) {
    b.kernels.deactivate(b.part[i], b.deactivate_lanes[i]);
  }
  return false;
}

template <class Batch>
bool IsActiveVerb(Batch& b, std::size_t) {
  for (std::size_t i = 0; i < b.part.block_count(); ++i) {
    b.kernels.is_active(b.part[i], b.active[i]);
  }
  return false;
}

}  // namespace manyworlds::bench
