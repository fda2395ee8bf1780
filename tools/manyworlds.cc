// manyworlds: step a reference scene in many worlds and report throughput and
// constraint error; print a scene's plan; list the scenes (docs/scenes.md).
// The run's report is tools/run_report.cc, its progress line and Ctrl-C stop
// tools/progress.cc.
//
//   manyworlds run --scene cartpole --worlds 4096 --steps 1000 [--threads N]
//                  [--substeps N] [--velocity-iterations N] [--velocity-tolerance V]
//                  [--position-iterations N]
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
#include "tools/run_command.h"
#include "tools/run_report.h"
#include "tools/sweep.h"
#ifdef MANYWORLDS_WITH_MPI
#include "tools/sharded_run.h"
#endif

namespace {

using namespace manyworlds;
using tools::Options;
using tools::UsageError;

constexpr const char* kUsage =
    "usage:\n"
    "  manyworlds run --scene ID [--worlds N] [--steps N] [--threads N] [--substeps N]\n"
    "                 [--velocity-iterations N] [--velocity-tolerance V]\n"
    "                 [--position-iterations N] [--warmup N]\n"
    "                 [--seed N] [--mass-range-limit R] [--record FILE [--record-worlds LIST]]\n"
    "                 [--solver gauss-seidel|exact [--exact-tolerance M]\n"
    "                 [--geometric-stiffness F] [--curvature-velocity on|off]]\n"
    "                 [--profile]\n"
    "      steps N worlds of a reference or stress scene and reports throughput and constraint\n"
    "      error (defaults: 4096 worlds, 1000 timed steps after 20 warm-up steps,\n"
    "      threads 0 = every core, 1 substep, 10 velocity and 2 position iterations,\n"
    "      seed 1 for the actions; --mass-range-limit R >= 1 first raises every body\n"
    "      lighter than 1/R of the heaviest body joined to it through dynamic\n"
    "      bodies, LimitMassRange, docs/stability.md; 0 = off, the default).\n"
    "      --velocity-tolerance V > 0 lets each world stop its velocity iterations after\n"
    "      the first pass that changed no body's velocity by more than V m/s or rad/s\n"
    "      (StepSettings::velocity_tolerance; default 0: every pass, as Jolt).\n"
    "      --solver exact solves all equality rows of a scene at once (ball, hinge,\n"
    "      fixed, slider, gear, rack and pinion, swing-twist, cone, rod, six-DOF's\n"
    "      all-fixed parts; motors, limits, a six-DOF's other rows, ropes, struts,\n"
    "      springs, pulley and path constraints around it; docs/stepping.md):\n"
    "      --position-iterations is then the most Newton position steps per substep\n"
    "      (4 hold the chains, 30 chain16-r1000), --exact-tolerance the error\n"
    "      they stop at (default 1e-5 m or rad),\n"
    "      --geometric-stiffness how much of the joints' pull is taken implicitly\n"
    "      (default 1; 0 off), --curvature-velocity whether the velocities take\n"
    "      the normal velocity the joints' curvature needs over a step where every\n"
    "      joint is an equality (default on; off loses energy at first order).\n"
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
    "                   [--solver gauss-seidel|exact]\n"
    "      error against run time: steps every scene at each setting of substeps\n"
    "      (1 2 4 8), velocity (1 2 4 8 10) and position iterations (0 1 2), one knob\n"
    "      at a time from 1/10/2 (--grid full: every combination), and writes\n"
    "      DIR/sweep.csv, sweep.md, sweep.gp and, when gnuplot is installed, one PNG\n"
    "      per scene (defaults: every scene, 1024 worlds timed on 1 thread, 1 s\n"
    "      simulated, errors over 16 worlds, out dir 'sweep', whose earlier report only\n"
    "      --overwrite replaces; --small: rackpinion and chain16, 64 worlds, 0.25 s,\n"
    "      2 values per knob; see docs/accuracy.md); --solver exact sweeps the exact\n"
    "      joint solve (every reference scene) over substeps 1 2 4\n"
    "      and 2 4 10 30 Newton steps, every combination\n"
    "  manyworlds help | --help | -h  prints this\n"
    "exit codes: 0 done, 1 refused by the library or the file system, 2 bad\n"
    "arguments, 130 run interrupted by Ctrl-C\n";

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
  const Options options = tools::RunOptions(argc, argv);
  const tools::RunSetup setup = tools::ParseRunSetup(options);
  Batch batch(setup.scene, setup.worlds, setup.batch_options);
  tools::RunRecording recording(options, batch, setup.scene_id, setup.settings.delta_time);
  // Ctrl-C stops at the next step boundary and still reports; on a terminal
  // a progress line shows how far the run is (tools/progress.h).
  const tools::SigintStop sigint;
  tools::ProgressLine progress(setup.warmup + setup.steps, setup.worlds);
  const tools::LoopResult loop = tools::StepLoop(
      batch, 0, setup, recording, progress, [&] { return sigint.requested(); },
      [&] { batch.Step(setup.settings); }, [] {});
  progress.Erase();
  recording.Close();
  const std::uint64_t timed_done = loop.steps_done - std::min(loop.steps_done, setup.warmup);
  tools::PrintRunReport(batch, SceneActions(setup.scene_id),
                        {.scene_id = setup.scene_id,
                         .mass_range = setup.mass_range,
                         .settings = setup.settings,
                         .warmup_steps = setup.warmup,
                         .timed_steps = setup.steps,
                         .steps_done = loop.steps_done,
                         .timed_seconds = loop.timed_seconds,
                         .interrupted = loop.interrupted,
                         .stop_signal = "SIGINT",
                         .recording = recording.Describe(),
                         .rank_worlds = {},
                         .rank_world_steps_per_second = {},
                         .rank_other_seconds_per_step = {}},
                        tools::WorldStats::Of(batch, timed_done));
  return loop.interrupted ? tools::ReportInterrupted(loop.steps_done, setup) : 0;
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
    if (command == "run") {
      // `mpirun -n R manyworlds run ...`: the worlds sharded over the ranks.
      if (tools::StartedByMpirun()) {
#ifdef MANYWORLDS_WITH_MPI
        return tools::ShardedRun(argc, argv);
#else
        throw std::runtime_error(
            "started by mpirun, but this manyworlds was built without MPI: install "
            "libopenmpi-dev (scripts/install-deps does) and build again, or run without mpirun");
#endif
      }
      return Run(argc, argv);
    }
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
  } catch (...) {
    return tools::ReportError(std::current_exception(), true);
  }
}
