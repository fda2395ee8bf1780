// manyworlds: step a reference scene in many worlds and report throughput and
// constraint error; print a scene's plan; list the scenes (docs/scenes.md).
// The run's report is tools/run_report.cc, its progress line and Ctrl-C stop
// tools/progress.cc.
//
//   manyworlds run --scene cartpole --worlds 4096 --steps 1000 [--threads N]
//                  [--substeps N] [--velocity-iterations N] [--position-iterations N]
//                  [--warmup N] [--seed N] [--mass-range-limit R]
//                  [--record FILE [--record-worlds 0,1,7]]
//   manyworlds plan --scene ID
//   manyworlds scenes
//   manyworlds sweep [--scenes A,B] [--worlds N] [--seconds S] [--small] ... (tools/sweep.h)
//
// Exit codes: 0 success, 1 the library, the file system or gnuplot refused
// something (sweep: also an earlier report without --overwrite), 2 bad
// arguments (one line on stderr naming the argument and what is accepted, and
// a hint), 130 a run stopped by Ctrl-C (SIGINT), after its report.

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "manyworlds/batch.h"
#include "manyworlds/error.h"
#include "manyworlds/mass_range.h"
#include "manyworlds/scene.h"
#include "manyworlds/scenes.h"
#include "tools/options.h"
#include "tools/progress.h"
#include "tools/record_option.h"
#include "tools/run_report.h"
#include "tools/sweep.h"

namespace {

using namespace manyworlds;
using tools::Options;
using tools::UsageError;

constexpr const char* kUsage =
    "usage:\n"
    "  manyworlds run --scene ID [--worlds N] [--steps N] [--threads N] [--substeps N]\n"
    "                 [--velocity-iterations N] [--position-iterations N] [--warmup N]\n"
    "                 [--seed N] [--mass-range-limit R] [--record FILE [--record-worlds LIST]]\n"
    "                 [--profile]\n"
    "      steps N worlds of a reference or stress scene and reports throughput and constraint\n"
    "      error (defaults: 4096 worlds, 1000 timed steps after 20 warm-up steps,\n"
    "      threads 0 = every core, 1 substep, 10 velocity and 2 position iterations,\n"
    "      seed 1 for the actions; --mass-range-limit R >= 1 first raises every body\n"
    "      lighter than 1/R of the heaviest body joined to it through dynamic\n"
    "      bodies, LimitMassRange, docs/stability.md; 0 = off, the default).\n"
    "      Constraint errors after the last step, linear (m) and angular (rad) apart,\n"
    "      max and mean over worlds. On a terminal a progress line shows the steps\n"
    "      done, world-steps/s and the time left; Ctrl-C stops at the next step,\n"
    "      reports the steps done and exits with 130 (a second Ctrl-C kills);\n"
    "      --record FILE writes worlds LIST (default 0) every step to the NPZ file\n"
    "      FILE, which must not exist, docs/recording.md); --profile adds where the\n"
    "      timed steps' time went, phase by phase (BatchOptions::profile_phases)\n"
    "  manyworlds plan --scene ID     prints what one step of the scene runs\n"
    "  manyworlds scenes              lists every scene id: bodies, constraints and\n"
    "                                 what it tests\n"
    "  manyworlds sweep [--scenes A,B] [--worlds N] [--seconds S] [--threads N]\n"
    "                   [--sample-worlds N] [--passes N] [--min-time S] [--grid knobs|full]\n"
    "                   [--out DIR] [--overwrite] [--seed N] [--small] [--mass-range-limit R]\n"
    "      error against run time: steps every scene at each setting of substeps\n"
    "      (1 2 4 8), velocity (1 2 4 8 10) and position iterations (0 1 2), one knob\n"
    "      at a time from 1/10/2 (--grid full: every combination), and writes\n"
    "      DIR/sweep.csv, sweep.md, sweep.gp and, when gnuplot is installed, one PNG\n"
    "      per scene (defaults: every scene, 1024 worlds timed on 1 thread, 1 s\n"
    "      simulated, errors over 16 worlds, out dir 'sweep', whose earlier report only\n"
    "      --overwrite replaces; --small: rackpinion and chain16, 64 worlds, 0.25 s,\n"
    "      2 values per knob; see docs/accuracy.md)\n"
    "  manyworlds help | --help | -h  prints this\n"
    "exit codes: 0 done, 1 refused by the library or the file system, 2 bad\n"
    "arguments, 130 run interrupted by Ctrl-C\n";

// The exit code of a run stopped by SIGINT: 128 + 2, what a shell reports
// for a program the signal killed.
constexpr int kExitInterrupted = 130;

// The line after a usage error, instead of the whole usage.
constexpr const char* kUsageHint = "run 'manyworlds --help' for usage";

// The scene of --scene; a UsageError naming the option for a missing or
// unknown id (the library's message lists every valid id).
Scene SceneOf(const Options& options) {
  if (!options.Has("--scene")) {
    throw UsageError("--scene is required: a scene id, e.g. cartpole ('manyworlds scenes' "
                     "lists them all)");
  }
  try {
    return MakeScene(options.Text("--scene"));
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string("--scene: ") + e.what());
  }
}

