// Rack-and-pinion part benchmarks: every SIMD verb over a batch of worlds with
// random per-world inputs, both bodies dynamic.
#include <string>
#include <vector>

#include "batch/part_binding.h"
#include "batch/world_blocks.h"
#include "bench/bench_registry.h"
#include "bench/bench_support.h"
#include "kernels/rack_and_pinion.h"

namespace manyworlds::bench {
namespace {

class RackAndPinionBatch {
 public:
  RackAndPinionBatch(const RackAndPinionKernels& kernels, std::size_t worlds)
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
    const PartBinding rack = BindPart(bodies, "rack", PartKind::kRackAndPinion, 0, 1);
    for (std::size_t block = 0; block < bodies.block_count(); ++block) {
      pairs.push_back(PairInBlock(bodies, rack, block));
      for (std::size_t lane = 0; lane < kLaneWidth; ++lane) {
        RackAndPinionGeometry& g = geometry[block];
        SetLane(g.hinge_axis, lane, random.UnitVector());
        SetLane(g.slider_axis, lane, random.UnitVector());
        // 1 rad of pinion = 0.02 .. 0.5 m of rack, either direction.
        g.ratio[lane] = random.Sign() * random.LogUniform(2.0f, 50.0f);
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
  RackAndPinionBatch(const RackAndPinionBatch&) = delete;  // pairs point into `bodies`
  RackAndPinionBatch& operator=(const RackAndPinionBatch&) = delete;

  std::string Insane() const {
    if (std::string problem = InsaneBodies(bodies); !problem.empty()) return problem;
    for (std::size_t block = 0; block < bodies.block_count(); ++block) {
      for (std::size_t lane = 0; lane < kLaneWidth; ++lane) {
        const RackAndPinionLanes& p = part[block];
        for (const float value : {p.persistent.total_lambda[lane], p.effective_mass[lane]}) {
          std::string problem = InsaneValue(
              "rack-and-pinion impulse or effective mass in block " + std::to_string(block),
              value);
          if (!problem.empty()) return problem;
        }
      }
    }
    return "";
  }

  const RackAndPinionKernels& kernels;
  BodyBlocks bodies;
  std::vector<BodyPair> pairs;  // per block
  PartBlocks<RackAndPinionGeometry> geometry;
  PartBlocks<RackAndPinionLanes> part;
  PartBlocks<LaneArray> error[2];  // C, -C
  PartBlocks<LaneFlags> deactivate_lanes;
  PartBlocks<LaneFlags> active;
};

bool CalculateProperties(RackAndPinionBatch& b, std::size_t) {
  for (std::size_t i = 0; i < b.pairs.size(); ++i) {
    b.kernels.calculate_properties(b.pairs[i], b.geometry[i], b.part[i]);
  }
  return false;
}

// Ratio -1: the impulse flips sign on every call, so velocities alternate
// between two values instead of growing. Same arithmetic as any ratio.
bool WarmStart(RackAndPinionBatch& b, std::size_t) {
  for (std::size_t i = 0; i < b.pairs.size(); ++i) {
    b.kernels.warm_start(b.pairs[i], b.part[i], -1.0f);
  }
  return false;
}

bool SolveVelocity(RackAndPinionBatch& b, std::size_t) {
  bool applied = false;
  for (std::size_t i = 0; i < b.pairs.size(); ++i) {
    applied |= b.kernels.solve_velocity(b.pairs[i], b.geometry[i], b.part[i]);
  }
  return applied;
}

bool SolvePosition(RackAndPinionBatch& b, std::size_t iteration) {
  bool applied = false;
  for (std::size_t i = 0; i < b.pairs.size(); ++i) {
    applied |= b.kernels.solve_position(b.pairs[i], b.error[iteration & 1][i], b.part[i],
                                        kBaumgarte);
  }
  return applied;
}

const bool kRegistered = RegisterPartBenchmarks<RackAndPinionBatch, RackAndPinionKernels>(
    "rack_and_pinion", {{"calculate_properties", &CalculateProperties},
                  {"warm_start", &WarmStart},
                  {"solve_velocity", &SolveVelocity},
                  {"solve_position", &SolvePosition},
                  {"deactivate", &DeactivateVerb<RackAndPinionBatch>},
                  {"is_active", &IsActiveVerb<RackAndPinionBatch>}});

}  // namespace
}  // namespace manyworlds::bench
