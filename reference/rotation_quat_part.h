// RotationQuatPart: fixes the rotation of body 2 relative to body 1 like
// RotationEulerPart, but with the exact quaternion Jacobian instead of the
// small-angle one (spec 2.7; no Jolt constraint uses it). Scalar reference, written
// from the formulas.
//
// Constraint (r0⁻¹ as in rotation_euler_part.h, q2 = q1·r0 at rest):
//
//   C = xyz(q1*·q2·r0⁻¹)
//
// No w sign normalisation: the Jacobian below is the exact derivative of this very
// expression, so the signs stay consistent.
//
// Derivative: q̇ = ½ ω q (ω world, as a pure quaternion), so (q1*)˙ = −½ q1* ω1 and
//
//   d/dt (q1*·q2·r0⁻¹) = ½ q1*·(ω2 − ω1)·(q2 r0⁻¹)
//
// Writing L(p), R(p) for the 4×4 left/right multiplication matrices of p in
// (x, y, z, w) order and A = [E 0] for "take xyz":
//
//   JP = A·L(½ q1*)·R(q2 r0⁻¹)·Aᵀ   (the upper-left 3×3),   J = [ 0, −JP, 0, JP ]
//
// computed here column by column: JP e_i = xyz(½ q1*·(e_i, 0)·q2 r0⁻¹).
//
//   K = JP (I1⁻¹ + I2⁻¹) JPᵀ,  3×3 adjugate / det; det == 0 ⇒ Deactivate.
//
// Velocity step: Δλ = −K⁻¹ J·v = (K⁻¹JP)(w1 − w2); Λ += Δλ;
//   w1 −= I1⁻¹JPᵀΔλ,  w2 += I2⁻¹JPᵀΔλ     (dynamic bodies only).
// Position step: C from the current rotations; if C != 0: λ = −β K⁻¹ C, body 1
// rotates by −I1⁻¹JPᵀλ, body 2 by +I2⁻¹JPᵀλ.
//
// API decision (as DualAxisPart): inertia and JP from the bodies' current rotations.
#pragma once

#include "reference/body.h"
#include "reference/math.h"

namespace manyworlds::reference {

// C = xyz(q1*·q2·r0⁻¹) from the bodies' current rotations.
template <class T>
Vec3<T> RotationQuatPositionError(const Body<T>& body1, const Body<T>& body2,
                                  const Quat<T>& inv_initial_orientation) {
  return Quat<T>(body1.rotation.conjugate() * body2.rotation * inv_initial_orientation).vec();
}

// JP = ∂C/∂(w2 − w1) at the bodies' current rotations (see the header comment).
template <class T>
Mat33<T> RotationQuatJacobian(const Body<T>& body1, const Body<T>& body2,
                              const Quat<T>& inv_initial_orientation) {
  const Quat<T> q1_conjugate = body1.rotation.conjugate();
  const Quat<T> q2_r0_inv = body2.rotation * inv_initial_orientation;
  Mat33<T> jp;
  for (int i = 0; i < 3; ++i) {
    const Vec3<T> e = Vec3<T>::Unit(i);
    const Quat<T> pure(T(0), e.x(), e.y(), e.z());
    jp.col(i) = T(0.5) * Quat<T>(q1_conjugate * pure * q2_r0_inv).vec();
  }
  return jp;
}

template <class T>
class RotationQuatPart {
 public:
  void CalculateConstraintProperties(const Body<T>& body1, const Body<T>& body2,
                                     const Quat<T>& inv_initial_orientation) {
    const Mat33<T> jp = RotationQuatJacobian(body1, body2, inv_initial_orientation);
    const Mat33<T> inv_i1 = body1.IsDynamic() ? body1.InverseInertia() : Mat33<T>::Zero();
    const Mat33<T> inv_i2 = body2.IsDynamic() ? body2.InverseInertia() : Mat33<T>::Zero();
    inv_i1_jp_t_ = inv_i1 * jp.transpose();
    inv_i2_jp_t_ = inv_i2 * jp.transpose();
    const Mat33<T> k = jp * (inv_i1 + inv_i2) * jp.transpose();
    if (!Invert3x3(k, effective_mass_)) return Deactivate();
    effective_mass_jp_ = effective_mass_ * jp;
  }

