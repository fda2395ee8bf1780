// Angle lane maths (kernels/lane_math-inl.h: Atan, Atan2,
// CenterAngleAroundZero), lane by lane against the C library in double, on
// every Highway target this CPU supports, over the whole float range
// including zeros of both signs, infinities, NaN and the branch boundaries
// of the argument reduction.
#include <gtest/gtest.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <limits>
#include <numbers>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "kernels/lane_math.h"
#include "manyworlds/lanes.h"
#include "tests/test_support.h"

namespace manyworlds::testing {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr float kInf = std::numeric_limits<float>::infinity();
constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
const float kFloatPi = float(kPi);

class AngleMathTest : public ::testing::TestWithParam<const LaneMathKernels*> {
 protected:
  const LaneMathKernels& Kernels() const { return *GetParam(); }
};

std::string Precise(double value) {
  std::ostringstream out;
  out.precision(17);
  out << value;
  return out.str();
}

// Runs a one-argument lane function over `inputs`, a block at a time (the
// last block padded with zeros), and returns the outputs in input order.
template <class Kernel>
std::vector<float> RunOverBlocks(const std::vector<float>& inputs, Kernel kernel) {
  std::vector<float> outputs(inputs.size());
  for (std::size_t first = 0; first < inputs.size(); first += kLaneWidth) {
    LaneArray in{}, out{};
    for (std::size_t lane = 0; lane < kLaneWidth && first + lane < inputs.size(); ++lane) {
      in[lane] = inputs[first + lane];
    }
    kernel(in, out);
    for (std::size_t lane = 0; lane < kLaneWidth && first + lane < inputs.size(); ++lane) {
      outputs[first + lane] = out[lane];
    }
  }
  return outputs;
}

std::vector<float> Neighbours(float x, int count) {
  std::vector<float> values;
  float below = x, above = x;
  values.push_back(x);
  for (int i = 0; i < count; ++i) {
    below = std::nextafter(below, -kInf);
    above = std::nextafter(above, kInf);
    values.push_back(below);
    values.push_back(above);
  }
  return values;
}

// Identical as floats, including the sign of zero; NaN equals NaN.
bool SameFloat(float a, float b) {
  if (std::isnan(a) || std::isnan(b)) return std::isnan(a) && std::isnan(b);
  return a == b && std::signbit(a) == std::signbit(b);
}

// ---------------------------------------------------------------------- atan

// Relative bound of Atan against atan in double of the float input:
//  - reduction: r = (t - 1)/(t + 1) or -1/t, t - 1 exact (Sterbenz, t in
//    (0.41, 2.42]), t + 1 and the division one rounding each: r within
//    ~1 FLT_EPSILON relative, and d atan(r) = dr / (1 + r^2) passes that on
//    with |r| <= tan(pi/8), i.e. <= 0.42 FLT_EPSILON of pi/4 + atan(r);
//  - Cephes' polynomial: relative error ~1e-8 (< 0.1 FLT_EPSILON) on the
//    reduced range; evaluated as r + r z p with r z p << r, its rounding is
//    ~0.1 ulp;
//  - offset + atan(r): one rounding (<= 0.5 ulp <= 0.5 FLT_EPSILON
//    relative); the offset's low part removes the constant's own error.
// About 1.1 FLT_EPSILON in all; measured 1.16 on every target. 1.5
// FLT_EPSILON keeps a margin and still fails when the low part of the
// offset is dropped (1.62 measured). A wrong branch or offset is off by
// pi/8 or more.
constexpr double kAtanRelativeBound = 1.5 * FLT_EPSILON;

// Results in the subnormal range are exact roundings of the division, so
// their error is at most half the smallest subnormal.
double AtanTolerance(double expected) {
  return std::max(kAtanRelativeBound * std::abs(expected),
                  double(std::numeric_limits<float>::denorm_min()));
}

std::vector<float> AtanInputs() {
  std::vector<float> x = {0.0f,     -0.0f,   1.0f,   -1.0f,    FLT_MIN, -FLT_MIN,
                          FLT_MAX, -FLT_MAX, kInf,   -kInf,    1e-45f,  -1e-45f,
                          1e-20f,  1e20f,    1e-3f,  1e3f,     0.5f,    2.0f};
  // Both reduction boundaries, tan(pi/8) and tan(3 pi/8), and a few floats
  // either side of them and of 1.
  for (const float boundary : {0.4142135623730950f, 2.414213562373095f, 1.0f}) {
    for (const float v : Neighbours(boundary, 8)) {
      x.push_back(v);
      x.push_back(-v);
    }
  }
  Random random(31337u);
  for (int i = 0; i < 60000; ++i) x.push_back(float(random.Uniform(-10.0, 10.0)));
  // Every binade from subnormals to FLT_MAX, both signs.
  for (int i = 0; i < 60000; ++i) {
    const float magnitude = float(random.LogUniform(1e-44, 3e38));
    x.push_back(i % 2 ? magnitude : -magnitude);
  }
  return x;
}

TEST_P(AngleMathTest, AtanMatchesLibmWithinOneAndAHalfEpsilonRelative) {
  const std::vector<float> inputs = AtanInputs();
  const std::vector<float> outputs = RunOverBlocks(
      inputs, [&](const LaneArray& x, LaneArray& out) { Kernels().atan(x, out); });
  double max_relative_error = 0;
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    const double expected = std::atan(double(inputs[i]));
    const double error = std::abs(double(outputs[i]) - expected);
    if (std::abs(expected) >= FLT_MIN) {
      max_relative_error = std::max(max_relative_error, error / std::abs(expected));
    }
    EXPECT_LE(error, AtanTolerance(expected))
        << "atan(" << Precise(inputs[i]) << ") = " << Precise(outputs[i]) << ", libm "
        << Precise(expected);
    // Odd function with exact signs: atan(+-0) = +-0.
    EXPECT_EQ(std::signbit(outputs[i]), std::signbit(inputs[i])) << "sign of atan(" << inputs[i] << ")";
  }
  RecordProperty("max_atan_relative_error_in_flt_epsilon",
                 std::to_string(max_relative_error / FLT_EPSILON));
  std::printf("[ measured ] %s: atan max relative error %.3f FLT_EPSILON\n",
              Kernels().target.name, max_relative_error / FLT_EPSILON);
}

