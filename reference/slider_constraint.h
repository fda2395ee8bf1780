// Slider constraint of the reference world: body 2 slides along an axis of body
// 1 without rotating relative to it (spec 3, Slider). Parts, in solve order:
//
//   Axis (motor / friction) → DualAxis → RotationEuler → Axis (limit)
//
// Geometry, fixed at creation (body-COM space): anchors p1, p2; body 1's slider
// axis s and normal n; its second normal n' = s × n; r0⁻¹ from the frames with
// X = slider axis, Y = normal axis (spec 2.6).
//
// Per pose (spec 3): r1 = R1·p1, r2 = R2·p2, u = x2 + r2 − x1 − r1 (anchor 2 seen
// from anchor 1). Sideways (DualAxis on n1 = R1·n, n2 = R1·n'):
//
//   C = (u·n1, u·n2),  body 1's lever arm reaches anchor 2: r1 + u
//
// rotation (RotationEuler): C = 2·xyz(EnsureWPositive(q2·r0⁻¹·q1*)), and along the
// slider axis s_w = R1·s the position d = u·s_w (only computed when limits, motor
// or friction use it).
//
// Limits [min ≤ 0, max ≥ 0], none when both are ±FLT_MAX. The limit row is on when
// d <= min (C = d − min, impulse [0, ∞): only push body 2 towards +s) or d >= max
// (C = d − max, impulse (−∞, 0]); both ways when min == max. A limit spring with
// stiffness makes it soft; hard limits are also corrected in the position phase.
//
// Motor row on s_w (J·v = dd/dt):
//   Off + max_friction_force > 0: hard, bias 0, range dt·[−f, f] (friction);
//   Velocity: hard, bias −v_target, range dt·[min F, max F];
//   Position: motor spring (needs stiffness) on C = d − d_target;
//   PositionAndVelocity: motor spring (stiffness or damping), bias −v_target, same C.
//   Otherwise off. Motors act through velocities only.
//
// Setup:    r1, r2, u; DualAxis; RotationEuler; s_w and d; limit row; motor row.
// Velocity: motor, dual axis, rotation, limit (warm start and every iteration).
// Position: DualAxis recomputed from the current pose and stepped with u →
//           RotationEuler recomputed with the rotations as they are now, stepped →
//           hard limits only: r1, r2, u, s_w, d and the limit row recomputed, which
//           DEACTIVATES the row (Λ = 0, spec 1.3) when the limit is no longer
//           violated; else one step with d − min (d <= min) or d − max.
#pragma once

#include <algorithm>
#include <cfloat>
#include <cstddef>
#include <limits>

#include "manyworlds/scene.h"
#include "manyworlds/spring_settings.h"
#include "reference/axis_part.h"
#include "reference/body.h"
#include "reference/dual_axis_part.h"
#include "reference/math.h"
#include "reference/rotation_euler_part.h"
#include "reference/solver_state.h"
#include "reference/spring_part.h"
#include "reference/world_setup.h"

namespace manyworlds::reference {

// Position of anchor 2 along body 1's slider axis, from the current pose; shared
// with the rack-and-pinion position step.
template <class T>
T SliderCurrentPosition(const Body<T>& body1, const Body<T>& body2, const Vec3<T>& local_point1,
                        const Vec3<T>& local_point2, const Vec3<T>& local_slider_axis1) {
  const Vec3<T> u = (body2.position - body1.position) + body2.rotation * local_point2 -
                    body1.rotation * local_point1;
  return u.dot(body1.rotation * local_slider_axis1);
}

template <class T>
class SliderConstraint {
 public:
  SliderConstraint(const SliderConstraintSettings& settings, const Body<T>& body1,
                   const Body<T>& body2)
      : body1_(settings.body1), body2_(settings.body2) {
    const ConstraintBodies<T> bodies{body1, body2, settings.space};
    const LocalAnchors<T> anchors = FixedOrSliderAnchors(bodies, settings.auto_detect_point,
                                                         settings.point1, settings.point2);
    local_point1_ = anchors.point1;
    local_point2_ = anchors.point2;
    local_slider_axis1_ = bodies.LocalAxis1(settings.slider_axis1);
    local_normal1_ = bodies.LocalAxis1(settings.normal_axis1);
    local_normal2_ = local_slider_axis1_.cross(local_normal1_);
    inv_initial_orientation_ = bodies.BodySpaceInvInitialOrientation(InvInitialOrientationXY(
        ToVec3<T>(settings.slider_axis1), ToVec3<T>(settings.normal_axis1),
        ToVec3<T>(settings.slider_axis2), ToVec3<T>(settings.normal_axis2)));

    // "No limits" decided on the float settings (so float and double agree).
    has_limits_ = settings.limits_min != -FLT_MAX || settings.limits_max != FLT_MAX;
    limits_min_ = T(settings.limits_min);
    limits_max_ = T(settings.limits_max);
    limits_spring_ = ToReferenceSpring<T>(settings.limits_spring);
    hard_limits_ = settings.limits_spring.frequency_or_stiffness <= 0.0f;

    max_friction_force_ = T(settings.max_friction_force);
    motor_state_ = settings.motor_state;
    motor_spring_ = ToReferenceSpring<T>(settings.motor.spring);
    min_motor_force_ = T(settings.motor.min_force_limit);
    max_motor_force_ = T(settings.motor.max_force_limit);
    target_velocity_ = T(settings.target_velocity);
    SetTargetPosition(T(settings.target_position));
  }

