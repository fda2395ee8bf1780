// Reference scenes: world-steps per second of Batch::Step, against the scalar
// reference stepper, against the same kernels on Highway's scalar target, and
// 2 threads against 1, all in one run.
//
// For every reference scene (docs/scenes.md):
//   batch/<scene>/worlds:<N>/threads:<T>  Batch::Step of N worlds on T threads,
//       N in {64, 256, 1024, 4096, 16384, 65536}, T in {1, 2};
//   scalar/<scene>/worlds:4096/threads:1  the same batch forced onto Highway's
//       scalar target (BatchOptions::target = HWY_SCALAR: the same kernels,
//       one world per vector), right after the dispatched 1-thread run so
//       that both see the same load (SIMD efficiency, ideal = lane count);
//   reference/<scene>/worlds:64           reference::World<float>, one world
//       at a time, 64 worlds.
// The scene's actions (cartpole: a random force on every cart) are applied
// before every step and are part of the time; the spec's step settings
// (dt 1/60 s, 10 velocity and 2 position iterations, Baumgarte 0.2, float).
// Each benchmark builds its batch once, warms it up (20 steps or 0.2 s,
// whichever ends first) and keeps stepping it across Google Benchmark's
// trial runs. items_per_second = world-steps/s; counters bytes_per_world
// (as the library reports it), ns_per_world_step (wall clock) and lanes.
//
// Afterwards a table: per scene, batch 1 thread at 4096 worlds vs the
// reference and vs the scalar target, and 2 threads vs 1 at 4096 and 65536
// worlds. A spin check (two threads summing a counter vs one) runs before and
// after: the 2-thread figures mean something only when it gives ~2x, since
// the build machine's second core may be shared.
//
//   scene_bench [Google Benchmark flags], e.g. --benchmark_filter=cartpole

#include <benchmark/benchmark.h>
#include <hwy/targets.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "manyworlds/batch.h"
#include "manyworlds/scene.h"
#include "manyworlds/scenes.h"

#include "bench/scene_bench_support.h"
#include "reference/world.h"

