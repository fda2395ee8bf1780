// StepSettings::velocity_tolerance (batch/velocity_convergence-inl.h): a
// world stops its Gauss-Seidel velocity passes after the first pass that
// changed no velocity component of its dynamic bodies by more than the
// tolerance. What is asserted, on every target:
//  - each world's step with the tolerance is, bit for bit, the step with
//    exactly k fixed passes, where k is the first pass whose change (found
//    from steps with 0..10 fixed passes and no position iterations) is
//    within the tolerance: each world stops on its own, whatever its
//    neighbours in the block need, and keeps what it had after that pass;
//  - the double reference, given the same bodies and solver state, stops at
//    the same pass as the lane wherever none of the lane's changes is within
//    1 % of the tolerance (nearer, float and double rounding may fall on
//    either side): its step is then its own fixed-pass step at that pass, to
//    the last bit (how close the lane's and the reference's fixed-pass steps
//    are is scene_comparison_test.cc's business);
//  - a tolerance above every change stops every world after one pass (the
//    exact solve: two, its first visits no inequality row): the same bits
//    as velocity_iterations = 1 (2) over many steps;
//  - a negative, NaN or infinite tolerance is refused naming the field,
//    before anything is written.
// For Gauss-Seidel's passes (cartpole, ragdoll, box-pile, more_types) and the
// exact solve's passes around its joints (ragdoll, quadruped, more_types).

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include "manyworlds/batch.h"
#include "manyworlds/error.h"
#include "manyworlds/scenes.h"
#include "reference/world.h"
#include "tests/lane_vs_reference.h"
#include "tests/mixed_scenes.h"
#include "tests/step_targets.h"

