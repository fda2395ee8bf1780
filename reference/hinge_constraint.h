// Hinge constraint of the reference world: body 2 turns relative to body 1 about
// one axis through a shared anchor (spec 3, Hinge). Parts, in solve order:
//
//   Angle (motor / friction) → Point → HingeRotation → Angle (limit)
//
// Geometry, fixed at creation (body-COM space): anchors p1, p2; hinge axes h1, h2;
// r0⁻¹ from the frames with X = normal axis, Z = hinge axis (spec 2.6).
//
// Hinge angle (spec 3), from the current rotations:
//
//   diff = q2·r0⁻¹·q1*   (identity at rest, a rotation about a1 when the hinge holds)
//   a1   = q1·h1          θ = 2·atan((diff.xyz·a1) / diff.w) ∈ (−π, π]   (π if w = 0)
//
// Limits [min, max] with min ∈ [−π, 0], max ∈ [0, π]; the hinge has limits unless
// min = −π and max = π. The limit row is on when θ <= min or θ >= max, with the
// error to the NEARER limit measured on the circle:
//
//   e_min = CenterAngleAroundZero(θ − min),  e_max = CenterAngleAroundZero(θ − max),
//   C = e_min if |e_min| < |e_max| else e_max,
//   impulse range: both ways if min == max; [0, ∞) if the min limit is nearer
//   (body 2 may only be pushed towards larger θ); (−∞, 0] otherwise.
//
// A limit spring (limits_spring with stiffness) makes the row soft; a hard limit
// is also corrected in the position phase.
//
// Motor row on a1, J = [0, −a1, 0, a1], so J·v = a1·(w2 − w1) = dθ/dt:
//   Off + max_friction_torque > 0: hard, bias 0, range dt·[−f, f] (friction);
//   Velocity: hard, bias −ω_target (drives J·v to ω_target), range dt·[min τ, max τ];
//   Position: motor spring (needs stiffness) on C = CenterAngleAroundZero(θ − θ_target);
//   PositionAndVelocity: motor spring (stiffness or damping) with bias −ω_target and
//   the same C. Otherwise the row is off (Deactivate). Motors never take position
//   steps: they act through velocities only.
//
// Setup:    Point and HingeRotation from the current rotations; θ and a1 (if
//           limits, motor or friction are in use); limit row; motor row.
// Velocity: motor, point, rotation, limit (warm start and every iteration).
// Position: Point (recomputed) → HingeRotation (recomputed with the rotations the
//           point step left) → hard limits only: θ and the limit row recomputed,
//           which DEACTIVATES the row (and zeroes its accumulated impulse, spec 1.3)
//           when the limit is no longer violated; else one step with C.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <numbers>

#include "manyworlds/scene.h"
#include "manyworlds/spring_settings.h"
#include "reference/angle_part.h"
#include "reference/body.h"
#include "reference/hinge_rotation_part.h"
#include "reference/math.h"
#include "reference/point_part.h"
#include "reference/rotation_euler_part.h"
#include "reference/solver_state.h"
#include "reference/spring_part.h"
#include "reference/world_setup.h"

namespace manyworlds::reference {

// Rotation angle of body 2 relative to body 1 about body 1's hinge axis (see the
// header comment); shared with the gear and rack-and-pinion position steps.
template <class T>
T HingeCurrentAngle(const Body<T>& body1, const Body<T>& body2,
                    const Quat<T>& inv_initial_orientation, const Vec3<T>& local_hinge_axis1) {
  const Quat<T> diff = body2.rotation * inv_initial_orientation * body1.rotation.conjugate();
  const Vec3<T> a1 = body1.rotation * local_hinge_axis1;
  return QuatRotationAngle(diff, a1);
}

template <class T>
class HingeConstraint {
 public:
  HingeConstraint(const HingeConstraintSettings& settings, const Body<T>& body1,
                  const Body<T>& body2)
      : body1_(settings.body1), body2_(settings.body2) {
    const ConstraintBodies<T> bodies{body1, body2, settings.space};
    local_point1_ = bodies.LocalPoint1(settings.point1);
    local_point2_ = bodies.LocalPoint2(settings.point2);
    local_hinge_axis1_ = bodies.LocalAxis1(settings.hinge_axis1);
    local_hinge_axis2_ = bodies.LocalAxis2(settings.hinge_axis2);
    inv_initial_orientation_ = bodies.BodySpaceInvInitialOrientation(InvInitialOrientationXZ(
        ToVec3<T>(settings.normal_axis1), ToVec3<T>(settings.hinge_axis1),
        ToVec3<T>(settings.normal_axis2), ToVec3<T>(settings.hinge_axis2)));

    // "No limits" is decided on the float settings, against the float π the scene
    // uses, so float and double worlds agree on it.
    has_limits_ = settings.limits_min != -kPi || settings.limits_max != kPi;
    limits_min_ = T(settings.limits_min);
    limits_max_ = T(settings.limits_max);
    limits_spring_ = ToReferenceSpring<T>(settings.limits_spring);
    hard_limits_ = settings.limits_spring.frequency_or_stiffness <= 0.0f;

    max_friction_torque_ = T(settings.max_friction_torque);
    motor_state_ = settings.motor_state;
    motor_spring_ = ToReferenceSpring<T>(settings.motor.spring);
    min_motor_torque_ = T(settings.motor.min_force_limit);
    max_motor_torque_ = T(settings.motor.max_force_limit);
    target_angular_velocity_ = T(settings.target_angular_velocity);
    SetTargetAngle(T(settings.target_angle));
  }

