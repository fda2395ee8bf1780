// IndependentAxisPart: one linear degree of freedom shared by two bodies moving
// along two independent world axes (spec 2.11; the pulley: rope length
// |p1 − f1| + r·|p2 − f2|). Scalar reference, written from the formulas.
//
// Constraint (n_i unit from the fixed point f_i to the attachment p_i = x_i + r_i;
// the length L0 is the caller's; dn/dt ≈ 0 is assumed):
//
//   C = (x1 + r1 − f1)·n1 + r·(x2 + r2 − f2)·n2 − L0
//
// Jacobian (both bodies enter positively, spec 1.1):
//
//   J = [ n1ᵀ, (r1×n1)ᵀ, r·n2ᵀ, r·(r2×n2)ᵀ ]                 (v1, w1, v2, w2)
//
// Inverse effective mass, with a "NOT STATIC" test where other parts test
// "dynamic" (spec 1.5): a kinematic body's stored mass and inertia count in K,
// although it never receives an impulse (Jolt's behaviour; its debug build asserts):
//
//   K = [¬static1](m1⁻¹ + (r1×n1)·I1⁻¹(r1×n1)) + [¬static2](r²m2⁻¹ + (r r2×n2)·I2⁻¹(r r2×n2))
//
// m_eff = 1/K; K == 0 ⇒ Deactivate. Jacobian vectors and I⁻¹ vectors are zero for a
// static body. Inertia in vector form from the current rotation (spec 1.4).
//
// Velocity step: Δλ = −m_eff J·v
//   = −m_eff (n1·v1 + (r1×n1)·w1 + r n2·v2 + (r r2×n2)·w2),
// clamped on the accumulated value: Λ_new = clamp(Λ + Δλ, λmin, λmax), Δλ := Λ_new − Λ;
//   v1 += Δλ m1⁻¹n1,  w1 += Δλ I1⁻¹(r1×n1),  v2 += Δλ r m2⁻¹n2,  w2 += Δλ I2⁻¹(r r2×n2)
// (dynamic bodies only). No spring.
//
// Position step (spec 1.2): λ = −m_eff β C with the caller's C; positions and
// rotations move by += the same vectors times λ (dynamic only); skipped when C == 0.
#pragma once

#include <algorithm>
#include <cassert>
#include <cmath>

#include "reference/body.h"
#include "reference/math.h"

namespace manyworlds::reference {

template <class T>
class IndependentAxisPart {
 public:
  // r_i = p_i − x_i (world lever arm of the attachment), n_i its unit rope direction.
  void CalculateConstraintProperties(const Body<T>& body1, const Vec3<T>& r1,
                                     const Vec3<T>& n1, const Body<T>& body2,
                                     const Vec3<T>& r2, const Vec3<T>& n2, T ratio) {
    assert(std::abs(n1.squaredNorm() - T(1)) <= T(1e-5));
    assert(std::abs(n2.squaredNorm() - T(1)) <= T(1e-5));
    T k = T(0);
    if (body1.IsStatic()) {
      r1_x_n1_.setZero();
      inv_i1_r1_x_n1_.setZero();
    } else {
      r1_x_n1_ = r1.cross(n1);
      inv_i1_r1_x_n1_ = body1.MultiplyInverseInertia(r1_x_n1_);
      k += body1.inv_mass + r1_x_n1_.dot(inv_i1_r1_x_n1_);
    }
    if (body2.IsStatic()) {
      ratio_r2_x_n2_.setZero();
      inv_i2_ratio_r2_x_n2_.setZero();
    } else {
      ratio_r2_x_n2_ = ratio * r2.cross(n2);
      inv_i2_ratio_r2_x_n2_ = body2.MultiplyInverseInertia(ratio_r2_x_n2_);
      k += ratio * ratio * body2.inv_mass + ratio_r2_x_n2_.dot(inv_i2_ratio_r2_x_n2_);
    }
    if (k == T(0)) {
      Deactivate();
    } else {
      effective_mass_ = T(1) / k;
    }
  }

  // Scales the impulse of the previous step by dt/dt_prev and applies it.
  void WarmStart(Body<T>& body1, Body<T>& body2, const Vec3<T>& n1, const Vec3<T>& n2, T ratio,
                 T warm_start_ratio) {
    total_lambda_ *= warm_start_ratio;
    ApplyVelocityStep(body1, body2, n1, n2, ratio, total_lambda_);
  }

