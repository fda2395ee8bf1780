// manyworlds: step a reference scene in many worlds and report throughput and
// constraint error; print a scene's plan; list the scenes (docs/scenes.md).
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
// something (sweep: also an earlier report without --overwrite), 2 bad arguments.

#include <algorithm>
#include <chrono>
#include <cmath>
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
#include "tools/record_option.h"
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
    "      steps N worlds of a reference or stress scene and reports throughput and constraint\n"
    "      error (defaults: 4096 worlds, 1000 timed steps after 20 warm-up steps,\n"
    "      threads 0 = every core, 1 substep, 10 velocity and 2 position iterations,\n"
    "      seed 1 for the actions; --mass-range-limit R >= 1 first raises every body\n"
    "      lighter than 1/R of the heaviest body joined to it through dynamic\n"
    "      bodies, LimitMassRange, docs/stability.md; 0 = off, the default;\n"
    "      --record FILE writes worlds LIST (default 0) every step to the NPZ file\n"
    "      FILE, which must not exist, docs/recording.md)\n"
    "  manyworlds plan --scene ID     prints what one step of the scene runs\n"
    "  manyworlds scenes              lists the reference and stress scene ids\n"
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
    "      2 values per knob; see docs/accuracy.md)\n";

// The scene of --scene; a UsageError naming the option for an unknown id.
Scene SceneOf(const Options& options) {
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

int Scenes() {
  const std::vector<std::string> stress = StressSceneIds();
  for (const std::string& id : AllSceneIds()) {
    const Scene scene = MakeScene(id);
    const bool is_stress = std::find(stress.begin(), stress.end(), id) != stress.end();
    std::printf("%-19s %3zu bodies, %3zu constraints%s%s, dt %g s\n", id.c_str(),
                scene.bodies().size(), scene.constraints().size(),
                SceneActions(id).empty() ? "" : ", actions", is_stress ? ", stress" : "",
                double(SceneStepSettings(id).delta_time));
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
                         tools::kRecordWorldsOption});
  const std::string id = options.Text("--scene");
  Scene scene = SceneOf(options);
  const std::string mass_range = MassRangeLimitOf(options, scene);
  const std::size_t worlds = options.Number("--worlds", 4096, 1, std::uint64_t(1) << 26);
  const std::uint64_t steps = options.Number("--steps", 1000, 1, 1'000'000'000);
  const std::uint64_t warmup = options.Number("--warmup", 20, 0, 1'000'000'000);
  const std::uint64_t seed = options.Number("--seed", 1, 0, UINT64_MAX);
  BatchOptions batch_options;
  batch_options.threads = int(options.Number("--threads", 0, 0, 4096));
  // The spec's defaults (dt 1/60 s, gravity -9.81 Y, Baumgarte 0.2), or the
  // stress scene's own dt.
  StepSettings settings = SceneStepSettings(options.Text("--scene"));
  settings.substeps = int(options.Number("--substeps", 1, 1, 10'000));
  settings.velocity_iterations = int(options.Number("--velocity-iterations", 10, 0, 10'000));
  settings.position_iterations = int(options.Number("--position-iterations", 2, 0, 10'000));

  Batch batch(scene, worlds, batch_options);
  const SceneActions actions(id);
  tools::RunRecording recording(options, batch, id, settings.delta_time);
  std::uint64_t step = 0;
  recording.Capture(batch, step);
  for (; step < warmup; ++step) {
    actions.Apply(batch, step, seed);
    batch.Step(settings);
    recording.Capture(batch, step + 1);
  }
  const auto start = std::chrono::steady_clock::now();
  for (; step < warmup + steps; ++step) {
    actions.Apply(batch, step, seed);
    batch.Step(settings);
    recording.Capture(batch, step + 1);
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  recording.Close();

  // Accuracy and health after the last step.
  float max_error = 0.0f;
  double sum_error = 0.0;
  std::size_t bad_error = 0;
  for (std::size_t w = 0; w < worlds; ++w) {
    const float e = batch.MaxConstraintError(w);
    if (!std::isfinite(e)) {
      ++bad_error;
      continue;
    }
    max_error = std::max(max_error, e);
    sum_error += e;
  }
  // The library's own health check of the last step (WorldHealthBits).
  std::size_t by_bit[4] = {0, 0, 0, 0};
  for (const std::uint8_t bits : batch.WorldHealth()) {
    for (int bit = 0; bit < 4; ++bit) by_bit[bit] += (bits >> bit) & 1u;
  }

  const double world_steps = double(worlds) * double(steps);
  std::printf("scene:                %s (%zu bodies, %zu constraints)\n", id.c_str(),
              batch.body_count(), batch.constraint_count());
  std::printf("worlds:               %zu\n", worlds);
  std::printf("threads:              %d\n", batch.threads());
  std::printf("SIMD target:          %s, %zu float lanes per vector\n", batch.SimdTarget(),
              batch.SimdLanes());
  std::printf("precision:            float\n");
  std::printf("mass-range limit:     %s\n", mass_range.c_str());
  std::printf("iterations:           %d velocity, %d position, %d substep(s), Baumgarte %g\n",
              settings.velocity_iterations, settings.position_iterations, settings.substeps,
              double(settings.baumgarte));
  std::printf("dt:                   %.6g s per step, gravity (%g, %g, %g) m/s^2\n",
              double(settings.delta_time), double(settings.gravity[0]),
              double(settings.gravity[1]), double(settings.gravity[2]));
  const char* action_text =
      actions.empty() ? "none"
      : actions.forces_per_world() != 0
          ? "every step (cart force along X, uniform [-10, 10] N)"
          : "every step (elbow and knee position targets, uniform in their limits)";
  std::printf("actions:              %s\n", action_text);
  std::printf("recording:            %s\n", recording.Describe().c_str());
  std::printf("timed:                %llu steps after %llu warm-up steps, %.3f s wall\n",
              static_cast<unsigned long long>(steps), static_cast<unsigned long long>(warmup),
              seconds);
  std::printf("throughput:           %.4g world-steps/s\n", world_steps / seconds);
  std::printf("time per world-step:  %.4g ns\n", seconds * 1e9 / world_steps);
  std::printf("memory:               %zu bytes per world (state, parameters, scratch)\n",
              batch.BytesPerWorld());
  std::printf("constraint error:     max over worlds %.3g, mean over worlds %.3g, after step "
              "%llu (m for linear rows, rad for angular rows)\n",
              double(max_error), worlds > bad_error ? sum_error / double(worlds - bad_error) : 0.0,
              static_cast<unsigned long long>(warmup + steps));
  std::printf("unhealthy worlds:     %zu of %zu after the last step (non-finite state %zu, "
              "velocity overflow %zu, position out of range %zu, non-finite input %zu); "
              "%zu with a non-finite constraint error\n",
              batch.UnhealthyWorldCount(), worlds, by_bit[0], by_bit[1], by_bit[2], by_bit[3],
              bad_error);
  return 0;
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
      if (argc > 2) throw UsageError("'scenes' takes no arguments");
      return Scenes();
    }
    if (command == "help") {
      std::printf("%s", kUsage);
      return 0;
    }
    throw UsageError(command.empty() ? "no command given"
                                     : "unknown command '" + std::string(command) + "'");
  } catch (const UsageError& e) {
    std::fprintf(stderr, "manyworlds: %s\n%s", e.what(), kUsage);
    return 2;
  } catch (const SceneError& e) {
    std::fprintf(stderr, "manyworlds: the scene was refused: %s\n", e.what());
    return 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "manyworlds: %s\n", e.what());
    return 1;
  }
}
