// The flop counter of the roofline benchmark (bench/flop_count.h,
// bench/scene_flops.h): it counts known expressions exactly, charges
// transcendentals as documented, leaves constant evaluation out, and a
// reference world stepped in Counted<float> computes exactly the bits of
// reference::World<float> (counting changes nothing it counts).
#include "bench/scene_flops.h"  // before anything that includes the reference

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "manyworlds/scenes.h"
#include "reference/world.h"

namespace manyworlds::bench {
namespace {

using C = Counted<float>;

TEST(FlopCount, CountsEachArithmeticOperationOnce) {
  const C a(2.0f), b(3.0f), c(4.0f), d(16.0f), e(1.0f);
  ResetTally();
  const C r = (a * b + c) / std::sqrt(d) - e;  // mul, add, sqrt, div, sub
  EXPECT_FLOAT_EQ(r.value(), 1.5f);
  const FlopTally t = Tally();
  EXPECT_EQ(t.mul, 1u);
  EXPECT_EQ(t.add, 2u);
  EXPECT_EQ(t.div, 1u);
  EXPECT_EQ(t.sqrt, 1u);
  EXPECT_EQ(t.Flops(), 5u);
}

TEST(FlopCount, CompoundAssignmentNegationAndComparisons) {
  C x(1.0f);
  ResetTally();
  x += C(2.0f);
  x *= C(3.0f);
  x = -x;                                    // not counted
  const bool less = x < C(0.0f);             // not counted
  const C m = std::max(x, C(5.0f));          // not counted
  const C a = std::abs(x);                   // not counted
  EXPECT_TRUE(less);
  EXPECT_EQ(m.value(), 5.0f);
  EXPECT_EQ(a.value(), 9.0f);
  EXPECT_EQ(Tally().Flops(), 2u);
}

TEST(FlopCount, EigenDotCrossAndNormalise) {
  const Eigen::Matrix<C, 3, 1> u(C(1.0f), C(2.0f), C(3.0f)), v(C(4.0f), C(5.0f), C(6.0f));
  ResetTally();
  const C dot = u.dot(v);
  EXPECT_EQ(dot.value(), 32.0f);
  EXPECT_EQ(Tally().mul, 3u);
  EXPECT_EQ(Tally().add, 2u);

  ResetTally();
  const Eigen::Matrix<C, 3, 1> cross = u.cross(v);
  EXPECT_EQ(cross.x().value(), -3.0f);
  EXPECT_EQ(Tally().mul, 6u);
  EXPECT_EQ(Tally().add, 3u);

  ResetTally();
  const C norm = u.norm();  // 3 mul, 2 add, 1 sqrt
  EXPECT_FLOAT_EQ(norm.value(), std::sqrt(14.0f));
  EXPECT_EQ(Tally().Flops(), 6u);
}

TEST(FlopCount, TranscendentalsAreChargedTheLaneMathsFlops) {
  const C x(0.5f);
  ResetTally();
  const C s = std::sin(x), c = std::cos(x), t = std::atan2(s, c);
  EXPECT_FLOAT_EQ(t.value(), 0.5f);
  EXPECT_EQ(Tally().transcendental_calls, 3u);
  EXPECT_EQ(Tally().transcendental_flops, kSinFlops + kCosFlops + kAtan2Flops);
  EXPECT_EQ(Tally().Flops(), kSinFlops + kCosFlops + kAtan2Flops);
}

TEST(FlopCount, ConstantEvaluationIsNotCounted) {
  ResetTally();
  constexpr C kTwoPi = C(2.0f) * std::numbers::pi_v<C>;
  EXPECT_FLOAT_EQ(kTwoPi.value(), 2.0f * std::numbers::pi_v<float>);
  EXPECT_EQ(Tally().Flops(), 0u);
}

// Counting must not change the computation: the same reference world in
// float and in Counted<float>, same actions, same bits after 40 steps. The
// ragdoll is the exception in the last bits: Eigen computes float quaternion
// products and 4-vector reductions with SSE in another order of operations
// than its scalar path, which Counted takes, and the ragdoll is the one 3D
// scene (in the planar scenes those terms are exact zeros); it must agree to
// float rounding after one step (it is chaotic later).
TEST(FlopCount, CountedWorldStepsAsFloat) {
  for (const std::string& id : ReferenceSceneIds()) {
    SCOPED_TRACE(id);
    const Scene scene = MakeReferenceScene(id);
    const SceneActions actions(id);
    reference::World<float> plain(scene);
    reference::World<C> counted(scene);
    const bool bitwise = id != "ragdoll";
    const std::uint64_t steps = bitwise ? 40 : 1;
    for (std::uint64_t step = 0; step < steps; ++step) {
      actions.ApplyTo(plain, 0, step, 1);
      actions.ApplyTo(counted, 0, step, 1);
      plain.Step(StepSettings{});
      counted.Step(StepSettings{});
    }
    for (std::size_t b = 0; b < plain.body_count(); ++b) {
      for (int i = 0; i < 3; ++i) {
        const float x = plain.body(b).position[i], w = plain.body(b).angular_velocity[i];
        if (bitwise) {
          EXPECT_EQ(x, counted.body(b).position[i].value());
          EXPECT_EQ(w, counted.body(b).angular_velocity[i].value());
        } else {
          EXPECT_NEAR(x, counted.body(b).position[i].value(), 1e-5f * (1.0f + std::abs(x)));
          EXPECT_NEAR(w, counted.body(b).angular_velocity[i].value(),
                      1e-4f * (1.0f + std::abs(w)));
        }
      }
    }
  }
}

// Per-scene counts are deterministic and consistent: velocity iterations 2
// to 10 are a positive part of the step, no more than 9 full iterations.
TEST(FlopCount, SceneCountsAreRepeatableAndConsistent) {
  for (const std::string& id : ReferenceSceneIds()) {
    SCOPED_TRACE(id);
    const SceneFlops first = CountSceneFlops(id);
    const SceneFlops again = CountSceneFlops(id);
    EXPECT_EQ(first.per_step, again.per_step);
    EXPECT_EQ(first.per_step_few_iterations, again.per_step_few_iterations);
    EXPECT_GT(first.per_velocity_iteration, 0.0);
    EXPECT_GT(first.VelocityIterationsBeyondFew(), 0.0);
    EXPECT_LE(first.VelocityIterationsBeyondFew(), 9.0 * first.per_velocity_iteration * 1.1);
    EXPECT_LT(first.transcendental_per_step, first.per_step);
  }
}

// A chain's velocity iteration solves one point constraint per link: the
// first joins a link to the static world and updates one body, every other
// joins two dynamic links; so chain64 costs more than four chain16s and, by
// structure alone, at most 63/15 = 4.2 times (first joint free). The counts
// are averages over steps of iteration 2 minus iteration 1 and include
// data-dependent branches (a zero impulse skips its body updates), which
// moves the ratio by a few per cent (4.22 measured).
TEST(FlopCount, VelocityIterationScalesWithConstraintCount) {
  const double chain16 = CountSceneFlops("chain16").per_velocity_iteration;
  const double chain64 = CountSceneFlops("chain64").per_velocity_iteration;
  EXPECT_GT(chain64 / chain16, 4.0);
  EXPECT_LT(chain64 / chain16, 4.35);
}

}  // namespace
}  // namespace manyworlds::bench
