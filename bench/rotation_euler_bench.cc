// Rotation-Euler part benchmarks: every SIMD verb and rest-rotation helper
// over a batch of worlds with random per-world inputs, both bodies dynamic.
#include <array>
#include <string>
#include <vector>

#include "batch/part_binding.h"
#include "batch/world_blocks.h"
#include "bench/bench_registry.h"
#include "bench/bench_support.h"
#include "bench/rest_rotation_bench_support.h"
#include "kernels/rotation_euler.h"

namespace manyworlds::bench {
namespace {

class RotationEulerBatch {
 public:
  RotationEulerBatch(const RotationEulerKernels& kernels, std::size_t worlds)
      : kernels(kernels),
        bodies({MotionType::kDynamic, MotionType::kDynamic}, worlds),
        part(bodies.block_count()),
        inv_initial_orientation(bodies.block_count()),
        frames(bodies.block_count()),
        helper_output(bodies.block_count()),
        deactivate_lanes(bodies.block_count()),
        active(bodies.block_count()) {
    Random random(kSeed);
    for (std::size_t world = 0; world < worlds; ++world) {
      bodies.Set(world, 0, RandomBody(random));
      bodies.Set(world, 1, RandomBody(random));
    }
    const PartBinding fixed = BindPart(bodies, "fixed", PartKind::kRotationEuler, 0, 1);
    for (std::size_t block = 0; block < bodies.block_count(); ++block) {
      pairs.push_back(PairInBlock(bodies, fixed, block));
      for (std::size_t lane = 0; lane < kLaneWidth; ++lane) {
        const std::size_t world = block * kLaneWidth + lane;
        if (world < worlds) {
          SetLaneQuat(inv_initial_orientation[block], lane,
                      NearRestInverseInitialOrientation(random, bodies.Get(world, 0).rotation,
                                                        bodies.Get(world, 1).rotation));
        } else {
          SetLaneQuat(inv_initial_orientation[block], lane, {0.f, 0.f, 0.f, 1.f});
        }
        for (int body = 0; body < 2; ++body) {
          const Float3 x_axis = random.UnitVector();
          SetLane(frames[block][2 * body], lane, x_axis);
          SetLane(frames[block][2 * body + 1], lane, random.Perpendicular(x_axis));
        }
        SetLaneQuat(helper_output[block], lane, random.Rotation());
        part[block].persistent.total_lambda.x[lane] = random.Uniform(-1, 1);
        part[block].persistent.total_lambda.y[lane] = random.Uniform(-1, 1);
        part[block].persistent.total_lambda.z[lane] = random.Uniform(-1, 1);
        deactivate_lanes[block][lane] = random.Uniform(0, 1) < 0.5f ? 1.0f : 0.0f;
      }
      kernels.calculate_properties(pairs[block], part[block]);
    }
  }
  RotationEulerBatch(const RotationEulerBatch&) = delete;  // pairs point into `bodies`
  RotationEulerBatch& operator=(const RotationEulerBatch&) = delete;

  std::string Insane() const {
    if (std::string problem = InsaneBodies(bodies); !problem.empty()) return problem;
    for (std::size_t block = 0; block < bodies.block_count(); ++block) {
      const RotationEulerLanes& p = part[block];
      const QuatLanes& q = helper_output[block];
      for (std::size_t lane = 0; lane < kLaneWidth; ++lane) {
        for (const float value :
             {p.persistent.total_lambda.x[lane], p.persistent.total_lambda.y[lane],
              p.persistent.total_lambda.z[lane], p.effective_mass.xx[lane],
              p.effective_mass.xy[lane], p.effective_mass.xz[lane], p.effective_mass.yy[lane],
              p.effective_mass.yz[lane], p.effective_mass.zz[lane], q.x[lane], q.y[lane],
              q.z[lane], q.w[lane]}) {
          std::string problem = InsaneValue(
              "rotation-Euler impulse, effective mass or rest rotation in block " +
                  std::to_string(block),
              value);
          if (!problem.empty()) return problem;
        }
      }
    }
    return "";
  }

