// PointPart: makes an anchor point of body 1 and an anchor point of body 2
// coincide, removing three linear degrees of freedom (spec 2.4; the ball joint in
// point, fixed, hinge, cone, swing-twist, six-DOF). Scalar reference, written from
// the formulas.
//
// Constraint (r1 = R1·r1_local, r2 = R2·r2_local world lever arms from the COMs):
//
//   C = p2 − p1 = (x2 + r2) − (x1 + r1)
//
// Velocity of an anchor: v + w × r = v − [r]× w, so
//
//   J·v = v2 − [r2]× w2 − v1 + [r1]× w1,   J = [ −E, [r1]×, E, −[r2]× ]   (v1, w1, v2, w2)
//
// Inverse effective mass (only dynamic bodies contribute, spec 1.5):
//
//   K = (m1⁻¹ + m2⁻¹)·E + [r1]× I1⁻¹ [r1]×ᵀ + [r2]× I2⁻¹ [r2]×ᵀ
//
// 3×3 inverse by adjugate / det with det = c0·(c1×c2); det == 0 ⇒ Deactivate.
//
// Velocity step (spec 1.1): Δλ = −K⁻¹ J·v = K⁻¹(v1 − r1×w1 − v2 + r2×w2); Λ += Δλ;
// v += M⁻¹Jᵀ Δλ, with Jᵀ of body 1's angular row = [r1]×ᵀ = −[r1]×:
//   v1 −= m1⁻¹Δλ,  w1 −= I1⁻¹(r1 × Δλ),  v2 += m2⁻¹Δλ,  w2 += I2⁻¹(r2 × Δλ)
// (dynamic bodies only). I⁻¹[r]× is cached as a matrix so that I⁻¹(r × Δλ) is one
// product.
//
// Position step (spec 1.2): C = (x2 − x1) + r2 − r1 from the CURRENT centres of mass
// and the lever arms of the last CalculateConstraintProperties; if C != 0:
// λ = −β K⁻¹ C, applied like the velocity step to positions and rotations.
//
// API decision (as DualAxisPart): Jolt passes the rotation matrices R1, R2 that feed
// r = R·r_local and I⁻¹ = R R_I D R_Iᵀ Rᵀ; every constraint passes the bodies'
// current rotations, so here they are taken from the bodies themselves.
#pragma once

#include "reference/body.h"
#include "reference/math.h"

namespace manyworlds::reference {

template <class T>
class PointPart {
 public:
  // r_local: anchor relative to the COM in body space. Inertia (matrix form) and
  // lever arms from each body's current rotation.
  void CalculateConstraintProperties(const Body<T>& body1, const Vec3<T>& r1_local,
                                     const Body<T>& body2, const Vec3<T>& r2_local) {
    r1_ = body1.rotation * r1_local;
    r2_ = body2.rotation * r2_local;

    Mat33<T> k = Mat33<T>::Zero();
    if (body1.IsDynamic()) {
      const Mat33<T> r1_x = CrossProductMatrix(r1_);
      const Mat33<T> inv_i1 = body1.InverseInertia();
      inv_i1_r1_x_ = inv_i1 * r1_x;
      k += body1.inv_mass * Mat33<T>::Identity() + r1_x * inv_i1 * r1_x.transpose();
    } else {
      inv_i1_r1_x_.setZero();
    }
    if (body2.IsDynamic()) {
      const Mat33<T> r2_x = CrossProductMatrix(r2_);
      const Mat33<T> inv_i2 = body2.InverseInertia();
      inv_i2_r2_x_ = inv_i2 * r2_x;
      k += body2.inv_mass * Mat33<T>::Identity() + r2_x * inv_i2 * r2_x.transpose();
    } else {
      inv_i2_r2_x_.setZero();
    }
    if (!Invert3x3(k, effective_mass_)) Deactivate();
  }

  // Scales the impulse of the previous step by dt/dt_prev and applies it.
  void WarmStart(Body<T>& body1, Body<T>& body2, T warm_start_ratio) {
    total_lambda_ *= warm_start_ratio;
    ApplyVelocityStep(body1, body2, total_lambda_);
  }

