// Lane maths (kernels/lane_math-inl.h, exported as LaneMathKernels of every
// kernel table), lane by lane against libm, Eigen in double and
// reference/math.h, on every Highway target this CPU supports. Inputs differ
// in every lane; every lane of several blocks is checked.
#include <gtest/gtest.h>

#include <Eigen/SVD>
#include <algorithm>
#include <array>
#include <cfloat>
#include <cmath>
#include <cstring>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "kernels/body_lanes.h"
#include "kernels/lane_math.h"
#include "manyworlds/lanes.h"
#include "reference/math.h"
#include "tests/test_support.h"

namespace manyworlds::testing {
namespace {

constexpr int kBlocks = 64;  // blocks of random lanes per test
constexpr double kPi = std::numbers::pi;

class LaneMathTest : public ::testing::TestWithParam<const LaneMathKernels*> {
 protected:
  const LaneMathKernels& Kernels() const { return *GetParam(); }
};

std::string LaneLabel(const std::string& what, std::size_t block, std::size_t lane) {
  return what + ", lane " + std::to_string(lane) + " of block " + std::to_string(block);
}

std::string Precise(double value) {
  std::ostringstream out;
  out.precision(17);
  out << value;
  return out.str();
}

// A unit quaternion as a block stores it: rounded to float and renormalised
// in float (the same rule as RandomBodyState), read back exactly in double.
Quatd FloatUnitQuat(Random& random) {
  const Quatd q = random.Rotation();
  const float norm = std::sqrt(float(q.x() * q.x() + q.y() * q.y() +
                                     q.z() * q.z() + q.w() * q.w()));
  return Quatd(float(q.w()) / norm, float(q.x()) / norm, float(q.y()) / norm,
               float(q.z()) / norm);
}

bool LaneBitsEqual(const QuatLanes& a, const QuatLanes& b, std::size_t lane) {
  return BitEqual(&a.x.lanes[lane], &b.x.lanes[lane], sizeof(float)) &&
         BitEqual(&a.y.lanes[lane], &b.y.lanes[lane], sizeof(float)) &&
         BitEqual(&a.z.lanes[lane], &b.z.lanes[lane], sizeof(float)) &&
         BitEqual(&a.w.lanes[lane], &b.w.lanes[lane], sizeof(float));
}

// ------------------------------------------------------------------ sin/cos

// Bound on |kernel - libm(x)| for sin and cos of an exact float x, |x| <= 8000.
// The reference is std::sin/std::cos in double of the float input itself, so
// the 0.5 ulp(x) uncertainty of x does not enter. What remains:
//  - range reduction y = x - q pi/2 with q = round(x 2/pi) <= 5093: the first
//    two Cody-Waite products are exact (8 and 11 significant bits times
//    q < 2^13) and pi/2 - (C1 + C2 + C3) ~ 1e-15 is negligible, so y
//    (|y| <= pi/4 + tiny) carries two roundings of at most 0.5 ulp(pi/4) =
//    FLT_EPSILON/4 each;
//  - the degree-7/8 minimax polynomials on [-pi/4, pi/4] (relative error ~1e-8,
//    below FLT_EPSILON/8) evaluated in float: about one rounding of a result
//    <= 1, i.e. <= FLT_EPSILON/2, a little more without FMA.
// Hence 2 ulp of 1 = 2 * FLT_EPSILON absolute (the kernel's documented
// accuracy); a wrong quadrant or sign is an error of order 1.
constexpr double kSinCosBound = 2.0 * FLT_EPSILON;

// Special values, multiples of pi/2 (quadrant boundaries, where sin or cos of
// the float value is tiny), odd multiples of pi/4 (where the reduction picks
// between two quadrants) and uniform random values in [-1000, 1000] (plus
// some in [-8000, 8000]).
std::vector<float> SinCosInputs() {
  const float pi = float(kPi);
  std::vector<float> x = {0.0f,    -0.0f,    1e-8f,        -1e-8f,        pi / 4,
                          -pi / 4, pi / 2,   -pi / 2,      pi,            -pi,
                          3 * pi / 4, -3 * pi / 4, 100.0f, -100.0f,   1000.0f,
                          -1000.0f, FLT_MIN, -FLT_MIN};
  for (int k = -64; k <= 64; ++k) x.push_back(float(k * kPi / 2));  // |x| <= 100.5
  for (int k = -637; k <= 636; ++k) x.push_back(float((k + 0.5) * kPi / 2));
  Random random(20240601u);
  while (x.size() % kLaneWidth != 0 || x.size() < 160000) {
    x.push_back(float(random.Uniform(-1000.0, 1000.0)));
  }
  // The kernel documents an exact reduction up to |x| ~ 8000 (q < 2^13 keeps
  // the first two Cody-Waite products exact), so the same bound must hold.
  for (int i = 0; i < 40000; ++i) x.push_back(float(random.Uniform(-8000.0, 8000.0)));
  return x;
}

TEST_P(LaneMathTest, SinCosMatchesLibmWithinTwoUlpOfOne) {
  const std::vector<float> inputs = SinCosInputs();
  double max_sin_error = 0, max_cos_error = 0;
  for (std::size_t block = 0; block * kLaneWidth < inputs.size(); ++block) {
    LaneArray x, sin, cos;
    for (std::size_t lane = 0; lane < kLaneWidth; ++lane) {
      x[lane] = inputs[block * kLaneWidth + lane];
    }
    Kernels().sin_cos(x, sin, cos);
    for (std::size_t lane = 0; lane < kLaneWidth; ++lane) {
      const double xd = x[lane];
      const double expected_sin = std::sin(xd), expected_cos = std::cos(xd);
      const double sin_error = std::abs(sin[lane] - expected_sin);
      const double cos_error = std::abs(cos[lane] - expected_cos);
      max_sin_error = std::max(max_sin_error, sin_error);
      max_cos_error = std::max(max_cos_error, cos_error);
      const std::string label = LaneLabel("x = " + Precise(xd), block, lane);
      // Absolute bound, scale 1 (|sin|, |cos| <= 1): see kSinCosBound.
      EXPECT_LE(sin_error, kSinCosBound)
          << label << ": sin " << Precise(sin[lane]) << " vs " << Precise(expected_sin);
      EXPECT_LE(cos_error, kSinCosBound)
          << label << ": cos " << Precise(cos[lane]) << " vs " << Precise(expected_cos);
      if (std::abs(xd) <= kPi / 4) {
        // No reduction (q = 0, y = x exactly): sin is relatively accurate,
        // scale |sin x| (catches sin(1e-8) returned as 0, which the absolute
        // bound would accept). 2 FLT_EPSILON relative covers the polynomial's
        // few roundings.
        EXPECT_LE(sin_error, 2.0 * FLT_EPSILON * std::abs(expected_sin))
            << label << ": relative error of sin " << Precise(sin[lane]) << " vs "
            << Precise(expected_sin);
      }
      if (xd == 0.0) {
        // sin(+-0) = +-0 and cos(0) = 1 exactly.
        EXPECT_EQ(sin[lane], 0.0f) << label;
        EXPECT_EQ(std::signbit(sin[lane]), std::signbit(x[lane])) << label << ": sign of sin(0)";
        EXPECT_EQ(cos[lane], 1.0f) << label;
      }
    }
  }
  RecordProperty("max_sin_error_in_flt_epsilon", std::to_string(max_sin_error / FLT_EPSILON));
  RecordProperty("max_cos_error_in_flt_epsilon", std::to_string(max_cos_error / FLT_EPSILON));
}

// NaN and infinite angles (a world whose state went bad) give NaN in that
// lane only. Under UBSan this also checks that no lane converts NaN to int
// (undefined behaviour on the SCALAR target, found by scripts/test-sanitizers).
TEST_P(LaneMathTest, SinCosOfNonFiniteLanesIsNaNAndLeavesOtherLanesAlone) {
  LaneArray x, sin, cos;
  for (std::size_t lane = 0; lane < kLaneWidth; ++lane) x[lane] = 0.25f * float(lane);
  x[0] = NAN;
  x[5] = INFINITY;
  x[kLaneWidth - 1] = -INFINITY;
  Kernels().sin_cos(x, sin, cos);
  for (std::size_t lane = 0; lane < kLaneWidth; ++lane) {
    if (std::isfinite(x[lane])) {
      EXPECT_NEAR(sin[lane], std::sin(double(x[lane])), kSinCosBound) << "lane " << lane;
      EXPECT_NEAR(cos[lane], std::cos(double(x[lane])), kSinCosBound) << "lane " << lane;
    } else {
      EXPECT_TRUE(std::isnan(sin[lane]) && std::isnan(cos[lane])) << "lane " << lane;
    }
  }
}

// -------------------------------------------------------------- 3-vectors

TEST_P(LaneMathTest, CrossAndDotMatchEigen) {
  Random random(101);
  for (std::size_t block = 0; block < kBlocks; ++block) {
    Vec3Lanes a, b, cross;
    LaneArray dot;
    for (std::size_t lane = 0; lane < kLaneWidth; ++lane) {
      const Vec3d va = random.UnitVector() * random.LogUniform(1e-3, 1e3);
      Vec3d vb = random.UnitVector() * random.LogUniform(1e-3, 1e3);
      // Every fourth lane: nearly parallel (cross product much smaller than
      // its terms), every fourth other lane nearly perpendicular.
      if (lane % 4 == 1) vb = va * random.Uniform(-3, 3) + random.Vector(1e-4 * va.norm());
      if (lane % 4 == 2) vb = random.Perpendicular(va.normalized()) * random.LogUniform(1e-3, 1e3);
      SetLaneVec3(a, lane, va);
      SetLaneVec3(b, lane, vb);
    }
    Kernels().cross_dot(a, b, cross, dot);
    for (std::size_t lane = 0; lane < kLaneWidth; ++lane) {
      const Vec3d va = LaneVec3(a, lane), vb = LaneVec3(b, lane);
      // Scale |a||b|: bounds every product summed in a cross or dot component.
      const double tolerance = Tolerance(va.norm() * vb.norm());
      ExpectVec3Near(LaneVec3(cross, lane), va.cross(vb), tolerance,
                     LaneLabel("a x b", block, lane));
      EXPECT_NEAR(dot[lane], va.dot(vb), tolerance) << LaneLabel("a . b", block, lane);
    }
  }
}

// ------------------------------------------------------------- quaternions

TEST_P(LaneMathTest, QuatMultiplyMatchesEigenHamiltonProduct) {
  Random random(202);
  for (std::size_t block = 0; block < kBlocks; ++block) {
    QuatLanes a, b, product;
    for (std::size_t lane = 0; lane < kLaneWidth; ++lane) {
      // Not unit: the product is bilinear, so any size and sign must work.
      auto any_quat = [&] {
        return Quatd(random.Uniform(-2, 2), random.Uniform(-2, 2), random.Uniform(-2, 2),
                     random.Uniform(-2, 2));
      };
      SetLaneQuat(a, lane, lane % 2 ? any_quat() : FloatUnitQuat(random));
      SetLaneQuat(b, lane, any_quat());
    }
    Kernels().quat_multiply(a, b, product);
    for (std::size_t lane = 0; lane < kLaneWidth; ++lane) {
      const Quatd qa = LaneQuat(a, lane), qb = LaneQuat(b, lane);
      // Scale |a||b|: every term of a product component is bounded by it.
      ExpectQuatNear(LaneQuat(product, lane), qa * qb,
                     Tolerance(qa.norm() * qb.norm()), LaneLabel("a * b", block, lane));
    }
  }
}

TEST_P(LaneMathTest, QuatRotateAndInverseRotateMatchEigen) {
  Random random(303);
  for (std::size_t block = 0; block < kBlocks; ++block) {
    QuatLanes q;
    Vec3Lanes v, rotated, inverse_rotated;
    for (std::size_t lane = 0; lane < kLaneWidth; ++lane) {
      SetLaneQuat(q, lane, FloatUnitQuat(random));
      SetLaneVec3(v, lane, random.UnitVector() * random.LogUniform(1e-3, 1e3));
    }
    Kernels().quat_rotate(q, v, rotated, inverse_rotated);
    for (std::size_t lane = 0; lane < kLaneWidth; ++lane) {
      const Quatd qd = LaneQuat(q, lane);
      const Vec3d vd = LaneVec3(v, lane);
      // Scale |v| (a rotation preserves length; q is unit to float rounding).
      ExpectVec3Near(LaneVec3(rotated, lane), qd * vd, Tolerance(vd.norm()),
                     LaneLabel("q v q*", block, lane));
      ExpectVec3Near(LaneVec3(inverse_rotated, lane), qd.conjugate() * vd,
                     Tolerance(vd.norm()), LaneLabel("q* v q", block, lane));
    }
  }
}

TEST_P(LaneMathTest, QuatNormalizeMatchesEigen) {
  Random random(404);
  for (std::size_t block = 0; block < kBlocks; ++block) {
    QuatLanes q, normalized;
    for (std::size_t lane = 0; lane < kLaneWidth; ++lane) {
      const Quatd direction(random.Uniform(-1, 1), random.Uniform(-1, 1),
                            random.Uniform(-1, 1), random.Uniform(-1, 1));
      const double length = random.LogUniform(1e-3, 1e3);
      SetLaneQuat(q, lane, Quatd(direction.coeffs() * (length / direction.norm())));
    }
    Kernels().quat_normalize(q, normalized);
    for (std::size_t lane = 0; lane < kLaneWidth; ++lane) {
      // Scale 1: the result is a unit quaternion.
      ExpectQuatNear(LaneQuat(normalized, lane), LaneQuat(q, lane).normalized(),
                     Tolerance(1.0), LaneLabel("normalize(q)", block, lane));
    }
  }
}

// The twist about X, Y or Z against reference/math.h's QuatTwist in double,
// on random unit quaternions and, in some lanes, on quaternions with no
// component about the axis and w = 0 (a half turn about a perpendicular
// axis), where both give the identity.
TEST_P(LaneMathTest, TwistAboutAxisMatchesReference) {
  Random random(606);
  for (int axis = 0; axis < 3; ++axis) {
    for (std::size_t block = 0; block < kBlocks; ++block) {
      QuatLanes q, twist;
      for (std::size_t lane = 0; lane < kLaneWidth; ++lane) {
        Quatd value = FloatUnitQuat(random);
        if (lane % 5 == 4) {  // no twist at all: identity
          value.w() = 0;
          value.coeffs()[axis] = 0;
          value.normalize();
        }
        SetLaneQuat(q, lane, value);
      }
      Kernels().twist_about_axis(q, axis, twist);
      for (std::size_t lane = 0; lane < kLaneWidth; ++lane) {
        const Quatd expected = reference::QuatTwist(LaneQuat(q, lane), Vec3d(Vec3d::Unit(axis)));
        // Scale 1: a normalised 2-component quaternion, a few roundings.
        ExpectQuatNear(LaneQuat(twist, lane), expected, Tolerance(1.0),
                       LaneLabel("twist about axis " + std::to_string(axis), block, lane));
      }
    }
  }
}

TEST_P(LaneMathTest, QuatFromAxisAngleMatchesReference) {
  Random random(505);
  for (std::size_t block = 0; block < kBlocks; ++block) {
    Vec3Lanes axis;
    LaneArray angle;
    QuatLanes q;
    for (std::size_t lane = 0; lane < kLaneWidth; ++lane) {
      SetLaneVec3(axis, lane, random.UnitVector());
      // Small, moderate and large angles (half angles up to 1000: the range
      // the sin/cos test covers).
      angle[lane] = float(lane % 4 == 0   ? random.Uniform(-1e-3, 1e-3)
                          : lane % 4 == 3 ? random.Uniform(-2000, 2000)
                                          : random.Uniform(-2 * kPi, 2 * kPi));
    }
    Kernels().quat_from_axis_angle(axis, angle, q);
    for (std::size_t lane = 0; lane < kLaneWidth; ++lane) {
      const Quatd expected =
          reference::QuatFromAxisAngle<double>(LaneVec3(axis, lane), angle[lane]);
      // Scale 1: components are axis * sin and cos (angle / 2 is exact in float).
      ExpectQuatNear(LaneQuat(q, lane), expected, Tolerance(1.0),
                     LaneLabel("quat(axis, " + Precise(angle[lane]) + ")", block, lane));
    }
  }
}

// Lanes of AddRotationStep: below the 1e-6 threshold (q must stay
// bit-identical), just above it (q must change), moderate and large angles;
// and blocks of small angles only (up to 0.5 rad, the position corrections'
// range), so that a path taken only when no lane of a chunk is large would
// be tested too.
enum class StepKind { kTiny, kJustAbove, kModerate, kLarge, kSmallTaylor };

void CheckAddRotationStep(const LaneMathKernels& kernels, Random& random,
                          const std::array<StepKind, 4>& kind_of_lane_mod_4) {
  for (std::size_t block = 0; block < kBlocks; ++block) {
    QuatLanes q, before;
    Vec3Lanes theta;
    std::array<StepKind, kLaneWidth> kinds;
    for (std::size_t lane = 0; lane < kLaneWidth; ++lane) {
      kinds[lane] = kind_of_lane_mod_4[lane % 4];
      double length = 0;
      switch (kinds[lane]) {
        // Exactly zero in one lane per block, else up to 0.9e-6: clear of the
        // threshold after rounding to float.
        case StepKind::kTiny: length = lane == 0 ? 0.0 : random.Uniform(0, 0.9e-6); break;
        case StepKind::kJustAbove: length = random.Uniform(2e-6, 1e-5); break;
        case StepKind::kModerate: length = random.LogUniform(1e-3, 1.0); break;
        case StepKind::kLarge: length = random.LogUniform(1.0, 1000.0); break;
        // Up to 0.5 rad, which lane 3 of every block hits (to float
        // rounding, just below or above).
        case StepKind::kSmallTaylor:
          length = lane == 3 ? 0.5 : random.LogUniform(1e-5, 0.5);
          break;
      }
      SetLaneQuat(q, lane, FloatUnitQuat(random));
      SetLaneVec3(theta, lane, random.UnitVector() * length);
    }
    before = q;
    kernels.add_rotation_step(q, theta);
    for (std::size_t lane = 0; lane < kLaneWidth; ++lane) {
      const Vec3d t = LaneVec3(theta, lane);
      const std::string label =
          LaneLabel("AddRotationStep, |theta| = " + Precise(t.norm()), block, lane);
      Quatd expected = LaneQuat(before, lane);
      reference::AddRotationStep(expected, t);
      if (kinds[lane] == StepKind::kTiny) {
        ASSERT_LE(t.norm(), 1e-6) << label;  // the test's own premise
        EXPECT_TRUE(LaneBitsEqual(q, before, lane))
            << label << ": a rotation below 1e-6 rad must leave q bit-identical, got "
            << LaneQuat(q, lane).coeffs().transpose() << " from "
            << LaneQuat(before, lane).coeffs().transpose();
        continue;
      }
      if (kinds[lane] == StepKind::kJustAbove) {
        // Rotations of 2e-6..1e-5 rad change components of size ~0.5 by
        // 16..80 float ulps: q must change (the threshold is not too high).
        EXPECT_FALSE(LaneBitsEqual(q, before, lane)) << label << ": q did not rotate";
      }
      // Scale max(1, |theta|): q is unit, and the angle is computed in float,
      // so its rounding error (relative FLT_EPSILON) enters the half-angle
      // sin/cos with size |theta|.
      ExpectQuatNear(LaneQuat(q, lane), expected, Tolerance(std::max(1.0, t.norm())), label);
    }
  }
}

TEST_P(LaneMathTest, AddRotationStepMatchesReferenceAndKeepsTinyStepsExact) {
  Random random(606);
  CheckAddRotationStep(Kernels(), random, {StepKind::kTiny, StepKind::kJustAbove,
                                           StepKind::kModerate, StepKind::kLarge});
}

// Every lane within 0.5 rad, against the same reference.
TEST_P(LaneMathTest, AddRotationStepOfSmallAnglesMatchesReference) {
  Random random(607);
  CheckAddRotationStep(Kernels(), random, {StepKind::kTiny, StepKind::kJustAbove,
                                           StepKind::kSmallTaylor, StepKind::kSmallTaylor});
}

// ---------------------------------------------------------- inverse inertia

// Bodies with random rotations, inertia rotations and inverse-inertia
// diagonals spanning 1e-3..1e3 per axis; the other fields random too, so
// reading a wrong field shows.
void FillInertiaBodies(Random& random, BodyLanes& body) {
  for (std::size_t lane = 0; lane < kLaneWidth; ++lane) {
    BodyState state = RandomBodyState(random);
    state.inv_inertia_diagonal = {float(random.LogUniform(1e-3, 1e3)),
                                  float(random.LogUniform(1e-3, 1e3)),
                                  float(random.LogUniform(1e-3, 1e3))};
    WriteLane(body, lane, state);
  }
}

TEST_P(LaneMathTest, WorldInverseInertiaMatchesReference) {
  Random random(707);
  for (std::size_t block = 0; block < kBlocks; ++block) {
    // Value-initialised: FillInertiaBodies does not write dof_restricted, and
    // garbage there (seen in the -O0 ASan build) would send the kernels to
    // DOF locks this body does not have (BodyLockLanes).
    BodyLanes body{};
    FillInertiaBodies(random, body);
    Sym33Lanes m;
    Kernels().world_inverse_inertia(body, m);
    for (std::size_t lane = 0; lane < kLaneWidth; ++lane) {
      const Vec3d diagonal = LaneVec3(body.inv_inertia_diagonal, lane);
      const Mat33d expected = reference::WorldInverseInertia<double>(
          LaneQuat(body.rotation, lane), LaneQuat(body.inertia_rotation, lane), diagonal);
      // Scale max D: |R D R^T| entries are bounded by the largest diagonal entry.
      const double tolerance = Tolerance(diagonal.maxCoeff());
      const std::string label = LaneLabel("world inverse inertia", block, lane);
      EXPECT_NEAR(m.xx[lane], expected(0, 0), tolerance) << label << " (0,0)";
      EXPECT_NEAR(m.xy[lane], expected(0, 1), tolerance) << label << " (0,1)";
      EXPECT_NEAR(m.xz[lane], expected(0, 2), tolerance) << label << " (0,2)";
      EXPECT_NEAR(m.yy[lane], expected(1, 1), tolerance) << label << " (1,1)";
      EXPECT_NEAR(m.yz[lane], expected(1, 2), tolerance) << label << " (1,2)";
      EXPECT_NEAR(m.zz[lane], expected(2, 2), tolerance) << label << " (2,2)";
    }
  }
}

TEST_P(LaneMathTest, InverseInertiaTimesMatchesReference) {
  Random random(808);
  for (std::size_t block = 0; block < kBlocks; ++block) {
    // Value-initialised: FillInertiaBodies does not write dof_restricted, and
    // garbage there (seen in the -O0 ASan build) would send the kernels to
    // DOF locks this body does not have (BodyLockLanes).
    BodyLanes body{};
    FillInertiaBodies(random, body);
    Vec3Lanes v, product;
    for (std::size_t lane = 0; lane < kLaneWidth; ++lane) {
      SetLaneVec3(v, lane, random.UnitVector() * random.LogUniform(1e-2, 1e2));
    }
    Kernels().inverse_inertia_times(body, v, product);
    for (std::size_t lane = 0; lane < kLaneWidth; ++lane) {
      const Vec3d diagonal = LaneVec3(body.inv_inertia_diagonal, lane);
      const Vec3d vd = LaneVec3(v, lane);
      const Vec3d expected = reference::MultiplyWorldInverseInertia<double>(
          LaneQuat(body.rotation, lane), LaneQuat(body.inertia_rotation, lane), diagonal, vd);
      // Scale max D * |v| (the operator norm of I^-1 is max D).
      ExpectVec3Near(LaneVec3(product, lane), expected,
                     Tolerance(diagonal.maxCoeff() * vd.norm()),
                     LaneLabel("I^-1 v", block, lane));
    }
  }
}

// ------------------------------------------------------------- inverses

// What a lane of an inverse test holds.
enum class MatrixKind {
  kWellConditioned,  // singular values within a factor 4, any overall scale
  kSymmetric,        // symmetric positive definite (an effective mass)
  kIndefinite,       // one negative eigenvalue / negative determinant
  kNearSingular,     // condition number 1e3..1e5
  kZero,             // exactly singular from here on
  kZeroRow,
  kZeroColumn,
  kEqualColumns,
  kCount
};

bool IsSingular(MatrixKind kind) { return kind >= MatrixKind::kZero; }

const char* KindName(MatrixKind kind) {
  switch (kind) {
    case MatrixKind::kWellConditioned: return "well-conditioned";
    case MatrixKind::kSymmetric: return "symmetric positive definite";
    case MatrixKind::kIndefinite: return "indefinite";
    case MatrixKind::kNearSingular: return "near-singular";
    case MatrixKind::kZero: return "zero";
    case MatrixKind::kZeroRow: return "zero row";
    case MatrixKind::kZeroColumn: return "zero column";
    case MatrixKind::kEqualColumns: return "equal columns";
    case MatrixKind::kCount: break;
  }
  return "?";
}

MatrixKind KindOfLane(std::size_t block, std::size_t lane) {
  return MatrixKind((block + lane) % std::size_t(MatrixKind::kCount));
}

bool AllFinite(const Eigen::MatrixXd& m) { return m.allFinite(); }

Eigen::Matrix2d Rotation2(double angle) {
  Eigen::Matrix2d r;
  r << std::cos(angle), -std::sin(angle), std::sin(angle), std::cos(angle);
  return r;
}

// A random symmetric 2x2 of the given kind (in double; rounded to float by
// the caller).
Mat22d RandomSym22(Random& random, MatrixKind kind) {
  const double scale = random.LogUniform(1e-3, 1e3);
  const Eigen::Matrix2d r = Rotation2(random.Uniform(-kPi, kPi));
  Eigen::Vector2d eigenvalues(random.Uniform(0.5, 2.0), random.Uniform(0.5, 2.0));
  Mat22d k = Mat22d::Zero();
  switch (kind) {
    case MatrixKind::kWellConditioned:
    case MatrixKind::kSymmetric: break;
    case MatrixKind::kIndefinite: eigenvalues(1) = -eigenvalues(1); break;
    case MatrixKind::kNearSingular: eigenvalues(1) /= random.LogUniform(1e3, 1e5); break;
    case MatrixKind::kZero: return k;
    case MatrixKind::kZeroRow:  // symmetric: a zero row is also a zero column
    case MatrixKind::kZeroColumn: {
      const int i = random.Uniform(0, 1) < 0.5 ? 0 : 1;
      k(1 - i, 1 - i) = scale * random.Uniform(-2, 2);
      return k;
    }
    case MatrixKind::kEqualColumns:
      k.setConstant(scale * random.Uniform(-2, 2));  // symmetric with equal columns
      return k;
    case MatrixKind::kCount: break;
  }
  return scale * r * eigenvalues.asDiagonal() * r.transpose();
}

TEST_P(LaneMathTest, InverseSym22MatchesReferenceAndFlagsExactlySingularLanes) {
  Random random(909);
  for (std::size_t block = 0; block < kBlocks; ++block) {
    Sym22Lanes k, inverse;
    LaneFlags invertible;
    for (std::size_t lane = 0; lane < kLaneWidth; ++lane) {
      const Mat22d m = RandomSym22(random, KindOfLane(block, lane));
      k.xx[lane] = float(m(0, 0));
      k.xy[lane] = float(0.5 * (m(0, 1) + m(1, 0)));
      k.yy[lane] = float(m(1, 1));
    }
    Kernels().inverse_sym22(k, inverse, invertible);
    for (std::size_t lane = 0; lane < kLaneWidth; ++lane) {
      const MatrixKind kind = KindOfLane(block, lane);
      const std::string label = LaneLabel(std::string(KindName(kind)) + " 2x2", block, lane);
      Mat22d kd;  // the float matrix the kernel inverted, exactly
      kd << k.xx[lane], k.xy[lane], k.xy[lane], k.yy[lane];
      Mat22d expected;
      const bool reference_invertible = reference::InvertSymmetricOr2x2(kd, expected);
      Mat22d actual;
      actual << inverse.xx[lane], inverse.xy[lane], inverse.xy[lane], inverse.yy[lane];
      ASSERT_EQ(reference_invertible, !IsSingular(kind)) << label << ": test premise";
      EXPECT_TRUE(AllFinite(actual)) << label << ": " << actual;
      if (IsSingular(kind)) {
        EXPECT_EQ(invertible[lane], 0.0f) << label << ": singular lane flagged invertible";
        EXPECT_EQ(inverse.xx[lane], 0.0f) << label << ": inverse not zero";
        EXPECT_EQ(inverse.xy[lane], 0.0f) << label << ": inverse not zero";
        EXPECT_EQ(inverse.yy[lane], 0.0f) << label << ": inverse not zero";
        continue;
      }
      EXPECT_EQ(invertible[lane], 1.0f) << label << ": invertible lane not flagged";
      const double condition = Condition<2>(kd);
      // Scale |K^-1| (Frobenius, bounds every entry), amplified by cond(K):
      // the rounding of det is relative FLT_EPSILON * cond(K) without FMA.
      EXPECT_LE((actual - expected).cwiseAbs().maxCoeff(),
                Tolerance(expected.norm(), condition))
          << label << " (cond " << condition << "): kernel\n" << actual << "\nreference\n"
          << expected;
      // K K^-1 = I: scale 1 (dimensionless), entries of K K^-1 are sums of
      // terms up to |K||K^-1| = cond(K).
      EXPECT_LE((kd * actual - Mat22d::Identity()).cwiseAbs().maxCoeff(),
                Tolerance(1.0, condition))
          << label << " (cond " << condition << "): K K^-1 =\n" << kd * actual;
    }
  }
}

// Singular values, largest first.
Eigen::Vector3d SingularValues(const Mat33d& m) {
  return Eigen::JacobiSVD<Mat33d>(m).singularValues();
}

Mat33d RandomRotation3(Random& random) { return random.Rotation().toRotationMatrix(); }

// A random (generally non-symmetric, so a transposed inverse shows) 3x3 of
// the given kind: U diag(s) V^T, or exactly singular by structure.
Mat33d RandomMat33(Random& random, MatrixKind kind) {
  const double scale = random.LogUniform(1e-3, 1e3);
  const Mat33d u = RandomRotation3(random);
  const Mat33d v = RandomRotation3(random);
  Eigen::Vector3d s(random.Uniform(0.5, 2.0), random.Uniform(0.5, 2.0), random.Uniform(0.5, 2.0));
  Mat33d k;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) k(i, j) = scale * random.Uniform(-2, 2);
  }
  const int index = std::min(2, int(random.Uniform(0, 3)));
  switch (kind) {
    case MatrixKind::kWellConditioned: return scale * u * s.asDiagonal() * v.transpose();
    case MatrixKind::kSymmetric: return scale * u * s.asDiagonal() * u.transpose();
    case MatrixKind::kIndefinite:  // det < 0: a reflection in V
      return scale * u * s.asDiagonal() * (v * Eigen::Vector3d(1, 1, -1).asDiagonal()).transpose();
    case MatrixKind::kNearSingular:
      s(2) /= random.LogUniform(1e3, 1e5);
      return scale * u * s.asDiagonal() * v.transpose();
    case MatrixKind::kZero: return Mat33d::Zero();
    case MatrixKind::kZeroRow: k.row(index).setZero(); return k;
    case MatrixKind::kZeroColumn: k.col(index).setZero(); return k;
    case MatrixKind::kEqualColumns:
      if (index == 0) {
        k.col(2) = k.col(1);  // any reals: c1 x c2 is exactly zero in float
      } else {
        // Columns (0, index) equal: small integers, so every float product
        // and sum in det = c0 . (c1 x c2) is exact and det is exactly 0 (with
        // arbitrary reals the rounded triple product is a tiny non-zero, and
        // the kernel rightly treats it as invertible: spec 5, no threshold).
        for (int i = 0; i < 3; ++i) {
          for (int j = 0; j < 3; ++j) k(i, j) = std::round(random.Uniform(-9.5, 9.5));
        }
        k.col(index) = k.col(0);
      }
      return k;
    case MatrixKind::kCount: break;
  }
  return k;
}

