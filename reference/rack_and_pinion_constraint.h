// Rack-and-pinion constraint of the reference world: couples the rotation θ of a
// pinion (body 1) about its hinge axis to the translation d of a rack (body 2)
// along its slider axis, θ − r·d = 0 (spec 3, RackAndPinion; r in rad/m, e.g.
// 2π·teeth_rack / (length·teeth_pinion)). One RackAndPinionPart (spec 2.9).
//
// Geometry: the pinion's hinge axis in body 1 space and the rack's slider axis in
// body 2 space, fixed at creation.
// Setup:    a = R1·h, b = R2·s, part properties.
// Velocity: warm start, one part iteration per velocity iteration.
// Position: only when the pinion's hinge and the rack's slider are both given.
//           θ = the hinge's current unwrapped angle if the pinion is the hinge's
//           body 2, else minus it; d = the slider's current position if the rack
//           is the slider's body 2, else minus it. Then
//
//             C = θ − r·d
//
//           (Jolt folds CenterAngleAroundZero(fmod(θ − r·d, 2π)) of the wrapped
//           angle: the same unless the rack slipped by whole turns, which the
//           fold would hide), properties recomputed from the current rotations,
//           one Baumgarte step.
//           The world measures θ and d (it owns the helpers) and passes them in.
#pragma once

#include <cstddef>

#include "manyworlds/scene.h"
#include "reference/body.h"
#include "reference/math.h"
#include "reference/rack_and_pinion_part.h"
#include "reference/solver_state.h"
#include "reference/world_setup.h"

namespace manyworlds::reference {

template <class T>
class RackAndPinionConstraint {
 public:
  RackAndPinionConstraint(const RackAndPinionConstraintSettings& settings,
                          const Body<T>& body1, const Body<T>& body2)
      : body1_(settings.body1),
        body2_(settings.body2),
        hinge_(settings.hinge),
        slider_(settings.slider),
        ratio_(T(settings.ratio)) {
    const ConstraintBodies<T> bodies{body1, body2, settings.space};
    local_hinge_axis1_ = bodies.LocalAxis1(settings.hinge_axis1);
    local_slider_axis2_ = bodies.LocalAxis2(settings.slider_axis2);
  }

  std::size_t body1() const { return body1_; }
  std::size_t body2() const { return body2_; }
  std::size_t hinge() const { return hinge_; }    // kNoConstraint if not given
  std::size_t slider() const { return slider_; }  // kNoConstraint if not given
  bool HasPositionCorrection() const {
    return hinge_ != kNoConstraint && slider_ != kNoConstraint;
  }
  T ratio() const { return ratio_; }
  const Vec3<T>& local_hinge_axis1() const { return local_hinge_axis1_; }
  const Vec3<T>& local_slider_axis2() const { return local_slider_axis2_; }

  void SetupVelocityConstraint(const Body<T>& body1, const Body<T>& body2, T /*dt*/) {
    CalculateProperties(body1, body2);
  }

  void WarmStartVelocityConstraint(Body<T>& body1, Body<T>& body2, T warm_start_ratio) {
    part_.WarmStart(body1, body2, warm_start_ratio);
  }

  bool SolveVelocityConstraint(Body<T>& body1, Body<T>& body2, T /*dt*/) {
    return part_.SolveVelocityConstraint(body1, body2, a_, b_, ratio_);
  }

  // θ: the pinion's rotation, d: the rack's translation, as measured by the helpers.
  bool SolvePositionConstraint(Body<T>& body1, Body<T>& body2, T rotation, T translation,
                               T baumgarte) {
    const T error = PositionError(rotation, translation);
    if (error == T(0)) return false;
    CalculateProperties(body1, body2);
    return part_.SolvePositionConstraint(body1, body2, error, baumgarte);
  }

  // C = θ − r·d of the unwrapped angle.
  T PositionError(T rotation, T translation) const { return rotation - ratio_ * translation; }

  const RackAndPinionPart<T>& rack_and_pinion_part() const { return part_; }

  // Solver state (reference/solver_state.h), in the batch's order
  // (docs/stepping.md, "Solver state of one world").
  void SaveSolverState(SolverStateWriter<T>& out) const {
    out(part_.SaveState());
  }
  void RestoreSolverState(SolverStateReader<T>& in) {
    part_.RestoreState(in.Scalar());
  }

 private:
  void CalculateProperties(const Body<T>& body1, const Body<T>& body2) {
    a_ = body1.rotation * local_hinge_axis1_;
    b_ = body2.rotation * local_slider_axis2_;
    part_.CalculateConstraintProperties(body1, a_, body2, b_, ratio_);
  }

  std::size_t body1_, body2_;
  std::size_t hinge_, slider_;
  T ratio_;
  Vec3<T> local_hinge_axis1_ = Vec3<T>::UnitX();
  Vec3<T> local_slider_axis2_ = Vec3<T>::UnitX();
  Vec3<T> a_ = Vec3<T>::Zero();  // world hinge axis of the pinion
  Vec3<T> b_ = Vec3<T>::Zero();  // world slider axis of the rack
  RackAndPinionPart<T> part_;
};

}  // namespace manyworlds::reference
