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
// principal axes in body space. The allowed-DOF masks are Body's (reference/body.h).
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

// ---------------------------------------------------------------------------
// Helpers added with the axis/angle/point/rotation/hinge/gear/independent-axis/
// swing-twist reference parts (spec 2.4-2.12 and 5). General maths only.
// ---------------------------------------------------------------------------

// [v]×: the matrix with [v]× w = v × w.
template <class T>
Mat33<T> CrossProductMatrix(const Vec3<T>& v) {
  Mat33<T> m;
  m << T(0), -v.z(), v.y(),  //
      v.z(), T(0), -v.x(),   //
      -v.y(), v.x(), T(0);
  return m;
}

// q or −q, whichever has w >= 0 (Jolt's EnsureWPositive: w == 0 keeps q). Both
// describe the same rotation; w >= 0 is the one of angle <= π.
template <class T>
Quat<T> EnsureWPositive(const Quat<T>& q) {
  return q.w() >= T(0) ? q : Quat<T>(-q.w(), -q.x(), -q.y(), -q.z());
}

// A unit vector perpendicular to unit v, chosen as Jolt's GetNormalizedPerpendicular
// (spec 2.5): zero the smaller of |x|, |y| and swap the other with z:
//   |x| > |y|:  (z, 0, −x) / √(x² + z²)      else:  (0, z, −y) / √(y² + z²)
template <class T>
Vec3<T> NormalizedPerpendicular(const Vec3<T>& v) {
  if (std::abs(v.x()) > std::abs(v.y())) {
    return Vec3<T>(v.z(), T(0), -v.x()) / std::sqrt(v.x() * v.x() + v.z() * v.z());
  }
  return Vec3<T>(T(0), v.z(), -v.y()) / std::sqrt(v.y() * v.y() + v.z() * v.z());
}

// Rotation angle of q about a unit axis, assuming q rotates about that axis (spec 3,
// Hinge): 2·atan((xyz·axis)/w) in (−π, π], and π when w == 0 (Jolt's
// GetRotationAngle). libm atan, not Jolt's polynomial.
template <class T>
T QuatRotationAngle(const Quat<T>& q, const Vec3<T>& axis) {
  if (q.w() == T(0)) return std::numbers::pi_v<T>;
  return T(2) * std::atan(q.vec().dot(axis) / q.w());
}

// The twist of q about a unit axis: the rotation about the axis closest to q,
// normalize(axis·(xyz·axis), w); identity when that is zero (spec 5, GetTwist).
template <class T>
Quat<T> QuatTwist(const Quat<T>& q, const Vec3<T>& axis) {
  const Vec3<T> twist_axis = axis * q.vec().dot(axis);
  const Quat<T> twist(q.w(), twist_axis.x(), twist_axis.y(), twist_axis.z());
  const T length_squared = twist.squaredNorm();
  if (length_squared == T(0)) return Quat<T>::Identity();
  return Quat<T>(twist.coeffs() / std::sqrt(length_squared));
}

// q = swing·twist with twist about X (y = z = 0) and swing about an axis in the YZ
// plane (x = 0) (spec 2.12, Jolt's GetSwingTwist). With s = √(w² + x²):
//   twist = (x/s, 0, 0, w/s),   swing = (0, (wy − xz)/s, (wz + xy)/s, s)    [xyz, w]
// (expanding swing·twist gives back q). s == 0 is a half turn about an axis in the
// YZ plane: twist = identity, swing = q. swing.w = s >= 0 otherwise.
template <class T>
struct SwingTwist {
  Quat<T> swing;
  Quat<T> twist;
};

template <class T>
SwingTwist<T> DecomposeSwingTwist(const Quat<T>& q) {
  const T x = q.x(), y = q.y(), z = q.z(), w = q.w();
  const T s = std::sqrt(w * w + x * x);
  if (s == T(0)) return {q, Quat<T>::Identity()};
  return {Quat<T>(s, T(0), (w * y - x * z) / s, (w * z + x * y) / s),
          Quat<T>(w / s, x / s, T(0), T(0))};
}

// Axis-aligned ellipse (x/a)² + (y/b)² = 1, a, b > 0 (spec 2.12, cone swing limit).
template <class T>
bool EllipseIsInside(T a, T b, const Vec2<T>& point) {
  return (point.x() / a) * (point.x() / a) + (point.y() / b) * (point.y() / b) <= T(1);
}

// Closest point on the ellipse to `point` (meant for points outside it).
// The closest point c satisfies point − c = t·(c.x/a², c.y/b²) for some t >= 0 (the
// difference is along the normal), so c = (a²·px/(t + a²), b²·py/(t + b²)), and c on
// the ellipse means
//   g(t) = (a·px/(t + a²))² + (b·py/(t + b²))² − 1 = 0,
//   g'(t) = −2·(a²px²/(t + a²)³ + b²py²/(t + b²)³).
// Newton from t = 0 (g is decreasing and convex there, so it converges monotonically
// from an outside point). Jolt loops in float without a cap until |g| < 1e-6; the
// reference iterates IN DOUBLE whatever T is, with the same stop rule |g| < 1e-6 and
// a generous cap of 100 iterations (never reached in practice; asserted). The number
// of Newton steps taken goes to *iterations if given.
template <class T>
Vec2<T> EllipseClosestPoint(T a, T b, const Vec2<T>& point, int* iterations = nullptr) {
  assert(a > T(0) && b > T(0));
  const double ad = double(a), bd = double(b);
  const double px = double(point.x()), py = double(point.y());
  const double a_sq = ad * ad, b_sq = bd * bd;
  double t = 0.0;
  int steps = 0;
  for (;; ++steps) {
    const double t_plus_a_sq = t + a_sq;
    const double t_plus_b_sq = t + b_sq;
    const double gx = ad * px / t_plus_a_sq;
    const double gy = bd * py / t_plus_b_sq;
    const double g = gx * gx + gy * gy - 1.0;
    if (std::abs(g) < 1e-6 || steps == 100) {
      assert(std::abs(g) < 1e-6 && "ellipse closest point did not converge in 100 steps");
      if (iterations != nullptr) *iterations = steps;
      return Vec2<T>(T(a_sq * px / t_plus_a_sq), T(b_sq * py / t_plus_b_sq));
    }
    const double dg = -2.0 * (a_sq * px * px / (t_plus_a_sq * t_plus_a_sq * t_plus_a_sq) +
                              b_sq * py * py / (t_plus_b_sq * t_plus_b_sq * t_plus_b_sq));
    t -= g / dg;
  }
}

// ---------------------------------------------------------------------------

}  // namespace manyworlds::reference
