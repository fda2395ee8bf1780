// Shared helpers of the lane-by-lane tests: random inputs that differ per
// world, conversions between block lanes and the scalar reference, and the
// tolerance rule every comparison uses.
#pragma once

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cfloat>
#include <cctype>
#include <cmath>
#include <cstring>
#include <functional>
#include <optional>
#include <utility>
#include <cstddef>
#include <random>
#include <string>
#include <vector>

#include "batch/part_binding.h"
#include "batch/world_blocks.h"
#include "kernels/kernel_table.h"
#include "manyworlds/body_state.h"
#include "manyworlds/lanes.h"
#include "reference/body.h"
#include "reference/math.h"

namespace manyworlds::testing {

using RefBody = reference::Body<double>;
using Vec3d = reference::Vec3<double>;
using Vec2d = reference::Vec2<double>;
using Quatd = reference::Quat<double>;
using Mat22d = reference::Mat22<double>;
using Mat33d = reference::Mat33<double>;

// Tolerance rule. Kernels compute in float, the reference in double from the
// same float inputs. Every compared value is a chain of at most a few dozen
// float roundings (3-vector dots and crosses, a quaternion rotation, a 2x2
// inverse) of quantities no larger than `scale`, so its error is bounded by
// kRoundingBudget * FLT_EPSILON * scale. Wherever an effective mass K^-1 enters,
// rounding errors of its inputs are amplified by at most cond(K), so those
// comparisons multiply by the lane's condition number. A real bug (a wrong
// sign, a missing term, a wrong lane) shows up as an error of order `scale`.
inline constexpr double kRoundingBudget = 64.0;

inline double Tolerance(double scale, double condition = 1.0) {
  return kRoundingBudget * FLT_EPSILON * std::max(scale, 1e-30) * condition;
}

// Condition number of a symmetric positive (semi)definite matrix (infinity
// when singular).
template <int N>
double Condition(const Eigen::Matrix<double, N, N>& m) {
  const Eigen::Matrix<double, N, N> sym = 0.5 * (m + m.transpose());
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, N, N>> solver(sym);
  const auto values = solver.eigenvalues().cwiseAbs();
  if (values.minCoeff() == 0.0) return INFINITY;
  return values.maxCoeff() / values.minCoeff();
}

// ------------------------------------------------------------ random inputs

class Random {
 public:
  explicit Random(unsigned seed) : engine_(seed) {}
  double Uniform(double lo, double hi) {
    return std::uniform_real_distribution<double>(lo, hi)(engine_);
  }
  // Log-uniform in [lo, hi] (masses and inertias spanning decades).
  double LogUniform(double lo, double hi) {
    return std::exp(Uniform(std::log(lo), std::log(hi)));
  }
  Vec3d UnitVector() {
    Vec3d v;
    do {
      v = Vec3d(Uniform(-1, 1), Uniform(-1, 1), Uniform(-1, 1));
    } while (v.norm() < 0.1 || v.norm() > 1.0);
    return v.normalized();
  }
  Vec3d Vector(double max_length) { return UnitVector() * Uniform(0, max_length); }
  Quatd Rotation() {
    const Vec3d axis = UnitVector();
    return Quatd(Eigen::AngleAxisd(Uniform(-M_PI, M_PI), axis));
  }
  // A unit vector perpendicular to `n`.
  Vec3d Perpendicular(const Vec3d& n) {
    Vec3d p;
    do {
      p = UnitVector();
      p -= p.dot(n) * n;
    } while (p.norm() < 0.1);
    return p.normalized();
  }

