// Constraint-part kernels: nanoseconds per world for every part and verb, on
// the SIMD target Highway dispatches to and on Highway's scalar target, and
// their ratio (the SIMD speed-up; ideal = float lanes per vector).
//
// Every benchmark runs one verb over all blocks of a batch of worlds (default
// 1024 = 64 blocks, so the working set stays in L2) with random per-world
// inputs: masses, inertias, rotations, lever arms, axes and ratios differ from
// world to world, both bodies are dynamic, one thread, float.
//
//   part_bench [--worlds=N] [Google Benchmark flags]
//   MANYWORLDS_BENCH_WORLDS=N part_bench ...      (--worlds wins)
//
// After all benchmarks ran, a table of ns/world on both targets and their
// ratio is printed; all figures come from this one run.

#include <benchmark/benchmark.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <map>
#include <random>
#include <string>
#include <string_view>
#include <vector>

#include "batch/part_binding.h"
#include "batch/world_blocks.h"
#include "hwy/targets.h"
#include "kernels/dual_axis.h"
#include "kernels/lane_math.h"
#include "kernels/rack_and_pinion.h"
#include "manyworlds/lanes.h"
#include "manyworlds/targets.h"

namespace manyworlds {
namespace {

constexpr std::size_t kDefaultWorlds = 1024;  // 64 blocks: stays in L2
constexpr float kBaumgarte = 0.2f;            // Jolt's default
// Warm start with ratio -1: the accumulated impulse flips sign on every call,
// so the velocities alternate between two values instead of growing by the
// same impulse each iteration (ratio 1). Same arithmetic as any other ratio.
constexpr float kWarmStartRatio = -1.0f;
// After a benchmark every body and impulse must be finite and below this.
constexpr float kSaneBound = 1.0e6f;
constexpr unsigned kSeed = 20240601;  // same inputs for every target

// ------------------------------------------------------------ random inputs

using Float3 = std::array<float, 3>;
using Float4 = std::array<float, 4>;

class Random {
 public:
  explicit Random(unsigned seed) : engine_(seed) {}

  float Uniform(float lo, float hi) {
    return std::uniform_real_distribution<float>(lo, hi)(engine_);
  }
  // Log-uniform in [lo, hi] (masses and inertias spanning decades).
  float LogUniform(float lo, float hi) {
    return std::exp(Uniform(std::log(lo), std::log(hi)));
  }
  float Sign() { return Uniform(0.0f, 1.0f) < 0.5f ? -1.0f : 1.0f; }

  Float3 UnitVector() {
    for (;;) {
      const Float3 v{Uniform(-1, 1), Uniform(-1, 1), Uniform(-1, 1)};
      const float length = Length(v);
      if (length > 0.1f && length <= 1.0f) return Scale(v, 1.0f / length);
    }
  }
  Float3 Vector(float min_length, float max_length) {
    return Scale(UnitVector(), Uniform(min_length, max_length));
  }
  // A unit vector perpendicular to the unit vector n.
  Float3 Perpendicular(const Float3& n) {
    for (;;) {
      const Float3 v = UnitVector();
      const float along = v[0] * n[0] + v[1] * n[1] + v[2] * n[2];
      const Float3 p{v[0] - along * n[0], v[1] - along * n[1], v[2] - along * n[2]};
      const float length = Length(p);
      if (length > 0.1f) return Scale(p, 1.0f / length);
    }
  }
  // A unit quaternion (x, y, z, w) of a random axis and angle.
  Float4 Rotation() {
    const Float3 axis = UnitVector();
    const float half = 0.5f * Uniform(-3.14159265f, 3.14159265f);
    const float s = std::sin(half);
    Float4 q{axis[0] * s, axis[1] * s, axis[2] * s, std::cos(half)};
    const float norm = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    for (float& c : q) c /= norm;
    return q;
  }

 private:
  static float Length(const Float3& v) {
    return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  }
  static Float3 Scale(const Float3& v, float s) { return {v[0] * s, v[1] * s, v[2] * s}; }

