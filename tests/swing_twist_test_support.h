// Inputs of the swing-twist tests: the scene configurations they run, random
// per-world limits consistent with a configuration, and relative rotations
// chosen inside or outside those limits, clear of every decision boundary
// of the clamp (so float kernel and double reference take the same branch).
#pragma once

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "kernels/swing_twist.h"
#include "reference/swing_twist_part.h"
#include "tests/test_support.h"

namespace manyworlds::testing {

using RefSwingTwist = reference::SwingTwistPart<double>;

// A unit quaternion rounded to float and renormalised in float, read back
// exactly (so kernel and reference start from the same numbers).
inline Quatd ToFloatUnit(const Quatd& q) {
  const float x = float(q.x()), y = float(q.y()), z = float(q.z()), w = float(q.w());
  const float norm = std::sqrt(x * x + y * y + z * z + w * w);
  return Quatd(w / norm, x / norm, y / norm, z / norm);
}

constexpr double kDegree = std::numbers::pi / 180.0;

struct NamedSwingTwistConfig {
  const char* name;
  SwingTwistConfig config;
};

// Every branch of the clamp and of CalculateProperties: cone and pyramid
// with two limited swing axes, one free swing axis, one locked swing axis
// (each side), both locked, both free; twist locked, limited and free.
inline const std::vector<NamedSwingTwistConfig>& SwingTwistConfigs() {
  using K = AxisLimitKind;
  static const std::vector<NamedSwingTwistConfig> configs = {
      {"cone, twist limited", {SwingType::kCone, K::kLimited, K::kLimited, K::kLimited}},
      {"pyramid, twist limited", {SwingType::kPyramid, K::kLimited, K::kLimited, K::kLimited}},
      {"cone, swing Y free, twist free", {SwingType::kCone, K::kFree, K::kFree, K::kLimited}},
      {"pyramid, swing Z free, twist locked",
       {SwingType::kPyramid, K::kLocked, K::kLimited, K::kFree}},
      {"swing Y locked, twist free", {SwingType::kCone, K::kFree, K::kLocked, K::kLimited}},
      {"swing Z locked, twist locked", {SwingType::kPyramid, K::kLocked, K::kLimited, K::kLocked}},
      {"swing Y and Z locked, twist limited",
       {SwingType::kCone, K::kLimited, K::kLocked, K::kLocked}},
      {"everything locked", {SwingType::kCone, K::kLocked, K::kLocked, K::kLocked}},
      {"swing free (cone), twist limited", {SwingType::kCone, K::kLimited, K::kFree, K::kFree}},
      {"swing free (pyramid), twist locked",
       {SwingType::kPyramid, K::kLocked, K::kFree, K::kFree}},
  };
  return configs;
}

inline reference::SwingType ToReference(SwingType type) {
  return type == SwingType::kCone ? reference::SwingType::kCone
                                  : reference::SwingType::kPyramid;
}

// One world's limit angles (radians, float values as the lanes hold them).
struct LimitAngles {
  float twist_min, twist_max, swing_y_min, swing_y_max, swing_z_min, swing_z_max;
};

// min <= max of the given kind, well away from Jolt's 0.5 and 179.5 degree
// thresholds so that the reference classifies it the same way. Cone swing
// limits are symmetric (half cone angles 2..120 degrees, log-uniform so that
// narrow cones, the hard case of the ellipse, are common).
inline void RandomAxisAngles(Random& random, AxisLimitKind kind, bool symmetric,
                             double max_magnitude, float& min_angle, float& max_angle) {
  switch (kind) {
    case AxisLimitKind::kLocked:
      min_angle = float(-random.Uniform(0.0, 0.4) * kDegree);
      max_angle = float(random.Uniform(0.0, 0.4) * kDegree);
      return;
    case AxisLimitKind::kFree:
      min_angle = float(-random.Uniform(179.6, 179.9) * kDegree);
      max_angle = float(random.Uniform(179.6, 179.9) * kDegree);
      return;
    case AxisLimitKind::kLimited:
      if (symmetric) {
        const double half = random.LogUniform(2.0, 120.0) * kDegree;
        min_angle = float(-half);
        max_angle = float(half);
        return;
      }
      const double lo = random.Uniform(-max_magnitude, 20.0 * kDegree);
      // One world in ten has a one-value range (its row is two-sided).
      const double hi = random.Uniform(0, 1) < 0.1 && std::abs(lo) > 2.0 * kDegree
                            ? lo
                            : random.Uniform(std::max(lo + 10.0 * kDegree, 5.0 * kDegree),
                                             max_magnitude);
      min_angle = float(lo);
      max_angle = float(hi);
      return;
  }
}

inline LimitAngles RandomLimitAngles(Random& random, const SwingTwistConfig& config) {
  LimitAngles a{};
  const bool cone = config.swing_type == SwingType::kCone;
  RandomAxisAngles(random, config.twist, false, 170.0 * kDegree, a.twist_min, a.twist_max);
  RandomAxisAngles(random, config.swing_y, cone, 150.0 * kDegree, a.swing_y_min, a.swing_y_max);
  RandomAxisAngles(random, config.swing_z, cone, 150.0 * kDegree, a.swing_z_min, a.swing_z_max);
  return a;
}

inline void SetReferenceLimits(RefSwingTwist& part, const SwingTwistConfig& config,
                               const LimitAngles& a) {
  part.SetSwingType(ToReference(config.swing_type));
  part.SetLimits(a.twist_min, a.twist_max, a.swing_y_min, a.swing_y_max, a.swing_z_min,
                 a.swing_z_max);
}

inline void SetLaneLimitAngles(SwingTwistLimitAngles& lanes, std::size_t lane,
                               const LimitAngles& a) {
  lanes.twist_min[lane] = a.twist_min;
  lanes.twist_max[lane] = a.twist_max;
  lanes.swing_y_min[lane] = a.swing_y_min;
  lanes.swing_y_max[lane] = a.swing_y_max;
  lanes.swing_z_min[lane] = a.swing_z_min;
  lanes.swing_z_max[lane] = a.swing_z_max;
}

// Where a world's relative rotation lies.
enum class RotationKind {
  kInside,    // every axis within its limits (locked axes: off, see below)
  kOutside,   // every limited axis beyond a limit by a clear margin
  kMixed,     // each axis inside or outside at random
  kTwistNearHalfTurn,  // twist within 0.01..0.2 rad of +-pi
};

// An angle for an axis of the given kind: inside or outside [min, max],
// within +-max_magnitude. Locked axes always get 2..30 degrees of either sign:
// a locked component that is exactly zero in double is a few 1e-8 in float,
// and "!= 0" would then differ between kernel and reference.
inline double RandomAxisAngle(Random& random, AxisLimitKind kind, double min_angle,
                              double max_angle, bool inside, double max_magnitude) {
  const double sign = random.Uniform(0, 1) < 0.5 ? -1.0 : 1.0;
  if (kind == AxisLimitKind::kLocked) return sign * random.Uniform(2.0, 30.0) * kDegree;
  if (kind == AxisLimitKind::kFree) return random.Uniform(-max_magnitude, max_magnitude);
  // A one-value range has no inside that is clear of both limits.
  if (inside && max_angle - min_angle > 1.0 * kDegree) {
    return random.Uniform(min_angle, max_angle);
  }
  const double below = std::max(min_angle + max_magnitude, 0.0);  // room under min
  const double above = std::max(max_magnitude - max_angle, 0.0);
  if (below + above < 6.0 * kDegree) return random.Uniform(min_angle, max_angle);
  const double pick = random.Uniform(0, below + above);
  return pick < below ? min_angle - pick : max_angle + (pick - below);
}

// A relative rotation q = swing twist for a world with these limits.
inline Quatd RandomRelativeRotation(Random& random, const SwingTwistConfig& config,
                                    const LimitAngles& a, RotationKind kind) {
  auto inside = [&] {
    return kind == RotationKind::kInside ||
           (kind == RotationKind::kMixed && random.Uniform(0, 1) < 0.5);
  };
  double twist = RandomAxisAngle(random, config.twist, a.twist_min, a.twist_max, inside(),
                                 170.0 * kDegree);
  if (kind == RotationKind::kTwistNearHalfTurn) {
    twist = (random.Uniform(0, 1) < 0.5 ? -1 : 1) *
            (std::numbers::pi - random.Uniform(0.01, 0.2));
  }
  Quatd swing;
  if (config.swing_type == SwingType::kCone && config.swing_y != AxisLimitKind::kLocked &&
      config.swing_z != AxisLimitKind::kLocked) {
    // A point of the (sin(swing_y/2), sin(swing_z/2)) plane, scaled from the
    // ellipse: inside r <= 0.9, outside r >= 1.15, |(y, z)| <= sin(80 deg).
    const double semi_y = std::sin(0.5 * a.swing_y_max), semi_z = std::sin(0.5 * a.swing_z_max);
    const double phi = random.Uniform(-std::numbers::pi, std::numbers::pi);
    const double on_ellipse = std::hypot(semi_y * std::cos(phi), semi_z * std::sin(phi));
    const double max_r = std::sin(80.0 * kDegree) / on_ellipse;
    double r = inside() ? random.Uniform(0.0, std::min(0.9, max_r))
                        : (max_r > 1.2 ? random.Uniform(1.15, max_r) : random.Uniform(0, 0.9));
    const double y = r * semi_y * std::cos(phi), z = r * semi_z * std::sin(phi);
    swing = Quatd(std::sqrt(1.0 - y * y - z * z), 0.0, y, z);
  } else {
    // Half angles (atan2(y, w), atan2(z, w)) as the pyramid clamp sees them.
    const double half_y = 0.5 * RandomAxisAngle(random, config.swing_y, a.swing_y_min,
                                                a.swing_y_max, inside(), 150.0 * kDegree);
    const double half_z = 0.5 * RandomAxisAngle(random, config.swing_z, a.swing_z_min,
                                                a.swing_z_max, inside(), 150.0 * kDegree);
    swing = Quatd(std::cos(half_y) * std::cos(half_z), 0.0, std::sin(half_y) * std::cos(half_z),
                  std::cos(half_y) * std::sin(half_z))
                .normalized();
  }
  const Quatd twist_q(std::cos(0.5 * twist), std::sin(0.5 * twist), 0.0, 0.0);
  return swing * twist_q;
}

// |d| folded by d > 1 => 2 - d (the clamp's nearest-limit distance).
inline double Folded(double d) {
  d = std::abs(d);
  return d > 1.0 ? 2.0 - d : d;
}

// Decision margin of a 1-DOF clamp of sin value v against [sin_min, sin_max].
inline double OneAxisMargin(double v, const reference::AxisLimit<double>& limit) {
  const double delta_min = limit.sin_min - v, delta_max = v - limit.sin_max;
  double margin = std::min(std::abs(delta_min), std::abs(delta_max));
  // A one-value range ties exactly (|delta_min| == |delta_max| in any
  // precision): both sides pick the max limit, no margin needed.
  if ((delta_min > 0 || delta_max > 0) && limit.sin_min != limit.sin_max) {
    margin = std::min(margin, std::abs(Folded(delta_min) - Folded(delta_max)));
  }
  return margin;
}

// What a test needs to know about a world's rotation: whether every clamp
// decision is clear (margins of 2e-3 in sin or half-angle space, 5% of the
// ellipse's value, a swing away from s == 0), and how strongly float
// rounding is amplified: 1/s through the decomposition, and 1/|desired x
// current| through the normalised 2-DOF swing axis (times 10 for the cone,
// whose closest point stops at |g| < 1e-6 rather than at rounding level).
struct RotationCheck {
  bool clear = false;
  double condition = 1.0;
};

inline RotationCheck CheckRotation(const SwingTwistConfig& config, const RefSwingTwist& part,
                                   const Quatd& q, bool exact_half_turn = false) {
  constexpr double kMargin = 2e-3;
  RotationCheck check;
  const reference::SwingTwist<double> st = reference::DecomposeSwingTwist(q);
  const double s = std::sqrt(q.w() * q.w() + q.x() * q.x());
  if (!exact_half_turn && s < 0.08) return check;
  check.condition = exact_half_turn ? 1.0 : 1.0 / s;
  const double twist_sign = st.twist.w() < 0 ? -1.0 : 1.0;
  const double swing_sign = st.swing.w() < 0 ? -1.0 : 1.0;
  const double tx = twist_sign * st.twist.x();
  const double y = swing_sign * st.swing.y(), z = swing_sign * st.swing.z();
  const double w = swing_sign * st.swing.w();
  double margin = 1.0;
  // An exact half turn has exactly zero components where double has them.
  auto off_zero = [&](double v) { return exact_half_turn && v == 0.0 ? 1.0 : std::abs(v); };
  if (config.twist == AxisLimitKind::kLocked) margin = std::min(margin, off_zero(tx));
  if (config.twist == AxisLimitKind::kLimited) {
    margin = std::min(margin, OneAxisMargin(tx, part.TwistLimit()));
  }
  const bool y_locked = config.swing_y == AxisLimitKind::kLocked;
  const bool z_locked = config.swing_z == AxisLimitKind::kLocked;
  if (y_locked) margin = std::min(margin, off_zero(y));
  if (z_locked) margin = std::min(margin, off_zero(z));
  if (y_locked && !z_locked) margin = std::min(margin, OneAxisMargin(z, part.SwingZLimit()));
  if (z_locked && !y_locked) margin = std::min(margin, OneAxisMargin(y, part.SwingYLimit()));
  const bool two_dof = !y_locked && !z_locked;
  if (two_dof && config.swing_type == SwingType::kCone) {
    const double a = part.SwingYLimit().sin_max, b = part.SwingZLimit().sin_max;
    const double value = (y / a) * (y / a) + (z / b) * (z / b);
    if (std::abs(value - 1.0) < 0.05 * std::max(1.0, value)) return check;
  }
  if (two_dof && config.swing_type == SwingType::kPyramid) {
    for (const auto& [half, limit] : {std::pair{std::atan2(y, w), part.SwingYLimit()},
                                      std::pair{std::atan2(z, w), part.SwingZLimit()}}) {
      margin = std::min({margin, std::abs(half - limit.half_min), std::abs(half - limit.half_max)});
    }
  }
  if (margin < kMargin) return check;
  if (two_dof) {
    // The 2-DOF row's axis is normalize(desired x current).
    Quatd swing = st.swing, twist = st.twist;
    if ((part.ClampSwingTwist(swing, twist) & RefSwingTwist::kClampedSwingY) != 0) {
      const double cross = (swing * Vec3d::UnitX()).cross(st.swing * Vec3d::UnitX()).norm();
      if (cross < 1e-2) return check;
      check.condition *= 1.0 + (config.swing_type == SwingType::kCone ? 10.0 : 4.0) / cross;
    }
  }
  check.clear = true;
  return check;
}

}  // namespace manyworlds::testing
