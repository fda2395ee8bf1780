// HingeRotationPart: keeps the hinge axis of body 2 aligned with the hinge axis of
// body 1, removing two angular degrees of freedom (spec 2.5; hinge, path). Scalar
// reference, written from the formulas.
//
// Constraint (Chappuis §2.4.1, eq. 87): a1 = world hinge axis of body 1, a2 = that
// of body 2 (unit), b2 ⟂ a2 and c2 = a2 × b2 two axes fixed in body 2 across a2:
//
//   C = (a1·b2, a1·c2)                         (zero iff a1 ∥ a2)
//
// Jacobian (eq. 90): d/dt(a1·e) = (w1 × a1)·e + a1·(w2 × e) = (e × a1)·(w2 − w1), so
//
//   J_i = [ 0, −(e_i × a1)ᵀ, 0, (e_i × a1)ᵀ ],   e_0 = b2, e_1 = c2
//
//   K_ij = (e_i × a1)·(I1⁻¹ + I2⁻¹)(e_j × a1),   2×2 closed-form inverse; det == 0 ⇒
//   Deactivate. I⁻¹ (matrix form, current rotation) is zero unless dynamic (1.5).
//
// Degenerate axes (spec 2.5): C = 0 also holds for a1 = −a2, and far from a1 ∥ a2 the
// linearisation can push towards that wrong solution. If a1·a2 <= 1e-3 (>= ~90°
// apart), a2 is replaced by normalize(0.99·normalize(p) + 0.01·a1) with
// p = a2 − (a1·a2)a1 its part perpendicular to a1; if |p|² < 1e-6 (anti-parallel)
// p := NormalizedPerpendicular(a1) first. The replacement is less than 90° from a1.
// b2 = NormalizedPerpendicular(a2), c2 = a2 × b2 with the (replaced) a2.
//
// Velocity step: Δλ = −K⁻¹ J·v = K⁻¹((b2×a1)·(w1 − w2), (c2×a1)·(w1 − w2)); Λ += Δλ;
//   P = (b2×a1)Δλ0 + (c2×a1)Δλ1,  w1 −= I1⁻¹P,  w2 += I2⁻¹P     (dynamic bodies only).
// Position step: C from the cached a1, b2, c2 (callers recompute first); if C != 0:
// λ = −β K⁻¹ C and the same P rotates body 1 by −I1⁻¹P and body 2 by +I2⁻¹P.
//
// API decision (as DualAxisPart): inertia from the bodies' current rotations.
#pragma once

#include <cassert>
#include <cmath>

#include "reference/body.h"
#include "reference/math.h"

namespace manyworlds::reference {

// b2 and c2 after the degenerate-axis repair of a2 (see the header comment).
template <class T>
struct HingeRotationBasis {
  Vec3<T> b2;
  Vec3<T> c2;
};

template <class T>
HingeRotationBasis<T> HingeRotationPerpendiculars(const Vec3<T>& hinge_axis1,
                                                  const Vec3<T>& hinge_axis2) {
  Vec3<T> a2 = hinge_axis2;
  const T dot = hinge_axis1.dot(a2);
  if (dot <= T(1e-3)) {
    Vec3<T> perpendicular = a2 - dot * hinge_axis1;
    if (perpendicular.squaredNorm() < T(1e-6)) {
      perpendicular = NormalizedPerpendicular(hinge_axis1);
    }
    a2 = (T(0.99) * perpendicular.normalized() + T(0.01) * hinge_axis1).normalized();
  }
  const Vec3<T> b2 = NormalizedPerpendicular(a2);
  return {b2, a2.cross(b2)};
}

template <class T>
class HingeRotationPart {
 public:
  void CalculateConstraintProperties(const Body<T>& body1, const Vec3<T>& hinge_axis1,
                                     const Body<T>& body2, const Vec3<T>& hinge_axis2) {
    assert(std::abs(hinge_axis1.squaredNorm() - T(1)) <= T(1e-5));
    assert(std::abs(hinge_axis2.squaredNorm() - T(1)) <= T(1e-5));
    a1_ = hinge_axis1;
    const HingeRotationBasis<T> basis = HingeRotationPerpendiculars(hinge_axis1, hinge_axis2);
    b2_ = basis.b2;
    c2_ = basis.c2;

    inv_i1_ = body1.IsDynamic() ? body1.InverseInertia() : Mat33<T>::Zero();
    inv_i2_ = body2.IsDynamic() ? body2.InverseInertia() : Mat33<T>::Zero();
    b2_x_a1_ = b2_.cross(a1_);
    c2_x_a1_ = c2_.cross(a1_);

    const Mat33<T> summed_inv_inertia = inv_i1_ + inv_i2_;
    const Vec3<T> rows[2] = {b2_x_a1_, c2_x_a1_};
    Mat22<T> k;
    for (int i = 0; i < 2; ++i) {
      for (int j = 0; j < 2; ++j) k(i, j) = rows[i].dot(summed_inv_inertia * rows[j]);
    }
    if (!InvertSymmetricOr2x2(k, effective_mass_)) Deactivate();
  }

