// Fixed constraint of the reference world: welds body 2 to body 1, all six
// degrees of freedom (spec 3, Fixed). RotationEulerPart then PointPart.
//
//   rotation:  C = 2·xyz(EnsureWPositive(q2·r0⁻¹·q1*))     (3 angular rows)
//   point:     C = (x2 + R2·p2_local) − (x1 + R1·p1_local)   (3 linear rows)
//
// r0⁻¹ (q2 = q1·r0 at rest) comes from the X/Y frames of the settings (spec 2.6).
// With auto_detect_point (world space) the anchor is the inverse-mass-weighted
// average of the two COMs (world_setup.h).
//
// Setup:    both parts from the current rotations.
// Velocity: rotation first, then point (warm start and every iteration).
// Position: recompute the rotation part, step it towards r0; then recompute the
//           point part (the rotation step changed the lever arms) and step it.
#pragma once

#include <cstddef>

#include "manyworlds/scene.h"
#include "reference/body.h"
#include "reference/math.h"
#include "reference/point_part.h"
#include "reference/rotation_euler_part.h"
#include "reference/solver_state.h"
#include "reference/world_setup.h"

namespace manyworlds::reference {

template <class T>
class FixedConstraint {
 public:
  FixedConstraint(const FixedConstraintSettings& settings, const Body<T>& body1,
                  const Body<T>& body2)
      : body1_(settings.body1), body2_(settings.body2) {
    const ConstraintBodies<T> bodies{body1, body2, settings.space};
    const LocalAnchors<T> anchors = FixedOrSliderAnchors(bodies, settings.auto_detect_point,
                                                         settings.point1, settings.point2);
    local_point1_ = anchors.point1;
    local_point2_ = anchors.point2;
    inv_initial_orientation_ = bodies.BodySpaceInvInitialOrientation(
        InvInitialOrientationXY(ToVec3<T>(settings.axis_x1), ToVec3<T>(settings.axis_y1),
                                ToVec3<T>(settings.axis_x2), ToVec3<T>(settings.axis_y2)));
  }

  std::size_t body1() const { return body1_; }
  std::size_t body2() const { return body2_; }

  void SetupVelocityConstraint(const Body<T>& body1, const Body<T>& body2, T /*dt*/) {
    rotation_.CalculateConstraintProperties(body1, body2);
    point_.CalculateConstraintProperties(body1, local_point1_, body2, local_point2_);
  }

  void WarmStartVelocityConstraint(Body<T>& body1, Body<T>& body2, T warm_start_ratio) {
    rotation_.WarmStart(body1, body2, warm_start_ratio);
    point_.WarmStart(body1, body2, warm_start_ratio);
  }

  // Both parts solve every iteration; `|` (not `||`) so neither is skipped.
  bool SolveVelocityConstraint(Body<T>& body1, Body<T>& body2, T /*dt*/) {
    const bool rotation = rotation_.SolveVelocityConstraint(body1, body2);
    const bool point = point_.SolveVelocityConstraint(body1, body2);
    return rotation | point;
  }

  bool SolvePositionConstraint(Body<T>& body1, Body<T>& body2, T /*dt*/, T baumgarte) {
    rotation_.CalculateConstraintProperties(body1, body2);
    const bool rotation =
        rotation_.SolvePositionConstraint(body1, body2, inv_initial_orientation_, baumgarte);
    point_.CalculateConstraintProperties(body1, local_point1_, body2, local_point2_);
    const bool point = point_.SolvePositionConstraint(body1, body2, baumgarte);
    return rotation | point;
  }

  const Quat<T>& inv_initial_orientation() const { return inv_initial_orientation_; }
  const Vec3<T>& local_point1() const { return local_point1_; }
  const Vec3<T>& local_point2() const { return local_point2_; }

  // The point part's accumulated impulse (the exact solve's point group).
  Vec3<T> PointImpulse() const { return point_.SaveState(); }
  // Solver state (reference/solver_state.h), in the batch's order
  // (docs/stepping.md, "Solver state of one world").
  void SaveSolverState(SolverStateWriter<T>& out) const {
    out(rotation_.SaveState());
    out(point_.SaveState());
  }
  void RestoreSolverState(SolverStateReader<T>& in) {
    rotation_.RestoreState(in.Vector3());
    point_.RestoreState(in.Vector3());
  }

 private:
  std::size_t body1_, body2_;
  Vec3<T> local_point1_ = Vec3<T>::Zero();
  Vec3<T> local_point2_ = Vec3<T>::Zero();
  Quat<T> inv_initial_orientation_ = Quat<T>::Identity();  // r0⁻¹, body space
  RotationEulerPart<T> rotation_;
  PointPart<T> point_;
};

}  // namespace manyworlds::reference
