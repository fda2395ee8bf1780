// IndependentAxisConstraintPart (pulley) kernels, every verb, every lane
// against the scalar reference, on every Highway target this CPU supports, for
// 1, 7, 16 and 1000 worlds and every motion-type pairing with a non-static
// body. Lanes carry the pulley's impulse ranges ([0, inf) at the minimum
// length, (-inf, 0] at the maximum, unbounded, and tight finite ranges that
// clamp), and the "not static" rule (a kinematic body's mass counts in K but
// receives nothing) is compared lane by lane.
#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <memory>
#include <vector>

#include "batch/part_binding.h"
#include "batch/part_state.h"
#include "batch/world_blocks.h"
#include "kernels/independent_axis.h"
#include "reference/independent_axis_part.h"
#include "tests/test_support.h"

namespace manyworlds::testing {
namespace {

using RefIndependentAxis = reference::IndependentAxisPart<double>;

constexpr float kInfinity = std::numeric_limits<float>::infinity();

enum class LaneKind {
  kUnbounded,      // (-inf, inf): both pulley limits reached (min = max)
  kPushOnly,       // [0, inf): rope at its minimum length
  kPullOnly,       // (-inf, 0]: rope at its maximum length
  kTightRange,     // [-0.05, 0.05]: clamps in most solves
  kTinyMass,       // K ~ 1e-8: 1/K huge but exact to float precision
  kSingular,       // no mass, no inertia: K == 0
  kDeactivatedByFlag,
  kAsymmetricRange,  // [-0.2, 0.7]
};

LaneKind KindOfWorld(std::size_t world) { return LaneKind(world % 8); }

class IndependentAxisTest : public PartTestBase<IndependentAxisKernels> {
 protected:
  void SetUp() override {
    SetUpBodies("pulley", PartKind::kIndependentAxis);
    const std::size_t world_count = GetParam().world_count;
    geometry_ = std::make_unique<PartBlocks<IndependentAxisGeometry>>(blocks());
    parts_ = std::make_unique<PartBlocks<IndependentAxisLanes>>(blocks());
    error_ = std::make_unique<PartBlocks<LaneArray>>(blocks());
    reference_.resize(world_count);
    for (std::size_t world = 0; world < world_count; ++world) FillWorld(world);
  }

  void FillWorld(std::size_t world) {
    Random random(1618033u + 104723u * unsigned(world));
    BodyState body1 = RandomBodyState(random);
    BodyState body2 = RandomBodyState(random);
    float min_lambda = -kInfinity, max_lambda = kInfinity;
    switch (KindOfWorld(world)) {
      case LaneKind::kPushOnly: min_lambda = 0.0f; break;
      case LaneKind::kPullOnly: max_lambda = 0.0f; break;
      case LaneKind::kTightRange: min_lambda = -0.05f, max_lambda = 0.05f; break;
      case LaneKind::kAsymmetricRange: min_lambda = -0.2f, max_lambda = 0.7f; break;
      case LaneKind::kTinyMass:
        for (BodyState* body : {&body1, &body2}) {
          body->inv_mass *= 1e-8f;
          for (float& d : body->inv_inertia_diagonal) d *= 1e-8f;
        }
        break;
      case LaneKind::kSingular:
        for (BodyState* body : {&body1, &body2}) {
          body->inv_mass = 0.0f;
          body->inv_inertia_diagonal = {0.f, 0.f, 0.f};
        }
        break;
      default: break;
    }
    bodies_->Set(world, 0, body1);
    bodies_->Set(world, 1, body2);
    IndependentAxisGeometry& g = (*geometry_)[Block(world)];
    const std::size_t lane = Lane(world);
    SetLaneVec3(g.r1, lane, random.Vector(1.0));
    SetLaneVec3(g.n1, lane, random.UnitVector());
    SetLaneVec3(g.r2, lane, random.Vector(1.0));
    SetLaneVec3(g.n2, lane, random.UnitVector());
    g.ratio[lane] = float(random.LogUniform(0.1, 10.0));  // block and tackle
    g.min_lambda[lane] = min_lambda;
    g.max_lambda[lane] = max_lambda;
    (*error_)[Block(world)][lane] = float(random.Uniform(-0.3, 0.3));
    // Sometimes outside the range: warm starting does not clamp, solves do.
    SetTotalLambda(*parts_, world, float(random.Uniform(-1, 1)));
  }

