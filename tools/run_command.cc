// `manyworlds run`'s options and step loop (tools/run_command.h).

#include "tools/run_command.h"

#include <chrono>
#include <cstdlib>
#include <cstdio>
#include <stdexcept>
#include <string_view>
#include <vector>

#include "manyworlds/error.h"
#include "manyworlds/mass_range.h"

namespace manyworlds::tools {
namespace {

// Applies --mass-range-limit R (0 or absent: off) to `scene` and describes
// what it changed, for the report.
std::string MassRangeLimitOf(const Options& options, Scene& scene) {
  const double limit = MassRangeLimitOption(options);
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

}  // namespace

Options RunOptions(int argc, char** argv) {
  return Options(argc, argv,
                 {"--scene", "--worlds", "--steps", "--threads", "--substeps",
                  "--velocity-iterations", "--velocity-tolerance", "--position-iterations",
                  "--warmup", "--seed",
                  "--mass-range-limit", "--solver", "--exact-tolerance",
                  "--geometric-stiffness", "--curvature-velocity", kRecordOption,
                  kRecordWorldsOption},
                 {"--profile"});
}

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

RunSetup ParseRunSetup(const Options& options) {
  RunSetup setup;
  setup.scene = SceneOf(options);
  setup.scene_id = options.Text("--scene");
  setup.mass_range = MassRangeLimitOf(options, setup.scene);
  setup.worlds = options.Number("--worlds", 4096, 1, std::uint64_t(1) << 26);
  setup.steps = options.Number("--steps", 1000, 1, 1'000'000'000);
  setup.warmup = options.Number("--warmup", 20, 0, 1'000'000'000);
  setup.seed = options.Number("--seed", 1, 0, UINT64_MAX);
  setup.batch_options.threads = int(options.Number("--threads", 0, 0, 4096));
  setup.batch_options.profile_phases = options.Has("--profile");
  // The spec's defaults (dt 1/60 s, gravity -9.81 Y, Baumgarte 0.2), or the
  // stress scene's own dt.
  setup.settings = SceneStepSettings(setup.scene_id);
  setup.settings.substeps = int(options.Number("--substeps", 1, 1, 10'000));
  setup.settings.velocity_iterations =
      int(options.Number("--velocity-iterations", 10, 0, 10'000));
  setup.settings.position_iterations = int(options.Number("--position-iterations", 2, 0, 10'000));
  if (options.Has("--curvature-velocity")) {
    const std::string on = options.Text("--curvature-velocity");
    if (on != "on" && on != "off") {
      throw UsageError("--curvature-velocity = '" + on + "': accepted on (the default) and off");
    }
    setup.settings.exact_curvature_velocity = on == "on";
  }
  const std::string solver = options.Text("--solver", "gauss-seidel");
  if (solver == "exact") {
    setup.settings.solver = JointSolver::kExact;
  } else if (solver != "gauss-seidel") {
    throw UsageError("--solver = '" + solver + "': accepted gauss-seidel (Jolt's, the default) "
                     "and exact");
  }
  // A decimal number in (0, max] (tolerance) or [0, max] (stiffness).
  const auto real = [&](const char* flag, double max, bool zero_allowed, const char* what) {
    const std::string text = options.Text(flag);
    char* end = nullptr;
    const double value = std::strtod(text.c_str(), &end);
    if (text.empty() || *end != '\0' || !(value <= max) || !(zero_allowed ? value >= 0.0 : value > 0.0)) {
      throw UsageError(std::string(flag) + " = '" + text + "': " + what);
    }
    return float(value);
  };
  if (options.Has("--velocity-tolerance")) {
    setup.settings.velocity_tolerance =
        real("--velocity-tolerance", 1e6, true, "a velocity in m/s and rad/s in [0, 1e6]");
  }
  if (options.Has("--exact-tolerance")) {
    setup.settings.exact_tolerance = real("--exact-tolerance", 1.0, false, "a length in m in (0, 1]");
  }
  if (options.Has("--geometric-stiffness")) {
    setup.settings.exact_geometric_stiffness =
        real("--geometric-stiffness", 1e6, true, "a factor in [0, 1e6]");
  }
  return setup;
}

LoopResult StepLoop(Batch& batch, std::uint64_t first_world, const RunSetup& setup,
                    RunRecording& recording, ProgressLine& progress,
                    const std::function<bool()>& stop_requested,
                    const std::function<void()>& step_batch,
                    const std::function<void()>& timing_starts) {
  const SceneActions actions(setup.scene_id);
  const std::uint64_t last = setup.warmup + setup.steps;
  std::uint64_t step = 0;
  recording.Capture(batch, step);
  const auto one_step = [&] {
    actions.Apply(batch, step, setup.seed, first_world);
    step_batch();
    recording.Capture(batch, step + 1);
    progress.Update(step + 1);
  };
  for (; step < setup.warmup && !stop_requested(); ++step) one_step();
  batch.ResetPhaseProfile();  // --profile: the timed steps only
  timing_starts();
  const auto start = std::chrono::steady_clock::now();
  for (; step < last && !stop_requested(); ++step) one_step();
  LoopResult result;
  result.timed_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  result.steps_done = step;
  // A SIGINT after the last step changes nothing: the run is complete.
  result.interrupted = step < last;
  return result;
}

int ReportInterrupted(std::uint64_t steps_done, const RunSetup& setup, const char* signal) {
  std::fprintf(stderr, "manyworlds: interrupted by %s after step %llu of %llu; the report "
                       "covers the steps done\n",
               signal, static_cast<unsigned long long>(steps_done),
               static_cast<unsigned long long>(setup.warmup + setup.steps));
  return 130;
}

bool StartedByMpirun() {
  // An escape for a program started by an MPI process (which inherits these
  // variables) that must not join its job: MANYWORLDS_NO_MPI=1.
  const char* no_mpi = std::getenv("MANYWORLDS_NO_MPI");
  if (no_mpi != nullptr && std::string_view(no_mpi) == "1") return false;
  for (const char* variable : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_SIZE"}) {
    if (std::getenv(variable) != nullptr) return true;
  }
  return false;
}

int ReportError(std::exception_ptr error, bool print) {
  try {
    std::rethrow_exception(error);
  } catch (const UsageError& e) {
    if (print) std::fprintf(stderr, "manyworlds: %s\nrun 'manyworlds --help' for usage\n", e.what());
    return 2;
  } catch (const SceneError& e) {
    if (print) std::fprintf(stderr, "manyworlds: the scene was refused: %s\n", e.what());
    return 1;
  } catch (const std::exception& e) {
    if (print) std::fprintf(stderr, "manyworlds: %s\n", e.what());
    return 1;
  } catch (...) {
    if (print) std::fprintf(stderr, "manyworlds: an exception that is not a std::exception\n");
    return 1;
  }
}

}  // namespace manyworlds::tools
