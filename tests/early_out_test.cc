// The step skips work a block does not need (docs/stepping.md, "Work skipped
// where no world of a block needs it"): the hinge axes' repair, a rotation
// step, a velocity clamp or a friction clamp no lane takes, the position
// step of a rotation-only part whose error is exactly zero in every world,
// and the velocity step of a part whose -J v is exactly zero in every world.
// The decision is made per block (or per chunk) from all of its worlds, so a
// world's bits must never depend on whether its neighbours needed the work.
//
// Each test steps two full blocks and a half one whose worlds are
// triplets: world w, w + 16 and w + 32 (w < 8) start alike and get the same
// forces every step. Then one world of the first block and every real world
// of the third are given a state that needs the skipped work. Every other
// world of the first block must end bit for bit equal to its twin in the
// second block (which skipped the work), and the odd world equal to its twin
// in the third (a block with padding lanes, where no world can have skipped
// it). Run on every target: the position steps are skipped per block on
// every target, the other work per chunk (AVX3: 16 lanes, AVX2: 8, SSE4: 4,
// scalar: 1).

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <functional>
#include <string>
#include <vector>

#include "manyworlds/batch.h"
#include "manyworlds/scenes.h"
#include "tests/step_targets.h"

namespace manyworlds {
namespace {

namespace rs = reference_scene;

constexpr std::size_t kBlock = 16;
constexpr std::size_t kWorlds = 2 * kBlock + kBlock / 2;  // the last block half padding
constexpr std::size_t kOddWorld = 5;  // in the first block
static_assert(kOddWorld + 2 * kBlock < kWorlds, "the odd world's twin in the third block");
constexpr int kSteps = 60;

// State row of one body of one world: position 0-2, rotation 3-6 (x, y, z,
// w), linear velocity 7-9, angular velocity 10-12.
float* Row(std::vector<float>& state, std::size_t bodies, std::size_t world, std::size_t body) {
  return state.data() + (world * bodies + body) * kStateFloatsPerBody;
}

// Turns the body's rotation by `angle` about the world X axis.
void TurnAboutX(float* row, float angle) {
  const float s = std::sin(angle / 2), c = std::cos(angle / 2);
  const float x = row[3], y = row[4], z = row[5], w = row[6];
  // (s, 0, 0, c) * (x, y, z, w)
  row[3] = c * x + s * w;
  row[4] = c * y - s * z;
  row[5] = c * z + s * y;
  row[6] = c * w - s * x;
}

// Steps the triplets with `change(state row array, body count, world)`
// applied to the odd world and to the third block's worlds, forces from
// `force(world index within its block, step)` on `body`, and compares.
void ExpectTwinsAgree(const std::string& scene_id, std::int64_t target, std::size_t body,
                      const std::function<void(std::vector<float>&, std::size_t, std::size_t)>& change,
                      const std::function<Float3(std::size_t, int)>& force) {
  const Scene scene = MakeScene(scene_id);
  BatchOptions options;
  options.target = target;
  Batch batch(scene, kWorlds, options);
  const std::size_t bodies = scene.bodies().size();
  std::vector<float> state(kWorlds * bodies * kStateFloatsPerBody);
  batch.GetState(state);
  change(state, bodies, kOddWorld);
  for (std::size_t w = 2 * kBlock; w < kWorlds; ++w) change(state, bodies, w);
  batch.SetState(state);
  const StepSettings settings = SceneStepSettings(scene_id);
  for (int step = 0; step < kSteps; ++step) {
    for (std::size_t w = 0; w < kWorlds; ++w) batch.SetForce(w, body, force(w % kBlock, step));
    batch.Step(settings);
  }
  batch.GetState(state);
  EXPECT_EQ(batch.UnhealthyWorldCount(), 0u);
  const std::size_t bytes = bodies * kStateFloatsPerBody * sizeof(float);
  const auto same = [&](std::size_t a, std::size_t b) {
    return std::memcmp(Row(state, bodies, a, 0), Row(state, bodies, b, 0), bytes) == 0;
  };
  for (std::size_t w = 0; w < kBlock; ++w) {
    if (w == kOddWorld) continue;
    EXPECT_TRUE(same(w, w + kBlock)) << "world " << w << " differs from its twin " << w + kBlock
                                     << ", whose block skipped the work";
  }
  EXPECT_TRUE(same(kOddWorld, kOddWorld + 2 * kBlock))
      << "world " << kOddWorld << " differs from its twin " << kOddWorld + 2 * kBlock
      << ", whose block did the work in every world";
  // The odd world did go another way, or the test exercised nothing.
  EXPECT_FALSE(same(kOddWorld, kOddWorld + kBlock));
}

// A cart force that differs by world and step, the same for twins.
Float3 CartForce(std::size_t world, int step) {
  return {std::sin(0.7f * float(world) + 0.1f * float(step)) * 8.0f, 0.0f, 0.0f};
}

Float3 NoForce(std::size_t, int) { return {0.0f, 0.0f, 0.0f}; }

class EarlyOutTest : public ::testing::TestWithParam<std::int64_t> {};

// Cartpole is planar: its hinge axes stay exactly aligned and its cart never
// turns, so the hinge-rotation and slider-rotation position steps and most
// rotation steps are skipped. A pole tilted out of the plane needs them all.
TEST_P(EarlyOutTest, PoleTiltedOutOfThePlane) {
  ExpectTwinsAgree(
      "cartpole", GetParam(), rs::kCart,
      [](std::vector<float>& state, std::size_t bodies, std::size_t world) {
        TurnAboutX(Row(state, bodies, world, rs::kPole), 0.3f);
      },
      CartForce);
}

// A pole turned 115 degrees about X has its hinge axis more than 90 degrees
// from the cart's: Jolt's axes repair, which no other world needs.
TEST_P(EarlyOutTest, HingeAxesRepairedInOneWorld) {
  ExpectTwinsAgree(
      "cartpole", GetParam(), rs::kCart,
      [](std::vector<float>& state, std::size_t bodies, std::size_t world) {
        TurnAboutX(Row(state, bodies, world, rs::kPole), 2.0f);
      },
      CartForce);
}

// A cart moving faster than its velocity limit (500 m/s, Jolt's default) is
// clamped in the force step and again at integration; no other world is.
TEST_P(EarlyOutTest, VelocityClampedInOneWorld) {
  ExpectTwinsAgree(
      "cartpole", GetParam(), rs::kCart,
      [](std::vector<float>& state, std::size_t bodies, std::size_t world) {
        Row(state, bodies, world, rs::kCart)[7] = 900.0f;
      },
      CartForce);
}

// rackpinion turns its pinion about a fixed axle through its centre and
// slides its rack exactly along its rail: the velocity steps of the pinion
// hinge's point part, the rail's two rows and the rack's rotation rows see
// -J v = 0 in every world and are skipped. A rack knocked off its rail and
// turned, and a pinion pushed off its axle, need them all.
TEST_P(EarlyOutTest, RackKnockedOffItsRailInOneWorld) {
  ExpectTwinsAgree(
      "rackpinion", GetParam(), rs::kRack,
      [](std::vector<float>& state, std::size_t bodies, std::size_t world) {
        float* rack = Row(state, bodies, world, rs::kRack);
        rack[8] = 0.3f;   // linear velocity off the rail (Y)
        rack[12] = 0.5f;  // turning about Z
        Row(state, bodies, world, rs::kPinion)[7] = 0.2f;
      },
      CartForce);
}

// geartrain's gears turn about their centres: the hinges' point parts are
// skipped in every world but one whose gear was pushed off its axle (a
// lever arm that turns with the gear, corrected a fifth per iteration).
TEST_P(EarlyOutTest, GearPushedOffItsAxleInOneWorld) {
  ExpectTwinsAgree(
      "geartrain", GetParam(), rs::kGear2,
      [](std::vector<float>& state, std::size_t bodies, std::size_t world) {
        float* gear = Row(state, bodies, world, rs::kGear2);
        gear[1] += 0.01f;
        gear[8] = -0.4f;
      },
      NoForce);
}

// box-drop's boxes land and rest; one box thrown sideways slides, so its
// friction impulse is clamped to the friction circle.
TEST_P(EarlyOutTest, FrictionClampedInOneWorld) {
  ExpectTwinsAgree(
      "box-drop", GetParam(), 1,
      [](std::vector<float>& state, std::size_t bodies, std::size_t world) {
        float* box = Row(state, bodies, world, 1);
        box[7] = 6.0f;
        box[9] = -3.0f;
      },
      NoForce);
}

INSTANTIATE_TEST_SUITE_P(EveryTarget, EarlyOutTest,
                         ::testing::ValuesIn(SupportedStepTargets()),
                         [](const auto& info) { return std::string(hwy::TargetName(info.param)); });

}  // namespace
}  // namespace manyworlds
