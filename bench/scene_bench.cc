// Reference scenes: world-steps per second of Batch::Step, against the scalar
// reference stepper, and 2 threads against 1, all in one run.
//
// For every reference scene (docs/scenes.md):
//   batch/<scene>/worlds:<N>/threads:<T>  Batch::Step of N worlds on T threads,
//       N in {64, 256, 1024, 4096, 16384, 65536}, T in {1, 2};
//   reference/<scene>/worlds:64           reference::World<float>, one world
//       at a time, 64 worlds.
// The scene's actions (cartpole: a random force on every cart) are applied
// before every step and are part of the time; the spec's step settings
// (dt 1/60 s, 10 velocity and 2 position iterations, Baumgarte 0.2, float).
// Each benchmark builds its batch once, warms it up (20 steps or 0.2 s,
// whichever ends first) and keeps stepping it across Google Benchmark's
// trial runs. items_per_second = world-steps/s; counters bytes_per_world
// (as the library reports it) and ns_per_world_step (wall clock).
//
// Afterwards a table: per scene, batch 1 thread at 4096 worlds vs the
// reference, and 2 threads vs 1 at 4096 and 65536 worlds. A spin check (two
// threads summing a counter vs one) runs before and after: the 2-thread
// figures mean something only when it gives ~2x, since the build machine's
// second core may be shared.
//
//   scene_bench [Google Benchmark flags], e.g. --benchmark_filter=cartpole

#include <benchmark/benchmark.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "manyworlds/batch.h"
#include "manyworlds/scene.h"
#include "manyworlds/scenes.h"

#include "reference/world.h"

