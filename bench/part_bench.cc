// Constraint-part kernels: nanoseconds per world for every part and verb, on
// the SIMD target Highway dispatches to and on Highway's scalar target, and
// their ratio (the SIMD speed-up; ideal = float lanes per vector).
//
// Every part registers its verbs from its own bench/<part>_bench.cc (see
// bench_registry.h). Each benchmark runs one verb over all blocks of a batch
// of worlds (default 1024 = 64 blocks, so the working set stays in L2) with
// random per-world inputs, one thread, float.
//
//   part_bench [--worlds=N] [--target=NAME] [Google Benchmark flags]
//   MANYWORLDS_BENCH_WORLDS=N, MANYWORLDS_BENCH_TARGET=NAME  (flags win)
//
// --target picks the SIMD target to compare with SCALAR (default: the one
// Highway dispatches to), e.g. --target=AVX2 on an AVX-512 machine. After all
// benchmarks ran, a table of ns/world on both targets and their ratio is
// printed; all figures come from this one run.

#include <benchmark/benchmark.h>
#include <unistd.h>

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "batch/world_blocks.h"
#include "bench/bench_registry.h"
#include "hwy/targets.h"
#include "kernels/lane_math.h"
#include "manyworlds/lanes.h"

namespace manyworlds::bench {

std::vector<VerbBenchmark>& Registry() {
  static std::vector<VerbBenchmark> registry;
  return registry;
}

namespace {

constexpr std::size_t kDefaultWorlds = 1024;  // 64 blocks: stays in L2

// "dual_axis/solve_velocity/AVX2"
std::string BenchmarkName(const VerbBenchmark& verb, const TargetInfo& target) {
  return verb.part + "/" + verb.verb + "/" + target.name;
}

void RunBenchmark(benchmark::State& state, const VerbBenchmark& verb,
                  const TargetInfo& target, std::size_t worlds) {
  const std::unique_ptr<VerbRun> run = verb.make(target, worlds);
  if (!run) {
    state.SkipWithError("no kernel table for this target");
    return;
  }
  std::size_t iteration = 0;
  const auto start = std::chrono::steady_clock::now();
  for (auto _ : state) {
    bool applied = run->Run(iteration++);
    benchmark::DoNotOptimize(applied);
    benchmark::ClobberMemory();
  }
  const std::chrono::duration<double, std::nano> elapsed =
      std::chrono::steady_clock::now() - start;
  if (const std::string problem = run->Insane(); !problem.empty()) {
    std::fprintf(stderr, "part_bench: %s left the state unsound: %s; aborting\n",
                 BenchmarkName(verb, target).c_str(), problem.c_str());
    std::exit(EXIT_FAILURE);
  }
  // Wall-clock ns per world, computed here rather than as an inverted rate
  // counter (which the console would print with a misleading "s" suffix).
  state.counters["ns_per_world"] =
      elapsed.count() / (double(state.iterations()) * double(worlds));
}

void Register(const VerbBenchmark& verb, const TargetInfo& target, std::size_t worlds) {
  benchmark::RegisterBenchmark(BenchmarkName(verb, target).c_str(),
                               [&verb, target, worlds](benchmark::State& state) {
                                 RunBenchmark(state, verb, target, worlds);
                               });
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
      ns_per_iteration_[run.run_name.function_name].push_back(seconds * 1e9);
    }
    benchmark::ConsoleReporter::ReportRuns(runs);
  }

  // NaN if the benchmark did not run (filtered out).
  double NsPerIteration(const std::string& name) const {
    const auto found = ns_per_iteration_.find(name);
    if (found == ns_per_iteration_.end() || found->second.empty()) return NAN;
    std::vector<double> times = found->second;
    std::sort(times.begin(), times.end());
    const std::size_t n = times.size();
    return n % 2 ? times[n / 2] : 0.5 * (times[n / 2 - 1] + times[n / 2]);
  }

 private:
  std::map<std::string, std::vector<double>> ns_per_iteration_;
};

std::string Figure(double value, const char* format) {
  if (std::isnan(value)) return "-";
  char text[32];
  std::snprintf(text, sizeof text, format, value);
  return text;
}

void PrintTable(const RecordingReporter& reporter, const TargetInfo& simd,
                const TargetInfo* scalar, std::size_t worlds) {
  const std::string base = scalar ? scalar->name : "SCALAR";
  std::printf(
      "\nSIMD speed-up: %zu worlds (%zu blocks of %zu), threads = 1, float; "
      "target %s with %zu float lanes per vector vs Highway's %s target (ideal "
      "ratio = %zu)\n",
      worlds, BlockCount(worlds), kLaneWidth, simd.name, simd.vector_lanes,
      base.c_str(), simd.vector_lanes);
  const std::string simd_column = std::string("ns/world ") + simd.name;
  const std::string base_column = "ns/world " + base;
  const std::string ratio_column = base + "/" + simd.name + " (SIMD speed-up)";
  std::printf("%-20s %-21s %16s %16s  %s\n", "part", "verb", simd_column.c_str(),
              base_column.c_str(), ratio_column.c_str());
  for (const VerbBenchmark& verb : Registry()) {
    const double simd_ns = reporter.NsPerIteration(BenchmarkName(verb, simd)) / double(worlds);
    const double base_ns =
        scalar ? reporter.NsPerIteration(BenchmarkName(verb, *scalar)) / double(worlds) : NAN;
    if (std::isnan(simd_ns) && std::isnan(base_ns)) continue;  // filtered out
    std::printf("%-20s %-21s %16s %16s  %s\n", verb.part.c_str(), verb.verb.c_str(),
                Figure(simd_ns, "%.3f").c_str(), Figure(base_ns, "%.3f").c_str(),
                Figure(base_ns / simd_ns, "%.2fx").c_str());
  }
  if (!scalar) std::printf("(no distinct scalar target here: no ratios)\n");
  std::fflush(stdout);
}

