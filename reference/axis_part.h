// AxisPart: removes one linear degree of freedom along a world axis n; with a
// clamped accumulated impulse it is a limit or a motor, with its SpringPart a soft
// limit or spring (spec 2.2; used by distance, slider, six-DOF, path). Scalar
// reference, written from the formulas.
//
// Constraint (n unit, pointing from body 1 to body 2; u = p2 − p1):
//
//   C = (p2 − p1)·n
//
// Jacobian (Chappuis §2.1.1 with the extra u term, eq. 55); body 1's lever arm
// reaches p2, so the caller passes r1 + u = p2 − x1, and r2 = p2 − x2:
//
//   J = [ −nᵀ, −a1ᵀ, nᵀ, a2ᵀ ],   a1 = (r1 + u) × n,   a2 = r2 × n    (v1, w1, v2, w2)
//
// Inverse effective mass (only dynamic bodies have mass here, spec 1.5):
//
//   K = [dyn1](m1⁻¹ + a1·I1⁻¹a1) + [dyn2](m2⁻¹ + a2·I2⁻¹a2)
//
// K == 0 ⇒ Deactivate (m_eff = 0, Λ = 0) before anything else; otherwise
// m_eff = 1/K (hard) or 1/(K + γ) (soft; SpringPart, spec 2.1). The five
// CalculateConstraintProperties variants differ only in when the spring is on
// (table in spec 2.1, implemented by SpringPart::For*).
//
// Motion types (spec 1.5): a1 (a2) is computed when body 1 (2) is not static, so a
// kinematic body's velocity enters J·v; m⁻¹ and I⁻¹ terms only for dynamic bodies;
// impulses only to dynamic bodies. Cached vectors of a body that does not take
// part are zero, not stale. Inertia in vector form from the current rotation (1.4).
//
// Velocity step (spec 1.1). With s = −J·v = n·(v1 − v2) + a1·w1 − a2·w2:
//   Δλ = m_eff·(s − (γΛ + b)),
//   Λ_new = clamp(Λ + Δλ, λmin, λmax),  Δλ := Λ_new − Λ,  Λ := Λ_new,
//   v1 −= Δλ m1⁻¹ n,  w1 −= Δλ I1⁻¹a1,  v2 += Δλ m2⁻¹ n,  w2 += Δλ I2⁻¹a2.
// Unclamped and hard, this leaves J·v = −b; soft, J·v + γΛ + b = 0.
//
// Position step (spec 1.2): only when C != 0 and the spring is off (a soft part
// corrects position through its bias): λ = −m_eff β C, applied to positions and
// rotations with the velocity-step vectors. Uses the cached m_eff; callers
// recompute the properties from the current pose first.
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
class AxisPart {
 public:
  // Hard, with velocity bias b (J·v + b = 0 when unclamped).
  void CalculateConstraintProperties(const Body<T>& body1, const Vec3<T>& r1_plus_u,
                                     const Body<T>& body2, const Vec3<T>& r2,
                                     const Vec3<T>& axis, T bias = T(0)) {
    const T k = CalculateInverseEffectiveMass(body1, r1_plus_u, body2, r2, axis);
    if (k == T(0)) return Deactivate();
    effective_mass_ = spring_.ForBias(k, bias);
  }

  // Soft iff frequency > 0, else hard with `bias`.
  void CalculateConstraintPropertiesWithFrequencyAndDamping(
      T dt, const Body<T>& body1, const Vec3<T>& r1_plus_u, const Body<T>& body2,
      const Vec3<T>& r2, const Vec3<T>& axis, T bias, T error_c, T frequency, T damping_ratio) {
    const T k = CalculateInverseEffectiveMass(body1, r1_plus_u, body2, r2, axis);
    if (k == T(0)) return Deactivate();
    effective_mass_ =
        spring_.ForFrequencyAndDamping(dt, k, bias, error_c, frequency, damping_ratio);
  }

