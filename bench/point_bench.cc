// Point part benchmarks: every SIMD verb over a batch of worlds with random
// per-world inputs, both bodies dynamic.
#include <string>
#include <vector>

#include "batch/part_binding.h"
#include "batch/world_blocks.h"
#include "bench/bench_registry.h"
#include "bench/bench_support.h"
#include "kernels/point.h"

namespace manyworlds::bench {
namespace {

class PointBatch {
 public:
  PointBatch(const PointKernels& kernels, std::size_t worlds)
      : kernels(kernels),
        bodies({MotionType::kDynamic, MotionType::kDynamic}, worlds),
        geometry(bodies.block_count()),
        part(bodies.block_count()),
        deactivate_lanes(bodies.block_count()),
        active(bodies.block_count()) {
    Random random(kSeed);
    const PartBinding joint = BindPart(bodies, "ball_joint", PartKind::kPoint, 0, 1);
    for (std::size_t block = 0; block < bodies.block_count(); ++block) {
      pairs.push_back(PairInBlock(bodies, joint, block));
    }
    for (std::size_t world = 0; world < worlds; ++world) {
      const std::size_t block = world / kLaneWidth, lane = world % kLaneWidth;
      BodyState body1 = RandomBody(random), body2 = RandomBody(random);
      SetLane(geometry[block].r1_local, lane, random.Vector(0.0f, 1.5f));
      SetLane(geometry[block].r2_local, lane, random.Vector(0.0f, 1.0f));
      bodies.Set(world, 0, body1);
      bodies.Set(world, 1, body2);
      part[block].persistent.total_lambda.x[lane] = random.Uniform(-1, 1);
      part[block].persistent.total_lambda.y[lane] = random.Uniform(-1, 1);
      part[block].persistent.total_lambda.z[lane] = random.Uniform(-1, 1);
      deactivate_lanes[block][lane] = random.Uniform(0, 1) < 0.5f ? 1.0f : 0.0f;
    }
    // Body 2 where the joint is nearly closed (a few cm apart), as in a
    // running simulation, so the position steps are small corrections.
    for (std::size_t block = 0; block < bodies.block_count(); ++block) {
      kernels.calculate_properties(pairs[block], geometry[block], part[block]);
      for (std::size_t lane = 0; lane < kLaneWidth; ++lane) {
        BodyLanes& body2 = *pairs[block].body2;
        const BodyLanes& body1 = *pairs[block].body1;
        const Float3 gap = random.Vector(0.01f, 0.05f);
        const Vec3Lanes& r1 = part[block].r1;
        const Vec3Lanes& r2 = part[block].r2;
        body2.position.x[lane] = body1.position.x[lane] + r1.x[lane] - r2.x[lane] + gap[0];
        body2.position.y[lane] = body1.position.y[lane] + r1.y[lane] - r2.y[lane] + gap[1];
        body2.position.z[lane] = body1.position.z[lane] + r1.z[lane] - r2.z[lane] + gap[2];
      }
    }
  }
  PointBatch(const PointBatch&) = delete;  // pairs point into `bodies`
  PointBatch& operator=(const PointBatch&) = delete;

  std::string Insane() const {
    if (std::string problem = InsaneBodies(bodies); !problem.empty()) return problem;
    for (std::size_t block = 0; block < bodies.block_count(); ++block) {
      const PointLanes& p = part[block];
      for (std::size_t lane = 0; lane < kLaneWidth; ++lane) {
        for (const float value :
             {p.persistent.total_lambda.x[lane], p.persistent.total_lambda.y[lane],
              p.persistent.total_lambda.z[lane], p.effective_mass.xx[lane],
              p.effective_mass.xy[lane], p.effective_mass.xz[lane], p.effective_mass.yy[lane],
              p.effective_mass.yz[lane], p.effective_mass.zz[lane]}) {
          std::string problem = InsaneValue(
              "point impulse or effective mass in block " + std::to_string(block), value);
          if (!problem.empty()) return problem;
        }
      }
    }
    return "";
  }

  const PointKernels& kernels;
  BodyBlocks bodies;
  std::vector<BodyPair> pairs;  // per block
  PartBlocks<PointGeometry> geometry;
  PartBlocks<PointLanes> part;
  PartBlocks<LaneFlags> deactivate_lanes;
  PartBlocks<LaneFlags> active;
};

bool CalculateProperties(PointBatch& b, std::size_t) {
  for (std::size_t i = 0; i < b.pairs.size(); ++i) {
    b.kernels.calculate_properties(b.pairs[i], b.geometry[i], b.part[i]);
  }
  return false;
}

// Ratio -1: the impulse flips sign on every call, so velocities alternate
// between two values instead of growing. Same arithmetic as any ratio.
bool WarmStart(PointBatch& b, std::size_t) {
  for (std::size_t i = 0; i < b.pairs.size(); ++i) {
    b.kernels.warm_start(b.pairs[i], b.part[i], -1.0f);
  }
  return false;
}

bool SolveVelocity(PointBatch& b, std::size_t) {
  bool applied = false;
  for (std::size_t i = 0; i < b.pairs.size(); ++i) {
    applied |= b.kernels.solve_velocity(b.pairs[i], b.part[i]);
  }
  return applied;
}

// Each call closes a fifth of the remaining gap; positions converge, nothing
// grows, and the arithmetic per call is the same whatever the gap.
bool SolvePosition(PointBatch& b, std::size_t) {
  bool applied = false;
  for (std::size_t i = 0; i < b.pairs.size(); ++i) {
    applied |= b.kernels.solve_position(b.pairs[i], b.part[i], kBaumgarte);
  }
  return applied;
}

const bool kRegistered = RegisterPartBenchmarks<PointBatch, PointKernels>(
    "point", {{"calculate_properties", &CalculateProperties},
              {"warm_start", &WarmStart},
              {"solve_velocity", &SolveVelocity},
              {"solve_position", &SolvePosition},
              {"deactivate", &DeactivateVerb<PointBatch>},
              {"is_active", &IsActiveVerb<PointBatch>}});

}  // namespace
}  // namespace manyworlds::bench