  std::size_t body1() const { return body1_; }
  std::size_t body2() const { return body2_; }

  void SetTargetAngularVelocity(T angular_velocity) {
    target_angular_velocity_ = angular_velocity;
  }
  // Clamped into the limits when the hinge has limits (spec 3).
  void SetTargetAngle(T angle) {
    target_angle_ = has_limits_ ? std::clamp(angle, limits_min_, limits_max_) : angle;
  }
  T target_angle() const { return target_angle_; }

  // θ from the bodies' current rotations (what gear and rack-and-pinion read).
  T CurrentAngle(const Body<T>& body1, const Body<T>& body2) const {
    return HingeCurrentAngle(body1, body2, inv_initial_orientation_, local_hinge_axis1_);
  }

  // The unwrapped angle now: the current angle continued from the angle and
  // whole turns counted at the last setup (the gear and rack-and-pinion
  // position steps read it; docs/constraint-parts.md, "Unwrapped angles").
  T UnwrappedAngle(const Body<T>& body1, const Body<T>& body2) const {
    constexpr T kTwoPi = T(2) * std::numbers::pi_v<T>;
    T since_setup = CurrentAngle(body1, body2) - turn_reference_angle_;
    if (since_setup > std::numbers::pi_v<T>) since_setup -= kTwoPi;
    if (since_setup < -std::numbers::pi_v<T>) since_setup += kTwoPi;
    return turn_reference_angle_ + kTwoPi * turns_ + since_setup;
  }

  void SetupVelocityConstraint(const Body<T>& body1, const Body<T>& body2, T dt) {
    const T theta = CurrentAngle(body1, body2);
    CountTurns(theta);
    point_.CalculateConstraintProperties(body1, local_point1_, body2, local_point2_);
    rotation_.CalculateConstraintProperties(body1, body1.rotation * local_hinge_axis1_, body2,
                                            body2.rotation * local_hinge_axis2_);
    CalculateAxisAndAngle(body1, theta);
    CalculateLimitProperties(body1, body2, dt);
    CalculateMotorProperties(body1, body2, dt);
  }

  void WarmStartVelocityConstraint(Body<T>& body1, Body<T>& body2, T warm_start_ratio) {
    motor_.WarmStart(body1, body2, warm_start_ratio);
    point_.WarmStart(body1, body2, warm_start_ratio);
    rotation_.WarmStart(body1, body2, warm_start_ratio);
    limit_.WarmStart(body1, body2, warm_start_ratio);
  }

  // Every part solves every iteration; `|` (not `||`) so none is skipped.
  bool SolveVelocityConstraint(Body<T>& body1, Body<T>& body2, T dt) {
    const bool motor = SolveMotorVelocity(body1, body2, dt);
    const bool point = point_.SolveVelocityConstraint(body1, body2);
    const bool rotation = rotation_.SolveVelocityConstraint(body1, body2);
    const bool limit = SolveLimitVelocity(body1, body2);
    return motor | point | rotation | limit;
  }

  bool SolvePositionConstraint(Body<T>& body1, Body<T>& body2, T dt, T baumgarte) {
    point_.CalculateConstraintProperties(body1, local_point1_, body2, local_point2_);
    const bool point = point_.SolvePositionConstraint(body1, body2, baumgarte);

    // The point step rotated the bodies: axes from the rotations as they are now.
    rotation_.CalculateConstraintProperties(body1, body1.rotation * local_hinge_axis1_, body2,
                                            body2.rotation * local_hinge_axis2_);
    const bool rotation = rotation_.SolvePositionConstraint(body1, body2, baumgarte);
    const bool limit = SolveLimitPosition(body1, body2, dt, baumgarte);
    return point | rotation | limit;
  }

