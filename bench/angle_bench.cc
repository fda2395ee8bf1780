// Angle part benchmarks: every SIMD verb over a batch of worlds with random
// per-world inputs, both bodies dynamic. Lanes mix what a scene mixes: about
// half soft (a spring limit), half hard; some rows clamped one-sided or to a
// small range, the rest unclamped.
#include <cfloat>
#include <string>
#include <vector>

#include "batch/part_binding.h"
#include "batch/world_blocks.h"
#include "bench/bench_registry.h"
#include "bench/bench_support.h"
#include "kernels/angle.h"

namespace manyworlds::bench {
namespace {

inline constexpr float kDeltaTime = 1.0f / 60.0f;

class AngleBatch {
 public:
  AngleBatch(const AngleKernels& kernels, std::size_t worlds)
      : kernels(kernels),
        bodies({MotionType::kDynamic, MotionType::kDynamic}, worlds),
        geometry{PartBlocks<AngleGeometry>(bodies.block_count()),
                 PartBlocks<AngleGeometry>(bodies.block_count())},
        part(bodies.block_count()),
        deactivate_lanes(bodies.block_count()),
        active(bodies.block_count()) {
    Random random(kSeed);
    for (std::size_t world = 0; world < worlds; ++world) {
      bodies.Set(world, 0, RandomBody(random));
      bodies.Set(world, 1, RandomBody(random));
    }
    const PartBinding hinge = BindPart(bodies, "hinge_limit", PartKind::kAngle, 0, 1);
    for (std::size_t block = 0; block < bodies.block_count(); ++block) {
      pairs.push_back(PairInBlock(bodies, hinge, block));
      for (std::size_t lane = 0; lane < kLaneWidth; ++lane) {
        AngleGeometry& g = geometry[0][block];
        SetLane(g.axis, lane, random.UnitVector());
        g.error[lane] = random.Sign() * random.Uniform(0.01f, 0.1f);
        g.bias[lane] = random.Uniform(-0.5f, 0.5f);
        const float range = random.Uniform(0.0f, 1.0f);
        g.min_lambda[lane] = range < 0.5f ? -FLT_MAX : range < 0.75f ? 0.0f : -0.01f;
        g.max_lambda[lane] = range < 0.5f ? FLT_MAX : 0.01f;
        const bool soft = random.Uniform(0.0f, 1.0f) < 0.5f;
        g.spring.frequency_or_stiffness[lane] = soft ? random.Uniform(0.5f, 10.0f) : 0.0f;
        g.spring.damping[lane] = random.Uniform(0.0f, 1.0f);
        part[block].persistent.total_lambda[lane] = random.Uniform(-1, 1);
        deactivate_lanes[block][lane] = random.Uniform(0, 1) < 0.5f ? 1.0f : 0.0f;
      }
      // Errors C and -C: position solves alternate, bodies stay put.
      geometry[1][block] = geometry[0][block];
      for (std::size_t lane = 0; lane < kLaneWidth; ++lane) {
        geometry[1][block].error[lane] = -geometry[0][block].error[lane];
      }
      kernels.calculate_properties_for_limit(pairs[block], geometry[0][block], part[block],
                                             kDeltaTime, SpringMode::kFrequencyAndDamping);
    }
  }
  AngleBatch(const AngleBatch&) = delete;  // pairs point into `bodies`
  AngleBatch& operator=(const AngleBatch&) = delete;

  std::string Insane() const {
    if (std::string problem = InsaneBodies(bodies); !problem.empty()) return problem;
    for (std::size_t block = 0; block < bodies.block_count(); ++block) {
      for (std::size_t lane = 0; lane < kLaneWidth; ++lane) {
        const AngleLanes& p = part[block];
        for (const float value :
             {p.persistent.total_lambda[lane], p.properties.effective_mass[lane],
              p.properties.spring.softness[lane], p.properties.spring.bias[lane]}) {
          std::string problem = InsaneValue(
              "angle impulse, effective mass or spring in block " + std::to_string(block),
              value);
          if (!problem.empty()) return problem;
        }
      }
    }
    return "";
  }