// ------------------------------------------------------------ command line

std::size_t ParseWorldCount(std::string_view text, const char* source) {
  unsigned long long value = 0;
  const auto [end, error] =
      std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || value == 0 ||
      value > (1ull << 26)) {
    std::fprintf(stderr,
                 "part_bench: %s = '%.*s' is not a world count (a whole number "
                 "from 1 to %llu)\n",
                 source, int(text.size()), text.data(), 1ull << 26);
    std::exit(2);
  }
  return std::size_t(value);
}

// MANYWORLDS_BENCH_WORLDS, then --worlds=N (removed from argv so that Google
// Benchmark does not see it).
std::size_t WorldCount(int& argc, char** argv) {
  std::size_t worlds = kDefaultWorlds;
  if (const char* env = std::getenv("MANYWORLDS_BENCH_WORLDS")) {
    worlds = ParseWorldCount(env, "MANYWORLDS_BENCH_WORLDS");
  }
  constexpr std::string_view kFlag = "--worlds=";
  int kept = 1;
  for (int i = 1; i < argc; ++i) {
    const std::string_view arg = argv[i];
    if (arg.starts_with(kFlag)) {
      worlds = ParseWorldCount(arg.substr(kFlag.size()), "--worlds");
    } else {
      if (arg == "--help") {
        std::printf(
            "part_bench [--worlds=N] [--target=NAME] [benchmark flags]: N worlds "
            "per batch (default %zu; also MANYWORLDS_BENCH_WORLDS=N), NAME the SIMD "
            "target to compare with SCALAR (default: dispatched)\n\n",
            kDefaultWorlds);
      }
      argv[kept++] = argv[i];
    }
  }
  argc = kept;
  argv[argc] = nullptr;
  return worlds;
}

// The target to compare with SCALAR: MANYWORLDS_BENCH_TARGET or --target=NAME
// (removed from argv), else the dispatched one. Exits if it is not supported.
TargetInfo ChosenTarget(int& argc, char** argv) {
  std::string wanted;
  if (const char* env = std::getenv("MANYWORLDS_BENCH_TARGET")) wanted = env;
  constexpr std::string_view kFlag = "--target=";
  int kept = 1;
  for (int i = 1; i < argc; ++i) {
    const std::string_view arg = argv[i];
    if (arg.starts_with(kFlag)) {
      wanted = std::string(arg.substr(kFlag.size()));
    } else {
      argv[kept++] = argv[i];
    }
  }
  argc = kept;
  argv[argc] = nullptr;
  if (wanted.empty()) return DispatchedKernels<LaneMathKernels>().target;
  std::string names;
  for (const LaneMathKernels* table : SupportedKernels<LaneMathKernels>()) {
    if (wanted == table->target.name) return table->target;
    names += std::string(" ") + table->target.name;
  }
  std::fprintf(stderr, "part_bench: target '%s' is not supported here; choose one of:%s\n",
               wanted.c_str(), names.c_str());
  std::exit(2);
}

}  // namespace
}  // namespace manyworlds::bench

int main(int argc, char** argv) {
  using namespace manyworlds;
  using namespace manyworlds::bench;
  const std::size_t worlds = WorldCount(argc, argv);
  const TargetInfo simd = ChosenTarget(argc, argv);
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;

  const LaneMathKernels* scalar_table = KernelsForTarget<LaneMathKernels>(HWY_SCALAR);
  const TargetInfo* scalar =
      scalar_table && scalar_table->target.bits != simd.bits ? &scalar_table->target : nullptr;
  for (const VerbBenchmark& verb : Registry()) {
    Register(verb, simd, worlds);
    if (scalar) Register(verb, *scalar, worlds);
  }

  std::printf("part_bench: %zu worlds, threads = 1, float, target %s (%zu float lanes "
              "per vector; dispatched here: %s)\n",
              worlds, simd.name, simd.vector_lanes,
              DispatchedKernels<LaneMathKernels>().target.name);
  std::fflush(stdout);

  const int color = isatty(fileno(stdout)) ? benchmark::ConsoleReporter::OO_Color : 0;
  RecordingReporter reporter(benchmark::ConsoleReporter::OutputOptions(
      benchmark::ConsoleReporter::OO_Tabular | color));
  benchmark::RunSpecifiedBenchmarks(&reporter);
  std::cout.flush();
  PrintTable(reporter, simd, scalar, worlds);
  benchmark::Shutdown();
  return 0;
}