  std::mt19937 engine_;
};

BodyState RandomBody(Random& random) {
  BodyState s;
  s.position = random.Vector(0.0f, 5.0f);
  s.rotation = random.Rotation();
  s.linear_velocity = random.Vector(0.0f, 3.0f);
  s.angular_velocity = random.Vector(0.0f, 3.0f);
  s.inv_mass = random.LogUniform(0.1f, 10.0f);
  s.inv_inertia_diagonal = {random.LogUniform(0.1f, 10.0f),
                            random.LogUniform(0.1f, 10.0f),
                            random.LogUniform(0.1f, 10.0f)};
  s.inertia_rotation = random.Rotation();
  return s;
}

void SetLane(Vec3Lanes& v, std::size_t lane, const Float3& value) {
  v.x[lane] = value[0];
  v.y[lane] = value[1];
  v.z[lane] = value[2];
}

// ------------------------------------------------------------------- batch

// Every part's kernels on one target.
struct PartKernels {
  TargetInfo target;
  const DualAxisKernels* dual_axis;
  const RackAndPinionKernels* rack_and_pinion;
};

// nullptr members if the target is not supported here.
PartKernels KernelsOf(const TargetInfo& target) {
  return {target, KernelsForTarget<DualAxisKernels>(target.bits),
          KernelsForTarget<RackAndPinionKernels>(target.bits)};
}

enum class Verb {
  kCalculateProperties,
  kWarmStart,
  kSolveVelocity,
  kSolvePosition,
  kDeactivate,
  kIsActive,
};

const char* VerbName(Verb verb) {
  switch (verb) {
    case Verb::kCalculateProperties: return "calculate_properties";
    case Verb::kWarmStart: return "warm_start";
    case Verb::kSolveVelocity: return "solve_velocity";
    case Verb::kSolvePosition: return "solve_position";
    case Verb::kDeactivate: return "deactivate";
    case Verb::kIsActive: return "is_active";
  }
  return "unknown";
}

// Two dynamic bodies per world with one dual-axis and one rack-and-pinion part
// between them, plus every per-block input the verbs take. Padding lanes of the
// last block keep inert bodies (zero mass properties), which deactivates them.
class Batch {
 public:
  explicit Batch(std::size_t worlds)
      : bodies({MotionType::kDynamic, MotionType::kDynamic}, worlds),
        blocks(bodies.block_count()),
        dual_axis_geometry(blocks),
        dual_axis(blocks),
        separation{PartBlocks<Vec3Lanes>(blocks), PartBlocks<Vec3Lanes>(blocks)},
        rack_and_pinion_geometry(blocks),
        rack_and_pinion(blocks),
        rack_and_pinion_error{PartBlocks<LaneArray>(blocks),
                              PartBlocks<LaneArray>(blocks)},
        deactivate_lanes(blocks),
        active(blocks) {
    Random random(kSeed);
    for (std::size_t world = 0; world < worlds; ++world) {
      bodies.Set(world, 0, RandomBody(random));
      bodies.Set(world, 1, RandomBody(random));
    }
    const PartBinding slider =
        BindPart(bodies, "slider", PartKind::kDualAxis, 0, 1);
    const PartBinding rack =
        BindPart(bodies, "rack", PartKind::kRackAndPinion, 0, 1);
    for (std::size_t block = 0; block < blocks; ++block) {
      dual_axis_pairs.push_back(PairInBlock(bodies, slider, block));
      rack_and_pinion_pairs.push_back(PairInBlock(bodies, rack, block));
      for (std::size_t lane = 0; lane < kLaneWidth; ++lane) {
        DualAxisGeometry& g = dual_axis_geometry[block];
        const Float3 n1 = random.UnitVector();
        SetLane(g.n1, lane, n1);
        SetLane(g.n2, lane, random.Perpendicular(n1));
        SetLane(g.r1_plus_u, lane, random.Vector(0.0f, 1.5f));
        SetLane(g.r2, lane, random.Vector(0.0f, 1.0f));
        // Position error u and -u: the position solves alternate between
        // them, so bodies move back and forth instead of drifting away.
        const Float3 u = random.Vector(0.01f, 0.05f);
        SetLane(separation[0][block], lane, u);
        SetLane(separation[1][block], lane, {-u[0], -u[1], -u[2]});
        dual_axis[block].persistent.total_lambda.x[lane] = random.Uniform(-1, 1);
        dual_axis[block].persistent.total_lambda.y[lane] = random.Uniform(-1, 1);

        RackAndPinionGeometry& r = rack_and_pinion_geometry[block];
        SetLane(r.hinge_axis, lane, random.UnitVector());
        SetLane(r.slider_axis, lane, random.UnitVector());
        // 1 rad of pinion = 0.02 .. 0.5 m of rack, either direction.
        r.ratio[lane] = random.Sign() * random.LogUniform(2.0f, 50.0f);
        const float error = random.Sign() * random.Uniform(0.01f, 0.1f);
        rack_and_pinion_error[0][block][lane] = error;
        rack_and_pinion_error[1][block][lane] = -error;
        rack_and_pinion[block].persistent.total_lambda[lane] = random.Uniform(-1, 1);

        deactivate_lanes[block][lane] = random.Uniform(0, 1) < 0.5f ? 1.0f : 0.0f;
      }
    }
  }
  Batch(const Batch&) = delete;  // the pairs point into `bodies`
  Batch& operator=(const Batch&) = delete;

