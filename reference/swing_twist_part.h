// SwingTwistPart: limits the rotation of body 2's constraint frame relative to body
// 1's by a swing cone (or pyramid) and a twist range (spec 2.12; the ragdoll joint,
// swing-twist and six-DOF constraints). A composite of three AngleParts (swing Y,
// swing Z, twist). Scalar reference, written from the formulas.
//
// Constraint space: X = twist axis, Y and Z = swing axes. With c_i the rotation
// from constraint space to body i space, the relative rotation is
//
//   q = (q1·c1)*·(q2·c2) = swing·twist     (DecomposeSwingTwist in math.h)
//
// twist about X, swing about an axis in the YZ plane. Limits are kept in sin(θ/2)
// space (the quaternion components): twist.x ∈ [sin(tmin/2), sin(tmax/2)]; swing
// (y, z) inside an ellipse with semi-axes (sin(θYmax/2), sin(θZmax/2)) (Cone, only
// symmetric limits) or half angles (atan2(y, w), atan2(z, w)) inside per-axis
// ranges (Pyramid).
//
// Per axis (SetLimits): LOCKED if min > −0.5° and max < 0.5° (sin 0/0, cos 1/1);
// FREE if min < −179.5° and max > 179.5° (sin −1/+1, cos 0/0); else LIMITED.
//
// ClampSwingTwist (after forcing w >= 0 on both; signs restored at the end):
// - twist locked: clamped (both flags) iff x != 0, result identity; limited: out of
//   range iff sin_min − x > 0 or x − sin_max > 0, set to the nearer limit
//   quaternion, nearness measured as |Δ| folded by "Δ > 1 ⇒ 2 − Δ" (±1 are the same
//   rotation; Jolt notes this can pick the far limit for extreme ranges).
// - swing Y and Z locked: identity (flags for each non-zero component).
// - one locked: flags for the locked component if non-zero; 1-DOF clamp of the other
//   (same nearest rule, swing := that limit's quaternion); if the other was in
//   range but the locked one non-zero, swing := (0, 0, z, √(1 − z²)) (resp. y).
// - neither locked (this includes both free): Cone: if (y, z) is outside the
//   ellipse, move it to the closest ellipse point (EllipseClosestPoint) and
//   w := √max(0, 1 − y² − z²); Pyramid: clamp both half angles, and if either
//   changed rebuild (0, sin hy cos hz, cos hy sin hz, cos hy cos hz) normalised (x
//   left out so no twist is introduced). Either sets all four swing flags.
//
// Velocity constraints (CalculateConstraintProperties), axes in world space from
// F = (q1·c1)·swing with the UNCLAMPED swing, AngleParts with bias 0:
// - one or both swing axes locked: swing Y part on F·Y, swing Z part on F·Z. A
//   locked axis is always active; the other (limited) one only when clamped, its
//   axis NEGATED when clamped at the min side so the impulse range is always
//   (−∞, 0].
// - neither locked, not both free, some swing flag set: ONE axis
//   n = normalize(desired × current), current = F·X, desired = (q1·c1)·swing_clamped·X
//   on the swing Y part (a positive rotation about n moves current away from
//   desired, which λ <= 0 forbids); zero cross product ⇒ Y deactivated. Swing Z is
//   deactivated.
// - twist: locked ⇒ always active on F·X; limited ⇒ active when clamped, axis
//   negated at the min side; free ⇒ deactivated.
// Velocity step, in the order swing Y, swing Z, twist, for the active parts only:
// AnglePart solve with λ ∈ (−∞, 0], or (−∞, ∞) when that axis' sin_min == sin_max
// (locked, or a limited range of one value).
//
// Position step: decompose and clamp again from the caller's current q; if any flag
// is set, one full 3-DOF Baumgarte step of a temporary RotationEulerPart (inertia at
// the current rotations) towards the clamped orientation, i.e. with
// r0⁻¹ = c2·(c1·swing_clamped·twist_clamped)*.
//
// Decisions: the ellipse iteration runs in double with a cap (see math.h); the
// 1-DOF rebuild uses √max(0, 1 − z²) (Jolt: √(1 − z²); equal unless rounding makes
// |z| > 1); (−∞, 0] uses −∞ where Jolt uses −FLT_MAX (same result for finite
// impulses). SaveState / GetTotalLambda pack the three Λ as (swing Y, swing Z, twist).
#pragma once

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>

