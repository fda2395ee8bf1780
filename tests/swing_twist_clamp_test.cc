// Swing-twist decomposition, limit set-up and clamp (kernels/swing_twist_clamp-inl.h)
// against reference/swing_twist_part.h, lane by lane, on every Highway target
// this CPU supports, for every configuration of SwingTwistConfigs(), with the
// Newton steps of the cone's ellipse projection measured. The verbs are in
// swing_twist_test.cc.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "batch/part_binding.h"
#include "batch/part_state.h"
#include "batch/world_blocks.h"
#include "kernels/swing_twist.h"
#include "reference/swing_twist_part.h"
#include "tests/swing_twist_test_support.h"
#include "tests/test_support.h"

namespace manyworlds::testing {
namespace {

constexpr double kPi = std::numbers::pi;

std::string ConfigLabel(const NamedSwingTwistConfig& c, std::size_t world) {
  return std::string(c.name) + ", world " + std::to_string(world);
}

// --------------------------------------------- decomposition, limits, clamp

class SwingTwistMathTest : public ::testing::TestWithParam<const SwingTwistKernels*> {
 protected:
  const SwingTwistKernels& Kernels() const { return *GetParam(); }
};

TEST_P(SwingTwistMathTest, DecomposeMatchesReferenceIncludingExactHalfTurns) {
  Random random(11);
  for (int block = 0; block < 64; ++block) {
    QuatLanes q, swing, twist;
    for (std::size_t lane = 0; lane < kLaneWidth; ++lane) {
      Quatd value = ToFloatUnit(random.Rotation());
      // s == 0: a half turn about an axis in the YZ plane (w = x = 0 exactly).
      if (lane % 4 == 0) {
        const double phi = random.Uniform(-kPi, kPi);
        value = Quatd(0.0, 0.0, float(std::cos(phi)), float(std::sin(phi)));
      }
      if (lane % 4 == 1) {  // near it: s down to 0.05
        const double s = random.Uniform(0.05, 0.2), phi = random.Uniform(-kPi, kPi);
        const double theta = random.Uniform(-kPi, kPi), r = std::sqrt(1 - s * s);
        value = ToFloatUnit(Quatd(s * std::cos(theta), s * std::sin(theta),
                                  r * std::cos(phi), r * std::sin(phi)));
      }
      SetLaneQuat(q, lane, value);
    }
    Kernels().decompose(q, swing, twist);
    for (std::size_t lane = 0; lane < kLaneWidth; ++lane) {
      const Quatd qd = LaneQuat(q, lane);
      const reference::SwingTwist<double> expected = reference::DecomposeSwingTwist(qd);
      const std::string label = "decompose, lane " + std::to_string(lane) + " of block " +
                                std::to_string(block);
      const double s = std::sqrt(qd.w() * qd.w() + qd.x() * qd.x());
      if (s == 0.0) {
        // The s == 0 branch: swing = q and twist = identity, bit for bit.
        EXPECT_EQ(LaneQuat(swing, lane).coeffs(), qd.coeffs()) << label;
        EXPECT_EQ(LaneQuat(twist, lane).coeffs(), Quatd::Identity().coeffs()) << label;
        continue;
      }
      // Scale 1, amplified by 1/s (components are divided by s).
      ExpectQuatNear(LaneQuat(swing, lane), expected.swing, Tolerance(1.0, 1.0 / s), label);
      ExpectQuatNear(LaneQuat(twist, lane), expected.twist, Tolerance(1.0, 1.0 / s), label);
      EXPECT_EQ(swing.x[lane], 0.0f) << label;
      EXPECT_EQ(twist.y[lane], 0.0f) << label;
      EXPECT_EQ(twist.z[lane], 0.0f) << label;
    }
  }
}

TEST_P(SwingTwistMathTest, SetLimitsMatchesReference) {
  Random random(12);
  for (const NamedSwingTwistConfig& c : SwingTwistConfigs()) {
    SwingTwistLimitAngles angles;
    SwingTwistLimitLanes limits;
    std::array<LimitAngles, kLaneWidth> lane_angles;
    for (std::size_t lane = 0; lane < kLaneWidth; ++lane) {
      lane_angles[lane] = RandomLimitAngles(random, c.config);
      SetLaneLimitAngles(angles, lane, lane_angles[lane]);
    }
    Kernels().set_limits(c.config, angles, limits);
    for (std::size_t lane = 0; lane < kLaneWidth; ++lane) {
      RefSwingTwist ref;
      SetReferenceLimits(ref, c.config, lane_angles[lane]);
      const std::string label = ConfigLabel(c, lane);
      const std::pair<const AxisLimitLanes*, reference::AxisLimit<double>> axes[] = {
          {&limits.twist, ref.TwistLimit()},
          {&limits.swing_y, ref.SwingYLimit()},
          {&limits.swing_z, ref.SwingZLimit()}};
      for (const auto& [kernel, expected] : axes) {
        // Half angles are exact (a multiplication by 0.5); sin and cos of them
        // within the SinCos bound (2 FLT_EPSILON), locked and free exactly.
        EXPECT_EQ(kernel->half_min[lane], expected.half_min) << label;
        EXPECT_EQ(kernel->half_max[lane], expected.half_max) << label;
        const double tolerance = expected.kind == reference::AxisLimitKind::kLimited
                                     ? 2.0 * FLT_EPSILON : 0.0;
        EXPECT_NEAR(kernel->sin_half_min[lane], expected.sin_min, tolerance) << label;
        EXPECT_NEAR(kernel->sin_half_max[lane], expected.sin_max, tolerance) << label;
        EXPECT_NEAR(kernel->cos_half_min[lane], expected.cos_min, tolerance) << label;
        EXPECT_NEAR(kernel->cos_half_max[lane], expected.cos_max, tolerance) << label;
      }
    }
  }
}

// The clamp alone, on decomposed rotations inside, outside and across the
// limits of every configuration (and exact half turns). Also measures the
// Newton steps of the cone's ellipse projection: every lane must converge
// well before the cap.
TEST_P(SwingTwistMathTest, ClampMatchesReferenceAndEllipseConvergesBeforeTheCap) {
  Random random(13);
  std::map<int, int> iteration_histogram;
  for (const NamedSwingTwistConfig& c : SwingTwistConfigs()) {
    for (int block = 0; block < 48; ++block) {
      SwingTwistLimitAngles angles;
      SwingTwistLimitLanes limits;
      QuatLanes swing, twist;
      std::array<RefSwingTwist, kLaneWidth> refs;
      std::array<double, kLaneWidth> condition;
      for (std::size_t lane = 0; lane < kLaneWidth; ++lane) {
        const LimitAngles a = RandomLimitAngles(random, c.config);
        SetLaneLimitAngles(angles, lane, a);
        SetReferenceLimits(refs[lane], c.config, a);
        RotationCheck check;
        Quatd q;
        for (int attempt = 0; !check.clear; ++attempt) {
          ASSERT_LT(attempt, 200) << "no rotation clear of the clamp's boundaries for "
                                  << ConfigLabel(c, lane);
          // Lane 5 tries an exact half turn first (s == 0), if its limits
          // leave every decision clear.
          const bool half_turn = lane == 5 && attempt == 0;
          q = half_turn ? Quatd(0.0, 0.0, 0.6, 0.8)
                        : RandomRelativeRotation(random, c.config, a, RotationKind(lane % 4));
          check = CheckRotation(c.config, refs[lane], q, half_turn);
        }
        const reference::SwingTwist<double> st = reference::DecomposeSwingTwist(q);
        // Random overall signs: the clamp works on w >= 0 and restores them.
        const double swing_sign = random.Uniform(0, 1) < 0.5 ? -1 : 1;
        const double twist_sign = random.Uniform(0, 1) < 0.5 ? -1 : 1;
        SetLaneQuat(swing, lane, Quatd(swing_sign * st.swing.coeffs()));
        SetLaneQuat(twist, lane, Quatd(twist_sign * st.twist.coeffs()));
        condition[lane] = check.condition;
      }
      Kernels().set_limits(c.config, angles, limits);
      SwingTwistClampLanes out;
      Kernels().clamp(c.config, limits, swing, twist, out);
      for (std::size_t lane = 0; lane < kLaneWidth; ++lane) {
        Quatd ref_swing = LaneQuat(swing, lane), ref_twist = LaneQuat(twist, lane);
        const unsigned flags = refs[lane].ClampSwingTwist(ref_swing, ref_twist);
        const std::string label = ConfigLabel(c, lane) + ", block " + std::to_string(block);
        EXPECT_EQ(out.twist_min[lane] != 0, (flags & RefSwingTwist::kClampedTwistMin) != 0) << label;
        EXPECT_EQ(out.twist_max[lane] != 0, (flags & RefSwingTwist::kClampedTwistMax) != 0) << label;
        EXPECT_EQ(out.swing_y_min[lane] != 0, (flags & RefSwingTwist::kClampedSwingYMin) != 0) << label;
        EXPECT_EQ(out.swing_y_max[lane] != 0, (flags & RefSwingTwist::kClampedSwingYMax) != 0) << label;
        EXPECT_EQ(out.swing_z_min[lane] != 0, (flags & RefSwingTwist::kClampedSwingZMin) != 0) << label;
        EXPECT_EQ(out.swing_z_max[lane] != 0, (flags & RefSwingTwist::kClampedSwingZMax) != 0) << label;
        // Scale 1 (unit quaternions); the cone's projection stops at
        // |g| < 1e-6 in float (kernel) and in double (reference): allow 1e-6.
        const double tolerance = Tolerance(1.0, condition[lane]) + 1e-6;
        ExpectQuatNear(LaneQuat(out.swing, lane), ref_swing, tolerance, label + ", swing");
        ExpectQuatNear(LaneQuat(out.twist, lane), ref_twist, tolerance, label + ", twist");
        const int iterations = int(out.ellipse_iterations[lane]);
        if (iterations > 0) ++iteration_histogram[iterations];
      }
    }
  }
  int max_iterations = 0;
  std::string histogram;
  for (const auto& [steps, count] : iteration_histogram) {
    max_iterations = std::max(max_iterations, steps);
    histogram += " " + std::to_string(steps) + ":" + std::to_string(count);
  }
  // The documented cap is 32; the test inputs (half cone angles 2..120 deg)
  // need far fewer.
  EXPECT_LE(max_iterations, 16) << "Newton steps per projected lane:" << histogram;
  std::printf("[ measured ] %s: ellipse Newton steps (steps:lanes)%s\n", Kernels().target.name,
              histogram.c_str());
}

// Narrow cones (half angles down to 0.25 deg, the smallest that is not
// locked) and points far outside: the hardest inputs for Newton from t = 0.
TEST_P(SwingTwistMathTest, EllipseProjectionOfNarrowConesConvergesWithinTheCap) {
  Random random(14);
  const SwingTwistConfig cone{SwingType::kCone, AxisLimitKind::kFree, AxisLimitKind::kLimited,
                              AxisLimitKind::kLimited};
  int max_iterations = 0;
  for (int block = 0; block < 256; ++block) {
    SwingTwistLimitAngles angles{};
    SwingTwistLimitLanes limits;
    QuatLanes swing, twist;
    for (std::size_t lane = 0; lane < kLaneWidth; ++lane) {
      // Half cone angles 0.5..60 deg: semi-axes sin(angle/2) 0.0044..0.5.
      const double cone_y = random.LogUniform(0.5, 60.0) * kDegree;
      const double cone_z = lane % 2 ? 0.5 * kDegree : random.LogUniform(0.5, 60.0) * kDegree;
      angles.swing_y_min[lane] = float(-cone_y);
      angles.swing_y_max[lane] = float(cone_y);
      angles.swing_z_min[lane] = float(-cone_z);
      angles.swing_z_max[lane] = float(cone_z);
      const double phi = random.Uniform(-kPi, kPi), r = random.Uniform(0.3, 0.99);
      SetLaneQuat(swing, lane, ToFloatUnit(Quatd(std::sqrt(1 - r * r), 0.0, r * std::cos(phi),
                                                 r * std::sin(phi))));
      SetLaneQuat(twist, lane, Quatd::Identity());
    }
    Kernels().set_limits(cone, angles, limits);
    SwingTwistClampLanes out;
    Kernels().clamp(cone, limits, swing, twist, out);
    for (std::size_t lane = 0; lane < kLaneWidth; ++lane) {
      const int iterations = int(out.ellipse_iterations[lane]);
      max_iterations = std::max(max_iterations, iterations);
      const double a = limits.swing_y.sin_half_max[lane], b = limits.swing_z.sin_half_max[lane];
      const Vec2d point(swing.y[lane], swing.z[lane]);
      if (reference::EllipseIsInside(a, b, point)) {
        EXPECT_EQ(iterations, 0) << "inside, lane " << lane;
        continue;
      }
      int reference_iterations = 0;
      const Vec2d expected = reference::EllipseClosestPoint(a, b, point, &reference_iterations);
      const Vec2d actual(out.swing.y[lane], out.swing.z[lane]);
      const std::string label = "a = " + std::to_string(a) + ", b = " + std::to_string(b) +
                                ", lane " + std::to_string(lane);
      EXPECT_LT(iterations, 32) << label << ": the cap was reached";
      // On the ellipse: the stop rule |g| < 1e-6 plus the rounding of c.
      const double g = (actual.x() / a) * (actual.x() / a) + (actual.y() / b) * (actual.y() / b);
      EXPECT_NEAR(g, 1.0, 1e-5) << label;
      // Same point as the double-precision reference: a closest-point error
      // dc moves g by ~2 dc / min(a, b).
      EXPECT_LE((actual - expected).cwiseAbs().maxCoeff(), 2e-6 * std::min(a, b) + Tolerance(1.0))
          << label << " (reference took " << reference_iterations << " steps)";
    }
  }
  std::printf("[ measured ] %s: narrow cones, at most %d Newton steps (cap 32)\n",
              Kernels().target.name, max_iterations);
}

INSTANTIATE_TEST_SUITE_P(EveryTarget, SwingTwistMathTest,
                         ::testing::ValuesIn(SupportedKernels<SwingTwistKernels>()),
                         TableName<SwingTwistKernels>);

}  // namespace
}  // namespace manyworlds::testing
