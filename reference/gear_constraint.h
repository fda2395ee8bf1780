// Gear constraint of the reference world: couples the rotation of body 1 about its
// hinge axis to that of body 2 about its own, θ1 + r·θ2 = 0 (spec 3, Gear; gears
// turn in opposite directions; r = teeth2 / teeth1). One GearPart (spec 2.10),
// which in this project applies Jᵀλ exactly (body 2's impulse carries r; Jolt
// omits it, see reference/gear_part.h and docs/constraint-parts.md).
//
// Geometry: the hinge axes in body-COM space, fixed at creation.
// Setup:    a = R1·h1, b = R2·h2, GearPart properties.
// Velocity: warm start, one GearPart iteration per velocity iteration.
// Position: only when both hinge constraints are given (the only way to measure
//           θ1, θ2). θ_i is the rotation of gear i as its hinge measures it: the
//           hinge's current unwrapped angle (turns counted at every setup) if the
//           gear is the hinge's body 2, minus it if the gear is the hinge's body 1
//           (the hinge angle is body 2 relative to body 1). Then
//
//             C = θ1 + r·θ2,
//
//           properties recomputed from the current rotations, one Baumgarte step.
//           The world computes θ1, θ2 (it owns the hinges) and passes them in.
//           Jolt folds C = CenterAngleAroundZero(fmod(θ1 + r·θ2, 2π)) of wrapped
//           angles, which with a non-integer r jumps by 2π·r once gear 2 turns
//           past ±π (docs/constraint-parts.md, "Unwrapped angles").
#pragma once

#include <cstddef>

#include "manyworlds/scene.h"
#include "reference/body.h"
#include "reference/gear_part.h"
#include "reference/math.h"
#include "reference/solver_state.h"
#include "reference/world_setup.h"

namespace manyworlds::reference {

template <class T>
class GearConstraint {
 public:
  GearConstraint(const GearConstraintSettings& settings, const Body<T>& body1,
                 const Body<T>& body2)
      : body1_(settings.body1),
        body2_(settings.body2),
        hinge1_(settings.hinge1),
        hinge2_(settings.hinge2),
        ratio_(T(settings.ratio)) {
    const ConstraintBodies<T> bodies{body1, body2, settings.space};
    local_hinge_axis1_ = bodies.LocalAxis1(settings.hinge_axis1);
    local_hinge_axis2_ = bodies.LocalAxis2(settings.hinge_axis2);
  }

  std::size_t body1() const { return body1_; }
  std::size_t body2() const { return body2_; }
  std::size_t hinge1() const { return hinge1_; }  // kNoConstraint if not given
  std::size_t hinge2() const { return hinge2_; }
  bool HasPositionCorrection() const {
    return hinge1_ != kNoConstraint && hinge2_ != kNoConstraint;
  }
  T ratio() const { return ratio_; }
  const Vec3<T>& local_hinge_axis1() const { return local_hinge_axis1_; }
  const Vec3<T>& local_hinge_axis2() const { return local_hinge_axis2_; }

  void SetupVelocityConstraint(const Body<T>& body1, const Body<T>& body2, T /*dt*/) {
    CalculateProperties(body1, body2);
  }

  void WarmStartVelocityConstraint(Body<T>& body1, Body<T>& body2, T warm_start_ratio) {
    gear_.WarmStart(body1, body2, warm_start_ratio);
  }

  bool SolveVelocityConstraint(Body<T>& body1, Body<T>& body2, T /*dt*/) {
    return gear_.SolveVelocityConstraint(body1, body2, a_, b_, ratio_);
  }

  // θ1, θ2: each gear's rotation as its hinge measures it (see the header).
  bool SolvePositionConstraint(Body<T>& body1, Body<T>& body2, T rotation1, T rotation2,
                               T baumgarte) {
    const T error = PositionError(rotation1, rotation2);
    if (error == T(0)) return false;
    CalculateProperties(body1, body2);
    return gear_.SolvePositionConstraint(body1, body2, error, baumgarte);
  }

  // C = θ1 + r·θ2 of the unwrapped angles (Jolt folds wrapped ones:
  // docs/constraint-parts.md, "Unwrapped angles").
  T PositionError(T rotation1, T rotation2) const { return rotation1 + ratio_ * rotation2; }

  const GearPart<T>& gear_part() const { return gear_; }

  // Solver state (reference/solver_state.h), in the batch's order
  // (docs/stepping.md, "Solver state of one world").
  void SaveSolverState(SolverStateWriter<T>& out) const {
    out(gear_.SaveState());
  }
  void RestoreSolverState(SolverStateReader<T>& in) {
    gear_.RestoreState(in.Scalar());
  }

 private:
  void CalculateProperties(const Body<T>& body1, const Body<T>& body2) {
    a_ = body1.rotation * local_hinge_axis1_;
    b_ = body2.rotation * local_hinge_axis2_;
    gear_.CalculateConstraintProperties(body1, a_, body2, b_, ratio_);
  }

  std::size_t body1_, body2_;
  std::size_t hinge1_, hinge2_;
  T ratio_;
  Vec3<T> local_hinge_axis1_ = Vec3<T>::UnitX();
  Vec3<T> local_hinge_axis2_ = Vec3<T>::UnitX();
  Vec3<T> a_ = Vec3<T>::Zero();  // world hinge axes
  Vec3<T> b_ = Vec3<T>::Zero();
  GearPart<T> gear_;
};

}  // namespace manyworlds::reference