  const AngleKernels& kernels;
  BodyBlocks bodies;
  std::vector<BodyPair> pairs;          // per block
  PartBlocks<AngleGeometry> geometry[2];  // identical but for the sign of C
  PartBlocks<AngleLanes> part;
  PartBlocks<LaneFlags> deactivate_lanes;
  PartBlocks<LaneFlags> active;
};

bool CalculateProperties(AngleBatch& b, std::size_t) {
  for (std::size_t i = 0; i < b.pairs.size(); ++i) {
    b.kernels.calculate_properties(b.pairs[i], b.geometry[0][i], b.part[i]);
  }
  return false;
}

bool CalculatePropertiesWithFrequencyAndDamping(AngleBatch& b, std::size_t) {
  for (std::size_t i = 0; i < b.pairs.size(); ++i) {
    b.kernels.calculate_properties_with_frequency_and_damping(b.pairs[i], b.geometry[0][i],
                                                              b.part[i], kDeltaTime);
  }
  return false;
}

bool CalculatePropertiesWithStiffnessAndDamping(AngleBatch& b, std::size_t) {
  for (std::size_t i = 0; i < b.pairs.size(); ++i) {
    b.kernels.calculate_properties_with_stiffness_and_damping(b.pairs[i], b.geometry[0][i],
                                                              b.part[i], kDeltaTime);
  }
  return false;
}

bool CalculatePropertiesForLimit(AngleBatch& b, std::size_t) {
  for (std::size_t i = 0; i < b.pairs.size(); ++i) {
    b.kernels.calculate_properties_for_limit(b.pairs[i], b.geometry[0][i], b.part[i],
                                             kDeltaTime, SpringMode::kFrequencyAndDamping);
  }
  return false;
}

bool CalculatePropertiesForMotor(AngleBatch& b, std::size_t) {
  for (std::size_t i = 0; i < b.pairs.size(); ++i) {
    b.kernels.calculate_properties_for_motor(b.pairs[i], b.geometry[0][i], b.part[i],
                                             kDeltaTime,
                                             SpringMode::kMassNormalizedStiffnessAndDamping);
  }
  return false;
}

// Ratio -1: the impulse flips sign on every call, so velocities alternate
// between two values instead of growing. Same arithmetic as any ratio.
bool WarmStart(AngleBatch& b, std::size_t) {
  for (std::size_t i = 0; i < b.pairs.size(); ++i) {
    b.kernels.warm_start(b.pairs[i], b.part[i], -1.0f);
  }
  return false;
}

bool SolveVelocity(AngleBatch& b, std::size_t) {
  bool applied = false;
  for (std::size_t i = 0; i < b.pairs.size(); ++i) {
    applied |= b.kernels.solve_velocity(b.pairs[i], b.geometry[0][i], b.part[i]);
  }
  return applied;
}

bool SolvePosition(AngleBatch& b, std::size_t iteration) {
  bool applied = false;
  for (std::size_t i = 0; i < b.pairs.size(); ++i) {
    applied |= b.kernels.solve_position(b.pairs[i], b.geometry[iteration & 1][i], b.part[i],
                                        kBaumgarte);
  }
  return applied;
}

const bool kRegistered = RegisterPartBenchmarks<AngleBatch, AngleKernels>(
    "angle",
    {{"calculate_properties", &CalculateProperties},
     {"properties_frequency", &CalculatePropertiesWithFrequencyAndDamping},
     {"properties_stiffness", &CalculatePropertiesWithStiffnessAndDamping},
     {"properties_limit", &CalculatePropertiesForLimit},
     {"properties_motor", &CalculatePropertiesForMotor},
     {"warm_start", &WarmStart},
     {"solve_velocity", &SolveVelocity},
     {"solve_position", &SolvePosition},
     {"deactivate", &DeactivateVerb<AngleBatch>},
     {"is_active", &IsActiveVerb<AngleBatch>}});

}  // namespace
}  // namespace manyworlds::bench
