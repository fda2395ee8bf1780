// DualAxisPart: keeps the anchor of body 2 on a line of body 1 by removing the two
// linear degrees of freedom along n1 and n2 (spec 2.3; used sideways by the slider
// and path constraints). Scalar reference, written from the formulas.
//
// Constraint (n1 ⟂ n2, both unit; u = p2 − p1, r1 = p1 − x1, r2 = p2 − x2):
//
//   C = (u·n1, u·n2)
//
// Jacobian, one row per axis n_i (Chappuis §2.1.1 with the extra u term, eq. 55);
// body 1's lever arm reaches p2, so the caller passes r1 + u = p2 − x1:
//
//   J_i = [ −n_iᵀ, −((r1 + u) × n_i)ᵀ, n_iᵀ, (r2 × n_i)ᵀ ]     (v1, w1, v2, w2)
//
// Inverse effective mass K = J M⁻¹ Jᵀ (2×2); only dynamic bodies contribute:
//
//   K_ij = [dyn1](m1⁻¹ δ_ij + ((r1+u)×n_i)·I1⁻¹((r1+u)×n_j))
//        + [dyn2](m2⁻¹ δ_ij + (r2×n_i)·I2⁻¹(r2×n_j))
//
// K⁻¹ by the closed 2×2 formula; det == 0 ⇒ Deactivate (K⁻¹ = 0, Λ = 0).
//
// Velocity step (spec 1.1). The solver works with the negated velocity error
//   s_i = −J_i·v = n_i·(v1 − v2) + ((r1+u)×n_i)·w1 − (r2×n_i)·w2,
// so Δλ = K⁻¹ s drives J·v to zero; Λ += Δλ (no clamp, no spring). The impulse
// M⁻¹Jᵀ Δλ with P = n1 Δλ0 + n2 Δλ1 is
//   v1 −= m1⁻¹ P,  w1 −= Σ_i Δλ_i I1⁻¹((r1+u)×n_i),  v2 += m2⁻¹ P,  w2 += Σ_i Δλ_i I2⁻¹(r2×n_i),
// written to dynamic bodies only (spec 1.5).
//
// Position step (spec 1.2): λ = −β K⁻¹ C, the same update applied to positions and
// rotations through Add/SubPositionStep and Add/SubRotationStep; skipped when
// C == 0 exactly. Callers recompute the properties from the current pose first.
#pragma once

#include <cassert>

#include "reference/body.h"
#include "reference/math.h"

namespace manyworlds::reference {

template <class T>
class DualAxisPart {
 public:
  // Inertia comes from each body's current rotation (spec 1.4, matrix form).
  // Cross products are always computed (they also read the velocities of kinematic
  // bodies); mass and inertia terms only for dynamic bodies.
  void CalculateConstraintProperties(const Body<T>& body1, const Vec3<T>& r1_plus_u,
                                     const Body<T>& body2, const Vec3<T>& r2, const Vec3<T>& n1,
                                     const Vec3<T>& n2) {
    const Vec3<T> n[2] = {n1, n2};
    for (int i = 0; i < 2; ++i) {
      r1_plus_u_x_n_[i] = r1_plus_u.cross(n[i]);
      r2_x_n_[i] = r2.cross(n[i]);
    }

    T inv_m1 = T(0);
    if (body1.IsDynamic()) {
      inv_m1 = body1.inv_mass;
      const Mat33<T> inv_i1 = body1.InverseInertia();
      for (int i = 0; i < 2; ++i) inv_i1_r1_plus_u_x_n_[i] = inv_i1 * r1_plus_u_x_n_[i];
    } else {
      // Zero, not stale, so that inactive lanes compute 0·x = 0 (spec 1.3).
      for (int i = 0; i < 2; ++i) inv_i1_r1_plus_u_x_n_[i].setZero();
    }

    T inv_m2 = T(0);
    if (body2.IsDynamic()) {
      inv_m2 = body2.inv_mass;
      const Mat33<T> inv_i2 = body2.InverseInertia();
      for (int i = 0; i < 2; ++i) inv_i2_r2_x_n_[i] = inv_i2 * r2_x_n_[i];
    } else {
      for (int i = 0; i < 2; ++i) inv_i2_r2_x_n_[i].setZero();
    }

    // Every entry straight from K_ij; a non-dynamic body's terms are exactly zero.
    Mat22<T> k;
    for (int i = 0; i < 2; ++i) {
      for (int j = 0; j < 2; ++j) {
        const T linear = (i == j) ? inv_m1 + inv_m2 : T(0);
        k(i, j) = linear + r1_plus_u_x_n_[i].dot(inv_i1_r1_plus_u_x_n_[j]) +
                  r2_x_n_[i].dot(inv_i2_r2_x_n_[j]);
      }
    }
    if (!InvertSymmetricOr2x2(k, effective_mass_)) Deactivate();
  }