 private:
  std::mt19937 engine_;
};

// Rounds every field to float, as the block stores it.
inline Vec3d ToFloat(const Vec3d& v) {
  return Vec3d(float(v.x()), float(v.y()), float(v.z()));
}

// A random body with per-world mass properties; unit quaternions are rounded
// to float and renormalised in float so that kernel and reference share them.
inline BodyState RandomBodyState(Random& random) {
  BodyState s;
  auto set3 = [](std::array<float, 3>& out, const Vec3d& v) {
    out = {float(v.x()), float(v.y()), float(v.z())};
  };
  auto set4 = [](std::array<float, 4>& out, const Quatd& q) {
    const float norm = std::sqrt(float(q.x() * q.x() + q.y() * q.y() +
                                       q.z() * q.z() + q.w() * q.w()));
    out = {float(q.x()) / norm, float(q.y()) / norm, float(q.z()) / norm,
           float(q.w()) / norm};
  };
  set3(s.position, random.Vector(5.0));
  set4(s.rotation, random.Rotation());
  set3(s.linear_velocity, random.Vector(3.0));
  set3(s.angular_velocity, random.Vector(3.0));
  s.inv_mass = float(random.LogUniform(0.1, 10.0));
  set3(s.inv_inertia_diagonal,
       Vec3d(random.LogUniform(0.1, 10.0), random.LogUniform(0.1, 10.0),
             random.LogUniform(0.1, 10.0)));
  set4(s.inertia_rotation, random.Rotation());
  return s;
}

// ------------------------------------------------ block lanes <-> reference

inline Vec3d ToVec3d(const std::array<float, 3>& v) { return Vec3d(v[0], v[1], v[2]); }
inline Quatd ToQuatd(const std::array<float, 4>& q) {
  return Quatd(q[3], q[0], q[1], q[2]);  // Eigen takes (w, x, y, z)
}

inline RefBody ToReference(const BodyState& s, MotionType motion) {
  RefBody body;
  body.position = ToVec3d(s.position);
  body.rotation = ToQuatd(s.rotation);
  body.linear_velocity = ToVec3d(s.linear_velocity);
  body.angular_velocity = ToVec3d(s.angular_velocity);
  body.inv_mass = s.inv_mass;
  body.inv_inertia_diagonal = ToVec3d(s.inv_inertia_diagonal);
  body.inertia_rotation = ToQuatd(s.inertia_rotation);
  body.motion_type = motion;
  return body;
}

inline Vec3d LaneVec3(const Vec3Lanes& v, std::size_t lane) {
  return Vec3d(v.x[lane], v.y[lane], v.z[lane]);
}
inline void SetLaneVec3(Vec3Lanes& v, std::size_t lane, const Vec3d& value) {
  v.x[lane] = float(value.x());
  v.y[lane] = float(value.y());
  v.z[lane] = float(value.z());
}
inline Quatd LaneQuat(const QuatLanes& q, std::size_t lane) {
  return Quatd(q.w[lane], q.x[lane], q.y[lane], q.z[lane]);
}
inline void SetLaneQuat(QuatLanes& q, std::size_t lane, const Quatd& value) {
  q.x[lane] = float(value.x());
  q.y[lane] = float(value.y());
  q.z[lane] = float(value.z());
  q.w[lane] = float(value.w());
}

// --------------------------------------------------------------- comparisons

inline std::string WorldLabel(std::size_t world, const char* what) {
  return std::string(what) + " of world " + std::to_string(world);
}

inline void ExpectVec3Near(const Vec3d& actual, const Vec3d& expected,
                           double tolerance, const std::string& label) {
  EXPECT_LE((actual - expected).cwiseAbs().maxCoeff(), tolerance)
      << label << ": kernel (" << actual.transpose() << ") vs reference ("
      << expected.transpose() << ")";
}

// Quaternions q and -q are the same rotation, but every verb here is a
// continuous function of its inputs, so the sign must match too.
inline void ExpectQuatNear(const Quatd& actual, const Quatd& expected,
                           double tolerance, const std::string& label) {
  EXPECT_LE((actual.coeffs() - expected.coeffs()).cwiseAbs().maxCoeff(), tolerance)
      << label << ": kernel (" << actual.coeffs().transpose()
      << ") vs reference (" << expected.coeffs().transpose() << ")";
}

inline bool BitEqual(const void* a, const void* b, std::size_t bytes) {
  return std::memcmp(a, b, bytes) == 0;
}

// Compares body `body` of `world` after a verb with the reference body after
// the same verb. Each field's scale is its size plus the change the verb made,
// the change amplified by `condition` (cond(K) of the part's effective mass).
inline void ExpectBodyNear(const BodyBlocks& blocks, std::size_t world,
                           std::size_t body, const RefBody& before,
                           const RefBody& expected, double condition,
                           const std::string& label) {
  const BodyState actual = blocks.Get(world, body);
  auto scale = [&](const Vec3d& was, const Vec3d& now) {
    return std::max(was.norm(), now.norm()) + condition * (now - was).norm();
  };
  const std::string where = label + ", body " + std::to_string(body) +
                            " of world " + std::to_string(world);
  ExpectVec3Near(ToVec3d(actual.linear_velocity), expected.linear_velocity,
                 Tolerance(scale(before.linear_velocity, expected.linear_velocity)),
                 where + ", linear velocity");
  ExpectVec3Near(ToVec3d(actual.angular_velocity), expected.angular_velocity,
                 Tolerance(scale(before.angular_velocity, expected.angular_velocity)),
                 where + ", angular velocity");
  ExpectVec3Near(ToVec3d(actual.position), expected.position,
                 Tolerance(scale(before.position, expected.position)),
                 where + ", position");
  const double rotation_change =
      (expected.rotation.coeffs() - before.rotation.coeffs()).norm();
  ExpectQuatNear(ToQuatd(actual.rotation), expected.rotation,
                 Tolerance(1.0 + condition * rotation_change), where + ", rotation");
}

// How a part test reaches its accumulated impulses and effective-mass
// condition, so one comparison routine serves every part.
struct PartHooks {
  std::function<Eigen::VectorXd(std::size_t world)> kernel_lambda;
  std::function<Eigen::VectorXd(std::size_t world)> reference_lambda;
  // Copies the kernel's impulse of a world into its reference part.
  std::function<void(std::size_t world)> sync_reference_lambda;
  // cond(K) of the world's effective mass (1 for scalar parts).
  std::function<double(std::size_t world)> condition;
};

// A part's impulse as the vector CompareVerbOnEveryLane compares.
inline Eigen::VectorXd AsVector(double value) { return Eigen::VectorXd::Constant(1, value); }
template <int N>
Eigen::VectorXd AsVector(const Eigen::Matrix<double, N, 1>& value) {
  return value;
}

// The hooks of a part whose reference parts have Get/SetTotalLambda:
// kernel_lambda(world) reads the kernel's impulse (a double or an Eigen
// vector), condition(world) is the lane's cond(K).
template <class Reference, class KernelLambda, class ConditionOf>
PartHooks MakePartHooks(std::vector<Reference>& reference, KernelLambda kernel_lambda,
                        ConditionOf condition) {
  return {[kernel_lambda](std::size_t w) { return AsVector(kernel_lambda(w)); },
          [&reference](std::size_t w) { return AsVector(reference[w].GetTotalLambda()); },
          [&reference, kernel_lambda](std::size_t w) {
            reference[w].SetTotalLambda(kernel_lambda(w));
          },
          condition};
}

// Runs one verb on the kernel (per block) and on the reference (per world)
// from the same body state and impulse, then compares every lane's bodies and
// impulse, and the kernel's per-block "any lane applied" with the reference.
// kernel_verb(block) -> bool; reference_verb(world, body1, body2) -> bool.
template <class KernelVerb, class ReferenceVerb>
void CompareVerbOnEveryLane(const char* label, const BodyBlocks& bodies,
                            const PartHooks& hooks, KernelVerb kernel_verb,
                            ReferenceVerb reference_verb) {
  const std::size_t worlds = bodies.world_count();
  std::vector<RefBody> before1(worlds), before2(worlds), after1(worlds), after2(worlds);
  std::vector<Eigen::VectorXd> lambda_before(worlds);
  std::vector<bool> reference_applied(bodies.block_count(), false);
  for (std::size_t w = 0; w < worlds; ++w) {
    lambda_before[w] = hooks.kernel_lambda(w);
    before1[w] = after1[w] = ToReference(bodies.Get(w, 0), bodies.motion_type(0));
    before2[w] = after2[w] = ToReference(bodies.Get(w, 1), bodies.motion_type(1));
    hooks.sync_reference_lambda(w);
    if (reference_verb(w, after1[w], after2[w])) {
      reference_applied[w / kLaneWidth] = true;
    }
  }
  for (std::size_t block = 0; block < bodies.block_count(); ++block) {
    EXPECT_EQ(kernel_verb(block), reference_applied[block])
        << label << ": 'any lane applied' of block " << block;
  }
  for (std::size_t w = 0; w < worlds; ++w) {
    const double condition = hooks.condition(w);
    ExpectBodyNear(bodies, w, 0, before1[w], after1[w], condition, label);
    ExpectBodyNear(bodies, w, 1, before2[w], after2[w], condition, label);
    // Same scale rule as the bodies: size before and after, plus the change
    // amplified by cond(K).
    const Eigen::VectorXd expected = hooks.reference_lambda(w);
    const double scale = std::max(lambda_before[w].norm(), expected.norm()) +
                         condition * (expected - lambda_before[w]).norm();
    EXPECT_LE((hooks.kernel_lambda(w) - expected).cwiseAbs().maxCoeff(), Tolerance(scale))
        << label << ": accumulated impulse of world " << w;
  }
}

// One parameter set of a part test: target, world count, motion types.
template <class Table>
struct PartCase {
  const Table* kernels;
  std::size_t world_count;
  MotionType motion1;
  MotionType motion2;
};

// What every part test fixture holds: the case, the bodies of its worlds and
// the part's binding to bodies 0 and 1.
template <class Table>
class PartTestBase : public ::testing::TestWithParam<PartCase<Table>> {
 protected:
  void SetUpBodies(const char* constraint_name, PartKind kind) {
    const PartCase<Table>& c = this->GetParam();
    kernels_ = c.kernels;
    bodies_.emplace(std::vector<MotionType>{c.motion1, c.motion2}, c.world_count);
    binding_ = BindPart(*bodies_, constraint_name, kind, 0, 1);
  }

