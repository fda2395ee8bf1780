// Storage of the swing-twist part (swing cone or pyramid and twist range,
// three angle rows) for one block of worlds. The maths is in
// swing_twist_clamp-inl.h (decomposition and clamping) and swing_twist-inl.h
// (the verbs).
#pragma once

#include <cstdint>

#include "kernels/angle.h"
#include "kernels/body_lanes.h"
#include "kernels/kernel_table.h"
#include "manyworlds/lanes.h"
#include "manyworlds/swing_type.h"  // SwingType

namespace manyworlds {


// What one axis (twist X, swing Y, swing Z) allows.
enum class AxisLimitKind : std::uint8_t {
  kLimited,  // a range [min, max]
  kLocked,   // no rotation at all
  kFree,     // no limit
};

// Jolt's SetLimits rule for one axis: locked if min > -0.5 deg and max <
// 0.5 deg, free if min < -179.5 deg and max > 179.5 deg, else limited.
// Scenes use it to derive the configuration from one world's angles.
inline AxisLimitKind ClassifyAxisLimit(float min_angle, float max_angle) {
  constexpr float kLockedAngle = 0.5f * 3.14159265358979f / 180.0f;
  constexpr float kFreeAngle = 179.5f * 3.14159265358979f / 180.0f;
  if (min_angle > -kLockedAngle && max_angle < kLockedAngle) return AxisLimitKind::kLocked;
  if (min_angle < -kFreeAngle && max_angle > kFreeAngle) return AxisLimitKind::kFree;
  return AxisLimitKind::kLimited;
}

// Which axes are locked, limited or free, and cone or pyramid: a scene
// setting, the same in every world, so the kernels branch on it as ordinary
// control flow. The limit values are per world (SwingTwistLimitLanes).
struct SwingTwistConfig {
  SwingType swing_type = SwingType::kCone;
  AxisLimitKind twist = AxisLimitKind::kLimited;
  AxisLimitKind swing_y = AxisLimitKind::kLimited;
  AxisLimitKind swing_z = AxisLimitKind::kLimited;
};

// Per-world limit angles in radians (min <= max; swing within [-pi, pi]),
// the input of set_limits. Cone limits must be symmetric and, where limited,
// non-zero (the ellipse divides by them; Jolt asserts the same).
struct SwingTwistLimitAngles {
  LaneArray twist_min, twist_max;
  LaneArray swing_y_min, swing_y_max;
  LaneArray swing_z_min, swing_z_max;
};

// One axis' limits as the clamp uses them: half angles (pyramid) and their
// sine and cosine, overridden for locked (0/0, 1/1) and free (-1/1, 0/0) axes.
struct AxisLimitLanes {
  LaneArray half_min, half_max;
  LaneArray sin_half_min, sin_half_max;
  LaneArray cos_half_min, cos_half_max;
};

struct SwingTwistLimitLanes {
  AxisLimitLanes twist, swing_y, swing_z;
};

// Per-constraint inputs: rotations from constraint space (X = twist axis,
// Y and Z = swing axes) to body 1 and body 2 space (c1, c2). The kernels form
// q = (q1 c1)* (q2 c2) from the bodies' current rotations.
struct SwingTwistGeometry {
  QuatLanes constraint_to_body1;
  QuatLanes constraint_to_body2;
};

// One of the three angle rows: its world axis (negated when clamped at the
// min side, so the impulse range is always (-inf, 0]), the upper impulse
// bound (FLT_MAX where sin_min == sin_max, i.e. locked, else 0) and the
// angle part's cached properties.
struct SwingTwistRowLanes {
  Vec3Lanes axis;
  LaneArray max_lambda;
  AngleProperties properties;  // zero effective mass when the row is off
};

// Everything the part caches between its verbs. Only `persistent` survives
// from one step to the next; the rest is recomputed in CalculateProperties.
struct SwingTwistLanes {
  SwingTwistRowLanes swing_y, swing_z, twist;

  struct Persistent {
    LaneArray swing_y_lambda;
    LaneArray swing_z_lambda;
    LaneArray twist_lambda;
  } persistent;
};

// Result of ClampSwingTwist for one block (exported for tests and tools):
// the clamped swing and twist (constraint space), which limits were hit, and
// how many Newton steps the cone's ellipse projection took per lane.
struct SwingTwistClampLanes {
  QuatLanes swing, twist;
  LaneFlags twist_min, twist_max;
  LaneFlags swing_y_min, swing_y_max;
  LaneFlags swing_z_min, swing_z_max;
  LaneArray ellipse_iterations;
};

// The part's kernels on one target; each call processes one block.
struct SwingTwistKernels {
  TargetInfo target;
  // Jolt's SetLimits: sin/cos of the half angles, per the configuration.
  void (*set_limits)(const SwingTwistConfig&, const SwingTwistLimitAngles&,
                     SwingTwistLimitLanes&);
  // q = swing twist (Jolt's GetSwingTwist), for tests.
  void (*decompose)(const QuatLanes& q, QuatLanes& swing, QuatLanes& twist);
  // Jolt's ClampSwingTwist on a decomposed swing and twist, for tests.
  void (*clamp)(const SwingTwistConfig&, const SwingTwistLimitLanes&, const QuatLanes& swing,
                const QuatLanes& twist, SwingTwistClampLanes& clamped);

  void (*calculate_properties)(const BodyPair&, const SwingTwistConfig&,
                               const SwingTwistGeometry&, const SwingTwistLimitLanes&,
                               SwingTwistLanes&);
  void (*warm_start)(const BodyPair&, const SwingTwistConfig&, SwingTwistLanes&,
                     float warm_start_ratio);
  // Solves return true if any lane applied a non-zero impulse / correction.
  bool (*solve_velocity)(const BodyPair&, const SwingTwistConfig&, SwingTwistLanes&);
  // Decomposes and clamps the current rotation again and, where a limit is
  // violated, takes one rotation-Euler Baumgarte step towards the clamped one.
  bool (*solve_position)(const BodyPair&, const SwingTwistConfig&, const SwingTwistGeometry&,
                         const SwingTwistLimitLanes&, float baumgarte);
  void (*deactivate)(SwingTwistLanes&, const LaneFlags& lanes);
  void (*is_active)(const SwingTwistLanes&, LaneFlags& active);
};

MANYWORLDS_DECLARE_KERNEL_TABLE(SwingTwistKernels)

}  // namespace manyworlds
