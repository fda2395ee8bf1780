// Cone constraint of the reference world (spec 3, Cone): a ball joint whose
// twist axes may part by at most the half cone angle α. PointPart (spec 2.4),
// then one AnglePart (spec 2.8) as a one-sided limit.
//
//   t1 = R1·t1_local, t2 = R2·t2_local, cos θ = t1·t2.
//   cos θ < cos α:  a = (t2 × t1)/|t2 × t1| (the previous a when the cross
//                   product is zero; initially a perpendicular of body 1's
//                   local twist axis; saved state), AnglePart on a,
//                   λ ∈ [0, ∞) (turns body 2 about a, t2 towards t1);
//   else:           Deactivate.
//
// Velocity: point, then the angle row (only where active).
// Position: recompute the point part, step it; recompute the cone row at the
// new rotations (may deactivate), step it with C = cos θ − cos α.
#pragma once

#include <cmath>
#include <cstddef>
#include <limits>

#include "manyworlds/scene.h"
#include "reference/angle_part.h"
#include "reference/body.h"
#include "reference/math.h"
#include "reference/point_part.h"
#include "reference/solver_state.h"
#include "reference/world_setup.h"

namespace manyworlds::reference {

template <class T>
class ConeConstraint {
 public:
  ConeConstraint(const ConeConstraintSettings& settings, const Body<T>& body1,
                 const Body<T>& body2)
      : body1_(settings.body1), body2_(settings.body2) {
    const ConstraintBodies<T> bodies{body1, body2, settings.space};
    local_point1_ = bodies.LocalPoint1(settings.point1);
    local_point2_ = bodies.LocalPoint2(settings.point2);
    local_twist1_ = bodies.LocalAxis1(settings.twist_axis1);
    local_twist2_ = bodies.LocalAxis2(settings.twist_axis2);
    cos_half_cone_ = std::cos(T(settings.half_cone_angle));
    rotation_axis_ = NormalizedPerpendicular(local_twist1_);
  }

  std::size_t body1() const { return body1_; }
  std::size_t body2() const { return body2_; }

  void SetupVelocityConstraint(const Body<T>& body1, const Body<T>& body2, T /*dt*/) {
    point_.CalculateConstraintProperties(body1, local_point1_, body2, local_point2_);
    CalculateRotationProperties(body1, body2);
  }

  void WarmStartVelocityConstraint(Body<T>& body1, Body<T>& body2, T warm_start_ratio) {
    point_.WarmStart(body1, body2, warm_start_ratio);
    angle_.WarmStart(body1, body2, warm_start_ratio);
  }

  bool SolveVelocityConstraint(Body<T>& body1, Body<T>& body2, T /*dt*/) {
    const bool point = point_.SolveVelocityConstraint(body1, body2);
    bool rotation = false;
    if (angle_.IsActive()) {
      rotation = angle_.SolveVelocityConstraint(body1, body2, rotation_axis_, T(0),
                                                std::numeric_limits<T>::max());
    }
    return point || rotation;
  }

  bool SolvePositionConstraint(Body<T>& body1, Body<T>& body2, T /*dt*/, T baumgarte) {
    point_.CalculateConstraintProperties(body1, local_point1_, body2, local_point2_);
    const bool point = point_.SolvePositionConstraint(body1, body2, baumgarte);
    CalculateRotationProperties(body1, body2);
    bool rotation = false;
    if (angle_.IsActive()) {
      rotation = angle_.SolvePositionConstraint(body1, body2, cos_theta_ - cos_half_cone_,
                                                baumgarte);
    }
    return point || rotation;
  }

  const Vec3<T>& rotation_axis() const { return rotation_axis_; }

  // The exact solve's view (reference/world.h): the anchors (body space) of
  // its point group, and the cone row it leaves to Gauss-Seidel.
  const Vec3<T>& local_point1() const { return local_point1_; }
  const Vec3<T>& local_point2() const { return local_point2_; }
  void SetupInequalityRows(const Body<T>& body1, const Body<T>& body2, T /*dt*/) {
    CalculateRotationProperties(body1, body2);
  }
  void WarmStartInequalityRows(Body<T>& body1, Body<T>& body2, T warm_start_ratio) {
    angle_.WarmStart(body1, body2, warm_start_ratio);
  }
  bool SolveInequalityVelocity(Body<T>& body1, Body<T>& body2, T /*dt*/) {
    return angle_.IsActive() && angle_.SolveVelocityConstraint(body1, body2, rotation_axis_, T(0),
                                                               std::numeric_limits<T>::max());
  }
  bool SolveLimitPosition(Body<T>& body1, Body<T>& body2, T /*dt*/, T baumgarte) {
    CalculateRotationProperties(body1, body2);
    return angle_.IsActive() &&
           angle_.SolvePositionConstraint(body1, body2, cos_theta_ - cos_half_cone_, baumgarte);
  }
  // The point part's accumulated impulse (the exact solve's point group).
  Vec3<T> PointImpulse() const { return point_.SaveState(); }

  // Solver state (reference/solver_state.h), in the batch's order
  // (docs/stepping.md, "Solver state of one world").
  void SaveSolverState(SolverStateWriter<T>& out) const {
    out(point_.SaveState());
    out(angle_.SaveState());
    out(rotation_axis_);
  }
  void RestoreSolverState(SolverStateReader<T>& in) {
    point_.RestoreState(in.Vector3());
    angle_.RestoreState(in.Scalar());
    rotation_axis_ = in.Vector3();
  }

 private:
  void CalculateRotationProperties(const Body<T>& body1, const Body<T>& body2) {
    const Vec3<T> twist1 = body1.rotation * local_twist1_;
    const Vec3<T> twist2 = body2.rotation * local_twist2_;
    cos_theta_ = twist1.dot(twist2);
    if (cos_theta_ < cos_half_cone_) {
      const Vec3<T> axis = twist2.cross(twist1);
      const T length = axis.norm();
      if (length > T(0)) rotation_axis_ = axis / length;
      angle_.CalculateConstraintProperties(body1, body2, rotation_axis_);
    } else {
      angle_.Deactivate();
    }
  }

  std::size_t body1_, body2_;
  Vec3<T> local_point1_ = Vec3<T>::Zero(), local_point2_ = Vec3<T>::Zero();
  Vec3<T> local_twist1_ = Vec3<T>::UnitX(), local_twist2_ = Vec3<T>::UnitX();
  T cos_half_cone_ = T(1);
  T cos_theta_ = T(1);
  Vec3<T> rotation_axis_ = Vec3<T>::UnitY();  // saved state (spec 4.4)
  PointPart<T> point_;
  AnglePart<T> angle_;
};

}  // namespace manyworlds::reference
