// Rotation-quaternion part benchmarks: every SIMD verb over a batch of worlds
// with random per-world inputs, both bodies dynamic.
#include <string>
#include <vector>

#include "batch/part_binding.h"
#include "batch/world_blocks.h"
#include "bench/bench_registry.h"
#include "bench/bench_support.h"
#include "bench/rest_rotation_bench_support.h"
#include "kernels/rotation_quat.h"

namespace manyworlds::bench {
namespace {

class RotationQuatBatch {
 public:
  RotationQuatBatch(const RotationQuatKernels& kernels, std::size_t worlds)
      : kernels(kernels),
        bodies({MotionType::kDynamic, MotionType::kDynamic}, worlds),
        part(bodies.block_count()),
        inv_initial_orientation(bodies.block_count()),
        deactivate_lanes(bodies.block_count()),
        active(bodies.block_count()) {
    Random random(kSeed);
    for (std::size_t world = 0; world < worlds; ++world) {
      bodies.Set(world, 0, RandomBody(random));
      bodies.Set(world, 1, RandomBody(random));
    }
    const PartBinding fixed = BindPart(bodies, "fixed", PartKind::kRotationQuat, 0, 1);
    for (std::size_t block = 0; block < bodies.block_count(); ++block) {
      pairs.push_back(PairInBlock(bodies, fixed, block));
      for (std::size_t lane = 0; lane < kLaneWidth; ++lane) {
        const std::size_t world = block * kLaneWidth + lane;
        SetLaneQuat(inv_initial_orientation[block], lane,
                    world < worlds ? NearRestInverseInitialOrientation(
                                         random, bodies.Get(world, 0).rotation,
                                         bodies.Get(world, 1).rotation)
                                   : Float4{0.f, 0.f, 0.f, 1.f});
        part[block].persistent.total_lambda.x[lane] = random.Uniform(-1, 1);
        part[block].persistent.total_lambda.y[lane] = random.Uniform(-1, 1);
        part[block].persistent.total_lambda.z[lane] = random.Uniform(-1, 1);
        deactivate_lanes[block][lane] = random.Uniform(0, 1) < 0.5f ? 1.0f : 0.0f;
      }
      kernels.calculate_properties(pairs[block], inv_initial_orientation[block], part[block]);
    }
  }
  RotationQuatBatch(const RotationQuatBatch&) = delete;  // pairs point into `bodies`
  RotationQuatBatch& operator=(const RotationQuatBatch&) = delete;

  std::string Insane() const {
    if (std::string problem = InsaneBodies(bodies); !problem.empty()) return problem;
    for (std::size_t block = 0; block < bodies.block_count(); ++block) {
      const RotationQuatLanes& p = part[block];
      for (std::size_t lane = 0; lane < kLaneWidth; ++lane) {
        for (const float value :
             {p.persistent.total_lambda.x[lane], p.persistent.total_lambda.y[lane],
              p.persistent.total_lambda.z[lane], p.effective_mass.xx[lane],
              p.effective_mass.xy[lane], p.effective_mass.xz[lane], p.effective_mass.yy[lane],
              p.effective_mass.yz[lane], p.effective_mass.zz[lane]}) {
          std::string problem = InsaneValue(
              "rotation-quaternion impulse or effective mass in block " + std::to_string(block),
              value);
          if (!problem.empty()) return problem;
        }
      }
    }
    return "";
  }

  const RotationQuatKernels& kernels;
  BodyBlocks bodies;
  std::vector<BodyPair> pairs;  // per block
  PartBlocks<RotationQuatLanes> part;
  PartBlocks<QuatLanes> inv_initial_orientation;
  PartBlocks<LaneFlags> deactivate_lanes;
  PartBlocks<LaneFlags> active;
};

bool CalculateProperties(RotationQuatBatch& b, std::size_t) {
  for (std::size_t i = 0; i < b.pairs.size(); ++i) {
    b.kernels.calculate_properties(b.pairs[i], b.inv_initial_orientation[i], b.part[i]);
  }
  return false;
}

// Ratio -1: the impulse flips sign on every call, so velocities alternate
// between two values instead of growing. Same arithmetic as any ratio.
bool WarmStart(RotationQuatBatch& b, std::size_t) {
  for (std::size_t i = 0; i < b.pairs.size(); ++i) {
    b.kernels.warm_start(b.pairs[i], b.part[i], -1.0f);
  }
  return false;
}

bool SolveVelocity(RotationQuatBatch& b, std::size_t) {
  bool applied = false;
  for (std::size_t i = 0; i < b.pairs.size(); ++i) {
    applied |= b.kernels.solve_velocity(b.pairs[i], b.part[i]);
  }
  return applied;
}

// Each call removes a fifth of the remaining rotation error; rotations
// converge and stay unit, and the arithmetic per call is the same.
bool SolvePosition(RotationQuatBatch& b, std::size_t) {
  bool applied = false;
  for (std::size_t i = 0; i < b.pairs.size(); ++i) {
    applied |= b.kernels.solve_position(b.pairs[i], b.inv_initial_orientation[i], b.part[i],
                                        kBaumgarte);
  }
  return applied;
}

const bool kRegistered = RegisterPartBenchmarks<RotationQuatBatch, RotationQuatKernels>(
    "rotation_quat", {{"calculate_properties", &CalculateProperties},
                      {"warm_start", &WarmStart},
                      {"solve_velocity", &SolveVelocity},
                      {"solve_position", &SolvePosition},
                      {"deactivate", &DeactivateVerb<RotationQuatBatch>},
                      {"is_active", &IsActiveVerb<RotationQuatBatch>}});

}  // namespace
}  // namespace manyworlds::bench
