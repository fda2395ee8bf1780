// Swing-twist constraint of the reference world (spec 3, SwingTwist), the
// ragdoll joint: rotation drives (reference/rotation_drive.h: twist motor about
// X, swing motors about Y and Z, or friction), a SwingTwistPart (spec 2.12) on
// the rotation of body 2's constraint frame relative to body 1's, then a
// PointPart (2.4).
//
// Constraint frame per body: X = twist axis, Y = plane × twist, Z = plane
// axis; c_i = that frame as a rotation into body i's space (local settings,
// or world settings moved into body space at creation). Part limits: twist
// [twist_min, twist_max], swing Y ±plane_half_cone, swing Z ±normal_half_cone,
// cone or pyramid.
//
// Setup:    Point; q = (q1·c1)*·(q2·c2); SwingTwistPart(q, q1·c1); drives.
// Velocity: twist drive, swing drives, swing Y, swing Z, twist limits (active
//           rows), then point.
// Position: SwingTwistPart (one rotation-Euler step towards the clamped
//           orientation where violated), then the point part recomputed and
//           stepped. Drives take no position steps.
#pragma once

#include <cstddef>

#include "manyworlds/scene.h"
#include "reference/body.h"
#include "reference/math.h"
#include "reference/point_part.h"
#include "reference/rotation_drive.h"
#include "reference/solver_state.h"
#include "reference/swing_twist_part.h"
#include "reference/world_setup.h"

namespace manyworlds::reference {

template <class T>
class SwingTwistConstraint {
 public:
  SwingTwistConstraint(const SwingTwistConstraintSettings& settings, const Body<T>& body1,
                       const Body<T>& body2)
      : body1_(settings.body1),
        body2_(settings.body2),
        drive_({MakeRotationDriveAxis<T>(settings.twist_motor_state, settings.twist_motor,
                                         settings.max_friction_torque),
                MakeRotationDriveAxis<T>(settings.swing_motor_state, settings.swing_motor,
                                         settings.max_friction_torque),
                MakeRotationDriveAxis<T>(settings.swing_motor_state, settings.swing_motor,
                                         settings.max_friction_torque)},
               /*project=*/false) {
    const ConstraintBodies<T> bodies{body1, body2, settings.space};
    local_point1_ = bodies.LocalPoint1(settings.point1);
    local_point2_ = bodies.LocalPoint2(settings.point2);
    constraint_to_body1_ = Frame(bodies.LocalAxis1(settings.twist_axis1),
                                 bodies.LocalAxis1(settings.plane_axis1));
    constraint_to_body2_ = Frame(bodies.LocalAxis2(settings.twist_axis2),
                                 bodies.LocalAxis2(settings.plane_axis2));
    part_.SetSwingType(settings.swing_type == manyworlds::SwingType::kCone
                           ? SwingType::kCone
                           : SwingType::kPyramid);
    part_.SetLimits(T(settings.twist_min_angle), T(settings.twist_max_angle),
                    -T(settings.plane_half_cone_angle), T(settings.plane_half_cone_angle),
                    -T(settings.normal_half_cone_angle), T(settings.normal_half_cone_angle));
    drive_.SetTargetAngularVelocity(ToVec3<T>(settings.target_angular_velocity));
    SetTargetOrientation(ToQuat<T>(settings.target_orientation).normalized());
  }

  // Body 2's frame in body 1's; clamped into the limits.
  void SetTargetOrientation(const Quat<T>& target) { drive_.SetTargetOrientation(target, part_); }
  void SetTargetAngularVelocity(const Vec3<T>& w) { drive_.SetTargetAngularVelocity(w); }

  std::size_t body1() const { return body1_; }
  std::size_t body2() const { return body2_; }

  void SetupVelocityConstraint(const Body<T>& body1, const Body<T>& body2, T dt) {
    point_.CalculateConstraintProperties(body1, local_point1_, body2, local_point2_);
    SetupInequalityRows(body1, body2, dt);
  }

