// PointConstraintPart kernels, every verb, every lane against the scalar
// reference, on every Highway target this CPU supports, for 1, 7, 16 and 1000
// worlds and every motion-type pairing of the two bodies.
#include <gtest/gtest.h>

#include <array>
#include <memory>
#include <vector>

#include "batch/part_binding.h"
#include "batch/part_state.h"
#include "batch/world_blocks.h"
#include "kernels/point.h"
#include "reference/point_part.h"
#include "tests/three_row_test_support.h"
#include "tests/test_support.h"

namespace manyworlds::testing {
namespace {

using RefPoint = reference::PointPart<double>;

// Regular lanes; lanes with the joint exactly closed (exact rotations and
// dyadic anchors and positions, so C == 0 exactly); lanes whose K has a
// condition number ~1e3..1e4 (tiny inverse masses and lever arms of both
// bodies along one world line, so K's only small eigenvalue is m1^-1 + m2^-1
// along it); exactly singular lanes (immovable dynamic bodies: K == 0); lanes
// deactivated explicitly.
enum class LaneKind { kRegular, kAtRest, kNearSingular, kSingular, kDeactivatedByFlag };

LaneKind KindOfWorld(std::size_t world) {
  switch (world % 8) {
    case 2: return LaneKind::kAtRest;
    case 3: return LaneKind::kNearSingular;
    case 5: return LaneKind::kSingular;
    case 6: return LaneKind::kDeactivatedByFlag;
    default: return LaneKind::kRegular;
  }
}

class PointTest : public PartTestBase<PointKernels> {
 protected:
  void SetUp() override {
    SetUpBodies("ball_joint", PartKind::kPoint);
    geometry_ = std::make_unique<PartBlocks<PointGeometry>>(blocks());
    parts_ = std::make_unique<PartBlocks<PointLanes>>(blocks());
    reference_.resize(worlds());
    for (std::size_t world = 0; world < worlds(); ++world) FillWorld(world);
  }

  // Random, different in every world; the reference reads back the float
  // values the blocks hold, so both start from identical inputs. Body 2 sits
  // where the joint is nearly closed (separation up to 0.2), as in a running
  // simulation, so that position steps are small corrections.
  void FillWorld(std::size_t world) {
    Random random(2718281u + 7919u * unsigned(world));
    BodyState body1 = RandomBodyState(random);
    BodyState body2 = RandomBodyState(random);
    Vec3d r1_local = random.Vector(2.0), r2_local = random.Vector(2.0);
    Vec3d gap = random.Vector(0.2);
    if (KindOfWorld(world) == LaneKind::kAtRest) {
      auto dyadic = [](const Vec3d& v) { return Vec3d((8.0 * v).array().round() / 8.0); };
      body1.rotation = ToFloat4(ExactRotation(random));
      body2.rotation = ToFloat4(ExactRotation(random));
      body1.position = {float(dyadic(ToVec3d(body1.position)).x()),
                        float(dyadic(ToVec3d(body1.position)).y()),
                        float(dyadic(ToVec3d(body1.position)).z())};
      r1_local = dyadic(r1_local);
      r2_local = dyadic(r2_local);
      gap.setZero();
    }
    const Quatd q1 = ToQuatd(body1.rotation), q2 = ToQuatd(body2.rotation);
    switch (KindOfWorld(world)) {
      case LaneKind::kNearSingular: {
        body1.inv_mass = body2.inv_mass = 1e-3f;
        const Vec3d line = random.UnitVector();
        r1_local = q1.conjugate() * (1.5 * line + random.Vector(1e-3));
        r2_local = q2.conjugate() * (-0.8 * line + random.Vector(1e-3));
        break;
      }
      case LaneKind::kSingular:
        body1.inv_mass = body2.inv_mass = 0.0f;
        body1.inv_inertia_diagonal = body2.inv_inertia_diagonal = {0.f, 0.f, 0.f};
        break;
      default: break;
    }
    r1_local = ToFloat(r1_local);
    r2_local = ToFloat(r2_local);
    const Vec3d x2 = ToVec3d(body1.position) + q1 * r1_local - q2 * r2_local + gap;
    body2.position = {float(x2.x()), float(x2.y()), float(x2.z())};
    bodies_->Set(world, 0, body1);
    bodies_->Set(world, 1, body2);
    PointGeometry& g = (*geometry_)[Block(world)];
    SetLaneVec3(g.r1_local, Lane(world), r1_local);
    SetLaneVec3(g.r2_local, Lane(world), r2_local);
    SetTotalLambda(*parts_, world,
                   {float(random.Uniform(-1, 1)), float(random.Uniform(-1, 1)),
                    float(random.Uniform(-1, 1))});
  }

