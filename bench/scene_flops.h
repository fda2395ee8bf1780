// Floating-point operations per world-step of a reference scene, counted by
// stepping one world of the scalar reference stepper in Counted<float>
// (bench/flop_count.h; rule and limits in docs/benchmarks.md, "Roofline").
#pragma once

// flop_count.h must come before the reference (it adds the std:: overloads
// the reference's qualified calls resolve to).
#include "bench/flop_count.h"

#include <cstdint>
#include <string>

#include "manyworlds/batch.h"
#include "manyworlds/scenes.h"
#include "reference/world.h"

namespace manyworlds::bench {

struct SceneFlops {
  // Mean over kCountedSteps steps at the spec's settings (10 velocity + 2
  // position iterations), actions applied as in the benchmarks.
  double per_step = 0;
  double transcendental_per_step = 0;  // of per_step: sin, cos, atan, atan2, fmod
  double divisions_and_roots_per_step = 0;
  // The same steps from the same states with kFewVelocityIterations (1)
  // velocity iteration: per_step - per_step_few_iterations is the work of
  // velocity iterations 2 to 10 as they run at the spec's settings (the
  // stepper stops early once no constraint applies an impulse, as cartpole's
  // does after about 9).
  double per_step_few_iterations = 0;
  // One full velocity iteration over every solved constraint (iteration 2
  // minus iteration 1 from the same state), for reference.
  double per_velocity_iteration = 0;

  double VelocityIterationsBeyondFew() const { return per_step - per_step_few_iterations; }
};

inline constexpr int kWarmUpSteps = 20;
inline constexpr int kCountedSteps = 10;
inline constexpr int kFewVelocityIterations = 1;

inline SceneFlops CountSceneFlops(const std::string& id, std::uint64_t seed = 1,
                                  std::uint64_t world_index = 0) {
  using World = reference::World<Counted<float>>;
  const SceneActions actions(id);
  const StepSettings settings;
  World world(MakeScene(id));
  std::uint64_t step = 0;
  for (; step < std::uint64_t(kWarmUpSteps); ++step) {
    actions.ApplyTo(world, world_index, step, seed);
    world.Step(settings);
  }
  // Flops of this step from the current state with `velocity_iterations`,
  // on a copy (the state moves on with the spec's settings).
  const auto flops_with = [&](int velocity_iterations) {
    World copy = world;
    actions.ApplyTo(copy, world_index, step, seed);
    StepSettings changed = settings;
    changed.velocity_iterations = velocity_iterations;
    ResetTally();
    copy.Step(changed);
    return double(Tally().Flops());
  };
  SceneFlops flops;
  for (int i = 0; i < kCountedSteps; ++i, ++step) {
    flops.per_step_few_iterations += flops_with(kFewVelocityIterations) / kCountedSteps;
    flops.per_velocity_iteration += (flops_with(2) - flops_with(1)) / kCountedSteps;
    actions.ApplyTo(world, world_index, step, seed);
    ResetTally();
    world.Step(settings);
    const FlopTally& t = Tally();
    flops.per_step += double(t.Flops()) / kCountedSteps;
    flops.transcendental_per_step += double(t.transcendental_flops) / kCountedSteps;
    flops.divisions_and_roots_per_step += double(t.div + t.sqrt) / kCountedSteps;
  }
  return flops;
}

}  // namespace manyworlds::bench