  const IndependentAxisGeometry& G(std::size_t w) const { return (*geometry_)[Block(w)]; }
  Vec3d R1(std::size_t w) const { return LaneVec3(G(w).r1, Lane(w)); }
  Vec3d N1(std::size_t w) const { return LaneVec3(G(w).n1, Lane(w)); }
  Vec3d R2(std::size_t w) const { return LaneVec3(G(w).r2, Lane(w)); }
  Vec3d N2(std::size_t w) const { return LaneVec3(G(w).n2, Lane(w)); }
  double Ratio(std::size_t w) const { return G(w).ratio[Lane(w)]; }
  double MinLambda(std::size_t w) const { return G(w).min_lambda[Lane(w)]; }
  double MaxLambda(std::size_t w) const { return G(w).max_lambda[Lane(w)]; }
  double Error(std::size_t w) const { return (*error_)[Block(w)][Lane(w)]; }
  double Lambda(std::size_t world) const { return GetTotalLambda(*parts_, world); }
  bool AnyKinematic() const {
    return bodies_->motion_type(0) == MotionType::kKinematic ||
           bodies_->motion_type(1) == MotionType::kKinematic;
  }

  void CalculateProperties() {
    for (std::size_t block = 0; block < blocks(); ++block) {
      kernels_->calculate_properties(Pair(block), (*geometry_)[block], (*parts_)[block]);
    }
    for (std::size_t w = 0; w < worlds(); ++w) {
      reference_[w].SetTotalLambda(Lambda(w));
      reference_[w].CalculateConstraintProperties(Body(w, 0), R1(w), N1(w), Body(w, 1), R2(w),
                                                  N2(w), Ratio(w));
    }
  }

  void DeactivateFlaggedLanes() {
    DeactivateWorlds(*parts_, reference_,
                     [](std::size_t w) { return KindOfWorld(w) == LaneKind::kDeactivatedByFlag; });
  }

  // What the other parts of an island do between two solves of this one:
  // change the velocities, so every solve has real work and its "applied"
  // flag is not a comparison of rounding noise in float and double.
  void KickVelocities(unsigned seed) {
    for (std::size_t w = 0; w < worlds(); ++w) {
      Random random(seed + 7u * unsigned(w));
      for (std::size_t body = 0; body < 2; ++body) {
        BodyState state = bodies_->Get(w, body);
        for (float& c : state.linear_velocity) c += float(random.Uniform(-1, 1));
        for (float& c : state.angular_velocity) c += float(random.Uniform(-1, 1));
        bodies_->Set(w, body, state);
      }
    }
  }

  PartHooks Hooks() {  // K is a scalar: no amplification
    return MakePartHooks(reference_, [this](std::size_t w) { return Lambda(w); },
                         [](std::size_t) { return 1.0; });
  }

  template <class KernelVerb, class ReferenceVerb>
  void CompareVerb(const char* label, KernelVerb kernel_verb, ReferenceVerb reference_verb) {
    CompareVerbOnEveryLane(label, *bodies_, Hooks(), kernel_verb, reference_verb);
  }

  void WarmStart(float ratio) {
    CompareVerb(
        "warm start",
        [&](std::size_t block) {
          kernels_->warm_start(Pair(block), (*geometry_)[block], (*parts_)[block], ratio);
          return false;
        },
        [&](std::size_t w, RefBody& b1, RefBody& b2) {
          reference_[w].WarmStart(b1, b2, N1(w), N2(w), Ratio(w), ratio);
          return false;
        });
  }

