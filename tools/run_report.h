// The report `manyworlds run` prints after stepping (docs/scenes.md,
// "Running a scene"): the setup, throughput, memory, constraint errors split
// into linear (m) and angular (rad), and health.
#pragma once

#include <cstdint>
#include <string>

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
  double timed_seconds = 0.0;      // wall time of the timed steps done
  bool interrupted = false;        // SIGINT stopped the run before the end
  std::string recording = "off";   // what --record wrote (tools/record_option.h)
};

// Prints the report to stdout, from `batch` as the last step left it.
void PrintRunReport(const Batch& batch, const SceneActions& actions, const RunFacts& facts);

}  // namespace manyworlds::tools
