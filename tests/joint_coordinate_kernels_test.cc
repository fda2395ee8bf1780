// The SIMD joint-coordinate kernels (batch/joint_coordinate_kernels.cc), on
// every Highway target this CPU runs, against the double per-lane read-out
// (JointCoordinatesOfLane, the same formulas in Eigen doubles), lane by lane,
// on blocks of every constraint type whose bodies are put at random poses
// and velocities: relative rotations of any size (hinges past +-pi,
// swing-twist near its singular swing of pi), random turn counts.
//
// Tolerances. Both sides read the same float lanes; they differ only in the
// arithmetic: float with FMA and polynomial atan (1-2 ulp) against double
// libm. A coordinate is a short chain (a normalisation, two or three
// quaternion products or rotations, a dot product, one atan), each step
// adding a few ulp relative to the magnitudes involved, which here are at
// most ~10 (positions in [-2, 2] m plus lever arms, velocities in [-3, 3]):
//   angles (rad):              kAngle = 4e-5 (~340 FLT_EPSILON): the hinge's
//                              2 atan(along / w) is a ratio of two quaternion
//                              components that random poses, which violate the
//                              hinge, can make both small, dividing float's
//                              error by their norm (measured worst 8.8e-6);
//                              near the swing-twist singularity the swing's
//                              division by s = sqrt(w^2 + x^2) scales it by
//                              1/s: kAngle + 8 FLT_EPSILON / s
//   unwrapped hinge angles:    kAngle + 8 FLT_EPSILON |value| (reference +
//                              2 pi turns rounded in float twice, ~2 ulp of
//                              values up to ~320 rad, 50 turns)
//   lengths, positions (m),
//   velocities (m/s, rad/s):   kScaled * max(1, |value|), kScaled = 4e-5,
//                              for sums of products of terms up to ~30
// The worst measured errors are printed; each bound is above them by about 4x or more.
// The lanes past those asked for (13 of 16 here) must be left untouched.
// The path fraction is computed by the double read-out itself (a search over
// the path's segments) and must be bit-equal.

#include <gtest/gtest.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "batch/constraint_lanes.h"
#include "batch/joint_coordinates.h"
#include "batch/plan.h"
#include "batch/scene_setup.h"
#include "kernels/body_lanes.h"
#include "manyworlds/scenes.h"
#include "tests/mixed_scenes.h"

