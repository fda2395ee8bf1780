// BatchOptions::profile_phases (batch.h, PhaseProfile): the profiled step
// gives every bit of the plain one; the profile counts every block and world
// stepped, times every phase the scene has, never more than the threads
// could have spent, and is zero without profiling or after a reset.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <chrono>
#include <cstring>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

#include "manyworlds/batch.h"
#include "manyworlds/scenes.h"

namespace manyworlds {
namespace {

constexpr int kSteps = 20;

std::vector<std::byte> Bytes(const Batch& batch) {
  const BatchSnapshot snapshot = batch.Snapshot();
  return {snapshot.bytes().begin(), snapshot.bytes().end()};
}

class PhaseProfileTest : public ::testing::TestWithParam<std::tuple<std::string, int>> {};

TEST_P(PhaseProfileTest, ProfiledStepKeepsEveryBitAndCountsEveryPhase) {
  const auto& [id, threads] = GetParam();
  const std::size_t worlds = 1030;  // 65 blocks, the last one partial
  const Scene scene = MakeScene(id);
  const SceneActions actions(id);
  const StepSettings settings = SceneStepSettings(id);
  BatchOptions options;
  options.threads = threads;
  Batch plain(scene, worlds, options);
  options.profile_phases = true;
  Batch profiled(scene, worlds, options);
  const auto start = std::chrono::steady_clock::now();
  for (int step = 0; step < kSteps; ++step) {
    actions.Apply(plain, std::uint64_t(step), 3);
    actions.Apply(profiled, std::uint64_t(step), 3);
    plain.Step(settings);
    profiled.Step(settings);
  }
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const std::vector<std::byte> plain_bytes = Bytes(plain), profiled_bytes = Bytes(profiled);
  ASSERT_EQ(plain_bytes.size(), profiled_bytes.size());
  EXPECT_EQ(std::memcmp(plain_bytes.data(), profiled_bytes.data(), plain_bytes.size()), 0);

  const PhaseProfile profile = profiled.GetPhaseProfile();
  EXPECT_EQ(profile.world_steps, std::uint64_t(kSteps) * worlds);
  EXPECT_EQ(profile.block_steps, std::uint64_t(kSteps) * ((worlds + 15) / 16));
  double total = 0.0;
  for (std::size_t p = 0; p < kStepPhaseCount; ++p) {
    // Every scene here has dynamic bodies and constraints: every phase runs.
    EXPECT_GT(profile.seconds[p], 0.0) << StepPhaseName(StepPhase(p));
    total += profile.seconds[p];
  }
  // Phases are timed inside each block's task: their sum cannot exceed what
  // the threads had (both batches' steps ran within `wall`).
  EXPECT_LE(total, wall * threads);

  const PhaseProfile none = plain.GetPhaseProfile();
  EXPECT_EQ(none.world_steps, 0u);
  for (double seconds : none.seconds) EXPECT_EQ(seconds, 0.0);
  profiled.ResetPhaseProfile();
  const PhaseProfile reset = profiled.GetPhaseProfile();
  EXPECT_EQ(reset.block_steps, 0u);
  for (double seconds : reset.seconds) EXPECT_EQ(seconds, 0.0);
}

INSTANTIATE_TEST_SUITE_P(ScenesAndThreads, PhaseProfileTest,
                         ::testing::Combine(::testing::Values("cartpole", "ragdoll"),
                                            ::testing::Values(1, 2)));

TEST(PhaseProfileTest, PhasesHaveNames) {
  const std::vector<std::string> names = {"forces",      "setup",    "warm_start", "velocity",
                                          "integration", "position", "finish"};
  for (std::size_t p = 0; p < kStepPhaseCount; ++p) {
    EXPECT_EQ(StepPhaseName(StepPhase(p)), names[p]);
  }
  EXPECT_THROW(StepPhaseName(StepPhase(kStepPhaseCount)), std::invalid_argument);
}

}  // namespace
}  // namespace manyworlds
