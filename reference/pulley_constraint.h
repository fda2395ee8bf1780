// Pulley constraint of the reference world (spec 3, Pulley): a rope from body
// 1's attachment p1 over the fixed world point f1, then f2, to body 2's
// attachment p2, with length L = |p1 − f1| + r·|p2 − f2| kept in [min, max].
// One IndependentAxisPart (spec 2.11).
//
//   p_i = x_i + R_i·r_i_local,  r_i = p_i − x_i,
//   n_i = (p_i − f_i)/|p_i − f_i|, the previous n_i when the length is 0
//         (initially −Y; saved state).
//
// Setup: the part from (r1, n1, r2, n2, r); active with
//   min = max:  λ ∈ (−∞, ∞);   L ≤ min:  λ ∈ [0, ∞);   L ≥ max:  λ ∈ (−∞, 0];
//   else Deactivate.
// Position: C = L − min if L < min, L − max if L > max, else 0 (current poses);
// if C ≠ 0: recompute the properties at the current poses, one Baumgarte step.
// Negative min or max take the initial length.
#pragma once

#include <cstddef>
#include <limits>

#include "manyworlds/scene.h"
#include "reference/body.h"
#include "reference/independent_axis_part.h"
#include "reference/math.h"
#include "reference/solver_state.h"
#include "reference/world_setup.h"

namespace manyworlds::reference {

template <class T>
class PulleyConstraint {
 public:
  PulleyConstraint(const PulleyConstraintSettings& settings, const Body<T>& body1,
                   const Body<T>& body2)
      : body1_(settings.body1), body2_(settings.body2), ratio_(T(settings.ratio)) {
    const ConstraintBodies<T> bodies{body1, body2, settings.space};
    local_point1_ = bodies.LocalPoint1(settings.body_point1);
    local_point2_ = bodies.LocalPoint2(settings.body_point2);
    fixed_point1_ = ToVec3<T>(settings.fixed_point1);
    fixed_point2_ = ToVec3<T>(settings.fixed_point2);
    const T initial = CurrentLength(body1, body2);
    min_ = settings.min_length < 0.0f ? initial : T(settings.min_length);
    max_ = settings.max_length < 0.0f ? initial : T(settings.max_length);
  }

  std::size_t body1() const { return body1_; }
  std::size_t body2() const { return body2_; }
  T min_length() const { return min_; }
  T max_length() const { return max_; }

  T CurrentLength(const Body<T>& body1, const Body<T>& body2) const {
    return (Attachment(body1, local_point1_) - fixed_point1_).norm() +
           ratio_ * (Attachment(body2, local_point2_) - fixed_point2_).norm();
  }

  void SetupVelocityConstraint(const Body<T>& body1, const Body<T>& body2, T /*dt*/) {
    CalculateConstraintProperties(body1, body2);
  }

  void WarmStartVelocityConstraint(Body<T>& body1, Body<T>& body2, T warm_start_ratio) {
    part_.WarmStart(body1, body2, n1_, n2_, ratio_, warm_start_ratio);
  }

  bool SolveVelocityConstraint(Body<T>& body1, Body<T>& body2, T /*dt*/) {
    return part_.SolveVelocityConstraint(body1, body2, n1_, n2_, ratio_, min_lambda_,
                                         max_lambda_);
  }

  bool SolvePositionConstraint(Body<T>& body1, Body<T>& body2, T /*dt*/, T baumgarte) {
    const T length = CurrentLength(body1, body2);
    T error = T(0);
    if (length < min_) {
      error = length - min_;
    } else if (length > max_) {
      error = length - max_;
    }
    if (error == T(0)) return false;
    CalculateConstraintProperties(body1, body2);
    return part_.SolvePositionConstraint(body1, body2, n1_, n2_, ratio_, error, baumgarte);
  }

  const IndependentAxisPart<T>& part() const { return part_; }

  // Solver state (reference/solver_state.h), in the batch's order
  // (docs/stepping.md, "Solver state of one world").
  void SaveSolverState(SolverStateWriter<T>& out) const {
    out(part_.SaveState());
    out(n1_);
    out(n2_);
  }
  void RestoreSolverState(SolverStateReader<T>& in) {
    part_.RestoreState(in.Scalar());
    n1_ = in.Vector3();
    n2_ = in.Vector3();
  }

 private:
  static Vec3<T> Attachment(const Body<T>& body, const Vec3<T>& local) {
    return body.position + body.rotation * local;
  }

  void CalculateConstraintProperties(const Body<T>& body1, const Body<T>& body2) {
    const Vec3<T> r1 = body1.rotation * local_point1_;
    const Vec3<T> r2 = body2.rotation * local_point2_;
    const Vec3<T> segment1 = body1.position + r1 - fixed_point1_;
    const Vec3<T> segment2 = body2.position + r2 - fixed_point2_;
    const T length1 = segment1.norm(), length2 = segment2.norm();
    if (length1 > T(0)) n1_ = segment1 / length1;
    if (length2 > T(0)) n2_ = segment2 / length2;
    const T length = length1 + ratio_ * length2;
    constexpr T kInfinity = std::numeric_limits<T>::max();
    if (min_ == max_) {
      min_lambda_ = -kInfinity;
      max_lambda_ = kInfinity;
    } else if (length <= min_) {
      min_lambda_ = T(0);
      max_lambda_ = kInfinity;
    } else if (length >= max_) {
      min_lambda_ = -kInfinity;
      max_lambda_ = T(0);
    } else {
      part_.Deactivate();
      return;
    }
    part_.CalculateConstraintProperties(body1, r1, n1_, body2, r2, n2_, ratio_);
  }

  std::size_t body1_, body2_;
  T ratio_;
  Vec3<T> local_point1_ = Vec3<T>::Zero(), local_point2_ = Vec3<T>::Zero();
  Vec3<T> fixed_point1_ = Vec3<T>::Zero(), fixed_point2_ = Vec3<T>::Zero();
  T min_ = T(0), max_ = T(0);
  Vec3<T> n1_ = -Vec3<T>::UnitY(), n2_ = -Vec3<T>::UnitY();  // saved state (spec 4.4)
  T min_lambda_ = T(0), max_lambda_ = T(0);
  IndependentAxisPart<T> part_;
};

}  // namespace manyworlds::reference
