// Shared pieces of the three-row part tests (point, rotation Euler, rotation
// quaternion): 3x3 matrices read from lanes, rest rotations near the current
// one, exactly representable rotations, and quaternion comparison up to sign.
#pragma once

#include <gtest/gtest.h>

#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "manyworlds/body_state.h"
#include "manyworlds/lanes.h"
#include "tests/test_support.h"

namespace manyworlds::testing {

inline Mat33d LaneMat33(const Mat33Lanes& m, std::size_t lane) {
  Mat33d out;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) out(i, j) = m.m[i][j][lane];
  }
  return out;
}

// A symmetric matrix stored as its upper triangle, as a full matrix (so each
// stored entry is compared with both mirrored entries of the reference).
inline Mat33d LaneSym33(const Sym33Lanes& s, std::size_t lane) {
  Mat33d out;
  out << s.xx[lane], s.xy[lane], s.xz[lane],  //
      s.xy[lane], s.yy[lane], s.yz[lane],     //
      s.xz[lane], s.yz[lane], s.zz[lane];
  return out;
}

inline void ExpectMat33Near(const Mat33d& actual, const Mat33d& expected, double tolerance,
                            const std::string& label) {
  EXPECT_LE((actual - expected).cwiseAbs().maxCoeff(), tolerance)
      << label << ": kernel\n" << actual << "\nvs reference\n" << expected;
}

// q and -q are the same rotation; helpers that build a rest rotation from
// frames may pick either sign.
inline void ExpectSameRotation(const Quatd& actual, const Quatd& expected, double tolerance,
                               const std::string& label) {
  const double same = (actual.coeffs() - expected.coeffs()).cwiseAbs().maxCoeff();
  const double flipped = (actual.coeffs() + expected.coeffs()).cwiseAbs().maxCoeff();
  EXPECT_LE(std::min(same, flipped), tolerance)
      << label << ": kernel (" << actual.coeffs().transpose() << ") vs reference ("
      << expected.coeffs().transpose() << ")";
}

inline std::array<float, 4> ToFloat4(const Quatd& q) {
  return {float(q.x()), float(q.y()), float(q.z()), float(q.w())};
}

// r0^-1 such that the error rotation q2 r0^-1 q1* is a random rotation of up
// to `max_angle` rad (q2 = q1 r0 would be at rest), with a random overall sign
// (so that the w >= 0 rule of the rotation-Euler error is exercised).
inline Quatd NearRestInverseInitialOrientation(Random& random, const Quatd& q1,
                                               const Quatd& q2, double max_angle) {
  const Quatd error(Eigen::AngleAxisd(random.Uniform(0, max_angle), random.UnitVector()));
  const Quatd r0_inv = q2.conjugate() * error * q1;
  return random.Uniform(0, 1) < 0.5 ? r0_inv : Quatd(-r0_inv.coeffs());
}

// The 12 rotations of the tetrahedral group: every component is 0, +-1/2 or
// +-1, so products and rotation matrices are exact in float, and a principal
// axis of the inertia maps exactly onto a world axis (locked rotations).
inline Quatd ExactRotation(Random& random) {
  static const std::array<Quatd, 12> rotations = {
      Quatd(1, 0, 0, 0),           Quatd(0, 1, 0, 0),           Quatd(0, 0, 1, 0),
      Quatd(0, 0, 0, 1),           Quatd(0.5, 0.5, 0.5, 0.5),   Quatd(0.5, -0.5, 0.5, 0.5),
      Quatd(0.5, 0.5, -0.5, 0.5),  Quatd(0.5, 0.5, 0.5, -0.5),  Quatd(0.5, -0.5, -0.5, 0.5),
      Quatd(0.5, -0.5, 0.5, -0.5), Quatd(0.5, 0.5, -0.5, -0.5), Quatd(0.5, -0.5, -0.5, -0.5)};
  return rotations[std::size_t(random.Uniform(0, 12)) % 12];
}

// Locks a body's rotation about the given world axes: its rotation and
// inertia rotation become exact, and the principal inverse inertias that map
// onto those axes become 0, so its world inverse inertia has exactly zero
// rows and columns there.
inline void LockRotationAbout(const std::vector<int>& world_axes, Random& random,
                              BodyState& body) {
  const Quatd rotation = ExactRotation(random), inertia_rotation = ExactRotation(random);
  body.rotation = ToFloat4(rotation);
  body.inertia_rotation = ToFloat4(inertia_rotation);
  const Mat33d r = (rotation * inertia_rotation).toRotationMatrix();
  for (const int axis : world_axes) {
    for (int principal = 0; principal < 3; ++principal) {
      if (r(axis, principal) != 0.0) body.inv_inertia_diagonal[principal] = 0.0f;
    }
  }
}

}  // namespace manyworlds::testing