  // Scales the impulse of the previous step by dt/dt_prev and applies it.
  void WarmStart(Body<T>& body1, Body<T>& body2, T warm_start_ratio) {
    total_lambda_ *= warm_start_ratio;
    ApplyVelocityStep(body1, body2, total_lambda_);
  }

  // One Gauss–Seidel iteration; true iff an impulse was applied (spec 1.1).
  bool SolveVelocityConstraint(Body<T>& body1, Body<T>& body2) {
    const Vec3<T> delta_lambda =
        effective_mass_jp_ * (body1.AngularVelocity() - body2.AngularVelocity());
    total_lambda_ += delta_lambda;
    return ApplyVelocityStep(body1, body2, delta_lambda);
  }

  // Baumgarte step towards q2 = q1·r0; true iff C != 0 (then a step was taken).
  bool SolvePositionConstraint(Body<T>& body1, Body<T>& body2,
                               const Quat<T>& inv_initial_orientation, T baumgarte) const {
    const Vec3<T> c = RotationQuatPositionError(body1, body2, inv_initial_orientation);
    if (c.isZero(T(0))) return false;
    const Vec3<T> lambda = -baumgarte * (effective_mass_ * c);
    if (body1.IsDynamic()) body1.SubRotationStep(inv_i1_jp_t_ * lambda);
    if (body2.IsDynamic()) body2.AddRotationStep(inv_i2_jp_t_ * lambda);
    return true;
  }

  // Wipes the warm-start impulse too: that is Jolt's behaviour (spec 1.3). K⁻¹JP is
  // what the velocity step multiplies by, so it is zeroed with K⁻¹.
  void Deactivate() {
    effective_mass_.setZero();
    effective_mass_jp_.setZero();
    total_lambda_.setZero();
  }
  bool IsActive() const { return (effective_mass_.array() != T(0)).any(); }

  Vec3<T> GetTotalLambda() const { return total_lambda_; }
  void SetTotalLambda(const Vec3<T>& lambda) { total_lambda_ = lambda; }
  Vec3<T> SaveState() const { return total_lambda_; }  // Λ is all that persists (spec 4.4)
  void RestoreState(const Vec3<T>& lambda) { total_lambda_ = lambda; }

  // Read-only views of the cached properties, for tests.
  const Mat33<T>& EffectiveMass() const { return effective_mass_; }       // K⁻¹
  const Mat33<T>& EffectiveMassJP() const { return effective_mass_jp_; }  // K⁻¹ JP
  const Mat33<T>& InvI1JPt() const { return inv_i1_jp_t_; }               // I1⁻¹ JPᵀ
  const Mat33<T>& InvI2JPt() const { return inv_i2_jp_t_; }               // I2⁻¹ JPᵀ

 private:
  // w += I⁻¹ Jᵀ λ for dynamic bodies; true iff any component of λ is non-zero.
  bool ApplyVelocityStep(Body<T>& body1, Body<T>& body2, const Vec3<T>& lambda) const {
    if (body1.IsDynamic()) body1.angular_velocity -= inv_i1_jp_t_ * lambda;
    if (body2.IsDynamic()) body2.angular_velocity += inv_i2_jp_t_ * lambda;
    return !lambda.isZero(T(0));
  }

  Mat33<T> inv_i1_jp_t_ = Mat33<T>::Zero();        // I1⁻¹ JPᵀ (zero unless dynamic)
  Mat33<T> inv_i2_jp_t_ = Mat33<T>::Zero();        // I2⁻¹ JPᵀ
  Mat33<T> effective_mass_ = Mat33<T>::Zero();     // K⁻¹
  Mat33<T> effective_mass_jp_ = Mat33<T>::Zero();  // K⁻¹ JP
  Vec3<T> total_lambda_ = Vec3<T>::Zero();         // Λ
};

// J·v = dC/dt = JP (w2 − w1) at the bodies' current rotations, for invariant checks.
template <class T>
Vec3<T> RotationQuatVelocityError(const Body<T>& body1, const Body<T>& body2,
                                  const Quat<T>& inv_initial_orientation) {
  return RotationQuatJacobian(body1, body2, inv_initial_orientation) *
         (body2.AngularVelocity() - body1.AngularVelocity());
}

}  // namespace manyworlds::reference
