// Axis and angle part benchmarks (the two spring rows): every SIMD verb over a
// batch of worlds with random per-world inputs, both bodies dynamic. Lanes mix what a scene mixes: about
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
#include "kernels/axis.h"

namespace manyworlds::bench {
namespace {

inline constexpr float kDeltaTime = 1.0f / 60.0f;

// What differs between the axis and the angle row: types, names, the axis
// row's lever arms and its warm start's use of the geometry.
struct AxisRow {
  using Kernels = AxisKernels;
  using Geometry = AxisGeometry;
  using Lanes = AxisLanes;
  static constexpr const char* kPart = "axis";
  static constexpr const char* kConstraint = "distance";
  static constexpr PartKind kKind = PartKind::kAxis;
  static void SetLeverArms(Geometry& g, std::size_t lane, Random& random) {
    SetLane(g.r1_plus_u, lane, random.Vector(0.0f, 1.5f));
    SetLane(g.r2, lane, random.Vector(0.0f, 1.0f));
  }
  static void WarmStart(const Kernels& k, const BodyPair& pair, const Geometry& g,
                        Lanes& part, float ratio) {
    k.warm_start(pair, g, part, ratio);
  }
};

struct AngleRow {
  using Kernels = AngleKernels;
  using Geometry = AngleGeometry;
  using Lanes = AngleLanes;
  static constexpr const char* kPart = "angle";
  static constexpr const char* kConstraint = "hinge_limit";
  static constexpr PartKind kKind = PartKind::kAngle;
  static void SetLeverArms(Geometry&, std::size_t, Random&) {}
  static void WarmStart(const Kernels& k, const BodyPair& pair, const Geometry&, Lanes& part,
                        float ratio) {
    k.warm_start(pair, part, ratio);
  }
};

template <class Row>
class SpringRowBatch {
 public:
  using Geometry = typename Row::Geometry;