  // Soft iff stiffness > 0 or damping > 0, else hard with `bias`.
  void CalculateConstraintPropertiesWithStiffnessAndDamping(
      T dt, const Body<T>& body1, const Vec3<T>& r1_plus_u, const Body<T>& body2,
      const Vec3<T>& r2, const Vec3<T>& axis, T bias, T error_c, T stiffness, T damping) {
    const T k = CalculateInverseEffectiveMass(body1, r1_plus_u, body2, r2, axis);
    if (k == T(0)) return Deactivate();
    effective_mass_ = spring_.ForStiffnessAndDamping(dt, k, bias, error_c, stiffness, damping);
  }

  // Limit: soft iff settings.HasStiffness() (damping alone keeps a limit hard).
  void CalculateConstraintPropertiesWithSettingsForLimit(
      T dt, const Body<T>& body1, const Vec3<T>& r1_plus_u, const Body<T>& body2,
      const Vec3<T>& r2, const Vec3<T>& axis, T bias, T error_c,
      const SpringSettings<T>& settings) {
    const T k = CalculateInverseEffectiveMass(body1, r1_plus_u, body2, r2, axis);
    if (k == T(0)) return Deactivate();
    effective_mass_ = spring_.ForLimit(dt, k, bias, error_c, settings);
  }

  // Motor: always soft (settings must have stiffness or damping).
  void CalculateConstraintPropertiesWithSettingsForMotor(
      T dt, const Body<T>& body1, const Vec3<T>& r1_plus_u, const Body<T>& body2,
      const Vec3<T>& r2, const Vec3<T>& axis, T bias, T error_c,
      const SpringSettings<T>& settings) {
    const T k = CalculateInverseEffectiveMass(body1, r1_plus_u, body2, r2, axis);
    if (k == T(0)) return Deactivate();
    effective_mass_ = spring_.ForMotor(dt, k, bias, error_c, settings);
  }

  // Scales the impulse of the previous step by dt/dt_prev and applies it.
  void WarmStart(Body<T>& body1, Body<T>& body2, const Vec3<T>& axis, T warm_start_ratio) {
    total_lambda_ *= warm_start_ratio;
    ApplyVelocityStep(body1, body2, axis, total_lambda_);
  }

  // One Gauss–Seidel iteration with the accumulated impulse clamped to
  // [min_lambda, max_lambda]; true iff an impulse was applied (spec 1.1).
  bool SolveVelocityConstraint(Body<T>& body1, Body<T>& body2, const Vec3<T>& axis,
                               T min_lambda, T max_lambda) {
    const T s = axis.dot(body1.LinearVelocity() - body2.LinearVelocity()) +
                r1_plus_u_x_axis_.dot(body1.AngularVelocity()) -
                r2_x_axis_.dot(body2.AngularVelocity());
    const T unclamped = effective_mass_ * (s - spring_.GetBias(total_lambda_));
    // min/max rather than std::clamp: no precondition on the range, as in Jolt.
    const T new_total = std::min(std::max(total_lambda_ + unclamped, min_lambda), max_lambda);
    const T delta_lambda = new_total - total_lambda_;
    total_lambda_ = new_total;
    return ApplyVelocityStep(body1, body2, axis, delta_lambda);
  }