TEST_P(LaneMathTest, Inverse33MatchesReferenceAndFlagsExactlySingularLanes) {
  Random random(1010);
  for (std::size_t block = 0; block < kBlocks; ++block) {
    Mat33Lanes k, inverse;
    LaneFlags invertible;
    for (std::size_t lane = 0; lane < kLaneWidth; ++lane) {
      const Mat33d m = RandomMat33(random, KindOfLane(block, lane));
      for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) k.m[i][j][lane] = float(m(i, j));
      }
    }
    Kernels().inverse33(k, inverse, invertible);
    for (std::size_t lane = 0; lane < kLaneWidth; ++lane) {
      const MatrixKind kind = KindOfLane(block, lane);
      const std::string label = LaneLabel(std::string(KindName(kind)) + " 3x3", block, lane);
      Mat33d kd, actual;  // kd: the float matrix the kernel inverted, exactly
      for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
          kd(i, j) = k.m[i][j][lane];
          actual(i, j) = inverse.m[i][j][lane];
        }
      }
      Mat33d expected;
      const bool reference_invertible = reference::Invert3x3(kd, expected);
      ASSERT_EQ(reference_invertible, !IsSingular(kind)) << label << ": test premise";
      EXPECT_TRUE(AllFinite(actual)) << label << ":\n" << actual;
      if (IsSingular(kind)) {
        EXPECT_EQ(invertible[lane], 0.0f) << label << ": singular lane flagged invertible";
        EXPECT_TRUE((actual.array() == 0.0).all()) << label << ": inverse not zero\n" << actual;
        continue;
      }
      EXPECT_EQ(invertible[lane], 1.0f) << label << ": invertible lane not flagged";
      // cond(K) from the singular values: Condition<3> (test_support.h)
      // symmetrises its argument, which is only right for symmetric K.
      const Eigen::Vector3d s = SingularValues(kd);
      const double condition = s(0) / s(2);
      if (kind == MatrixKind::kSymmetric) {
        // Both in double, so they agree to far better than relative 1e-6.
        EXPECT_NEAR(Condition<3>(kd), condition, 1e-6 * condition) << label;
      }
      // Scale |K^-1| (Frobenius), amplified by cond(K): an adjugate entry's
      // rounding is <= FLT_EPSILON |c_i||c_j| / |det| <= FLT_EPSILON
      // cond(K) |K^-1|, and det's relative rounding <= FLT_EPSILON cond(K).
      EXPECT_LE((actual - expected).cwiseAbs().maxCoeff(),
                Tolerance(expected.norm(), condition))
          << label << " (cond " << condition << "): kernel\n" << actual << "\nreference\n"
          << expected;
      // K K^-1 = I: scale 1; the adjugate errors above, multiplied by |K| =
      // s0, give FLT_EPSILON s0^2 / (s1 s2) = cond(K) * s0/s1 (equal to
      // cond(K) when the two largest singular values are alike).
      EXPECT_LE((kd * actual - Mat33d::Identity()).cwiseAbs().maxCoeff(),
                Tolerance(1.0, condition * s(0) / s(1)))
          << label << " (cond " << condition << "): K K^-1 =\n" << kd * actual;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(EveryTarget, LaneMathTest, ::testing::ValuesIn(SupportedKernels<LaneMathKernels>()),
                         TableName<LaneMathKernels>);

}  // namespace
}  // namespace manyworlds::testing