#include "reference/angle_part.h"
#include "reference/body.h"
#include "reference/math.h"
#include "reference/rotation_euler_part.h"

namespace manyworlds::reference {

enum class SwingType : std::uint8_t {
  kCone,     // ellipse in (sin(θy/2), sin(θz/2)); symmetric limits only
  kPyramid,  // box in half-angle space; asymmetric limits allowed
};

enum class AxisLimitKind : std::uint8_t { kLimited, kLocked, kFree };

// One axis' limits as the clamp uses them.
template <class T>
struct AxisLimit {
  AxisLimitKind kind = AxisLimitKind::kFree;  // default: what SetLimits(−π, π) gives
  T half_min = -std::numbers::pi_v<T> / T(2);  // θmin/2 (pyramid)
  T half_max = std::numbers::pi_v<T> / T(2);   // θmax/2
  T sin_min = T(-1), sin_max = T(1);   // sin(θ/2), overridden for locked/free axes
  T cos_min = T(0), cos_max = T(0);    // cos(θ/2), likewise
};

// q = (q1·c1)*·(q2·c2): body 2's constraint frame seen from body 1's.
template <class T>
Quat<T> SwingTwistConstraintRotation(const Body<T>& body1, const Quat<T>& constraint_to_body1,
                                     const Body<T>& body2, const Quat<T>& constraint_to_body2) {
  return (body1.rotation * constraint_to_body1).conjugate() *
         (body2.rotation * constraint_to_body2);
}

template <class T>
class SwingTwistPart {
 public:
  // Which limits ClampSwingTwist hit.
  static constexpr unsigned kClampedTwistMin = 1u << 0;
  static constexpr unsigned kClampedTwistMax = 1u << 1;
  static constexpr unsigned kClampedSwingYMin = 1u << 2;
  static constexpr unsigned kClampedSwingYMax = 1u << 3;
  static constexpr unsigned kClampedSwingZMin = 1u << 4;
  static constexpr unsigned kClampedSwingZMax = 1u << 5;
  static constexpr unsigned kClampedSwingY = kClampedSwingYMin | kClampedSwingYMax;
  static constexpr unsigned kClampedSwingZ = kClampedSwingZMin | kClampedSwingZMax;
  static constexpr unsigned kClampedTwist = kClampedTwistMin | kClampedTwistMax;

  void SetSwingType(SwingType type) { swing_type_ = type; }
  SwingType GetSwingType() const { return swing_type_; }

  // Angles in radians; min <= max; swing limits within [−π, π]. Scenes give
  // float angles, and float π lies above π in double: such limits are taken
  // as ±π (both are "free" by the ±179.5° rule).
  void SetLimits(T twist_min, T twist_max, T swing_y_min, T swing_y_max, T swing_z_min,
                 T swing_z_max) {
    assert(twist_min <= twist_max && swing_y_min <= swing_y_max && swing_z_min <= swing_z_max);
    [[maybe_unused]] constexpr T kFloatPi = T(3.14159265358979323846f);
    assert(swing_y_min >= -kFloatPi && swing_y_max <= kFloatPi);
    assert(swing_z_min >= -kFloatPi && swing_z_max <= kFloatPi);
    const auto within_pi = [](T angle) {
      return std::clamp(angle, -std::numbers::pi_v<T>, std::numbers::pi_v<T>);
    };
    swing_y_min = within_pi(swing_y_min), swing_y_max = within_pi(swing_y_max);
    swing_z_min = within_pi(swing_z_min), swing_z_max = within_pi(swing_z_max);
    twist_ = MakeAxisLimit(twist_min, twist_max);
    swing_y_ = MakeAxisLimit(swing_y_min, swing_y_max);
    swing_z_ = MakeAxisLimit(swing_z_min, swing_z_max);
  }