  // The rows the exact solve leaves to Gauss-Seidel (motor or friction, and
  // limits; reference/world.h): their setup at the current poses (the turn
  // count apart, CountTurnsAt), warm start, velocity and position steps.
  void SetupInequalityRows(const Body<T>& body1, const Body<T>& body2, T dt) {
    CalculateAxisAndAngle(body1, CurrentAngle(body1, body2));
    CalculateLimitProperties(body1, body2, dt);
    CalculateMotorProperties(body1, body2, dt);
  }
  void WarmStartInequalityRows(Body<T>& body1, Body<T>& body2, T warm_start_ratio) {
    motor_.WarmStart(body1, body2, warm_start_ratio);
    limit_.WarmStart(body1, body2, warm_start_ratio);
  }
  bool SolveInequalityVelocity(Body<T>& body1, Body<T>& body2, T dt) {
    const bool motor = SolveMotorVelocity(body1, body2, dt);
    return motor | SolveLimitVelocity(body1, body2);
  }
  bool SolveLimitPosition(Body<T>& body1, Body<T>& body2, T dt, T baumgarte) {
    if (!has_limits_ || !hard_limits_) return false;
    CalculateAxisAndAngle(body1, CurrentAngle(body1, body2));
    CalculateLimitProperties(body1, body2, dt);  // may deactivate (Λ = 0), spec 1.3
    if (!limit_.IsActive()) return false;
    return limit_.SolvePositionConstraint(body1, body2, SmallestAngleToLimit(), baumgarte);
  }

  // Read-only views for tests.
  const AnglePart<T>& motor_part() const { return motor_; }
  const AnglePart<T>& limit_part() const { return limit_; }
  const PointPart<T>& point_part() const { return point_; }
  const HingeRotationPart<T>& rotation_part() const { return rotation_; }
  bool has_limits() const { return has_limits_; }
  // The exact solve's view: anchors and axes in body space; whether limits,
  // motor or friction add inequality rows.
  const Vec3<T>& local_point1() const { return local_point1_; }
  const Vec3<T>& local_point2() const { return local_point2_; }
  const Vec3<T>& local_hinge_axis1() const { return local_hinge_axis1_; }
  const Vec3<T>& local_hinge_axis2() const { return local_hinge_axis2_; }
  bool HasInequalityRows() const { return UsesAngle(); }
  // What a velocity setup does to the turn count (the exact solve has none).
  void CountTurnsAt(const Body<T>& body1, const Body<T>& body2) {
    CountTurns(CurrentAngle(body1, body2));
  }

  // The point part's accumulated impulse (the exact solve's point group).
  Vec3<T> PointImpulse() const { return point_.SaveState(); }
  // Solver state (reference/solver_state.h), in the batch's order
  // (docs/stepping.md, "Solver state of one world").
  void SaveSolverState(SolverStateWriter<T>& out) const {
    out(motor_.SaveState());
    out(point_.SaveState());
    out(rotation_.SaveState());
    out(limit_.SaveState());
    out(turn_reference_angle_);
    out(turns_);
  }
  void RestoreSolverState(SolverStateReader<T>& in) {
    motor_.RestoreState(in.Scalar());
    point_.RestoreState(in.Vector3());
    rotation_.RestoreState(in.Vector2());
    limit_.RestoreState(in.Scalar());
    turn_reference_angle_ = in.Scalar();
    turns_ = in.Scalar();
  }

 private:
  struct LambdaRange {
    T min;
    T max;
  };

  bool SolveMotorVelocity(Body<T>& body1, Body<T>& body2, T dt) {
    if (!motor_.IsActive()) return false;
    if (motor_state_ == MotorState::kOff) {
      // Friction: a zero-velocity row that can apply at most f·dt per step.
      const T max_lambda = max_friction_torque_ * dt;
      return motor_.SolveVelocityConstraint(body1, body2, a1_, -max_lambda, max_lambda);
    }
    return motor_.SolveVelocityConstraint(body1, body2, a1_, dt * min_motor_torque_,
                                          dt * max_motor_torque_);
  }

  bool SolveLimitVelocity(Body<T>& body1, Body<T>& body2) {
    if (!limit_.IsActive()) return false;
    const LambdaRange range = LimitLambdaRange();
    return limit_.SolveVelocityConstraint(body1, body2, a1_, range.min, range.max);
  }

  // A jump of more than pi since the last setup is a wrap through +-pi (the
  // hinge turned less than pi the other way): one turn up or down.
  void CountTurns(T theta) {
    const T jump = theta - turn_reference_angle_;
    if (jump < -std::numbers::pi_v<T>) turns_ += T(1);
    if (jump > std::numbers::pi_v<T>) turns_ -= T(1);
    turn_reference_angle_ = theta;
  }

