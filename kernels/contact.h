// Block storage of one contact slot (a pair of shapes that may touch) for 16
// worlds: the manifold's friction rows and, after it, one ContactPointLanes per
// point the pair can make (1 to 4). The maths is in kernels/contact-inl.h.
#pragma once

#include <cstddef>

#include "kernels/axis.h"
#include "manyworlds/lanes.h"

namespace manyworlds {

// The most points one contact manifold holds (a box face on a plane).
inline constexpr std::size_t kMaxContactPoints = 4;

// One point of a manifold.
struct ContactPointLanes {
  // Persistent between steps: where the point sits on each body (centre-of-
  // mass frame), 1 where this step kept the point (else 0) and its normal
  // impulse. The next step matches its points against these (1 cm) to warm
  // start; the position phase measures the separation from them.
  Vec3Lanes local_point1, local_point2;
  LaneFlags present;
  LaneArray normal_lambda;
  // This step's normal row: lever arms from the midpoint of the two surface
  // points, effective mass, speculative or restitution bias (spring.bias).
  AxisProperties normal_row;
  LaneArray anchor_distance;  // d_i: distance from the friction anchor across n
};

// The manifold of one slot.
struct ContactLanes {
  // Per-world parameters: combined friction sqrt(mu1 mu2) and restitution
  // max(e1, e2), from the scene.
  LaneArray friction, restitution;
  // Persistent: 1 where the manifold existed this step (friction impulses
  // carry over to the next step only then), and the friction impulses.
  LaneFlags present;
  LaneArray tangent1_lambda, tangent2_lambda, angular_lambda;
  // This step: the normal (body 1 to body 2, world), the tangents t1 =
  // perp(n), t2 = n x t1, and their rows at the friction anchor.
  Vec3Lanes normal, tangent1, tangent2;
  AxisProperties tangent1_row, tangent2_row;
  // The angular friction row about n (two or more points kept): I1^-1 n,
  // I2^-1 n (zero unless dynamic) and 1 / (n.I1^-1 n + n.I2^-1 n), else 0.
  Vec3Lanes inv_i1_normal, inv_i2_normal;
  LaneArray angular_effective_mass;
};

}  // namespace manyworlds
