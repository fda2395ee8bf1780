// Path constraint of the reference world (spec 3, Path): body 2's attachment
// point slides along a Hermite path (reference/hermite_path.h) fixed to body 1.
//
// Frames, fixed at creation: path space in body 1's COM space (rotation qp1,
// origin tp1; world settings moved in at the initial poses); the attachment
// frame (X = tangent, Y = binormal, Z = normal of the path at the starting
// fraction) in body 2's COM space (qa2, ta2); for kFullyConstrained
// r0⁻¹ = q2*·q1 of the initial poses.
//
// CalculateConstraintProperties (setup, and again at the start of every
// position iteration): a = x2 + q2·ta2; fraction = closest point of the path to
// a in path space; path point p, tangent t, normal n, binormal b there (world);
// r1 = p − x1, r2 = a − x2, u = a − p. Then
//   DualAxisPart on (n, b) with lever arms r1 + u, r2;
//   end limit: an AxisPart on t, hard, where an open path's fraction is ≤ 0
//     (impulse ≥ 0) or ≥ its end (impulse ≤ 0); Deactivate (Λ = 0) otherwise;
//   rotation: HingeRotationPart on (t, n or b) and body 2's (X, Z or Y) axis, or
//     RotationEulerPart (to the path: r0⁻¹ = qa2·(qp1·q_frame)*, q_frame the
//     (t, b, n) frame in path space; fully constrained: the fixed r0⁻¹);
//   motor: an AxisPart on t: friction (bias 0, dt·[−f, f]), velocity (bias
//     −v, dt·[min F, max F]), position (motor spring on C = fraction − target,
//     wrapped into ±half the length on a looping path), position and velocity.
// Velocity: motor, dual axis, end limit, rotation (warm start likewise).
// Position: recompute as above, then one step each: dual axis on u, end limit
// on u·t, rotation.
#pragma once

#include <cfloat>
#include <cmath>
#include <cstddef>
#include <limits>

#include "manyworlds/scene.h"
#include "reference/axis_part.h"
#include "reference/body.h"
#include "reference/dual_axis_part.h"
#include "reference/hermite_path.h"
#include "reference/hinge_rotation_part.h"
#include "reference/math.h"
#include "reference/rotation_euler_part.h"
#include "reference/solver_state.h"
#include "reference/spring_part.h"
#include "reference/world_setup.h"

namespace manyworlds::reference {

template <class T>
class PathConstraint {
 public:
  PathConstraint(const PathConstraintSettings& settings, const Body<T>& body1,
                 const Body<T>& body2)
      : body1_(settings.body1),
        body2_(settings.body2),
        path_(settings.path, settings.looping),
        rotation_mode_(settings.rotation),
        motor_state_(settings.motor_state),
        motor_spring_(ToReferenceSpring<T>(settings.motor.spring)),
        min_motor_force_(T(settings.motor.min_force_limit)),
        max_motor_force_(T(settings.motor.max_force_limit)),
        max_friction_force_(T(settings.max_friction_force)),
        target_velocity_(T(settings.target_velocity)),
        target_fraction_(T(settings.target_path_fraction)) {
    path_rotation_ = ToQuat<T>(settings.path_rotation).normalized();
    path_position_ = ToVec3<T>(settings.path_position);
    if (settings.space == ConstraintSpace::kWorldSpace) {
      path_rotation_ = (body1.rotation.conjugate() * path_rotation_).normalized();
      path_position_ = body1.rotation.conjugate() * (path_position_ - body1.position);
    }
    const typename HermitePath<T>::Frame start = path_.PointOnPath(T(settings.path_fraction));
    const Quat<T> attachment_world = body1.rotation * path_rotation_ * FrameRotation(start);
    const Vec3<T> attachment =
        body1.position + body1.rotation * (path_position_ + path_rotation_ * start.position);
    attachment_rotation_ = (body2.rotation.conjugate() * attachment_world).normalized();
    attachment_position_ = body2.rotation.conjugate() * (attachment - body2.position);
    inv_initial_orientation_ = (body2.rotation.conjugate() * body1.rotation).normalized();
  }

  std::size_t body1() const { return body1_; }
  std::size_t body2() const { return body2_; }
  void SetTargetVelocity(T velocity) { target_velocity_ = velocity; }
  void SetTargetFraction(T fraction) { target_fraction_ = fraction; }
  T fraction() const { return fraction_; }

  void SetupVelocityConstraint(const Body<T>& body1, const Body<T>& body2, T dt) {
    CalculateConstraintProperties(body1, body2, dt);
  }

