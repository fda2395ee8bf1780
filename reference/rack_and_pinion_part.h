// RackAndPinionPart: couples the rotation of a pinion (body 1) about the world hinge
// axis a to the translation of a rack (body 2) along the world slider axis b with
// ratio r (spec 2.9). Scalar reference, written from the formulas.
//
// Constraint (θ1 = rotation of body 1 about a, d2 = translation of body 2 along b):
//
//   C = θ1(t) − r·d2(t)
//
// Jacobian (body 1 enters positively, unlike the Axis/DualAxis parts, spec 1.1):
//
//   J = [ 0, aᵀ, −r·bᵀ, 0 ]                              (v1, w1, v2, w2)
//
// Inverse effective mass, using b·b = 1:
//
//   K = J M⁻¹ Jᵀ = a·I1⁻¹a + r²·m2⁻¹,   m_eff = 1/K;  K == 0 ⇒ Deactivate.
//
// Unlike most parts the mass terms are ALWAYS used, whatever the motion type
// (spec 1.5): a kinematic body contributes its stored inverse mass / inertia. Static
// bodies are invalid here (Jolt reads their missing motion properties); the scene
// layer refuses them and the reference asserts.
//
// Velocity step: Δλ = −m_eff J·v = m_eff (r·b·v2 − a·w1); Λ += Δλ; v += M⁻¹Jᵀ Δλ:
//   w1 += Δλ I1⁻¹a,   v2 −= Δλ r m2⁻¹ b,
// applied WITHOUT motion-type checks (spec 1.5: kinematic bodies are written too).
// Warm starting goes through the same application.
//
// Position step (spec 1.2): λ = −m_eff β C; body 1 rotates by +λ I1⁻¹a, body 2
// translates by −λ r m2⁻¹ b, dynamic bodies only; skipped when C == 0 exactly. The
// caller supplies C (the constraint wraps it with CenterAngleAroundZero(fmod(·, 2π)),
// spec 3) and recomputes the properties first.
#pragma once

#include <cassert>

#include "reference/body.h"
#include "reference/math.h"

namespace manyworlds::reference {

template <class T>
class RackAndPinionPart {
 public:
  // Inertia of body 1 in vector form from its current rotation (spec 1.4).
  void CalculateConstraintProperties(const Body<T>& body1, const Vec3<T>& hinge_axis,
                                     const Body<T>& body2, const Vec3<T>& slider_axis,
                                     T ratio) {
    assert(!body1.IsStatic() && !body2.IsStatic());
    inv_i1_hinge_axis_ = body1.MultiplyInverseInertia(hinge_axis);
    ratio_inv_m2_slider_axis_ = (ratio * body2.inv_mass) * slider_axis;
    const T k = hinge_axis.dot(inv_i1_hinge_axis_) + ratio * ratio * body2.inv_mass;
    if (k == T(0)) {
      Deactivate();
    } else {
      effective_mass_ = T(1) / k;
    }
  }

  // Scales the impulse of the previous step by dt/dt_prev and applies it.
  void WarmStart(Body<T>& body1, Body<T>& body2, T warm_start_ratio) {
    total_lambda_ *= warm_start_ratio;
    ApplyVelocityStep(body1, body2, total_lambda_);
  }

  // One Gauss–Seidel iteration; true iff an impulse was applied (spec 1.1).
  bool SolveVelocityConstraint(Body<T>& body1, Body<T>& body2, const Vec3<T>& hinge_axis,
                               const Vec3<T>& slider_axis, T ratio) {
    assert(!body1.IsStatic() && !body2.IsStatic());
    const T delta_lambda =
        effective_mass_ * (ratio * slider_axis.dot(body2.linear_velocity) -
                           hinge_axis.dot(body1.angular_velocity));
    total_lambda_ += delta_lambda;
    return ApplyVelocityStep(body1, body2, delta_lambda);
  }

  // Baumgarte step on the caller's C; true iff C != 0 (then a step was taken).
  bool SolvePositionConstraint(Body<T>& body1, Body<T>& body2, T error_c, T baumgarte) const {
    if (error_c == T(0)) return false;
    const T lambda = -effective_mass_ * baumgarte * error_c;
    if (body1.IsDynamic()) body1.AddRotationStep(lambda * inv_i1_hinge_axis_);
    if (body2.IsDynamic()) body2.SubPositionStep(lambda * ratio_inv_m2_slider_axis_);
    return true;
  }

  // Wipes the warm-start impulse too: that is Jolt's behaviour (spec 1.3).
  void Deactivate() {
    effective_mass_ = T(0);
    total_lambda_ = T(0);
  }
  bool IsActive() const { return effective_mass_ != T(0); }

  T GetTotalLambda() const { return total_lambda_; }
  void SetTotalLambda(T lambda) { total_lambda_ = lambda; }
  T SaveState() const { return total_lambda_; }  // Λ is all that persists (spec 4.4)
  void RestoreState(T lambda) { total_lambda_ = lambda; }

  // Read-only views of the cached properties, for tests.
  T EffectiveMass() const { return effective_mass_; }  // 1/K
  const Vec3<T>& InvI1HingeAxis() const { return inv_i1_hinge_axis_; }
  const Vec3<T>& RatioInvM2SliderAxis() const { return ratio_inv_m2_slider_axis_; }

 private:
  // v += M⁻¹ Jᵀ λ with no motion-type check (spec 1.5); true iff λ != 0.
  bool ApplyVelocityStep(Body<T>& body1, Body<T>& body2, T lambda) const {
    body1.angular_velocity += lambda * inv_i1_hinge_axis_;
    body2.SubLinearVelocityStep(lambda * ratio_inv_m2_slider_axis_);
    return lambda != T(0);
  }

  Vec3<T> inv_i1_hinge_axis_ = Vec3<T>::Zero();         // I1⁻¹ a
  Vec3<T> ratio_inv_m2_slider_axis_ = Vec3<T>::Zero();  // r m2⁻¹ b
  T effective_mass_ = T(0);                             // m_eff = 1/K
  T total_lambda_ = T(0);                               // Λ
};

// J·v = dC/dt = a·w1 − r·b·v2, for invariant checks: zero after a velocity solve.
template <class T>
T RackAndPinionVelocityError(const Body<T>& body1, const Body<T>& body2,
                             const Vec3<T>& hinge_axis, const Vec3<T>& slider_axis, T ratio) {
  return hinge_axis.dot(body1.AngularVelocity()) -
         ratio * slider_axis.dot(body2.LinearVelocity());
}

}  // namespace manyworlds::reference
