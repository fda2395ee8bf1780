// Storage of the independent-axis part (pulley: one linear row over two
// independent axes, one per body) for one block of worlds. The maths is in
// independent_axis-inl.h.
#pragma once

#include "kernels/body_lanes.h"
#include "kernels/kernel_table.h"
#include "manyworlds/lanes.h"

namespace manyworlds {

// Per-step inputs the owning constraint computes before CalculateProperties.
struct IndependentAxisGeometry {
  Vec3Lanes r1;      // p1 - x1: body 1's lever arm to its attachment
  Vec3Lanes n1;      // unit, from body 1's fixed point to its attachment
  Vec3Lanes r2;      // p2 - x2
  Vec3Lanes n2;      // unit, from body 2's fixed point to its attachment
  LaneArray ratio;   // r: C = |p1 - f1| + r |p2 - f2| - length
  // Range of the accumulated impulse (pulley: [0, inf) at the minimum length,
  // (-inf, 0] at the maximum, both when they coincide); infinities allowed.
  LaneArray min_lambda, max_lambda;
};

struct IndependentAxisLanes {
  Vec3Lanes r1_x_n1;              // zero if body 1 is static
  Vec3Lanes inv_i1_r1_x_n1;       // I1^-1 (r1 x n1); zero if body 1 is static
  Vec3Lanes ratio_r2_x_n2;        // r (r2 x n2); zero if body 2 is static
  Vec3Lanes inv_i2_ratio_r2_x_n2; // I2^-1 r (r2 x n2); zero if body 2 is static
  LaneArray effective_mass;       // 1 / K; zero when deactivated

  struct Persistent {
    LaneArray total_lambda;  // stays in [min_lambda, max_lambda] after a solve
  } persistent;
};

// The part's kernels on one target; each call processes one block.
struct IndependentAxisKernels {
  TargetInfo target;
  void (*calculate_properties)(const BodyPair&, const IndependentAxisGeometry&,
                               IndependentAxisLanes&);
  void (*warm_start)(const BodyPair&, const IndependentAxisGeometry&,
                     IndependentAxisLanes&, float warm_start_ratio);
  // Clamps the accumulated impulse to the geometry's [min_lambda, max_lambda].
  bool (*solve_velocity)(const BodyPair&, const IndependentAxisGeometry&,
                         IndependentAxisLanes&);
  // `error` = C per lane (pulley: length minus its violated bound).
  bool (*solve_position)(const BodyPair&, const IndependentAxisGeometry&,
                         const LaneArray& error, const IndependentAxisLanes&,
                         float baumgarte);
  void (*deactivate)(IndependentAxisLanes&, const LaneFlags& lanes);
  void (*is_active)(const IndependentAxisLanes&, LaneFlags& active);
};

MANYWORLDS_DECLARE_KERNEL_TABLE(IndependentAxisKernels)

}  // namespace manyworlds
