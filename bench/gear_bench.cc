// Gear part benchmarks: every SIMD verb over a batch of worlds with random
// per-world inputs, both bodies dynamic.
#include <string>
#include <vector>

#include "batch/part_binding.h"
#include "batch/world_blocks.h"
#include "bench/bench_registry.h"
#include "bench/bench_support.h"
#include "kernels/gear.h"

namespace manyworlds::bench {
namespace {

class GearBatch {
 public:
  GearBatch(const GearKernels& kernels, std::size_t worlds)
      : kernels(kernels),
        bodies({MotionType::kDynamic, MotionType::kDynamic}, worlds),
        geometry(bodies.block_count()),
        part(bodies.block_count()),
        error{PartBlocks<LaneArray>(bodies.block_count()),
              PartBlocks<LaneArray>(bodies.block_count())},
        deactivate_lanes(bodies.block_count()),
        active(bodies.block_count()) {
    Random random(kSeed);
    for (std::size_t world = 0; world < worlds; ++world) {
      bodies.Set(world, 0, RandomBody(random));
      bodies.Set(world, 1, RandomBody(random));
    }
    const PartBinding gear = BindPart(bodies, "gear", PartKind::kGear, 0, 1);
    for (std::size_t block = 0; block < bodies.block_count(); ++block) {
      pairs.push_back(PairInBlock(bodies, gear, block));
      for (std::size_t lane = 0; lane < kLaneWidth; ++lane) {
        GearGeometry& g = geometry[block];
        SetLane(g.hinge_axis1, lane, random.UnitVector());
        SetLane(g.hinge_axis2, lane, random.UnitVector());
        // Teeth ratios from 1:4 to 4:1.
        g.ratio[lane] = random.LogUniform(0.25f, 4.0f);
        // Errors C and -C: position solves alternate, bodies stay put.
        const float c = random.Sign() * random.Uniform(0.01f, 0.1f);
        error[0][block][lane] = c;
        error[1][block][lane] = -c;
        part[block].persistent.total_lambda[lane] = random.Uniform(-1, 1);
        deactivate_lanes[block][lane] = random.Uniform(0, 1) < 0.5f ? 1.0f : 0.0f;
      }
      kernels.calculate_properties(pairs[block], geometry[block], part[block]);
    }
  }
  GearBatch(const GearBatch&) = delete;  // pairs point into `bodies`
  GearBatch& operator=(const GearBatch&) = delete;

  std::string Insane() const {
    if (std::string problem = InsaneBodies(bodies); !problem.empty()) return problem;
    for (std::size_t block = 0; block < bodies.block_count(); ++block) {
      for (std::size_t lane = 0; lane < kLaneWidth; ++lane) {
        const GearLanes& p = part[block];
        for (const float value : {p.persistent.total_lambda[lane], p.effective_mass[lane]}) {
          std::string problem = InsaneValue(
              "gear impulse or effective mass in block " + std::to_string(block), value);
          if (!problem.empty()) return problem;
        }
      }
    }
    return "";
  }

  const GearKernels& kernels;
  BodyBlocks bodies;
  std::vector<BodyPair> pairs;  // per block
  PartBlocks<GearGeometry> geometry;
  PartBlocks<GearLanes> part;
  PartBlocks<LaneArray> error[2];  // C, -C
  PartBlocks<LaneFlags> deactivate_lanes;
  PartBlocks<LaneFlags> active;
};

bool CalculateProperties(GearBatch& b, std::size_t) {
  for (std::size_t i = 0; i < b.pairs.size(); ++i) {
    b.kernels.calculate_properties(b.pairs[i], b.geometry[i], b.part[i]);
  }
  return false;
}

// Ratio -1: the impulse flips sign on every call, so velocities alternate
// between two values instead of growing. Same arithmetic as any ratio.
bool WarmStart(GearBatch& b, std::size_t) {
  for (std::size_t i = 0; i < b.pairs.size(); ++i) {
    b.kernels.warm_start(b.pairs[i], b.part[i], -1.0f);
  }
  return false;
}

bool SolveVelocity(GearBatch& b, std::size_t) {
  bool applied = false;
  for (std::size_t i = 0; i < b.pairs.size(); ++i) {
    applied |= b.kernels.solve_velocity(b.pairs[i], b.geometry[i], b.part[i]);
  }
  return applied;
}

bool SolvePosition(GearBatch& b, std::size_t iteration) {
  bool applied = false;
  for (std::size_t i = 0; i < b.pairs.size(); ++i) {
    applied |= b.kernels.solve_position(b.pairs[i], b.error[iteration & 1][i], b.part[i],
                                        kBaumgarte);
  }
  return applied;
}

const bool kRegistered = RegisterPartBenchmarks<GearBatch, GearKernels>(
    "gear", {{"calculate_properties", &CalculateProperties},
             {"warm_start", &WarmStart},
             {"solve_velocity", &SolveVelocity},
             {"solve_position", &SolvePosition},
             {"deactivate", &DeactivateVerb<GearBatch>},
             {"is_active", &IsActiveVerb<GearBatch>}});

}  // namespace
}  // namespace manyworlds::bench