  std::size_t body1() const { return body1_; }
  std::size_t body2() const { return body2_; }

  void SetTargetVelocity(T velocity) { target_velocity_ = velocity; }
  // Clamped into the limits when the slider has limits (spec 3).
  void SetTargetPosition(T position) {
    target_position_ = has_limits_ ? std::clamp(position, limits_min_, limits_max_) : position;
  }
  T target_position() const { return target_position_; }

  // d from the bodies' current pose (what rack-and-pinion reads).
  T CurrentPosition(const Body<T>& body1, const Body<T>& body2) const {
    return SliderCurrentPosition(body1, body2, local_point1_, local_point2_, local_slider_axis1_);
  }

  void SetupVelocityConstraint(const Body<T>& body1, const Body<T>& body2, T dt) {
    CalculateLeverArms(body1, body2);
    CalculateDualAxisProperties(body1, body2);
    rotation_.CalculateConstraintProperties(body1, body2);
    CalculateSlidingAxisAndPosition(body1);
    CalculateLimitProperties(body1, body2, dt);
    CalculateMotorProperties(body1, body2, dt);
  }

  void WarmStartVelocityConstraint(Body<T>& body1, Body<T>& body2, T warm_start_ratio) {
    motor_.WarmStart(body1, body2, slider_axis_, warm_start_ratio);
    dual_axis_.WarmStart(body1, body2, n1_, n2_, warm_start_ratio);
    rotation_.WarmStart(body1, body2, warm_start_ratio);
    limit_.WarmStart(body1, body2, slider_axis_, warm_start_ratio);
  }

  // Every part solves every iteration; `|` (not `||`) so none is skipped.
  bool SolveVelocityConstraint(Body<T>& body1, Body<T>& body2, T dt) {
    const bool motor = SolveMotorVelocity(body1, body2, dt);
    const bool sideways = dual_axis_.SolveVelocityConstraint(body1, body2, n1_, n2_);
    const bool rotation = rotation_.SolveVelocityConstraint(body1, body2);
    const bool limit = SolveLimitVelocity(body1, body2);
    return motor | sideways | rotation | limit;
  }

  // The rows the exact solve leaves to Gauss-Seidel (motor or friction, and
  // limits; reference/world.h): their setup at the current poses, warm
  // start, velocity and position steps.
  void SetupInequalityRows(const Body<T>& body1, const Body<T>& body2, T dt) {
    CalculateLeverArms(body1, body2);
    CalculateSlidingAxisAndPosition(body1);
    CalculateLimitProperties(body1, body2, dt);
    CalculateMotorProperties(body1, body2, dt);
  }
  void WarmStartInequalityRows(Body<T>& body1, Body<T>& body2, T warm_start_ratio) {
    motor_.WarmStart(body1, body2, slider_axis_, warm_start_ratio);
    limit_.WarmStart(body1, body2, slider_axis_, warm_start_ratio);
  }
  bool SolveInequalityVelocity(Body<T>& body1, Body<T>& body2, T dt) {
    const bool motor = SolveMotorVelocity(body1, body2, dt);
    return motor | SolveLimitVelocity(body1, body2);
  }