  // One Gauss–Seidel iteration; true iff an impulse was applied (spec 1.1).
  bool SolveVelocityConstraint(Body<T>& body1, Body<T>& body2) {
    const Vec3<T> minus_jv = body1.LinearVelocity() - r1_.cross(body1.AngularVelocity()) -
                             body2.LinearVelocity() + r2_.cross(body2.AngularVelocity());
    const Vec3<T> delta_lambda = effective_mass_ * minus_jv;
    total_lambda_ += delta_lambda;
    return ApplyVelocityStep(body1, body2, delta_lambda);
  }

  // Baumgarte step on the current separation; true iff C != 0 (then a step was taken).
  bool SolvePositionConstraint(Body<T>& body1, Body<T>& body2, T baumgarte) const {
    const Vec3<T> c = (body2.position - body1.position) + r2_ - r1_;
    if (c.isZero(T(0))) return false;
    const Vec3<T> lambda = -baumgarte * (effective_mass_ * c);
    if (body1.IsDynamic()) {
      body1.SubPositionStep(body1.inv_mass * lambda);
      body1.SubRotationStep(inv_i1_r1_x_ * lambda);
    }
    if (body2.IsDynamic()) {
      body2.AddPositionStep(body2.inv_mass * lambda);
      body2.AddRotationStep(inv_i2_r2_x_ * lambda);
    }
    return true;
  }

  // Wipes the warm-start impulse too: that is Jolt's behaviour (spec 1.3).
  void Deactivate() {
    effective_mass_.setZero();
    total_lambda_.setZero();
  }
  bool IsActive() const { return (effective_mass_.array() != T(0)).any(); }

  Vec3<T> GetTotalLambda() const { return total_lambda_; }
  void SetTotalLambda(const Vec3<T>& lambda) { total_lambda_ = lambda; }
  Vec3<T> SaveState() const { return total_lambda_; }  // Λ is all that persists (spec 4.4)
  void RestoreState(const Vec3<T>& lambda) { total_lambda_ = lambda; }

  // Read-only views of the cached properties, for tests.
  const Mat33<T>& EffectiveMass() const { return effective_mass_; }  // K⁻¹
  const Vec3<T>& R1() const { return r1_; }                          // world lever arms
  const Vec3<T>& R2() const { return r2_; }
  const Mat33<T>& InvI1R1x() const { return inv_i1_r1_x_; }  // I1⁻¹[r1]×
  const Mat33<T>& InvI2R2x() const { return inv_i2_r2_x_; }  // I2⁻¹[r2]×

 private:
  // v += M⁻¹ Jᵀ λ for dynamic bodies; true iff any component of λ is non-zero.
  bool ApplyVelocityStep(Body<T>& body1, Body<T>& body2, const Vec3<T>& lambda) const {
    if (body1.IsDynamic()) {
      body1.SubLinearVelocityStep(body1.inv_mass * lambda);
      body1.angular_velocity -= inv_i1_r1_x_ * lambda;
    }
    if (body2.IsDynamic()) {
      body2.AddLinearVelocityStep(body2.inv_mass * lambda);
      body2.angular_velocity += inv_i2_r2_x_ * lambda;
    }
    return !lambda.isZero(T(0));
  }

  Vec3<T> r1_ = Vec3<T>::Zero();                // R1 r1_local
  Vec3<T> r2_ = Vec3<T>::Zero();                // R2 r2_local
  Mat33<T> inv_i1_r1_x_ = Mat33<T>::Zero();     // I1⁻¹[r1]×
  Mat33<T> inv_i2_r2_x_ = Mat33<T>::Zero();     // I2⁻¹[r2]×
  Mat33<T> effective_mass_ = Mat33<T>::Zero();  // K⁻¹
  Vec3<T> total_lambda_ = Vec3<T>::Zero();      // Λ
};

// J·v = dC/dt = v2 + w2 × r2 − v1 − w1 × r1 with world lever arms r1, r2, for
// invariant checks: zero after a velocity solve.
template <class T>
Vec3<T> PointVelocityError(const Body<T>& body1, const Vec3<T>& r1, const Body<T>& body2,
                           const Vec3<T>& r2) {
  return body2.LinearVelocity() + body2.AngularVelocity().cross(r2) - body1.LinearVelocity() -
         body1.AngularVelocity().cross(r1);
}

}  // namespace manyworlds::reference