  const RotationEulerKernels& kernels;
  BodyBlocks bodies;
  std::vector<BodyPair> pairs;  // per block
  PartBlocks<RotationEulerLanes> part;
  PartBlocks<QuatLanes> inv_initial_orientation;
  PartBlocks<std::array<Vec3Lanes, 4>> frames;  // X1, Y1 (or Z1), X2, Y2 (or Z2)
  PartBlocks<QuatLanes> helper_output;
  PartBlocks<LaneFlags> deactivate_lanes;
  PartBlocks<LaneFlags> active;
};

bool CalculateProperties(RotationEulerBatch& b, std::size_t) {
  for (std::size_t i = 0; i < b.pairs.size(); ++i) {
    b.kernels.calculate_properties(b.pairs[i], b.part[i]);
  }
  return false;
}

// Ratio -1: the impulse flips sign on every call, so velocities alternate
// between two values instead of growing. Same arithmetic as any ratio.
bool WarmStart(RotationEulerBatch& b, std::size_t) {
  for (std::size_t i = 0; i < b.pairs.size(); ++i) {
    b.kernels.warm_start(b.pairs[i], b.part[i], -1.0f);
  }
  return false;
}

bool SolveVelocity(RotationEulerBatch& b, std::size_t) {
  bool applied = false;
  for (std::size_t i = 0; i < b.pairs.size(); ++i) {
    applied |= b.kernels.solve_velocity(b.pairs[i], b.part[i]);
  }
  return applied;
}

// Each call removes a fifth of the remaining rotation error; rotations
// converge and stay unit, and the arithmetic per call is the same.
bool SolvePosition(RotationEulerBatch& b, std::size_t) {
  bool applied = false;
  for (std::size_t i = 0; i < b.pairs.size(); ++i) {
    applied |= b.kernels.solve_position(b.pairs[i], b.inv_initial_orientation[i], b.part[i],
                                        kBaumgarte);
  }
  return applied;
}

bool RestRotationFromBodies(RotationEulerBatch& b, std::size_t) {
  for (std::size_t i = 0; i < b.pairs.size(); ++i) {
    b.kernels.inverse_initial_orientation_from_bodies(b.pairs[i], b.helper_output[i]);
  }
  return false;
}

bool RestRotationFromFramesXY(RotationEulerBatch& b, std::size_t) {
  for (std::size_t i = 0; i < b.pairs.size(); ++i) {
    const std::array<Vec3Lanes, 4>& f = b.frames[i];
    b.kernels.inverse_initial_orientation_from_frames_xy(f[0], f[1], f[2], f[3],
                                                         b.helper_output[i]);
  }
  return false;
}

bool RestRotationFromFramesXZ(RotationEulerBatch& b, std::size_t) {
  for (std::size_t i = 0; i < b.pairs.size(); ++i) {
    const std::array<Vec3Lanes, 4>& f = b.frames[i];
    b.kernels.inverse_initial_orientation_from_frames_xz(f[0], f[1], f[2], f[3],
                                                         b.helper_output[i]);
  }
  return false;
}

// In place: q2* r q1 of unit quaternions stays unit (to rounding).
bool RestRotationWorldToLocal(RotationEulerBatch& b, std::size_t) {
  for (std::size_t i = 0; i < b.pairs.size(); ++i) {
    b.kernels.inverse_initial_orientation_world_to_local(b.pairs[i], b.helper_output[i]);
  }
  return false;
}

const bool kRegistered = RegisterPartBenchmarks<RotationEulerBatch, RotationEulerKernels>(
    "rotation_euler",
    {{"calculate_properties", &CalculateProperties},
     {"warm_start", &WarmStart},
     {"solve_velocity", &SolveVelocity},
     {"solve_position", &SolvePosition},
     {"deactivate", &DeactivateVerb<RotationEulerBatch>},
     {"is_active", &IsActiveVerb<RotationEulerBatch>},
     {"rest_rotation_from_bodies", &RestRotationFromBodies},
     {"rest_rotation_from_frames_xy", &RestRotationFromFramesXY},
     {"rest_rotation_from_frames_xz", &RestRotationFromFramesXZ},
     {"rest_rotation_world_to_local", &RestRotationWorldToLocal}});

}  // namespace
}  // namespace manyworlds::bench