  bool SolvePositionConstraint(Body<T>& body1, Body<T>& body2, T dt, T baumgarte) {
    CalculateLeverArms(body1, body2);
    CalculateDualAxisProperties(body1, body2);
    const bool sideways =
        dual_axis_.SolvePositionConstraint(body1, body2, u_, n1_, n2_, baumgarte);

    // The sideways step rotated the bodies: inertia from the rotations as they are now.
    rotation_.CalculateConstraintProperties(body1, body2);
    const bool rotation =
        rotation_.SolvePositionConstraint(body1, body2, inv_initial_orientation_, baumgarte);

    const bool limit = SolveLimitPosition(body1, body2, dt, baumgarte);
    return sideways | rotation | limit;
  }

  bool SolveLimitPosition(Body<T>& body1, Body<T>& body2, T dt, T baumgarte) {
    if (!has_limits_ || !hard_limits_) return false;
    CalculateLeverArms(body1, body2);
    CalculateSlidingAxisAndPosition(body1);
    CalculateLimitProperties(body1, body2, dt);  // may deactivate (Λ = 0), spec 1.3
    if (!limit_.IsActive()) return false;
    const T error = d_ <= limits_min_ ? d_ - limits_min_ : d_ - limits_max_;
    return limit_.SolvePositionConstraint(body1, body2, slider_axis_, error, baumgarte);
  }

  // Read-only views for tests.
  const AxisPart<T>& motor_part() const { return motor_; }
  const AxisPart<T>& limit_part() const { return limit_; }
  const DualAxisPart<T>& dual_axis_part() const { return dual_axis_; }
  const RotationEulerPart<T>& rotation_part() const { return rotation_; }
  const Quat<T>& inv_initial_orientation() const { return inv_initial_orientation_; }
  bool has_limits() const { return has_limits_; }
  // The exact solve's view (body space).
  const Vec3<T>& local_point1() const { return local_point1_; }
  const Vec3<T>& local_point2() const { return local_point2_; }
  const Vec3<T>& local_normal1() const { return local_normal1_; }
  const Vec3<T>& local_normal2() const { return local_normal2_; }
  bool HasInequalityRows() const { return UsesPosition(); }

  // Solver state (reference/solver_state.h), in the batch's order
  // (docs/stepping.md, "Solver state of one world").
  void SaveSolverState(SolverStateWriter<T>& out) const {
    out(motor_.SaveState());
    out(dual_axis_.SaveState());
    out(rotation_.SaveState());
    out(limit_.SaveState());
  }
  void RestoreSolverState(SolverStateReader<T>& in) {
    motor_.RestoreState(in.Scalar());
    dual_axis_.RestoreState(in.Vector2());
    rotation_.RestoreState(in.Vector3());
    limit_.RestoreState(in.Scalar());
  }

 private:
  bool SolveMotorVelocity(Body<T>& body1, Body<T>& body2, T dt) {
    if (!motor_.IsActive()) return false;
    if (motor_state_ == MotorState::kOff) {
      // Friction: a zero-velocity row that can apply at most f·dt per step.
      const T max_lambda = max_friction_force_ * dt;
      return motor_.SolveVelocityConstraint(body1, body2, slider_axis_, -max_lambda, max_lambda);
    }
    return motor_.SolveVelocityConstraint(body1, body2, slider_axis_, dt * min_motor_force_,
                                          dt * max_motor_force_);
  }

  bool SolveLimitVelocity(Body<T>& body1, Body<T>& body2) {
    if (!limit_.IsActive()) return false;
    // Range from d of the last setup (the velocity phase does not move bodies).
    constexpr T kMax = std::numeric_limits<T>::max();
    T min_lambda = -kMax, max_lambda = kMax;
    if (limits_min_ != limits_max_) {
      if (d_ <= limits_min_) {
        min_lambda = T(0);
      } else {
        max_lambda = T(0);
      }
    }
    return limit_.SolveVelocityConstraint(body1, body2, slider_axis_, min_lambda, max_lambda);
  }

  bool UsesPosition() const {
    return has_limits_ || motor_state_ != MotorState::kOff || max_friction_force_ > T(0);
  }

