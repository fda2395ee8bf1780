// Six-DOF constraint of the reference world (spec 3, SixDOF): per axis of the
// constraint frame fixed, free or limited; translation limit springs; a drive
// (motor or friction) per axis; Jolt's all-fixed shortcuts.
//
// Frames: c_i = (axis_x_i, axis_y_i, axis_x_i × axis_y_i) as a rotation into body
// i's space. Limits after Jolt's rules (SixDofLimitsOf): an axis is fixed
// when min ≥ max, free when the range covers ±FLT_MAX (translation) or ±π
// (rotation), else limited. Jolt's normalisation: a translation with min > max
// becomes 0/0; rotation limits are clamped into [−π, π] and inverted ones become
// 0/0; a cone's swing limits become ±max(0, max).
//
// Translation, axes t_i = columns of R(q1·c1), r1 = R1·p1, r2 = R2·p2,
// r1 + u = x2 + r2 − x1, u = p2 − p1, d_i = t_i·u:
//   all fixed, no springs: PointPart on the anchors (its position step on body 1's
//   anchor moved by c1·min);
//   else per non-free axis an AxisPart with that axis' limit spring: fixed always
//   on with C = d − min, impulse both ways; limited on where d ≤ min (C = d − min,
//   impulse ≥ 0) or d ≥ max (C = d − max, impulse ≤ 0);
//   drives per axis as the slider's (C = d − target, bias −v_target).
// Rotation: all fixed: RotationEulerPart (position target r0⁻¹ = c2·(c1·euler(min))*);
//   some constrained: SwingTwistPart with twist [min_x, max_x], swing Y
//   [min_y, max_y], swing Z [min_z, max_z]; drives (reference/rotation_drive.h)
//   with the orientation error projected onto the position-driven axes. The
//   drives of an all-fixed group (translation point or rotation Euler) are not
//   used, as in Jolt.
// Velocity: translation drives, rotation drives, rotation rows, translation rows.
// Position: rotation, then translation (point, or per hard axis recomputed at the
// current poses and one AxisPart step on its error when that is non-zero).
#pragma once

#include <algorithm>
#include <array>
#include <cfloat>
#include <cstddef>
#include <limits>

#include "manyworlds/scene.h"
#include "reference/axis_part.h"
#include "reference/body.h"
#include "reference/math.h"
#include "reference/point_part.h"
#include "reference/rotation_drive.h"
#include "reference/rotation_euler_part.h"
#include "reference/solver_state.h"
#include "reference/spring_part.h"
#include "reference/swing_twist_part.h"
#include "reference/world_setup.h"

