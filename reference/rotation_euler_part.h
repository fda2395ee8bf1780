// RotationEulerPart: fixes the rotation of body 2 relative to body 1, removing
// three angular degrees of freedom (spec 2.6; fixed, slider, six-DOF, path, and the
// position step of swing-twist). Scalar reference, written from the formulas.
//
// Reference orientation: r0 with q2 = q1·r0 at rest; the part stores nothing of it,
// callers pass r0⁻¹ ("inverse initial orientation", helpers below).
//
// Position-level error (small-angle form of the rotation vector of the difference):
//
//   diff = q2·r0⁻¹·q1*   (identity at rest),   diff := EnsureWPositive(diff),
//   C = 2·diff.xyz
//
// Forcing w >= 0 takes the shorter way round (the whole quaternion is negated).
//
// Jacobian and inverse effective mass (d/dt diff ≈ ½(w2 − w1)·diff near rest):
//
//   J = [ 0, −E, 0, E ],   K = I1⁻¹ + I2⁻¹   (inertia only of dynamic bodies, 1.5)
//
// Inversion: 3×3 adjugate / det. If det == 0, every all-zero column of K is replaced
// by the matching identity column and the inverse retried: a rotation axis locked on
// both bodies then gets a finite effective mass, and stays locked because every
// impulse is multiplied by I⁻¹, which is zero on that axis (Jolt commit b385bc3d,
// test TestSixDOFLockedRotation). Still singular ⇒ Deactivate.
//
// Velocity step (spec 1.1): Δλ = −K⁻¹ J·v = K⁻¹(w1 − w2); Λ += Δλ;
//   w1 −= I1⁻¹Δλ,  w2 += I2⁻¹Δλ            (dynamic bodies only).
//
// Position step (spec 1.2): C from the CURRENT rotations and the caller's r0⁻¹; if
// C != 0: λ = −β K⁻¹ C, body 1 rotates by −I1⁻¹λ, body 2 by +I2⁻¹λ. Callers
// recompute the properties first.
//
// API decision (as DualAxisPart): Jolt passes rotation matrices for the inertia;
// constraints always pass the current rotations, so they come from the bodies.
#pragma once

#include "reference/body.h"
#include "reference/math.h"

