// Where one step's time goes, phase by phase, per scene: the breakdown every
// change to the step is read against (docs/benchmarks.md, "Phase breakdown").
//
// Each scene steps --worlds worlds (default 4096) on --threads threads
// (default 1) with its reference actions, --steps steps after --warmup
// steps, with BatchOptions::profile_phases: every block's step reads the
// clock after each phase (StepPhase) and sums the time per phase. Printed
// per scene: ns per world-step of each phase and of the profiled step, its
// share, and the world-steps/s of the same batch stepped without profiling
// (interleaved with the profiled one, median of --repeats), so the clock
// reads' own cost shows as the gap between the two totals.
//
//   build/bench/phase_bench                        # every reference scene
//   build/bench/phase_bench --scenes cartpole,chain16,ragdoll --worlds 65536
//
// Exits 1 if any world goes non-finite (the timing is then meaningless).

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <vector>

#include "manyworlds/batch.h"
#include "manyworlds/scenes.h"

namespace {

using namespace manyworlds;

// The reference scenes, then the contact scenes.
std::vector<std::string> DefaultScenes() {
  std::vector<std::string> scenes = ReferenceSceneIds();
  for (const std::string& id : ContactSceneIds()) scenes.push_back(id);
  return scenes;
}

struct Options {
  std::vector<std::string> scenes = DefaultScenes();
  std::size_t worlds = 4096;
  int threads = 1;
  int steps = 100, warmup = 20, repeats = 5;
};

std::vector<std::string> Split(const std::string& list) {
  std::vector<std::string> parts;
  std::size_t start = 0;
  while (start <= list.size()) {
    const std::size_t comma = std::min(list.find(',', start), list.size());
    if (comma > start) parts.push_back(list.substr(start, comma - start));
    start = comma + 1;
  }
  return parts;
}

Options Parse(int argc, char** argv) {
  Options options;
  for (int i = 1; i < argc; ++i) {
    const std::string flag = argv[i];
    if (flag == "--help") {
      std::printf("usage: phase_bench [--scenes a,b] [--worlds N] [--threads N] [--steps N] "
                  "[--warmup N] [--repeats N]\n");
      std::exit(0);
    }
    if (i + 1 >= argc) throw std::invalid_argument(flag + ": needs a value");
    const std::string value = argv[++i];
    const auto count = [&](long low) {
      char* end = nullptr;
      const long n = std::strtol(value.c_str(), &end, 10);
      if (end == value.c_str() || *end != '\0' || n < low) {
        throw std::invalid_argument(flag + " " + value + ": expected an integer >= " +
                                    std::to_string(low));
      }
      return n;
    };
    if (flag == "--scenes") {
      options.scenes = Split(value);
    } else if (flag == "--worlds") {
      options.worlds = std::size_t(count(1));
    } else if (flag == "--threads") {
      options.threads = int(count(1));
    } else if (flag == "--steps") {
      options.steps = int(count(1));
    } else if (flag == "--warmup") {
      options.warmup = int(count(0));
    } else if (flag == "--repeats") {
      options.repeats = int(count(1));
    } else {
      throw std::invalid_argument(flag + ": unknown flag (see --help)");
    }
  }
  return options;
}

// Steps `batch` `steps` times with the scene's actions from step `first`;
// returns the wall time of the Step calls alone (not of writing the actions).
double Run(Batch& batch, const SceneActions& actions, const StepSettings& settings, int first,
           int steps) {
  double seconds = 0.0;
  for (int s = first; s < first + steps; ++s) {
    actions.Apply(batch, std::uint64_t(s), 1);
    const auto start = std::chrono::steady_clock::now();
    batch.Step(settings);
    seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
  return seconds;
}

double Median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  return values[values.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
  Options options;
  try {
    options = Parse(argc, argv);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "phase_bench: %s\n", e.what());
    return 2;
  }
  std::printf("phase breakdown: ns per world-step, %zu worlds, %d thread(s), %d steps x %d "
              "repeats (median)\n",
              options.worlds, options.threads, options.steps, options.repeats);
  std::printf("%-14s", "scene");
  for (std::size_t p = 0; p < kStepPhaseCount; ++p) {
    std::printf(" %11s", StepPhaseName(StepPhase(p)));
  }
  std::printf(" %9s %9s  %s\n", "profiled", "plain", "largest phase");
  bool healthy = true;
  for (const std::string& id : options.scenes) {
    const Scene scene = MakeScene(id);
    const SceneActions actions(id);
    const StepSettings settings = SceneStepSettings(id);
    BatchOptions profiled_options, plain_options;
    profiled_options.threads = plain_options.threads = options.threads;
    profiled_options.profile_phases = true;
    Batch profiled(scene, options.worlds, profiled_options);
    Batch plain(scene, options.worlds, plain_options);
    Run(profiled, actions, settings, 0, options.warmup);
    Run(plain, actions, settings, 0, options.warmup);
    std::vector<std::vector<double>> phase_ns(kStepPhaseCount);
    std::vector<double> profiled_ns, plain_ns;
    const double world_steps = double(options.worlds) * options.steps;
    for (int r = 0; r < options.repeats; ++r) {
      const int first = options.warmup + r * options.steps;
      profiled.ResetPhaseProfile();
      // With one thread the phases sum to the step's wall time; with more,
      // to the threads' time, so both are shown per world-step of the
      // threads' work: profiled wall time x threads.
      profiled_ns.push_back(Run(profiled, actions, settings, first, options.steps) * 1e9 *
                            options.threads / world_steps);
      plain_ns.push_back(Run(plain, actions, settings, first, options.steps) * 1e9 *
                         options.threads / world_steps);
      const PhaseProfile profile = profiled.GetPhaseProfile();
      for (std::size_t p = 0; p < kStepPhaseCount; ++p) {
        phase_ns[p].push_back(profile.seconds[p] * 1e9 / double(profile.world_steps));
      }
    }
    healthy &= profiled.UnhealthyWorldCount() == 0 && plain.UnhealthyWorldCount() == 0;
    std::printf("%-14s", id.c_str());
    double largest = -1.0, total = 0.0;
    std::size_t largest_phase = 0;
    std::vector<double> medians(kStepPhaseCount);
    for (std::size_t p = 0; p < kStepPhaseCount; ++p) {
      medians[p] = Median(phase_ns[p]);
      total += medians[p];
      if (medians[p] > largest) largest = medians[p], largest_phase = p;
    }
    for (std::size_t p = 0; p < kStepPhaseCount; ++p) {
      std::printf(" %6.1f %3.0f%%", medians[p], 100.0 * medians[p] / total);
    }
    std::printf(" %9.1f %9.1f  %s\n", Median(profiled_ns), Median(plain_ns),
                StepPhaseName(StepPhase(largest_phase)));
  }
  if (!healthy) {
    std::fprintf(stderr, "phase_bench: a world went non-finite\n");
    return 1;
  }
  return 0;
}