namespace manyworlds::reference {

// A six-DOF constraint's limits after Jolt's normalisation (see above).
struct SixDofLimitRanges {
  std::array<double, kSixDofAxes> min, max;
  std::array<AxisLimitKind, kSixDofAxes> kind;  // kLocked = fixed
};

inline SixDofLimitRanges SixDofLimitsOf(const SixDofConstraintSettings& s) {
  SixDofLimitRanges r;
  for (std::size_t i = 0; i < kSixDofAxes; ++i) {
    r.min[i] = s.limit_min[i];
    r.max[i] = s.limit_max[i];
  }
  for (std::size_t i = 0; i < 3; ++i) {
    if (r.min[i] > r.max[i]) r.min[i] = r.max[i] = 0.0;
  }
  for (std::size_t i = 3; i < 6; ++i) {
    if (s.swing_type == manyworlds::SwingType::kCone && i >= 4) {
      r.max[i] = std::max(0.0, r.max[i]);
      r.min[i] = -r.max[i];
    }
    // Clamped in float, as the settings are floats: pi rounds to kPi.
    r.min[i] = std::clamp(float(r.min[i]), -manyworlds::kPi, manyworlds::kPi);
    r.max[i] = std::clamp(float(r.max[i]), -manyworlds::kPi, manyworlds::kPi);
    if (r.min[i] > r.max[i]) r.min[i] = r.max[i] = 0.0;
  }
  for (std::size_t i = 0; i < kSixDofAxes; ++i) {
    const double bound = i < 3 ? double(FLT_MAX) : double(manyworlds::kPi);
    r.kind[i] = r.min[i] >= r.max[i]                          ? AxisLimitKind::kLocked
                : r.min[i] <= -bound && r.max[i] >= bound ? AxisLimitKind::kFree
                                                             : AxisLimitKind::kLimited;
  }
  return r;
}

template <class T>
class SixDofConstraint {
 public:
  SixDofConstraint(const SixDofConstraintSettings& settings, const Body<T>& body1,
                   const Body<T>& body2)
      : body1_(settings.body1),
        body2_(settings.body2),
        drive_(RotationDriveAxes(settings), /*project=*/true) {
    const ConstraintBodies<T> bodies{body1, body2, settings.space};
    local_point1_ = bodies.LocalPoint1(settings.position1);
    local_point2_ = bodies.LocalPoint2(settings.position2);
    constraint_to_body1_ =
        Frame(bodies.LocalAxis1(settings.axis_x1), bodies.LocalAxis1(settings.axis_y1));
    constraint_to_body2_ =
        Frame(bodies.LocalAxis2(settings.axis_x2), bodies.LocalAxis2(settings.axis_y2));
    const SixDofLimitRanges limits = SixDofLimitsOf(settings);
    bool translation_fixed = true, translation_constrained = false, any_spring = false;
    for (int i = 0; i < 3; ++i) {
      kind_[i] = limits.kind[i];
      min_[i] = T(limits.min[i]);
      max_[i] = T(limits.max[i]);
      spring_[i] = ToReferenceSpring<T>(settings.limits_spring[i]);
      translation_fixed &= kind_[i] == AxisLimitKind::kLocked;
      translation_constrained |= kind_[i] != AxisLimitKind::kFree;
      any_spring |= spring_[i].HasStiffness();
      motor_state_[i] = settings.motor_state[i];
      motor_spring_[i] = ToReferenceSpring<T>(settings.motor[i].spring);
      min_force_[i] = T(settings.motor[i].min_force_limit);
      max_force_[i] = T(settings.motor[i].max_force_limit);
      max_friction_[i] = T(settings.max_friction[i]);
      target_velocity_[i] = T(settings.target_velocity[i]);
      target_position_[i] = T(settings.target_position[i]);
    }
    translation_point_ = translation_fixed && !any_spring;
    translation_rows_ = !translation_point_ && translation_constrained;
    bool rotation_fixed = true, rotation_constrained = false;
    for (std::size_t i = 3; i < 6; ++i) {
      const AxisLimitKind kind = limits.kind[i];
      rotation_fixed &= kind == AxisLimitKind::kLocked;
      rotation_constrained |= kind != AxisLimitKind::kFree;
    }
    rotation_euler_ = rotation_fixed;
    rotation_limits_ = !rotation_fixed && rotation_constrained;
    swing_twist_.SetSwingType(settings.swing_type == manyworlds::SwingType::kCone
                                  ? SwingType::kCone
                                  : SwingType::kPyramid);
    swing_twist_.SetLimits(T(limits.min[3]), T(limits.max[3]), T(limits.min[4]),
                           T(limits.max[4]), T(limits.min[5]), T(limits.max[5]));
    fixed_point1_ = local_point1_ + constraint_to_body1_ * Vec3<T>(min_[0], min_[1], min_[2]);
    inv_initial_orientation_ =
        (constraint_to_body2_ *
         (constraint_to_body1_ * EulerRotation(T(limits.min[3]), T(limits.min[4]),
                                               T(limits.min[5])))
             .conjugate())
            .normalized();
    drive_.SetTargetAngularVelocity(ToVec3<T>(settings.target_angular_velocity));
    SetTargetOrientation(ToQuat<T>(settings.target_orientation).normalized());
  }

