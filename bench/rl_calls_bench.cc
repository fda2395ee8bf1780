// The calls an RL loop makes around Batch::Step, per world, in one run so
// their costs read as ratios to the step (docs/benchmarks.md, "RL calls"):
// Step, GetState, GetJointCoordinates of every constraint, Reset of 5 % of
// the worlds, and Snapshot / Restore, for cartpole, chain16 and ragdoll at
// 4096 worlds on one thread;
// and a whole RL loop (the scene's actions, Step, a reset of 5 % of the
// worlds, the state read) against Step with the same actions: once as
// separate calls, once as one Step(settings, io).
//
//   build/bench/rl_calls_bench --benchmark_counters_tabular=true

#include <benchmark/benchmark.h>

#include <cstdint>
#include <string>
#include <vector>

#include "manyworlds/batch.h"
#include "manyworlds/scenes.h"

namespace manyworlds {
namespace {

constexpr std::size_t kWorlds = 4096;

enum class Call {
  kStep, kGetState, kJointCoordinates, kReset, kSnapshot, kRestore,
  kActStep, kLoopSeparate, kLoopFused
};
const char* CallName(Call call) {
  switch (call) {
    case Call::kStep: return "step";
    case Call::kGetState: return "get_state";
    case Call::kJointCoordinates: return "joint_coordinates";
    case Call::kReset: return "reset_5_percent";
    case Call::kSnapshot: return "snapshot";
    case Call::kRestore: return "restore";
    case Call::kActStep: return "actions_step";
    case Call::kLoopSeparate: return "rl_loop_separate";
    case Call::kLoopFused: return "rl_loop_one_call";
  }
  return "";
}

// The scene's actions of one step (SceneActions, seed 1) as StepActions:
// each force a [world][3] array, each motor target a [world] array.
struct StepActions {
  std::vector<std::vector<float>> arrays;
  std::vector<StepAction> actions;

  StepActions(const SceneActions& scene, std::size_t worlds, std::uint64_t step) {
    for (std::size_t i = 0; i < scene.forces_per_world(); ++i) {
      std::vector<float> forces(worlds * 3);
      std::size_t body = 0;
      for (std::size_t w = 0; w < worlds; ++w) {
        const BodyForce f = scene.Force(i, w, step, 1);
        body = f.body;
        for (int k = 0; k < 3; ++k) forces[w * 3 + k] = f.force[k];
      }
      arrays.push_back(std::move(forces));
      actions.push_back({ActionKind::kForce, body, arrays.back()});
    }
    for (std::size_t i = 0; i < scene.targets_per_world(); ++i) {
      std::vector<float> targets(worlds);
      std::size_t constraint = 0;
      for (std::size_t w = 0; w < worlds; ++w) {
        const MotorTarget t = scene.Target(i, w, step, 1);
        constraint = t.constraint;
        targets[w] = t.position;
      }
      arrays.push_back(std::move(targets));
      actions.push_back({ActionKind::kTargetPosition, constraint, arrays.back()});
    }
  }
};

// The separate calls' way of giving the same actions.
void GiveActions(Batch& batch, const StepActions& given) {
  for (const StepAction& action : given.actions) {
    if (action.kind == ActionKind::kForce) {
      batch.SetForces(action.index, action.per_world);
    } else {
      batch.SetTargetPositions(action.index, action.per_world);
    }
  }
}

void Bench(benchmark::State& state, const std::string& id, Call call) {
  BatchOptions one_thread;
  one_thread.threads = 1;
  Batch batch(MakeScene(id), kWorlds, one_thread);
  const SceneActions actions(id);
  for (std::uint64_t step = 0; step < 20; ++step) {  // warm starts and moving bodies
    actions.Apply(batch, step, 1);
    batch.Step(SceneStepSettings(id));
  }
  std::vector<float> states(kWorlds * batch.body_count() * kStateFloatsPerBody);
  std::vector<float> joints(kWorlds * batch.JointCoordinatesPerWorld());
  const BatchSnapshot saved = batch.Snapshot();
  // Every 20th world resets (5 %), the worlds shifting by one each step.
  const StepActions given(actions, kWorlds, 20);
  std::vector<std::uint8_t> masks[20];
  for (std::size_t m = 0; m < 20; ++m) {
    masks[m].assign(kWorlds, 0);
    for (std::size_t w = m; w < kWorlds; w += 20) masks[m][w] = 1;
  }
  std::size_t step = 0;
  for (auto _ : state) {
    const std::vector<std::uint8_t>& reset = masks[step++ % 20];
    switch (call) {
      case Call::kStep: batch.Step(SceneStepSettings(id)); break;
      case Call::kGetState: batch.GetState(states); break;
      case Call::kJointCoordinates: batch.GetJointCoordinates(joints); break;
      case Call::kReset: batch.Reset(reset); break;
      case Call::kSnapshot: benchmark::DoNotOptimize(batch.Snapshot()); break;
      case Call::kRestore: batch.Restore(saved); break;
      case Call::kActStep:
        GiveActions(batch, given);
        batch.Step(SceneStepSettings(id));
        break;
      case Call::kLoopSeparate:
        GiveActions(batch, given);
        batch.Step(SceneStepSettings(id));
        batch.Reset(reset);
        batch.GetState(states);
        break;
      case Call::kLoopFused: {
        StepIo io;
        io.actions = given.actions;
        io.reset_mask = reset;
        io.state_out = states;
        batch.Step(SceneStepSettings(id), io);
        break;
      }
    }
    benchmark::ClobberMemory();
  }
  state.counters["ns_per_world"] = benchmark::Counter(
      double(kWorlds), benchmark::Counter::kIsIterationInvariantRate |
                           benchmark::Counter::kInvert);
  state.counters["world_steps_or_reads_per_s"] =
      benchmark::Counter(double(kWorlds), benchmark::Counter::kIsIterationInvariantRate);
}

void RegisterAll() {
  for (const char* id : {"cartpole", "chain16", "ragdoll"}) {
    for (const Call call :
         {Call::kStep, Call::kGetState, Call::kJointCoordinates, Call::kReset, Call::kSnapshot,
          Call::kRestore, Call::kActStep, Call::kLoopSeparate, Call::kLoopFused}) {
      const std::string name = std::string(id) + "/" + CallName(call);
      benchmark::RegisterBenchmark(name.c_str(), [id, call](benchmark::State& state) {
        Bench(state, id, call);
      })->Unit(benchmark::kMicrosecond);
    }
  }
}

}  // namespace
}  // namespace manyworlds

int main(int argc, char** argv) {
  manyworlds::RegisterAll();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
