// What sharding over MPI ranks costs (docs/scale-out.md): run as
//
//   mpirun -n R build/bench/mpi_bench [--quick]
//
// and rank 0 prints, for this machine and R ranks:
// - the latency of one MPI_Allreduce of an int (what ShardedBatch::Step and
//   the run's stop check add per step, each);
// - ShardedBatch::Step against Batch::Step on the same 16-world shard: the
//   whole per-step cost of the collective refusal check;
// - the gathers a caller makes (per-world returns of 65536 worlds, the
//   health bytes, the states of 64 chosen worlds): time and bytes per rank;
// - the compute they sit beside: ns per world-step of cartpole and chain16
//   with 4096 worlds per rank, 1 thread, so that bytes and microseconds per
//   step can be set against compute per step.
// Every figure is the median of 5 repeats; each rank times its own calls and
// rank 0 prints the slowest rank's (a collective is as slow as its last
// rank). --quick: a few iterations only (the ctest smoke run).

#include <mpi.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <functional>
#include <numeric>
#include <vector>

#include "manyworlds/scenes.h"
#include "manyworlds/sharded_batch.h"

namespace {

using namespace manyworlds;
using Clock = std::chrono::steady_clock;

// Seconds per call of fn, median of 5 repeats of `calls` calls, the slowest
// rank's; every rank starts each repeat together.
double SecondsPerCall(MPI_Comm comm, int calls, const std::function<void()>& fn) {
  std::vector<double> repeats;
  for (int repeat = 0; repeat < 5; ++repeat) {
    MPI_Barrier(comm);
    const auto start = Clock::now();
    for (int i = 0; i < calls; ++i) fn();
    repeats.push_back(std::chrono::duration<double>(Clock::now() - start).count() / calls);
  }
  std::nth_element(repeats.begin(), repeats.begin() + 2, repeats.end());
  double mine = repeats[2], slowest = 0.0;
  MPI_Allreduce(&mine, &slowest, 1, MPI_DOUBLE, MPI_MAX, comm);
  return slowest;
}

}  // namespace

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  const bool quick = argc > 1 && std::strcmp(argv[1], "--quick") == 0;
  const int scale = quick ? 1 : 100;
  int rank = 0, ranks = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &ranks);
  const auto print = [rank](const char* what, double us, const char* extra) {
    if (rank == 0) std::printf("%-58s %10.3f us  %s\n", what, us, extra);
  };
  if (rank == 0) std::printf("mpi_bench: %d ranks, 1 thread each\n", ranks);

  {
    int mine = rank, out = 0;
    const double s = SecondsPerCall(MPI_COMM_WORLD, 20 * scale, [&] {
      MPI_Allreduce(&mine, &out, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
    });
    print("MPI_Allreduce of one int", s * 1e6, "4 bytes sent per rank");
  }
  {
    const std::size_t shard_worlds = 16;
    ShardedBatch sharded(MPI_COMM_WORLD, MakeScene("cartpole"), shard_worlds * std::size_t(ranks),
                         BatchOptions{.threads = 1});
    const StepSettings settings;
    const double local = SecondsPerCall(MPI_COMM_WORLD, 10 * scale,
                                        [&] { sharded.local().Step(settings); });
    const double collective =
        SecondsPerCall(MPI_COMM_WORLD, 10 * scale, [&] { sharded.Step(settings); });
    char extra[96];
    std::snprintf(extra, sizeof extra, "(Batch::Step %.2f us, ShardedBatch::Step %.2f us)",
                  local * 1e6, collective * 1e6);
    print("ShardedBatch::Step's check per step (16 cartpoles a rank)",
          (collective - local) * 1e6, extra);
  }
  {
    const std::size_t total = 65536;
    ShardedBatch sharded(MPI_COMM_WORLD, MakeScene("cartpole"), total, BatchOptions{.threads = 1});
    const std::vector<float> returns(sharded.shard().count, 1.0f);
    char extra[96];
    std::snprintf(extra, sizeof extra, "%zu bytes sent per rank",
                  sharded.shard().count * sizeof(float));
    print("GatherPerWorld: one float per world, 65536 worlds",
          SecondsPerCall(MPI_COMM_WORLD, 2 * scale,
                         [&] { (void)sharded.GatherPerWorld(returns, 1); }) * 1e6,
          extra);
    std::snprintf(extra, sizeof extra, "%zu bytes sent per rank", sharded.shard().count);
    print("GatherHealth: 65536 worlds",
          SecondsPerCall(MPI_COMM_WORLD, 2 * scale, [&] { (void)sharded.GatherHealth(); }) * 1e6,
          extra);
    std::vector<std::size_t> chosen(64);
    for (std::size_t i = 0; i < chosen.size(); ++i) chosen[i] = i * (total / chosen.size());
    std::snprintf(extra, sizeof extra, "%zu bytes in all (3 bodies x 13 floats a world)",
                  chosen.size() * 3 * kStateFloatsPerBody * sizeof(float));
    print("GatherStates: 64 worlds spread over the ranks",
          SecondsPerCall(MPI_COMM_WORLD, 2 * scale, [&] { (void)sharded.GatherStates(chosen); }) *
              1e6,
          extra);
  }
  for (const char* id : {"cartpole", "chain16"}) {
    const std::size_t per_rank = 4096;
    ShardedBatch sharded(MPI_COMM_WORLD, MakeScene(id), per_rank * std::size_t(ranks),
                         BatchOptions{.threads = 1});
    const StepSettings settings;
    sharded.Step(settings);  // warm
    const double s =
        SecondsPerCall(MPI_COMM_WORLD, quick ? 1 : 20, [&] { sharded.Step(settings); });
    char extra[96];
    std::snprintf(extra, sizeof extra, "%.1f ns per world-step", s * 1e9 / double(per_rank));
    char what[96];
    std::snprintf(what, sizeof what, "compute: one step of %s, 4096 worlds a rank", id);
    print(what, s * 1e6, extra);
  }
  MPI_Finalize();
  return 0;
}