  std::size_t body1() const { return body1_; }
  std::size_t body2() const { return body2_; }

  void SetTargetOrientation(const Quat<T>& target) {
    drive_.SetTargetOrientation(target, swing_twist_);
  }
  void SetTargetAngularVelocity(const Vec3<T>& w) { drive_.SetTargetAngularVelocity(w); }
  void SetTargetTranslation(const Vec3<T>& p) { target_position_ = p; }
  void SetTargetLinearVelocity(const Vec3<T>& v) { target_velocity_ = v; }

  void SetupVelocityConstraint(const Body<T>& body1, const Body<T>& body2, T dt) {
    Setup(body1, body2, dt, true);
  }
  void WarmStartVelocityConstraint(Body<T>& body1, Body<T>& body2, T warm_start_ratio) {
    WarmStart(body1, body2, warm_start_ratio, true);
  }
  bool SolveVelocityConstraint(Body<T>& body1, Body<T>& body2, T dt) {
    return SolveVelocity(body1, body2, dt, true);
  }
  bool SolvePositionConstraint(Body<T>& body1, Body<T>& body2, T /*dt*/, T baumgarte) {
    return SolvePosition(body1, body2, baumgarte, true);
  }

  // The exact solve's view (reference/world.h): its groups are the all-fixed
  // shortcuts (the point on body 1's anchor moved by c1 min, the rotation
  // towards r0^-1), and it leaves the other rows to Gauss-Seidel.
  bool translation_point() const { return translation_point_; }
  bool rotation_euler() const { return rotation_euler_; }
  bool HasExactGroups() const { return translation_point_ || rotation_euler_; }
  bool HasInequalityRows() const {
    return (!translation_point_ && (translation_rows_ || TranslationDrivesInUse())) ||
           (!rotation_euler_ && (rotation_limits_ || drive_.InUse()));
  }
  const Vec3<T>& fixed_point1() const { return fixed_point1_; }
  const Vec3<T>& local_point2() const { return local_point2_; }
  const Quat<T>& inv_initial_orientation() const { return inv_initial_orientation_; }
  void SetupInequalityRows(const Body<T>& body1, const Body<T>& body2, T dt) {
    Setup(body1, body2, dt, false);
  }
  void WarmStartInequalityRows(Body<T>& body1, Body<T>& body2, T warm_start_ratio) {
    WarmStart(body1, body2, warm_start_ratio, false);
  }
  bool SolveInequalityVelocity(Body<T>& body1, Body<T>& body2, T dt) {
    return SolveVelocity(body1, body2, dt, false);
  }
  bool SolveLimitPosition(Body<T>& body1, Body<T>& body2, T /*dt*/, T baumgarte) {
    return SolvePosition(body1, body2, baumgarte, false);
  }
  // The point part's accumulated impulse (the exact solve's point group).
  Vec3<T> PointImpulse() const { return point_.SaveState(); }

  // Solver state (reference/solver_state.h), in the batch's order
  // (docs/stepping.md, "Solver state of one world").
  void SaveSolverState(SolverStateWriter<T>& out) const {
    for (const AxisPart<T>& part : motor_) out(part.SaveState());
    drive_.SaveSolverState(out);
    out(rotation_.SaveState());
    out(swing_twist_.SaveState());
    out(point_.SaveState());
    for (const AxisPart<T>& part : limit_) out(part.SaveState());
  }
  void RestoreSolverState(SolverStateReader<T>& in) {
    for (AxisPart<T>& part : motor_) part.RestoreState(in.Scalar());
    drive_.RestoreSolverState(in);
    rotation_.RestoreState(in.Vector3());
    swing_twist_.RestoreState(in.Vector3());
    point_.RestoreState(in.Vector3());
    for (AxisPart<T>& part : limit_) part.RestoreState(in.Scalar());
  }

