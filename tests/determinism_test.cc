// Determinism of the batch (design.md, scenes-and-metrics.md "Determinism"):
// a world's bits after N steps do not depend on the thread count, on how
// blocks are split into tasks, on the lane or block it sits in, or on its
// neighbours; resetting or changing world i changes no bit of world j.
//
// Every comparison here is exact (bitwise): worlds never interact, so any
// difference is a bug, not rounding.

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "hwy/targets.h"
#include "manyworlds/batch.h"
#include "manyworlds/error.h"
#include "manyworlds/scenes.h"

namespace manyworlds {
namespace {

constexpr std::uint64_t kSeed = 12345;
constexpr int kSteps = 40;

// Makes worlds differ from the start: a small per-world velocity kick on
// every moving body (deterministic in the world index).
std::vector<float> DistinctStates(const Batch& batch) {
  std::vector<float> state(batch.world_count() * batch.body_count() * kStateFloatsPerBody);
  batch.GetState(state);
  for (std::size_t w = 0; w < batch.world_count(); ++w) {
    std::mt19937 random(static_cast<unsigned>(w) * 7919u + 1u);
    std::uniform_real_distribution<float> kick(-0.2f, 0.2f);
    for (std::size_t b = 0; b < batch.body_count(); ++b) {
      if (batch.scene().bodies()[b].motion_type != MotionType::kDynamic) continue;
      float* body = state.data() + (w * batch.body_count() + b) * kStateFloatsPerBody;
      for (int i = 7; i < 13; ++i) body[i] += kick(random);
    }
  }
  return state;
}

// Steps `batch` with the scene's actions from step `first` on, world w
// getting the actions of world index_of(w).
template <class IndexOf>
void StepWithActions(Batch& batch, const SceneActions& actions, int steps, IndexOf index_of,
                     int first = 0) {
  StepSettings settings;
  for (int step = first; step < first + steps; ++step) {
    for (std::size_t w = 0; w < batch.world_count(); ++w) {
      for (std::size_t i = 0; i < actions.forces_per_world(); ++i) {
        const BodyForce f = actions.Force(i, index_of(w), static_cast<std::uint64_t>(step), kSeed);
        batch.SetForce(w, f.body, f.force);
      }
      for (std::size_t i = 0; i < actions.targets_per_world(); ++i) {
        const MotorTarget t =
            actions.Target(i, index_of(w), static_cast<std::uint64_t>(step), kSeed);
        batch.SetTargetPosition(w, t.constraint, t.position);
      }
    }
    batch.Step(settings);
  }
}

std::vector<float> StateOf(const Batch& batch) {
  std::vector<float> state(batch.world_count() * batch.body_count() * kStateFloatsPerBody);
  batch.GetState(state);
  return state;
}

// Bitwise equality of world `a` of one state array and world `b` of another.
bool SameWorld(const std::vector<float>& sa, std::size_t a, const std::vector<float>& sb,
               std::size_t b, std::size_t floats_per_world) {
  return std::memcmp(sa.data() + a * floats_per_world, sb.data() + b * floats_per_world,
                     floats_per_world * sizeof(float)) == 0;
}

class DeterminismTest : public ::testing::TestWithParam<std::string> {};

TEST_P(DeterminismTest, ThreadsAndTaskSplitsGiveIdenticalBits) {
  const Scene scene = MakeScene(GetParam());
  const SceneActions actions(GetParam());
  const std::size_t worlds = 200;  // 13 blocks, the last one partly padding
  auto identity = [](std::size_t w) { return w; };

  std::vector<std::vector<float>> results;
  for (const BatchOptions options : {BatchOptions{1, 0}, BatchOptions{2, 0},
                                     BatchOptions{2, 1}, BatchOptions{2, 5}}) {
    Batch batch(scene, worlds, options);
    batch.SetState(DistinctStates(batch));
    StepWithActions(batch, actions, kSteps, identity);
    results.push_back(StateOf(batch));
  }
  for (std::size_t i = 1; i < results.size(); ++i) {
    EXPECT_EQ(0, std::memcmp(results[0].data(), results[i].data(),
                             results[0].size() * sizeof(float)))
        << "options set " << i << " differs from 1 thread";
  }
}

TEST_P(DeterminismTest, AWorldIsTheSameInAnyLaneAloneOrAmongOthers) {
  const Scene scene = MakeScene(GetParam());
  const SceneActions actions(GetParam());
  const std::size_t worlds = 37;
  Batch many(scene, worlds);
  const std::vector<float> start = DistinctStates(many);
  many.SetState(start);
  StepWithActions(many, actions, kSteps, [](std::size_t w) { return w; });
  const std::vector<float> reference = StateOf(many);
  const std::size_t per_world = many.body_count() * kStateFloatsPerBody;

  // World k alone in a batch of one (lane 0, padding neighbours), and world k
  // moved to lane (k + 5) % 37 of a batch whose worlds are rotated.
  for (const std::size_t k : {std::size_t{0}, std::size_t{3}, std::size_t{17}, std::size_t{36}}) {
    Batch alone(scene, 1);
    alone.SetState(std::vector<float>(start.begin() + k * per_world,
                                      start.begin() + (k + 1) * per_world));
    StepWithActions(alone, actions, kSteps, [k](std::size_t) { return k; });
    EXPECT_TRUE(SameWorld(StateOf(alone), 0, reference, k, per_world)) << "world " << k;
  }
  Batch rotated(scene, worlds);
  std::vector<float> rotated_start(start.size());
  auto source = [&](std::size_t w) { return (w + worlds - 5) % worlds; };
  for (std::size_t w = 0; w < worlds; ++w) {
    std::memcpy(rotated_start.data() + w * per_world, start.data() + source(w) * per_world,
                per_world * sizeof(float));
  }
  rotated.SetState(rotated_start);
  StepWithActions(rotated, actions, kSteps, source);
  const std::vector<float> rotated_end = StateOf(rotated);
  for (std::size_t w = 0; w < worlds; ++w) {
    EXPECT_TRUE(SameWorld(rotated_end, w, reference, source(w), per_world))
        << "world " << source(w) << " in lane " << w % 16 << " of block " << w / 16;
  }
}

// A block steps in its thread's working block, whose scratch (what setup
// recomputes) the thread reuses for every block of every batch it steps
// (batch/working_block.h). What another scene's batch left there changes no
// bit: both batches on one thread, the other stepped before each step.
TEST_P(DeterminismTest, ScratchLeftByAnotherBatchChangesNoBit) {
  const Scene scene = MakeScene(GetParam());
  const SceneActions actions(GetParam());
  const std::string other_id = GetParam() == "ragdoll" ? "quadruped" : "ragdoll";
  const SceneActions other_actions(other_id);
  auto identity = [](std::size_t w) { return w; };
  const BatchOptions one_thread{1, 0};
  Batch alone(scene, 20, one_thread), interleaved(scene, 20, one_thread);
  Batch other(MakeScene(other_id), 40, one_thread);
  const std::vector<float> start = DistinctStates(alone);
  alone.SetState(start);
  interleaved.SetState(start);
  other.SetState(DistinctStates(other));
  StepWithActions(alone, actions, kSteps, identity);
  for (int step = 0; step < kSteps; ++step) {
    StepWithActions(other, other_actions, 1, identity, step);
    StepWithActions(interleaved, actions, 1, identity, step);
  }
  const std::vector<float> a = StateOf(alone), b = StateOf(interleaved);
  ASSERT_EQ(a.size(), b.size());
  EXPECT_EQ(0, std::memcmp(a.data(), b.data(), a.size() * sizeof(float)));
}

TEST_P(DeterminismTest, ResettingOrChangingOneWorldLeavesTheOthersBitIdentical) {
  const Scene scene = MakeScene(GetParam());
  const SceneActions actions(GetParam());
  const std::size_t worlds = 40;
  Batch plain(scene, worlds), touched(scene, worlds);
  const std::vector<float> start = DistinctStates(plain);
  plain.SetState(start);
  touched.SetState(start);
  auto identity = [](std::size_t w) { return w; };
  StepWithActions(plain, actions, kSteps / 2, identity);
  StepWithActions(touched, actions, kSteps / 2, identity);

  // World 3 reset, world 20 heavier (the first dynamic body), world 21 given
  // a new state; the rest must not notice.
  std::vector<std::uint8_t> mask(worlds, 0);
  mask[3] = 1;
  touched.Reset(mask);
  std::size_t dynamic = 0;
  while (scene.bodies()[dynamic].motion_type != MotionType::kDynamic) ++dynamic;
  touched.SetMassProperties(20, dynamic, 3.0f, {1.0f, 2.0f, 3.0f});
  std::size_t last_dynamic = scene.bodies().size() - 1;
  while (scene.bodies()[last_dynamic].motion_type != MotionType::kDynamic) --last_dynamic;
  std::vector<float> state = StateOf(touched);
  const std::size_t per_world = touched.body_count() * kStateFloatsPerBody;
  state[21 * per_world + last_dynamic * kStateFloatsPerBody + 0] += 0.01f;  // moved 1 cm
  std::vector<std::uint8_t> only21(worlds, 0);
  only21[21] = 1;
  touched.SetState(state, only21);

  StepWithActions(plain, actions, kSteps / 2, identity);
  StepWithActions(touched, actions, kSteps / 2, identity);
  const std::vector<float> a = StateOf(plain), b = StateOf(touched);
  for (std::size_t w = 0; w < worlds; ++w) {
    if (w == 3 || w == 20 || w == 21) {
      EXPECT_FALSE(SameWorld(a, w, b, w, per_world)) << "the change to world " << w
                                                     << " had no effect";
    } else {
      EXPECT_TRUE(SameWorld(a, w, b, w, per_world)) << "world " << w << " changed";
    }
  }
}

// AVX3 (16 lanes) and AVX2 (8 lanes) both fuse multiply-adds and run every
// lane through the same operations, so a world's bits must not depend on
// which of the two a machine dispatches: a trajectory recorded on one
// replays on the other. (SSE4 and the scalar target have no FMA: their bits
// differ, docs/testing.md.)
TEST_P(DeterminismTest, Avx2AndAvx3GiveIdenticalBits) {
  const Scene scene = MakeScene(GetParam());
  const SceneActions actions(GetParam());
  std::vector<std::vector<float>> results;
  for (const std::int64_t target : {std::int64_t{HWY_AVX3}, std::int64_t{HWY_AVX2}}) {
    BatchOptions options;
    options.target = target;
    try {
      Batch batch(scene, 37, options);
      batch.SetState(DistinctStates(batch));
      StepWithActions(batch, actions, 200, [](std::size_t w) { return w; });
      results.push_back(StateOf(batch));
    } catch (const SceneError&) {
      GTEST_SKIP() << hwy::TargetName(target) << " is not supported here";
    }
  }
  EXPECT_EQ(0, std::memcmp(results[0].data(), results[1].data(),
                           results[0].size() * sizeof(float)));
}

INSTANTIATE_TEST_SUITE_P(ReferenceScenes, DeterminismTest,
                         ::testing::Values("cartpole", "chain16", "rackpinion", "geartrain", "ragdoll",
                                           "box-drop", "sphere-roll", "pile", "box-stack", "box-pile",
                                           "hopper"),
                         [](const auto& info) {
                           std::string name = info.param;
                           for (char& c : name) c = c == '-' ? '_' : c;  // a test name
                           return name;
                         });

}  // namespace
}  // namespace manyworlds
