// ShardedBatch under mpirun (mpi/CMakeLists.txt runs this with 1, 2 and 3
// ranks). Every rank runs every test, so collective calls line up; root
// (rank 0) also steps the same worlds in one plain Batch and compares bits.
//
// What must hold whatever the rank count:
// - a world's state after any number of steps is bit for bit the state of
//   the same world in one process (memcmp, no tolerance: worlds never
//   interact and every input is keyed by the global world index);
// - a non-finite world is flagged on its rank and changes no bit of any
//   other world;
// - a refusal on one rank (a bad per-world input, bad settings, too few
//   worlds) throws RankError on every rank, naming that rank, and the batch
//   stays usable: no rank is left waiting.

#include <gtest/gtest.h>
#include <mpi.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <numeric>
#include <string>
#include <vector>

#include "manyworlds/lanes.h"
#include "manyworlds/scenes.h"
#include "manyworlds/sharded_batch.h"

namespace manyworlds {
namespace {

constexpr int kRoot = 0;
constexpr std::uint64_t kSeed = 7;

int Rank() {
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  return rank;
}

int Ranks() {
  int ranks = 0;
  MPI_Comm_size(MPI_COMM_WORLD, &ranks);
  return ranks;
}

std::vector<std::size_t> AllWorlds(std::size_t total) {
  std::vector<std::size_t> worlds(total);
  std::iota(worlds.begin(), worlds.end(), std::size_t(0));
  return worlds;
}

// Bitwise equality of two float arrays, naming the first differing index.
::testing::AssertionResult SameBits(const std::vector<float>& a, const std::vector<float>& b) {
  if (a.size() != b.size()) {
    return ::testing::AssertionFailure() << "sizes " << a.size() << " and " << b.size();
  }
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (std::memcmp(&a[i], &b[i], sizeof(float)) != 0) {
      return ::testing::AssertionFailure()
             << "first difference at float " << i << ": " << a[i] << " vs " << b[i];
    }
  }
  return ::testing::AssertionSuccess();
}

// A scene stepped sharded and in one process with the scene's own actions
// (random forces or motor targets keyed by global world and step).
void ExpectShardedEqualsOneProcess(const std::string& id, std::size_t total, int steps) {
  SCOPED_TRACE(id + ", " + std::to_string(total) + " worlds, " + std::to_string(Ranks()) +
               " ranks");
  const Scene scene = MakeScene(id);
  const SceneActions actions(id);
  const StepSettings settings = SceneStepSettings(id);
  ShardedBatch sharded(MPI_COMM_WORLD, scene, total, BatchOptions{.threads = 1});
  ASSERT_EQ(sharded.local().world_count(), sharded.shard().count);
  for (int step = 0; step < steps; ++step) {
    actions.Apply(sharded.local(), std::uint64_t(step), kSeed, sharded.shard().first);
    sharded.Step(settings);
  }
  const std::vector<float> states = sharded.GatherStates(AllWorlds(total), kRoot);
  // The joint coordinates through the per-world gather.
  const std::size_t per_world = sharded.local().JointCoordinatesPerWorld();
  std::vector<float> local_joints(sharded.shard().count * per_world);
  sharded.local().GetJointCoordinates(local_joints);
  const std::vector<float> joints = sharded.GatherPerWorld(local_joints, per_world, kRoot);
  if (Rank() != kRoot) {
    EXPECT_TRUE(states.empty());
    EXPECT_TRUE(joints.empty());
    return;
  }
  Batch one(scene, total, BatchOptions{.threads = 1});
  for (int step = 0; step < steps; ++step) {
    actions.Apply(one, std::uint64_t(step), kSeed);
    one.Step(settings);
  }
  std::vector<float> expected_states(total * one.body_count() * kStateFloatsPerBody);
  one.GetState(expected_states);
  std::vector<float> expected_joints(total * per_world);
  one.GetJointCoordinates(expected_joints);
  EXPECT_TRUE(SameBits(states, expected_states));
  EXPECT_TRUE(SameBits(joints, expected_joints));
  // And the worlds really moved (a test that compared initial states would pass too).
  Batch fresh(scene, 1);
  std::vector<float> initial(fresh.body_count() * kStateFloatsPerBody);
  fresh.GetWorldState(0, initial);
  EXPECT_NE(std::memcmp(initial.data(), states.data() + (total - 1) * initial.size(),
                        initial.size() * sizeof(float)),
            0);
}

TEST(ShardedBatchTest, EveryWorldBitIdenticalToOneProcess) {
  // 37 worlds: 3 blocks, the last part empty; 100: 7 blocks over 2 or 3 ranks.
  ExpectShardedEqualsOneProcess("cartpole", 37, 60);
  ExpectShardedEqualsOneProcess("cartpole", 100, 60);
  ExpectShardedEqualsOneProcess("chain16", 100, 30);
  ExpectShardedEqualsOneProcess("ragdoll", 37, 30);  // motor targets keyed by world
  ExpectShardedEqualsOneProcess("geartrain", 37, 30);
  // Fewer blocks than ranks: shards inside one block.
  if (Ranks() > 1) ExpectShardedEqualsOneProcess("rackpinion", 5, 30);
}

TEST(ShardedBatchTest, OwnerAndShardsAgree) {
  const ShardedBatch sharded(MPI_COMM_WORLD, MakeScene("cartpole"), 100,
                             BatchOptions{.threads = 1});
  for (int r = 0; r < sharded.ranks(); ++r) {
    const WorldShard shard = sharded.shard_of(r);
    EXPECT_EQ(sharded.owner(shard.first), r);
    EXPECT_EQ(sharded.owner(shard.first + shard.count - 1), r);
  }
  EXPECT_THROW(sharded.owner(100), std::out_of_range);
}

TEST(ShardedBatchTest, NonFiniteWorldIsFlaggedAndIsolatedOnItsRank) {
  const std::size_t total = 100, bad_world = 61;  // on rank 1 of 2, rank 1 of 3
  const Scene scene = MakeScene("chain16");
  ShardedBatch sharded(MPI_COMM_WORLD, scene, total, BatchOptions{.threads = 1});
  const float nan = std::nanf("");
  for (int step = 0; step < 20; ++step) {
    if (step == 5 && sharded.owner(bad_world) == sharded.rank()) {
      sharded.local().SetForce(bad_world - sharded.shard().first, 3, {nan, 0, 0});
    }
    sharded.Step(StepSettings{});
  }
  const HealthCounts counts = sharded.ReduceHealth(kRoot);
  const std::vector<std::uint8_t> health = sharded.GatherHealth(kRoot);
  const std::vector<float> states = sharded.GatherStates(AllWorlds(total), kRoot);
  if (Rank() != kRoot) return;
  EXPECT_EQ(counts.unhealthy, 1u);
  EXPECT_EQ(counts.non_finite_state, 1u);
  ASSERT_EQ(health.size(), total);
  for (std::size_t w = 0; w < total; ++w) {
    EXPECT_EQ(health[w] != 0, w == bad_world) << "world " << w;
  }
  Batch one(scene, total, BatchOptions{.threads = 1});
  for (int step = 0; step < 20; ++step) {
    if (step == 5) one.SetForce(bad_world, 3, {nan, 0, 0});
    one.Step(StepSettings{});
  }
  std::vector<float> expected(states.size());
  one.GetState(expected);
  // Every healthy world bit for bit; the bad one is NaN in both.
  const std::size_t per_world = one.body_count() * kStateFloatsPerBody;
  for (std::size_t w = 0; w < total; ++w) {
    if (w == bad_world) continue;
    ASSERT_EQ(std::memcmp(states.data() + w * per_world, expected.data() + w * per_world,
                          per_world * sizeof(float)),
              0)
        << "world " << w;
  }
}

TEST(ShardedBatchTest, RefusalOnOneRankThrowsOnEveryRankAndNothingHangs) {
  ShardedBatch sharded(MPI_COMM_WORLD, MakeScene("ragdoll"), 100, BatchOptions{.threads = 1});
  const int last = sharded.ranks() - 1;
  // A per-world input only the last rank gets wrong: too few targets.
  try {
    sharded.AllOrNone([&](Batch& batch) {
      std::vector<float> targets(batch.world_count() - (sharded.rank() == last ? 1 : 0), 0.5f);
      batch.SetTargetPositions(7, targets);
    });
    ADD_FAILURE() << "no RankError";
  } catch (const RankError& e) {
    EXPECT_EQ(e.rank(), last);
    EXPECT_NE(std::string(e.what()).find("rank " + std::to_string(last) + ": "),
              std::string::npos)
        << e.what();
  }
  // Settings every rank refuses: reported as the lowest rank's, on all.
  StepSettings bad;
  bad.substeps = 0;
  try {
    sharded.Step(bad);
    ADD_FAILURE() << "no RankError";
  } catch (const RankError& e) {
    EXPECT_EQ(e.rank(), 0);
    EXPECT_NE(std::string(e.what()).find("substeps"), std::string::npos) << e.what();
  }
  // Settings only the last rank gets wrong: no rank steps, so every world
  // stays where it was (the worlds of one process that did not step).
  const std::vector<float> before = sharded.GatherStates(AllWorlds(100), kRoot);
  StepSettings settings_of_rank;
  if (sharded.rank() == last) settings_of_rank.velocity_iterations = -1;
  try {
    sharded.Step(settings_of_rank);
    ADD_FAILURE() << "no RankError";
  } catch (const RankError& e) {
    EXPECT_EQ(e.rank(), last);
    EXPECT_NE(std::string(e.what()).find("velocity_iterations"), std::string::npos) << e.what();
  }
  EXPECT_TRUE(SameBits(sharded.GatherStates(AllWorlds(100), kRoot), before));
  // A gather with a wrong size on one rank.
  std::vector<float> values(sharded.shard().count + (sharded.rank() == last ? 1 : 0));
  EXPECT_THROW(sharded.GatherPerWorld(values, 1, kRoot), RankError);
  // Arguments that differ from rank 0's: named, not a mismatched gather.
  if (sharded.ranks() > 1) {
    const std::size_t per_world = sharded.rank() == last ? 2 : 1;
    std::vector<float> rows(sharded.shard().count * per_world);
    try {
      (void)sharded.GatherPerWorld(rows, per_world, kRoot);
      ADD_FAILURE() << "no RankError";
    } catch (const RankError& e) {
      EXPECT_EQ(e.rank(), last);
      EXPECT_NE(std::string(e.what()).find("per_world 2 differs from rank 0's 1"),
                std::string::npos)
          << e.what();
    }
    const std::vector<std::size_t> list = {std::size_t(sharded.rank() == last ? 5 : 4)};
    EXPECT_THROW((void)sharded.GatherStates(list, kRoot), RankError);
    EXPECT_THROW((void)sharded.ReduceHealth(sharded.rank() == last ? 1 : 0), RankError);
  }
  EXPECT_THROW((void)sharded.GatherHealth(sharded.ranks()), RankError);  // not a rank
  // Still in step with each other: a collective step and gather work.
  sharded.Step(StepSettings{});
  const HealthCounts counts = sharded.ReduceHealth(kRoot);
  if (Rank() == kRoot) {
    EXPECT_EQ(counts.unhealthy, 0u);
  }
}

TEST(ShardedBatchTest, TooFewWorldsForTheRanksIsRefusedOnEveryRank) {
  const std::size_t total = std::size_t(Ranks()) - 1;
  try {
    ShardedBatch sharded(MPI_COMM_WORLD, MakeScene("cartpole"), total);
    ADD_FAILURE() << "no RankError";
  } catch (const RankError& e) {
    EXPECT_NE(std::string(e.what()).find("every rank needs at least one world"),
              std::string::npos)
        << e.what();
  }
}

TEST(ShardedBatchTest, BadSceneIsRefusedOnEveryRankNamingTheBody) {
  Scene scene = MakeScene("cartpole");
  scene.bodies()[1].mass = -1.0f;
  try {
    ShardedBatch sharded(MPI_COMM_WORLD, scene, 64);
    ADD_FAILURE() << "no RankError";
  } catch (const RankError& e) {
    EXPECT_EQ(e.rank(), 0);  // every rank refuses; the lowest is named
    EXPECT_NE(std::string(e.what()).find("mass"), std::string::npos) << e.what();
  }
}

// Prints a failure of a rank other than root, which has no result printer
// (every rank's log interleaved would be unreadable).
class RankFailurePrinter : public ::testing::EmptyTestEventListener {
 public:
  explicit RankFailurePrinter(int rank) : rank_(rank) {}
  void OnTestPartResult(const ::testing::TestPartResult& result) override {
    if (!result.failed()) return;
    const ::testing::TestInfo* test = ::testing::UnitTest::GetInstance()->current_test_info();
    std::fprintf(stderr, "[rank %d] FAILED %s.%s at %s:%d\n%s\n", rank_,
                 test ? test->test_suite_name() : "?", test ? test->name() : "?",
                 result.file_name() ? result.file_name() : "?", result.line_number(),
                 result.message());
  }

 private:
  int rank_;
};

}  // namespace
}  // namespace manyworlds

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  ::testing::InitGoogleTest(&argc, argv);
  // Only root prints the test log; every rank's failures still fail mpirun.
  if (manyworlds::Rank() != 0) {
    ::testing::TestEventListeners& listeners = ::testing::UnitTest::GetInstance()->listeners();
    delete listeners.Release(listeners.default_result_printer());
    listeners.Append(new manyworlds::RankFailurePrinter(manyworlds::Rank()));
  }
  const int result = RUN_ALL_TESTS();
  MPI_Finalize();
  return result;
}