  // Effective masses and cached Jacobian vectors, as a step computes them
  // before warm start and the solves.
  void CalculateProperties(const PartKernels& kernels) {
    for (std::size_t block = 0; block < blocks; ++block) {
      kernels.dual_axis->calculate_properties(
          dual_axis_pairs[block], dual_axis_geometry[block], dual_axis[block]);
      kernels.rack_and_pinion->calculate_properties(
          rack_and_pinion_pairs[block], rack_and_pinion_geometry[block],
          rack_and_pinion[block]);
    }
  }

  // Exits with a message if any body or impulse is not finite or has grown
  // beyond kSaneBound, or a rotation is no longer unit.
  void CheckSane(const std::string& benchmark) const {
    auto fail = [&](const std::string& what, float value) {
      std::fprintf(stderr,
                   "part_bench: %s left the state unsound: %s = %g (must be "
                   "finite and below %g); aborting\n",
                   benchmark.c_str(), what.c_str(), double(value), double(kSaneBound));
      std::exit(EXIT_FAILURE);
    };
    auto check = [&](const std::string& what, float value) {
      if (!std::isfinite(value) || std::fabs(value) > kSaneBound) fail(what, value);
    };
    for (std::size_t world = 0; world < bodies.world_count(); ++world) {
      for (std::size_t body = 0; body < 2; ++body) {
        const BodyState s = bodies.Get(world, body);
        const std::string where = " of body " + std::to_string(body) +
                                  " in world " + std::to_string(world);
        for (int i = 0; i < 3; ++i) {
          check("position" + where, s.position[i]);
          check("linear velocity" + where, s.linear_velocity[i]);
          check("angular velocity" + where, s.angular_velocity[i]);
        }
        float norm_squared = 0.0f;
        for (float c : s.rotation) norm_squared += c * c;
        const float norm = std::sqrt(norm_squared);
        if (!(std::fabs(norm - 1.0f) < 1e-3f)) fail("|rotation|" + where, norm);
      }
    }
    for (std::size_t block = 0; block < blocks; ++block) {
      for (std::size_t lane = 0; lane < kLaneWidth; ++lane) {
        const std::string where = " in block " + std::to_string(block) +
                                  ", lane " + std::to_string(lane);
        const DualAxisLanes& d = dual_axis[block];
        check("dual-axis impulse" + where, d.persistent.total_lambda.x[lane]);
        check("dual-axis impulse" + where, d.persistent.total_lambda.y[lane]);
        check("dual-axis effective mass" + where, d.effective_mass.xx[lane]);
        check("dual-axis effective mass" + where, d.effective_mass.xy[lane]);
        check("dual-axis effective mass" + where, d.effective_mass.yy[lane]);
        const RackAndPinionLanes& r = rack_and_pinion[block];
        check("rack-and-pinion impulse" + where, r.persistent.total_lambda[lane]);
        check("rack-and-pinion effective mass" + where, r.effective_mass[lane]);
      }
    }
  }

