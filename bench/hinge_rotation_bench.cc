// Hinge-rotation part benchmarks: every SIMD verb over a batch of worlds with
// random per-world inputs, both bodies dynamic.
#include <cmath>
#include <string>
#include <vector>

#include "batch/part_binding.h"
#include "batch/world_blocks.h"
#include "bench/bench_registry.h"
#include "bench/bench_support.h"
#include "kernels/hinge_rotation.h"

namespace manyworlds::bench {
namespace {

class HingeRotationBatch {
 public:
  HingeRotationBatch(const HingeRotationKernels& kernels, std::size_t worlds)
      : kernels(kernels),
        bodies({MotionType::kDynamic, MotionType::kDynamic}, worlds),
        geometry(bodies.block_count()),
        part(bodies.block_count()),
        deactivate_lanes(bodies.block_count()),
        active(bodies.block_count()) {
    Random random(kSeed);
    for (std::size_t world = 0; world < worlds; ++world) {
      bodies.Set(world, 0, RandomBody(random));
      bodies.Set(world, 1, RandomBody(random));
    }
    const PartBinding hinge = BindPart(bodies, "hinge", PartKind::kHingeRotation, 0, 1);
    for (std::size_t block = 0; block < bodies.block_count(); ++block) {
      pairs.push_back(PairInBlock(bodies, hinge, block));
      for (std::size_t lane = 0; lane < kLaneWidth; ++lane) {
        HingeRotationGeometry& g = geometry[block];
        const Float3 a1 = random.UnitVector();
        SetLane(g.hinge_axis1, lane, a1);
        // Mostly a few degrees of misalignment, as in a running hinge; one
        // lane in eight is >= 90 deg off so the axes repair is exercised.
        if (random.Uniform(0, 1) < 0.125f) {
          SetLane(g.hinge_axis2, lane, random.UnitVector());
        } else {
          const Float3 tilt = random.Perpendicular(a1);
          const float t = random.Uniform(0.0f, 0.1f);
          const Float3 a2{a1[0] + t * tilt[0], a1[1] + t * tilt[1], a1[2] + t * tilt[2]};
          const float inv_length = 1.0f / std::sqrt(a2[0] * a2[0] + a2[1] * a2[1] +
                                                    a2[2] * a2[2]);
          SetLane(g.hinge_axis2, lane,
                  {a2[0] * inv_length, a2[1] * inv_length, a2[2] * inv_length});
        }
        part[block].persistent.total_lambda.x[lane] = random.Uniform(-1, 1);
        part[block].persistent.total_lambda.y[lane] = random.Uniform(-1, 1);
        deactivate_lanes[block][lane] = random.Uniform(0, 1) < 0.5f ? 1.0f : 0.0f;
      }
      kernels.calculate_properties(pairs[block], geometry[block], part[block]);
    }
  }
  HingeRotationBatch(const HingeRotationBatch&) = delete;  // pairs point into `bodies`
  HingeRotationBatch& operator=(const HingeRotationBatch&) = delete;

  std::string Insane() const {
    if (std::string problem = InsaneBodies(bodies); !problem.empty()) return problem;
    for (std::size_t block = 0; block < bodies.block_count(); ++block) {
      for (std::size_t lane = 0; lane < kLaneWidth; ++lane) {
        const HingeRotationLanes& p = part[block];
        for (const float value :
             {p.persistent.total_lambda.x[lane], p.persistent.total_lambda.y[lane],
              p.effective_mass.xx[lane], p.effective_mass.xy[lane],
              p.effective_mass.yy[lane]}) {
          std::string problem = InsaneValue(
              "hinge-rotation impulse or effective mass in block " + std::to_string(block),
              value);
          if (!problem.empty()) return problem;
        }
      }
    }
    return "";
  }

  const HingeRotationKernels& kernels;
  BodyBlocks bodies;
  std::vector<BodyPair> pairs;  // per block
  PartBlocks<HingeRotationGeometry> geometry;
  PartBlocks<HingeRotationLanes> part;
  PartBlocks<LaneFlags> deactivate_lanes;
  PartBlocks<LaneFlags> active;
};

bool CalculateProperties(HingeRotationBatch& b, std::size_t) {
  for (std::size_t i = 0; i < b.pairs.size(); ++i) {
    b.kernels.calculate_properties(b.pairs[i], b.geometry[i], b.part[i]);
  }
  return false;
}

// Ratio -1: the impulse flips sign on every call, so velocities alternate
// between two values instead of growing. Same arithmetic as any ratio.
bool WarmStart(HingeRotationBatch& b, std::size_t) {
  for (std::size_t i = 0; i < b.pairs.size(); ++i) {
    b.kernels.warm_start(b.pairs[i], b.part[i], -1.0f);
  }
  return false;
}

bool SolveVelocity(HingeRotationBatch& b, std::size_t) {
  bool applied = false;
  for (std::size_t i = 0; i < b.pairs.size(); ++i) {
    applied |= b.kernels.solve_velocity(b.pairs[i], b.part[i]);
  }
  return applied;
}

// The error comes from the cached axes, so every call takes the same small
// rotation step; rotations stay unit, nothing grows.
bool SolvePosition(HingeRotationBatch& b, std::size_t) {
  bool applied = false;
  for (std::size_t i = 0; i < b.pairs.size(); ++i) {
    applied |= b.kernels.solve_position(b.pairs[i], b.part[i], kBaumgarte);
  }
  return applied;
}

const bool kRegistered = RegisterPartBenchmarks<HingeRotationBatch, HingeRotationKernels>(
    "hinge_rotation", {{"calculate_properties", &CalculateProperties},
                       {"warm_start", &WarmStart},
                       {"solve_velocity", &SolveVelocity},
                       {"solve_position", &SolvePosition},
                       {"deactivate", &DeactivateVerb<HingeRotationBatch>},
                       {"is_active", &IsActiveVerb<HingeRotationBatch>}});

}  // namespace
}  // namespace manyworlds::bench