TEST_P(AngleMathTest, AtanSpecialValuesAreExact) {
  const std::vector<std::pair<float, float>> cases = {
      {0.0f, 0.0f},
      {-0.0f, -0.0f},
      {kInf, float(kPi / 2)},
      {-kInf, -float(kPi / 2)},
      {1.0f, float(kPi / 4)},
      {-1.0f, -float(kPi / 4)},
      {1e-30f, 1e-30f},  // atan(x) = x to float precision for tiny x
      {kNaN, kNaN},
  };
  std::vector<float> inputs;
  for (const auto& [x, expected] : cases) inputs.push_back(x);
  const std::vector<float> outputs = RunOverBlocks(
      inputs, [&](const LaneArray& x, LaneArray& out) { Kernels().atan(x, out); });
  for (std::size_t i = 0; i < cases.size(); ++i) {
    EXPECT_TRUE(SameFloat(outputs[i], cases[i].second))
        << "atan(" << Precise(cases[i].first) << ") = " << Precise(outputs[i])
        << ", expected exactly " << Precise(cases[i].second);
  }
}

// --------------------------------------------------------------------- atan2

// Atan2 is AtanOfNonNegative(smaller / larger) (<= pi/4; the bound above
// plus the division's rounding, passed on with factor <= 1), then pi/2 - a
// and pi - a, one rounding each of a result at least as large as a; the
// float pi and pi/2 are within 0.5 ulp of the results' scale. Measured 1.37
// FLT_EPSILON; 2 FLT_EPSILON relative. A wrong quadrant is off by pi/2 or
// more, a wrong sign by twice the angle.
constexpr double kAtan2RelativeBound = 2.0 * FLT_EPSILON;

double Atan2Tolerance(double expected) {
  return std::max(kAtan2RelativeBound * std::abs(expected),
                  double(std::numeric_limits<float>::denorm_min()));
}

std::vector<std::pair<float, float>> Atan2Inputs() {
  std::vector<std::pair<float, float>> yx;
  Random random(4242u);
  // Every direction at radii 1e-30..1e30.
  for (int i = 0; i < 60000; ++i) {
    const double angle = random.Uniform(-kPi, kPi);
    const double radius = random.LogUniform(1e-30, 1e30);
    yx.emplace_back(float(radius * std::sin(angle)), float(radius * std::cos(angle)));
  }
  // Independent magnitudes: ratios from 1e-40 to 1e40 (results near 0, pi/2,
  // pi), every sign combination.
  for (int i = 0; i < 40000; ++i) {
    const float y = float(random.LogUniform(1e-30, 1e30)) * (i % 2 ? 1.0f : -1.0f);
    const float x = float(random.LogUniform(1e-30, 1e30)) * (i % 4 < 2 ? 1.0f : -1.0f);
    yx.emplace_back(y, x);
  }
  // Near the octant boundaries, where the ratio is about 1 and tan(pi/8),
  // tan(3 pi/8): the reduction switches branch.
  for (const float t : {1.0f, 0.4142135623730950f, 2.414213562373095f}) {
    for (const float v : Neighbours(t, 4)) {
      for (const float sy : {1.0f, -1.0f}) {
        for (const float sx : {1.0f, -1.0f}) {
          yx.emplace_back(sy * v, sx * 1.0f);
          yx.emplace_back(sy * 1.0f, sx * v);
        }
      }
    }
  }
  // Axes with both zeros, finite values, infinities.
  for (const float a : {0.0f, -0.0f, 1.0f, -1.0f, 1e-38f, -3e38f, kInf, -kInf}) {
    for (const float b : {0.0f, -0.0f, 2.5f, -2.5f, kInf, -kInf}) {
      yx.emplace_back(a, b);
      yx.emplace_back(b, a);
    }
  }
  return yx;
}