namespace manyworlds {
namespace {

constexpr double kAngle = 4e-5;
constexpr double kScaled = 4e-5;
constexpr int kTrials = 40;

bool IsAngle(ConstraintType type, std::size_t i) {
  switch (type) {
    case ConstraintType::kHinge: return i == 0;
    case ConstraintType::kCone: return true;
    case ConstraintType::kSwingTwist: return i < 3;
    case ConstraintType::kSixDof: return i >= 3 && i < 6;
    default: return false;
  }
}

// One block of a scene, laid out by the plan.
struct Block {
  explicit Block(const Scene& scene) : plan(CompilePlan(scene)) {
    arrays.resize(plan.block_bytes / sizeof(LaneArray));
    WriteInitialBlock(scene, plan, bytes());
  }
  std::byte* bytes() { return reinterpret_cast<std::byte*>(arrays.data()); }
  template <class Lanes>
  Lanes& at(std::size_t offset) {
    return *reinterpret_cast<Lanes*>(bytes() + offset);
  }
  StepPlan plan;
  std::vector<LaneArray> arrays;
};

// Every body of every lane at a random pose and velocity; every hinge with a
// random turn count and reference angle.
void Randomise(Block& block, std::mt19937& rng) {
  std::uniform_real_distribution<float> position(-2.0f, 2.0f), velocity(-3.0f, 3.0f);
  std::normal_distribution<float> gaussian;
  std::uniform_int_distribution<int> turns(-50, 50);
  std::uniform_real_distribution<float> angle(-3.14159f, 3.14159f);
  for (const BodyPlan& body : block.plan.bodies) {
    BodyLanes& b = block.at<BodyLanes>(body.offset);
    for (std::size_t l = 0; l < kLaneWidth; ++l) {
      b.position.x[l] = position(rng), b.position.y[l] = position(rng);
      b.position.z[l] = position(rng);
      for (Vec3Lanes* v : {&b.linear_velocity, &b.angular_velocity}) {
        v->x[l] = velocity(rng), v->y[l] = velocity(rng), v->z[l] = velocity(rng);
      }
      float q[4], length = 0.0f;
      for (float& c : q) {
        c = gaussian(rng);
        length += c * c;
      }
      length = std::sqrt(length);
      b.rotation.x[l] = q[0] / length, b.rotation.y[l] = q[1] / length;
      b.rotation.z[l] = q[2] / length, b.rotation.w[l] = q[3] / length;
    }
  }
  for (const ConstraintPlan& c : block.plan.constraints) {
    if (c.type != ConstraintType::kHinge) continue;
    auto& hinge = block.at<HingeConstraintLanes>(c.offset);
    for (std::size_t l = 0; l < kLaneWidth; ++l) {
      hinge.turns[l] = float(turns(rng));
      hinge.turn_reference_angle[l] = angle(rng);
    }
  }
}

// The swing-twist singularity measure s of a swing-twist or six-DOF lane,
// from the double read-out's angles: s = cos(swing / 2) for the larger swing
// is a lower bound of sqrt(w^2 + x^2) away from tiny s; computed directly
// instead from the reference angles would need the frames: bounded below
// by 1e-3 so a lane exactly at the singularity is held to the 1/s bound.
double SwingScale(const float* reference) {
  const double swing = std::max(std::abs(reference[1]), std::abs(reference[2]));
  return std::max(1e-3, std::cos(0.5 * swing));
}

// The largest error / bound of each kind, and where.
struct Worst {
  double angle = 0, unwrapped = 0, scaled = 0;
  std::string angle_at, unwrapped_at, scaled_at;
  static void Note(double ratio, const std::string& where, double& worst, std::string& at) {
    if (ratio > worst) worst = ratio, at = where;
  }
};

void CompareScene(const std::string& name, const Scene& scene, Worst& worst) {
  Block block(scene);
  std::mt19937 rng(1234);
  std::vector<float> simd, reference;
  for (int trial = 0; trial < kTrials; ++trial) {
    Randomise(block, rng);
    for (std::size_t ci = 0; ci < block.plan.constraints.size(); ++ci) {
      const ConstraintPlan& c = block.plan.constraints[ci];
      const std::size_t count = JointCoordinateCount(c);
      if (count == 0) continue;
      reference.assign(kLaneWidth * count, 0.0f);
      for (std::size_t l = 0; l < kLaneWidth; ++l) {
        JointCoordinatesOfLane(block.plan, block.bytes(), l, ci, &reference[l * count]);
      }
      for (const JointCoordinateKernels* kernels : SupportedKernels<JointCoordinateKernels>()) {
        // 13 lanes: the rows of lanes past `lanes` must stay untouched.
        simd.assign(kLaneWidth * count, -7.0f);
        kernels->read_block(block.plan, block.bytes(), ci, 13, count, simd.data());
        for (std::size_t l = 0; l < kLaneWidth; ++l) {
          for (std::size_t i = 0; i < count; ++i) {
            const float got = simd[l * count + i], want = reference[l * count + i];
            const std::string where = name + " " + c.label + " " + kernels->target.name +
                                      " trial " + std::to_string(trial) + " lane " +
                                      std::to_string(l) + " coordinate " + std::to_string(i);
            if (l >= 13) {
              ASSERT_EQ(got, -7.0f) << where << ": written past the lanes asked for";
              continue;
            }
            if (c.type == ConstraintType::kPath) {
              ASSERT_EQ(got, want) << where;
              continue;
            }
            const double error = std::abs(double(got) - double(want));
            double bound;
            if (c.type == ConstraintType::kHinge && i == 1) {
              bound = kAngle + 8.0 * FLT_EPSILON * std::abs(want);
              Worst::Note(error / bound, where, worst.unwrapped, worst.unwrapped_at);
            } else if (IsAngle(c.type, i)) {
              const bool swing_twist = c.type == ConstraintType::kSwingTwist ||
                                       c.type == ConstraintType::kSixDof;
              const float* angles = &reference[l * count + (c.type == ConstraintType::kSixDof ? 3 : 0)];
              bound = kAngle + (swing_twist ? 8.0 * FLT_EPSILON / SwingScale(angles) : 0.0);
              Worst::Note(error / bound, where, worst.angle, worst.angle_at);
            } else {
              bound = kScaled * std::max(1.0, std::abs(double(want)));
              Worst::Note(error / bound, where, worst.scaled, worst.scaled_at);
            }
            ASSERT_LE(error, bound) << where << ": " << got << " against " << want;
          }
        }
      }
    }
  }
}

TEST(JointCoordinateKernelsTest, EveryTargetMatchesTheDoubleReadOutAtRandomPoses) {
  Worst worst;
  CompareScene("mixed", test_scenes::MixedScene(), worst);
  CompareScene("more_types", test_scenes::MoreTypesScene(), worst);
  CompareScene("ragdoll", MakeScene("ragdoll"), worst);
  CompareScene("cartpole", MakeScene("cartpole"), worst);
  std::printf("worst error / bound:\n  angles %.3f (%s)\n  unwrapped angles %.3f (%s)\n"
              "  lengths and rates %.3f (%s)\n",
              worst.angle, worst.angle_at.c_str(), worst.unwrapped, worst.unwrapped_at.c_str(),
              worst.scaled, worst.scaled_at.c_str());
}

}  // namespace
}  // namespace manyworlds