  // J v is a sum of products of O(|v|) terms; when they nearly cancel, its
  // float rounding relative to J v itself grows by sum|terms| / |J v|, and
  // dL = -K^-1 J v inherits that. Used as the condition of a velocity solve.
  double VelocityErrorCancellation(std::size_t w) const {
    const RefBody b1 = Body(w, 0), b2 = Body(w, 1);
    const double jv = reference::IndependentAxisVelocityError(b1, R1(w), N1(w), b2, R2(w),
                                                              N2(w), Ratio(w));
    const double terms =
        b1.LinearVelocity().norm() + R1(w).cross(N1(w)).norm() * b1.AngularVelocity().norm() +
        Ratio(w) * (b2.LinearVelocity().norm() +
                    R2(w).cross(N2(w)).norm() * b2.AngularVelocity().norm());
    return std::clamp(terms / std::abs(jv), 1.0, 1e12);
  }

  void SolveVelocity() {
    std::vector<double> cancellation(worlds());
    for (std::size_t w = 0; w < worlds(); ++w) cancellation[w] = VelocityErrorCancellation(w);
    PartHooks hooks = Hooks();
    hooks.condition = [&](std::size_t w) { return cancellation[w]; };
    CompareVerbOnEveryLane(
        "velocity solve", *bodies_, hooks,
        [&](std::size_t block) {
          return kernels_->solve_velocity(Pair(block), (*geometry_)[block], (*parts_)[block]);
        },
        [&](std::size_t w, RefBody& b1, RefBody& b2) {
          return reference_[w].SolveVelocityConstraint(b1, b2, N1(w), N2(w), Ratio(w),
                                                       MinLambda(w), MaxLambda(w));
        });
  }

  void SolvePosition(float baumgarte) {
    CompareVerb(
        "position solve",
        [&](std::size_t block) {
          return kernels_->solve_position(Pair(block), (*geometry_)[block], (*error_)[block],
                                          (*parts_)[block], baumgarte);
        },
        [&](std::size_t w, RefBody& b1, RefBody& b2) {
          return reference_[w].SolvePositionConstraint(b1, b2, N1(w), N2(w), Ratio(w), Error(w),
                                                       baumgarte);
        });
  }