  // Clamps swing (x = 0) and twist (y = z = 0), both in constraint space, to the
  // limits; returns the kClamped* flags. See the header comment for the rules.
  unsigned ClampSwingTwist(Quat<T>& swing, Quat<T>& twist) const {
    unsigned clamped = 0;
    const bool negate_swing = swing.w() < T(0);
    if (negate_swing) swing = Negated(swing);
    const bool negate_twist = twist.w() < T(0);
    if (negate_twist) twist = Negated(twist);

    // Twist.
    if (twist_.kind == AxisLimitKind::kLocked) {
      if (twist.x() != T(0)) clamped |= kClampedTwist;
      twist = Quat<T>::Identity();
    } else if (twist_.kind == AxisLimitKind::kLimited) {
      const int side = ClampSide(twist.x(), twist_);
      if (side < 0) {
        twist = Quat<T>(twist_.cos_min, twist_.sin_min, T(0), T(0));
        clamped |= kClampedTwistMin;
      } else if (side > 0) {
        twist = Quat<T>(twist_.cos_max, twist_.sin_max, T(0), T(0));
        clamped |= kClampedTwistMax;
      }
    }

    // Swing.
    const bool y_locked = swing_y_.kind == AxisLimitKind::kLocked;
    const bool z_locked = swing_z_.kind == AxisLimitKind::kLocked;
    if (y_locked && z_locked) {
      if (swing.y() != T(0)) clamped |= kClampedSwingY;
      if (swing.z() != T(0)) clamped |= kClampedSwingZ;
      swing = Quat<T>::Identity();
    } else if (y_locked) {
      if (swing.y() != T(0)) clamped |= kClampedSwingY;
      const int side = ClampSide(swing.z(), swing_z_);
      if (side < 0) {
        swing = Quat<T>(swing_z_.cos_min, T(0), T(0), swing_z_.sin_min);
        clamped |= kClampedSwingZMin;
      } else if (side > 0) {
        swing = Quat<T>(swing_z_.cos_max, T(0), T(0), swing_z_.sin_max);
        clamped |= kClampedSwingZMax;
      } else if ((clamped & kClampedSwingY) != 0) {
        const T z = swing.z();
        swing = Quat<T>(std::sqrt(std::max(T(0), T(1) - z * z)), T(0), T(0), z);
      }
    } else if (z_locked) {
      if (swing.z() != T(0)) clamped |= kClampedSwingZ;
      const int side = ClampSide(swing.y(), swing_y_);
      if (side < 0) {
        swing = Quat<T>(swing_y_.cos_min, T(0), swing_y_.sin_min, T(0));
        clamped |= kClampedSwingYMin;
      } else if (side > 0) {
        swing = Quat<T>(swing_y_.cos_max, T(0), swing_y_.sin_max, T(0));
        clamped |= kClampedSwingYMax;
      } else if ((clamped & kClampedSwingZ) != 0) {
        const T y = swing.y();
        swing = Quat<T>(std::sqrt(std::max(T(0), T(1) - y * y)), T(0), y, T(0));
      }
    } else if (swing_type_ == SwingType::kCone) {
      const Vec2<T> point(swing.y(), swing.z());
      if (!EllipseIsInside(swing_y_.sin_max, swing_z_.sin_max, point)) {
        const Vec2<T> closest = EllipseClosestPoint(swing_y_.sin_max, swing_z_.sin_max, point);
        const T w = std::sqrt(
            std::max(T(0), T(1) - closest.x() * closest.x() - closest.y() * closest.y()));
        swing = Quat<T>(w, T(0), closest.x(), closest.y());
        clamped |= kClampedSwingY | kClampedSwingZ;  // the side is not used for a cone
      }
    } else {
      // Swing about Y by θy then about Z by θz is (−sy·sz, sy·cz, cy·sz, cy·cz) with
      // s/c of the half angles, so θy/2 = atan2(y, w) and θz/2 = atan2(z, w).
      const T half_y = std::atan2(swing.y(), swing.w());
      const T half_z = std::atan2(swing.z(), swing.w());
      const T clamped_y = std::min(std::max(half_y, swing_y_.half_min), swing_y_.half_max);
      const T clamped_z = std::min(std::max(half_z, swing_z_.half_min), swing_z_.half_max);
      if (clamped_y != half_y || clamped_z != half_z) {
        const T sy = std::sin(clamped_y), cy = std::cos(clamped_y);
        const T sz = std::sin(clamped_z), cz = std::cos(clamped_z);
        swing = Quat<T>(cy * cz, T(0), sy * cz, cy * sz).normalized();
        clamped |= kClampedSwingY | kClampedSwingZ;  // the side is not used for a pyramid
      }
    }

    if (negate_swing) swing = Negated(swing);
    if (negate_twist) twist = Negated(twist);
    return clamped;
  }