 private:
  // The verbs on every row (`shortcuts`, Gauss-Seidel) or on every row but
  // the all-fixed shortcuts (the exact solve's groups).
  void Setup(const Body<T>& body1, const Body<T>& body2, T dt, bool shortcuts) {
    const Quat<T> frame1 = body1.rotation * constraint_to_body1_;
    if (translation_point_) {
      if (shortcuts) {
        point_.CalculateConstraintProperties(body1, local_point1_, body2, local_point2_);
      }
    } else if (translation_rows_ || TranslationDrivesInUse()) {
      CalculateTranslationFrame(body1, body2);
      for (int i = 0; i < 3; ++i) {
        if (HasTranslationRow(i)) CalculateLimitProperties(body1, body2, i, dt);
        CalculateMotorProperties(body1, body2, i, dt);
      }
    }
    if (rotation_euler_) {
      if (shortcuts) rotation_.CalculateConstraintProperties(body1, body2);
    } else if (rotation_limits_ || drive_.InUse()) {
      const Quat<T> frame2 = body2.rotation * constraint_to_body2_;
      const Quat<T> q = frame1.conjugate() * frame2;
      if (rotation_limits_) swing_twist_.CalculateConstraintProperties(body1, body2, q, frame1);
      if (drive_.InUse()) drive_.CalculateConstraintProperties(body1, body2, q, frame2, dt);
    }
  }

  void WarmStart(Body<T>& body1, Body<T>& body2, T warm_start_ratio, bool shortcuts) {
    if (!translation_point_) {
      for (int i = 0; i < 3; ++i) motor_[i].WarmStart(body1, body2, axis_[i], warm_start_ratio);
    }
    if (!rotation_euler_) drive_.WarmStart(body1, body2, warm_start_ratio);
    if (rotation_euler_ && shortcuts) rotation_.WarmStart(body1, body2, warm_start_ratio);
    if (rotation_limits_) swing_twist_.WarmStart(body1, body2, warm_start_ratio);
    if (translation_point_ && shortcuts) point_.WarmStart(body1, body2, warm_start_ratio);
    for (int i = 0; i < 3; ++i) {
      if (HasTranslationRow(i)) limit_[i].WarmStart(body1, body2, axis_[i], warm_start_ratio);
    }
  }

  bool SolveVelocity(Body<T>& body1, Body<T>& body2, T dt, bool shortcuts) {
    bool applied = false;
    for (int i = 0; i < 3 && !translation_point_; ++i) {
      if (!motor_[i].IsActive()) continue;
      const bool friction = motor_state_[i] == MotorState::kOff;
      const T min_lambda = friction ? -dt * max_friction_[i] : dt * min_force_[i];
      const T max_lambda = friction ? dt * max_friction_[i] : dt * max_force_[i];
      applied |= motor_[i].SolveVelocityConstraint(body1, body2, axis_[i], min_lambda, max_lambda);
    }
    if (!rotation_euler_ && drive_.InUse()) {
      applied |= drive_.SolveVelocityConstraint(body1, body2, dt);
    }
    if (rotation_euler_ && shortcuts) applied |= rotation_.SolveVelocityConstraint(body1, body2);
    if (rotation_limits_) applied |= swing_twist_.SolveVelocityConstraint(body1, body2);
    if (translation_point_ && shortcuts) applied |= point_.SolveVelocityConstraint(body1, body2);
    for (int i = 0; i < 3; ++i) {
      if (!HasTranslationRow(i) || !limit_[i].IsActive()) continue;
      constexpr T kMax = std::numeric_limits<T>::max();
      T min_lambda = -kMax, max_lambda = kMax;
      if (kind_[i] == AxisLimitKind::kLimited && min_[i] != max_[i]) {
        if (displacement_[i] <= min_[i]) {
          min_lambda = T(0);
        } else {
          max_lambda = T(0);
        }
      }
      applied |= limit_[i].SolveVelocityConstraint(body1, body2, axis_[i], min_lambda, max_lambda);
    }
    return applied;
  }