  // Scales the impulse of the previous step by dt/dt_prev and applies it.
  void WarmStart(Body<T>& body1, Body<T>& body2, T warm_start_ratio) {
    total_lambda_ *= warm_start_ratio;
    ApplyVelocityStep(body1, body2, total_lambda_);
  }

  // One Gauss–Seidel iteration; true iff an impulse was applied (spec 1.1).
  bool SolveVelocityConstraint(Body<T>& body1, Body<T>& body2) {
    const Vec3<T> delta_w = body1.AngularVelocity() - body2.AngularVelocity();
    const Vec2<T> delta_lambda =
        effective_mass_ * Vec2<T>(b2_x_a1_.dot(delta_w), c2_x_a1_.dot(delta_w));
    total_lambda_ += delta_lambda;
    return ApplyVelocityStep(body1, body2, delta_lambda);
  }

  // Baumgarte step on C = (a1·b2, a1·c2); true iff C != 0 (then a step was taken).
  bool SolvePositionConstraint(Body<T>& body1, Body<T>& body2, T baumgarte) const {
    const Vec2<T> c(a1_.dot(b2_), a1_.dot(c2_));
    if (c(0) == T(0) && c(1) == T(0)) return false;
    const Vec2<T> lambda = -baumgarte * (effective_mass_ * c);
    const Vec3<T> impulse = b2_x_a1_ * lambda(0) + c2_x_a1_ * lambda(1);
    if (body1.IsDynamic()) body1.SubRotationStep(inv_i1_ * impulse);
    if (body2.IsDynamic()) body2.AddRotationStep(inv_i2_ * impulse);
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
  const Vec3<T>& A1() const { return a1_; }
  const Vec3<T>& B2() const { return b2_; }
  const Vec3<T>& C2() const { return c2_; }
  const Vec3<T>& B2xA1() const { return b2_x_a1_; }
  const Vec3<T>& C2xA1() const { return c2_x_a1_; }
  const Mat33<T>& InvI1() const { return inv_i1_; }
  const Mat33<T>& InvI2() const { return inv_i2_; }

 private:
  // w += I⁻¹ Jᵀ λ for dynamic bodies; true iff any component of λ is non-zero.
  bool ApplyVelocityStep(Body<T>& body1, Body<T>& body2, const Vec2<T>& lambda) const {
    const Vec3<T> impulse = b2_x_a1_ * lambda(0) + c2_x_a1_ * lambda(1);
    if (body1.IsDynamic()) body1.angular_velocity -= inv_i1_ * impulse;
    if (body2.IsDynamic()) body2.angular_velocity += inv_i2_ * impulse;
    return lambda(0) != T(0) || lambda(1) != T(0);
  }

  Vec3<T> a1_ = Vec3<T>::Zero();  // world hinge axis of body 1
  Vec3<T> b2_ = Vec3<T>::Zero();  // perpendiculars of body 2's (repaired) hinge axis
  Vec3<T> c2_ = Vec3<T>::Zero();
  Mat33<T> inv_i1_ = Mat33<T>::Zero();  // I1⁻¹ (zero unless dynamic)
  Mat33<T> inv_i2_ = Mat33<T>::Zero();  // I2⁻¹
  Vec3<T> b2_x_a1_ = Vec3<T>::Zero();
  Vec3<T> c2_x_a1_ = Vec3<T>::Zero();
  Mat22<T> effective_mass_ = Mat22<T>::Zero();  // K⁻¹
  Vec2<T> total_lambda_ = Vec2<T>::Zero();      // Λ
};

// J·v = ((b2×a1)·(w2 − w1), (c2×a1)·(w2 − w1)) with b2, c2 from the same repair, for
// invariant checks: zero after a velocity solve.
template <class T>
Vec2<T> HingeRotationVelocityError(const Body<T>& body1, const Vec3<T>& hinge_axis1,
                                   const Body<T>& body2, const Vec3<T>& hinge_axis2) {
  const HingeRotationBasis<T> basis = HingeRotationPerpendiculars(hinge_axis1, hinge_axis2);
  const Vec3<T> delta_w = body2.AngularVelocity() - body1.AngularVelocity();
  return Vec2<T>(basis.b2.cross(hinge_axis1).dot(delta_w),
                 basis.c2.cross(hinge_axis1).dot(delta_w));
}

}  // namespace manyworlds::reference