std::vector<float> RunAtan2(const LaneMathKernels& kernels,
                            const std::vector<std::pair<float, float>>& yx) {
  std::vector<float> outputs(yx.size());
  for (std::size_t first = 0; first < yx.size(); first += kLaneWidth) {
    LaneArray y{}, x{}, out{};
    for (std::size_t lane = 0; lane < kLaneWidth && first + lane < yx.size(); ++lane) {
      y[lane] = yx[first + lane].first;
      x[lane] = yx[first + lane].second;
    }
    kernels.atan2(y, x, out);
    for (std::size_t lane = 0; lane < kLaneWidth && first + lane < yx.size(); ++lane) {
      outputs[first + lane] = out[lane];
    }
  }
  return outputs;
}

TEST_P(AngleMathTest, Atan2MatchesLibmInEveryQuadrantWithinTwoEpsilonRelative) {
  const std::vector<std::pair<float, float>> inputs = Atan2Inputs();
  const std::vector<float> outputs = RunAtan2(Kernels(), inputs);
  double max_relative_error = 0;
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    const auto [y, x] = inputs[i];
    const double expected = std::atan2(double(y), double(x));
    const double error = std::abs(double(outputs[i]) - expected);
    if (std::abs(expected) >= FLT_MIN) {
      max_relative_error = std::max(max_relative_error, error / std::abs(expected));
    }
    const std::string label = "atan2(" + Precise(y) + ", " + Precise(x) + ") = " +
                              Precise(outputs[i]) + ", libm " + Precise(expected);
    EXPECT_LE(error, Atan2Tolerance(expected)) << label;
    // The sign of y, also of +-0, is the sign of the result.
    EXPECT_EQ(std::signbit(outputs[i]), std::signbit(y)) << label;
  }
  RecordProperty("max_atan2_relative_error_in_flt_epsilon",
                 std::to_string(max_relative_error / FLT_EPSILON));
  std::printf("[ measured ] %s: atan2 max relative error %.3f FLT_EPSILON\n",
              Kernels().target.name, max_relative_error / FLT_EPSILON);
}

// The special cases of C's atan2f (C11 F.10.1.4), bit for bit (signs of zero
// included), and NaN in any argument giving NaN.
TEST_P(AngleMathTest, Atan2SpecialCasesMatchAtan2fExactly) {
  std::vector<std::pair<float, float>> inputs;
  for (const float y : {0.0f, -0.0f, 1.0f, -1.0f, kInf, -kInf, kNaN}) {
    for (const float x : {0.0f, -0.0f, 3.0f, -3.0f, kInf, -kInf, kNaN}) {
      inputs.emplace_back(y, x);
    }
  }
  const std::vector<float> outputs = RunAtan2(Kernels(), inputs);
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    const auto [y, x] = inputs[i];
    const bool axis_or_special = y == 0.0f || x == 0.0f || std::isinf(y) || std::isinf(x) ||
                                 std::isnan(y) || std::isnan(x);
    if (!axis_or_special) continue;  // (+-1, +-3): covered by the accuracy test
    const float expected = std::atan2(y, x);  // float overload: atan2f
    EXPECT_TRUE(SameFloat(outputs[i], expected))
        << "atan2(" << y << ", " << x << ") = " << Precise(outputs[i]) << ", atan2f "
        << Precise(expected);
  }
  // Spelled out, so the test does not depend on the C library alone.
  EXPECT_TRUE(SameFloat(outputs[0], 0.0f));           // atan2(+0, +0) = +0
  EXPECT_TRUE(SameFloat(outputs[1], kFloatPi));       // atan2(+0, -0) = +pi
  EXPECT_TRUE(SameFloat(outputs[7], -0.0f));          // atan2(-0, +0) = -0
  EXPECT_TRUE(SameFloat(outputs[8], -kFloatPi));      // atan2(-0, -0) = -pi
}

// --------------------------------------------------- CenterAngleAroundZero