  void WarmStartVelocityConstraint(Body<T>& body1, Body<T>& body2, T warm_start_ratio) {
    motor_.WarmStart(body1, body2, tangent_, warm_start_ratio);
    dual_axis_.WarmStart(body1, body2, normal_, binormal_, warm_start_ratio);
    limit_.WarmStart(body1, body2, tangent_, warm_start_ratio);
    if (UsesHinge()) hinge_.WarmStart(body1, body2, warm_start_ratio);
    if (UsesEuler()) rotation_.WarmStart(body1, body2, warm_start_ratio);
  }

  bool SolveVelocityConstraint(Body<T>& body1, Body<T>& body2, T dt) {
    bool motor = false;
    if (motor_.IsActive()) {
      const bool friction = motor_state_ == MotorState::kOff;
      const T min_lambda = friction ? -dt * max_friction_force_ : dt * min_motor_force_;
      const T max_lambda = friction ? dt * max_friction_force_ : dt * max_motor_force_;
      motor = motor_.SolveVelocityConstraint(body1, body2, tangent_, min_lambda, max_lambda);
    }
    const bool sideways = dual_axis_.SolveVelocityConstraint(body1, body2, normal_, binormal_);
    bool limit = false;
    if (limit_.IsActive()) {
      constexpr T kMax = std::numeric_limits<T>::max();
      limit = fraction_ <= T(0)
                  ? limit_.SolveVelocityConstraint(body1, body2, tangent_, T(0), kMax)
                  : limit_.SolveVelocityConstraint(body1, body2, tangent_, -kMax, T(0));
    }
    bool rotation = false;
    if (UsesHinge()) rotation = hinge_.SolveVelocityConstraint(body1, body2);
    if (UsesEuler()) rotation = rotation_.SolveVelocityConstraint(body1, body2);
    return motor | sideways | limit | rotation;
  }

  bool SolvePositionConstraint(Body<T>& body1, Body<T>& body2, T dt, T baumgarte) {
    CalculateConstraintProperties(body1, body2, dt);
    const bool sideways =
        dual_axis_.SolvePositionConstraint(body1, body2, u_, normal_, binormal_, baumgarte);
    bool limit = false;
    if (limit_.IsActive()) {
      limit = limit_.SolvePositionConstraint(body1, body2, tangent_, u_.dot(tangent_), baumgarte);
    }
    bool rotation = false;
    if (UsesHinge()) rotation = hinge_.SolvePositionConstraint(body1, body2, baumgarte);
    if (UsesEuler()) {
      rotation = rotation_.SolvePositionConstraint(body1, body2, inv_initial_orientation_,
                                                   baumgarte);
    }
    return sideways | limit | rotation;
  }

  // Solver state (reference/solver_state.h), in the batch's order
  // (docs/stepping.md, "Solver state of one world").
  void SaveSolverState(SolverStateWriter<T>& out) const {
    out(motor_.SaveState());
    out(dual_axis_.SaveState());
    out(limit_.SaveState());
    out(hinge_.SaveState());
    out(rotation_.SaveState());
  }
  void RestoreSolverState(SolverStateReader<T>& in) {
    motor_.RestoreState(in.Scalar());
    dual_axis_.RestoreState(in.Vector2());
    limit_.RestoreState(in.Scalar());
    hinge_.RestoreState(in.Vector2());
    rotation_.RestoreState(in.Vector3());
  }

 private:
  static Quat<T> FrameRotation(const typename HermitePath<T>::Frame& f) {
    Mat33<T> m;
    m << f.tangent, f.binormal, f.normal;
    return Quat<T>(m).normalized();
  }
  bool UsesHinge() const {
    return rotation_mode_ == PathRotation::kConstrainAroundTangent ||
           rotation_mode_ == PathRotation::kConstrainAroundNormal ||
           rotation_mode_ == PathRotation::kConstrainAroundBinormal;
  }
  bool UsesEuler() const {
    return rotation_mode_ == PathRotation::kConstrainToPath ||
           rotation_mode_ == PathRotation::kFullyConstrained;
  }