  void WarmStartVelocityConstraint(Body<T>& body1, Body<T>& body2, T warm_start_ratio) {
    WarmStartInequalityRows(body1, body2, warm_start_ratio);
    point_.WarmStart(body1, body2, warm_start_ratio);
  }

  bool SolveVelocityConstraint(Body<T>& body1, Body<T>& body2, T dt) {
    const bool bounded = SolveInequalityVelocity(body1, body2, dt);
    return point_.SolveVelocityConstraint(body1, body2) || bounded;
  }

  bool SolvePositionConstraint(Body<T>& body1, Body<T>& body2, T dt, T baumgarte) {
    const bool limits = SolveLimitPosition(body1, body2, dt, baumgarte);
    point_.CalculateConstraintProperties(body1, local_point1_, body2, local_point2_);
    return point_.SolvePositionConstraint(body1, body2, baumgarte) || limits;
  }

  // The exact solve's view (reference/world.h): the anchors (body space),
  // and the limits and drives it leaves to Gauss-Seidel.
  const Vec3<T>& local_point1() const { return local_point1_; }
  const Vec3<T>& local_point2() const { return local_point2_; }
  void SetupInequalityRows(const Body<T>& body1, const Body<T>& body2, T dt) {
    const Quat<T> q = Rotation(body1, body2);
    part_.CalculateConstraintProperties(body1, body2, q,
                                        Quat<T>(body1.rotation * constraint_to_body1_));
    if (drive_.InUse()) {
      drive_.CalculateConstraintProperties(body1, body2, q,
                                           Quat<T>(body2.rotation * constraint_to_body2_), dt);
    }
  }

  void WarmStartInequalityRows(Body<T>& body1, Body<T>& body2, T warm_start_ratio) {
    if (drive_.InUse()) drive_.WarmStart(body1, body2, warm_start_ratio);
    part_.WarmStart(body1, body2, warm_start_ratio);
  }
  bool SolveInequalityVelocity(Body<T>& body1, Body<T>& body2, T dt) {
    const bool drives = drive_.InUse() && drive_.SolveVelocityConstraint(body1, body2, dt);
    const bool limits = part_.SolveVelocityConstraint(body1, body2);
    return limits || drives;
  }
  bool SolveLimitPosition(Body<T>& body1, Body<T>& body2, T /*dt*/, T baumgarte) {
    return part_.SolvePositionConstraint(body1, body2, Rotation(body1, body2),
                                         constraint_to_body1_, constraint_to_body2_, baumgarte);
  }

  // The point part's accumulated impulse (the exact solve's point group).
  Vec3<T> PointImpulse() const { return point_.SaveState(); }
  // Solver state (reference/solver_state.h), in the batch's order
  // (docs/stepping.md, "Solver state of one world").
  void SaveSolverState(SolverStateWriter<T>& out) const {
    drive_.SaveSolverState(out);
    out(part_.SaveState());
    out(point_.SaveState());
  }
  void RestoreSolverState(SolverStateReader<T>& in) {
    drive_.RestoreSolverState(in);
    part_.RestoreState(in.Vector3());
    point_.RestoreState(in.Vector3());
  }

 private:
  // The frame (X = twist, Y = plane × twist, Z = plane) as a rotation.
  static Quat<T> Frame(const Vec3<T>& twist, const Vec3<T>& plane) {
    Mat33<T> frame;
    frame << twist, plane.cross(twist), plane;
    return Quat<T>(frame).normalized();
  }
  Quat<T> Rotation(const Body<T>& body1, const Body<T>& body2) const {
    return SwingTwistConstraintRotation(body1, constraint_to_body1_, body2,
                                        constraint_to_body2_);
  }

  std::size_t body1_, body2_;
  Vec3<T> local_point1_ = Vec3<T>::Zero(), local_point2_ = Vec3<T>::Zero();
  Quat<T> constraint_to_body1_ = Quat<T>::Identity();
  Quat<T> constraint_to_body2_ = Quat<T>::Identity();
  SwingTwistPart<T> part_;
  PointPart<T> point_;
  RotationDrive<T> drive_;
};

}  // namespace manyworlds::reference