  std::size_t worlds() const { return bodies_->world_count(); }
  std::size_t blocks() const { return bodies_->block_count(); }
  static std::size_t Block(std::size_t world) { return world / kLaneWidth; }
  static std::size_t Lane(std::size_t world) { return world % kLaneWidth; }
  BodyPair Pair(std::size_t block) { return PairInBlock(*bodies_, binding_, block); }
  RefBody Body(std::size_t world, std::size_t body) const {
    return ToReference(bodies_->Get(world, body), bodies_->motion_type(body));
  }

  // Expects both bodies of every selected world to be bit-identical to `before`.
  template <class Selected>
  void ExpectBodiesUnchanged(const BodyBlocks& before, Selected selected,
                             const char* what) const {
    for (std::size_t w = 0; w < worlds(); ++w) {
      for (std::size_t body = 0; body < 2; ++body) {
        if (!selected(w, body)) continue;
        const BodyState a = before.Get(w, body), b = bodies_->Get(w, body);
        EXPECT_TRUE(BitEqual(&a, &b, sizeof(BodyState)))
            << what << ": body " << body << " of world " << w << " changed";
      }
    }
  }

  // Deactivates the worlds `selected(world)` picks, in the kernel (through
  // per-lane flags) and in their reference parts.
  template <class PartLanes, class Reference, class Selected>
  void DeactivateWorlds(PartBlocks<PartLanes>& parts, std::vector<Reference>& reference,
                        Selected selected) {
    PartBlocks<LaneFlags> flags(blocks());
    for (std::size_t w = 0; w < worlds(); ++w) {
      if (!selected(w)) continue;
      flags[Block(w)][Lane(w)] = 1.0f;
      reference[w].Deactivate();
    }
    for (std::size_t block = 0; block < blocks(); ++block) {
      kernels_->deactivate(parts[block], flags[block]);
    }
  }

