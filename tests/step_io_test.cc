// Batch::Step(settings, io) (batch.h, StepIo): resets and observation reads
// inside the step's pass over each block give exactly the bits of the
// separate calls Step; Reset or ResetTo; GetState; GetJointCoordinates, on
// one and several threads; a refused call changes and writes nothing; a
// world with bad inputs is flagged and leaks into no other world.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <stdexcept>
#include <stop_token>
#include <string>
#include <tuple>
#include <vector>

#include "manyworlds/batch.h"
#include "manyworlds/error.h"
#include "manyworlds/scenes.h"

namespace manyworlds {
namespace {

using ::testing::HasSubstr;

constexpr int kSteps = 30;
constexpr std::uint64_t kSeed = 11;

// Bitwise (NaN-safe, -0 != +0).
template <class T>
bool SameBits(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0;
}

std::vector<std::byte> Bytes(const Batch& batch) {
  const BatchSnapshot snapshot = batch.Snapshot();  // bytes() is a view into it
  return {snapshot.bytes().begin(), snapshot.bytes().end()};
}

std::vector<float> StateOf(const Batch& batch) {
  std::vector<float> state(batch.world_count() * batch.body_count() * kStateFloatsPerBody);
  batch.GetState(state);
  return state;
}

// About `rate` of the worlds, drawn per step.
std::vector<std::uint8_t> DoneMask(std::size_t worlds, double rate, std::mt19937_64& rng) {
  std::bernoulli_distribution done(rate);
  std::vector<std::uint8_t> mask(worlds);
  for (auto& m : mask) m = done(rng) ? 1 : 0;
  return mask;
}

// Reset states: every world's current state with the positions moved a
// little, so that a ResetTo is told apart from a Reset.
std::vector<float> ShiftedStates(const Batch& batch, float shift) {
  std::vector<float> states = StateOf(batch);
  for (std::size_t i = 0; i < states.size(); i += kStateFloatsPerBody) states[i] += shift;
  return states;
}

struct Case {
  std::string scene;
  std::size_t worlds;
  int threads;
  bool reset_states;  // ResetTo rather than Reset
};

class StepIoTest : public ::testing::TestWithParam<std::tuple<std::string, std::size_t, int, bool>> {
 protected:
  Case Get() const {
    const auto& [scene, worlds, threads, reset_states] = GetParam();
    return {scene, worlds, threads, reset_states};
  }
};

// Two batches, the same actions; one steps with separate calls, the other
// with one fused call. Every step: the state, the joint coordinates, the
// health and the whole snapshot (impulses, targets, step size) agree bit
// for bit.
TEST_P(StepIoTest, FusedCallGivesTheBitsOfTheSeparateCalls) {
  const Case c = Get();
  const Scene scene = MakeScene(c.scene);
  const StepSettings settings = SceneStepSettings(c.scene);
  const SceneActions actions(c.scene);
  BatchOptions options;
  options.threads = c.threads;
  Batch separate(scene, c.worlds, options), fused(scene, c.worlds, options);
  const std::size_t state_floats = c.worlds * separate.body_count() * kStateFloatsPerBody;
  const std::size_t joint_floats = c.worlds * separate.JointCoordinatesPerWorld();
  std::vector<float> state_a(state_floats), state_b(state_floats, -1.0f);
  std::vector<float> joints_a(joint_floats), joints_b(joint_floats, -1.0f);
  std::mt19937_64 rng(kSeed);
  for (int step = 0; step < kSteps; ++step) {
    const std::vector<std::uint8_t> mask = DoneMask(c.worlds, step % 3 == 0 ? 0.3 : 0.05, rng);
    const std::vector<float> states =
        c.reset_states ? ShiftedStates(separate, 0.01f * float(step + 1)) : std::vector<float>{};
    actions.Apply(separate, step, kSeed);
    actions.Apply(fused, step, kSeed);

    separate.Step(settings);
    if (c.reset_states) {
      separate.ResetTo(mask, states);
    } else {
      separate.Reset(mask);
    }
    separate.GetState(state_a);
    separate.GetJointCoordinates(joints_a);

    StepIo io;
    io.reset_mask = mask;
    io.reset_states = states;
    io.state_out = state_b;
    io.joints_out = joints_b;
    ASSERT_TRUE(fused.Step(settings, io));

    ASSERT_TRUE(SameBits(state_a, state_b)) << "step " << step;
    ASSERT_TRUE(SameBits(joints_a, joints_b)) << "step " << step;
    ASSERT_TRUE(std::equal(separate.WorldHealth().begin(), separate.WorldHealth().end(),
                           fused.WorldHealth().begin()))
        << "step " << step;
    if (step % 10 == 9) {  // the whole snapshot: impulses, targets, step size
      ASSERT_TRUE(SameBits(Bytes(separate), Bytes(fused))) << "step " << step;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(
    ScenesAndThreads, StepIoTest,
    ::testing::Combine(::testing::Values("cartpole", "ragdoll"),
                       // 40: a partial last block; 1030: enough blocks for
                       // the read-outs to go parallel as well
                       ::testing::Values(std::size_t{40}, std::size_t{1030}),
                       ::testing::Values(1, 2), ::testing::Bool()));

// Only some outputs, no resets: each output alone equals its separate call.
TEST(StepIoTest, EachPartIsOptional) {
  const Scene scene = MakeScene("cartpole");
  Batch separate(scene, 40), fused(scene, 40);
  std::vector<float> state_a(40 * 3 * kStateFloatsPerBody), state_b(state_a.size());
  std::vector<float> joints_a(40 * separate.JointCoordinatesPerWorld()), joints_b(joints_a.size());
  separate.Step(StepSettings{});
  separate.GetState(state_a);
  StepIo io;
  io.state_out = state_b;
  fused.Step(StepSettings{}, io);
  EXPECT_TRUE(SameBits(state_a, state_b));
  separate.Step(StepSettings{});
  separate.GetJointCoordinates(joints_a);
  io = StepIo{};
  io.joints_out = joints_b;
  fused.Step(StepSettings{}, io);
  EXPECT_TRUE(SameBits(joints_a, joints_b));
  separate.Step(StepSettings{});
  fused.Step(StepSettings{}, StepIo{});
  EXPECT_TRUE(SameBits(Bytes(separate), Bytes(fused)));
}

// Every refusal names the argument, and leaves the batch (snapshot bytes:
// state, impulses, previous step size) and every output untouched.
TEST(StepIoTest, RefusalsChangeAndWriteNothing) {
  const std::size_t worlds = 40;
  Batch batch(MakeScene("cartpole"), worlds);
  batch.Step(StepSettings{});
  const std::size_t state_floats = worlds * batch.body_count() * kStateFloatsPerBody;
  const std::size_t joint_floats = worlds * batch.JointCoordinatesPerWorld();
  std::vector<std::uint8_t> mask(worlds, 1), short_mask(worlds - 1, 1);
  std::vector<float> states = StateOf(batch), short_states(state_floats - 1);
  std::vector<float> zero_rotation = states;
  for (int i = 3; i < 7; ++i) zero_rotation[(7 * 3 + 2) * kStateFloatsPerBody + i] = 0.0f;
  std::vector<float> state_out(state_floats, 7.0f), short_state_out(state_floats + 1, 7.0f);
  std::vector<float> joints_out(joint_floats, 7.0f), short_joints_out(joint_floats - 1, 7.0f);
  StepSettings bad_settings;
  bad_settings.substeps = 0;

  struct Refused {
    StepIo io;
    StepSettings settings;
    const char* message;
  };
  const auto with = [&](auto fill) {
    StepIo io;
    io.state_out = state_out;
    io.joints_out = joints_out;
    fill(io);
    return io;
  };
  const std::vector<Refused> refused = {
      {with([&](StepIo& io) { io.reset_mask = short_mask; }), {}, "reset_mask"},
      {with([&](StepIo& io) { io.reset_states = states; }), {}, "without a reset_mask"},
      {with([&](StepIo& io) {
         io.reset_mask = mask;
         io.reset_states = short_states;
       }),
       {},
       "reset_states"},
      {with([&](StepIo& io) {
         io.reset_mask = mask;
         io.reset_states = zero_rotation;
       }),
       {},
       "in world 7: rotation is zero"},
      {with([&](StepIo& io) { io.state_out = short_state_out; }), {}, "state_out"},
      {with([&](StepIo& io) { io.joints_out = short_joints_out; }), {}, "joints_out"},
      {with([&](StepIo& io) { io.reset_mask = mask; }), bad_settings, "substeps"},
  };
  const std::vector<std::byte> before = Bytes(batch);
  const std::vector<std::uint8_t> health_before(batch.WorldHealth().begin(),
                                                batch.WorldHealth().end());
  for (const Refused& r : refused) {
    // CheckStep refuses exactly what Step refuses (ShardedBatch relies on it).
    try {
      batch.CheckStep(r.settings, r.io);
      ADD_FAILURE() << "CheckStep did not refuse: " << r.message;
    } catch (const std::exception& e) {
      EXPECT_THAT(e.what(), HasSubstr(r.message));
    }
    try {
      batch.Step(r.settings, r.io);
      ADD_FAILURE() << "not refused: " << r.message;
    } catch (const std::exception& e) {
      EXPECT_THAT(e.what(), HasSubstr(r.message));
    }
    EXPECT_TRUE(SameBits(before, Bytes(batch))) << r.message;
    EXPECT_TRUE(std::equal(health_before.begin(), health_before.end(),
                           batch.WorldHealth().begin()));
    EXPECT_TRUE(SameBits(state_out, std::vector<float>(state_floats, 7.0f))) << r.message;
    EXPECT_TRUE(SameBits(joints_out, std::vector<float>(joint_floats, 7.0f))) << r.message;
  }
  // Accepted arguments: CheckStep neither steps nor writes the outputs.
  EXPECT_NO_THROW(batch.CheckStep(StepSettings{}, with([&](StepIo& io) { io.reset_mask = mask; })));
  EXPECT_TRUE(SameBits(before, Bytes(batch)));
  EXPECT_TRUE(SameBits(state_out, std::vector<float>(state_floats, 7.0f)));
}

// A NaN force in one world: that world is flagged, every other world holds
// the bits of a run without it; resetting the world in a later fused step
// clears its flag and brings it back to the scene's initial state.
TEST(StepIoTest, UnhealthyWorldsAreIsolatedAndResetClearsThem) {
  const std::size_t worlds = 40, bad = 21;
  const Scene scene = MakeScene("cartpole");
  const SceneActions actions("cartpole");
  const StepSettings settings = SceneStepSettings("cartpole");
  Batch clean(scene, worlds), dirty(scene, worlds);
  const std::size_t per_world = clean.body_count() * kStateFloatsPerBody;
  std::vector<float> state_clean(worlds * per_world), state_dirty(worlds * per_world);
  const std::vector<float> initial = StateOf(clean);
  std::vector<std::uint8_t> no_reset(worlds, 0), reset_bad(worlds, 0);
  reset_bad[bad] = 1;
  for (int step = 0; step < 6; ++step) {
    actions.Apply(clean, step, kSeed);
    actions.Apply(dirty, step, kSeed);
    if (step == 2) dirty.SetForce(bad, reference_scene::kCart, {NAN, 0.0f, 0.0f});
    StepIo io;
    io.state_out = state_clean;
    io.reset_mask = no_reset;
    clean.Step(settings, io);
    io.state_out = state_dirty;
    io.reset_mask = step == 4 ? reset_bad : no_reset;
    dirty.Step(settings, io);
    for (std::size_t w = 0; w < worlds; ++w) {
      if (w == bad) continue;
      ASSERT_EQ(std::memcmp(&state_clean[w * per_world], &state_dirty[w * per_world],
                            per_world * sizeof(float)),
                0)
          << "world " << w << " step " << step;
      ASSERT_EQ(dirty.WorldHealth()[w], 0) << "world " << w << " step " << step;
    }
    if (step == 2) {
      EXPECT_NE(dirty.WorldHealth()[bad] & kNonFiniteInput, 0);
    }
    if (step == 3) {
      EXPECT_NE(dirty.WorldHealth()[bad] & kNonFiniteState, 0);  // NaN since step 2
    }
  }
  // Reset at step 4, then stepped once (step 5) from the initial state as a
  // fresh world: healthy again. Step 4's output held the initial state.
  EXPECT_EQ(dirty.WorldHealth()[bad], 0);
  for (std::size_t i = 0; i < per_world; ++i) EXPECT_TRUE(std::isfinite(state_dirty[bad * per_world + i]));
}

// A stop requested before the step: no block steps or resets (nothing of
// the batch changes but the kNotStepped flags), and the outputs still hold
// every world as it is.
TEST(StepIoTest, AStoppedStepNeitherStepsNorResetsButWritesOutputs) {
  const std::size_t worlds = 40;
  Batch batch(MakeScene("cartpole"), worlds);
  for (int i = 0; i < 3; ++i) batch.Step(StepSettings{});
  const std::vector<float> before = StateOf(batch);
  std::vector<float> state_out(before.size(), -1.0f);
  std::vector<std::uint8_t> mask(worlds, 1);
  std::stop_source stop;
  stop.request_stop();
  StepIo io;
  io.reset_mask = mask;
  io.state_out = state_out;
  EXPECT_FALSE(batch.Step(StepSettings{}, io, stop.get_token()));
  EXPECT_TRUE(SameBits(before, StateOf(batch)));
  EXPECT_TRUE(SameBits(before, state_out));
  for (std::uint8_t bits : batch.WorldHealth()) EXPECT_EQ(bits, kNotStepped);
}

}  // namespace
}  // namespace manyworlds