  // constraint_rotation = q (SwingTwistConstraintRotation), constraint_to_world = q1·c1.
  void CalculateConstraintProperties(const Body<T>& body1, const Body<T>& body2,
                                     const Quat<T>& constraint_rotation,
                                     const Quat<T>& constraint_to_world) {
    const SwingTwist<T> decomposed = DecomposeSwingTwist(constraint_rotation);
    Quat<T> clamped_swing = decomposed.swing;
    Quat<T> clamped_twist = decomposed.twist;
    const unsigned clamped = ClampSwingTwist(clamped_swing, clamped_twist);

    const Quat<T> swing_to_world = constraint_to_world * decomposed.swing;
    const Vec3<T> frame_x = swing_to_world * Vec3<T>::UnitX();
    const bool y_locked = swing_y_.kind == AxisLimitKind::kLocked;
    const bool z_locked = swing_z_.kind == AxisLimitKind::kLocked;
    const bool both_free =
        swing_y_.kind == AxisLimitKind::kFree && swing_z_.kind == AxisLimitKind::kFree;

    if (y_locked || z_locked) {
      swing_y_axis_ = swing_to_world * Vec3<T>::UnitY();
      swing_z_axis_ = swing_to_world * Vec3<T>::UnitZ();
      // A locked axis is always on; a limited one only when clamped, flipped at min.
      if (y_locked || (clamped & kClampedSwingY) != 0) {
        if (!y_locked && (clamped & kClampedSwingYMin) != 0) swing_y_axis_ = -swing_y_axis_;
        swing_y_part_.CalculateConstraintProperties(body1, body2, swing_y_axis_);
      } else {
        swing_y_part_.Deactivate();
      }
      if (z_locked || (clamped & kClampedSwingZ) != 0) {
        if (!z_locked && (clamped & kClampedSwingZMin) != 0) swing_z_axis_ = -swing_z_axis_;
        swing_z_part_.CalculateConstraintProperties(body1, body2, swing_z_axis_);
      } else {
        swing_z_part_.Deactivate();
      }
    } else if (!both_free && (clamped & (kClampedSwingY | kClampedSwingZ)) != 0) {
      const Vec3<T> desired = constraint_to_world * (clamped_swing * Vec3<T>::UnitX());
      const Vec3<T> axis = desired.cross(frame_x);
      const T length = axis.norm();
      if (length != T(0)) {
        swing_y_axis_ = axis / length;
        swing_y_part_.CalculateConstraintProperties(body1, body2, swing_y_axis_);
      } else {
        swing_y_part_.Deactivate();
      }
      swing_z_part_.Deactivate();
    } else {
      swing_y_part_.Deactivate();
      swing_z_part_.Deactivate();
    }

    if (twist_.kind == AxisLimitKind::kLocked) {
      twist_axis_ = frame_x;
      twist_part_.CalculateConstraintProperties(body1, body2, twist_axis_);
    } else if (twist_.kind == AxisLimitKind::kLimited && (clamped & kClampedTwist) != 0) {
      twist_axis_ = (clamped & kClampedTwistMin) != 0 ? Vec3<T>(-frame_x) : frame_x;
      twist_part_.CalculateConstraintProperties(body1, body2, twist_axis_);
    } else {
      twist_part_.Deactivate();
    }
  }

