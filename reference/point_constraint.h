// Point constraint (ball joint) of the reference world: body 1's anchor and body
// 2's anchor coincide (spec 3, Point). One PointPart (spec 2.4).
//
//   C = (x2 + R2·p2_local) − (x1 + R1·p1_local)          (3 linear rows)
//
// Setup:    PointPart properties from the current rotations.
// Velocity: warm start, then one PointPart iteration per velocity iteration.
// Position: recompute the PointPart from the current rotations (the bodies moved
//           since setup), one Baumgarte step on the current separation.
#pragma once

#include <cstddef>

#include "manyworlds/scene.h"
#include "reference/body.h"
#include "reference/math.h"
#include "reference/point_part.h"
#include "reference/solver_state.h"
#include "reference/world_setup.h"

namespace manyworlds::reference {

template <class T>
class PointConstraint {
 public:
  PointConstraint(const PointConstraintSettings& settings, const Body<T>& body1,
                  const Body<T>& body2)
      : body1_(settings.body1), body2_(settings.body2) {
    const ConstraintBodies<T> bodies{body1, body2, settings.space};
    local_point1_ = bodies.LocalPoint1(settings.point1);
    local_point2_ = bodies.LocalPoint2(settings.point2);
  }

  std::size_t body1() const { return body1_; }
  std::size_t body2() const { return body2_; }

  void SetupVelocityConstraint(const Body<T>& body1, const Body<T>& body2, T /*dt*/) {
    point_.CalculateConstraintProperties(body1, local_point1_, body2, local_point2_);
  }

  void WarmStartVelocityConstraint(Body<T>& body1, Body<T>& body2, T warm_start_ratio) {
    point_.WarmStart(body1, body2, warm_start_ratio);
  }

  bool SolveVelocityConstraint(Body<T>& body1, Body<T>& body2, T /*dt*/) {
    return point_.SolveVelocityConstraint(body1, body2);
  }

  bool SolvePositionConstraint(Body<T>& body1, Body<T>& body2, T /*dt*/, T baumgarte) {
    point_.CalculateConstraintProperties(body1, local_point1_, body2, local_point2_);
    return point_.SolvePositionConstraint(body1, body2, baumgarte);
  }

  const PointPart<T>& point_part() const { return point_; }
  // The anchors in each body's COM space (the exact solve reads them).
  const Vec3<T>& local_point1() const { return local_point1_; }
  const Vec3<T>& local_point2() const { return local_point2_; }

  // The point part's accumulated impulse (the exact solve's point group).
  Vec3<T> PointImpulse() const { return point_.SaveState(); }
  // Solver state (reference/solver_state.h), in the batch's order
  // (docs/stepping.md, "Solver state of one world").
  void SaveSolverState(SolverStateWriter<T>& out) const {
    out(point_.SaveState());
  }
  void RestoreSolverState(SolverStateReader<T>& in) {
    point_.RestoreState(in.Vector3());
  }

 private:
  std::size_t body1_, body2_;
  Vec3<T> local_point1_ = Vec3<T>::Zero();  // anchor, body 1 COM space
  Vec3<T> local_point2_ = Vec3<T>::Zero();  // anchor, body 2 COM space
  PointPart<T> point_;
};

}  // namespace manyworlds::reference