  SpringRowBatch(const typename Row::Kernels& kernels, std::size_t worlds)
      : kernels(kernels),
        bodies({MotionType::kDynamic, MotionType::kDynamic}, worlds),
        geometry{PartBlocks<Geometry>(bodies.block_count()),
                 PartBlocks<Geometry>(bodies.block_count())},
        part(bodies.block_count()),
        deactivate_lanes(bodies.block_count()),
        active(bodies.block_count()) {
    Random random(kSeed);
    for (std::size_t world = 0; world < worlds; ++world) {
      bodies.Set(world, 0, RandomBody(random));
      bodies.Set(world, 1, RandomBody(random));
    }
    const PartBinding binding = BindPart(bodies, Row::kConstraint, Row::kKind, 0, 1);
    for (std::size_t block = 0; block < bodies.block_count(); ++block) {
      pairs.push_back(PairInBlock(bodies, binding, block));
      for (std::size_t lane = 0; lane < kLaneWidth; ++lane) {
        Geometry& g = geometry[0][block];
        SetLane(g.axis, lane, random.UnitVector());
        Row::SetLeverArms(g, lane, random);
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
  SpringRowBatch(const SpringRowBatch&) = delete;  // pairs point into `bodies`
  SpringRowBatch& operator=(const SpringRowBatch&) = delete;

  std::string Insane() const {
    if (std::string problem = InsaneBodies(bodies); !problem.empty()) return problem;
    for (std::size_t block = 0; block < bodies.block_count(); ++block) {
      for (std::size_t lane = 0; lane < kLaneWidth; ++lane) {
        const typename Row::Lanes& p = part[block];
        for (const float value :
             {p.persistent.total_lambda[lane], p.properties.effective_mass[lane],
              p.properties.spring.softness[lane], p.properties.spring.bias[lane]}) {
          std::string problem = InsaneValue(
              std::string(Row::kPart) + " impulse, effective mass or spring in block " +
                  std::to_string(block),
              value);
          if (!problem.empty()) return problem;
        }
      }
    }
    return "";
  }

  const typename Row::Kernels& kernels;
  BodyBlocks bodies;
  std::vector<BodyPair> pairs;          // per block
  PartBlocks<Geometry> geometry[2];  // identical but for the sign of C
  PartBlocks<typename Row::Lanes> part;
  PartBlocks<LaneFlags> deactivate_lanes;
  PartBlocks<LaneFlags> active;
};

template <class Row>
bool CalculateProperties(SpringRowBatch<Row>& b, std::size_t) {
  for (std::size_t i = 0; i < b.pairs.size(); ++i) {
    b.kernels.calculate_properties(b.pairs[i], b.geometry[0][i], b.part[i]);
  }
  return false;
}

template <class Row>
bool CalculatePropertiesWithFrequencyAndDamping(SpringRowBatch<Row>& b, std::size_t) {
  for (std::size_t i = 0; i < b.pairs.size(); ++i) {
    b.kernels.calculate_properties_with_frequency_and_damping(b.pairs[i], b.geometry[0][i],
                                                              b.part[i], kDeltaTime);
  }
  return false;
}

template <class Row>
bool CalculatePropertiesWithStiffnessAndDamping(SpringRowBatch<Row>& b, std::size_t) {
  for (std::size_t i = 0; i < b.pairs.size(); ++i) {
    b.kernels.calculate_properties_with_stiffness_and_damping(b.pairs[i], b.geometry[0][i],
                                                              b.part[i], kDeltaTime);
  }
  return false;
}

template <class Row>
bool CalculatePropertiesForLimit(SpringRowBatch<Row>& b, std::size_t) {
  for (std::size_t i = 0; i < b.pairs.size(); ++i) {
    b.kernels.calculate_properties_for_limit(b.pairs[i], b.geometry[0][i], b.part[i],
                                             kDeltaTime, SpringMode::kFrequencyAndDamping);
  }
  return false;
}

template <class Row>
bool CalculatePropertiesForMotor(SpringRowBatch<Row>& b, std::size_t) {
  for (std::size_t i = 0; i < b.pairs.size(); ++i) {
    b.kernels.calculate_properties_for_motor(b.pairs[i], b.geometry[0][i], b.part[i],
                                             kDeltaTime,
                                             SpringMode::kMassNormalizedStiffnessAndDamping);
  }
  return false;
}

// Ratio -1: the impulse flips sign on every call, so velocities alternate
// between two values instead of growing. Same arithmetic as any ratio.
template <class Row>
bool WarmStart(SpringRowBatch<Row>& b, std::size_t) {
  for (std::size_t i = 0; i < b.pairs.size(); ++i) {
    Row::WarmStart(b.kernels, b.pairs[i], b.geometry[0][i], b.part[i], -1.0f);
  }
  return false;
}

template <class Row>
bool SolveVelocity(SpringRowBatch<Row>& b, std::size_t) {
  bool applied = false;
  for (std::size_t i = 0; i < b.pairs.size(); ++i) {
    applied |= b.kernels.solve_velocity(b.pairs[i], b.geometry[0][i], b.part[i]);
  }
  return applied;
}

template <class Row>
bool SolvePosition(SpringRowBatch<Row>& b, std::size_t iteration) {
  bool applied = false;
  for (std::size_t i = 0; i < b.pairs.size(); ++i) {
    applied |= b.kernels.solve_position(b.pairs[i], b.geometry[iteration & 1][i], b.part[i],
                                        kBaumgarte);
  }
  return applied;
}

template <class Row>
bool Register() {
  using Batch = SpringRowBatch<Row>;
  return RegisterPartBenchmarks<Batch, typename Row::Kernels>(
      Row::kPart,
      {{"calculate_properties", &CalculateProperties<Row>},
       {"properties_frequency", &CalculatePropertiesWithFrequencyAndDamping<Row>},
       {"properties_stiffness", &CalculatePropertiesWithStiffnessAndDamping<Row>},
       {"properties_limit", &CalculatePropertiesForLimit<Row>},
       {"properties_motor", &CalculatePropertiesForMotor<Row>},
       {"warm_start", &WarmStart<Row>},
       {"solve_velocity", &SolveVelocity<Row>},
       {"solve_position", &SolvePosition<Row>},
       {"deactivate", &DeactivateVerb<Batch>},
       {"is_active", &IsActiveVerb<Batch>}});
}

const bool kAxisRegistered = Register<AxisRow>();
const bool kAngleRegistered = Register<AngleRow>();

}  // namespace
}  // namespace manyworlds::bench
