// Bad data at run time (issue 7.3, design.md "Correctness"): NaN, infinite or
// huge forces, torques, motor targets and states written into some worlds.
// Those worlds are flagged after the step (Batch::WorldHealth), kept or reset
// as StepSettings::unhealthy_worlds says, and every other world steps
// bit-identically to a run in which nothing bad was written.
//
// Every comparison of healthy worlds is bitwise: worlds never interact, so a
// single differing bit is a leak between lanes, not rounding.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <functional>
#include <limits>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include "hwy/targets.h"
#include "tests/step_targets.h"
#include "manyworlds/batch.h"
#include "manyworlds/error.h"
#include "manyworlds/scenes.h"

namespace manyworlds {
namespace {

namespace rs = reference_scene;

constexpr std::uint64_t kSeed = 99;
constexpr std::size_t kWorlds = 40;  // 3 blocks of 16, the last one partly padding
constexpr int kStepsBefore = 10;     // clean steps before the bad data
constexpr int kStepsAfter = 20;      // steps with and after the bad data
constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

std::vector<float> StateOf(const Batch& batch) {
  std::vector<float> state(batch.world_count() * batch.body_count() * kStateFloatsPerBody);
  batch.GetState(state);
  return state;
}

std::size_t FloatsPerWorld(const Batch& batch) {
  return batch.body_count() * kStateFloatsPerBody;
}

bool SameWorld(const std::vector<float>& a, const std::vector<float>& b, std::size_t world,
               std::size_t floats_per_world) {
  return std::memcmp(a.data() + world * floats_per_world, b.data() + world * floats_per_world,
                     floats_per_world * sizeof(float)) == 0;
}

// One way of writing bad data into one world, with the health bits it must
// raise in the step that follows, and those it may raise besides (a NaN
// target can be clamped into a finite motor impulse, or not, by the target's
// min/max; an infinite torque gives NaN or infinite velocities).
struct Injection {
  std::string name;
  std::function<void(Batch&, std::size_t world)> inject;
  std::uint8_t expected_bits;
  std::uint8_t may_also = 0;
};

// Worlds 0 (lane 0, so also the lane that scene-uniform lane reads use), 17
// (mid-block) and 39 (last real world, next to padding) get the bad data.
const std::set<std::size_t> kBadWorlds = {0, 17, 39};

// The first dynamic body free in every degree of freedom: a NaN force or
// torque on a locked axis (the hopper's torso turns only about Z) is flagged
// as input but never reaches the state, so the injections need a free body.
std::size_t FirstDynamicBody(const Scene& scene) {
  for (std::size_t b = 0; b < scene.bodies().size(); ++b) {
    if (scene.bodies()[b].motion_type == MotionType::kDynamic &&
        scene.bodies()[b].allowed_dofs == AllowedDofs::kAll) {
      return b;
    }
  }
  return 0;
}

// The state of one world with one number replaced.
std::function<void(Batch&, std::size_t)> SetStateValue(std::size_t body, std::size_t index,
                                                       float value) {
  return [=](Batch& batch, std::size_t world) {
    std::vector<float> state = StateOf(batch);
    state[(world * batch.body_count() + body) * kStateFloatsPerBody + index] = value;
    std::vector<std::uint8_t> mask(batch.world_count(), 0);
    mask[world] = 1;
    batch.SetState(state, mask);
  };
}

std::vector<Injection> InjectionsFor(const std::string& scene_id, const Scene& scene) {
  const std::size_t body = FirstDynamicBody(scene);
  std::vector<Injection> injections = {
      {"NaN force", [=](Batch& b, std::size_t w) { b.SetForce(w, body, {kNaN, 0, 0}); },
       kNonFiniteInput | kNonFiniteState},
      {"infinite torque", [=](Batch& b, std::size_t w) { b.SetTorque(w, body, {0, 0, kInf}); },
       kNonFiniteInput | kNonFiniteState, kVelocityOverflow},
      // Zero torque in every other world: what they get anyway (no scene's
      // actions are torques).
      {"NaN torque, span form for every world",
       [=](Batch& b, std::size_t) {
         std::vector<float> torques(b.world_count() * 3, 0.0f);
         for (const std::size_t bad : kBadWorlds) torques[bad * 3 + 1] = kNaN;
         b.SetTorques(body, torques);
       },
       kNonFiniteInput | kNonFiniteState},
      // 1e30 N on a body of 0.1-2 kg for 1/60 s: |v|^2 ~ 1e56 overflows float.
      {"1e30 N force", [=](Batch& b, std::size_t w) { b.SetForce(w, body, {1e30f, 0, 0}); },
       kVelocityOverflow},
      {"NaN position", SetStateValue(body, 1, kNaN), kNonFiniteState},
      // |w|^2 = inf in the force step: also the overflow bit.
      {"infinite angular velocity", SetStateValue(body, 12, -kInf),
       kNonFiniteState | kVelocityOverflow},
      // 2^24 m is where float spacing reaches 1 m (kMaxHealthyCoordinate).
      {"position at 1e9 m", SetStateValue(body, 0, 1e9f), kPositionOutOfRange,
       kNonFiniteState | kVelocityOverflow},
  };
  if (scene_id == "geartrain" || scene_id == "rackpinion") {
    const std::size_t motor = scene_id == "geartrain" ? rs::kGear1Hinge : rs::kPinionHinge;
    injections.push_back({"NaN motor target velocity",
                          [=](Batch& b, std::size_t w) { b.SetTargetVelocity(w, motor, kNaN); },
                          kNonFiniteInput, kNonFiniteState});
  }
  return injections;
}

// Steps `batch` with the scene's actions; before step kStepsBefore, `inject`
// writes bad data into `bad_worlds`. Returns the state after every step.
std::vector<std::vector<float>> RunWithInjection(Batch& batch, const SceneActions& actions,
                                    const StepSettings& settings,
                                    const std::set<std::size_t>& bad_worlds,
                                    const Injection* injection,
                                    std::vector<std::vector<std::uint8_t>>* health = nullptr) {
  std::vector<std::vector<float>> states;
  for (int step = 0; step < kStepsBefore + kStepsAfter; ++step) {
    actions.Apply(batch, static_cast<std::uint64_t>(step), kSeed);
    if (step == kStepsBefore && injection != nullptr) {
      for (const std::size_t w : bad_worlds) injection->inject(batch, w);
    }
    batch.Step(settings);
    states.push_back(StateOf(batch));
    if (health != nullptr) {
      const auto flags = batch.WorldHealth();
      health->emplace_back(flags.begin(), flags.end());
    }
  }
  return states;
}

// Scene id, Highway target bit: the health check is SIMD code, so it runs on
// every target this CPU supports.
class HealthTest
    : public ::testing::TestWithParam<std::tuple<std::string, std::int64_t>> {};


TEST_P(HealthTest, BadWorldsAreFlaggedAndEveryOtherWorldKeepsItsBits) {
  const auto& [scene_id, target] = GetParam();
  const Scene scene = MakeScene(scene_id);
  const SceneActions actions(scene_id);
  BatchOptions options;
  options.target = target;
  for (const UnhealthyWorlds policy : {UnhealthyWorlds::kKeep, UnhealthyWorlds::kReset}) {
    StepSettings settings;
    settings.unhealthy_worlds = policy;
    Batch clean_batch(scene, kWorlds, options);
    const auto clean = RunWithInjection(clean_batch, actions, settings, {}, nullptr);
    EXPECT_EQ(clean_batch.UnhealthyWorldCount(), 0u);

    for (const Injection& injection : InjectionsFor(scene_id, scene)) {
      SCOPED_TRACE(injection.name + (policy == UnhealthyWorlds::kKeep ? ", keep" : ", reset"));
      Batch batch(scene, kWorlds, options);
      std::vector<std::vector<std::uint8_t>> health;
      const auto bad = RunWithInjection(batch, actions, settings, kBadWorlds, &injection, &health);
      const std::size_t floats = FloatsPerWorld(batch);
      for (int step = 0; step < kStepsBefore + kStepsAfter; ++step) {
        for (std::size_t w = 0; w < kWorlds; ++w) {
          if (kBadWorlds.count(w) != 0 && step >= kStepsBefore) continue;
          ASSERT_TRUE(SameWorld(bad[step], clean[step], w, floats))
              << "world " << w << " differs from the clean run after step " << step;
          ASSERT_EQ(health[step][w], 0) << "healthy world " << w << " flagged at step " << step;
        }
      }
      // The step that saw the bad data flags exactly the expected bits.
      for (const std::size_t w : kBadWorlds) {
        EXPECT_EQ(health[kStepsBefore][w] & ~injection.may_also, injection.expected_bits)
            << "world " << w << ": bits " << int(health[kStepsBefore][w]);
      }
      if (policy == UnhealthyWorlds::kReset) {
        // Reset right after the flagged step: the scene's initial state, then
        // stepping on as a fresh world (its later steps may be anything finite).
        const Batch fresh(scene, kWorlds, options);
        const std::vector<float> initial = StateOf(fresh);
        for (const std::size_t w : kBadWorlds) {
          EXPECT_TRUE(SameWorld(bad[kStepsBefore], initial, w, floats))
              << "world " << w << " was not reset to the scene's initial state";
          for (int step = kStepsBefore + 1; step < kStepsBefore + kStepsAfter; ++step) {
            EXPECT_EQ(health[step][w], 0) << "reset world " << w << " at step " << step;
          }
        }
      } else if ((injection.expected_bits & kNonFiniteState) != 0) {
        // Kept: a NaN world stays NaN, and stays flagged, until the user resets it.
        for (const std::size_t w : kBadWorlds) {
          EXPECT_NE(health.back()[w] & kNonFiniteState, 0) << "world " << w;
        }
        std::vector<std::uint8_t> mask(kWorlds, 0);
        for (const std::size_t w : kBadWorlds) mask[w] = 1;
        batch.Reset(mask);
        EXPECT_EQ(batch.UnhealthyWorldCount(), 0u) << "Reset clears the flags";
      }
    }
  }
}

INSTANTIATE_TEST_SUITE_P(
    ReferenceScenes, HealthTest,
    ::testing::Combine(::testing::Values("cartpole", "chain16", "rackpinion", "geartrain", "ragdoll",
                                         "box-drop", "sphere-roll", "pile", "box-pile", "hopper"),
                       ::testing::ValuesIn(SupportedStepTargets())),
    [](const auto& info) {
      std::string name = std::get<0>(info.param) + "_" + hwy::TargetName(std::get<1>(info.param));
      for (char& c : name) c = c == '-' ? '_' : c;  // a test name
      return name;
    });

TEST(HealthTest, OverflowedVelocityIsFlaggedButKeptFiniteAsJoltClampsIt) {
  // Jolt's clamp v *= v_max / |v| gives 0 when |v|^2 overflows: the world stays
  // finite, so only the flag tells the user that its force was absurd.
  const Scene scene = MakeReferenceScene("cartpole");
  Batch batch(scene, 4);
  batch.SetForce(2, rs::kCart, {1e30f, 0, 0});
  batch.Step(StepSettings{});
  EXPECT_EQ(batch.WorldHealth()[2], kVelocityOverflow);
  EXPECT_EQ(batch.UnhealthyWorldCount(), 1u);
  const std::vector<float> state = StateOf(batch);
  for (const float v : state) EXPECT_TRUE(std::isfinite(v));
  // The flag describes the last step only: a clean step clears it.
  batch.Step(StepSettings{});
  EXPECT_EQ(batch.UnhealthyWorldCount(), 0u);
}

TEST(HealthTest, ZeroRotationIsRefusedBeforeAnythingIsWritten) {
  const Scene scene = MakeReferenceScene("chain16");
  Batch batch(scene, 20);
  batch.Step(StepSettings{});
  const std::vector<float> before = StateOf(batch);
  std::vector<float> state = before;
  for (float& v : state) v += 0.5f;  // every world changed...
  float* rotation = state.data() + (19 * batch.body_count() + 3) * kStateFloatsPerBody + 3;
  for (int i = 0; i < 4; ++i) rotation[i] = 0.0f;  // ...and one rotation zero
  try {
    batch.SetState(state);
    ADD_FAILURE() << "a zero rotation was accepted";
  } catch (const SceneError& error) {
    EXPECT_NE(std::string(error.what()).find("world 19"), std::string::npos) << error.what();
  }
  std::vector<std::uint8_t> mask(20, 1);
  EXPECT_THROW(batch.ResetTo(mask, state), SceneError);
  EXPECT_EQ(std::memcmp(StateOf(batch).data(), before.data(), before.size() * sizeof(float)), 0)
      << "a refused SetState or ResetTo changed the batch";
}

}  // namespace
}  // namespace manyworlds
