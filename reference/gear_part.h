// GearPart: couples the rotation of body 1 about its world hinge axis a to the
// rotation of body 2 about its world hinge axis b with ratio r (spec 2.10). Scalar
// reference, written from the formulas.
//
// Constraint (θ1, θ2 = rotations about a, b; gears turn in opposite directions):
//
//   C = θ1 + r·θ2
//
// Jacobian (both bodies enter positively, spec 1.1):
//
//   J = [ 0, aᵀ, 0, r·bᵀ ]                                 (v1, w1, v2, w2)
//
// Inverse effective mass:
//
//   K = J M⁻¹ Jᵀ = a·I1⁻¹a + r²·(b·I2⁻¹b),   m_eff = 1/K;  K == 0 ⇒ Deactivate.
//
// Velocity step: Δλ = −m_eff J·v = −m_eff (a·w1 + r·b·w2); Λ += Δλ; w += I⁻¹Jᵀ Δλ:
//
//   w1 += Δλ I1⁻¹a,   w2 += Δλ r I2⁻¹b.
//
// THIS PROJECT DIFFERS FROM JOLT HERE (spec 2.10): Jolt applies body 2's impulse
// as Δλ I2⁻¹b, without the factor r that Jᵀ requires (also in its position step).
// We apply Jᵀλ exactly: body 2's angular impulse and position step carry r. Jolt
// still converges to J·v = 0 for moderate r but splits the impulse 1:1 instead of
// 1:r. Example, equal bodies, a = b, r = 2, ω = (1, 0): one solve gives
// Δλ = −1/(5 I⁻¹) and ω = (0.8, −0.4) here (J·v = 0 at once), where Jolt's
// Gauss–Seidel sweep tends to (0.6667, −0.3333). With r = 1 both agree. The
// cached body-2 vector is therefore r·I2⁻¹b (as RackAndPinionPart caches r·m2⁻¹b).
//
// Motion types (spec 1.5, as RackAndPinionPart): the inertia of BOTH bodies is
// always used whatever the motion type, and the velocity step (and warm start)
// writes both bodies without checking; the position step moves dynamic bodies only.
// Static bodies are invalid (Jolt reads their missing motion properties); asserted.
// Inertia in vector form from the current rotation (spec 1.4).
//
// Position step (spec 1.2): λ = −m_eff β C with the caller's C (the constraint wraps
// it with CenterAngleAroundZero(fmod(·, 2π)), spec 3); body 1 rotates by +λ I1⁻¹a,
// body 2 by +λ r I2⁻¹b; skipped when C == 0 exactly.
#pragma once

#include <cassert>

#include "reference/body.h"
#include "reference/math.h"

namespace manyworlds::reference {

template <class T>
class GearPart {
 public:
  void CalculateConstraintProperties(const Body<T>& body1, const Vec3<T>& hinge_axis1,
                                     const Body<T>& body2, const Vec3<T>& hinge_axis2,
                                     T ratio) {
    assert(!body1.IsStatic() && !body2.IsStatic());
    inv_i1_hinge_axis1_ = body1.MultiplyInverseInertia(hinge_axis1);
    const Vec3<T> inv_i2_hinge_axis2 = body2.MultiplyInverseInertia(hinge_axis2);
    ratio_inv_i2_hinge_axis2_ = ratio * inv_i2_hinge_axis2;
    const T k = hinge_axis1.dot(inv_i1_hinge_axis1_) +
                ratio * ratio * hinge_axis2.dot(inv_i2_hinge_axis2);
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
  bool SolveVelocityConstraint(Body<T>& body1, Body<T>& body2, const Vec3<T>& hinge_axis1,
                               const Vec3<T>& hinge_axis2, T ratio) {
    assert(!body1.IsStatic() && !body2.IsStatic());
    const T delta_lambda = -effective_mass_ * (hinge_axis1.dot(body1.angular_velocity) +
                                               ratio * hinge_axis2.dot(body2.angular_velocity));
    total_lambda_ += delta_lambda;
    return ApplyVelocityStep(body1, body2, delta_lambda);
  }

  // Baumgarte step on the caller's C; true iff C != 0 (then a step was taken).
  bool SolvePositionConstraint(Body<T>& body1, Body<T>& body2, T error_c, T baumgarte) const {
    if (error_c == T(0)) return false;
    const T lambda = -effective_mass_ * baumgarte * error_c;
    if (body1.IsDynamic()) body1.AddRotationStep(lambda * inv_i1_hinge_axis1_);
    if (body2.IsDynamic()) body2.AddRotationStep(lambda * ratio_inv_i2_hinge_axis2_);
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
  const Vec3<T>& InvI1HingeAxis1() const { return inv_i1_hinge_axis1_; }              // I1⁻¹a
  const Vec3<T>& RatioInvI2HingeAxis2() const { return ratio_inv_i2_hinge_axis2_; }  // r I2⁻¹b

 private:
  // w += I⁻¹ Jᵀ λ with no motion-type check (spec 1.5); true iff λ != 0.
  bool ApplyVelocityStep(Body<T>& body1, Body<T>& body2, T lambda) const {
    body1.angular_velocity += lambda * inv_i1_hinge_axis1_;
    body2.angular_velocity += lambda * ratio_inv_i2_hinge_axis2_;
    return lambda != T(0);
  }

  Vec3<T> inv_i1_hinge_axis1_ = Vec3<T>::Zero();        // I1⁻¹ a
  Vec3<T> ratio_inv_i2_hinge_axis2_ = Vec3<T>::Zero();  // r I2⁻¹ b
  T effective_mass_ = T(0);                             // m_eff = 1/K
  T total_lambda_ = T(0);                               // Λ
};

// J·v = dC/dt = a·w1 + r·b·w2, for invariant checks: zero after a velocity solve.
template <class T>
T GearVelocityError(const Body<T>& body1, const Body<T>& body2, const Vec3<T>& hinge_axis1,
                    const Vec3<T>& hinge_axis2, T ratio) {
  return hinge_axis1.dot(body1.AngularVelocity()) +
         ratio * hinge_axis2.dot(body2.AngularVelocity());
}

}  // namespace manyworlds::reference