  bool SolvePosition(Body<T>& body1, Body<T>& body2, T baumgarte, bool shortcuts) {
    bool applied = false;
    if (rotation_euler_) {
      if (shortcuts) {
        rotation_.CalculateConstraintProperties(body1, body2);
        applied |= rotation_.SolvePositionConstraint(body1, body2, inv_initial_orientation_,
                                                     baumgarte);
      }
    } else if (rotation_limits_) {
      const Quat<T> q = (body1.rotation * constraint_to_body1_).conjugate() *
                        (body2.rotation * constraint_to_body2_);
      applied |= swing_twist_.SolvePositionConstraint(body1, body2, q, constraint_to_body1_,
                                                      constraint_to_body2_, baumgarte);
    }
    if (translation_point_ && shortcuts) {
      point_.CalculateConstraintProperties(body1, fixed_point1_, body2, local_point2_);
      applied |= point_.SolvePositionConstraint(body1, body2, baumgarte);
    }
    for (int i = 0; i < 3; ++i) {
      if (!HasTranslationRow(i) || spring_[i].HasStiffness()) continue;
      CalculateTranslationFrame(body1, body2);
      const T d = displacement_[i];
      T error = T(0);
      if (kind_[i] == AxisLimitKind::kLocked) {
        error = d - min_[i];
      } else if (d <= min_[i]) {
        error = d - min_[i];
      } else if (d >= max_[i]) {
        error = d - max_[i];
      }
      if (error == T(0)) continue;
      limit_[i].CalculateConstraintProperties(body1, r1_plus_u_, body2, r2_, axis_[i]);
      applied |= limit_[i].SolvePositionConstraint(body1, body2, axis_[i], error, baumgarte);
    }
    return applied;
  }

  static std::array<RotationDriveAxis<T>, 3> RotationDriveAxes(
      const SixDofConstraintSettings& s) {
    // An all-fixed rotation uses the rotation-Euler part and no drives.
    const SixDofLimitRanges limits = SixDofLimitsOf(s);
    bool fixed = true;
    for (std::size_t i = 3; i < 6; ++i) fixed &= limits.kind[i] == AxisLimitKind::kLocked;
    std::array<RotationDriveAxis<T>, 3> axes;
    for (int i = 0; i < 3 && !fixed; ++i) {
      axes[i] = MakeRotationDriveAxis<T>(s.motor_state[3 + i], s.motor[3 + i],
                                         s.max_friction[3 + i]);
    }
    return axes;
  }
  static Quat<T> Frame(const Vec3<T>& x, const Vec3<T>& y) {
    Mat33<T> frame;
    frame << x, y, x.cross(y);
    return Quat<T>(frame).normalized();
  }
  // Jolt's Quat::sEulerAngles: q = Rz·Ry·Rx.
  static Quat<T> EulerRotation(T x, T y, T z) {
    return Quat<T>(Eigen::AngleAxis<T>(z, Vec3<T>::UnitZ()) *
                   Eigen::AngleAxis<T>(y, Vec3<T>::UnitY()) *
                   Eigen::AngleAxis<T>(x, Vec3<T>::UnitX()));
  }

  bool HasTranslationRow(int i) const {
    return translation_rows_ && kind_[i] != AxisLimitKind::kFree;
  }
  bool TranslationDrivesInUse() const {
    for (int i = 0; i < 3; ++i) {
      if (motor_state_[i] != MotorState::kOff || max_friction_[i] > T(0)) return true;
    }
    return false;
  }

  void CalculateTranslationFrame(const Body<T>& body1, const Body<T>& body2) {
    const Vec3<T> r1 = body1.rotation * local_point1_;
    r2_ = body2.rotation * local_point2_;
    r1_plus_u_ = body2.position + r2_ - body1.position;
    const Vec3<T> u = r1_plus_u_ - r1;
    const Mat33<T> axes = (body1.rotation * constraint_to_body1_).toRotationMatrix();
    for (int i = 0; i < 3; ++i) {
      axis_[i] = axes.col(i);
      displacement_[i] = axis_[i].dot(u);
    }
  }