  Vec3d R1Local(std::size_t w) const { return LaneVec3((*geometry_)[Block(w)].r1_local, Lane(w)); }
  Vec3d R2Local(std::size_t w) const { return LaneVec3((*geometry_)[Block(w)].r2_local, Lane(w)); }
  Vec3d Lambda(std::size_t world) const {
    const auto l = GetTotalLambda(*parts_, world);
    return Vec3d(l[0], l[1], l[2]);
  }
  // cond(K) of the reference's effective mass; 1 for deactivated lanes.
  double ConditionOf(std::size_t world) const {
    const Mat33d& k_inv = reference_[world].EffectiveMass();
    return k_inv.isZero(0.0) ? 1.0 : Condition<3>(k_inv);
  }

  void CalculateProperties() {
    for (std::size_t block = 0; block < blocks(); ++block) {
      kernels_->calculate_properties(Pair(block), (*geometry_)[block], (*parts_)[block]);
    }
    for (std::size_t w = 0; w < worlds(); ++w) {
      reference_[w].SetTotalLambda(Lambda(w));
      reference_[w].CalculateConstraintProperties(Body(w, 0), R1Local(w), Body(w, 1),
                                                  R2Local(w));
    }
  }

  void DeactivateFlaggedLanes() {
    DeactivateWorlds(*parts_, reference_,
                     [](std::size_t w) { return KindOfWorld(w) == LaneKind::kDeactivatedByFlag; });
  }

  PartHooks Hooks() {
    return MakePartHooks(reference_, [this](std::size_t w) { return Lambda(w); },
                         [this](std::size_t w) { return ConditionOf(w); });
  }

  void WarmStart(float ratio) {
    CompareVerbOnEveryLane(
        "warm start", *bodies_, Hooks(),
        [&](std::size_t block) {
          kernels_->warm_start(Pair(block), (*parts_)[block], ratio);
          return false;
        },
        [&](std::size_t w, RefBody& b1, RefBody& b2) {
          reference_[w].WarmStart(b1, b2, ratio);
          return false;
        });
  }

  void SolveVelocity() {
    CompareVerbOnEveryLane(
        "velocity solve", *bodies_, Hooks(),
        [&](std::size_t block) {
          return kernels_->solve_velocity(Pair(block), (*parts_)[block]);
        },
        [&](std::size_t w, RefBody& b1, RefBody& b2) {
          return reference_[w].SolveVelocityConstraint(b1, b2);
        });
  }

  void SolvePosition(float baumgarte) {
    CompareVerbOnEveryLane(
        "position solve", *bodies_, Hooks(),
        [&](std::size_t block) {
          return kernels_->solve_position(Pair(block), (*parts_)[block], baumgarte);
        },
        [&](std::size_t w, RefBody& b1, RefBody& b2) {
          return reference_[w].SolvePositionConstraint(b1, b2, baumgarte);
        });
  }

  void ExpectZeroVelocityError(const std::vector<double>& speed, const char* when);

  bool Singular(std::size_t w) const {
    return KindOfWorld(w) == LaneKind::kSingular ||
           (bodies_->motion_type(0) != MotionType::kDynamic &&
            bodies_->motion_type(1) != MotionType::kDynamic);
  }

