// Rotation drives of the reference world's swing-twist and six-DOF
// constraints (spec 3): one AnglePart (spec 2.8) per axis of body 2's
// constraint frame (X = twist, Y and Z = swing), each a motor or friction row.
//
//   axes a_i = columns of R(q2·c2)
//   q = (q1·c1)*·(q2·c2)                 body 2's frame relative to body 1's
//   target' = target if q·target > 0, else −target   (shortest way round)
//   diff = q*·target'                    rotation still to go, body 2's frame
//   diff projected onto the position-driven axes (six-DOF; swing-twist keeps
//   all three): GetTwist about the axis for one; diff·GetTwist(third axis)*
//   for two; diff for three
//   C_i = −2·diff.xyz_i                  small-angle error (the sign is right
//                                        for large errors, which is enough)
//
// Row i, J = [0, −a_i, 0, a_i]:
//   Off + max friction > 0: hard, bias 0, impulse dt·[−f, f];
//   Velocity: hard, bias −ω_target_i, dt·[min τ, max τ];
//   Position: motor spring (needs stiffness) on C_i;
//   PositionAndVelocity: motor spring (stiffness or damping), bias −ω_target_i, C_i.
//   Otherwise off (Deactivate). Drives take no position steps.
//
// The target orientation is clamped into the constraint's swing-twist limits
// when set (Jolt's SetTargetOrientationCS): swing·twist if a limit was hit,
// else the target as given.
#pragma once

#include <array>
#include <cstddef>

#include "manyworlds/spring_settings.h"
#include "reference/angle_part.h"
#include "reference/body.h"
#include "reference/math.h"
#include "reference/solver_state.h"
#include "reference/spring_part.h"
#include "reference/swing_twist_part.h"
#include "reference/world_setup.h"

namespace manyworlds::reference {

// One axis' drive settings.
template <class T>
struct RotationDriveAxis {
  MotorState state = MotorState::kOff;
  SpringSettings<T> spring;
  T min_torque = T(0), max_torque = T(0);  // N m; the impulse range is dt times these
  T max_friction = T(0);                   // N m

  bool InUse() const { return state != MotorState::kOff || max_friction > T(0); }
  bool UsesPositionError() const {
    return state == MotorState::kPosition || state == MotorState::kPositionAndVelocity;
  }
};

template <class T>
inline RotationDriveAxis<T> MakeRotationDriveAxis(MotorState state,
                                                  const manyworlds::MotorSettings& motor,
                                                  float max_friction) {
  return {state, ToReferenceSpring<T>(motor.spring), T(motor.min_force_limit),
          T(motor.max_force_limit), T(max_friction)};
}

template <class T>
class RotationDrive {
 public:
  // `project` is six-DOF's projection of the error onto the position-driven
  // axes; swing-twist uses the whole error.
  RotationDrive(const std::array<RotationDriveAxis<T>, 3>& axes, bool project)
      : axes_(axes) {
    position_axes_ = 0;
    for (int i = 0; i < 3; ++i) {
      if (axes_[i].UsesPositionError()) position_axes_ |= 1u << i;
    }
    if (!project) position_axes_ = 0b111;
  }

  bool InUse() const { return axes_[0].InUse() || axes_[1].InUse() || axes_[2].InUse(); }

  void SetTargetAngularVelocity(const Vec3<T>& w) { target_angular_velocity_ = w; }
  // Clamped into the part's limits as Jolt's SetTargetOrientationCS does.
  void SetTargetOrientation(const Quat<T>& target, const SwingTwistPart<T>& limits) {
    const SwingTwist<T> split = DecomposeSwingTwist(target);
    Quat<T> swing = split.swing, twist = split.twist;
    target_orientation_ = limits.ClampSwingTwist(swing, twist) != 0 ? Quat<T>(swing * twist)
                                                                   : target;
  }

