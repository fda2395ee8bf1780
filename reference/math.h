// One-world maths for the scalar reference: the test oracle for the SIMD kernels.
//
// Written straight from docs/jolt-constraint-parts.md (spec sections 1.2, 1.4, 4.3
// and 5), templated on the scalar so tests can run the same code in float (to
// compare with the kernels) and in double (to check the kernels' invariants
// against a more exact answer). Clarity over speed: no early-outs beyond those the
// spec makes part of the behaviour.
#pragma once

#include <Eigen/Dense>
#include <Eigen/Geometry>

#include <cassert>
#include <cmath>
#include <numbers>

namespace manyworlds::reference {

template <class T>
using Vec2 = Eigen::Matrix<T, 2, 1>;
template <class T>
using Vec3 = Eigen::Matrix<T, 3, 1>;
template <class T>
using Mat22 = Eigen::Matrix<T, 2, 2>;
template <class T>
using Mat33 = Eigen::Matrix<T, 3, 3>;
template <class T>
using Quat = Eigen::Quaternion<T>;

// Rotation by `angle` radians about `unit_axis`: (axis·sin(angle/2), cos(angle/2)).
// Uses libm, not Jolt's polynomial SinCos, so it differs from Jolt in the last bits.
template <class T>
Quat<T> QuatFromAxisAngle(const Vec3<T>& unit_axis, T angle) {
  const T half = angle / T(2);
  const T s = std::sin(half);
  const T c = std::cos(half);
  return Quat<T>(c, unit_axis.x() * s, unit_axis.y() * s, unit_axis.z() * s);
}

// World-space inverse inertia I^-1 = (R_q R_I) diag(D) (R_q R_I)^T (spec 4.3).
// `rotation` is the body's orientation, `inertia_rotation` the rotation of its
// principal axes in body space. No DOF masks exist in this project yet.
template <class T>
Mat33<T> WorldInverseInertia(const Quat<T>& rotation, const Quat<T>& inertia_rotation,
                             const Vec3<T>& inv_inertia_diagonal) {
  const Mat33<T> r = rotation.toRotationMatrix() * inertia_rotation.toRotationMatrix();
  return r * inv_inertia_diagonal.asDiagonal() * r.transpose();
}

// I^-1 v in vector form (spec 1.4): rotate v into inertia space by (q q_I)^-1,
// scale by D, rotate back. Same maths as WorldInverseInertia(...) * v; the parts
// without rotation matrices in their signature (Axis, Angle, RackAndPinion, ...)
// use this form. q and q_I are unit, so the inverse is the conjugate.
template <class T>
Vec3<T> MultiplyWorldInverseInertia(const Quat<T>& rotation, const Quat<T>& inertia_rotation,
                                    const Vec3<T>& inv_inertia_diagonal, const Vec3<T>& v) {
  const Quat<T> to_world = rotation * inertia_rotation;
  const Vec3<T> in_inertia_space = to_world.conjugate() * v;
  const Vec3<T> scaled = inv_inertia_diagonal.cwiseProduct(in_inertia_space);
  return to_world * scaled;
}

// Rotates q by the rotation vector theta (spec 1.2): the increment is rebuilt from
// axis and angle and the result renormalised; increments of 1e-6 rad or less are
// dropped entirely (this is behaviour, not an optimisation: it changes q).
template <class T>
void AddRotationStep(Quat<T>& q, const Vec3<T>& theta) {
  const T angle = theta.norm();
  if (angle > T(1e-6)) {
    const Vec3<T> axis = theta / angle;
    q = (QuatFromAxisAngle(axis, angle) * q).normalized();
  }
}

// Closed-form 2x2 inverse (spec 2.3, 5). K of a two-row part is symmetric in exact
// arithmetic, but the reference builds every entry from the formula, so the
// off-diagonals may differ by rounding; the general formula handles both.
// Jolt computes det with an FMA-compensated DifferenceOfProducts; here it is the
// plain product difference in T (double makes the difference immaterial).
// det == 0 exactly => false with `inverse` zero (the caller deactivates); there is
// no conditioning threshold, nearly singular matrices are inverted as they are.
template <class T>
bool InvertSymmetricOr2x2(const Mat22<T>& k, Mat22<T>& inverse) {
  const T det = k(0, 0) * k(1, 1) - k(0, 1) * k(1, 0);
  if (det == T(0)) {
    inverse.setZero();
    return false;
  }
  const T inv_det = T(1) / det;
  inverse(0, 0) = k(1, 1) * inv_det;
  inverse(0, 1) = -k(0, 1) * inv_det;
  inverse(1, 0) = -k(1, 0) * inv_det;
  inverse(1, 1) = k(0, 0) * inv_det;
  return true;
}

// 3x3 inverse by adjugate / det, det = c0·(c1×c2) for columns c0, c1, c2 (spec 5).
// The rows of the inverse are (c1×c2, c2×c0, c0×c1) / det: row i dotted with
// column j is det when i == j and a triple product with a repeated vector (0)
// otherwise. det == 0 exactly => false with `inverse` zero.
template <class T>
bool Invert3x3(const Mat33<T>& k, Mat33<T>& inverse) {
  const Vec3<T> c0 = k.col(0);
  const Vec3<T> c1 = k.col(1);
  const Vec3<T> c2 = k.col(2);
  const Vec3<T> c1xc2 = c1.cross(c2);
  const T det = c0.dot(c1xc2);
  if (det == T(0)) {
    inverse.setZero();
    return false;
  }
  const T inv_det = T(1) / det;
  inverse.row(0) = c1xc2.transpose() * inv_det;
  inverse.row(1) = c2.cross(c0).transpose() * inv_det;
  inverse.row(2) = c0.cross(c1).transpose() * inv_det;
  return true;
}

// Folds an angle into [-pi, pi] by whole turns (spec 5, "Angle wrap-around").
// The loop mirrors the spec; the SIMD kernels use a branch-free fold instead.
template <class T>
T CenterAngleAroundZero(T angle) {
  assert(std::isfinite(angle));  // an infinite angle would never leave the loop
  constexpr T kPi = std::numbers::pi_v<T>;
  constexpr T kTwoPi = T(2) * std::numbers::pi_v<T>;
  while (angle < -kPi) angle += kTwoPi;
  while (angle > kPi) angle -= kTwoPi;
  return angle;
}

}  // namespace manyworlds::reference
