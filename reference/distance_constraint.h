// Distance constraint of the reference world (spec 3, Distance): body 1's
// anchor p1 and body 2's anchor p2 stay between min and max apart. One AxisPart
// (spec 2.2) along the anchor line, used as a limit: a rod (min = max), a rope
// (min = 0), or with a limits spring a spring.
//
//   p_i = x_i + R_i·r_i_local,  L = |p2 − p1|,
//   n = (p2 − p1)/L, the previous n when L = 0 (initially +Y; saved state),
//   lever arms r1 + u = p2 − x1, r2 = p2 − x2.
//
// Setup (CalculateConstraintProperties, which also stores p1, p2):
//   min = max:  C = L − min, λ ∈ (−∞, ∞)
//   L ≤ min:    C = L − min, λ ∈ [0, ∞)
//   L ≥ max:    C = L − max, λ ∈ (−∞, 0]
//   else:       Deactivate (m_eff = 0, Λ = 0).
// The axis part is a limit (soft iff the limits spring has stiffness).
//
// Position (hard limits only; Jolt's quirk): d = (p2_stored − p1_stored)·n_stored
// from the last CalculateConstraintProperties (before integration on the first
// iteration); error d − min if d < min, d − max if d > max, else nothing happens.
// With an error: recompute everything at the current poses (may deactivate),
// then one Baumgarte step with that error along the new n.
//
// Bounds given as negative take the initial distance L0: both, L0 for both;
// min only, min(L0, max); max only, max(L0, min).
#pragma once

#include <algorithm>
#include <cstddef>
#include <limits>

#include "manyworlds/scene.h"
#include "reference/axis_part.h"
#include "reference/body.h"
#include "reference/math.h"
#include "reference/solver_state.h"
#include "reference/world_setup.h"

namespace manyworlds::reference {

template <class T>
class DistanceConstraint {
 public:
  DistanceConstraint(const DistanceConstraintSettings& settings, const Body<T>& body1,
                     const Body<T>& body2)
      : body1_(settings.body1), body2_(settings.body2) {
    const ConstraintBodies<T> bodies{body1, body2, settings.space};
    local_point1_ = bodies.LocalPoint1(settings.point1);
    local_point2_ = bodies.LocalPoint2(settings.point2);
    const T initial = (WorldPoint(body2, local_point2_) - WorldPoint(body1, local_point1_)).norm();
    min_ = T(settings.min_distance);
    max_ = T(settings.max_distance);
    if (min_ < T(0) && max_ < T(0)) {
      min_ = max_ = initial;
    } else if (min_ < T(0)) {
      min_ = std::min(initial, max_);
    } else if (max_ < T(0)) {
      max_ = std::max(initial, min_);
    }
    limits_spring_ = ToReferenceSpring<T>(settings.limits_spring);
    hard_limits_ = settings.limits_spring.frequency_or_stiffness <= 0.0f;
    rigid_ = settings.rigid();
  }

  std::size_t body1() const { return body1_; }
  std::size_t body2() const { return body2_; }
  T min_distance() const { return min_; }
  T max_distance() const { return max_; }

  void SetupVelocityConstraint(const Body<T>& body1, const Body<T>& body2, T dt) {
    CalculateConstraintProperties(body1, body2, dt);
  }

  void WarmStartVelocityConstraint(Body<T>& body1, Body<T>& body2, T warm_start_ratio) {
    axis_.WarmStart(body1, body2, normal_, warm_start_ratio);
  }

  bool SolveVelocityConstraint(Body<T>& body1, Body<T>& body2, T /*dt*/) {
    return axis_.SolveVelocityConstraint(body1, body2, normal_, min_lambda_, max_lambda_);
  }

  bool SolvePositionConstraint(Body<T>& body1, Body<T>& body2, T dt, T baumgarte) {
    if (!hard_limits_) return false;
    const T distance = (world_point2_ - world_point1_).dot(normal_);
    T error = T(0);
    if (distance < min_) {
      error = distance - min_;
    } else if (distance > max_) {
      error = distance - max_;
    }
    if (error == T(0)) return false;
    CalculateConstraintProperties(body1, body2, dt);
    return axis_.SolvePositionConstraint(body1, body2, normal_, error, baumgarte);
  }

  const AxisPart<T>& axis_part() const { return axis_; }
  const Vec3<T>& normal() const { return normal_; }

  // The exact solve's view (reference/world.h): a rod whose row it factors
  // (chosen by the world as the batch's plan does, ChooseRodGroups), its
  // anchors (body space).
  bool rigid() const { return rigid_; }
  bool exact_group() const { return exact_group_; }
  void set_exact_group(bool group) { exact_group_ = group; }
  const Vec3<T>& local_point1() const { return local_point1_; }
  const Vec3<T>& local_point2() const { return local_point2_; }

  // Solver state (reference/solver_state.h), in the batch's order
  // (docs/stepping.md, "Solver state of one world").
  void SaveSolverState(SolverStateWriter<T>& out) const {
    out(axis_.SaveState());
    out(normal_);
  }
  void RestoreSolverState(SolverStateReader<T>& in) {
    axis_.RestoreState(in.Scalar());
    normal_ = in.Vector3();
  }

 private:
  static Vec3<T> WorldPoint(const Body<T>& body, const Vec3<T>& local) {
    return body.position + body.rotation * local;
  }

  void CalculateConstraintProperties(const Body<T>& body1, const Body<T>& body2, T dt) {
    world_point1_ = WorldPoint(body1, local_point1_);
    world_point2_ = WorldPoint(body2, local_point2_);
    const Vec3<T> delta = world_point2_ - world_point1_;
    const T length = delta.norm();
    if (length > T(0)) normal_ = delta / length;
    const Vec3<T> r1_plus_u = world_point2_ - body1.position;
    const Vec3<T> r2 = world_point2_ - body2.position;
    constexpr T kInfinity = std::numeric_limits<T>::max();
    T error;
    if (min_ == max_) {
      error = length - min_;
      min_lambda_ = -kInfinity;
      max_lambda_ = kInfinity;
    } else if (length <= min_) {
      error = length - min_;
      min_lambda_ = T(0);
      max_lambda_ = kInfinity;
    } else if (length >= max_) {
      error = length - max_;
      min_lambda_ = -kInfinity;
      max_lambda_ = T(0);
    } else {
      axis_.Deactivate();
      return;
    }
    axis_.CalculateConstraintPropertiesWithSettingsForLimit(dt, body1, r1_plus_u, body2, r2,
                                                            normal_, T(0), error,
                                                            limits_spring_);
  }

  std::size_t body1_, body2_;
  Vec3<T> local_point1_ = Vec3<T>::Zero();
  Vec3<T> local_point2_ = Vec3<T>::Zero();
  T min_ = T(0), max_ = T(0);
  SpringSettings<T> limits_spring_;
  bool hard_limits_ = true;
  bool rigid_ = false, exact_group_ = false;
  Vec3<T> normal_ = Vec3<T>::UnitY();  // saved state (spec 4.4)
  Vec3<T> world_point1_ = Vec3<T>::Zero(), world_point2_ = Vec3<T>::Zero();
  T min_lambda_ = T(0), max_lambda_ = T(0);
  AxisPart<T> axis_;
};

}  // namespace manyworlds::reference
