// Swing-twist part benchmarks: every SIMD verb over a batch of worlds with
// random per-world limits and orientations (about half of them outside the
// limits, so the rows and the position step have work), both bodies dynamic.
// Registered twice: a cone (ellipse projection, Newton) and a pyramid
// (atan2 and sin/cos) swing limit, both with a limited twist.
#include <cmath>
#include <string>
#include <vector>

#include "batch/part_binding.h"
#include "batch/world_blocks.h"
#include "bench/bench_registry.h"
#include "bench/bench_support.h"
#include "kernels/swing_twist.h"

namespace manyworlds::bench {
namespace {

constexpr float kDegree = 3.14159265f / 180.0f;

Float4 Multiply(const Float4& a, const Float4& b) {  // Hamilton product, (x, y, z, w)
  return {a[3] * b[0] + b[3] * a[0] + a[1] * b[2] - a[2] * b[1],
          a[3] * b[1] + b[3] * a[1] + a[2] * b[0] - a[0] * b[2],
          a[3] * b[2] + b[3] * a[2] + a[0] * b[1] - a[1] * b[0],
          a[3] * b[3] - a[0] * b[0] - a[1] * b[1] - a[2] * b[2]};
}
Float4 Conjugate(const Float4& q) { return {-q[0], -q[1], -q[2], q[3]}; }
void SetLane(QuatLanes& q, std::size_t lane, const Float4& value) {
  q.x[lane] = value[0];
  q.y[lane] = value[1];
  q.z[lane] = value[2];
  q.w[lane] = value[3];
}

template <SwingType kSwingType>
class SwingTwistBatch {
 public:
  SwingTwistBatch(const SwingTwistKernels& kernels, std::size_t worlds)
      : kernels(kernels),
        bodies({MotionType::kDynamic, MotionType::kDynamic}, worlds),
        config{kSwingType, AxisLimitKind::kLimited, AxisLimitKind::kLimited,
               AxisLimitKind::kLimited},
        geometry(bodies.block_count()),
        limits(bodies.block_count()),
        part(bodies.block_count()),
        deactivate_lanes(bodies.block_count()),
        active(bodies.block_count()) {
    Random random(kSeed);
    PartBlocks<SwingTwistLimitAngles> angles(bodies.block_count());
    const PartBinding joint = BindPart(bodies, "ragdoll_joint", PartKind::kSwingTwist, 0, 1);
    for (std::size_t world = 0; world < worlds; ++world) {
      const std::size_t block = world / kLaneWidth, lane = world % kLaneWidth;
      SwingTwistLimitAngles& a = angles[block];
      a.twist_min[lane] = -random.Uniform(20, 90) * kDegree;
      a.twist_max[lane] = random.Uniform(20, 90) * kDegree;
      const float cone_y = random.Uniform(20, 70) * kDegree;
      const float cone_z = random.Uniform(20, 70) * kDegree;
      const bool cone = kSwingType == SwingType::kCone;
      a.swing_y_min[lane] = cone ? -cone_y : -random.Uniform(20, 70) * kDegree;
      a.swing_y_max[lane] = cone_y;
      a.swing_z_min[lane] = cone ? -cone_z : -random.Uniform(20, 70) * kDegree;
      a.swing_z_max[lane] = cone_z;
      // Relative rotation: swing and twist of up to ~1.4x the limits.
      const Float3 swing_axis = random.Perpendicular({1.0f, 0.0f, 0.0f});
      const float swing = 0.5f * random.Uniform(0.0f, 1.4f * std::max(cone_y, cone_z));
      const float twist = 0.5f * random.Uniform(-1.4f, 1.4f) * a.twist_max[lane];
      const Float4 q = Multiply(
          {swing_axis[0] * std::sin(swing), swing_axis[1] * std::sin(swing),
           swing_axis[2] * std::sin(swing), std::cos(swing)},
          {std::sin(twist), 0.0f, 0.0f, std::cos(twist)});
      BodyState body1 = RandomBody(random), body2 = RandomBody(random);
      const Float4 c1 = random.Rotation(), c2 = random.Rotation();
      // q2 = q1 c1 q c2*, so that (q1 c1)* (q2 c2) = q.
      body2.rotation = Multiply(Multiply(Multiply(body1.rotation, c1), q), Conjugate(c2));
      bodies.Set(world, 0, body1);
      bodies.Set(world, 1, body2);
      SetLane(geometry[block].constraint_to_body1, lane, c1);
      SetLane(geometry[block].constraint_to_body2, lane, c2);
      part[block].persistent.swing_y_lambda[lane] = -random.Uniform(0, 1);
      part[block].persistent.twist_lambda[lane] = -random.Uniform(0, 1);
      deactivate_lanes[block][lane] = random.Uniform(0, 1) < 0.5f ? 1.0f : 0.0f;
    }
    for (std::size_t block = 0; block < bodies.block_count(); ++block) {
      pairs.push_back(PairInBlock(bodies, joint, block));
      kernels.set_limits(config, angles[block], limits[block]);
      kernels.calculate_properties(pairs[block], config, geometry[block], limits[block],
                                   part[block]);
    }
  }
  SwingTwistBatch(const SwingTwistBatch&) = delete;  // pairs point into `bodies`
  SwingTwistBatch& operator=(const SwingTwistBatch&) = delete;

