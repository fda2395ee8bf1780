// Batch::GetSolverState / SetSolverState (one world's accumulated impulses,
// hinge turns, remembered directions and kept contact points) and
// reference::World::SolverState / SetSolverState, which share its layout:
//  - a world given another world's bodies and solver state continues exactly
//    as that world, bit for bit: nothing a step reads from the last step is
//    missing from the two;
//  - the layout has the same size on both sides, and a reference world gives
//    back exactly what it was given;
//  - bad input is refused, naming the constraint or contact and the value,
//    before anything is written.
// That the values mean the same on both sides (an impulse in the place of the
// same row) is checked by scene_comparison_test.cc, which compares them after
// every step.

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "manyworlds/batch.h"
#include "manyworlds/scenes.h"
#include "reference/world.h"
#include "tests/lane_vs_reference.h"
#include "tests/mixed_scenes.h"

namespace manyworlds {
namespace {

// Every constraint type, motors, limits, drives, paths, and contacts of
// every pair kind (mixed, more_types and reference scenes).
using test_scenes::SceneById;

class SolverStateTest : public ::testing::TestWithParam<std::string> {};

std::vector<float> SolverState(const Batch& batch, std::size_t world) {
  std::vector<float> values(batch.SolverStateSize());
  batch.GetSolverState(world, values);
  return values;
}

// World 5 (block 0) and world 21 (block 1) become copies of world 2 after 40
// steps and must then stay its exact copies for 60 more steps.
TEST_P(SolverStateTest, AWorldGivenAnothersStateContinuesAsItBitForBit) {
  constexpr std::size_t kWorlds = 24, kSource = 2;
  Batch batch(SceneById(GetParam()), kWorlds, BatchOptions{1});
  KickEveryWorldDifferently(batch);
  const StepSettings settings;
  for (int step = 0; step < 40; ++step) batch.Step(settings);
  const std::size_t per_world = batch.body_count() * kStateFloatsPerBody;
  std::vector<float> state(kWorlds * per_world);
  batch.GetState(state);
  const std::vector<float> source = SolverState(batch, kSource);
  for (const std::size_t copy : {std::size_t{5}, std::size_t{21}}) {
    ASSERT_NE(SolverState(batch, copy), source) << "world " << copy << " already equal";
    std::copy_n(state.begin() + kSource * per_world, per_world, state.begin() + copy * per_world);
    batch.SetSolverState(copy, source);
  }
  batch.SetState(state);
  for (int step = 0; step < 60; ++step) {
    batch.Step(settings);
    batch.GetState(state);
    for (const std::size_t copy : {std::size_t{5}, std::size_t{21}}) {
      for (std::size_t i = 0; i < per_world; ++i) {
        ASSERT_EQ(std::bit_cast<std::uint32_t>(state[copy * per_world + i]),
                  std::bit_cast<std::uint32_t>(state[kSource * per_world + i]))
            << "world " << copy << " state float " << i << " after step " << step;
      }
      ASSERT_EQ(SolverState(batch, copy), SolverState(batch, kSource)) << "after step " << step;
    }
  }
}

TEST_P(SolverStateTest, SettingOneWorldLeavesTheOthersAlone) {
  constexpr std::size_t kWorlds = 20;
  Batch batch(SceneById(GetParam()), kWorlds, BatchOptions{1});
  KickEveryWorldDifferently(batch);
  for (int step = 0; step < 30; ++step) batch.Step({});
  std::vector<std::vector<float>> before;
  for (std::size_t w = 0; w < kWorlds; ++w) before.push_back(SolverState(batch, w));
  const BatchSnapshot snapshot = batch.Snapshot();
  // Setting a world its own state changes no byte where there are no
  // contacts. (A contact's kept points are written to its first slots, and
  // the local points of slots not kept, which no step reads, become 0; the
  // test above shows the step continues bit for bit.)
  batch.SetSolverState(7, before[7]);
  const BatchSnapshot after = batch.Snapshot();
  if (reference::World<float>(batch.scene()).contact_count() == 0) {
    EXPECT_TRUE(std::equal(snapshot.bytes().begin(), snapshot.bytes().end(),
                           after.bytes().begin(), after.bytes().end()));
  }
  batch.SetSolverState(7, before[12]);
  for (std::size_t w = 0; w < kWorlds; ++w) {
    EXPECT_EQ(SolverState(batch, w), w == 7 ? before[12] : before[w]) << "world " << w;
  }
}

TEST_P(SolverStateTest, TheReferenceHasTheSameLayoutAndGivesBackWhatItWasGiven) {
  Batch batch(SceneById(GetParam()), 16, BatchOptions{1});
  KickEveryWorldDifferently(batch);
  for (int step = 0; step < 30; ++step) batch.Step({});
  reference::World<float> world(batch.scene());
  EXPECT_EQ(world.SolverState().size(), batch.SolverStateSize());
  const std::vector<float> values = SolverState(batch, 9);
  world.SetSolverState(values);
  EXPECT_EQ(world.SolverState(), values);
  std::vector<float> one_more = values;
  one_more.push_back(0.0f);
  EXPECT_THROW(world.SetSolverState(one_more), std::invalid_argument);
  EXPECT_THROW(world.SetSolverState(std::span<const float>(values).first(values.size() - 1)),
               std::invalid_argument);
}

INSTANTIATE_TEST_SUITE_P(Scenes, SolverStateTest,
                         ::testing::Values("cartpole", "ragdoll", "geartrain", "mixed",
                                           "more_types", "pile", "box-pile", "quadruped"),
                         [](const auto& info) {
                           std::string name = info.param;
                           for (char& c : name) c = c == '-' ? '_' : c;
                           return name;
                         });

// The refusals name the constraint or contact and write nothing.
void ExpectRefused(Batch& batch, const std::vector<float>& values, const std::string& names) {
  const BatchSnapshot before = batch.Snapshot();
  try {
    batch.SetSolverState(3, values);
    ADD_FAILURE() << "not refused";
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find(names), std::string::npos) << error.what();
  }
  const BatchSnapshot after = batch.Snapshot();
  EXPECT_TRUE(std::equal(before.bytes().begin(), before.bytes().end(), after.bytes().begin(),
                         after.bytes().end()));
}

TEST(SolverStateRefusals, BadValuesAreRefusedBeforeAnythingIsWritten) {
  // cartpole: slider 'rail' (no motor, no limits: 7 values), hinge 'pole
  // hinge' (9 values, no motor or limit either).
  Batch cartpole(MakeScene("cartpole"), 16, BatchOptions{1});
  for (int step = 0; step < 5; ++step) cartpole.Step({});
  const std::vector<float> good = SolverState(cartpole, 3);
  ASSERT_EQ(good.size(), 16u);
  EXPECT_THROW(cartpole.SetSolverState(3, std::span<const float>(good).first(15)),
               std::invalid_argument);
  EXPECT_THROW(cartpole.SetSolverState(16, good), std::out_of_range);
  std::vector<float> bad = good;
  bad[8] = std::numeric_limits<float>::quiet_NaN();  // the hinge's point impulse
  ExpectRefused(cartpole, bad, "'pole hinge' in world 3: point impulse (value 8");
  bad = good;
  bad[0] = 1.0f;  // the slider's motor row, which it does not have
  ExpectRefused(cartpole, bad, "'rail' in world 3: motor impulse (value 0");

  // box-drop: one box on the ground plane, 4 points.
  Batch drop(MakeScene("box-drop"), 16, BatchOptions{1});
  for (int step = 0; step < 60; ++step) drop.Step({});
  const std::vector<float> contact = SolverState(drop, 3);
  ASSERT_EQ(contact.size(), 35u);
  ASSERT_EQ(contact[3], 1.0f) << "the box should be resting on the ground";
  bad = contact;
  bad[3] = 0.5f;  // the first point's kept flag
  ExpectRefused(drop, bad, "must be 0 or 1");
  bad = contact;
  bad[3] = 0.0f;  // not kept, but its local points are not 0
  ExpectRefused(drop, bad, "not kept");
}

}  // namespace
}  // namespace manyworlds