  std::unique_ptr<PartBlocks<IndependentAxisGeometry>> geometry_;
  std::unique_ptr<PartBlocks<IndependentAxisLanes>> parts_;
  std::unique_ptr<PartBlocks<LaneArray>> error_;
  std::vector<RefIndependentAxis> reference_;
};

TEST_P(IndependentAxisTest, CalculatePropertiesMatchesReference) {
  CalculateProperties();
  LaneFlags active;
  for (std::size_t w = 0; w < worlds(); ++w) {
    const IndependentAxisLanes& part = (*parts_)[Block(w)];
    const RefIndependentAxis& ref = reference_[w];
    const std::size_t lane = Lane(w);
    const double lever1 = R1(w).norm(), lever2 = Ratio(w) * R2(w).norm();
    ExpectVec3Near(LaneVec3(part.r1_x_n1, lane), ref.R1xN1(), Tolerance(lever1),
                   WorldLabel(w, "r1 x n1"));
    ExpectVec3Near(LaneVec3(part.ratio_r2_x_n2, lane), ref.RatioR2xN2(), Tolerance(lever2),
                   WorldLabel(w, "r (r2 x n2)"));
    ExpectVec3Near(LaneVec3(part.inv_i1_r1_x_n1, lane), ref.InvI1R1xN1(),
                   Tolerance(Body(w, 0).inv_inertia_diagonal.maxCoeff() * lever1),
                   WorldLabel(w, "I1^-1 (r1 x n1)"));
    ExpectVec3Near(LaneVec3(part.inv_i2_ratio_r2_x_n2, lane), ref.InvI2RatioR2xN2(),
                   Tolerance(Body(w, 1).inv_inertia_diagonal.maxCoeff() * lever2),
                   WorldLabel(w, "I2^-1 r (r2 x n2)"));
    EXPECT_NEAR(part.effective_mass[lane], ref.EffectiveMass(), Tolerance(ref.EffectiveMass()))
        << "1/K of world " << w;
    if (lane == 0) kernels_->is_active(part, active);
    EXPECT_EQ(active[lane] != 0.0f, ref.IsActive()) << "IsActive of world " << w;
    // Every pairing here has a non-static body, whose mass counts even when
    // kinematic: only massless lanes are singular.
    EXPECT_EQ(active[lane] == 0.0f, KindOfWorld(w) == LaneKind::kSingular)
        << "IsActive of world " << w;
    if (KindOfWorld(w) == LaneKind::kSingular) {
      EXPECT_EQ(Lambda(w), 0.0) << "singular world " << w << " keeps an impulse";
    }
  }
}

TEST_P(IndependentAxisTest, WarmStartScalesAndAppliesImpulseWithoutClamping) {
  CalculateProperties();
  WarmStart(0.75f);
}

TEST_P(IndependentAxisTest, WarmStartWithRatioZeroAppliesNothing) {
  CalculateProperties();
  const BodyBlocks before = *bodies_;
  for (std::size_t block = 0; block < blocks(); ++block) {
    kernels_->warm_start(Pair(block), (*geometry_)[block], (*parts_)[block], 0.0f);
  }
  for (std::size_t w = 0; w < worlds(); ++w) {
    EXPECT_EQ(Lambda(w), 0.0) << "world " << w;
  }
  ExpectBodiesUnchanged(before, [](std::size_t, std::size_t) { return true; },
                        "warm start with ratio 0");
}

TEST_P(IndependentAxisTest, VelocitySolveMatchesReferenceClampsAndZeroesVelocityError) {
  CalculateProperties();
  DeactivateFlaggedLanes();
  WarmStart(1.0f);
  std::size_t clamped_lanes = 0;
  for (int iteration = 0; iteration < 3; ++iteration) {
    KickVelocities(31u + unsigned(iteration));
    SolveVelocity();
    // The accumulated impulse is inside its range in every lane after every
    // solve, exactly (a clamp returns the bound itself).
    for (std::size_t w = 0; w < worlds(); ++w) {
      EXPECT_GE(Lambda(w), MinLambda(w)) << "world " << w << ", solve " << iteration;
      EXPECT_LE(Lambda(w), MaxLambda(w)) << "world " << w << ", solve " << iteration;
      if (reference_[w].IsActive() && (Lambda(w) == MinLambda(w) || Lambda(w) == MaxLambda(w))) {
        ++clamped_lanes;
      }
    }
  }
  if (worlds() >= 16) {
    EXPECT_GT(clamped_lanes, 0u) << "no lane clamped: the range test proves nothing";
  }
  // J v = 0 after a solve that was not clamped, where every non-static body
  // is dynamic: with a kinematic body K counts its mass, but the impulse does
  // not move it, so J v only shrinks (Jolt's behaviour, kept).
  if (AnyKinematic()) return;
  for (std::size_t w = 0; w < worlds(); ++w) {
    if (!reference_[w].IsActive() || Lambda(w) <= MinLambda(w) || Lambda(w) >= MaxLambda(w)) {
      continue;
    }
    const RefBody b1 = Body(w, 0), b2 = Body(w, 1);
    const double jv = reference::IndependentAxisVelocityError(b1, R1(w), N1(w), b2, R2(w), N2(w),
                                                              Ratio(w));
    const double lever = 1.0 + std::max(R1(w).norm(), R2(w).norm());
    const double speed = std::max({b1.linear_velocity.norm(), b1.angular_velocity.norm(),
                                   b2.linear_velocity.norm(), b2.angular_velocity.norm()});
    EXPECT_LE(std::abs(jv), Tolerance((1.0 + Ratio(w)) * lever * speed))
        << "J v after the velocity solve of world " << w;
  }
}

TEST_P(IndependentAxisTest, PositionSolveMatchesReferenceAndMovesOnlyDynamicBodies) {
  CalculateProperties();
  DeactivateFlaggedLanes();
  const BodyBlocks before = *bodies_;
  SolvePosition(0.2f);
  ExpectBodiesUnchanged(
      before,
      [&](std::size_t, std::size_t body) {
        return bodies_->motion_type(body) != MotionType::kDynamic;
      },
      "position solve of a non-dynamic body");
}

TEST_P(IndependentAxisTest, ImpulsesReachOnlyDynamicBodies) {
  CalculateProperties();
  const BodyBlocks before = *bodies_;
  for (std::size_t block = 0; block < blocks(); ++block) {
    kernels_->warm_start(Pair(block), (*geometry_)[block], (*parts_)[block], 1.0f);
    kernels_->solve_velocity(Pair(block), (*geometry_)[block], (*parts_)[block]);
  }
  ExpectBodiesUnchanged(
      before,
      [&](std::size_t, std::size_t body) {
        return bodies_->motion_type(body) != MotionType::kDynamic;
      },
      "velocity steps on a non-dynamic body");
}

TEST_P(IndependentAxisTest, DeactivatedAndSingularLanesStayFiniteAndApplyNothing) {
  CalculateProperties();
  DeactivateFlaggedLanes();
  const BodyBlocks before = *bodies_;
  for (std::size_t block = 0; block < blocks(); ++block) {
    kernels_->warm_start(Pair(block), (*geometry_)[block], (*parts_)[block], 1.0f);
    kernels_->solve_velocity(Pair(block), (*geometry_)[block], (*parts_)[block]);
    kernels_->solve_position(Pair(block), (*geometry_)[block], (*error_)[block],
                             (*parts_)[block], 0.2f);
  }
  for (std::size_t w = 0; w < worlds(); ++w) {
    if (!reference_[w].IsActive()) {
      EXPECT_EQ(Lambda(w), 0.0) << "inactive world " << w;
    }
  }
  ExpectBodiesUnchanged(
      before, [&](std::size_t w, std::size_t) { return !reference_[w].IsActive(); },
      "inactive lane");
}

TEST_P(IndependentAxisTest, GetSetSaveRestoreOfAccumulatedImpulse) {
  CalculateProperties();
  for (std::size_t w = 0; w < worlds(); ++w) {
    SetTotalLambda(*parts_, w, 0.5f * float(w) - 3.0f);
    EXPECT_EQ(GetTotalLambda(*parts_, w), 0.5f * float(w) - 3.0f);
  }
  WarmStart(1.0f);
  const auto saved = SavePartState(*parts_);
  std::vector<float> at_save;
  for (std::size_t w = 0; w < worlds(); ++w) at_save.push_back(GetTotalLambda(*parts_, w));
  KickVelocities(5u);
  SolveVelocity();
  RestorePartState(*parts_, saved);
  for (std::size_t w = 0; w < worlds(); ++w) {
    const float restored = GetTotalLambda(*parts_, w);
    EXPECT_TRUE(BitEqual(&restored, &at_save[w], sizeof(float))) << "world " << w;
  }
}

std::vector<PartCase<IndependentAxisKernels>> AllCases() {
  static const std::vector<std::pair<MotionType, MotionType>> pairings = {
      {MotionType::kDynamic, MotionType::kDynamic},
      {MotionType::kDynamic, MotionType::kStatic},
      {MotionType::kStatic, MotionType::kDynamic},
      {MotionType::kKinematic, MotionType::kDynamic},
      {MotionType::kDynamic, MotionType::kKinematic},
      {MotionType::kKinematic, MotionType::kStatic},
      {MotionType::kKinematic, MotionType::kKinematic},
  };
  return AllPartCases<IndependentAxisKernels>(pairings);
}

INSTANTIATE_TEST_SUITE_P(EveryTarget, IndependentAxisTest, ::testing::ValuesIn(AllCases()),
                         PartCaseName<IndependentAxisKernels>);

}  // namespace
}  // namespace manyworlds::testing