  BodyBlocks bodies;
  std::size_t blocks;
  std::vector<BodyPair> dual_axis_pairs, rack_and_pinion_pairs;  // per block
  PartBlocks<DualAxisGeometry> dual_axis_geometry;
  PartBlocks<DualAxisLanes> dual_axis;
  PartBlocks<Vec3Lanes> separation[2];  // u, -u
  PartBlocks<RackAndPinionGeometry> rack_and_pinion_geometry;
  PartBlocks<RackAndPinionLanes> rack_and_pinion;
  PartBlocks<LaneArray> rack_and_pinion_error[2];  // C, -C
  PartBlocks<LaneFlags> deactivate_lanes;          // about half the lanes
  PartBlocks<LaneFlags> active;                    // is_active's output
};

// ------------------------------------------------------- verb over a batch

// Runs one verb of one part over every block; returns the OR of what the
// verb returned (solves only), so that nothing is dead code. `iteration`
// picks the sign of the position error.
template <PartKind kPart, Verb kVerb>
bool RunOnEveryBlock(const PartKernels& k, Batch& batch, std::size_t iteration) {
  const std::size_t sign = iteration & 1;
  bool applied = false;
  for (std::size_t block = 0; block < batch.blocks; ++block) {
    if constexpr (kPart == PartKind::kDualAxis) {
      const BodyPair& pair = batch.dual_axis_pairs[block];
      const DualAxisGeometry& geometry = batch.dual_axis_geometry[block];
      DualAxisLanes& part = batch.dual_axis[block];
      if constexpr (kVerb == Verb::kCalculateProperties) {
        k.dual_axis->calculate_properties(pair, geometry, part);
      } else if constexpr (kVerb == Verb::kWarmStart) {
        k.dual_axis->warm_start(pair, geometry, part, kWarmStartRatio);
      } else if constexpr (kVerb == Verb::kSolveVelocity) {
        applied |= k.dual_axis->solve_velocity(pair, geometry, part);
      } else if constexpr (kVerb == Verb::kSolvePosition) {
        applied |= k.dual_axis->solve_position(
            pair, geometry, batch.separation[sign][block], part, kBaumgarte);
      } else if constexpr (kVerb == Verb::kDeactivate) {
        k.dual_axis->deactivate(part, batch.deactivate_lanes[block]);
      } else {
        k.dual_axis->is_active(part, batch.active[block]);
      }
    } else {
      const BodyPair& pair = batch.rack_and_pinion_pairs[block];
      const RackAndPinionGeometry& geometry = batch.rack_and_pinion_geometry[block];
      RackAndPinionLanes& part = batch.rack_and_pinion[block];
      if constexpr (kVerb == Verb::kCalculateProperties) {
        k.rack_and_pinion->calculate_properties(pair, geometry, part);
      } else if constexpr (kVerb == Verb::kWarmStart) {
        k.rack_and_pinion->warm_start(pair, part, kWarmStartRatio);
      } else if constexpr (kVerb == Verb::kSolveVelocity) {
        applied |= k.rack_and_pinion->solve_velocity(pair, geometry, part);
      } else if constexpr (kVerb == Verb::kSolvePosition) {
        applied |= k.rack_and_pinion->solve_position(
            pair, batch.rack_and_pinion_error[sign][block], part, kBaumgarte);
      } else if constexpr (kVerb == Verb::kDeactivate) {
        k.rack_and_pinion->deactivate(part, batch.deactivate_lanes[block]);
      } else {
        k.rack_and_pinion->is_active(part, batch.active[block]);
      }
    }
  }
  return applied;
}

struct BenchCase {
  PartKind part;
  Verb verb;
  bool (*run)(const PartKernels&, Batch&, std::size_t iteration);
};

template <PartKind kPart>
constexpr std::array<BenchCase, 6> CasesOf() {
  return {{
      {kPart, Verb::kCalculateProperties,
       &RunOnEveryBlock<kPart, Verb::kCalculateProperties>},
      {kPart, Verb::kWarmStart, &RunOnEveryBlock<kPart, Verb::kWarmStart>},
      {kPart, Verb::kSolveVelocity, &RunOnEveryBlock<kPart, Verb::kSolveVelocity>},
      {kPart, Verb::kSolvePosition, &RunOnEveryBlock<kPart, Verb::kSolvePosition>},
      {kPart, Verb::kDeactivate, &RunOnEveryBlock<kPart, Verb::kDeactivate>},
      {kPart, Verb::kIsActive, &RunOnEveryBlock<kPart, Verb::kIsActive>},
  }};
}

std::vector<BenchCase> AllCases() {
  std::vector<BenchCase> cases;
  for (const BenchCase& c : CasesOf<PartKind::kDualAxis>()) cases.push_back(c);
  for (const BenchCase& c : CasesOf<PartKind::kRackAndPinion>()) cases.push_back(c);
  return cases;
}

// "dual_axis/solve_velocity/AVX2"
std::string BenchmarkName(const BenchCase& c, const PartKernels& kernels) {
  return std::string(PartKindName(c.part)) + "/" + VerbName(c.verb) + "/" +
         kernels.target.name;
}

void RunBenchmark(benchmark::State& state, const BenchCase& c,
                  const PartKernels& kernels, std::size_t worlds) {
  Batch batch(worlds);  // same seed: identical inputs on every target
  batch.CalculateProperties(kernels);
  std::size_t iteration = 0;
  const auto start = std::chrono::steady_clock::now();
  for (auto _ : state) {
    bool applied = c.run(kernels, batch, iteration++);
    benchmark::DoNotOptimize(applied);
    benchmark::ClobberMemory();
  }
  const std::chrono::duration<double, std::nano> elapsed =
      std::chrono::steady_clock::now() - start;
  batch.CheckSane(BenchmarkName(c, kernels));
  // Wall-clock ns per world, computed here rather than as an inverted rate
  // counter (which the console would print with a misleading "s" suffix).
  state.counters["ns_per_world"] =
      elapsed.count() / (double(state.iterations()) * double(worlds));
}

// One generic registration: every (part, verb) on one kernel table.
void RegisterCase(const BenchCase& c, const PartKernels* kernels,
                  std::size_t worlds) {
  benchmark::RegisterBenchmark(
      BenchmarkName(c, *kernels).c_str(),
      [c, kernels, worlds](benchmark::State& state) {
        RunBenchmark(state, c, *kernels, worlds);
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

void PrintTable(const RecordingReporter& reporter, const std::vector<BenchCase>& cases,
                const PartKernels& dispatched, const PartKernels* scalar,
                std::size_t worlds) {
  const std::size_t lanes = DispatchedVectorLanes();
  const std::string simd = DispatchedTargetName();
  const std::string base = scalar ? scalar->target.name : "SCALAR";
  std::printf(
      "\nSIMD speed-up: %zu worlds (%zu blocks of %zu), threads = 1, float; "
      "dispatched target %s with %zu float lanes per vector vs Highway's %s "
      "target (ideal ratio = %zu)\n",
      worlds, BlockCount(worlds), kLaneWidth, simd.c_str(), lanes, base.c_str(),
      lanes);
  const std::string simd_column = "ns/world " + simd;
  const std::string base_column = "ns/world " + base;
  const std::string ratio_column = base + "/" + simd + " (SIMD speed-up)";
  std::printf("%-16s %-21s %16s %16s  %s\n", "part", "verb", simd_column.c_str(),
              base_column.c_str(), ratio_column.c_str());
  for (const BenchCase& c : cases) {
    const double simd_ns =
        reporter.NsPerIteration(BenchmarkName(c, dispatched)) / double(worlds);
    const double base_ns =
        scalar ? reporter.NsPerIteration(BenchmarkName(c, *scalar)) / double(worlds)
               : NAN;
    if (std::isnan(simd_ns) && std::isnan(base_ns)) continue;
    std::printf("%-16s %-21s %16s %16s  %s\n", PartKindName(c.part), VerbName(c.verb),
                Figure(simd_ns, "%.3f").c_str(), Figure(base_ns, "%.3f").c_str(),
                Figure(base_ns / simd_ns, "%.2fx").c_str());
  }
  if (!scalar) {
    std::printf("(Highway's scalar target is not available here: no ratios)\n");
  }
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
            "part_bench [--worlds=N] [benchmark flags]: N worlds per batch "
            "(default %zu; also MANYWORLDS_BENCH_WORLDS=N)\n\n",
            kDefaultWorlds);
      }
      argv[kept++] = argv[i];
    }
  }
  argc = kept;
  argv[argc] = nullptr;
  return worlds;
}

}  // namespace
}  // namespace manyworlds

