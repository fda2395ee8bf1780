// An outside program with manyworlds::mpi (tests/package/package_test.sh
// runs it with 2 ranks): 40 cartpoles sharded over the ranks, stepped with
// the scene's actions, every state gathered to rank 0 and compared bit for
// bit with one Batch of all 40 there. Exit code 0 when equal on every rank.

#include <mpi.h>

#include <cstdio>
#include <cstring>
#include <numeric>
#include <vector>

#include "manyworlds/scenes.h"
#include "manyworlds/sharded_batch.h"

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  int failed = 0;
  {
    using namespace manyworlds;
    const std::size_t total = 40;
    const SceneActions actions("cartpole");
    ShardedBatch sharded(MPI_COMM_WORLD, MakeScene("cartpole"), total);
    for (std::uint64_t step = 0; step < 30; ++step) {
      actions.Apply(sharded.local(), step, 1, sharded.shard().first);
      sharded.Step(StepSettings{});
    }
    std::vector<std::size_t> worlds(total);
    std::iota(worlds.begin(), worlds.end(), std::size_t(0));
    const std::vector<float> gathered = sharded.GatherStates(worlds);
    if (sharded.rank() == 0) {
      Batch one(MakeScene("cartpole"), total);
      for (std::uint64_t step = 0; step < 30; ++step) {
        actions.Apply(one, step, 1);
        one.Step(StepSettings{});
      }
      std::vector<float> expected(gathered.size());
      one.GetState(expected);
      failed = std::memcmp(gathered.data(), expected.data(), expected.size() * sizeof(float));
      std::printf("mpi_consumer: %d ranks, %zu worlds: %s\n", sharded.ranks(), total,
                  failed ? "DIFFERENT from one process" : "bit for bit one process");
    }
    MPI_Bcast(&failed, 1, MPI_INT, 0, MPI_COMM_WORLD);
  }
  MPI_Finalize();
  return failed ? 1 : 0;
}
