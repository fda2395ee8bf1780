// The report of `manyworlds run` (tools/run_report.h).

#include "tools/run_report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <span>
#include <vector>

#include "batch/hash.h"

namespace manyworlds::tools {
namespace {

unsigned long long Ull(std::uint64_t value) { return static_cast<unsigned long long>(value); }

}  // namespace

WorldStats WorldStats::Of(const Batch& batch, std::uint64_t timed_steps_done,
                          std::uint64_t first_world) {
  WorldStats stats;
  const std::size_t per_world = batch.body_count() * kStateFloatsPerBody;
  std::vector<float> states(batch.world_count() * per_world);
  batch.GetState(states);
  for (std::size_t w = 0; w < batch.world_count(); ++w) {
    std::uint64_t hash = SplitMix64(first_world + w);
    for (std::size_t i = 0; i < per_world; ++i) {
      std::uint32_t bits;
      std::memcpy(&bits, &states[w * per_world + i], sizeof bits);
      hash = SplitMix64(hash ^ bits);
    }
    stats.state_digest += hash;
  }
  stats.worlds = batch.world_count();
  stats.timed_world_steps = stats.worlds * timed_steps_done;
  // Worlds whose error is not finite are counted apart, not averaged in.
  for (std::size_t w = 0; w < batch.world_count(); ++w) {
    const ConstraintErrorSplit e = batch.MaxConstraintErrorSplit(w);
    if (!std::isfinite(e.linear) || !std::isfinite(e.angular)) {
      ++stats.non_finite_errors;
      continue;
    }
    ++stats.finite_errors;
    stats.linear_max = std::max(stats.linear_max, e.linear);
    stats.linear_sum += e.linear;
    stats.angular_max = std::max(stats.angular_max, e.angular);
    stats.angular_sum += e.angular;
  }
  // The library's own health check of the last step (WorldHealthBits).
  for (const std::uint8_t bits : batch.WorldHealth()) {
    stats.unhealthy += bits != 0;
    for (int bit = 0; bit < 4; ++bit) stats.by_bit[bit] += (bits >> bit) & 1u;
  }
  return stats;
}

void WorldStats::Add(const WorldStats& other) {
  worlds += other.worlds;
  timed_world_steps += other.timed_world_steps;
  finite_errors += other.finite_errors;
  non_finite_errors += other.non_finite_errors;
  linear_max = std::max(linear_max, other.linear_max);
  linear_sum += other.linear_sum;
  angular_max = std::max(angular_max, other.angular_max);
  angular_sum += other.angular_sum;
  unhealthy += other.unhealthy;
  for (int bit = 0; bit < 4; ++bit) by_bit[bit] += other.by_bit[bit];
  state_digest += other.state_digest;
}

void PrintRunReport(const Batch& batch, const SceneActions& actions, const RunFacts& facts,
                    const WorldStats& stats) {
  const StepSettings& settings = facts.settings;
  // A run stopped by SIGINT may have stopped in the warm-up: then no step was timed.
  const std::uint64_t warmup_done = std::min(facts.steps_done, facts.warmup_steps);
  const std::uint64_t timed_done = facts.steps_done - warmup_done;
  const std::size_t ranks = std::max<std::size_t>(facts.rank_worlds.size(), 1);

  std::printf("scene:                %s (%zu bodies, %zu %s)\n", facts.scene_id.c_str(),
              batch.body_count(), batch.constraint_count(),
              batch.constraint_count() == 1 ? "constraint" : "constraints");
  std::printf("worlds:               %llu\n", Ull(stats.worlds));
  if (!facts.rank_worlds.empty()) {
    std::printf("ranks:                %zu (MPI), worlds per rank", ranks);
    for (const std::size_t worlds : facts.rank_worlds) std::printf(" %zu", worlds);
    std::printf("\n");
  }
  std::printf("threads:              %d%s\n", batch.threads(),
              facts.rank_worlds.empty() ? "" : " per rank");
  std::printf("SIMD target:          %s, %zu float lanes per vector\n", batch.SimdTarget(),
              batch.SimdLanes());
  std::printf("precision:            float\n");
  std::printf("mass-range limit:     %s\n", facts.mass_range.c_str());
  if (settings.solver == JointSolver::kExact) {
    std::printf("solver:               exact: joints solved at once (geometric stiffness %g, "
                "curvature velocity %s), up to %d Newton position steps to %g m, %d "
                "substep(s)\n",
                double(settings.exact_geometric_stiffness),
                settings.exact_curvature_velocity ? "on" : "off", settings.position_iterations,
                double(settings.exact_tolerance), settings.substeps);
  } else {
    std::printf("iterations:           %d velocity, %d position, %d substep(s), Baumgarte %g\n",
                settings.velocity_iterations, settings.position_iterations, settings.substeps,
                double(settings.baumgarte));
  }
  if (settings.velocity_tolerance > 0.0f) {
    std::printf("velocity tolerance:   %g m/s and rad/s (a world's velocity passes stop after the "
                "first that changed its velocities by no more)\n",
                double(settings.velocity_tolerance));
  }
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
                "%.3f s wall; interrupted by %s after step %llu of %llu\n",
                Ull(timed_done), Ull(facts.timed_steps), Ull(warmup_done),
                Ull(facts.warmup_steps), facts.timed_seconds, facts.stop_signal.c_str(),
                Ull(facts.steps_done),
                Ull(facts.warmup_steps + facts.timed_steps));
  }
  const double world_steps = double(stats.timed_world_steps);
  if (world_steps > 0 && facts.timed_seconds > 0) {
    std::printf("throughput:           %.4g world-steps/s%s\n", world_steps / facts.timed_seconds,
                facts.rank_worlds.empty() ? "" : " (all ranks, over the slowest rank's wall time)");
    std::printf("time per world-step:  %.4g ns\n", facts.timed_seconds * 1e9 / world_steps);
  } else {
    std::printf("throughput:           none (no timed step)\n");
    std::printf("time per world-step:  none (no timed step)\n");
  }
  if (!facts.rank_world_steps_per_second.empty()) {
    std::printf("throughput per rank:  world-steps/s while stepping its worlds");
    for (const double rate : facts.rank_world_steps_per_second) std::printf(" %.4g", rate);
    std::printf("\n");
    std::printf("per step, per rank:   us outside its own stepping (2 allreduces of an int, "
                "waiting for slower ranks, the actions)");
    for (const double seconds : facts.rank_other_seconds_per_step) {
      std::printf(" %.3g", seconds * 1e6);
    }
    std::printf("\n");
  }
  // --profile: the timed steps' phases (the profile is reset after the
  // warm-up), in thread time per world-step, so they add up to the time per
  // world-step times the threads, less scheduling.
  const PhaseProfile profile = batch.GetPhaseProfile();
  if (profile.world_steps > 0) {
    double total = 0.0;
    for (double seconds : profile.seconds) total += seconds;
    std::printf("phases:               ns per world-step (thread time) and share, %.4g ns in all%s\n",
                total * 1e9 / double(profile.world_steps),
                facts.rank_worlds.empty() ? "" : ", rank 0's worlds");
    for (std::size_t p = 0; p < kStepPhaseCount; ++p) {
      std::printf("  %-19s %8.4g ns  %4.1f %%\n", StepPhaseName(StepPhase(p)),
                  profile.seconds[p] * 1e9 / double(profile.world_steps),
                  total > 0 ? 100.0 * profile.seconds[p] / total : 0.0);
    }
  }
  std::printf("memory:               %zu bytes per world (state, parameters, solver state)\n",
              batch.BytesPerWorld());
  // batch/constraint_error.h: each world's worst row of each unit, measured
  // against the constraint itself (0 = it holds exactly), not a reference run.
  const double finite = double(std::max<std::uint64_t>(stats.finite_errors, 1));
  std::printf("constraint error:     how far the poses after step %llu violate the constraints "
              "(0 = exact), worst row of each world, max and mean over worlds:\n",
              Ull(facts.steps_done));
  std::printf("  linear:             max %.3g m, mean %.3g m (anchor separation, anchor off "
              "a slider axis or path, linear limit, distance and pulley length violations)\n",
              stats.linear_max, stats.linear_sum / finite);
  std::printf("  angular:            max %.3g rad, mean %.3g rad (rotation from the rest pose, "
              "angle between hinge axes, angular limit violations, gear and rack-and-pinion "
              "coupling)\n",
              stats.angular_max, stats.angular_sum / finite);
  std::printf("unhealthy worlds:     %llu of %llu after the last step (non-finite state %llu, "
              "velocity overflow %llu, position out of range %llu, non-finite input %llu); "
              "%llu with a non-finite constraint error\n",
              Ull(stats.unhealthy), Ull(stats.worlds), Ull(stats.by_bit[0]), Ull(stats.by_bit[1]),
              Ull(stats.by_bit[2]), Ull(stats.by_bit[3]), Ull(stats.non_finite_errors));
  std::printf("state digest:         %016llx (every world's final state bits; equal digests "
              "mean the same worlds bit for bit, whatever the threads or MPI ranks)\n",
              Ull(stats.state_digest));
}

}  // namespace manyworlds::tools
