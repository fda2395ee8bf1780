// Reference scenes: world-steps per second of Batch::Step, against the scalar
// reference stepper, against the same kernels on Highway's scalar target, 2
// threads against 1, and as a fraction of this machine's FMA peak, all in one
// run (docs/benchmarks.md).
//
//   peak/fma/threads:<T>                  this machine's FMA peak (bench/fma_peak.h),
//       T in {1, 2}, measured first; peak/fma-after/threads:<T> again at the
//       end, to show how much the machine's load moved during the run;
// For every reference scene and every contact scene (docs/scenes.md):
//   batch/<scene>/worlds:<N>/threads:<T>  Batch::Step of N worlds on T threads,
//       N in {8, 64, 256, 1024, 4096, 16384, 65536}, T in {1, 2};
//   scalar/<scene>/worlds:4096/threads:1  the same batch forced onto Highway's
//       scalar target (BatchOptions::target = HWY_SCALAR: the same kernels,
//       one world per vector), right after the dispatched 1-thread run so
//       that both see the same load (SIMD efficiency, ideal = lane count);
//   batch-v1/<scene>/worlds:4096/threads:<T> and scalar-v1/<scene>/...
//       the same with 1 velocity iteration instead of 10: the difference in
//       time per world-step is velocity iterations 2 to 10 as they run at the
//       spec's settings, so the velocity phase gets its own flop rate (flops
//       of the same difference, counted) and SIMD efficiency;
//   exact/<scene>/worlds:4096/threads:1   JointSolver::kExact (scenes of ball
//       joints: the chains), 4 Newton position steps at most (30 for
//       chain16-r1000);
//   reference/<scene>/worlds:64           reference::World<float>, one world
//       at a time, 64 worlds.
// The scene's actions (cartpole: a random force on every cart; ragdoll:
// motor targets) are applied before every step and are part of the time; the
// spec's step settings (dt 1/60 s, 10 velocity and 2 position iterations,
// Baumgarte 0.2, float). Each benchmark builds its batch once, warms it up
// (20 steps or 0.2 s, whichever ends first) and keeps stepping it across
// Google Benchmark's trial runs. items_per_second = world-steps/s; counters
// bytes_per_world (as the library reports it), ns_per_world_step (wall
// clock), lanes, flop_per_world_step (counted, bench/scene_flops.h), GFLOPs
// (counted flops x world-steps / s) and peak_fraction (GFLOPs over the FMA
// peak of the same thread count measured at the start of this run).
//
// Afterwards two tables: per scene, batch 1 thread at 4096 worlds vs the
// reference and vs the scalar target, 2 threads vs 1 at 4096 and 65536
// worlds; and the roofline: counted flops, GFLOP/s and fraction of peak of
// the whole step and of the velocity iterations alone, and the velocity
// phase's SIMD efficiency. A spin check (two threads summing a counter vs
// one) runs before and after: the 2-thread figures mean something only when
// it gives ~2x, since the build machine's second core may be shared.
//
//   scene_bench [Google Benchmark flags], e.g. --benchmark_filter=cartpole

// scene_flops.h first: it must precede the reference (bench/flop_count.h).
#include "bench/scene_flops.h"

#include <benchmark/benchmark.h>
#include <hwy/targets.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <iostream>
#include <map>
#include <memory>
#include <thread>
#include <string>
#include <vector>

#include "batch/plan.h"
#include "manyworlds/batch.h"
#include "manyworlds/scene.h"
#include "manyworlds/scenes.h"

#include "bench/fma_peak.h"
#include "bench/scene_bench_support.h"