// Applies --mass-range-limit R (0 or absent: off) to `scene` and describes
// what it changed, for the report.
std::string MassRangeLimitOf(const Options& options, Scene& scene) {
  const double limit = tools::MassRangeLimitOption(options);
  if (limit == 0) return "off";
  const auto dynamic_mass = [&scene] {
    double sum = 0;
    for (const BodySettings& body : scene.bodies()) {
      if (body.motion_type == MotionType::kDynamic) sum += double(body.mass);
    }
    return sum;
  };
  const double before = dynamic_mass();
  const std::vector<MassRaise> raised = LimitMassRange(scene, float(limit));
  const double after = dynamic_mass();
  char text[160];
  std::snprintf(text, sizeof text,
                "%g: %zu bodies raised, dynamic mass %.4g kg -> %.4g kg (%+.3g %%)",
                limit, raised.size(), before, after,
                before > 0 ? 100.0 * (after - before) / before : 0.0);
  return text;
}

// One line per scene: id, bodies, constraints and what it tests.
int Scenes() {
  for (const std::string& id : AllSceneIds()) {
    const Scene scene = MakeScene(id);
    const std::size_t constraints = scene.constraints().size();
    std::printf("%-19s %3zu bodies %3zu %-11s  %s\n", id.c_str(), scene.bodies().size(),
                constraints, constraints == 1 ? "constraint" : "constraints",
                SceneDescription(id).c_str());
  }
  return 0;
}

int Plan(int argc, char** argv) {
  const Options options(argc, argv, {"--scene"});
  const Batch batch(SceneOf(options), 1, BatchOptions{.threads = 1});
  std::printf("scene %s\n%s", options.Text("--scene").c_str(), batch.Plan().c_str());
  return 0;
}

