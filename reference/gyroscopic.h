// The opt-in gyroscopic step (StepSettings::gyroscopic), scalar reference.
//
// Jolt's default integration keeps the world angular velocity w of a free
// body constant between constraint impulses: it leaves out Euler's term
// -w x (I w). A body spinning about a non-principal axis then keeps turning
// about that world axis instead of precessing, and the intermediate-axis flip
// (Dzhanibekov effect) never happens (docs/stability.md, spin-unstable).
//
// The remedy, once per substep before gravity and forces (where Jolt's own
// optional term sits, spec 4.1 step 1), for every dynamic body whose
// rotation is not restricted by allowed DOFs: in the principal frame
// P = R_q R_I, with w0 = P^T w and I = diag(1 / D), solve Euler's torque-free
// equations by the implicit midpoint rule
//
//   g(w1) = I (w1 - w0) + h wm x (I wm) = 0,   wm = (w0 + w1) / 2,
//
// which keeps both quadratic invariants of the exact motion, the kinetic
// energy w.I w and |I w| (dot g with wm and with I wm: the cross term
// vanishes), so a spin neither gains nor loses energy and the orbit of w in
// the body frame, hence the flip, is reproduced. Two Newton steps from
// w1 = w0, with the Jacobian
//
//   J = I + h/2 (S(wm) I - S(I wm)),   S(a) b = a x b,
//
// and J^-1 g from the cross products of J's rows (J^-1 = [r1 x r2, r2 x r0,
// r0 x r1] / det, det = r0.(r1 x r2)). Two steps converge to float rounding
// while h|w| is small against the inertia ratios; for large h|w| Newton may
// stop short or J may turn singular, so, to stay stable for any step:
//   - a lane where det <= 0 in either Newton step keeps w0 (Jolt's default);
//   - the result is rescaled to the energy of w0, w1 *= sqrt(w0.I w0 / w1.I w1),
//     so the gyroscopic step can never add energy, |w| stays below
//     sqrt(w0.I w0 / I_min), and a step that stopped short errs only in
//     direction.
// Bodies with restricted rotation DOFs are skipped: their inverse inertia is
// masked in world axes, which has no body-frame inertia to take Euler's term
// from.
#pragma once

#include <cmath>

#include "reference/body.h"
#include "reference/math.h"

namespace manyworlds::reference {

template <class T>
void ApplyGyroscopicStep(Body<T>& body, T h) {
  if (body.rotation_mask != Vec3<T>::Ones()) return;
  const Quat<T> to_world = body.rotation * body.inertia_rotation;
  const Vec3<T> w0 = to_world.conjugate() * body.angular_velocity;
  const Vec3<T> inertia = body.inv_inertia_diagonal.cwiseInverse();
  const auto skew = [](const Vec3<T>& a) {
    Mat33<T> s;
    s << T(0), -a.z(), a.y(), a.z(), T(0), -a.x(), -a.y(), a.x(), T(0);
    return s;
  };
  Vec3<T> w1 = w0;
  for (int newton = 0; newton < 2; ++newton) {
    const Vec3<T> wm = T(0.5) * (w0 + w1);
    const Vec3<T> iwm = inertia.cwiseProduct(wm);
    const Vec3<T> g = inertia.cwiseProduct(w1 - w0) + h * wm.cross(iwm);
    const Mat33<T> j = Mat33<T>(inertia.asDiagonal()) +
                       T(0.5) * h * (skew(wm) * inertia.asDiagonal() - skew(iwm));
    const Vec3<T> r0 = j.row(0).transpose(), r1 = j.row(1).transpose(),
                  r2 = j.row(2).transpose();
    const Vec3<T> c0 = r1.cross(r2), c1 = r2.cross(r0), c2 = r0.cross(r1);
    const T det = r0.dot(c0);
    if (!(det > T(0))) return;  // keep w0
    w1 -= (c0 * g.x() + c1 * g.y() + c2 * g.z()) / det;
  }
  const T energy0 = w0.dot(inertia.cwiseProduct(w0));
  const T energy1 = w1.dot(inertia.cwiseProduct(w1));
  if (!(energy1 > T(0)) || !std::isfinite(energy1)) return;
  w1 *= std::sqrt(energy0 / energy1);
  body.angular_velocity = to_world * w1;
}

}  // namespace manyworlds::reference
