// DualAxisConstraintPart kernels, every verb, every lane against the scalar
// reference, on every Highway target this CPU supports, for 1, 7, 16 and 1000
// worlds and every motion-type pairing of the two bodies.
#include <gtest/gtest.h>

#include <memory>
#include <optional>
#include <vector>

#include "batch/part_binding.h"
#include "batch/part_state.h"
#include "batch/world_blocks.h"
#include "kernels/dual_axis.h"
#include "reference/dual_axis_part.h"
#include "tests/test_support.h"

namespace manyworlds::testing {
namespace {

using RefDualAxis = reference::DualAxisPart<double>;

// What kind of lane a world is: most are regular; some have an effective
// mass with a condition number ~1e3..1e5 (tiny masses, lever arms along n1),
// some are exactly singular (immovable dynamic bodies: K == 0), some are
// deactivated explicitly after CalculateProperties.
enum class LaneKind { kRegular, kNearSingular, kSingular, kDeactivatedByFlag };

LaneKind KindOfWorld(std::size_t world) {
  switch (world % 8) {
    case 3: return LaneKind::kNearSingular;
    case 5: return LaneKind::kSingular;
    case 6: return LaneKind::kDeactivatedByFlag;
    default: return LaneKind::kRegular;
  }
}

class DualAxisTest : public PartTestBase<DualAxisKernels> {
 protected:
  void SetUp() override {
    SetUpBodies("slider_sideways", PartKind::kDualAxis);
    const std::size_t world_count = GetParam().world_count;
    const std::size_t blocks = bodies_->block_count();
    geometry_ = std::make_unique<PartBlocks<DualAxisGeometry>>(blocks);
    parts_ = std::make_unique<PartBlocks<DualAxisLanes>>(blocks);
    separation_ = std::make_unique<PartBlocks<Vec3Lanes>>(blocks);
    reference_.resize(world_count);
    for (std::size_t world = 0; world < world_count; ++world) FillWorld(world);
  }

  // Random, different in every world; the reference reads back the float
  // values the blocks hold, so both start from identical inputs.
  void FillWorld(std::size_t world) {
    Random random(1234567u + 7919u * unsigned(world));
    BodyState body1 = RandomBodyState(random);
    BodyState body2 = RandomBodyState(random);
    const Vec3d n1 = random.UnitVector();
    const Vec3d n2 = random.Perpendicular(n1);
    Vec3d r1_plus_u = random.Vector(2.0);
    Vec3d r2 = random.Vector(2.0);
    switch (KindOfWorld(world)) {
      case LaneKind::kNearSingular:
        body1.inv_mass = body2.inv_mass = 1e-3f;
        r1_plus_u = 1.5 * n1 + random.Vector(1e-3);
        r2 = -0.8 * n1 + random.Vector(1e-3);
        break;
      case LaneKind::kSingular:
        body1.inv_mass = body2.inv_mass = 0.0f;
        body1.inv_inertia_diagonal = body2.inv_inertia_diagonal = {0.f, 0.f, 0.f};
        break;
      default: break;
    }
    bodies_->Set(world, 0, body1);
    bodies_->Set(world, 1, body2);
    const std::size_t block = world / kLaneWidth, lane = world % kLaneWidth;
    DualAxisGeometry& g = (*geometry_)[block];
    SetLaneVec3(g.r1_plus_u, lane, r1_plus_u);
    SetLaneVec3(g.r2, lane, r2);
    SetLaneVec3(g.n1, lane, n1);
    SetLaneVec3(g.n2, lane, n2);
    SetLaneVec3((*separation_)[block], lane, random.Vector(0.2));
    SetTotalLambda(*parts_, world,
                   {float(random.Uniform(-1, 1)), float(random.Uniform(-1, 1))});
  }