namespace manyworlds::reference {

// ---- r0⁻¹ helpers (spec 2.6) ----

// From the bodies as they are now: q2 = q1·r0 ⇒ r0⁻¹ = q2*·q1.
template <class T>
Quat<T> InvInitialOrientation(const Body<T>& body1, const Body<T>& body2) {
  return body2.rotation.conjugate() * body1.rotation;
}

// From constraint frames given in each body's space. Frame i = rotation C_i whose
// columns are the frame axes; at rest the world frames coincide, q1·C1 = q2·C2, so
// r0 = C1·C2* and r0⁻¹ = C2·C1*. Equal frames give exactly the identity.
// X and Y axes given (Z = X × Y):
template <class T>
Quat<T> InvInitialOrientationXY(const Vec3<T>& axis_x1, const Vec3<T>& axis_y1,
                                const Vec3<T>& axis_x2, const Vec3<T>& axis_y2) {
  if (axis_x1 == axis_x2 && axis_y1 == axis_y2) return Quat<T>::Identity();
  Mat33<T> frame1, frame2;
  frame1 << axis_x1, axis_y1, axis_x1.cross(axis_y1);
  frame2 << axis_x2, axis_y2, axis_x2.cross(axis_y2);
  return Quat<T>(frame2) * Quat<T>(frame1).conjugate();
}

// X and Z axes given (Y = Z × X):
template <class T>
Quat<T> InvInitialOrientationXZ(const Vec3<T>& axis_x1, const Vec3<T>& axis_z1,
                                const Vec3<T>& axis_x2, const Vec3<T>& axis_z2) {
  if (axis_x1 == axis_x2 && axis_z1 == axis_z2) return Quat<T>::Identity();
  Mat33<T> frame1, frame2;
  frame1 << axis_x1, axis_z1.cross(axis_x1), axis_z1;
  frame2 << axis_x2, axis_z2.cross(axis_x2), axis_z2;
  return Quat<T>(frame2) * Quat<T>(frame1).conjugate();
}

// Frames given in world space at creation time (body rotations q10, q20): the
// body-space frames are q_i0*·W_i, so r0⁻¹ = q20*·(W2·W1*)·q10. `world_space` is the
// r0⁻¹ computed from the world-space axes.
template <class T>
Quat<T> InvInitialOrientationFromWorldSpace(const Quat<T>& world_space,
                                            const Quat<T>& rotation1_at_creation,
                                            const Quat<T>& rotation2_at_creation) {
  return rotation2_at_creation.conjugate() * world_space * rotation1_at_creation;
}

// C = 2·xyz(EnsureWPositive(q2·r0⁻¹·q1*)) from the bodies' current rotations.
template <class T>
Vec3<T> RotationEulerPositionError(const Body<T>& body1, const Body<T>& body2,
                                   const Quat<T>& inv_initial_orientation) {
  const Quat<T> diff = EnsureWPositive(Quat<T>(
      body2.rotation * inv_initial_orientation * body1.rotation.conjugate()));
  return T(2) * diff.vec();
}

template <class T>
class RotationEulerPart {
 public:
  // Inertia (matrix form) from each body's current rotation; zero unless dynamic.
  void CalculateConstraintProperties(const Body<T>& body1, const Body<T>& body2) {
    inv_i1_ = body1.IsDynamic() ? body1.InverseInertia() : Mat33<T>::Zero();
    inv_i2_ = body2.IsDynamic() ? body2.InverseInertia() : Mat33<T>::Zero();
    Mat33<T> k = inv_i1_ + inv_i2_;
    if (Invert3x3(k, effective_mass_)) return;
    // Locked rotation axes: identity columns for all-zero columns, then retry.
    for (int column = 0; column < 3; ++column) {
      if (k.col(column).isZero(T(0))) k.col(column) = Vec3<T>::Unit(column);
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
    const Vec3<T> delta_lambda =
        effective_mass_ * (body1.AngularVelocity() - body2.AngularVelocity());
    total_lambda_ += delta_lambda;
    return ApplyVelocityStep(body1, body2, delta_lambda);
  }

  // Baumgarte step towards q2 = q1·r0; true iff C != 0 (then a step was taken).
  bool SolvePositionConstraint(Body<T>& body1, Body<T>& body2,
                               const Quat<T>& inv_initial_orientation, T baumgarte) const {
    const Vec3<T> c = RotationEulerPositionError(body1, body2, inv_initial_orientation);
    if (c.isZero(T(0))) return false;
    const Vec3<T> lambda = -baumgarte * (effective_mass_ * c);
    if (body1.IsDynamic()) body1.SubRotationStep(inv_i1_ * lambda);
    if (body2.IsDynamic()) body2.AddRotationStep(inv_i2_ * lambda);
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
  const Mat33<T>& EffectiveMass() const { return effective_mass_; }  // K⁻¹ (after the fix)
  const Mat33<T>& InvI1() const { return inv_i1_; }
  const Mat33<T>& InvI2() const { return inv_i2_; }

 private:
  // w += I⁻¹ Jᵀ λ for dynamic bodies; true iff any component of λ is non-zero.
  bool ApplyVelocityStep(Body<T>& body1, Body<T>& body2, const Vec3<T>& lambda) const {
    if (body1.IsDynamic()) body1.angular_velocity -= inv_i1_ * lambda;
    if (body2.IsDynamic()) body2.angular_velocity += inv_i2_ * lambda;
    return !lambda.isZero(T(0));
  }

  Mat33<T> inv_i1_ = Mat33<T>::Zero();          // I1⁻¹ (zero unless dynamic)
  Mat33<T> inv_i2_ = Mat33<T>::Zero();          // I2⁻¹
  Mat33<T> effective_mass_ = Mat33<T>::Zero();  // K⁻¹
  Vec3<T> total_lambda_ = Vec3<T>::Zero();      // Λ
};

// J·v = dC/dt = w2 − w1, for invariant checks: zero after a velocity solve (on the
// axes the bodies can rotate about; a locked axis keeps its velocity).
template <class T>
Vec3<T> RotationEulerVelocityError(const Body<T>& body1, const Body<T>& body2) {
  return body2.AngularVelocity() - body1.AngularVelocity();
}

}  // namespace manyworlds::reference