  std::unique_ptr<PartBlocks<PointGeometry>> geometry_;
  std::unique_ptr<PartBlocks<PointLanes>> parts_;
  std::vector<RefPoint> reference_;
};

TEST_P(PointTest, CalculatePropertiesMatchesReference) {
  CalculateProperties();
  LaneFlags active;
  for (std::size_t w = 0; w < worlds(); ++w) {
    const PointLanes& part = (*parts_)[Block(w)];
    const RefPoint& ref = reference_[w];
    const std::size_t lane = Lane(w);
    const double lever = std::max(R1Local(w).norm(), R2Local(w).norm());
    ExpectVec3Near(LaneVec3(part.r1, lane), ref.R1(), Tolerance(lever), WorldLabel(w, "r1"));
    ExpectVec3Near(LaneVec3(part.r2, lane), ref.R2(), Tolerance(lever), WorldLabel(w, "r2"));
    // I^-1 [r]x: scale |I^-1| |r|, |I^-1| <= the largest diagonal entry.
    const double inertia1 = Body(w, 0).inv_inertia_diagonal.maxCoeff() * lever;
    const double inertia2 = Body(w, 1).inv_inertia_diagonal.maxCoeff() * lever;
    ExpectMat33Near(LaneMat33(part.inv_i1_r1_cross, lane), ref.InvI1R1x(),
                    Tolerance(inertia1), WorldLabel(w, "I1^-1 [r1]x"));
    ExpectMat33Near(LaneMat33(part.inv_i2_r2_cross, lane), ref.InvI2R2x(),
                    Tolerance(inertia2), WorldLabel(w, "I2^-1 [r2]x"));
    // K^-1 is stored symmetric: each stored entry against both mirrored ones.
    const Mat33d& k_inv = ref.EffectiveMass();
    ExpectMat33Near(LaneSym33(part.effective_mass, lane), k_inv,
                    Tolerance(k_inv.cwiseAbs().maxCoeff(), ConditionOf(w)),
                    WorldLabel(w, "K^-1"));
    // Singular lanes are deactivated: exact zeros, impulse cleared.
    if (lane == 0) kernels_->is_active(part, active);
    EXPECT_EQ(active[lane] != 0.0f, ref.IsActive()) << "IsActive of world " << w;
    EXPECT_EQ(active[lane] == 0.0f, Singular(w)) << "IsActive of world " << w;
    if (Singular(w)) {
      EXPECT_EQ(Lambda(w), Vec3d::Zero()) << "singular world " << w << " keeps an impulse";
    }
  }
}

TEST_P(PointTest, WarmStartScalesAndAppliesImpulse) {
  CalculateProperties();
  WarmStart(0.75f);
}

TEST_P(PointTest, WarmStartWithRatioZeroAppliesNothing) {
  CalculateProperties();
  const BodyBlocks before = *bodies_;
  for (std::size_t block = 0; block < blocks(); ++block) {
    kernels_->warm_start(Pair(block), (*parts_)[block], 0.0f);
  }
  for (std::size_t w = 0; w < worlds(); ++w) {
    EXPECT_EQ(Lambda(w), Vec3d::Zero()) << "world " << w;
  }
  ExpectBodiesUnchanged(before, [](std::size_t, std::size_t) { return true; },
                        "warm start with ratio 0");
}

// Invariant: one solve of an exactly inverted 3x3 system leaves J v = 0 (to
// rounding, amplified by cond(K)) in every active lane. The rounding is
// relative to the anchor velocities the solve cancelled, `speed`.
void PointTest::ExpectZeroVelocityError(const std::vector<double>& speed, const char* when) {
  for (std::size_t w = 0; w < worlds(); ++w) {
    if (!reference_[w].IsActive()) continue;
    const Vec3d jv = reference::PointVelocityError(Body(w, 0), reference_[w].R1(), Body(w, 1),
                                                   reference_[w].R2());
    EXPECT_LE(jv.cwiseAbs().maxCoeff(), Tolerance(speed[w], ConditionOf(w)))
        << "J v " << when << " of world " << w;
  }
}

// Only the first iteration is compared with the reference: later ones solve
// for the rounding residual of the first, whose float and double values
// differ by the rounding itself (and a float lane may reach exactly zero
// where the double one does not, so "any lane applied" would differ too).
TEST_P(PointTest, VelocitySolveMatchesReferenceAndZeroesVelocityError) {
  CalculateProperties();
  DeactivateFlaggedLanes();
  WarmStart(1.0f);
  std::vector<double> speed(worlds());
  for (std::size_t w = 0; w < worlds(); ++w) {
    const RefBody b1 = Body(w, 0), b2 = Body(w, 1);
    const double lever = 1.0 + std::max(R1Local(w).norm(), R2Local(w).norm());
    speed[w] = std::max({b1.LinearVelocity().norm(), b2.LinearVelocity().norm(),
                         lever * b1.AngularVelocity().norm(),
                         lever * b2.AngularVelocity().norm()});
  }
  SolveVelocity();
  ExpectZeroVelocityError(speed, "after the velocity solve");
  for (std::size_t block = 0; block < blocks(); ++block) {
    kernels_->solve_velocity(Pair(block), (*parts_)[block]);
    kernels_->solve_velocity(Pair(block), (*parts_)[block]);
  }
  ExpectZeroVelocityError(speed, "after two more velocity solves");
}

TEST_P(PointTest, PositionSolveMatchesReference) {
  CalculateProperties();
  DeactivateFlaggedLanes();
  SolvePosition(0.2f);
}

TEST_P(PointTest, DeactivatedAndSingularLanesStayFiniteAndApplyNothing) {
  CalculateProperties();
  DeactivateFlaggedLanes();
  const BodyBlocks before = *bodies_;
  for (std::size_t block = 0; block < blocks(); ++block) {
    kernels_->warm_start(Pair(block), (*parts_)[block], 1.0f);
    kernels_->solve_velocity(Pair(block), (*parts_)[block]);
    kernels_->solve_position(Pair(block), (*parts_)[block], 0.2f);
  }
  for (std::size_t w = 0; w < worlds(); ++w) {
    if (!reference_[w].IsActive()) {
      EXPECT_EQ(Lambda(w), Vec3d::Zero()) << "inactive world " << w;
    }
  }
  ExpectBodiesUnchanged(
      before, [&](std::size_t w, std::size_t) { return !reference_[w].IsActive(); },
      "inactive lane");
}

TEST_P(PointTest, PositionSolveAtRestMovesNothing) {
  CalculateProperties();
  const BodyBlocks before = *bodies_;
  for (std::size_t block = 0; block < blocks(); ++block) {
    kernels_->solve_position(Pair(block), (*parts_)[block], 0.2f);
  }
  ExpectBodiesUnchanged(
      before, [&](std::size_t w, std::size_t) { return KindOfWorld(w) == LaneKind::kAtRest; },
      "lane at rest (C == 0)");
}

// The position phase's verb against calculate_properties + solve_position,
// after the bodies of the lanes at rest (C == 0 exactly) have become
// immovable since the setup (K singular now) and every lane holds an
// impulse: a lane with an error gets the same bits either way (a singular
// one has its impulse cleared, as Jolt's recompute clears it); a lane at
// rest is left exactly as it is, impulse included (docs/stepping.md, "Work
// skipped where no world of a block needs it").
TEST_P(PointTest, PositionVerbLeavesLanesAtRestAsTheyAre) {
  CalculateProperties();
  const auto at_rest = [](std::size_t w) { return KindOfWorld(w) == LaneKind::kAtRest; };
  for (std::size_t w = 0; w < worlds(); ++w) {
    for (std::size_t body = 0; body < 2 && at_rest(w); ++body) {
      BodyState state = bodies_->Get(w, body);
      state.inv_mass = 0.0f;
      state.inv_inertia_diagonal = {0.0f, 0.0f, 0.0f};
      bodies_->Set(w, body, state);
    }
    SetTotalLambda(*parts_, w, {0.5f, -0.25f, float(w) + 1.0f});
  }
  const BodyBlocks start_bodies = *bodies_;
  const PartBlocks<PointLanes> start_parts = *parts_;
  for (std::size_t block = 0; block < blocks(); ++block) {
    kernels_->calculate_properties(Pair(block), (*geometry_)[block], (*parts_)[block]);
    kernels_->solve_position(Pair(block), (*parts_)[block], 0.2f);
  }
  const BodyBlocks separate_bodies = *bodies_;
  const PartBlocks<PointLanes> separate_parts = *parts_;
  *bodies_ = start_bodies;
  *parts_ = start_parts;
  for (std::size_t block = 0; block < blocks(); ++block) {
    kernels_->recompute_and_solve_position(Pair(block), (*geometry_)[block], (*parts_)[block],
                                           0.2f);
  }
  ExpectBodiesUnchanged(start_bodies, [&](std::size_t w, std::size_t) { return at_rest(w); },
                        "lane at rest (C == 0)");
  ExpectBodiesUnchanged(separate_bodies, [&](std::size_t w, std::size_t) { return !at_rest(w); },
                        "lane with an error, against calculate_properties + solve_position");
  for (std::size_t w = 0; w < worlds(); ++w) {
    const auto got = GetTotalLambda(*parts_, w);
    const auto want = GetTotalLambda(at_rest(w) ? start_parts : separate_parts, w);
    EXPECT_TRUE(BitEqual(&got, &want, sizeof got)) << "impulse of world " << w;
    if (at_rest(w)) {
      EXPECT_NE(got[2], 0.0f) << "world " << w << " at rest lost its impulse";
    }
  }
}

TEST_P(PointTest, GetSetSaveRestoreOfAccumulatedImpulse) {
  CalculateProperties();
  for (std::size_t w = 0; w < worlds(); ++w) {
    const std::array<float, 3> value{float(w) + 0.25f, -float(w), 0.5f * float(w)};
    SetTotalLambda(*parts_, w, value);
    EXPECT_EQ(GetTotalLambda(*parts_, w), value);
  }
  WarmStart(1.0f);
  const auto saved = SavePartState(*parts_);
  std::vector<std::array<float, 3>> lambdas_at_save;
  for (std::size_t w = 0; w < worlds(); ++w) lambdas_at_save.push_back(GetTotalLambda(*parts_, w));
  SolveVelocity();  // changes the impulses
  RestorePartState(*parts_, saved);
  for (std::size_t w = 0; w < worlds(); ++w) {
    const auto restored = GetTotalLambda(*parts_, w);
    EXPECT_TRUE(BitEqual(&restored, &lambdas_at_save[w], sizeof(restored))) << "world " << w;
  }
}

std::vector<PartCase<PointKernels>> AllCases() {
  static const std::vector<std::pair<MotionType, MotionType>> pairings = {
      {MotionType::kDynamic, MotionType::kDynamic},
      {MotionType::kDynamic, MotionType::kStatic},
      {MotionType::kStatic, MotionType::kDynamic},
      {MotionType::kKinematic, MotionType::kDynamic},
      {MotionType::kDynamic, MotionType::kKinematic},
      {MotionType::kKinematic, MotionType::kStatic},
  };
  return AllPartCases<PointKernels>(pairings);
}

INSTANTIATE_TEST_SUITE_P(EveryTarget, PointTest, ::testing::ValuesIn(AllCases()),
                         PartCaseName<PointKernels>);

}  // namespace
}  // namespace manyworlds::testing