  void Deactivate() {
    swing_y_part_.Deactivate();
    swing_z_part_.Deactivate();
    twist_part_.Deactivate();
  }
  bool IsActive() const {
    return swing_y_part_.IsActive() || swing_z_part_.IsActive() || twist_part_.IsActive();
  }

  // Scales the impulses of the previous step by dt/dt_prev and applies them
  // (inactive parts hold Λ = 0 and apply nothing).
  void WarmStart(Body<T>& body1, Body<T>& body2, T warm_start_ratio) {
    swing_y_part_.WarmStart(body1, body2, warm_start_ratio);
    swing_z_part_.WarmStart(body1, body2, warm_start_ratio);
    twist_part_.WarmStart(body1, body2, warm_start_ratio);
  }

  // Swing Y, swing Z, twist; true iff any of them applied an impulse.
  bool SolveVelocityConstraint(Body<T>& body1, Body<T>& body2) {
    bool applied = false;
    if (swing_y_part_.IsActive()) {
      applied |= swing_y_part_.SolveVelocityConstraint(body1, body2, swing_y_axis_, kMinusInf,
                                                       MaxLambda(swing_y_));
    }
    if (swing_z_part_.IsActive()) {
      applied |= swing_z_part_.SolveVelocityConstraint(body1, body2, swing_z_axis_, kMinusInf,
                                                       MaxLambda(swing_z_));
    }
    if (twist_part_.IsActive()) {
      applied |= twist_part_.SolveVelocityConstraint(body1, body2, twist_axis_, kMinusInf,
                                                     MaxLambda(twist_));
    }
    return applied;
  }

  // One 3-DOF Baumgarte step towards the clamped orientation if any limit is
  // violated; true iff a step was taken. constraint_rotation from the current poses.
  bool SolvePositionConstraint(Body<T>& body1, Body<T>& body2,
                               const Quat<T>& constraint_rotation,
                               const Quat<T>& constraint_to_body1,
                               const Quat<T>& constraint_to_body2, T baumgarte) const {
    const SwingTwist<T> decomposed = DecomposeSwingTwist(constraint_rotation);
    Quat<T> swing = decomposed.swing;
    Quat<T> twist = decomposed.twist;
    if (ClampSwingTwist(swing, twist) == 0) return false;
    const Quat<T> inv_initial_orientation =
        constraint_to_body2 * (constraint_to_body1 * swing * twist).conjugate();
    RotationEulerPart<T> towards_clamped;
    towards_clamped.CalculateConstraintProperties(body1, body2);
    return towards_clamped.SolvePositionConstraint(body1, body2, inv_initial_orientation,
                                                   baumgarte);
  }

  // Λ of (swing Y, swing Z, twist).
  Vec3<T> GetTotalLambda() const {
    return Vec3<T>(swing_y_part_.GetTotalLambda(), swing_z_part_.GetTotalLambda(),
                   twist_part_.GetTotalLambda());
  }
  void SetTotalLambda(const Vec3<T>& lambda) {
    swing_y_part_.SetTotalLambda(lambda.x());
    swing_z_part_.SetTotalLambda(lambda.y());
    twist_part_.SetTotalLambda(lambda.z());
  }
  Vec3<T> SaveState() const { return GetTotalLambda(); }  // the three Λ (spec 4.4)
  void RestoreState(const Vec3<T>& lambda) { SetTotalLambda(lambda); }

  // Read-only views, for tests.
  const AnglePart<T>& SwingYPart() const { return swing_y_part_; }
  const AnglePart<T>& SwingZPart() const { return swing_z_part_; }
  const AnglePart<T>& TwistPart() const { return twist_part_; }
  const Vec3<T>& SwingYAxis() const { return swing_y_axis_; }  // world, possibly negated
  const Vec3<T>& SwingZAxis() const { return swing_z_axis_; }
  const Vec3<T>& TwistAxis() const { return twist_axis_; }
  const AxisLimit<T>& TwistLimit() const { return twist_; }
  const AxisLimit<T>& SwingYLimit() const { return swing_y_; }
  const AxisLimit<T>& SwingZLimit() const { return swing_z_; }
  // Upper impulse bound of an axis: +∞ when sin_min == sin_max, else 0.
  static T MaxLambda(const AxisLimit<T>& limit) {
    return limit.sin_min == limit.sin_max ? std::numeric_limits<T>::infinity() : T(0);
  }