  void CalculateLimitProperties(const Body<T>& body1, const Body<T>& body2, int i, T dt) {
    const T d = displacement_[i];
    const bool fixed = kind_[i] == AxisLimitKind::kLocked;
    if (!fixed && d > min_[i] && d < max_[i]) return limit_[i].Deactivate();
    const T error = fixed || d <= min_[i] ? d - min_[i] : d - max_[i];
    limit_[i].CalculateConstraintPropertiesWithSettingsForLimit(dt, body1, r1_plus_u_, body2, r2_,
                                                                axis_[i], T(0), error,
                                                                spring_[i]);
  }

  void CalculateMotorProperties(const Body<T>& body1, const Body<T>& body2, int i, T dt) {
    AxisPart<T>& motor = motor_[i];
    const T error = displacement_[i] - target_position_[i];
    switch (motor_state_[i]) {
      case MotorState::kOff:
        if (max_friction_[i] > T(0)) {
          motor.CalculateConstraintProperties(body1, r1_plus_u_, body2, r2_, axis_[i]);
        } else {
          motor.Deactivate();
        }
        break;
      case MotorState::kVelocity:
        motor.CalculateConstraintProperties(body1, r1_plus_u_, body2, r2_, axis_[i],
                                            -target_velocity_[i]);
        break;
      case MotorState::kPosition:
        if (motor_spring_[i].HasStiffness()) {
          motor.CalculateConstraintPropertiesWithSettingsForMotor(
              dt, body1, r1_plus_u_, body2, r2_, axis_[i], T(0), error, motor_spring_[i]);
        } else {
          motor.Deactivate();
        }
        break;
      case MotorState::kPositionAndVelocity:
        if (motor_spring_[i].HasStiffnessOrDamping()) {
          motor.CalculateConstraintPropertiesWithSettingsForMotor(
              dt, body1, r1_plus_u_, body2, r2_, axis_[i], -target_velocity_[i], error,
              motor_spring_[i]);
        } else {
          motor.Deactivate();
        }
        break;
    }
  }

  std::size_t body1_, body2_;
  Vec3<T> local_point1_ = Vec3<T>::Zero(), local_point2_ = Vec3<T>::Zero();
  Vec3<T> fixed_point1_ = Vec3<T>::Zero();
  Quat<T> constraint_to_body1_ = Quat<T>::Identity();
  Quat<T> constraint_to_body2_ = Quat<T>::Identity();
  Quat<T> inv_initial_orientation_ = Quat<T>::Identity();

  // Translation.
  std::array<AxisLimitKind, 3> kind_{};
  Vec3<T> min_ = Vec3<T>::Zero(), max_ = Vec3<T>::Zero();
  std::array<SpringSettings<T>, 3> spring_{};
  bool translation_point_ = false, translation_rows_ = false;
  std::array<MotorState, 3> motor_state_{};
  std::array<SpringSettings<T>, 3> motor_spring_{};
  Vec3<T> min_force_ = Vec3<T>::Zero(), max_force_ = Vec3<T>::Zero();
  Vec3<T> max_friction_ = Vec3<T>::Zero();
  Vec3<T> target_velocity_ = Vec3<T>::Zero(), target_position_ = Vec3<T>::Zero();
  Vec3<T> r1_plus_u_ = Vec3<T>::Zero(), r2_ = Vec3<T>::Zero();
  std::array<Vec3<T>, 3> axis_{Vec3<T>::Zero(), Vec3<T>::Zero(), Vec3<T>::Zero()};
  Vec3<T> displacement_ = Vec3<T>::Zero();
  PointPart<T> point_;
  std::array<AxisPart<T>, 3> limit_, motor_;

  // Rotation.
  bool rotation_euler_ = false, rotation_limits_ = false;
  RotationEulerPart<T> rotation_;
  SwingTwistPart<T> swing_twist_;
  RotationDrive<T> drive_;
};

}  // namespace manyworlds::reference
