// AnglePart: removes one angular degree of freedom about a world axis a; with a
// clamped accumulated impulse it is a limit or a motor, with its SpringPart a soft
// limit or spring (spec 2.8; used by hinge, cone, swing-twist, six-DOF). Scalar
// reference, written from the formulas.
//
// Constraint: C is supplied by the caller (an angle about a, or for the cone
// constraint a cosine difference). The part does NO angle wrapping: callers wrap.
//
// Jacobian (a unit):
//
//   J = [ 0, −aᵀ, 0, aᵀ ]                                   (v1, w1, v2, w2)
//
// Inverse effective mass (inertia only of dynamic bodies, spec 1.5):
//
//   K = a·(I1⁻¹a + I2⁻¹a)
//
// K == 0 ⇒ Deactivate (m_eff = 0, Λ = 0) before anything else; otherwise
// m_eff = 1/K (hard) or 1/(K + γ) (soft; SpringPart, spec 2.1). The five
// CalculateConstraintProperties variants differ only in when the spring is on
// (table in spec 2.1, implemented by SpringPart::For*). Inertia in vector form from
// the current rotation (spec 1.4); I⁻¹a is zero for a body that is not dynamic.
//
// Velocity step (spec 1.1), with s = −J·v = a·(w1 − w2) (static bodies read as 0):
//   Δλ = m_eff·(s − (γΛ + b)),
//   Λ_new = clamp(Λ + Δλ, λmin, λmax),  Δλ := Λ_new − Λ,  Λ := Λ_new,
//   w1 −= Δλ I1⁻¹a,  w2 += Δλ I2⁻¹a           (dynamic bodies only).
//
// Position step (spec 1.2): only when C != 0 and the spring is off:
// λ = −m_eff β C; body 1 rotates by −λ I1⁻¹a, body 2 by +λ I2⁻¹a.
//
// Deactivate also resets the spring (decision, see spring_part.h).
#pragma once

#include <algorithm>
#include <cassert>
#include <cmath>

#include "reference/body.h"
#include "reference/math.h"
#include "reference/spring_part.h"

namespace manyworlds::reference {

template <class T>
class AnglePart {
 public:
  // Hard, with velocity bias b (J·v + b = 0 when unclamped).
  void CalculateConstraintProperties(const Body<T>& body1, const Body<T>& body2,
                                     const Vec3<T>& axis, T bias = T(0)) {
    const T k = CalculateInverseEffectiveMass(body1, body2, axis);
    if (k == T(0)) return Deactivate();
    effective_mass_ = spring_.ForBias(k, bias);
  }

  // Soft iff frequency > 0, else hard with `bias`.
  void CalculateConstraintPropertiesWithFrequencyAndDamping(T dt, const Body<T>& body1,
                                                            const Body<T>& body2,
                                                            const Vec3<T>& axis, T bias,
                                                            T error_c, T frequency,
                                                            T damping_ratio) {
    const T k = CalculateInverseEffectiveMass(body1, body2, axis);
    if (k == T(0)) return Deactivate();
    effective_mass_ =
        spring_.ForFrequencyAndDamping(dt, k, bias, error_c, frequency, damping_ratio);
  }

  // Soft iff stiffness > 0 or damping > 0, else hard with `bias`.
  void CalculateConstraintPropertiesWithStiffnessAndDamping(T dt, const Body<T>& body1,
                                                            const Body<T>& body2,
                                                            const Vec3<T>& axis, T bias,
                                                            T error_c, T stiffness,
                                                            T damping) {
    const T k = CalculateInverseEffectiveMass(body1, body2, axis);
    if (k == T(0)) return Deactivate();
    effective_mass_ = spring_.ForStiffnessAndDamping(dt, k, bias, error_c, stiffness, damping);
  }

  // Limit: soft iff settings.HasStiffness() (damping alone keeps a limit hard).
  void CalculateConstraintPropertiesWithSettingsForLimit(T dt, const Body<T>& body1,
                                                         const Body<T>& body2,
                                                         const Vec3<T>& axis, T bias,
                                                         T error_c,
                                                         const SpringSettings<T>& settings) {
    const T k = CalculateInverseEffectiveMass(body1, body2, axis);
    if (k == T(0)) return Deactivate();
    effective_mass_ = spring_.ForLimit(dt, k, bias, error_c, settings);
  }

  // Motor: always soft (settings must have stiffness or damping).
  void CalculateConstraintPropertiesWithSettingsForMotor(T dt, const Body<T>& body1,
                                                         const Body<T>& body2,
                                                         const Vec3<T>& axis, T bias,
                                                         T error_c,
                                                         const SpringSettings<T>& settings) {
    const T k = CalculateInverseEffectiveMass(body1, body2, axis);
    if (k == T(0)) return Deactivate();
    effective_mass_ = spring_.ForMotor(dt, k, bias, error_c, settings);
  }