 private:
  static constexpr T kMinusInf = -std::numeric_limits<T>::infinity();

  static Quat<T> Negated(const Quat<T>& q) { return Quat<T>(-q.w(), -q.x(), -q.y(), -q.z()); }

  static AxisLimit<T> MakeAxisLimit(T min_angle, T max_angle) {
    constexpr T kLockedAngle = T(0.5) * std::numbers::pi_v<T> / T(180);
    constexpr T kFreeAngle = T(179.5) * std::numbers::pi_v<T> / T(180);
    AxisLimit<T> limit;
    limit.half_min = T(0.5) * min_angle;
    limit.half_max = T(0.5) * max_angle;
    if (min_angle > -kLockedAngle && max_angle < kLockedAngle) {
      limit.kind = AxisLimitKind::kLocked;
      limit.sin_min = limit.sin_max = T(0);
      limit.cos_min = limit.cos_max = T(1);
    } else if (min_angle < -kFreeAngle && max_angle > kFreeAngle) {
      limit.kind = AxisLimitKind::kFree;
      limit.sin_min = T(-1);
      limit.sin_max = T(1);
      limit.cos_min = limit.cos_max = T(0);
    } else {
      limit.kind = AxisLimitKind::kLimited;
      limit.sin_min = std::sin(limit.half_min);
      limit.sin_max = std::sin(limit.half_max);
      limit.cos_min = std::cos(limit.half_min);
      limit.cos_max = std::cos(limit.half_max);
    }
    return limit;
  }

  // 1-DOF clamp side of a sin(θ/2) value: 0 in range, −1 clamp to min, +1 to max.
  // Outside the range the nearer limit wins, with distances folded by "d > 1 ⇒ 2 − d"
  // because sin(θ/2) = ±1 is the same rotation.
  static int ClampSide(T value, const AxisLimit<T>& limit) {
    T delta_min = limit.sin_min - value;
    T delta_max = value - limit.sin_max;
    if (!(delta_min > T(0) || delta_max > T(0))) return 0;
    delta_min = std::abs(delta_min);
    if (delta_min > T(1)) delta_min = T(2) - delta_min;
    delta_max = std::abs(delta_max);
    if (delta_max > T(1)) delta_max = T(2) - delta_max;
    return delta_min < delta_max ? -1 : 1;
  }

  SwingType swing_type_ = SwingType::kCone;
  AxisLimit<T> twist_;    // default: free
  AxisLimit<T> swing_y_;
  AxisLimit<T> swing_z_;

  Vec3<T> swing_y_axis_ = Vec3<T>::Zero();  // world rotation axes of the three parts
  Vec3<T> swing_z_axis_ = Vec3<T>::Zero();
  Vec3<T> twist_axis_ = Vec3<T>::Zero();
  AnglePart<T> swing_y_part_;
  AnglePart<T> swing_z_part_;
  AnglePart<T> twist_part_;
};

// J·v of the three angle parts, a·(w2 − w1) on each part's current axis; zero for an
// inactive part. After a velocity solve the part solved last is exactly satisfied.
template <class T>
Vec3<T> SwingTwistVelocityError(const SwingTwistPart<T>& part, const Body<T>& body1,
                                const Body<T>& body2) {
  auto error = [&](const AnglePart<T>& angle, const Vec3<T>& axis) {
    return angle.IsActive() ? AngleVelocityError(body1, body2, axis) : T(0);
  };
  return Vec3<T>(error(part.SwingYPart(), part.SwingYAxis()),
                 error(part.SwingZPart(), part.SwingZAxis()),
                 error(part.TwistPart(), part.TwistAxis()));
}

}  // namespace manyworlds::reference
