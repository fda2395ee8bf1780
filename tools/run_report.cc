// The report of `manyworlds run` (tools/run_report.h).

#include "tools/run_report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <span>

namespace manyworlds::tools {
namespace {

// Max and mean over worlds of one part of the constraint error; worlds whose
// error is not finite are counted apart, not averaged in.
struct OverWorlds {
  double max = 0.0;
  double sum = 0.0;
  std::size_t finite = 0;
  void Add(double error) {
    max = std::max(max, error);
    sum += error;
    ++finite;
  }
  double mean() const { return finite > 0 ? sum / double(finite) : 0.0; }
};

unsigned long long Ull(std::uint64_t value) { return static_cast<unsigned long long>(value); }

}  // namespace

void PrintRunReport(const Batch& batch, const SceneActions& actions, const RunFacts& facts) {
  const std::size_t worlds = batch.world_count();
  const StepSettings& settings = facts.settings;
  // A run stopped by SIGINT may have stopped in the warm-up: then no step was timed.
  const std::uint64_t warmup_done = std::min(facts.steps_done, facts.warmup_steps);
  const std::uint64_t timed_done = facts.steps_done - warmup_done;

  // Accuracy and health after the last step.
  OverWorlds linear, angular;
  std::size_t bad_error = 0;
  for (std::size_t w = 0; w < worlds; ++w) {
    const ConstraintErrorSplit e = batch.MaxConstraintErrorSplit(w);
    if (!std::isfinite(e.linear) || !std::isfinite(e.angular)) {
      ++bad_error;
      continue;
    }
    linear.Add(e.linear);
    angular.Add(e.angular);
  }
  // The library's own health check of the last step (WorldHealthBits).
  std::size_t by_bit[4] = {0, 0, 0, 0};
  for (const std::uint8_t bits : batch.WorldHealth()) {
    for (int bit = 0; bit < 4; ++bit) by_bit[bit] += (bits >> bit) & 1u;
  }

  std::printf("scene:                %s (%zu bodies, %zu %s)\n", facts.scene_id.c_str(),
              batch.body_count(), batch.constraint_count(),
              batch.constraint_count() == 1 ? "constraint" : "constraints");
  std::printf("worlds:               %zu\n", worlds);
  std::printf("threads:              %d\n", batch.threads());
  std::printf("SIMD target:          %s, %zu float lanes per vector\n", batch.SimdTarget(),
              batch.SimdLanes());
  std::printf("precision:            float\n");
  std::printf("mass-range limit:     %s\n", facts.mass_range.c_str());
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
  std::printf("recording:            %s\n", facts.recording.c_str());
  if (!facts.interrupted) {
    std::printf("timed:                %llu steps after %llu warm-up steps, %.3f s wall\n",
                Ull(facts.timed_steps), Ull(facts.warmup_steps), facts.timed_seconds);
  } else {
    std::printf("timed:                %llu of %llu steps after %llu of %llu warm-up steps, "
                "%.3f s wall; interrupted by SIGINT after step %llu of %llu\n",
                Ull(timed_done), Ull(facts.timed_steps), Ull(warmup_done),
                Ull(facts.warmup_steps), facts.timed_seconds, Ull(facts.steps_done),
                Ull(facts.warmup_steps + facts.timed_steps));
  }
  const double world_steps = double(worlds) * double(timed_done);
  if (timed_done > 0 && facts.timed_seconds > 0) {
    std::printf("throughput:           %.4g world-steps/s\n", world_steps / facts.timed_seconds);
    std::printf("time per world-step:  %.4g ns\n", facts.timed_seconds * 1e9 / world_steps);
  } else {
    std::printf("throughput:           none (no timed step)\n");
    std::printf("time per world-step:  none (no timed step)\n");
  }
  // --profile: the timed steps' phases (the profile is reset after the
  // warm-up), in thread time per world-step, so they add up to the time per
  // world-step times the threads, less scheduling.
  const PhaseProfile profile = batch.GetPhaseProfile();
  if (profile.world_steps > 0) {
    double total = 0.0;
    for (double seconds : profile.seconds) total += seconds;
    std::printf("phases:               ns per world-step (thread time) and share, %.4g ns in all\n",
                total * 1e9 / double(profile.world_steps));
    for (std::size_t p = 0; p < kStepPhaseCount; ++p) {
      std::printf("  %-19s %8.4g ns  %4.1f %%\n", StepPhaseName(StepPhase(p)),
                  profile.seconds[p] * 1e9 / double(profile.world_steps),
                  total > 0 ? 100.0 * profile.seconds[p] / total : 0.0);
    }
  }
  std::printf("memory:               %zu bytes per world (state, parameters, scratch)\n",
              batch.BytesPerWorld());
  // batch/constraint_error.h: each world's worst row of each unit, measured
  // against the constraint itself (0 = it holds exactly), not a reference run.
  std::printf("constraint error:     how far the poses after step %llu violate the constraints "
              "(0 = exact), worst row of each world, max and mean over worlds:\n",
              Ull(facts.steps_done));
  std::printf("  linear:             max %.3g m, mean %.3g m (anchor separation, anchor off "
              "a slider axis or path, linear limit, distance and pulley length violations)\n",
              linear.max, linear.mean());
  std::printf("  angular:            max %.3g rad, mean %.3g rad (rotation from the rest pose, "
              "angle between hinge axes, angular limit violations, gear and rack-and-pinion "
              "coupling)\n",
              angular.max, angular.mean());
  std::printf("unhealthy worlds:     %zu of %zu after the last step (non-finite state %zu, "
              "velocity overflow %zu, position out of range %zu, non-finite input %zu); "
              "%zu with a non-finite constraint error\n",
              batch.UnhealthyWorldCount(), worlds, by_bit[0], by_bit[1], by_bit[2], by_bit[3],
              bad_error);
}

}  // namespace manyworlds::tools
