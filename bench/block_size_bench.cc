// The velocity solve against the size of a block's working set: chains of
// 2 to 64 ball-jointed links (chain16's links and joints, docs/scenes.md),
// time per link and velocity iteration on the dispatched target and on
// Highway's scalar target, and their ratio (the velocity phase's SIMD
// efficiency), in one run.
//
// Why: a velocity iteration reads each joint's cached Jacobian terms and
// effective mass and both bodies' velocities and writes them back, for
// ~0.4 flop per byte, and a block of 16 worlds of chain16 is 80 KB, more than
// a core's L1 data cache (48 KB on Zen 5, 32-48 KB on recent x86). A chain
// whose block fits in L1 shows what the same kernels do when the data is
// close; longer chains show the cost of iterating out of L2
// (docs/benchmarks.md, "Velocity phase and L1").
//
//   chain/links:<L>/<target>/iterations:<V>  Batch::Step of 1024 worlds of an
//       L-link chain, 1 thread, V in {1, 10} velocity iterations, target
//       dispatched or scalar. (time at 10 - time at 1) / (9 L) is the time of
//       one joint's velocity solve per world.
//
//   block_size_bench [Google Benchmark flags]

#include <benchmark/benchmark.h>
#include <hwy/targets.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <iostream>
#include <string>

#include "manyworlds/batch.h"
#include "manyworlds/lanes.h"
#include "manyworlds/scene.h"

#include "bench/scene_bench_support.h"

namespace manyworlds::bench {
namespace {

constexpr std::size_t kWorlds = 1024;
constexpr std::size_t kLinks[] = {2, 4, 8, 16, 32, 64};
constexpr int kFew = 1, kMany = 10;

// chain16's link (docs/scenes.md) repeated `links` times.
Scene Chain(std::size_t links) {
  Scene scene;
  BodySettings world;
  world.motion_type = MotionType::kStatic;
  scene.AddBody(world);
  for (std::size_t i = 0; i < links; ++i) {
    BodySettings link;
    link.mass = 1.0f;
    link.inertia_diagonal = {0.001f, 0.0208f, 0.0208f};
    link.position = {0.25f + 0.5f * float(i), 0.0f, 0.0f};
    scene.AddBody(link);
  }
  for (std::size_t i = 0; i < links; ++i) {
    PointConstraintSettings ball;
    ball.body1 = i;
    ball.body2 = i + 1;
    ball.space = ConstraintSpace::kWorldSpace;
    ball.point1 = ball.point2 = {0.5f * float(i), 0.0f, 0.0f};
    scene.AddConstraint(ball);
  }
  return scene;
}

std::string Name(std::size_t links, bool scalar, int iterations) {
  return "chain/links:" + std::to_string(links) + (scalar ? "/scalar" : "/dispatched") +
         "/iterations:" + std::to_string(iterations);
}

void Run(benchmark::State& state, std::size_t links, bool scalar, int iterations) {
  Batch batch(Chain(links), kWorlds,
              BatchOptions{.threads = 1, .target = scalar ? HWY_SCALAR : 0});
  StepSettings settings;
  settings.velocity_iterations = iterations;
  WarmUp([&](std::uint64_t) { batch.Step(settings); });
  for (auto _ : state) batch.Step(settings);
  std::size_t unsound = 0;
  for (std::size_t w = 0; w < kWorlds; ++w) unsound += !std::isfinite(batch.MaxConstraintError(w));
  NonFiniteWorldTally() += unsound;
  state.SetItemsProcessed(std::int64_t(state.iterations() * kWorlds));
  state.counters["block_KiB"] = double(batch.BytesPerWorld()) * kLaneWidth / 1024.0;
}

void PrintTable(const RecordingReporter& r) {
  const Batch probe(Chain(2), 16, BatchOptions{.threads = 1});
  std::printf("\nvelocity solve of one ball joint per world, ns (time of %d velocity iterations "
              "minus %d, over %d x links), %zu worlds, 1 thread; wall clock and CPU time of the "
              "benchmark thread\n",
              kMany, kFew, kMany - kFew, kWorlds);
  std::printf("%6s %10s %12s %12s %16s %12s\n", "links", "block KiB", probe.SimdTarget(),
              "SCALAR", "SIMD (ideal 16)", "(CPU time)");
  for (const std::size_t links : kLinks) {
    const auto per_joint = [&](bool scalar, bool cpu) {
      const auto seconds = [&](int iterations) {
        const std::string name = Name(links, scalar, iterations);
        return 1.0 / (cpu ? r.WorldStepsPerCpuSecond(name, kWorlds)
                          : r.WorldStepsPerSecond(name, kWorlds));
      };
      return (seconds(kMany) - seconds(kFew)) / double((kMany - kFew) * links) * 1e9;
    };
    const double dispatched = per_joint(false, false);
    if (std::isnan(dispatched)) continue;
    const double scalar = per_joint(true, false);
    const Batch sized(Chain(links), 16, BatchOptions{.threads = 1});
    std::printf("%6zu %10.1f %12.3f %12.3f %16s %12s\n", links,
                double(sized.BytesPerWorld()) * kLaneWidth / 1024.0, dispatched, scalar,
                Figure(scalar / dispatched, "%.1fx").c_str(),
                Figure(per_joint(true, true) / per_joint(false, true), "%.1fx").c_str());
  }
  std::fflush(stdout);
}

void RegisterAll() {
  for (const std::size_t links : kLinks) {
    for (const bool scalar : {false, true}) {
      for (const int iterations : {kFew, kMany}) {
        benchmark::RegisterBenchmark(Name(links, scalar, iterations).c_str(),
                                     [=](benchmark::State& state) {
                                       Run(state, links, scalar, iterations);
                                     })
            ->UseRealTime();
      }
    }
  }
}

}  // namespace
}  // namespace manyworlds::bench

int main(int argc, char** argv) {
  using namespace manyworlds::bench;
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  RegisterAll();
  const int color = isatty(fileno(stdout)) ? benchmark::ConsoleReporter::OO_Color : 0;
  RecordingReporter reporter(benchmark::ConsoleReporter::OutputOptions(
      benchmark::ConsoleReporter::OO_Tabular | color));
  benchmark::RunSpecifiedBenchmarks(&reporter);
  std::cout.flush();
  PrintTable(reporter);
  benchmark::Shutdown();
  if (NonFiniteWorldTally() > 0) {
    std::printf("FAILED: %zu non-finite worlds\n", NonFiniteWorldTally());
    return 1;
  }
  return 0;
}