  // Baumgarte step on the caller's C; true iff a step was taken (C != 0, not soft).
  bool SolvePositionConstraint(Body<T>& body1, Body<T>& body2, const Vec3<T>& axis, T error_c,
                               T baumgarte) const {
    if (error_c == T(0) || spring_.IsActive()) return false;
    const T lambda = -effective_mass_ * baumgarte * error_c;
    if (body1.IsDynamic()) {
      body1.SubPositionStep((lambda * body1.inv_mass) * axis);
      body1.SubRotationStep(lambda * inv_i1_r1_plus_u_x_axis_);
    }
    if (body2.IsDynamic()) {
      body2.AddPositionStep((lambda * body2.inv_mass) * axis);
      body2.AddRotationStep(lambda * inv_i2_r2_x_axis_);
    }
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
  const Vec3<T>& R1PlusUxAxis() const { return r1_plus_u_x_axis_; }  // a1
  const Vec3<T>& R2xAxis() const { return r2_x_axis_; }               // a2
  const Vec3<T>& InvI1R1PlusUxAxis() const { return inv_i1_r1_plus_u_x_axis_; }
  const Vec3<T>& InvI2R2xAxis() const { return inv_i2_r2_x_axis_; }

 private:
  // Fills the cached vectors and returns K.
  T CalculateInverseEffectiveMass(const Body<T>& body1, const Vec3<T>& r1_plus_u,
                                  const Body<T>& body2, const Vec3<T>& r2,
                                  const Vec3<T>& axis) {
    assert(std::abs(axis.squaredNorm() - T(1)) <= T(1e-5));
    T k = T(0);

    r1_plus_u_x_axis_ = body1.IsStatic() ? Vec3<T>::Zero() : Vec3<T>(r1_plus_u.cross(axis));
    if (body1.IsDynamic()) {
      inv_i1_r1_plus_u_x_axis_ = body1.MultiplyInverseInertia(r1_plus_u_x_axis_);
      k += body1.inv_mass + r1_plus_u_x_axis_.dot(inv_i1_r1_plus_u_x_axis_);
    } else {
      inv_i1_r1_plus_u_x_axis_.setZero();
    }

    r2_x_axis_ = body2.IsStatic() ? Vec3<T>::Zero() : Vec3<T>(r2.cross(axis));
    if (body2.IsDynamic()) {
      inv_i2_r2_x_axis_ = body2.MultiplyInverseInertia(r2_x_axis_);
      k += body2.inv_mass + r2_x_axis_.dot(inv_i2_r2_x_axis_);
    } else {
      inv_i2_r2_x_axis_.setZero();
    }
    return k;
  }

  // v += M⁻¹ Jᵀ λ for dynamic bodies; true iff λ != 0.
  bool ApplyVelocityStep(Body<T>& body1, Body<T>& body2, const Vec3<T>& axis, T lambda) const {
    if (body1.IsDynamic()) {
      body1.SubLinearVelocityStep((lambda * body1.inv_mass) * axis);
      body1.angular_velocity -= lambda * inv_i1_r1_plus_u_x_axis_;
    }
    if (body2.IsDynamic()) {
      body2.AddLinearVelocityStep((lambda * body2.inv_mass) * axis);
      body2.angular_velocity += lambda * inv_i2_r2_x_axis_;
    }
    return lambda != T(0);
  }

  Vec3<T> r1_plus_u_x_axis_ = Vec3<T>::Zero();         // a1 = (r1 + u) × n
  Vec3<T> r2_x_axis_ = Vec3<T>::Zero();                // a2 = r2 × n
  Vec3<T> inv_i1_r1_plus_u_x_axis_ = Vec3<T>::Zero();  // I1⁻¹ a1
  Vec3<T> inv_i2_r2_x_axis_ = Vec3<T>::Zero();         // I2⁻¹ a2
  T effective_mass_ = T(0);                            // m_eff
  SpringPart<T> spring_;                               // γ, b
  T total_lambda_ = T(0);                              // Λ
};

// J·v = dC/dt = n·(v2 − v1) + (r2×n)·w2 − ((r1+u)×n)·w1, for invariant checks
// (static bodies read as zero velocity, so their terms vanish).
template <class T>
T AxisVelocityError(const Body<T>& body1, const Body<T>& body2, const Vec3<T>& r1_plus_u,
                    const Vec3<T>& r2, const Vec3<T>& axis) {
  return axis.dot(body2.LinearVelocity() - body1.LinearVelocity()) +
         r2.cross(axis).dot(body2.AngularVelocity()) -
         r1_plus_u.cross(axis).dot(body1.AngularVelocity());
}

}  // namespace manyworlds::reference
