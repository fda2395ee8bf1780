// Rest rotations for the rotation-Euler and rotation-quaternion benchmarks:
// r0^-1 near the bodies' current relative rotation, as in a running
// simulation, so position steps are small corrections.
#pragma once

#include <cmath>
#include <cstddef>

#include "bench/bench_support.h"
#include "manyworlds/lanes.h"

namespace manyworlds::bench {

inline void SetLaneQuat(QuatLanes& q, std::size_t lane, const Float4& value) {
  q.x[lane] = value[0];
  q.y[lane] = value[1];
  q.z[lane] = value[2];
  q.w[lane] = value[3];
}

// Hamilton product a b of (x, y, z, w) quaternions.
inline Float4 Multiply(const Float4& a, const Float4& b) {
  return {a[3] * b[0] + b[3] * a[0] + a[1] * b[2] - a[2] * b[1],
          a[3] * b[1] + b[3] * a[1] + a[2] * b[0] - a[0] * b[2],
          a[3] * b[2] + b[3] * a[2] + a[0] * b[1] - a[1] * b[0],
          a[3] * b[3] - (a[0] * b[0] + a[1] * b[1] + a[2] * b[2])};
}

inline Float4 Conjugate(const Float4& q) { return {-q[0], -q[1], -q[2], q[3]}; }

// r0^-1 = q2* e q1 with e a random rotation of up to ~6 degrees: the error
// rotation q2 r0^-1 q1* is then e.
inline Float4 NearRestInverseInitialOrientation(Random& random, const Float4& q1,
                                                const Float4& q2) {
  const Float3 half_angle = random.Vector(0.0f, 0.05f);
  Float4 e{half_angle[0], half_angle[1], half_angle[2], 1.0f};
  const float norm = std::sqrt(e[0] * e[0] + e[1] * e[1] + e[2] * e[2] + 1.0f);
  for (float& c : e) c /= norm;
  return Multiply(Multiply(Conjugate(q2), e), q1);
}

}  // namespace manyworlds::bench