namespace manyworlds::bench {
namespace {

using Clock = std::chrono::steady_clock;

constexpr std::size_t kWorldCounts[] = {64, 256, 1024, 4096, 16384, 65536};
constexpr int kThreadCounts[] = {1, 2};
constexpr std::size_t kReferenceWorlds = 64;
constexpr std::size_t kTableWorlds = 4096;
constexpr std::size_t kLargeWorlds = 65536;
constexpr std::uint64_t kSeed = 1;
// A batch above this is skipped (the machine is shared).
constexpr double kMaxBatchBytes = 2.0 * (1ull << 30);

std::string BatchName(const std::string& scene, std::size_t worlds, int threads) {
  return "batch/" + scene + "/worlds:" + std::to_string(worlds) +
         "/threads:" + std::to_string(threads);
}
std::string ReferenceName(const std::string& scene) {
  return "reference/" + scene + "/worlds:" + std::to_string(kReferenceWorlds);
}

// Runs `step` until 20 steps or 0.2 s have passed, whichever is first.
template <class Step>
std::uint64_t WarmUp(Step&& step) {
  const auto start = Clock::now();
  std::uint64_t steps = 0;
  while (steps < 20 && Clock::now() - start < std::chrono::milliseconds(200)) step(steps++);
  return steps;
}

// One benchmark's batch, built and warmed up by its first trial run and
// stepped on by the later ones (Google Benchmark calls the function several
// times); one at a time, so only one batch is alive.
struct BatchRun {
  std::string name;
  std::unique_ptr<Batch> batch;
  std::optional<SceneActions> actions;
  std::uint64_t step = 0;
};

void RunBatch(benchmark::State& state, const std::string& id, std::size_t worlds,
              int threads) {
  static BatchRun run;
  const StepSettings settings;
  const std::string name = BatchName(id, worlds, threads);
  if (run.name != name) {
    run = BatchRun{};
    const Scene scene = MakeReferenceScene(id);
    const double bytes =
        double(Batch(scene, 16, BatchOptions{.threads = 1}).BytesPerWorld()) * double(worlds);
    if (bytes > kMaxBatchBytes) {
      state.SkipWithError(("needs " + std::to_string(bytes / (1 << 20)) + " MiB").c_str());
      return;
    }
    run.batch = std::make_unique<Batch>(scene, worlds, BatchOptions{.threads = threads});
    run.actions.emplace(id);
    run.name = name;
    run.step = WarmUp([&](std::uint64_t step) {
      run.actions->Apply(*run.batch, step, kSeed);
      run.batch->Step(settings);
    });
  }
  Batch& batch = *run.batch;
  const SceneActions& actions = *run.actions;
  const auto start = Clock::now();
  for (auto _ : state) {
    actions.Apply(batch, run.step++, kSeed);
    batch.Step(settings);
  }
  const std::chrono::duration<double, std::nano> elapsed = Clock::now() - start;
  const double world_steps = double(state.iterations()) * double(worlds);
  std::size_t unsound = 0;
  for (std::size_t w = 0; w < worlds; ++w) unsound += !std::isfinite(batch.MaxConstraintError(w));
  state.SetItemsProcessed(std::int64_t(world_steps));
  state.counters["bytes_per_world"] = double(batch.BytesPerWorld());
  state.counters["ns_per_world_step"] = elapsed.count() / world_steps;
  state.counters["threads"] = double(batch.threads());
  if (unsound) state.counters["nonfinite_worlds"] = double(unsound);
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
      actions.ApplyTo(*worlds[w], w, step, kSeed);
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

// ------------------------------------------------------------ spin check

// Work per second of two threads each summing a counter, over one thread
// doing the same (ideal 2): whether two cores are really free.
double SpinRatio() {
  const auto spin = [](std::uint64_t n) {
    std::uint64_t sum = 0;
    for (std::uint64_t i = 0; i < n; ++i) {
      sum += i;
      benchmark::DoNotOptimize(sum);
    }
  };
  const auto seconds = [](auto&& work) {
    const auto start = Clock::now();
    work();
    return std::chrono::duration<double>(Clock::now() - start).count();
  };
  // Calibrate to ~50 ms on one thread.
  std::uint64_t n = 1'000'000;
  const double probe = seconds([&] { spin(n); });
  n = std::max<std::uint64_t>(n, std::uint64_t(double(n) * 0.05 / std::max(probe, 1e-6)));
  // Median of three trials: a moment of other load should not decide it.
  std::vector<double> ratios;
  for (int trial = 0; trial < 3; ++trial) {
    const double one = seconds([&] { spin(n); });
    const double two = seconds([&] {
      std::thread other([&] { spin(n); });
      spin(n);
      other.join();
    });
    ratios.push_back(2.0 * one / two);
  }
  std::sort(ratios.begin(), ratios.end());
  return ratios[1];
}

void PrintSpin(const char* when, double ratio) {
  std::printf("2-thread spin check (%s, median of 3): %.2fx the work per second of one thread "
              "(ideal 2.00; well below, e.g. < 1.8x, means the second core is shared and "
              "2-thread figures are not trustworthy)\n",
              when, ratio);
  std::fflush(stdout);
}

// -------------------------------------------------------- results and table

// The console output as usual, plus the wall-clock time per iteration of
// every benchmark (median over repetitions) for the table.
class RecordingReporter : public benchmark::ConsoleReporter {
 public:
  using benchmark::ConsoleReporter::ConsoleReporter;

  void ReportRuns(const std::vector<Run>& runs) override {
    for (const Run& run : runs) {
      if (run.run_type != Run::RT_Iteration || run.error_occurred) continue;
      const double seconds = run.GetAdjustedRealTime() /
                             benchmark::GetTimeUnitMultiplier(run.time_unit);
      seconds_per_iteration_[run.run_name.function_name].push_back(seconds);
    }
    benchmark::ConsoleReporter::ReportRuns(runs);
  }

  // World-steps per second of a benchmark of `worlds` worlds per iteration;
  // NaN if it did not run (filtered out, skipped).
  double WorldStepsPerSecond(const std::string& name, std::size_t worlds) const {
    const auto found = seconds_per_iteration_.find(name);
    if (found == seconds_per_iteration_.end() || found->second.empty()) return NAN;
    std::vector<double> times = found->second;
    std::sort(times.begin(), times.end());
    const std::size_t n = times.size();
    const double median = n % 2 ? times[n / 2] : 0.5 * (times[n / 2 - 1] + times[n / 2]);
    return double(worlds) / median;
  }

 private:
  std::map<std::string, std::vector<double>> seconds_per_iteration_;
};

std::string Figure(double value, const char* format) {
  if (std::isnan(value)) return "-";
  char text[32];
  std::snprintf(text, sizeof text, format, value);
  return text;
}

void PrintTable(const RecordingReporter& r) {
  const Batch probe(MakeReferenceScene("cartpole"), 1, BatchOptions{.threads = 1});
  std::printf(
      "\nworld-steps/s (median), float, target %s (%zu float lanes), dt 1/60 s, 10 velocity + "
      "2 position iterations, actions every step; reference = reference::World<float>, one "
      "world at a time, %zu worlds\n",
      probe.SimdTarget(), probe.SimdLanes(), kReferenceWorlds);
  std::printf("%-14s %18s %18s %12s %18s %18s\n", "scene", "batch 1T @4096", "reference",
              "batch/ref", "2T/1T @4096", "2T/1T @65536");
  for (const std::string& id : ReferenceSceneIds()) {
    const double batch1 = r.WorldStepsPerSecond(BatchName(id, kTableWorlds, 1), kTableWorlds);
    const double batch2 = r.WorldStepsPerSecond(BatchName(id, kTableWorlds, 2), kTableWorlds);
    const double large1 = r.WorldStepsPerSecond(BatchName(id, kLargeWorlds, 1), kLargeWorlds);
    const double large2 = r.WorldStepsPerSecond(BatchName(id, kLargeWorlds, 2), kLargeWorlds);
    const double ref = r.WorldStepsPerSecond(ReferenceName(id), kReferenceWorlds);
    if (std::isnan(batch1) && std::isnan(ref) && std::isnan(large1)) continue;  // filtered
    std::printf("%-14s %18s %18s %12s %18s %18s\n", id.c_str(), Figure(batch1, "%.4g").c_str(),
                Figure(ref, "%.4g").c_str(), Figure(batch1 / ref, "%.1fx").c_str(),
                Figure(batch2 / batch1, "%.2fx").c_str(),
                Figure(large2 / large1, "%.2fx").c_str());
  }
  std::fflush(stdout);
}

void RegisterAll() {
  for (const std::string& id : ReferenceSceneIds()) {
    // 1 and 2 threads back to back, so that their ratio sees the same load.
    for (const std::size_t worlds : kWorldCounts) {
      for (const int threads : kThreadCounts) {
        benchmark::RegisterBenchmark(BatchName(id, worlds, threads).c_str(),
                                     [id, worlds, threads](benchmark::State& state) {
                                       RunBatch(state, id, worlds, threads);
                                     })
            ->UseRealTime();
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
