// `mpirun -n R manyworlds run` (tools/sharded_run.h).
//
// Each rank steps its own shard with the same per-world actions (keyed by
// global world) as a one-process run; between steps the ranks exchange only
// two ints (two allreduces: the SIGUSR1 stop flag, so that all stop after
// the same step, and the step's refusal agreement, AllOrNone). The report's figures
// are reduced to rank 0 at the end, with each rank's time per step outside
// its own stepping (those messages, waiting for slower ranks, the actions).

#include "tools/sharded_run.h"

#include <mpi.h>
#include <signal.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>
#include <cstdint>
#include <vector>

#include "manyworlds/sharded_batch.h"
#include "tools/run_command.h"
#include "tools/run_report.h"

namespace manyworlds::tools {
namespace {

// MPI_Init and MPI_Finalize around the run, also when it throws.
class MpiSession {
 public:
  MpiSession(int* argc, char*** argv) {
    int provided = 0;
    // Only the main thread calls MPI (TBB's workers never do).
    MPI_Init_thread(argc, argv, MPI_THREAD_FUNNELED, &provided);
  }
  ~MpiSession() { MPI_Finalize(); }
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;
};

// Every rank's stats added up on rank 0 (sums and maxima apart).
WorldStats ReduceStats(const WorldStats& local, MPI_Comm comm) {
  // Unsigned sums wrap mod 2^64 in MPI as in C, which the digest relies on.
  std::uint64_t counts[10] = {local.worlds,     local.timed_world_steps, local.finite_errors,
                              local.non_finite_errors, local.unhealthy, local.by_bit[0],
                              local.by_bit[1],  local.by_bit[2],        local.by_bit[3],
                              local.state_digest};
  double sums[2] = {local.linear_sum, local.angular_sum};
  double maxima[2] = {local.linear_max, local.angular_max};
  std::uint64_t total_counts[10];
  double total_sums[2], total_maxima[2];
  MPI_Reduce(counts, total_counts, 10, MPI_UINT64_T, MPI_SUM, 0, comm);
  MPI_Reduce(sums, total_sums, 2, MPI_DOUBLE, MPI_SUM, 0, comm);
  MPI_Reduce(maxima, total_maxima, 2, MPI_DOUBLE, MPI_MAX, 0, comm);
  WorldStats total;
  total.worlds = total_counts[0];
  total.timed_world_steps = total_counts[1];
  total.finite_errors = total_counts[2];
  total.non_finite_errors = total_counts[3];
  total.unhealthy = total_counts[4];
  for (int bit = 0; bit < 4; ++bit) total.by_bit[bit] = total_counts[5 + bit];
  total.state_digest = total_counts[9];
  total.linear_sum = total_sums[0];
  total.angular_sum = total_sums[1];
  total.linear_max = total_maxima[0];
  total.angular_max = total_maxima[1];
  return total;
}

// The run itself, once the arguments are known to be good on every rank.
int StepShards(const Options& options, const RunSetup& setup, const SigintStop& sigint, int rank,
               int ranks) {
  ShardedBatch sharded(MPI_COMM_WORLD, setup.scene, setup.worlds, setup.batch_options);
  Batch& local = sharded.local();
  RunRecording recording(options, local, setup.scene_id, setup.settings.delta_time);
  ProgressLine progress(setup.warmup + setup.steps, setup.worlds, rank == 0);
  // The time this rank spends stepping its worlds, against the loop's wall
  // time: the rest is MPI (messages and waiting for slower ranks) and the
  // actions, which a one-process run has too.
  double stepping_seconds = 0.0;
  bool timing = false;
  const LoopResult loop = StepLoop(
      local, sharded.shard().first, setup, recording, progress,
      [&] {
        // The signal reaches the ranks at different steps: stop when any rank saw it.
        int mine = sigint.requested() ? 1 : 0, any = 0;
        MPI_Allreduce(&mine, &any, 1, MPI_INT, MPI_MAX, sharded.comm());
        return any != 0;
      },
      [&] {
        // The local step inside the refusal agreement (the settings are the
        // same on every rank), timed apart.
        sharded.AllOrNone([&](Batch& batch) {
          const auto start = std::chrono::steady_clock::now();
          batch.Step(setup.settings);
          if (timing) {
            stepping_seconds +=
                std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
          }
        });
      },
      [&] {
        MPI_Barrier(sharded.comm());
        timing = true;
      });
  progress.Erase();
  recording.Close();

  const std::uint64_t timed_done = loop.steps_done - std::min(loop.steps_done, setup.warmup);
  const WorldStats stats = ReduceStats(WorldStats::Of(local, timed_done, sharded.shard().first), sharded.comm());
  double slowest = 0.0;
  MPI_Reduce(&loop.timed_seconds, &slowest, 1, MPI_DOUBLE, MPI_MAX, 0, sharded.comm());
  // A rank's own speed: its world-steps over the time it spent stepping
  // them (the slowest rank sets the total's pace).
  const double rate = stepping_seconds > 0
                          ? double(local.world_count()) * double(timed_done) / stepping_seconds
                          : 0.0;
  std::vector<double> rates(std::size_t(ranks), 0.0);
  MPI_Gather(&rate, 1, MPI_DOUBLE, rates.data(), 1, MPI_DOUBLE, 0, sharded.comm());
  // Per timed step, the rest of the loop beside stepping the worlds.
  const double other = timed_done > 0 ? (loop.timed_seconds - stepping_seconds) / double(timed_done)
                                      : 0.0;
  std::vector<double> others(std::size_t(ranks), 0.0);
  MPI_Gather(&other, 1, MPI_DOUBLE, others.data(), 1, MPI_DOUBLE, 0, sharded.comm());
  if (rank != 0) return loop.interrupted ? 130 : 0;

  RunFacts facts{.scene_id = setup.scene_id,
                 .mass_range = setup.mass_range,
                 .settings = setup.settings,
                 .warmup_steps = setup.warmup,
                 .timed_steps = setup.steps,
                 .steps_done = loop.steps_done,
                 .timed_seconds = slowest,
                 .interrupted = loop.interrupted,
                 .stop_signal = "SIGUSR1",
                 .recording = recording.Describe(),
                 .rank_worlds = {},
                 .rank_world_steps_per_second = rates,
                 .rank_other_seconds_per_step = others};
  for (int r = 0; r < ranks; ++r) facts.rank_worlds.push_back(sharded.shard_of(r).count);
  PrintRunReport(local, SceneActions(setup.scene_id), facts, stats);
  return loop.interrupted ? ReportInterrupted(loop.steps_done, setup, "SIGUSR1") : 0;
}

// ShardedRun without MPI's set-up: throws as `run` does.
int RunOnRanks(int argc, char** argv, int rank, int ranks) {
  // OpenMPI's mpirun ends the job on Ctrl-C (SIGINT) but forwards SIGUSR1
  // to every rank: `kill -USR1 <mpirun's pid>` stops after the same step on
  // all ranks, with the report. Installed first, so that no SIGUSR1 kills.
  const SigintStop sigint(SIGUSR1);

  // Every rank parses the same arguments, so a usage error is raised by all
  // alike before any message is exchanged.
  const Options options = RunOptions(argc, argv);
  if (ranks > 1 && options.Has(kRecordOption)) {
    throw UsageError(std::string(kRecordOption) +
                     " needs a run in one process: the trajectories are bit for bit the same "
                     "whatever the rank count, so record the worlds without mpirun (or with "
                     "-n 1)");
  }
  if (options.Has(kRecordWorldsOption) && !options.Has(kRecordOption)) {
    throw UsageError(std::string(kRecordWorldsOption) + " needs " + kRecordOption + " FILE");
  }
  const RunSetup setup = ParseRunSetup(options);
  if (setup.worlds < std::size_t(ranks)) {
    throw UsageError("--worlds " + std::to_string(setup.worlds) + " is fewer than the " +
                     std::to_string(ranks) + " MPI ranks: every rank needs at least one world");
  }
  try {
    return StepShards(options, setup, sigint, rank, ranks);
  } catch (const RankError&) {
    throw;  // raised on every rank alike
  } catch (const std::exception& e) {
    if (ranks == 1) throw;  // nobody to wait for it: reported as `run` reports
    // Raised on this rank alone (e.g. out of memory): the others would wait
    // for it in their next collective call forever, so end them all.
    std::fprintf(stderr, "manyworlds: rank %d of %d: %s; ending every rank\n", rank, ranks,
                 e.what());
    std::fflush(stderr);
    MPI_Abort(MPI_COMM_WORLD, 1);
    return 1;
  }
}

}  // namespace

int ShardedRun(int argc, char** argv) {
  const MpiSession session(&argc, &argv);
  int rank = 0, ranks = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &ranks);
  int code = 0;
  try {
    code = RunOnRanks(argc, argv, rank, ranks);
  } catch (...) {
    // Every rank raised the same error (arguments, RankError): rank 0
    // prints it once.
    code = ReportError(std::current_exception(), rank == 0);
  }
  // No rank ends before rank 0 has printed its report or error: mpirun ends
  // the whole job as soon as one rank exits with an error code.
  std::fflush(stdout);
  MPI_Barrier(MPI_COMM_WORLD);
  return code;
}

}  // namespace manyworlds::tools
