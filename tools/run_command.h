// `manyworlds run`'s options and step loop, shared by the run in one process
// (tools/manyworlds.cc) and the run sharded over MPI ranks
// (tools/sharded_run.cc), so that both step exactly the same worlds.
#pragma once

#include <cstddef>
#include <cstdint>
#include <exception>
#include <functional>
#include <string>

#include "manyworlds/batch.h"
#include "manyworlds/scene.h"
#include "manyworlds/scenes.h"
#include "tools/options.h"
#include "tools/progress.h"
#include "tools/record_option.h"

namespace manyworlds::tools {

// The options `run` accepts, for Options.
Options RunOptions(int argc, char** argv);

// What the options ask for (UsageError naming a bad one).
struct RunSetup {
  std::string scene_id;
  Scene scene;             // after --mass-range-limit
  std::string mass_range;  // what --mass-range-limit changed, or "off"
  std::size_t worlds = 0;  // over all ranks
  std::uint64_t steps = 0;
  std::uint64_t warmup = 0;
  std::uint64_t seed = 0;
  BatchOptions batch_options;
  StepSettings settings;
};
RunSetup ParseRunSetup(const Options& options);

// The scene of --scene; a UsageError naming the option for a missing or
// unknown id (the library's message lists every valid id).
Scene SceneOf(const Options& options);

struct LoopResult {
  std::uint64_t steps_done = 0;  // warm-up and timed
  double timed_seconds = 0.0;
  bool interrupted = false;  // SIGINT before the last step
};

// The warm-up and timed steps of `batch`, whose world i is the run's world
// first_world + i (its actions are that world's). Before each step,
// `stop_requested` says whether to stop (Ctrl-C; under mpirun agreed by every
// rank, so that all stop after the same step); `step_batch` steps (Batch::Step,
// or ShardedBatch::Step); `timing_starts` runs just before the clock starts (a
// barrier under mpirun).
LoopResult StepLoop(Batch& batch, std::uint64_t first_world, const RunSetup& setup,
                    RunRecording& recording, ProgressLine& progress,
                    const std::function<bool()>& stop_requested,
                    const std::function<void()>& step_batch,
                    const std::function<void()>& timing_starts);

// A run stopped by Ctrl-C (or `signal`): says so on stderr (after the
// report) and returns the exit code 130, what a shell reports for a program
// SIGINT killed.
int ReportInterrupted(std::uint64_t steps_done, const RunSetup& setup,
                      const char* signal = "SIGINT");

// Whether mpirun (or mpiexec) started this process: OpenMPI's
// OMPI_COMM_WORLD_SIZE, PMIx's PMIX_RANK or MPICH's PMI_SIZE is set, and
// MANYWORLDS_NO_MPI is not 1. `run` then shards its worlds over the ranks
// (tools/sharded_run.h).
bool StartedByMpirun();

// The exit code of an error a command threw (2 for a UsageError, else 1),
// printed to stderr when `print`: one line naming the value and what is
// accepted, then for a usage error the hint "run 'manyworlds --help' for
// usage". (A sharded run prints on rank 0 only: every rank raises the same.)
int ReportError(std::exception_ptr error, bool print);

}  // namespace manyworlds::tools