  // r1, r2 and u from the current pose.
  void CalculateLeverArms(const Body<T>& body1, const Body<T>& body2) {
    r1_ = body1.rotation * local_point1_;
    r2_ = body2.rotation * local_point2_;
    u_ = (body2.position - body1.position) + r2_ - r1_;
  }

  // World normals (both fixed in body 1) and the sideways part.
  void CalculateDualAxisProperties(const Body<T>& body1, const Body<T>& body2) {
    n1_ = body1.rotation * local_normal1_;
    n2_ = body1.rotation * local_normal2_;
    dual_axis_.CalculateConstraintProperties(body1, r1_ + u_, body2, r2_, n1_, n2_);
  }

  void CalculateSlidingAxisAndPosition(const Body<T>& body1) {
    if (!UsesPosition()) return;
    slider_axis_ = body1.rotation * local_slider_axis1_;
    d_ = u_.dot(slider_axis_);
  }

  void CalculateLimitProperties(const Body<T>& body1, const Body<T>& body2, T dt) {
    const bool below_min = d_ <= limits_min_;
    if (has_limits_ && (below_min || d_ >= limits_max_)) {
      const T error = below_min ? d_ - limits_min_ : d_ - limits_max_;
      limit_.CalculateConstraintPropertiesWithSettingsForLimit(
          dt, body1, r1_ + u_, body2, r2_, slider_axis_, T(0), error, limits_spring_);
    } else {
      limit_.Deactivate();
    }
  }

  void CalculateMotorProperties(const Body<T>& body1, const Body<T>& body2, T dt) {
    switch (motor_state_) {
      case MotorState::kOff:
        if (max_friction_force_ > T(0)) {
          motor_.CalculateConstraintProperties(body1, r1_ + u_, body2, r2_, slider_axis_);
        } else {
          motor_.Deactivate();
        }
        return;
      case MotorState::kVelocity:
        motor_.CalculateConstraintProperties(body1, r1_ + u_, body2, r2_, slider_axis_,
                                             -target_velocity_);
        return;
      case MotorState::kPosition:
        if (motor_spring_.HasStiffness()) {
          motor_.CalculateConstraintPropertiesWithSettingsForMotor(
              dt, body1, r1_ + u_, body2, r2_, slider_axis_, T(0), d_ - target_position_,
              motor_spring_);
        } else {
          motor_.Deactivate();
        }
        return;
      case MotorState::kPositionAndVelocity:
        if (motor_spring_.HasStiffnessOrDamping()) {
          motor_.CalculateConstraintPropertiesWithSettingsForMotor(
              dt, body1, r1_ + u_, body2, r2_, slider_axis_, -target_velocity_,
              d_ - target_position_, motor_spring_);
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
  Vec3<T> local_slider_axis1_ = Vec3<T>::UnitX();
  Vec3<T> local_normal1_ = Vec3<T>::UnitY();
  Vec3<T> local_normal2_ = Vec3<T>::UnitZ();  // slider × normal, body 1
  Quat<T> inv_initial_orientation_ = Quat<T>::Identity();  // r0⁻¹

  // Limits.
  bool has_limits_ = false;
  bool hard_limits_ = true;
  T limits_min_ = T(0);
  T limits_max_ = T(0);
  SpringSettings<T> limits_spring_;

  // Motor and friction.
  MotorState motor_state_ = MotorState::kOff;
  SpringSettings<T> motor_spring_;
  T min_motor_force_ = T(0);  // N; the impulse range is dt times these
  T max_motor_force_ = T(0);
  T max_friction_force_ = T(0);
  T target_velocity_ = T(0);
  T target_position_ = T(0);

  // Per pose (setup; refreshed in the position phase).
  Vec3<T> r1_ = Vec3<T>::Zero();
  Vec3<T> r2_ = Vec3<T>::Zero();
  Vec3<T> u_ = Vec3<T>::Zero();
  Vec3<T> n1_ = Vec3<T>::Zero();
  Vec3<T> n2_ = Vec3<T>::Zero();
  Vec3<T> slider_axis_ = Vec3<T>::Zero();  // s_w = R1·s
  T d_ = T(0);

  AxisPart<T> motor_;
  DualAxisPart<T> dual_axis_;
  RotationEulerPart<T> rotation_;
  AxisPart<T> limit_;
};

}  // namespace manyworlds::reference