  const Table* kernels_ = nullptr;
  std::optional<BodyBlocks> bodies_;
  PartBinding binding_;
};

// Every supported target x TestWorldCounts() x the given motion pairings.
template <class Table>
std::vector<PartCase<Table>> AllPartCases(
    const std::vector<std::pair<MotionType, MotionType>>& pairings);

// Name of a kernel table for test names ("AVX2", "SCALAR", ...).
inline std::string TargetLabel(const TargetInfo& target) {
  std::string name = target.name;
  for (char& c : name) {
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  }
  return name;
}

// gtest parameter name of a per-target test: the target's name.
template <class Table>
std::string TableName(const ::testing::TestParamInfo<const Table*>& info) {
  return TargetLabel(info.param->target);
}

// The world counts every part test runs with: one world, a partial block,
// exactly one block, and many blocks with a partial last one.
inline const std::vector<std::size_t>& TestWorldCounts() {
  static const std::vector<std::size_t> counts = {1, 7, 16, 1000};
  return counts;
}

template <class Table>
std::vector<PartCase<Table>> AllPartCases(
    const std::vector<std::pair<MotionType, MotionType>>& pairings) {
  std::vector<PartCase<Table>> cases;
  for (const Table* kernels : SupportedKernels<Table>()) {
    for (const std::size_t worlds : TestWorldCounts()) {
      for (const auto& [motion1, motion2] : pairings) {
        cases.push_back({kernels, worlds, motion1, motion2});
      }
    }
  }
  return cases;
}

template <class Table>
std::string PartCaseName(const ::testing::TestParamInfo<PartCase<Table>>& info) {
  const PartCase<Table>& c = info.param;
  return TargetLabel(c.kernels->target) + "_" + std::to_string(c.world_count) + "worlds_" +
         MotionTypeName(c.motion1) + "_" + MotionTypeName(c.motion2);
}

}  // namespace manyworlds::testing
