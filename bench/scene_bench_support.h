// Pieces shared by the scene-level benchmarks (scene_bench, mujoco_bench):
// a Batch benchmark body, warm-up, the 2-thread spin check and a console
// reporter that keeps every benchmark's time for the closing tables.
#pragma once

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "manyworlds/batch.h"
#include "manyworlds/scene.h"
#include "manyworlds/scenes.h"

namespace manyworlds::bench {

using Clock = std::chrono::steady_clock;

inline constexpr std::uint64_t kSceneSeed = 1;

// Runs `step(i)` until 20 steps or 0.2 s have passed, whichever is first;
// returns the number of steps taken.
template <class Step>
std::uint64_t WarmUp(Step&& step) {
  const auto start = Clock::now();
  std::uint64_t steps = 0;
  while (steps < 20 && Clock::now() - start < std::chrono::milliseconds(200)) step(steps++);
  return steps;
}

// Worlds found non-finite after any benchmark of this run (so that main can
// fail: the smoke test relies on it).
inline std::size_t& NonFiniteWorldTally() {
  static std::size_t tally = 0;
  return tally;
}

// Batch::Step of `worlds` copies of reference scene `id` with the scene's
// actions before every step, the spec's step settings, on `threads` threads
// and SIMD target `target` (0: dispatched). The batch is built and warmed up
// by the benchmark's first trial run and stepped on by the later ones (Google
// Benchmark calls the function several times); one at a time, so only one
// batch is alive. `name` identifies the benchmark. Batches above
// `max_bytes` are skipped (the machine is shared). `settings` defaults to the
// spec's; scene_bench's velocity-phase rows pass more velocity iterations.
inline void RunBatch(benchmark::State& state, const std::string& name, const std::string& id,
                     std::size_t worlds, int threads, std::int64_t target = 0,
                     double max_bytes = 2.0 * (1ull << 30),
                     const StepSettings& settings = StepSettings{}) {
  struct Run {
    std::string name;
    std::unique_ptr<Batch> batch;
    std::optional<SceneActions> actions;
    std::uint64_t step = 0;
  };
  static Run run;
  if (run.name != name) {
    run = Run{};
    const Scene scene = MakeScene(id);
    const double bytes =
        double(Batch(scene, 16, BatchOptions{.threads = 1}).BytesPerWorld()) * double(worlds);
    if (bytes > max_bytes) {
      state.SkipWithError(("needs " + std::to_string(bytes / (1 << 20)) + " MiB").c_str());
      return;
    }
    run.batch = std::make_unique<Batch>(scene, worlds,
                                        BatchOptions{.threads = threads, .target = target});
    run.actions.emplace(id);
    run.name = name;
    run.step = WarmUp([&](std::uint64_t step) {
      run.actions->Apply(*run.batch, step, kSceneSeed);
      run.batch->Step(settings);
    });
  }
  Batch& batch = *run.batch;
  const SceneActions& actions = *run.actions;
  const auto start = Clock::now();
  for (auto _ : state) {
    actions.Apply(batch, run.step++, kSceneSeed);
    batch.Step(settings);
  }
  const std::chrono::duration<double, std::nano> elapsed = Clock::now() - start;
  const double world_steps = double(state.iterations()) * double(worlds);
  std::size_t unsound = 0;
  for (std::size_t w = 0; w < worlds; ++w) unsound += !std::isfinite(batch.MaxConstraintError(w));
  NonFiniteWorldTally() += unsound;
  state.SetItemsProcessed(std::int64_t(world_steps));
  state.counters["bytes_per_world"] = double(batch.BytesPerWorld());
  state.counters["ns_per_world_step"] = elapsed.count() / world_steps;
  state.counters["threads"] = double(batch.threads());
  state.counters["lanes"] = double(batch.SimdLanes());
  if (unsound) state.counters["nonfinite_worlds"] = double(unsound);
}

// ------------------------------------------------------------ spin check

// Work per second of two threads each summing a counter, over one thread
// doing the same (ideal 2): whether two cores are really free.
inline double SpinRatio() {
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

inline void PrintSpin(const char* when, double ratio) {
  std::printf("2-thread spin check (%s, median of 3): %.2fx the work per second of one thread "
              "(ideal 2.00; well below, e.g. < 1.8x, means the second core is shared and "
              "2-thread figures are not trustworthy)\n",
              when, ratio);
  std::fflush(stdout);
}

// -------------------------------------------------------- results and table

// The console output as usual, plus the wall-clock and CPU time per
// iteration of every benchmark for the closing table: the median over
// repetitions, taken from Google Benchmark's "median" aggregate when it
// reports one (with --benchmark_report_aggregates_only or
// display_aggregates_only the reporter sees no single runs) and else from
// the runs themselves. CPU time is that of the benchmark's own thread: for
// 1-thread runs on a shared machine it leaves out the time the thread waited
// for a core; for 2-thread runs it means nothing (the TBB workers are not in
// it).
class RecordingReporter : public benchmark::ConsoleReporter {
 public:
  using benchmark::ConsoleReporter::ConsoleReporter;

  void ReportRuns(const std::vector<Run>& runs) override {
    for (const Run& run : runs) {
      if (run.error_occurred) continue;
      const double unit = benchmark::GetTimeUnitMultiplier(run.time_unit);
      const Times times{run.GetAdjustedRealTime() / unit, run.GetAdjustedCPUTime() / unit};
      if (run.run_type == Run::RT_Iteration) {
        iterations_[run.run_name.function_name].push_back(times);
      } else if (run.aggregate_name == "median") {
        medians_[run.run_name.function_name] = times;
      }
    }
    benchmark::ConsoleReporter::ReportRuns(runs);
  }

  // World-steps per wall-clock second of a benchmark of `worlds` worlds per
  // iteration; NaN if it did not run (filtered out, skipped).
  double WorldStepsPerSecond(const std::string& name, std::size_t worlds) const {
    return double(worlds) / Median(name, &Times::real);
  }
  // The same per CPU second of the benchmark's thread (1-thread runs only).
  double WorldStepsPerCpuSecond(const std::string& name, std::size_t worlds) const {
    return double(worlds) / Median(name, &Times::cpu);
  }

 private:
  struct Times {
    double real = 0, cpu = 0;  // seconds per iteration
  };

  double Median(const std::string& name, double Times::*field) const {
    if (const auto median = medians_.find(name); median != medians_.end()) {
      return median->second.*field;
    }
    const auto found = iterations_.find(name);
    if (found == iterations_.end() || found->second.empty()) return NAN;
    std::vector<double> times;
    for (const Times& t : found->second) times.push_back(t.*field);
    std::sort(times.begin(), times.end());
    const std::size_t n = times.size();
    return n % 2 ? times[n / 2] : 0.5 * (times[n / 2 - 1] + times[n / 2]);
  }

  std::map<std::string, std::vector<Times>> iterations_;
  std::map<std::string, Times> medians_;
};

// `value` printed with `format`, or "-" when it is NaN (did not run).
inline std::string Figure(double value, const char* format) {
  if (std::isnan(value)) return "-";
  char text[32];
  std::snprintf(text, sizeof text, format, value);
  return text;
}

}  // namespace manyworlds::bench