// CenterAngleAroundZero against remainder(x, 2 pi) in double (the nearest
// whole number of true turns removed). The kernel's reduction is exact up to
// two roundings of values of size <= pi + 0.003 (two FMA or subtraction
// stages of the three-part 2 pi), i.e. <= 1 ulp of pi = 2 FLT_EPSILON
// absolute; the neglected tail of 2 pi times 8000 turns is ~1e-11. A wrong
// turn count is off by 2 pi.
constexpr double kCenterAngleBound = 2.0 * FLT_EPSILON;

std::vector<float> CenterAngleInputs() {
  std::vector<float> x = {0.0f, -0.0f, kFloatPi, -kFloatPi, 1e-30f, -1e-30f};
  for (const float v : Neighbours(kFloatPi, 4)) {
    x.push_back(v);
    x.push_back(-v);
  }
  // Multiples of pi (odd ones are the boundary, where both ends are the
  // same angle) and of pi/2, and their float neighbours.
  for (int k = -200; k <= 200; ++k) {
    for (const float v : Neighbours(float(k * kPi), 2)) x.push_back(v);
    x.push_back(float(k * kPi / 2));
  }
  Random random(2718u);
  for (int i = 0; i < 40000; ++i) x.push_back(float(random.Uniform(-kPi, kPi)));
  for (int i = 0; i < 40000; ++i) x.push_back(float(random.Uniform(-20.0, 20.0)));
  for (int i = 0; i < 40000; ++i) x.push_back(float(random.Uniform(-50000.0, 50000.0)));
  return x;
}

TEST_P(AngleMathTest, CenterAngleAroundZeroMatchesRemainderAndStaysInRange) {
  const std::vector<float> inputs = CenterAngleInputs();
  const std::vector<float> outputs = RunOverBlocks(inputs, [&](const LaneArray& x, LaneArray& out) {
    Kernels().center_angle_around_zero(x, out);
  });
  double max_error = 0;
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    const float x = inputs[i], centered = outputs[i];
    const std::string label =
        "CenterAngleAroundZero(" + Precise(x) + ") = " + Precise(centered);
    // Range: [-pi, pi] with pi the float pi (the rounding of any angle in the
    // true range stays inside it).
    EXPECT_LE(std::abs(centered), kFloatPi) << label;
    // Inside the range nothing happens, bit for bit (the loop does nothing).
    if (std::abs(x) <= kFloatPi) {
      EXPECT_TRUE(SameFloat(centered, x)) << label << ": must return x unchanged";
      continue;
    }
    // On the boundary +pi and -pi are the same angle; the loop ends on the
    // side of the sign of x.
    const double expected = std::remainder(double(x), 2.0 * kPi);
    double error = std::abs(centered - expected);
    if (std::abs(std::abs(expected) - kPi) <= kCenterAngleBound) {
      error = std::min(error, std::abs(std::abs(error) - 2.0 * kPi));
      if (std::abs(centered) == kFloatPi) {
        EXPECT_EQ(std::signbit(centered), std::signbit(x)) << label << ": boundary side";
      }
    }
    max_error = std::max(max_error, error);
    EXPECT_LE(error, kCenterAngleBound) << label << ", remainder(x, 2 pi) " << Precise(expected);
  }
  RecordProperty("max_center_angle_error_in_flt_epsilon", std::to_string(max_error / FLT_EPSILON));
  std::printf("[ measured ] %s: CenterAngleAroundZero max absolute error %.3f FLT_EPSILON\n",
              Kernels().target.name, max_error / FLT_EPSILON);
}

// The spec's loop run in double on the float input gives the same turn count
// as the kernel away from the boundary; exactly +-pi is kept as is.
TEST_P(AngleMathTest, CenterAngleAroundZeroAgreesWithTheLoopOfTheSpec) {
  const std::vector<float> inputs = CenterAngleInputs();
  const std::vector<float> outputs = RunOverBlocks(inputs, [&](const LaneArray& x, LaneArray& out) {
    Kernels().center_angle_around_zero(x, out);
  });
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    if (std::abs(inputs[i]) > 100.0f) continue;  // keep the loop short
    const double expected = reference::CenterAngleAroundZero<double>(inputs[i]);
    if (std::abs(std::abs(expected) - kPi) <= kCenterAngleBound) continue;  // boundary: above
    // The loop adds 2 pi in double each time: ~1e-16 per turn, negligible.
    EXPECT_LE(std::abs(outputs[i] - expected), kCenterAngleBound)
        << "CenterAngleAroundZero(" << Precise(inputs[i]) << ") = " << Precise(outputs[i])
        << ", loop " << Precise(expected);
  }
}

INSTANTIATE_TEST_SUITE_P(EveryTarget, AngleMathTest,
                         ::testing::ValuesIn(SupportedKernels<LaneMathKernels>()),
                         TableName<LaneMathKernels>);

}  // namespace
}  // namespace manyworlds::testing
