// The report `manyworlds run` prints after stepping (docs/scenes.md,
// "Running a scene"): the setup, throughput, memory, constraint errors split
// into linear (m) and angular (rad), and health.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "manyworlds/batch.h"
#include "manyworlds/scenes.h"

namespace manyworlds::tools {

// What a run asked for and what it did.
struct RunFacts {
  std::string scene_id;
  std::string mass_range;  // what --mass-range-limit changed, or "off"
  StepSettings settings;
  std::uint64_t warmup_steps = 0;  // asked for
  std::uint64_t timed_steps = 0;   // asked for
  std::uint64_t steps_done = 0;    // warm-up and timed steps actually done
  double timed_seconds = 0.0;      // wall time of the timed steps done (slowest rank)
  bool interrupted = false;        // a stop signal ended the run before the end
  std::string stop_signal = "SIGINT";  // which: SIGUSR1 under mpirun
  std::string recording = "off";   // what --record wrote (tools/record_option.h)
  // Under mpirun (tools/sharded_run.h): each rank's worlds and world-steps/s
  // over the time it spent stepping them; empty for a run in one process.
  std::vector<std::size_t> rank_worlds;
  std::vector<double> rank_world_steps_per_second;
  // And each rank's wall time per timed step outside stepping its worlds:
  // MPI messages, waiting for slower ranks, writing the actions.
  std::vector<double> rank_other_seconds_per_step;
};

// What the report reads from the worlds after the last step, summed over
// worlds so that ranks can add theirs up (Add).
struct WorldStats {
  std::uint64_t worlds = 0;
  std::uint64_t timed_world_steps = 0;  // worlds x timed steps done
  std::uint64_t finite_errors = 0;      // worlds with a finite constraint error
  std::uint64_t non_finite_errors = 0;
  double linear_max = 0.0, linear_sum = 0.0;    // m, over finite_errors worlds
  double angular_max = 0.0, angular_sum = 0.0;  // rad
  std::uint64_t unhealthy = 0;
  std::uint64_t by_bit[4] = {0, 0, 0, 0};  // the first four WorldHealthBits
  // Every world's state bits hashed with its global index and added up
  // (mod 2^64): equal digests mean the same final states, whatever the
  // thread count, rank count or order of addition.
  std::uint64_t state_digest = 0;

  // `batch` as the last step left it, after `timed_steps_done` timed steps;
  // its world i is the run's world first_world + i.
  static WorldStats Of(const Batch& batch, std::uint64_t timed_steps_done,
                       std::uint64_t first_world = 0);
  void Add(const WorldStats& other);
};

// Prints the report to stdout: the setup from `batch` (under mpirun, rank
// 0's, whose options every rank shares), the figures from `stats` (every
// rank's).
void PrintRunReport(const Batch& batch, const SceneActions& actions, const RunFacts& facts,
                    const WorldStats& stats);

}  // namespace manyworlds::tools