namespace manyworlds {
namespace {

// 20 worlds: a full block and a block of 4 worlds and 12 padding lanes.
constexpr std::size_t kWorlds = 20;
constexpr int kMaxPasses = 10;

// Every world's bodies and solver state (the impulses the passes
// warm-start from).
struct Worlds {
  std::vector<float> bodies;
  std::vector<std::vector<float>> solver;
};

Worlds ReadWorlds(const Batch& batch) {
  Worlds worlds;
  worlds.bodies.resize(kWorlds * batch.body_count() * kStateFloatsPerBody);
  batch.GetState(worlds.bodies);
  for (std::size_t w = 0; w < kWorlds; ++w) {
    worlds.solver.emplace_back(batch.SolverStateSize());
    batch.GetSolverState(w, worlds.solver.back());
  }
  return worlds;
}

// Where every world starts its step from: kicked worlds after 20 steps.
using Start = Worlds;
Start MakeStart(const Scene& scene, std::int64_t target) {
  BatchOptions options{1};
  options.target = target;
  Batch batch(scene, kWorlds, options);
  KickEveryWorldDifferently(batch);
  for (int step = 0; step < 20; ++step) batch.Step({});
  return ReadWorlds(batch);
}

// Every world after one step from `start`.
using After = Worlds;
After StepOnce(const Scene& scene, std::int64_t target, const Start& start,
               const StepSettings& settings) {
  BatchOptions options{1};
  options.target = target;
  Batch batch(scene, kWorlds, options);
  // One step first, so that the step below warm-starts (dt / dt_prev = 1).
  batch.Step({});
  batch.SetState(start.bodies);
  for (std::size_t w = 0; w < kWorlds; ++w) batch.SetSolverState(w, start.solver[w]);
  batch.Step(settings);
  return ReadWorlds(batch);
}

StepSettings FixedPasses(JointSolver solver, int passes, int position_iterations) {
  StepSettings settings;
  settings.solver = solver;
  settings.velocity_iterations = passes;
  settings.position_iterations = position_iterations;
  return settings;
}

// The largest change of any dynamic body's velocity component between two
// steps' results, per world, in float as the step computes it (|a - b|
// rounded to float: in double a world whose change rounds onto the
// tolerance would be on the other side of it).
std::vector<double> LargestChange(const Scene& scene, const After& a, const After& b) {
  const std::size_t per_world = scene.bodies().size() * kStateFloatsPerBody;
  std::vector<double> change(kWorlds, 0.0);
  for (std::size_t w = 0; w < kWorlds; ++w) {
    for (std::size_t body = 0; body < scene.bodies().size(); ++body) {
      if (scene.bodies()[body].motion_type != MotionType::kDynamic) continue;
      for (std::size_t i = 7; i < 13; ++i) {
        const std::size_t at = w * per_world + body * kStateFloatsPerBody + i;
        const float difference = a.bodies[at] - b.bodies[at];
        change[w] = std::max(change[w], double(std::abs(difference)));
      }
    }
  }
  return change;
}

// Every world's velocities after 0 to kMaxPasses fixed passes from `start`
// (with no position iterations a step's velocities are the velocity passes'
// result), how much pass k changed world w's (changes[k][w]), a tolerance
// the worlds meet at different passes (just above the median of the second
// pass's changes) and the pass each world stops after with it.
struct Passes {
  std::vector<After> velocities;
  std::vector<std::vector<double>> changes;
  float tolerance = 0.0f;
  std::vector<int> stop;
};

Passes MeasurePasses(const Scene& s, std::int64_t target, JointSolver solver,
                     const Start& start) {
  Passes p;
  for (int k = 0; k <= kMaxPasses; ++k) {
    p.velocities.push_back(StepOnce(s, target, start, FixedPasses(solver, k, 0)));
  }
  p.changes.resize(kMaxPasses + 1);
  for (int k = 1; k <= kMaxPasses; ++k) {
    p.changes[k] = LargestChange(s, p.velocities[k], p.velocities[k - 1]);
  }
  // The exact solve's first pass (the joints solved at once, none of the
  // inequality rows) runs even at 0 passes, and no world stops after it.
  if (solver == JointSolver::kExact) {
    p.changes[1].assign(kWorlds, std::numeric_limits<double>::infinity());
  }
  // Half-way between the median and the next larger change, so that no
  // world's change sits on the tolerance.
  std::vector<double> second = p.changes[2];
  std::sort(second.begin(), second.end());
  std::size_t above = kWorlds / 2 + 1;
  while (above < kWorlds && second[above] == second[kWorlds / 2]) ++above;
  p.tolerance = above < kWorlds ? float(0.5 * (second[kWorlds / 2] + second[above]))
                                : float(2.0 * second[kWorlds / 2]);
  p.stop.assign(kWorlds, kMaxPasses);
  for (std::size_t w = 0; w < kWorlds; ++w) {
    for (int k = 1; k <= kMaxPasses; ++k) {
      if (p.changes[k][w] <= double(p.tolerance)) {
        p.stop[w] = k;
        break;
      }
    }
  }
  return p;
}

class VelocityToleranceTest
    : public ::testing::TestWithParam<std::tuple<std::int64_t, std::string, JointSolver>> {
 protected:
  std::int64_t target() const { return std::get<0>(GetParam()); }
  Scene scene() const { return test_scenes::SceneById(std::get<1>(GetParam())); }
  JointSolver solver() const { return std::get<2>(GetParam()); }
  StepSettings Fixed(int passes, int position_iterations) const {
    return FixedPasses(solver(), passes, position_iterations);
  }
};

TEST_P(VelocityToleranceTest, EachWorldStopsAfterItsFirstPassWithinTheTolerance) {
  const Scene s = scene();
  const Start start = MakeStart(s, target());
  const Passes passes = MeasurePasses(s, target(), solver(), start);
  const float tolerance = passes.tolerance;
  ASSERT_GT(tolerance, 0.0f);
  const std::vector<int>& stop = passes.stop;
  const std::set<int> stops_in_first_block(stop.begin(), stop.begin() + 16);
  ASSERT_GE(stops_in_first_block.size(), 2u)
      << "every world of the first block stops at the same pass: nothing is tested";

  for (const int position_iterations : {0, 2}) {
    StepSettings settings = Fixed(kMaxPasses, position_iterations);
    settings.velocity_tolerance = tolerance;
    const After with_tolerance = StepOnce(s, target(), start, settings);
    const std::size_t per_world = s.bodies().size() * kStateFloatsPerBody;
    for (std::size_t w = 0; w < kWorlds; ++w) {
      const After fixed =
          position_iterations == 0
              ? passes.velocities[stop[w]]
              : StepOnce(s, target(), start, Fixed(stop[w], position_iterations));
      for (std::size_t i = 0; i < per_world; ++i) {
        ASSERT_EQ(std::bit_cast<std::uint32_t>(with_tolerance.bodies[w * per_world + i]),
                  std::bit_cast<std::uint32_t>(fixed.bodies[w * per_world + i]))
            << "world " << w << " (stops after pass " << stop[w] << "), state float " << i
            << ", position iterations " << position_iterations;
      }
      ASSERT_EQ(with_tolerance.solver[w], fixed.solver[w])
          << "world " << w << " (stops after pass " << stop[w] << ")";
    }
  }
}

TEST_P(VelocityToleranceTest, TheReferenceStopsAtTheSamePassAsTheLane) {
  const Scene s = scene();
  const Start start = MakeStart(s, target());
  const Passes passes = MeasurePasses(s, target(), solver(), start);
  const float tolerance = passes.tolerance;
  StepSettings settings = Fixed(kMaxPasses, 2);
  settings.velocity_tolerance = tolerance;

  const std::size_t per_world = s.bodies().size() * kStateFloatsPerBody;
  std::size_t compared = 0;
  for (std::size_t w = 0; w < kWorlds; ++w) {
    // Skip worlds that have a pass within 1 % of the tolerance.
    bool clear = true;
    for (int k = 1; k <= kMaxPasses; ++k) {
      clear = clear &&
              std::abs(passes.changes[k][w] - double(tolerance)) > 0.01 * double(tolerance);
    }
    if (!clear) continue;
    ++compared;
    // The reference from the lane's start, once with the tolerance and once
    // with the lane's number of passes: it must stop where the lane stops.
    const auto reference_step = [&](const StepSettings& step_settings) {
      reference::World<double> world(s);
      world.Step({});  // so that the step below warm-starts, as the lane's
      SetReferenceState(world, start.bodies.data() + w * per_world);
      world.SetSolverState(std::vector<double>(start.solver[w].begin(), start.solver[w].end()));
      world.Step(step_settings);
      return world;
    };
    const reference::World<double> with_tolerance = reference_step(settings);
    const int lane_stop = passes.stop[w];
    const reference::World<double> fixed = reference_step(Fixed(lane_stop, 2));
    for (std::size_t b = 0; b < s.bodies().size(); ++b) {
      // The reference stopped at the lane's pass: its result is the fixed
      // passes' to the last bit (the same double arithmetic).
      EXPECT_EQ(with_tolerance.body(b).linear_velocity, fixed.body(b).linear_velocity)
          << "world " << w << " body " << b << ": the reference stopped elsewhere than pass "
          << lane_stop;
      EXPECT_EQ(with_tolerance.body(b).angular_velocity, fixed.body(b).angular_velocity)
          << "world " << w << " body " << b;
    }
  }
  EXPECT_GE(compared, kWorlds / 2) << "too few worlds clear of the tolerance to compare";
}

TEST_P(VelocityToleranceTest, AToleranceAboveEveryChangeStopsAfterTheFirstTestedPass) {
  const Scene s = scene();
  BatchOptions options{1};
  options.target = target();
  Batch one_pass(s, kWorlds, options), tolerant(s, kWorlds, options);
  KickEveryWorldDifferently(one_pass);
  KickEveryWorldDifferently(tolerant);
  StepSettings settings = Fixed(kMaxPasses, 2);
  settings.velocity_tolerance = 1e30f;
  // The exact solve's first pass visits none of the inequality rows and is
  // not tested: it stops after its second.
  const StepSettings one = Fixed(solver() == JointSolver::kExact ? 2 : 1, 2);
  std::vector<float> a(kWorlds * s.bodies().size() * kStateFloatsPerBody), b(a.size());
  for (int step = 0; step < 40; ++step) {
    one_pass.Step(one);
    tolerant.Step(settings);
    one_pass.GetState(a);
    tolerant.GetState(b);
    for (std::size_t i = 0; i < a.size(); ++i) {
      ASSERT_EQ(std::bit_cast<std::uint32_t>(a[i]), std::bit_cast<std::uint32_t>(b[i]))
          << "state float " << i << " after step " << step;
    }
  }
}

std::string CaseName(const ::testing::TestParamInfo<VelocityToleranceTest::ParamType>& info) {
  std::string scene = std::get<1>(info.param);
  std::replace(scene.begin(), scene.end(), '-', '_');
  return std::string(hwy::TargetName(std::get<0>(info.param))) + "_" + scene;
}

INSTANTIATE_TEST_SUITE_P(
    GaussSeidel, VelocityToleranceTest,
    ::testing::Combine(::testing::ValuesIn(SupportedStepTargets()),
                       ::testing::Values("cartpole", "ragdoll", "box-pile", "more_types"),
                       ::testing::Values(JointSolver::kGaussSeidel)),
    CaseName);

// The exact solve's passes of block Gauss-Seidel around the joints solved at
// once (motors, limits, contacts; more_types: cone rows, six-DOF rows beside
// their groups, and the distance, pulley, path and six-DOF constraints
// solved whole): scenes that have such rows.
INSTANTIATE_TEST_SUITE_P(
    Exact, VelocityToleranceTest,
    ::testing::Combine(::testing::ValuesIn(SupportedStepTargets()),
                       ::testing::Values("ragdoll", "quadruped", "more_types"),
                       ::testing::Values(JointSolver::kExact)),
    CaseName);

TEST(VelocityToleranceSettings, BadTolerancesAreRefusedNamingTheFieldBeforeAnythingIsWritten) {
  Batch batch(MakeScene("cartpole"), 4, BatchOptions{1});
  KickEveryWorldDifferently(batch);
  batch.Step({});
  const BatchSnapshot before = batch.Snapshot();
  for (const float bad : {-1e-3f, std::numeric_limits<float>::quiet_NaN(),
                          std::numeric_limits<float>::infinity()}) {
    StepSettings settings;
    settings.velocity_tolerance = bad;
    try {
      batch.Step(settings);
      ADD_FAILURE() << "tolerance " << bad << " was taken";
    } catch (const SceneError& e) {
      EXPECT_NE(std::string(e.what()).find("velocity_tolerance"), std::string::npos) << e.what();
    }
  }
  const BatchSnapshot after = batch.Snapshot();
  EXPECT_TRUE(std::equal(before.bytes().begin(), before.bytes().end(), after.bytes().begin(),
                         after.bytes().end()));
  reference::World<double> world(batch.scene());
  StepSettings negative;
  negative.velocity_tolerance = -1.0f;
  EXPECT_THROW(world.Step(negative), std::invalid_argument);
}

}  // namespace
}  // namespace manyworlds