  std::string Insane() const {
    if (std::string problem = InsaneBodies(bodies); !problem.empty()) return problem;
    for (std::size_t block = 0; block < bodies.block_count(); ++block) {
      const SwingTwistLanes& p = part[block];
      for (std::size_t lane = 0; lane < kLaneWidth; ++lane) {
        for (const float value :
             {p.persistent.swing_y_lambda[lane], p.persistent.swing_z_lambda[lane],
              p.persistent.twist_lambda[lane], p.swing_y.properties.effective_mass[lane],
              p.swing_z.properties.effective_mass[lane],
              p.twist.properties.effective_mass[lane]}) {
          std::string problem = InsaneValue(
              "swing-twist impulse or effective mass in block " + std::to_string(block), value);
          if (!problem.empty()) return problem;
        }
      }
    }
    return "";
  }

  const SwingTwistKernels& kernels;
  BodyBlocks bodies;
  SwingTwistConfig config;
  std::vector<BodyPair> pairs;  // per block
  PartBlocks<SwingTwistGeometry> geometry;
  PartBlocks<SwingTwistLimitLanes> limits;
  PartBlocks<SwingTwistLanes> part;
  PartBlocks<LaneFlags> deactivate_lanes;
  PartBlocks<LaneFlags> active;
};

template <SwingType kSwingType>
struct Verbs {
  using Batch = SwingTwistBatch<kSwingType>;

  static bool CalculateProperties(Batch& b, std::size_t) {
    for (std::size_t i = 0; i < b.pairs.size(); ++i) {
      b.kernels.calculate_properties(b.pairs[i], b.config, b.geometry[i], b.limits[i], b.part[i]);
    }
    return false;
  }
  // Ratio -1: the impulses flip sign on every call, so velocities alternate
  // between two values instead of growing. Same arithmetic as any ratio.
  static bool WarmStart(Batch& b, std::size_t) {
    for (std::size_t i = 0; i < b.pairs.size(); ++i) {
      b.kernels.warm_start(b.pairs[i], b.config, b.part[i], -1.0f);
    }
    return false;
  }
  static bool SolveVelocity(Batch& b, std::size_t) {
    bool applied = false;
    for (std::size_t i = 0; i < b.pairs.size(); ++i) {
      applied |= b.kernels.solve_velocity(b.pairs[i], b.config, b.part[i]);
    }
    return applied;
  }
  // The Baumgarte steps approach the limits from outside and never cross
  // them, so violated lanes stay violated and every call does the full work.
  static bool SolvePosition(Batch& b, std::size_t) {
    bool applied = false;
    for (std::size_t i = 0; i < b.pairs.size(); ++i) {
      applied |= b.kernels.solve_position(b.pairs[i], b.config, b.geometry[i], b.limits[i],
                                          kBaumgarte);
    }
    return applied;
  }

  static bool Register(const char* part) {
    return RegisterPartBenchmarks<Batch, SwingTwistKernels>(
        part, {{"calculate_properties", &CalculateProperties},
               {"warm_start", &WarmStart},
               {"solve_velocity", &SolveVelocity},
               {"solve_position", &SolvePosition},
               {"deactivate", &DeactivateVerb<Batch>},
               {"is_active", &IsActiveVerb<Batch>}});
  }
};

const bool kRegisteredCone = Verbs<SwingType::kCone>::Register("swing_twist_cone");
const bool kRegisteredPyramid = Verbs<SwingType::kPyramid>::Register("swing_twist_pyramid");

}  // namespace
}  // namespace manyworlds::bench