int main(int argc, char** argv) {
  using namespace manyworlds;
  const std::size_t worlds = WorldCount(argc, argv);
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;

  // Static: the registered benchmarks keep pointers to them.
  static const PartKernels dispatched =
      KernelsOf(DispatchedKernels<LaneMathKernels>().target);
  static PartKernels scalar_kernels;
  const PartKernels* scalar = nullptr;  // null: nothing to compare with
  const LaneMathKernels* scalar_math = KernelsForTarget<LaneMathKernels>(HWY_SCALAR);
  if (scalar_math && scalar_math->target.bits != dispatched.target.bits) {
    scalar_kernels = KernelsOf(scalar_math->target);
    scalar = &scalar_kernels;
  }
  const std::vector<BenchCase> cases = AllCases();
  for (const BenchCase& c : cases) {
    RegisterCase(c, &dispatched, worlds);
    if (scalar) RegisterCase(c, scalar, worlds);
  }

  std::printf("part_bench: %zu worlds, threads = 1, float, dispatched target %s "
              "(%zu float lanes per vector)\n",
              worlds, DispatchedTargetName().c_str(), DispatchedVectorLanes());
  std::fflush(stdout);

  const int color = isatty(fileno(stdout)) ? benchmark::ConsoleReporter::OO_Color : 0;
  RecordingReporter reporter(benchmark::ConsoleReporter::OutputOptions(
      benchmark::ConsoleReporter::OO_Tabular | color));
  benchmark::RunSpecifiedBenchmarks(&reporter);
  std::cout.flush();
  PrintTable(reporter, cases, dispatched, scalar, worlds);
  benchmark::Shutdown();
  return 0;
}