  // Scales the impulse of the previous step by dt/dt_prev and applies it.
  void WarmStart(Body<T>& body1, Body<T>& body2, const Vec3<T>& n1, const Vec3<T>& n2,
                 T warm_start_ratio) {
    total_lambda_ *= warm_start_ratio;
    ApplyVelocityStep(body1, body2, n1, n2, total_lambda_);
  }

  // One Gauss–Seidel iteration; true iff an impulse was applied (spec 1.1).
  bool SolveVelocityConstraint(Body<T>& body1, Body<T>& body2, const Vec3<T>& n1,
                               const Vec3<T>& n2) {
    const Vec3<T> v1 = body1.LinearVelocity();
    const Vec3<T> w1 = body1.AngularVelocity();
    const Vec3<T> v2 = body2.LinearVelocity();
    const Vec3<T> w2 = body2.AngularVelocity();
    const Vec3<T> dv = v1 - v2;
    const Vec2<T> s(n1.dot(dv) + r1_plus_u_x_n_[0].dot(w1) - r2_x_n_[0].dot(w2),
                    n2.dot(dv) + r1_plus_u_x_n_[1].dot(w1) - r2_x_n_[1].dot(w2));
    const Vec2<T> delta_lambda = effective_mass_ * s;
    total_lambda_ += delta_lambda;
    return ApplyVelocityStep(body1, body2, n1, n2, delta_lambda);
  }

  // Baumgarte step on C = (u·n1, u·n2); true iff C != 0 (then a step was taken).
  bool SolvePositionConstraint(Body<T>& body1, Body<T>& body2, const Vec3<T>& u,
                               const Vec3<T>& n1, const Vec3<T>& n2, T baumgarte) const {
    const Vec2<T> c(u.dot(n1), u.dot(n2));
    if (c(0) == T(0) && c(1) == T(0)) return false;

    const Vec2<T> lambda = -baumgarte * (effective_mass_ * c);
    const Vec3<T> p = n1 * lambda(0) + n2 * lambda(1);
    if (body1.IsDynamic()) {
      body1.SubPositionStep(body1.inv_mass * p);
      body1.SubRotationStep(inv_i1_r1_plus_u_x_n_[0] * lambda(0) +
                            inv_i1_r1_plus_u_x_n_[1] * lambda(1));
    }
    if (body2.IsDynamic()) {
      body2.AddPositionStep(body2.inv_mass * p);
      body2.AddRotationStep(inv_i2_r2_x_n_[0] * lambda(0) + inv_i2_r2_x_n_[1] * lambda(1));
    }
    return true;
  }

  // Wipes the warm-start impulse too: that is Jolt's behaviour (spec 1.3).
  void Deactivate() {
    effective_mass_.setZero();
    total_lambda_.setZero();
  }
  bool IsActive() const { return (effective_mass_.array() != T(0)).any(); }