namespace manyworlds::bench {
namespace {

constexpr std::size_t kWorldCounts[] = {8, 64, 256, 1024, 4096, 16384, 65536};
constexpr int kThreadCounts[] = {1, 2};
constexpr std::size_t kReferenceWorlds = 64;
constexpr std::size_t kTableWorlds = 4096;
constexpr std::size_t kLargeWorlds = 65536;
constexpr int kDefaultVelocityIterations = 10;  // StepSettings{}
// The velocity-phase rows step with 1 velocity iteration (the same count as
// the flops of bench/scene_flops.h) and are differenced with the default 10.

// The reference scenes, then the contact scenes (docs/contacts.md).
std::vector<std::string> BenchSceneIds() {
  std::vector<std::string> ids = ReferenceSceneIds();
  for (const std::string& id : ContactSceneIds()) ids.push_back(id);
  return ids;
}

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
// 1 velocity iteration instead of 10, 4096 worlds.
std::string FewIterationsName(const std::string& scene, int threads, bool scalar) {
  return std::string(scalar ? "scalar-v1/" : "batch-v1/") + scene +
         "/worlds:" + std::to_string(kTableWorlds) + "/threads:" + std::to_string(threads);
}
std::string PeakName(int threads, bool after) {
  return std::string(after ? "peak/fma-after" : "peak/fma") + "/threads:" +
         std::to_string(threads);
}

// Counted flops per scene (bench/scene_flops.h), once per run.
const SceneFlops& FlopsOf(const std::string& id) {
  static std::map<std::string, SceneFlops> counted;
  auto found = counted.find(id);
  if (found == counted.end()) found = counted.emplace(id, CountSceneFlops(id, kSceneSeed)).first;
  return found->second;
}

// FMA peak in flop/s per thread count, from the peak benchmarks at the start
// of this run (absent when they were filtered out), and from those at its end.
std::map<int, double>& MeasuredPeak(bool after = false) {
  static std::map<int, double> peak[2];
  return peak[after];
}
// Flops per benchmark iteration of peak/fma/threads:<T> (constant), to turn
// the reporter's CPU time per iteration into a CPU-time peak.
std::map<int, double>& PeakFlopsPerIteration() {
  static std::map<int, double> flops;
  return flops;
}
// flop/s of MeasuredPeak(after)[threads], NaN if not measured.
double PeakFlops(int threads, bool after) {
  const auto found = MeasuredPeak(after).find(threads);
  return found == MeasuredPeak(after).end() ? NAN : found->second;
}

// `threads` threads each running the FMA kernel; items_per_second = flop/s.
void RunPeak(benchmark::State& state, int threads, bool after) {
  constexpr std::uint64_t kRounds = 1 << 20;  // ~0.25 ms per call
  std::vector<float> sink(std::size_t(threads) * 16);
  double flops = 0;
  const auto start = Clock::now();
  for (auto _ : state) {
    std::vector<std::thread> others;
    for (int t = 1; t < threads; ++t) {
      others.emplace_back([&, t] { FmaPeakFlops(kRounds, &sink[std::size_t(t) * 16]); });
    }
    flops += FmaPeakFlops(kRounds, &sink[0]) * threads;
    for (std::thread& other : others) other.join();
  }
  const std::chrono::duration<double> elapsed = Clock::now() - start;
  benchmark::DoNotOptimize(sink.data());
  state.SetItemsProcessed(std::int64_t(flops));
  state.counters["GFLOPs"] = flops / elapsed.count() * 1e-9;
  state.counters["threads"] = threads;
  MeasuredPeak(after)[threads] = flops / elapsed.count();
  PeakFlopsPerIteration()[threads] = flops / double(state.iterations());
}

// RunBatch, then the roofline counters of the run.
void RunBatchWithFlops(benchmark::State& state, const std::string& name, const std::string& id,
                       std::size_t worlds, int threads, std::int64_t target = 0,
                       const StepSettings& settings = StepSettings{}) {
  const SceneFlops& flops = FlopsOf(id);  // before timing: counting takes a while
  RunBatch(state, name, id, worlds, threads, target, 2.0 * (1ull << 30), settings);
  const auto ns = state.counters.find("ns_per_world_step");
  if (ns == state.counters.end()) return;  // skipped
  const double per_step = settings.velocity_iterations == kDefaultVelocityIterations
                              ? flops.per_step
                              : flops.per_step_few_iterations;
  const double gflops = per_step / ns->second.value;  // flop per ns = GFLOP/s
  state.counters["flop_per_world_step"] = per_step;
  state.counters["GFLOPs"] = gflops;
  if (const auto peak = MeasuredPeak().find(threads); peak != MeasuredPeak().end()) {
    state.counters["peak_fraction"] = gflops * 1e9 / peak->second;
  }
}

// The scalar reference, one world after the other, on the same scene and actions.
void RunReference(benchmark::State& state, const std::string& id) {
  const Scene scene = MakeScene(id);
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
  for (const std::string& id : BenchSceneIds()) {
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

// Counted flops x world-steps/s against the FMA peak of the same thread
// count, for the whole step and for the velocity iterations alone (10
// iterations minus 1, in time and in counted flops), at 4096 worlds.
void PrintRoofline(const RecordingReporter& r) {
  const double flop_per_s[2] = {PeakFlops(1, false), PeakFlops(2, false)};
  const double after[2] = {PeakFlops(1, true), PeakFlops(2, true)};
  std::printf(
      "\nroofline: FMA peak (%s kernel, 12 independent FMA chains) 1 thread %s GFLOP/s (at the "
      "end of the run %s), 2 threads %s GFLOP/s (%s); scenes at %zu worlds; flops counted per "
      "world-step by the reference stepper in Counted<float> (FMA = 2; sin, cos, atan as the "
      "lane maths' flops; docs/benchmarks.md)\n",
      FmaPeakTarget(), Figure(flop_per_s[0] * 1e-9, "%.1f").c_str(),
      Figure(after[0] * 1e-9, "%.1f").c_str(), Figure(flop_per_s[1] * 1e-9, "%.1f").c_str(),
      Figure(after[1] * 1e-9, "%.1f").c_str(), kTableWorlds);
  // 1 thread also per CPU second of the benchmark thread, for the peak and
  // the scenes alike: on a shared machine it leaves out the time the thread
  // waited for a core.
  const double cpu_peak1 =
      PeakFlopsPerIteration().count(1)
          ? PeakFlopsPerIteration()[1] * r.WorldStepsPerCpuSecond(PeakName(1, false), 1)
          : NAN;
  std::printf("FMA peak, 1 thread, per CPU second: %s GFLOP/s\n",
              Figure(cpu_peak1 * 1e-9, "%.1f").c_str());
  std::printf("%-14s %10s %9s %9s %12s %9s %12s %9s %9s %9s %12s %9s %9s %9s %9s %9s\n",
              "scene", "flop/step", "div+sqrt", "transc", "flop/vel2-10", "flop/vit", "step GF/s 1T", "of peak", "(CPU)", "2T",
              "vel GF/s 1T", "of peak", "(CPU)", "2T", "vel SIMD", "(CPU)");
  for (const std::string& id : BenchSceneIds()) {
    const double batch1 = r.WorldStepsPerSecond(BatchName(id, kTableWorlds, 1), kTableWorlds);
    if (std::isnan(batch1)) continue;  // filtered out
    const SceneFlops& flops = FlopsOf(id);
    const double batch2 = r.WorldStepsPerSecond(BatchName(id, kTableWorlds, 2), kTableWorlds);
    // Seconds per world-step of velocity iterations 2 to 10: t(10) - t(1).
    const auto velocity_time = [&](const std::string& ten, const std::string& one) {
      return 1.0 / r.WorldStepsPerSecond(ten, kTableWorlds) -
             1.0 / r.WorldStepsPerSecond(one, kTableWorlds);
    };
    const double vel1 = velocity_time(BatchName(id, kTableWorlds, 1),
                                      FewIterationsName(id, 1, false));
    const double vel2 = velocity_time(BatchName(id, kTableWorlds, 2),
                                      FewIterationsName(id, 2, false));
    const double vel_scalar = velocity_time(ScalarName(id), FewIterationsName(id, 1, true));
    const auto cpu_velocity_time = [&](const std::string& ten, const std::string& one) {
      return 1.0 / r.WorldStepsPerCpuSecond(ten, kTableWorlds) -
             1.0 / r.WorldStepsPerCpuSecond(one, kTableWorlds);
    };
    const double cpu_vel1 = cpu_velocity_time(BatchName(id, kTableWorlds, 1),
                                              FewIterationsName(id, 1, false));
    const double cpu_vel_scalar =
        cpu_velocity_time(ScalarName(id), FewIterationsName(id, 1, true));
    const double cpu_step1 =
        r.WorldStepsPerCpuSecond(BatchName(id, kTableWorlds, 1), kTableWorlds);
    const double step_gflops1 = flops.per_step * batch1 * 1e-9;
    const double step_gflops2 = flops.per_step * batch2 * 1e-9;
    const double vel_flops = flops.VelocityIterationsBeyondFew();
    const double vel_gflops1 = vel_flops / vel1 * 1e-9;
    const double vel_gflops2 = vel_flops / vel2 * 1e-9;
    std::printf("%-14s %10.0f %9.0f %9.0f %12.0f %9.0f %12s %9s %9s %9s %12s %9s %9s %9s %9s "
                "%9s\n",
                id.c_str(), flops.per_step, flops.divisions_and_roots_per_step,
                flops.transcendental_per_step, vel_flops, flops.per_velocity_iteration,
                Figure(step_gflops1, "%.2f").c_str(),
                Figure(step_gflops1 * 1e9 / flop_per_s[0], "%.3f").c_str(),
                Figure(flops.per_step * cpu_step1 / cpu_peak1, "%.3f").c_str(),
                Figure(step_gflops2 * 1e9 / flop_per_s[1], "%.3f").c_str(),
                Figure(vel_gflops1, "%.2f").c_str(),
                Figure(vel_gflops1 * 1e9 / flop_per_s[0], "%.3f").c_str(),
                Figure(vel_flops / cpu_vel1 / cpu_peak1, "%.3f").c_str(),
                Figure(vel_gflops2 * 1e9 / flop_per_s[1], "%.3f").c_str(),
                Figure(vel_scalar / vel1, "%.1fx").c_str(),
                Figure(cpu_vel_scalar / cpu_vel1, "%.1fx").c_str());
  }
  std::printf("(div+sqrt: divisions and square roots per step, of flop/step; transc: flops "
              "charged for sin, cos, atan, atan2, fmod; flop/vel2-10: counted flops of velocity iterations 2-10 as they run, "
              "flop/vit: one full velocity iteration; of peak: counted GFLOP/s over the FMA peak "
              "of the same thread count; 2T: the same at 2 threads; vel: velocity iterations "
              "2-10 alone, time of 10 iterations minus 1; (CPU): the same per CPU second of the "
              "benchmark thread, 1 thread; vel SIMD: their time on "
              "Highway's scalar target over the dispatched target's, ideal = lane count)\n");
  std::fflush(stdout);
}

void RegisterPeak(bool after) {
  for (const int threads : kThreadCounts) {
    benchmark::RegisterBenchmark(PeakName(threads, after).c_str(),
                                 [threads, after](benchmark::State& state) {
                                   RunPeak(state, threads, after);
                                 })
        ->UseRealTime();
  }
}

void RegisterAll() {
  RegisterPeak(false);
  for (const std::string& id : BenchSceneIds()) {
    // 1 and 2 threads back to back, so that their ratio sees the same load.
    for (const std::size_t worlds : kWorldCounts) {
      for (const int threads : kThreadCounts) {
        const std::string name = BatchName(id, worlds, threads);
        benchmark::RegisterBenchmark(name.c_str(),
                                     [name, id, worlds, threads](benchmark::State& state) {
                                       RunBatchWithFlops(state, name, id, worlds, threads);
                                     })
            ->UseRealTime();
        if (worlds == kTableWorlds && threads == 1 &&
            CompilePlan(MakeScene(id)).exact.available()) {
          // The exact joint solve right after Gauss-Seidel (same load), at the
          // settings docs/stepping.md measures: at most 4 Newton steps (30 for
          // chain16-r1000, which comes apart with fewer).
          const std::string exact =
              "exact/" + id + "/worlds:" + std::to_string(worlds) + "/threads:1";
          StepSettings settings;
          settings.solver = JointSolver::kExact;
          settings.position_iterations = id == "chain16-r1000" ? 30 : 4;
          benchmark::RegisterBenchmark(exact.c_str(),
                                       [exact, id, settings](benchmark::State& state) {
                                         RunBatch(state, exact, id, kTableWorlds, 1, 0,
                                                  2.0 * (1ull << 30), settings);
                                       })
              ->UseRealTime();
        }
        if (worlds == kTableWorlds && threads == 1) {
          const std::string scalar = ScalarName(id);
          benchmark::RegisterBenchmark(scalar.c_str(),
                                       [scalar, id](benchmark::State& state) {
                                         RunBatchWithFlops(state, scalar, id, kTableWorlds, 1,
                                                           HWY_SCALAR);
                                       })
              ->UseRealTime();
        }
        if (worlds == kTableWorlds) {
          // The velocity-phase rows right after the 10-iteration ones they
          // are differenced with (same load), dispatched and, for 1 thread,
          // scalar target.
          StepSettings few;
          few.velocity_iterations = kFewVelocityIterations;
          for (const bool scalar : {false, true}) {
            if (scalar && threads != 1) continue;
            const std::string v1 = FewIterationsName(id, threads, scalar);
            const std::int64_t target = scalar ? HWY_SCALAR : 0;
            benchmark::RegisterBenchmark(
                v1.c_str(),
                [v1, id, threads, target, few](benchmark::State& state) {
                  RunBatchWithFlops(state, v1, id, kTableWorlds, threads, target, few);
                })
                ->UseRealTime();
          }
        }
      }
    }
    benchmark::RegisterBenchmark(ReferenceName(id).c_str(),
                                 [id](benchmark::State& state) { RunReference(state, id); })
        ->UseRealTime();
  }
  RegisterPeak(true);
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
  PrintRoofline(reporter);
  PrintSpin("after", SpinRatio());
  benchmark::Shutdown();
  // Fail (the smoke test relies on it) when any benchmarked world went non-finite.
  if (NonFiniteWorldTally() > 0) {
    std::printf("FAILED: %zu non-finite worlds\n", NonFiniteWorldTally());
    return 1;
  }
  return 0;
}
