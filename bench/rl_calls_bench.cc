// The calls an RL loop makes around Batch::Step, per world, in one run so
// their costs read as ratios to the step (docs/benchmarks.md, "RL calls"):
// Step, GetState, GetJointCoordinates of every constraint, and Snapshot /
// Restore, for cartpole, chain16 and ragdoll at 4096 worlds on one thread.
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

enum class Call { kStep, kGetState, kJointCoordinates, kSnapshot, kRestore };
const char* CallName(Call call) {
  switch (call) {
    case Call::kStep: return "step";
    case Call::kGetState: return "get_state";
    case Call::kJointCoordinates: return "joint_coordinates";
    case Call::kSnapshot: return "snapshot";
    case Call::kRestore: return "restore";
  }
  return "";
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
  for (auto _ : state) {
    switch (call) {
      case Call::kStep: batch.Step(SceneStepSettings(id)); break;
      case Call::kGetState: batch.GetState(states); break;
      case Call::kJointCoordinates: batch.GetJointCoordinates(joints); break;
      case Call::kSnapshot: benchmark::DoNotOptimize(batch.Snapshot()); break;
      case Call::kRestore: batch.Restore(saved); break;
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
    for (const Call call : {Call::kStep, Call::kGetState, Call::kJointCoordinates,
                            Call::kSnapshot, Call::kRestore}) {
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