  Vec2<T> GetTotalLambda() const { return total_lambda_; }
  void SetTotalLambda(const Vec2<T>& lambda) { total_lambda_ = lambda; }
  Vec2<T> SaveState() const { return total_lambda_; }  // Λ is all that persists (spec 4.4)
  void RestoreState(const Vec2<T>& lambda) { total_lambda_ = lambda; }

  // Read-only views of the cached properties, for tests.
  const Mat22<T>& EffectiveMass() const { return effective_mass_; }  // K⁻¹
  const Vec3<T>& R1PlusUxN(int i) const { return r1_plus_u_x_n_[Checked(i)]; }
  const Vec3<T>& R2xN(int i) const { return r2_x_n_[Checked(i)]; }
  const Vec3<T>& InvI1R1PlusUxN(int i) const { return inv_i1_r1_plus_u_x_n_[Checked(i)]; }
  const Vec3<T>& InvI2R2xN(int i) const { return inv_i2_r2_x_n_[Checked(i)]; }

 private:
  static int Checked(int i) {
    assert(i == 0 || i == 1);
    return i;
  }

  // v += M⁻¹ Jᵀ λ for dynamic bodies; true iff any component of λ is non-zero.
  bool ApplyVelocityStep(Body<T>& body1, Body<T>& body2, const Vec3<T>& n1, const Vec3<T>& n2,
                         const Vec2<T>& lambda) const {
    const Vec3<T> p = n1 * lambda(0) + n2 * lambda(1);
    if (body1.IsDynamic()) {
      body1.SubLinearVelocityStep(body1.inv_mass * p);
      body1.angular_velocity -=
          inv_i1_r1_plus_u_x_n_[0] * lambda(0) + inv_i1_r1_plus_u_x_n_[1] * lambda(1);
    }
    if (body2.IsDynamic()) {
      body2.AddLinearVelocityStep(body2.inv_mass * p);
      body2.angular_velocity += inv_i2_r2_x_n_[0] * lambda(0) + inv_i2_r2_x_n_[1] * lambda(1);
    }
    return lambda(0) != T(0) || lambda(1) != T(0);
  }

  Vec3<T> r1_plus_u_x_n_[2] = {Vec3<T>::Zero(), Vec3<T>::Zero()};
  Vec3<T> r2_x_n_[2] = {Vec3<T>::Zero(), Vec3<T>::Zero()};
  Vec3<T> inv_i1_r1_plus_u_x_n_[2] = {Vec3<T>::Zero(), Vec3<T>::Zero()};
  Vec3<T> inv_i2_r2_x_n_[2] = {Vec3<T>::Zero(), Vec3<T>::Zero()};
  Mat22<T> effective_mass_ = Mat22<T>::Zero();  // K⁻¹
  Vec2<T> total_lambda_ = Vec2<T>::Zero();      // Λ
};

// J·v = dC/dt of the two rows, for invariant checks: zero after a velocity solve.
//   (J·v)_i = n_i·(v2 − v1) + (r2×n_i)·w2 − ((r1+u)×n_i)·w1
template <class T>
Vec2<T> DualAxisVelocityError(const Body<T>& body1, const Body<T>& body2,
                              const Vec3<T>& r1_plus_u, const Vec3<T>& r2, const Vec3<T>& n1,
                              const Vec3<T>& n2) {
  const Vec3<T> v1 = body1.LinearVelocity();
  const Vec3<T> w1 = body1.AngularVelocity();
  const Vec3<T> v2 = body2.LinearVelocity();
  const Vec3<T> w2 = body2.AngularVelocity();
  const Vec3<T> n[2] = {n1, n2};
  Vec2<T> error;
  for (int i = 0; i < 2; ++i) {
    error(i) = n[i].dot(v2 - v1) + r2.cross(n[i]).dot(w2) - r1_plus_u.cross(n[i]).dot(w1);
  }
  return error;
}

}  // namespace manyworlds::reference