int Run(int argc, char** argv) {
  const Options options(argc, argv,
                        {"--scene", "--worlds", "--steps", "--threads", "--substeps",
                         "--velocity-iterations", "--position-iterations", "--warmup",
                         "--seed", "--mass-range-limit", tools::kRecordOption,
                         tools::kRecordWorldsOption},
                        {"--profile"});
  Scene scene = SceneOf(options);
  const std::string id = options.Text("--scene");
  const std::string mass_range = MassRangeLimitOf(options, scene);
  const std::size_t worlds = options.Number("--worlds", 4096, 1, std::uint64_t(1) << 26);
  const std::uint64_t steps = options.Number("--steps", 1000, 1, 1'000'000'000);
  const std::uint64_t warmup = options.Number("--warmup", 20, 0, 1'000'000'000);
  const std::uint64_t seed = options.Number("--seed", 1, 0, UINT64_MAX);
  BatchOptions batch_options;
  batch_options.threads = int(options.Number("--threads", 0, 0, 4096));
  batch_options.profile_phases = options.Has("--profile");
  // The spec's defaults (dt 1/60 s, gravity -9.81 Y, Baumgarte 0.2), or the
  // stress scene's own dt.
  StepSettings settings = SceneStepSettings(options.Text("--scene"));
  settings.substeps = int(options.Number("--substeps", 1, 1, 10'000));
  settings.velocity_iterations = int(options.Number("--velocity-iterations", 10, 0, 10'000));
  settings.position_iterations = int(options.Number("--position-iterations", 2, 0, 10'000));

  Batch batch(scene, worlds, batch_options);
  const SceneActions actions(id);
  tools::RunRecording recording(options, batch, id, settings.delta_time);
  // Ctrl-C stops at the next step boundary and still reports; on a terminal
  // a progress line shows how far the run is (tools/progress.h).
  const tools::SigintStop sigint;
  tools::ProgressLine progress(warmup + steps, worlds);
  std::uint64_t step = 0;
  recording.Capture(batch, step);
  for (; step < warmup && !sigint.requested(); ++step) {
    actions.Apply(batch, step, seed);
    batch.Step(settings);
    recording.Capture(batch, step + 1);
    progress.Update(step + 1);
  }
  batch.ResetPhaseProfile();  // --profile: the timed steps only
  const auto start = std::chrono::steady_clock::now();
  for (; step < warmup + steps && !sigint.requested(); ++step) {
    actions.Apply(batch, step, seed);
    batch.Step(settings);
    recording.Capture(batch, step + 1);
    progress.Update(step + 1);
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  progress.Erase();
  recording.Close();
  // A SIGINT after the last step changes nothing: the run is complete.
  const bool interrupted = step < warmup + steps;
  tools::PrintRunReport(batch, actions,
                        {.scene_id = id,
                         .mass_range = mass_range,
                         .settings = settings,
                         .warmup_steps = warmup,
                         .timed_steps = steps,
                         .steps_done = step,
                         .timed_seconds = seconds,
                         .interrupted = interrupted,
                         .recording = recording.Describe()});
  if (!interrupted) return 0;
  std::fprintf(stderr, "manyworlds: interrupted by SIGINT after step %llu of %llu; the report "
                       "covers the steps done\n",
               static_cast<unsigned long long>(step),
               static_cast<unsigned long long>(warmup + steps));
  return kExitInterrupted;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string_view command = argc > 1 ? argv[1] : "";
  for (int i = 1; i < argc; ++i) {
    if (std::string_view(argv[i]) == "--help" || std::string_view(argv[i]) == "-h") {
      std::printf("%s", kUsage);
      return 0;
    }
  }
  try {
    if (command == "run") return Run(argc, argv);
    if (command == "plan") return Plan(argc, argv);
    if (command == "sweep") return tools::Sweep(argc, argv);
    if (command == "scenes") {
      if (argc > 2) {
        throw UsageError("'scenes' takes no arguments, got '" + std::string(argv[2]) + "'");
      }
      return Scenes();
    }
    if (command == "help") {
      std::printf("%s", kUsage);
      return 0;
    }
    constexpr const char* kCommands = "; commands: run, plan, scenes, sweep, help";
    throw UsageError(command.empty() ? std::string("no command given") + kCommands
                                     : "unknown command '" + std::string(command) + "'" +
                                           kCommands);
  } catch (const UsageError& e) {
    std::fprintf(stderr, "manyworlds: %s\n%s\n", e.what(), kUsageHint);
    return 2;
  } catch (const SceneError& e) {
    std::fprintf(stderr, "manyworlds: the scene was refused: %s\n", e.what());
    return 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "manyworlds: %s\n", e.what());
    return 1;
  }
}