  bool UsesAngle() const {
    return has_limits_ || motor_state_ != MotorState::kOff || max_friction_torque_ > T(0);
  }

  // a1 and θ (the current angle), kept only when limits, motor or friction
  // need them (as Jolt).
  void CalculateAxisAndAngle(const Body<T>& body1, T theta) {
    if (!UsesAngle()) return;
    a1_ = body1.rotation * local_hinge_axis1_;
    theta_ = theta;
  }

  T AngleToMin() const { return CenterAngleAroundZero(theta_ - limits_min_); }
  T AngleToMax() const { return CenterAngleAroundZero(theta_ - limits_max_); }
  bool MinLimitIsNearer() const { return std::abs(AngleToMin()) < std::abs(AngleToMax()); }
  T SmallestAngleToLimit() const { return MinLimitIsNearer() ? AngleToMin() : AngleToMax(); }

  // Uses θ of the last setup, as the velocity phase does in Jolt.
  LambdaRange LimitLambdaRange() const {
    constexpr T kMax = std::numeric_limits<T>::max();
    if (limits_min_ == limits_max_) return {-kMax, kMax};
    if (MinLimitIsNearer()) return {T(0), kMax};
    return {-kMax, T(0)};
  }

  void CalculateLimitProperties(const Body<T>& body1, const Body<T>& body2, T dt) {
    if (has_limits_ && (theta_ <= limits_min_ || theta_ >= limits_max_)) {
      limit_.CalculateConstraintPropertiesWithSettingsForLimit(
          dt, body1, body2, a1_, T(0), SmallestAngleToLimit(), limits_spring_);
    } else {
      limit_.Deactivate();
    }
  }

  void CalculateMotorProperties(const Body<T>& body1, const Body<T>& body2, T dt) {
    switch (motor_state_) {
      case MotorState::kOff:
        if (max_friction_torque_ > T(0)) {
          motor_.CalculateConstraintProperties(body1, body2, a1_);
        } else {
          motor_.Deactivate();
        }
        return;
      case MotorState::kVelocity:
        motor_.CalculateConstraintProperties(body1, body2, a1_, -target_angular_velocity_);
        return;
      case MotorState::kPosition:
        if (motor_spring_.HasStiffness()) {
          motor_.CalculateConstraintPropertiesWithSettingsForMotor(
              dt, body1, body2, a1_, T(0), CenterAngleAroundZero(theta_ - target_angle_),
              motor_spring_);
        } else {
          motor_.Deactivate();
        }
        return;
      case MotorState::kPositionAndVelocity:
        if (motor_spring_.HasStiffnessOrDamping()) {
          motor_.CalculateConstraintPropertiesWithSettingsForMotor(
              dt, body1, body2, a1_, -target_angular_velocity_,
              CenterAngleAroundZero(theta_ - target_angle_), motor_spring_);
        } else {
          motor_.Deactivate();
        }
        return;
    }
  }

  std::size_t body1_, body2_;

  // Geometry (body-COM space), fixed at creation.
  Vec3<T> local_point1_ = Vec3<T>::Zero();
  Vec3<T> local_point2_ = Vec3<T>::Zero();
  Vec3<T> local_hinge_axis1_ = Vec3<T>::UnitY();
  Vec3<T> local_hinge_axis2_ = Vec3<T>::UnitY();
  Quat<T> inv_initial_orientation_ = Quat<T>::Identity();  // r0⁻¹

  // Limits.
  bool has_limits_ = false;
  bool hard_limits_ = true;  // no limit spring: position-phase limit steps
  T limits_min_ = T(0);
  T limits_max_ = T(0);
  SpringSettings<T> limits_spring_;

  // Motor and friction.
  MotorState motor_state_ = MotorState::kOff;
  SpringSettings<T> motor_spring_;
  T min_motor_torque_ = T(0);  // N m; the impulse range is dt times these
  T max_motor_torque_ = T(0);
  T max_friction_torque_ = T(0);
  T target_angular_velocity_ = T(0);
  T target_angle_ = T(0);

  // Per step (setup), refreshed in the position phase for hard limits.
  Vec3<T> a1_ = Vec3<T>::Zero();  // world hinge axis of body 1
  T theta_ = T(0);
  // Turn counting: the angle at the last setup and the whole turns since
  // the scene's pose (a hinge turning more than pi in one substep is
  // miscounted).
  T turn_reference_angle_ = T(0);
  T turns_ = T(0);

  AnglePart<T> motor_;
  PointPart<T> point_;
  HingeRotationPart<T> rotation_;
  AnglePart<T> limit_;
};

}  // namespace manyworlds::reference
