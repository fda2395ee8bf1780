// Storage of the angle part (one angular row with limits, motor or spring)
// for one block of worlds. The maths is in angle-inl.h.
#pragma once

#include "kernels/body_lanes.h"
#include "kernels/kernel_table.h"
#include "kernels/spring.h"
#include "manyworlds/lanes.h"

namespace manyworlds {

// Per-step inputs from the owning constraint (hinge limit or motor, cone,
// swing-twist, six-DOF): the row's axis and error, and the row's settings.
struct AngleGeometry {
  Vec3Lanes axis;          // a: world, unit; J = [0, -a, 0, a]
  LaneArray error;         // C: the caller's angle error (no wrapping here)
  LaneArray bias;          // b0: hard velocity bias, e.g. -target angular velocity
  LaneArray min_lambda;    // clamp of the accumulated impulse (N m s);
  LaneArray max_lambda;    //   -FLT_MAX / FLT_MAX for an unclamped row
  SpringSettingsLanes spring;  // used by the spring variants of CalculateProperties
};

// What CalculateProperties caches for one angular row, apart from the impulse.
// Separate from the impulse so that parts holding several angle rows
// (swing-twist) keep their impulses in their own Persistent struct.
struct AngleProperties {
  Vec3Lanes inv_i1_axis;     // I1^-1 a, zero unless body 1 is dynamic
  Vec3Lanes inv_i2_axis;     // I2^-1 a, zero unless body 2 is dynamic
  LaneArray effective_mass;  // 1/K or 1/(K + softness); zero when deactivated
  SpringLanes spring;
};

struct AngleLanes {
  AngleProperties properties;

  struct Persistent {
    LaneArray total_lambda;  // accumulated impulse
  } persistent;
};

// The part's kernels on one target; each call processes one block. The five
// CalculateProperties variants are Jolt's (spec 2.1): which lanes are soft.
struct AngleKernels {
  TargetInfo target;
  // Hard in every lane, velocity bias = geometry.bias.
  void (*calculate_properties)(const BodyPair&, const AngleGeometry&, AngleLanes&);
  // Soft where frequency > 0 (spring.frequency_or_stiffness = f, damping = zeta).
  void (*calculate_properties_with_frequency_and_damping)(const BodyPair&,
                                                          const AngleGeometry&,
                                                          AngleLanes&, float delta_time);
  // Soft where k > 0 or c > 0.
  void (*calculate_properties_with_stiffness_and_damping)(const BodyPair&,
                                                          const AngleGeometry&,
                                                          AngleLanes&, float delta_time);
  // A limit's spring: soft where frequency (or stiffness) > 0; damping alone is hard.
  void (*calculate_properties_for_limit)(const BodyPair&, const AngleGeometry&,
                                         AngleLanes&, float delta_time, SpringMode mode);
  // A motor's spring: soft where it has stiffness or damping (Jolt asserts it).
  void (*calculate_properties_for_motor)(const BodyPair&, const AngleGeometry&,
                                         AngleLanes&, float delta_time, SpringMode mode);
  void (*warm_start)(const BodyPair&, AngleLanes&, float warm_start_ratio);
  // Solves return true if any lane applied a non-zero impulse / correction.
  bool (*solve_velocity)(const BodyPair&, const AngleGeometry&, AngleLanes&);
  // Baumgarte step on geometry.error with the last CalculateProperties.
  bool (*solve_position)(const BodyPair&, const AngleGeometry&, const AngleLanes&,
                         float baumgarte);
  void (*deactivate)(AngleLanes&, const LaneFlags& lanes);
  void (*is_active)(const AngleLanes&, LaneFlags& active);
};

MANYWORLDS_DECLARE_KERNEL_TABLE(AngleKernels)

}  // namespace manyworlds