  // Scales the impulse of the previous step by dt/dt_prev and applies it.
  void WarmStart(Body<T>& body1, Body<T>& body2, T warm_start_ratio) {
    total_lambda_ *= warm_start_ratio;
    ApplyVelocityStep(body1, body2, total_lambda_);
  }

  // One Gauss–Seidel iteration with the accumulated impulse clamped to
  // [min_lambda, max_lambda]; true iff an impulse was applied (spec 1.1).
  bool SolveVelocityConstraint(Body<T>& body1, Body<T>& body2, const Vec3<T>& axis,
                               T min_lambda, T max_lambda) {
    const T s = axis.dot(body1.AngularVelocity() - body2.AngularVelocity());
    const T unclamped = effective_mass_ * (s - spring_.GetBias(total_lambda_));
    // min/max rather than std::clamp: no precondition on the range, as in Jolt.
    const T new_total = std::min(std::max(total_lambda_ + unclamped, min_lambda), max_lambda);
    const T delta_lambda = new_total - total_lambda_;
    total_lambda_ = new_total;
    return ApplyVelocityStep(body1, body2, delta_lambda);
  }

  // Baumgarte step on the caller's C; true iff a step was taken (C != 0, not soft).
  bool SolvePositionConstraint(Body<T>& body1, Body<T>& body2, T error_c, T baumgarte) const {
    if (error_c == T(0) || spring_.IsActive()) return false;
    const T lambda = -effective_mass_ * baumgarte * error_c;
    if (body1.IsDynamic()) body1.SubRotationStep(lambda * inv_i1_axis_);
    if (body2.IsDynamic()) body2.AddRotationStep(lambda * inv_i2_axis_);
    return true;
  }

  // Wipes the warm-start impulse too: that is Jolt's behaviour (spec 1.3).
  void Deactivate() {
    effective_mass_ = T(0);
    total_lambda_ = T(0);
    spring_.Reset();
  }
  bool IsActive() const { return effective_mass_ != T(0); }

  T GetTotalLambda() const { return total_lambda_; }
  void SetTotalLambda(T lambda) { total_lambda_ = lambda; }
  T SaveState() const { return total_lambda_; }  // Λ is all that persists (spec 4.4)
  void RestoreState(T lambda) { total_lambda_ = lambda; }

  // Read-only views of the cached properties, for tests.
  T EffectiveMass() const { return effective_mass_; }  // 1/K or 1/(K + γ)
  const SpringPart<T>& Spring() const { return spring_; }
  const Vec3<T>& InvI1Axis() const { return inv_i1_axis_; }  // I1⁻¹ a
  const Vec3<T>& InvI2Axis() const { return inv_i2_axis_; }  // I2⁻¹ a

 private:
  // Fills the cached vectors and returns K.
  T CalculateInverseEffectiveMass(const Body<T>& body1, const Body<T>& body2,
                                  const Vec3<T>& axis) {
    assert(std::abs(axis.squaredNorm() - T(1)) <= T(1e-4));
    inv_i1_axis_ = body1.IsDynamic() ? body1.MultiplyInverseInertia(axis) : Vec3<T>::Zero();
    inv_i2_axis_ = body2.IsDynamic() ? body2.MultiplyInverseInertia(axis) : Vec3<T>::Zero();
    return axis.dot(inv_i1_axis_ + inv_i2_axis_);
  }

  // w += I⁻¹ Jᵀ λ for dynamic bodies; true iff λ != 0.
  bool ApplyVelocityStep(Body<T>& body1, Body<T>& body2, T lambda) const {
    if (body1.IsDynamic()) body1.angular_velocity -= lambda * inv_i1_axis_;
    if (body2.IsDynamic()) body2.angular_velocity += lambda * inv_i2_axis_;
    return lambda != T(0);
  }

  Vec3<T> inv_i1_axis_ = Vec3<T>::Zero();  // I1⁻¹ a
  Vec3<T> inv_i2_axis_ = Vec3<T>::Zero();  // I2⁻¹ a
  T effective_mass_ = T(0);                // m_eff
  SpringPart<T> spring_;                   // γ, b
  T total_lambda_ = T(0);                  // Λ
};

// J·v = dC/dt = a·(w2 − w1), for invariant checks (static bodies read as zero).
template <class T>
T AngleVelocityError(const Body<T>& body1, const Body<T>& body2, const Vec3<T>& axis) {
  return axis.dot(body2.AngularVelocity() - body1.AngularVelocity());
}

}  // namespace manyworlds::reference
