// Dual-axis part benchmarks: every SIMD verb over a batch of worlds with
// random per-world inputs, both bodies dynamic.
#include <string>
#include <vector>

#include "batch/part_binding.h"
#include "batch/world_blocks.h"
#include "bench/bench_registry.h"
#include "bench/bench_support.h"
#include "kernels/dual_axis.h"

namespace manyworlds::bench {
namespace {

class DualAxisBatch {
 public:
  DualAxisBatch(const DualAxisKernels& kernels, std::size_t worlds)
      : kernels(kernels),
        bodies({MotionType::kDynamic, MotionType::kDynamic}, worlds),
        geometry(bodies.block_count()),
        part(bodies.block_count()),
        separation{PartBlocks<Vec3Lanes>(bodies.block_count()),
                   PartBlocks<Vec3Lanes>(bodies.block_count())},
        deactivate_lanes(bodies.block_count()),
        active(bodies.block_count()) {
    Random random(kSeed);
    for (std::size_t world = 0; world < worlds; ++world) {
      bodies.Set(world, 0, RandomBody(random));
      bodies.Set(world, 1, RandomBody(random));
    }
    const PartBinding slider = BindPart(bodies, "slider", PartKind::kDualAxis, 0, 1);
    for (std::size_t block = 0; block < bodies.block_count(); ++block) {
      pairs.push_back(PairInBlock(bodies, slider, block));
      for (std::size_t lane = 0; lane < kLaneWidth; ++lane) {
        DualAxisGeometry& g = geometry[block];
        const Float3 n1 = random.UnitVector();
        SetLane(g.n1, lane, n1);
        SetLane(g.n2, lane, random.Perpendicular(n1));
        SetLane(g.r1_plus_u, lane, random.Vector(0.0f, 1.5f));
        SetLane(g.r2, lane, random.Vector(0.0f, 1.0f));
        // Position errors u and -u: the position solves alternate between
        // them, so bodies move back and forth instead of drifting away.
        const Float3 u = random.Vector(0.01f, 0.05f);
        SetLane(separation[0][block], lane, u);
        SetLane(separation[1][block], lane, {-u[0], -u[1], -u[2]});
        part[block].persistent.total_lambda.x[lane] = random.Uniform(-1, 1);
        part[block].persistent.total_lambda.y[lane] = random.Uniform(-1, 1);
        deactivate_lanes[block][lane] = random.Uniform(0, 1) < 0.5f ? 1.0f : 0.0f;
      }
      kernels.calculate_properties(pairs[block], geometry[block], part[block]);
    }
  }
  DualAxisBatch(const DualAxisBatch&) = delete;  // pairs point into `bodies`
  DualAxisBatch& operator=(const DualAxisBatch&) = delete;

  std::string Insane() const {
    if (std::string problem = InsaneBodies(bodies); !problem.empty()) return problem;
    for (std::size_t block = 0; block < bodies.block_count(); ++block) {
      for (std::size_t lane = 0; lane < kLaneWidth; ++lane) {
        const DualAxisLanes& p = part[block];
        for (const float value :
             {p.persistent.total_lambda.x[lane], p.persistent.total_lambda.y[lane],
              p.effective_mass.xx[lane], p.effective_mass.xy[lane],
              p.effective_mass.yy[lane]}) {
          std::string problem = InsaneValue(
              "dual-axis impulse or effective mass in block " + std::to_string(block), value);
          if (!problem.empty()) return problem;
        }
      }
    }
    return "";
  }

  const DualAxisKernels& kernels;
  BodyBlocks bodies;
  std::vector<BodyPair> pairs;  // per block
  PartBlocks<DualAxisGeometry> geometry;
  PartBlocks<DualAxisLanes> part;
  PartBlocks<Vec3Lanes> separation[2];  // u, -u
  PartBlocks<LaneFlags> deactivate_lanes;
  PartBlocks<LaneFlags> active;
};

bool CalculateProperties(DualAxisBatch& b, std::size_t) {
  for (std::size_t i = 0; i < b.pairs.size(); ++i) {
    b.kernels.calculate_properties(b.pairs[i], b.geometry[i], b.part[i]);
  }
  return false;
}

// Ratio -1: the impulse flips sign on every call, so velocities alternate
// between two values instead of growing. Same arithmetic as any ratio.
bool WarmStart(DualAxisBatch& b, std::size_t) {
  for (std::size_t i = 0; i < b.pairs.size(); ++i) {
    b.kernels.warm_start(b.pairs[i], b.geometry[i], b.part[i], -1.0f);
  }
  return false;
}

bool SolveVelocity(DualAxisBatch& b, std::size_t) {
  bool applied = false;
  for (std::size_t i = 0; i < b.pairs.size(); ++i) {
    applied |= b.kernels.solve_velocity(b.pairs[i], b.geometry[i], b.part[i]);
  }
  return applied;
}

bool SolvePosition(DualAxisBatch& b, std::size_t iteration) {
  bool applied = false;
  for (std::size_t i = 0; i < b.pairs.size(); ++i) {
    applied |= b.kernels.solve_position(b.pairs[i], b.geometry[i],
                                        b.separation[iteration & 1][i], b.part[i],
                                        kBaumgarte);
  }
  return applied;
}

const bool kRegistered = RegisterPartBenchmarks<DualAxisBatch, DualAxisKernels>(
    "dual_axis", {{"calculate_properties", &CalculateProperties},
                  {"warm_start", &WarmStart},
                  {"solve_velocity", &SolveVelocity},
                  {"solve_position", &SolvePosition},
                  {"deactivate", &DeactivateVerb<DualAxisBatch>},
                  {"is_active", &IsActiveVerb<DualAxisBatch>}});

}  // namespace
}  // namespace manyworlds::bench