namespace manyworlds::bench {
namespace {

constexpr std::size_t kWorldCounts[] = {64, 256, 1024, 4096, 16384, 65536};
constexpr int kThreadCounts[] = {1, 2};
constexpr std::size_t kReferenceWorlds = 64;
constexpr std::size_t kTableWorlds = 4096;
constexpr std::size_t kLargeWorlds = 65536;

std::string BatchName(const std::string& scene, std::size_t worlds, int threads) {
  return "batch/" + scene + "/worlds:" + std::to_string(worlds) +
         "/threads:" + std::to_string(threads);
}
// The same kernels on Highway's scalar target (one world per "vector").
std::string ScalarName(const std::string& scene) {
  return "scalar/" + scene + "/worlds:" + std::to_string(kTableWorlds) + "/threads:1";
}
std::string ReferenceName(const std::string& scene) {
  return "reference/" + scene + "/worlds:" + std::to_string(kReferenceWorlds);
}

// The scalar reference, one world after the other, on the same scene and actions.
void RunReference(benchmark::State& state, const std::string& id) {
  const Scene scene = MakeReferenceScene(id);
  const SceneActions actions(id);
  const StepSettings settings;
  std::vector<std::unique_ptr<reference::World<float>>> worlds;
  for (std::size_t w = 0; w < kReferenceWorlds; ++w) {
    worlds.push_back(std::make_unique<reference::World<float>>(scene));
  }
  const auto step_all = [&](std::uint64_t step) {
    for (std::size_t w = 0; w < kReferenceWorlds; ++w) {
      actions.ApplyTo(*worlds[w], w, step, kSceneSeed);
      worlds[w]->Step(settings);
    }
  };
  std::uint64_t step = WarmUp(step_all);
  const auto start = Clock::now();
  for (auto _ : state) step_all(step++);
  const std::chrono::duration<double, std::nano> elapsed = Clock::now() - start;
  const double world_steps = double(state.iterations()) * double(kReferenceWorlds);
  benchmark::DoNotOptimize(worlds[0]->body(0).position);
  state.SetItemsProcessed(std::int64_t(world_steps));
  state.counters["ns_per_world_step"] = elapsed.count() / world_steps;
}

void PrintTable(const RecordingReporter& r) {
  const Batch probe(MakeReferenceScene("cartpole"), 1, BatchOptions{.threads = 1});
  std::printf(
      "\nworld-steps/s (median), float, target %s (%zu float lanes), dt 1/60 s, 10 velocity + "
      "2 position iterations, actions every step; reference = reference::World<float>, one "
      "world at a time, %zu worlds\n",
      probe.SimdTarget(), probe.SimdLanes(), kReferenceWorlds);
  char simd_header[48];
  std::snprintf(simd_header, sizeof simd_header, "%s/SCALAR (ideal %zu)", probe.SimdTarget(),
                probe.SimdLanes());
  std::printf("%-14s %16s %14s %10s %16s %22s %10s %13s %13s\n", "scene", "batch 1T @4096",
              "reference", "batch/ref", "SCALAR 1T @4096", simd_header, "(CPU time)",
              "2T/1T @4096", "2T/1T @65536");
  for (const std::string& id : ReferenceSceneIds()) {
    const double batch1 = r.WorldStepsPerSecond(BatchName(id, kTableWorlds, 1), kTableWorlds);
    const double batch2 = r.WorldStepsPerSecond(BatchName(id, kTableWorlds, 2), kTableWorlds);
    const double large1 = r.WorldStepsPerSecond(BatchName(id, kLargeWorlds, 1), kLargeWorlds);
    const double large2 = r.WorldStepsPerSecond(BatchName(id, kLargeWorlds, 2), kLargeWorlds);
    const double ref = r.WorldStepsPerSecond(ReferenceName(id), kReferenceWorlds);
    const double scalar = r.WorldStepsPerSecond(ScalarName(id), kTableWorlds);
    if (std::isnan(batch1) && std::isnan(ref) && std::isnan(large1) && std::isnan(scalar)) {
      continue;  // filtered out
    }
    // The SIMD ratio also per CPU second: both runs are 1 thread, and CPU
    // time leaves out what other work on a shared machine took from them.
    const double simd_cpu =
        r.WorldStepsPerCpuSecond(BatchName(id, kTableWorlds, 1), kTableWorlds) /
        r.WorldStepsPerCpuSecond(ScalarName(id), kTableWorlds);
    std::printf("%-14s %16s %14s %10s %16s %22s %10s %13s %13s\n", id.c_str(),
                Figure(batch1, "%.4g").c_str(), Figure(ref, "%.4g").c_str(),
                Figure(batch1 / ref, "%.1fx").c_str(), Figure(scalar, "%.4g").c_str(),
                Figure(batch1 / scalar, "%.1fx").c_str(), Figure(simd_cpu, "%.1fx").c_str(),
                Figure(batch2 / batch1, "%.2fx").c_str(), Figure(large2 / large1, "%.2fx").c_str());
  }
  std::fflush(stdout);
}

void RegisterAll() {
  for (const std::string& id : ReferenceSceneIds()) {
    // 1 and 2 threads back to back, so that their ratio sees the same load.
    for (const std::size_t worlds : kWorldCounts) {
      for (const int threads : kThreadCounts) {
        const std::string name = BatchName(id, worlds, threads);
        benchmark::RegisterBenchmark(name.c_str(),
                                     [name, id, worlds, threads](benchmark::State& state) {
                                       RunBatch(state, name, id, worlds, threads);
                                     })
            ->UseRealTime();
        if (worlds == kTableWorlds && threads == 1) {
          const std::string scalar = ScalarName(id);
          benchmark::RegisterBenchmark(scalar.c_str(),
                                       [scalar, id](benchmark::State& state) {
                                         RunBatch(state, scalar, id, kTableWorlds, 1, HWY_SCALAR);
                                       })
              ->UseRealTime();
        }
      }
    }
    benchmark::RegisterBenchmark(ReferenceName(id).c_str(),
                                 [id](benchmark::State& state) { RunReference(state, id); })
        ->UseRealTime();
  }
}

}  // namespace
}  // namespace manyworlds::bench

int main(int argc, char** argv) {
  using namespace manyworlds::bench;
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  RegisterAll();
  PrintSpin("before", SpinRatio());
  const int color = isatty(fileno(stdout)) ? benchmark::ConsoleReporter::OO_Color : 0;
  RecordingReporter reporter(benchmark::ConsoleReporter::OutputOptions(
      benchmark::ConsoleReporter::OO_Tabular | color));
  benchmark::RunSpecifiedBenchmarks(&reporter);
  std::cout.flush();
  PrintTable(reporter);
  PrintSpin("after", SpinRatio());
  benchmark::Shutdown();
  return 0;
}
