// Storage of the axis part (one linear row with limits, motor or spring) for
// one block of worlds. The maths is in axis-inl.h.
#pragma once

#include "kernels/body_lanes.h"
#include "kernels/kernel_table.h"
#include "kernels/spring.h"
#include "manyworlds/lanes.h"

namespace manyworlds {

// Per-step inputs from the owning constraint (distance, slider limit and
// motor, six-DOF translation, path): the row's geometry and error, and the
// row's settings.
struct AxisGeometry {
  Vec3Lanes r1_plus_u;     // p2 - x1: body 1's lever arm reaches body 2's anchor
  Vec3Lanes r2;            // p2 - x2
  Vec3Lanes axis;          // n: world, unit, from body 1 towards body 2
  LaneArray error;         // C = (p2 - p1) . n, or the caller's limit distance
  LaneArray bias;          // b0: hard velocity bias, e.g. -target velocity
  LaneArray min_lambda;    // clamp of the accumulated impulse (N s);
  LaneArray max_lambda;    //   -FLT_MAX / FLT_MAX for an unclamped row
  SpringSettingsLanes spring;  // used by the spring variants of CalculateProperties
};

// What CalculateProperties caches for one linear row, apart from the impulse
// (kept apart so that parts with several axis rows own their impulses).
struct AxisProperties {
  Vec3Lanes r1_plus_u_x_axis;         // a1 = (r1 + u) x n, zero if body 1 is static
  Vec3Lanes r2_x_axis;                // a2 = r2 x n, zero if body 2 is static
  Vec3Lanes inv_i1_r1_plus_u_x_axis;  // I1^-1 a1, zero unless body 1 is dynamic
  Vec3Lanes inv_i2_r2_x_axis;         // I2^-1 a2, zero unless body 2 is dynamic
  LaneArray effective_mass;  // 1/K or 1/(K + softness); zero when deactivated
  SpringLanes spring;
};

struct AxisLanes {
  AxisProperties properties;

  struct Persistent {
    LaneArray total_lambda;  // accumulated impulse
  } persistent;
};

// The part's kernels on one target; each call processes one block. The five
// CalculateProperties variants are Jolt's (spec 2.1): which lanes are soft.
struct AxisKernels {
  TargetInfo target;
  // Hard in every lane, velocity bias = geometry.bias.
  void (*calculate_properties)(const BodyPair&, const AxisGeometry&, AxisLanes&);
  // Soft where frequency > 0 (spring.frequency_or_stiffness = f, damping = zeta).
  void (*calculate_properties_with_frequency_and_damping)(const BodyPair&,
                                                          const AxisGeometry&, AxisLanes&,
                                                          float delta_time);
  // Soft where k > 0 or c > 0.
  void (*calculate_properties_with_stiffness_and_damping)(const BodyPair&,
                                                          const AxisGeometry&, AxisLanes&,
                                                          float delta_time);
  // A limit's spring: soft where frequency (or stiffness) > 0; damping alone is hard.
  void (*calculate_properties_for_limit)(const BodyPair&, const AxisGeometry&,
                                         AxisLanes&, float delta_time, SpringMode mode);
  // A motor's spring: soft where it has stiffness or damping (Jolt asserts it).
  void (*calculate_properties_for_motor)(const BodyPair&, const AxisGeometry&,
                                         AxisLanes&, float delta_time, SpringMode mode);
  void (*warm_start)(const BodyPair&, const AxisGeometry&, AxisLanes&,
                     float warm_start_ratio);
  // Solves return true if any lane applied a non-zero impulse / correction.
  bool (*solve_velocity)(const BodyPair&, const AxisGeometry&, AxisLanes&);
  // Baumgarte step on geometry.error along geometry.axis with the last
  // CalculateProperties (callers recompute both first).
  bool (*solve_position)(const BodyPair&, const AxisGeometry&, const AxisLanes&,
                         float baumgarte);
  void (*deactivate)(AxisLanes&, const LaneFlags& lanes);
  void (*is_active)(const AxisLanes&, LaneFlags& active);
};

MANYWORLDS_DECLARE_KERNEL_TABLE(AxisKernels)

}  // namespace manyworlds