  const DualAxisGeometry& G(std::size_t world) const { return (*geometry_)[Block(world)]; }
  Vec3d R1PlusU(std::size_t w) const { return LaneVec3(G(w).r1_plus_u, Lane(w)); }
  Vec3d R2(std::size_t w) const { return LaneVec3(G(w).r2, Lane(w)); }
  Vec3d N1(std::size_t w) const { return LaneVec3(G(w).n1, Lane(w)); }
  Vec3d N2(std::size_t w) const { return LaneVec3(G(w).n2, Lane(w)); }
  Vec3d Separation(std::size_t w) const { return LaneVec3((*separation_)[Block(w)], Lane(w)); }
  Vec2d Lambda(std::size_t world) const {
    const auto l = GetTotalLambda(*parts_, world);
    return Vec2d(l[0], l[1]);
  }
  // cond(K) of the reference's effective mass; 1 for deactivated lanes.
  double ConditionOf(std::size_t world) const {
    const Mat22d& k_inv = reference_[world].EffectiveMass();
    return k_inv.isZero(0.0) ? 1.0 : Condition<2>(k_inv);
  }

  void CalculateProperties() {
    for (std::size_t block = 0; block < blocks(); ++block) {
      kernels_->calculate_properties(Pair(block), (*geometry_)[block],
                                               (*parts_)[block]);
    }
    for (std::size_t w = 0; w < worlds(); ++w) {
      reference_[w].SetTotalLambda(Lambda(w));
      reference_[w].CalculateConstraintProperties(Body(w, 0), R1PlusU(w), Body(w, 1),
                                                  R2(w), N1(w), N2(w));
    }
  }

  void DeactivateFlaggedLanes() {
    DeactivateWorlds(*parts_, reference_,
                     [](std::size_t w) { return KindOfWorld(w) == LaneKind::kDeactivatedByFlag; });
  }

  // Runs one velocity-changing verb on kernel and reference, from the same
  // body state and impulse, and compares every lane. Returns per-block "any
  // lane applied" from the kernel next to the reference's.
  PartHooks Hooks() {
    return MakePartHooks(reference_, [this](std::size_t w) { return Lambda(w); },
                         [this](std::size_t w) { return ConditionOf(w); });
  }

  template <class KernelVerb, class ReferenceVerb>
  void CompareVerb(const char* label, KernelVerb kernel_verb, ReferenceVerb reference_verb) {
    CompareVerbOnEveryLane(label, *bodies_, Hooks(), kernel_verb, reference_verb);
  }

  void WarmStart(float ratio) {
    CompareVerb(
        "warm start",
        [&](std::size_t block) {
          kernels_->warm_start(Pair(block), (*geometry_)[block],
                                         (*parts_)[block], ratio);
          return false;
        },
        [&](std::size_t w, RefBody& b1, RefBody& b2) {
          reference_[w].WarmStart(b1, b2, N1(w), N2(w), ratio);
          return false;
        });
  }

  void SolveVelocity() {
    CompareVerb(
        "velocity solve",
        [&](std::size_t block) {
          return kernels_->solve_velocity(Pair(block), (*geometry_)[block],
                                                    (*parts_)[block]);
        },
        [&](std::size_t w, RefBody& b1, RefBody& b2) {
          return reference_[w].SolveVelocityConstraint(b1, b2, N1(w), N2(w));
        });
  }

  void SolvePosition(float baumgarte) {
    CompareVerb(
        "position solve",
        [&](std::size_t block) {
          return kernels_->solve_position(Pair(block), (*geometry_)[block],
                                                    (*separation_)[block],
                                                    (*parts_)[block], baumgarte);
        },
        [&](std::size_t w, RefBody& b1, RefBody& b2) {
          return reference_[w].SolvePositionConstraint(b1, b2, Separation(w), N1(w),
                                                       N2(w), baumgarte);
        });
  }