  // q = (q1 c1)* (q2 c2); frame2 = q2 c2.
  void CalculateConstraintProperties(const Body<T>& body1, const Body<T>& body2,
                                     const Quat<T>& q, const Quat<T>& frame2, T dt) {
    const Mat33<T> axes = frame2.toRotationMatrix();
    Vec3<T> error = Vec3<T>::Zero();
    if (axes_[0].UsesPositionError() || axes_[1].UsesPositionError() ||
        axes_[2].UsesPositionError()) {
      const Quat<T> target = q.coeffs().dot(target_orientation_.coeffs()) > T(0)
                                 ? target_orientation_
                                 : Quat<T>(-target_orientation_.coeffs());
      error = T(-2) * Project(q.conjugate() * target).vec();
    }
    for (int i = 0; i < 3; ++i) {
      axis_[i] = axes.col(i);
      const RotationDriveAxis<T>& a = axes_[i];
      AnglePart<T>& part = part_[i];
      switch (a.state) {
        case MotorState::kOff:
          if (a.max_friction > T(0)) {
            part.CalculateConstraintProperties(body1, body2, axis_[i]);
          } else {
            part.Deactivate();
          }
          break;
        case MotorState::kVelocity:
          part.CalculateConstraintProperties(body1, body2, axis_[i],
                                             -target_angular_velocity_[i]);
          break;
        case MotorState::kPosition:
          if (a.spring.HasStiffness()) {
            part.CalculateConstraintPropertiesWithSettingsForMotor(dt, body1, body2, axis_[i],
                                                                   T(0), error[i], a.spring);
          } else {
            part.Deactivate();
          }
          break;
        case MotorState::kPositionAndVelocity:
          if (a.spring.HasStiffnessOrDamping()) {
            part.CalculateConstraintPropertiesWithSettingsForMotor(
                dt, body1, body2, axis_[i], -target_angular_velocity_[i], error[i], a.spring);
          } else {
            part.Deactivate();
          }
          break;
      }
    }
  }

  void WarmStart(Body<T>& body1, Body<T>& body2, T warm_start_ratio) {
    for (AnglePart<T>& part : part_) part.WarmStart(body1, body2, warm_start_ratio);
  }

  bool SolveVelocityConstraint(Body<T>& body1, Body<T>& body2, T dt) {
    bool applied = false;
    for (int i = 0; i < 3; ++i) {
      if (!part_[i].IsActive()) continue;
      const RotationDriveAxis<T>& a = axes_[i];
      const bool friction = a.state == MotorState::kOff;
      const T min_lambda = friction ? -dt * a.max_friction : dt * a.min_torque;
      const T max_lambda = friction ? dt * a.max_friction : dt * a.max_torque;
      applied |= part_[i].SolveVelocityConstraint(body1, body2, axis_[i], min_lambda, max_lambda);
    }
    return applied;
  }

  const AnglePart<T>& part(int i) const { return part_[i]; }

  // The three rows' impulses, X (twist) then Y and Z (reference/solver_state.h).
  void SaveSolverState(SolverStateWriter<T>& out) const {
    for (const AnglePart<T>& part : part_) out(part.SaveState());
  }
  void RestoreSolverState(SolverStateReader<T>& in) {
    for (AnglePart<T>& part : part_) part.RestoreState(in.Scalar());
  }

 private:
  Quat<T> Project(const Quat<T>& diff) const {
    const auto twist = [&](int axis) { return QuatTwist(diff, Vec3<T>(Vec3<T>::Unit(axis))); };
    switch (position_axes_) {
      case 0b001: return twist(0);
      case 0b010: return twist(1);
      case 0b100: return twist(2);
      case 0b011: return diff * twist(2).conjugate();
      case 0b101: return diff * twist(1).conjugate();
      case 0b110: return diff * twist(0).conjugate();
      default: return diff;
    }
  }

  std::array<RotationDriveAxis<T>, 3> axes_;
  unsigned position_axes_ = 0b111;  // bit i: axis i's error counts
  Vec3<T> target_angular_velocity_ = Vec3<T>::Zero();
  Quat<T> target_orientation_ = Quat<T>::Identity();
  std::array<Vec3<T>, 3> axis_{Vec3<T>::Zero(), Vec3<T>::Zero(), Vec3<T>::Zero()};
  std::array<AnglePart<T>, 3> part_;
};

}  // namespace manyworlds::reference