  void CalculateConstraintProperties(const Body<T>& body1, const Body<T>& body2, T dt) {
    const Quat<T> path_to_world = body1.rotation * path_rotation_;
    const Vec3<T> origin = body1.position + body1.rotation * path_position_;
    const Vec3<T> attachment = body2.position + body2.rotation * attachment_position_;
    fraction_ = path_.ClosestPoint(path_to_world.conjugate() * (attachment - origin));
    const typename HermitePath<T>::Frame frame = path_.PointOnPath(fraction_);
    const Vec3<T> path_point = origin + path_to_world * frame.position;
    const Vec3<T> r1_plus_u = attachment - body1.position;
    const Vec3<T> r2 = attachment - body2.position;
    u_ = attachment - path_point;
    normal_ = path_to_world * frame.normal;
    binormal_ = path_to_world * frame.binormal;
    tangent_ = path_to_world * frame.tangent;
    dual_axis_.CalculateConstraintProperties(body1, r1_plus_u, body2, r2, normal_, binormal_);
    if (!path_.looping() && (fraction_ <= T(0) || fraction_ >= path_.max_fraction())) {
      limit_.CalculateConstraintProperties(body1, r1_plus_u, body2, r2, tangent_);
    } else {
      limit_.Deactivate();
    }
    const Quat<T> attachment_frame = body2.rotation * attachment_rotation_;
    switch (rotation_mode_) {
      case PathRotation::kFree: break;
      case PathRotation::kConstrainAroundTangent:
        hinge_.CalculateConstraintProperties(body1, tangent_, body2,
                                             attachment_frame * Vec3<T>::UnitX());
        break;
      case PathRotation::kConstrainAroundNormal:
        hinge_.CalculateConstraintProperties(body1, normal_, body2,
                                             attachment_frame * Vec3<T>::UnitZ());
        break;
      case PathRotation::kConstrainAroundBinormal:
        hinge_.CalculateConstraintProperties(body1, binormal_, body2,
                                             attachment_frame * Vec3<T>::UnitY());
        break;
      case PathRotation::kConstrainToPath:
        inv_initial_orientation_ =
            attachment_rotation_ * (path_rotation_ * FrameRotation(frame)).conjugate();
        rotation_.CalculateConstraintProperties(body1, body2);
        break;
      case PathRotation::kFullyConstrained:
        rotation_.CalculateConstraintProperties(body1, body2);
        break;
    }
    CalculateMotorProperties(body1, r1_plus_u, body2, r2, dt);
  }

  void CalculateMotorProperties(const Body<T>& body1, const Vec3<T>& r1_plus_u,
                                const Body<T>& body2, const Vec3<T>& r2, T dt) {
    T error = fraction_ - target_fraction_;
    if (path_.looping()) {
      const T length = path_.max_fraction(), half = T(0.5) * length;
      error = std::fmod(error, length);
      if (error > half) {
        error -= length;
      } else if (error < -half) {
        error += length;
      }
    }
    switch (motor_state_) {
      case MotorState::kOff:
        if (max_friction_force_ > T(0)) {
          motor_.CalculateConstraintProperties(body1, r1_plus_u, body2, r2, tangent_);
        } else {
          motor_.Deactivate();
        }
        break;
      case MotorState::kVelocity:
        motor_.CalculateConstraintProperties(body1, r1_plus_u, body2, r2, tangent_,
                                             -target_velocity_);
        break;
      case MotorState::kPosition:
        if (motor_spring_.HasStiffness()) {
          motor_.CalculateConstraintPropertiesWithSettingsForMotor(
              dt, body1, r1_plus_u, body2, r2, tangent_, T(0), error, motor_spring_);
        } else {
          motor_.Deactivate();
        }
        break;
      case MotorState::kPositionAndVelocity:
        if (motor_spring_.HasStiffnessOrDamping()) {
          motor_.CalculateConstraintPropertiesWithSettingsForMotor(
              dt, body1, r1_plus_u, body2, r2, tangent_, -target_velocity_, error,
              motor_spring_);
        } else {
          motor_.Deactivate();
        }
        break;
    }
  }

  std::size_t body1_, body2_;
  HermitePath<T> path_;
  PathRotation rotation_mode_;
  Quat<T> path_rotation_ = Quat<T>::Identity();
  Vec3<T> path_position_ = Vec3<T>::Zero();
  Quat<T> attachment_rotation_ = Quat<T>::Identity();
  Vec3<T> attachment_position_ = Vec3<T>::Zero();
  Quat<T> inv_initial_orientation_ = Quat<T>::Identity();

  MotorState motor_state_;
  SpringSettings<T> motor_spring_;
  T min_motor_force_, max_motor_force_, max_friction_force_;
  T target_velocity_, target_fraction_;

  // This step's geometry.
  T fraction_ = T(0);
  Vec3<T> u_ = Vec3<T>::Zero();
  Vec3<T> tangent_ = Vec3<T>::UnitX(), normal_ = Vec3<T>::UnitZ(), binormal_ = Vec3<T>::UnitY();

  AxisPart<T> motor_, limit_;
  DualAxisPart<T> dual_axis_;
  HingeRotationPart<T> hinge_;
  RotationEulerPart<T> rotation_;
};

}  // namespace manyworlds::reference