  std::unique_ptr<PartBlocks<DualAxisGeometry>> geometry_;
  std::unique_ptr<PartBlocks<DualAxisLanes>> parts_;
  std::unique_ptr<PartBlocks<Vec3Lanes>> separation_;
  std::vector<RefDualAxis> reference_;
};

TEST_P(DualAxisTest, CalculatePropertiesMatchesReference) {
  CalculateProperties();
  LaneFlags active;
  for (std::size_t w = 0; w < worlds(); ++w) {
    const DualAxisLanes& part = (*parts_)[Block(w)];
    const RefDualAxis& ref = reference_[w];
    const std::size_t lane = Lane(w);
    const double lever = std::max(R1PlusU(w).norm(), R2(w).norm());
    ExpectVec3Near(LaneVec3(part.r1_plus_u_x_n1, lane), ref.R1PlusUxN(0),
                   Tolerance(lever), WorldLabel(w, "(r1+u) x n1"));
    ExpectVec3Near(LaneVec3(part.r1_plus_u_x_n2, lane), ref.R1PlusUxN(1),
                   Tolerance(lever), WorldLabel(w, "(r1+u) x n2"));
    ExpectVec3Near(LaneVec3(part.r2_x_n1, lane), ref.R2xN(0), Tolerance(lever),
                   WorldLabel(w, "r2 x n1"));
    ExpectVec3Near(LaneVec3(part.r2_x_n2, lane), ref.R2xN(1), Tolerance(lever),
                   WorldLabel(w, "r2 x n2"));
    // I^-1 (lever x n): scale = |I^-1| |lever|, |I^-1| <= max diagonal entry.
    const double inertia1 = Body(w, 0).inv_inertia_diagonal.maxCoeff() * lever;
    const double inertia2 = Body(w, 1).inv_inertia_diagonal.maxCoeff() * lever;
    ExpectVec3Near(LaneVec3(part.inv_i1_r1_plus_u_x_n1, lane), ref.InvI1R1PlusUxN(0),
                   Tolerance(inertia1), WorldLabel(w, "I1^-1 (r1+u) x n1"));
    ExpectVec3Near(LaneVec3(part.inv_i1_r1_plus_u_x_n2, lane), ref.InvI1R1PlusUxN(1),
                   Tolerance(inertia1), WorldLabel(w, "I1^-1 (r1+u) x n2"));
    ExpectVec3Near(LaneVec3(part.inv_i2_r2_x_n1, lane), ref.InvI2R2xN(0),
                   Tolerance(inertia2), WorldLabel(w, "I2^-1 r2 x n1"));
    ExpectVec3Near(LaneVec3(part.inv_i2_r2_x_n2, lane), ref.InvI2R2xN(1),
                   Tolerance(inertia2), WorldLabel(w, "I2^-1 r2 x n2"));
    const Mat22d& k_inv = ref.EffectiveMass();
    const double k_tolerance = Tolerance(k_inv.cwiseAbs().maxCoeff(), ConditionOf(w));
    EXPECT_NEAR(part.effective_mass.xx[lane], k_inv(0, 0), k_tolerance) << "K^-1 of world " << w;
    EXPECT_NEAR(part.effective_mass.xy[lane], k_inv(0, 1), k_tolerance) << "K^-1 of world " << w;
    EXPECT_NEAR(part.effective_mass.yy[lane], k_inv(1, 1), k_tolerance) << "K^-1 of world " << w;
    // Singular lanes are deactivated: exact zeros, impulse cleared.
    const bool singular = KindOfWorld(w) == LaneKind::kSingular ||
                          (bodies_->motion_type(0) != MotionType::kDynamic &&
                           bodies_->motion_type(1) != MotionType::kDynamic);
    if (lane == 0) kernels_->is_active(part, active);
    EXPECT_EQ(active[lane] != 0.0f, ref.IsActive()) << "IsActive of world " << w;
    EXPECT_EQ(active[lane] == 0.0f, singular) << "IsActive of world " << w;
    if (singular) {
      EXPECT_EQ(Lambda(w), Vec2d::Zero()) << "singular world " << w << " keeps an impulse";
    }
  }
}

TEST_P(DualAxisTest, WarmStartScalesAndAppliesImpulse) {
  CalculateProperties();
  WarmStart(0.75f);
}

TEST_P(DualAxisTest, WarmStartWithRatioZeroAppliesNothing) {
  CalculateProperties();
  const BodyBlocks before = *bodies_;
  for (std::size_t block = 0; block < blocks(); ++block) {
    kernels_->warm_start(Pair(block), (*geometry_)[block], (*parts_)[block], 0.0f);
  }
  for (std::size_t w = 0; w < worlds(); ++w) {
    EXPECT_EQ(Lambda(w), Vec2d::Zero()) << "world " << w;
  }
  ExpectBodiesUnchanged(before, [](std::size_t, std::size_t) { return true; },
                        "warm start with ratio 0");
}

TEST_P(DualAxisTest, VelocitySolveMatchesReferenceAndZeroesVelocityError) {
  CalculateProperties();
  DeactivateFlaggedLanes();
  WarmStart(1.0f);
  for (int iteration = 0; iteration < 3; ++iteration) SolveVelocity();
  // Invariant: one solve of an exactly inverted 2x2 system leaves J v = 0 (to
  // rounding, amplified by cond(K)) in every active lane.
  for (std::size_t w = 0; w < worlds(); ++w) {
    if (!reference_[w].IsActive()) continue;
    const RefBody b1 = Body(w, 0), b2 = Body(w, 1);
    const Vec2d jv = reference::DualAxisVelocityError(b1, b2, R1PlusU(w), R2(w), N1(w), N2(w));
    const double lever = 1.0 + std::max(R1PlusU(w).norm(), R2(w).norm());
    const double speed = std::max({b1.linear_velocity.norm(), b1.angular_velocity.norm(),
                                   b2.linear_velocity.norm(), b2.angular_velocity.norm()});
    EXPECT_LE(jv.cwiseAbs().maxCoeff(), Tolerance(lever * speed, ConditionOf(w)))
        << "J v after the velocity solve of world " << w;
  }
}

TEST_P(DualAxisTest, PositionSolveMatchesReference) {
  CalculateProperties();
  DeactivateFlaggedLanes();
  SolvePosition(0.2f);
}

TEST_P(DualAxisTest, DeactivatedAndSingularLanesStayFiniteAndApplyNothing) {
  CalculateProperties();
  DeactivateFlaggedLanes();
  const BodyBlocks before = *bodies_;
  for (std::size_t block = 0; block < blocks(); ++block) {
    kernels_->warm_start(Pair(block), (*geometry_)[block], (*parts_)[block], 1.0f);
    kernels_->solve_velocity(Pair(block), (*geometry_)[block], (*parts_)[block]);
    kernels_->solve_position(Pair(block), (*geometry_)[block],
                                       (*separation_)[block], (*parts_)[block], 0.2f);
  }
  for (std::size_t w = 0; w < worlds(); ++w) {
    if (!reference_[w].IsActive()) {
      EXPECT_EQ(Lambda(w), Vec2d::Zero()) << "inactive world " << w;
    }
  }
  ExpectBodiesUnchanged(
      before, [&](std::size_t w, std::size_t) { return !reference_[w].IsActive(); },
      "inactive lane");
}

// The position phase's verb against calculate_properties + solve_position,
// with every fourth lane put on its rail (separation 0, so C == 0 exactly)
// with immovable bodies (K singular since the setup) and every lane holding
// an impulse: a lane with an error gets the same bits either way (a
// singular one has its impulse cleared, as Jolt's recompute clears it); a
// lane on its rail is left exactly as it is, impulse included
// (docs/stepping.md, "Work skipped where no world of a block needs it").
TEST_P(DualAxisTest, PositionVerbLeavesLanesOnTheRailAsTheyAre) {
  CalculateProperties();
  const auto on_rail = [](std::size_t w) { return w % 4 == 1; };
  for (std::size_t w = 0; w < worlds(); ++w) {
    if (on_rail(w)) {
      SetLaneVec3((*separation_)[Block(w)], Lane(w), Vec3d::Zero());
      for (std::size_t body = 0; body < 2; ++body) {
        BodyState state = bodies_->Get(w, body);
        state.inv_mass = 0.0f;
        state.inv_inertia_diagonal = {0.0f, 0.0f, 0.0f};
        bodies_->Set(w, body, state);
      }
    }
    SetTotalLambda(*parts_, w, {0.5f, float(w) + 1.0f});
  }
  const BodyBlocks start_bodies = *bodies_;
  const PartBlocks<DualAxisLanes> start_parts = *parts_;
  for (std::size_t block = 0; block < blocks(); ++block) {
    kernels_->calculate_properties(Pair(block), (*geometry_)[block], (*parts_)[block]);
    kernels_->solve_position(Pair(block), (*geometry_)[block], (*separation_)[block],
                             (*parts_)[block], 0.2f);
  }
  const BodyBlocks separate_bodies = *bodies_;
  const PartBlocks<DualAxisLanes> separate_parts = *parts_;
  *bodies_ = start_bodies;
  *parts_ = start_parts;
  for (std::size_t block = 0; block < blocks(); ++block) {
    kernels_->recompute_and_solve_position(Pair(block), (*geometry_)[block],
                                           (*separation_)[block], (*parts_)[block], 0.2f);
  }
  ExpectBodiesUnchanged(start_bodies, [&](std::size_t w, std::size_t) { return on_rail(w); },
                        "lane on its rail (C == 0)");
  ExpectBodiesUnchanged(separate_bodies, [&](std::size_t w, std::size_t) { return !on_rail(w); },
                        "lane with an error, against calculate_properties + solve_position");
  for (std::size_t w = 0; w < worlds(); ++w) {
    const auto got = GetTotalLambda(*parts_, w);
    const auto want = GetTotalLambda(on_rail(w) ? start_parts : separate_parts, w);
    EXPECT_TRUE(BitEqual(&got, &want, sizeof got)) << "impulse of world " << w;
    if (on_rail(w)) {
      EXPECT_NE(got[1], 0.0f) << "world " << w << " on its rail lost its impulse";
    }
  }
}

TEST_P(DualAxisTest, GetSetSaveRestoreOfAccumulatedImpulse) {
  CalculateProperties();
  for (std::size_t w = 0; w < worlds(); ++w) {
    const std::array<float, 2> value{float(w) + 0.25f, -float(w)};
    SetTotalLambda(*parts_, w, value);
    EXPECT_EQ(GetTotalLambda(*parts_, w), value);
  }
  WarmStart(1.0f);
  const auto saved = SavePartState(*parts_);
  const auto lambdas_at_save = [&] {
    std::vector<std::array<float, 2>> l;
    for (std::size_t w = 0; w < worlds(); ++w) l.push_back(GetTotalLambda(*parts_, w));
    return l;
  }();
  SolveVelocity();  // changes the impulses
  RestorePartState(*parts_, saved);
  for (std::size_t w = 0; w < worlds(); ++w) {
    const auto restored = GetTotalLambda(*parts_, w);
    EXPECT_TRUE(BitEqual(&restored, &lambdas_at_save[w], sizeof(restored))) << "world " << w;
  }
}

std::vector<PartCase<DualAxisKernels>> AllCases() {
  static const std::vector<std::pair<MotionType, MotionType>> pairings = {
      {MotionType::kDynamic, MotionType::kDynamic},
      {MotionType::kDynamic, MotionType::kStatic},
      {MotionType::kStatic, MotionType::kDynamic},
      {MotionType::kKinematic, MotionType::kDynamic},
      {MotionType::kDynamic, MotionType::kKinematic},
      {MotionType::kKinematic, MotionType::kStatic},
  };
  return AllPartCases<DualAxisKernels>(pairings);
}

INSTANTIATE_TEST_SUITE_P(EveryTarget, DualAxisTest, ::testing::ValuesIn(AllCases()),
                         PartCaseName<DualAxisKernels>);

}  // namespace
}  // namespace manyworlds::testing