  // One Gauss–Seidel iteration with the accumulated impulse clamped to
  // [min_lambda, max_lambda]; true iff an impulse was applied (spec 1.1).
  bool SolveVelocityConstraint(Body<T>& body1, Body<T>& body2, const Vec3<T>& n1,
                               const Vec3<T>& n2, T ratio, T min_lambda, T max_lambda) {
    const T jv = n1.dot(body1.LinearVelocity()) + r1_x_n1_.dot(body1.AngularVelocity()) +
                 ratio * n2.dot(body2.LinearVelocity()) +
                 ratio_r2_x_n2_.dot(body2.AngularVelocity());
    const T unclamped = -effective_mass_ * jv;
    // min/max rather than std::clamp: no precondition on the range, as in Jolt.
    const T new_total = std::min(std::max(total_lambda_ + unclamped, min_lambda), max_lambda);
    const T delta_lambda = new_total - total_lambda_;
    total_lambda_ = new_total;
    return ApplyVelocityStep(body1, body2, n1, n2, ratio, delta_lambda);
  }

  // Baumgarte step on the caller's C; true iff C != 0 (then a step was taken).
  bool SolvePositionConstraint(Body<T>& body1, Body<T>& body2, const Vec3<T>& n1,
                               const Vec3<T>& n2, T ratio, T error_c, T baumgarte) const {
    if (error_c == T(0)) return false;
    const T lambda = -effective_mass_ * baumgarte * error_c;
    if (body1.IsDynamic()) {
      body1.AddPositionStep((lambda * body1.inv_mass) * n1);
      body1.AddRotationStep(lambda * inv_i1_r1_x_n1_);
    }
    if (body2.IsDynamic()) {
      body2.AddPositionStep((lambda * ratio * body2.inv_mass) * n2);
      body2.AddRotationStep(lambda * inv_i2_ratio_r2_x_n2_);
    }
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
  const Vec3<T>& R1xN1() const { return r1_x_n1_; }
  const Vec3<T>& RatioR2xN2() const { return ratio_r2_x_n2_; }  // r (r2×n2)
  const Vec3<T>& InvI1R1xN1() const { return inv_i1_r1_x_n1_; }
  const Vec3<T>& InvI2RatioR2xN2() const { return inv_i2_ratio_r2_x_n2_; }

 private:
  // v += M⁻¹ Jᵀ λ for dynamic bodies; true iff λ != 0.
  bool ApplyVelocityStep(Body<T>& body1, Body<T>& body2, const Vec3<T>& n1, const Vec3<T>& n2,
                         T ratio, T lambda) const {
    if (body1.IsDynamic()) {
      body1.AddLinearVelocityStep((lambda * body1.inv_mass) * n1);
      body1.angular_velocity += lambda * inv_i1_r1_x_n1_;
    }
    if (body2.IsDynamic()) {
      body2.AddLinearVelocityStep((lambda * ratio * body2.inv_mass) * n2);
      body2.angular_velocity += lambda * inv_i2_ratio_r2_x_n2_;
    }
    return lambda != T(0);
  }

  Vec3<T> r1_x_n1_ = Vec3<T>::Zero();               // r1 × n1 (zero if static)
  Vec3<T> ratio_r2_x_n2_ = Vec3<T>::Zero();         // r (r2 × n2)
  Vec3<T> inv_i1_r1_x_n1_ = Vec3<T>::Zero();        // I1⁻¹ (r1 × n1)
  Vec3<T> inv_i2_ratio_r2_x_n2_ = Vec3<T>::Zero();  // I2⁻¹ r (r2 × n2)
  T effective_mass_ = T(0);                         // m_eff = 1/K
  T total_lambda_ = T(0);                           // Λ
};

// J·v = dC/dt = n1·v1 + (r1×n1)·w1 + r·(n2·v2 + (r2×n2)·w2), for invariant checks:
// zero after an unclamped velocity solve when no body is kinematic.
template <class T>
T IndependentAxisVelocityError(const Body<T>& body1, const Vec3<T>& r1, const Vec3<T>& n1,
                               const Body<T>& body2, const Vec3<T>& r2, const Vec3<T>& n2,
                               T ratio) {
  return n1.dot(body1.LinearVelocity()) + r1.cross(n1).dot(body1.AngularVelocity()) +
         ratio * (n2.dot(body2.LinearVelocity()) + r2.cross(n2).dot(body2.AngularVelocity()));
}

}  // namespace manyworlds::reference
