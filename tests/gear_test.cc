// GearConstraintPart kernels, every verb, every lane against the scalar
// reference, on every Highway target this CPU supports, for 1, 7, 16 and 1000
// worlds and every allowed motion-type pairing (static is refused). Plus the
// two properties of applying J^T lambda exactly, where we differ from Jolt
// (spec 2.10): gear 2 receives r times gear 1's angular impulse, and one
// velocity solve is the mass-weighted projection onto J v = 0.
#include <gtest/gtest.h>

#include <algorithm>
#include <memory>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include "batch/part_binding.h"
#include "batch/part_state.h"
#include "batch/world_blocks.h"
#include "kernels/gear.h"
#include "manyworlds/error.h"
#include "reference/gear_part.h"
#include "tests/test_support.h"

namespace manyworlds::testing {
namespace {

using RefGear = reference::GearPart<double>;

// Regular lanes; lanes with a tiny K (~1e-8: near-immovable gears), where
// 1/K is huge but exact to float precision since K is a scalar;
// exactly singular lanes (ratio 0 and no inertia on gear 1: K == 0); lanes
// deactivated explicitly.
enum class LaneKind { kRegular, kTinyMass, kSingular, kDeactivatedByFlag };

LaneKind KindOfWorld(std::size_t world) {
  switch (world % 8) {
    case 2: return LaneKind::kTinyMass;
    case 5: return LaneKind::kSingular;
    case 7: return LaneKind::kDeactivatedByFlag;
    default: return LaneKind::kRegular;
  }
}

class GearTest : public PartTestBase<GearKernels> {
 protected:
  void SetUp() override {
    SetUpBodies("gear", PartKind::kGear);
    const std::size_t world_count = GetParam().world_count;
    const std::size_t blocks = bodies_->block_count();
    geometry_ = std::make_unique<PartBlocks<GearGeometry>>(blocks);
    parts_ = std::make_unique<PartBlocks<GearLanes>>(blocks);
    error_ = std::make_unique<PartBlocks<LaneArray>>(blocks);
    reference_.resize(world_count);
    for (std::size_t world = 0; world < world_count; ++world) FillWorld(world);
  }

  void FillWorld(std::size_t world) {
    Random random(2718281u + 15485863u * unsigned(world));
    BodyState gear1 = RandomBodyState(random);
    BodyState gear2 = RandomBodyState(random);
    // Teeth ratios of both signs over two decades.
    double ratio = (random.Uniform(0, 1) < 0.5 ? -1 : 1) * random.LogUniform(0.1, 10.0);
    switch (KindOfWorld(world)) {
      case LaneKind::kTinyMass:
        // Both gears nearly immovable; with only gear 1 so, a tiny ratio would
        // turn gear 2 by hundreds of radians in a position step, where float
        // angles lose absolute precision whatever the kernel does.
        for (BodyState* gear : {&gear1, &gear2}) {
          for (float& d : gear->inv_inertia_diagonal) d *= 1e-8f;
        }
        break;
      case LaneKind::kSingular:
        gear1.inv_inertia_diagonal = {0.f, 0.f, 0.f};
        ratio = 0.0;
        break;
      default: break;
    }
    bodies_->Set(world, 0, gear1);
    bodies_->Set(world, 1, gear2);
    const std::size_t block = world / kLaneWidth, lane = world % kLaneWidth;
    GearGeometry& g = (*geometry_)[block];
    SetLaneVec3(g.hinge_axis1, lane, random.UnitVector());
    SetLaneVec3(g.hinge_axis2, lane, random.UnitVector());
    g.ratio[lane] = float(ratio);
    (*error_)[block][lane] = float(random.Uniform(-0.3, 0.3));
    SetTotalLambda(*parts_, world, float(random.Uniform(-1, 1)));
  }

  const GearGeometry& G(std::size_t w) const { return (*geometry_)[Block(w)]; }
  Vec3d Axis1(std::size_t w) const { return LaneVec3(G(w).hinge_axis1, Lane(w)); }
  Vec3d Axis2(std::size_t w) const { return LaneVec3(G(w).hinge_axis2, Lane(w)); }
  double Ratio(std::size_t w) const { return G(w).ratio[Lane(w)]; }
  double Error(std::size_t w) const { return (*error_)[Block(w)][Lane(w)]; }
  double Lambda(std::size_t world) const { return GetTotalLambda(*parts_, world); }

  void CalculateProperties() {
    for (std::size_t block = 0; block < blocks(); ++block) {
      kernels_->calculate_properties(Pair(block), (*geometry_)[block], (*parts_)[block]);
    }
    for (std::size_t w = 0; w < worlds(); ++w) {
      reference_[w].SetTotalLambda(Lambda(w));
      reference_[w].CalculateConstraintProperties(Body(w, 0), Axis1(w), Body(w, 1), Axis2(w),
                                                  Ratio(w));
    }
  }

  void DeactivateFlaggedLanes() {
    DeactivateWorlds(*parts_, reference_,
                     [](std::size_t w) { return KindOfWorld(w) == LaneKind::kDeactivatedByFlag; });
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
          kernels_->warm_start(Pair(block), (*parts_)[block], ratio);
          return false;
        },
        [&](std::size_t w, RefBody& b1, RefBody& b2) {
          reference_[w].WarmStart(b1, b2, ratio);
          return false;
        });
  }

  // J v = a.w1 + r b.w2; when the two terms nearly cancel, its float rounding
  // relative to J v grows by (|w1| + |r||w2|) / |J v|, and dL = -J v / K
  // inherits that. Used as the condition of a velocity solve.
  double VelocityErrorCancellation(std::size_t w) const {
    const RefBody b1 = Body(w, 0), b2 = Body(w, 1);
    const double jv = reference::GearVelocityError(b1, b2, Axis1(w), Axis2(w), Ratio(w));
    const double terms =
        b1.angular_velocity.norm() + std::abs(Ratio(w)) * b2.angular_velocity.norm();
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
          return reference_[w].SolveVelocityConstraint(b1, b2, Axis1(w), Axis2(w), Ratio(w));
        });
  }

  void SolvePosition(float baumgarte) {
    CompareVerb(
        "position solve",
        [&](std::size_t block) {
          return kernels_->solve_position(Pair(block), (*error_)[block], (*parts_)[block],
                                          baumgarte);
        },
        [&](std::size_t w, RefBody& b1, RefBody& b2) {
          return reference_[w].SolvePositionConstraint(b1, b2, Error(w), baumgarte);
        });
  }

  // What the other parts of an island do between two solves of this one:
  // change the velocities. Without it a second solve would only see rounding
  // noise, and whether rounding noise is exactly zero in float (kernel) or in
  // double (reference) is no property of the kernel.
  void KickVelocities(unsigned seed) {
    for (std::size_t w = 0; w < worlds(); ++w) {
      Random random(seed + 7u * unsigned(w));
      for (std::size_t body = 0; body < 2; ++body) {
        BodyState state = bodies_->Get(w, body);
        for (float& component : state.angular_velocity) {
          component += float(random.Uniform(-1, 1));
        }
        bodies_->Set(w, body, state);
      }
    }
  }

  // One kernel velocity solve on every block, no reference.
  void KernelSolveVelocityOnly() {
    for (std::size_t block = 0; block < blocks(); ++block) {
      kernels_->solve_velocity(Pair(block), (*geometry_)[block], (*parts_)[block]);
    }
  }

  std::unique_ptr<PartBlocks<GearGeometry>> geometry_;
  std::unique_ptr<PartBlocks<GearLanes>> parts_;
  std::unique_ptr<PartBlocks<LaneArray>> error_;
  std::vector<RefGear> reference_;
};

TEST_P(GearTest, CalculatePropertiesMatchesReference) {
  CalculateProperties();
  LaneFlags active;
  for (std::size_t w = 0; w < worlds(); ++w) {
    const GearLanes& part = (*parts_)[Block(w)];
    const RefGear& ref = reference_[w];
    const std::size_t lane = Lane(w);
    ExpectVec3Near(LaneVec3(part.inv_i1_hinge_axis1, lane), ref.InvI1HingeAxis1(),
                   Tolerance(Body(w, 0).inv_inertia_diagonal.maxCoeff()),
                   WorldLabel(w, "I1^-1 a"));
    ExpectVec3Near(LaneVec3(part.ratio_inv_i2_hinge_axis2, lane), ref.RatioInvI2HingeAxis2(),
                   Tolerance(std::abs(Ratio(w)) * Body(w, 1).inv_inertia_diagonal.maxCoeff()),
                   WorldLabel(w, "r I2^-1 b"));
    EXPECT_NEAR(part.effective_mass[lane], ref.EffectiveMass(), Tolerance(ref.EffectiveMass()))
        << "1/K of world " << w;
    if (lane == 0) kernels_->is_active(part, active);
    EXPECT_EQ(active[lane] != 0.0f, ref.IsActive()) << "IsActive of world " << w;
    if (KindOfWorld(w) == LaneKind::kSingular) {
      EXPECT_EQ(active[lane], 0.0f) << "singular world " << w << " is active";
      EXPECT_EQ(Lambda(w), 0.0) << "singular world " << w << " keeps an impulse";
    }
  }
}

TEST_P(GearTest, WarmStartScalesAndAppliesImpulse) {
  CalculateProperties();
  WarmStart(0.75f);
}

TEST_P(GearTest, WarmStartWithRatioZeroAppliesNothing) {
  CalculateProperties();
  const BodyBlocks before = *bodies_;
  for (std::size_t block = 0; block < blocks(); ++block) {
    kernels_->warm_start(Pair(block), (*parts_)[block], 0.0f);
  }
  for (std::size_t w = 0; w < worlds(); ++w) {
    EXPECT_EQ(Lambda(w), 0.0) << "world " << w;
  }
  ExpectBodiesUnchanged(before, [](std::size_t, std::size_t) { return true; },
                        "warm start with ratio 0");
}

TEST_P(GearTest, VelocitySolveMatchesReferenceAndZeroesVelocityError) {
  CalculateProperties();
  DeactivateFlaggedLanes();
  WarmStart(1.0f);
  for (int iteration = 0; iteration < 3; ++iteration) {
    KickVelocities(99u + unsigned(iteration));
    SolveVelocity();
  }
  // Invariant: both bodies receive their J^T share (kinematic ones too), so
  // the exact scalar solve leaves J v = a.w1 + r b.w2 zero to rounding.
  for (std::size_t w = 0; w < worlds(); ++w) {
    if (!reference_[w].IsActive()) continue;
    const RefBody b1 = Body(w, 0), b2 = Body(w, 1);
    const double jv = reference::GearVelocityError(b1, b2, Axis1(w), Axis2(w), Ratio(w));
    const double scale =
        b1.angular_velocity.norm() + std::abs(Ratio(w)) * b2.angular_velocity.norm();
    EXPECT_LE(std::abs(jv), Tolerance(scale)) << "J v after the velocity solve of world " << w;
  }
}

// J^T lambda exactly: the angular impulse I dw of gear 1 is dL a and that of
// gear 2 is dL r b, so gear 2's impulse along b is r times gear 1's along a.
// Jolt's variant (no r on body 2) fails this wherever r != 1.
TEST_P(GearTest, GearTwoReceivesRatioTimesGearOnesAngularImpulse) {
  CalculateProperties();
  const BodyBlocks before = *bodies_;
  KernelSolveVelocityOnly();
  for (std::size_t w = 0; w < worlds(); ++w) {
    if (KindOfWorld(w) != LaneKind::kRegular) continue;
    const RefBody b1_before = ToReference(before.Get(w, 0), before.motion_type(0));
    const RefBody b2_before = ToReference(before.Get(w, 1), before.motion_type(1));
    const Vec3d dw1 = Body(w, 0).angular_velocity - b1_before.angular_velocity;
    const Vec3d dw2 = Body(w, 1).angular_velocity - b2_before.angular_velocity;
    const Mat33d inertia1 = b1_before.InverseInertia().inverse();
    const Mat33d inertia2 = b2_before.InverseInertia().inverse();
    const Vec3d impulse1 = inertia1 * dw1, impulse2 = inertia2 * dw2;
    const double along_a = impulse1.dot(Axis1(w));
    // dw carries the rounding of the velocities it is the difference of, and
    // I amplifies it by at most |I|.
    const double velocity_scale = b1_before.angular_velocity.norm() +
                                  b2_before.angular_velocity.norm() + dw1.norm() + dw2.norm();
    const double tolerance =
        Tolerance(std::max(inertia1.norm(), inertia2.norm()) * velocity_scale *
                  (1.0 + std::abs(Ratio(w))));
    ExpectVec3Near(impulse1, along_a * Axis1(w), tolerance,
                   WorldLabel(w, "gear 1's angular impulse (along a only)"));
    ExpectVec3Near(impulse2, Ratio(w) * along_a * Axis2(w), tolerance,
                   WorldLabel(w, "gear 2's angular impulse (r times gear 1's, along b)"));
  }
}

// The mass-weighted projection of (w1, w2) onto J v = 0: the minimiser of
// (w - w0)^T I (w - w0) subject to a.w1 + r b.w2 = 0, from its KKT system
// [I J^T; J 0] (w, mu) = (I w0, 0), solved in double independently of the
// part's formula. One exact solve must land there.
TEST_P(GearTest, VelocitySolveIsTheMassWeightedProjection) {
  CalculateProperties();
  const BodyBlocks before = *bodies_;
  KernelSolveVelocityOnly();
  for (std::size_t w = 0; w < worlds(); ++w) {
    if (KindOfWorld(w) != LaneKind::kRegular) continue;
    const RefBody b1 = ToReference(before.Get(w, 0), before.motion_type(0));
    const RefBody b2 = ToReference(before.Get(w, 1), before.motion_type(1));
    Eigen::Matrix<double, 7, 7> kkt = Eigen::Matrix<double, 7, 7>::Zero();
    kkt.block<3, 3>(0, 0) = b1.InverseInertia().inverse();
    kkt.block<3, 3>(3, 3) = b2.InverseInertia().inverse();
    Eigen::Matrix<double, 6, 1> jacobian;
    jacobian << Axis1(w), Ratio(w) * Axis2(w);
    kkt.block<6, 1>(0, 6) = jacobian;
    kkt.block<1, 6>(6, 0) = jacobian.transpose();
    Eigen::Matrix<double, 6, 1> w0;
    w0 << b1.angular_velocity, b2.angular_velocity;
    Eigen::Matrix<double, 7, 1> rhs;
    rhs << kkt.block<6, 6>(0, 0) * w0, 0.0;
    const Eigen::Matrix<double, 6, 1> projected =
        kkt.fullPivLu().solve(rhs).head<6>();
    const double scale = w0.norm() + (projected - w0).norm();
    ExpectVec3Near(Body(w, 0).angular_velocity, projected.head<3>(), Tolerance(scale),
                   WorldLabel(w, "gear 1's angular velocity vs the projection"));
    ExpectVec3Near(Body(w, 1).angular_velocity, projected.tail<3>(), Tolerance(scale),
                   WorldLabel(w, "gear 2's angular velocity vs the projection"));
  }
}

TEST_P(GearTest, PositionSolveMatchesReferenceAndMovesOnlyDynamicBodies) {
  CalculateProperties();
  DeactivateFlaggedLanes();
  const BodyBlocks before = *bodies_;
  SolvePosition(0.2f);
  ExpectBodiesUnchanged(
      before,
      [&](std::size_t, std::size_t body) {
        return bodies_->motion_type(body) != MotionType::kDynamic;
      },
      "position solve of a kinematic body");
}

TEST_P(GearTest, DeactivatedAndSingularLanesStayFiniteAndApplyNothing) {
  CalculateProperties();
  DeactivateFlaggedLanes();
  const BodyBlocks before = *bodies_;
  for (std::size_t block = 0; block < blocks(); ++block) {
    kernels_->warm_start(Pair(block), (*parts_)[block], 1.0f);
    kernels_->solve_velocity(Pair(block), (*geometry_)[block], (*parts_)[block]);
    kernels_->solve_position(Pair(block), (*error_)[block], (*parts_)[block], 0.2f);
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

TEST_P(GearTest, GetSetSaveRestoreOfAccumulatedImpulse) {
  CalculateProperties();
  for (std::size_t w = 0; w < worlds(); ++w) {
    SetTotalLambda(*parts_, w, 0.5f * float(w) - 3.0f);
    EXPECT_EQ(GetTotalLambda(*parts_, w), 0.5f * float(w) - 3.0f);
  }
  WarmStart(1.0f);
  const auto saved = SavePartState(*parts_);
  std::vector<float> at_save;
  for (std::size_t w = 0; w < worlds(); ++w) at_save.push_back(GetTotalLambda(*parts_, w));
  SolveVelocity();
  RestorePartState(*parts_, saved);
  for (std::size_t w = 0; w < worlds(); ++w) {
    const float restored = GetTotalLambda(*parts_, w);
    EXPECT_TRUE(BitEqual(&restored, &at_save[w], sizeof(float))) << "world " << w;
  }
}

std::vector<PartCase<GearKernels>> AllCases() {
  static const std::vector<std::pair<MotionType, MotionType>> pairings = {
      {MotionType::kDynamic, MotionType::kDynamic},
      {MotionType::kKinematic, MotionType::kDynamic},
      {MotionType::kDynamic, MotionType::kKinematic},
      {MotionType::kKinematic, MotionType::kKinematic},
  };
  return AllPartCases<GearKernels>(pairings);
}

INSTANTIATE_TEST_SUITE_P(EveryTarget, GearTest, ::testing::ValuesIn(AllCases()),
                         PartCaseName<GearKernels>);

// The spec's example (2.10): two equal spheres on parallel axes, r = 2,
// w1 = 1, w2 = 0. K = I^-1 (1 + r^2), dL = -1 / K, so w1 = 1 - 1/5 = 0.8 and
// w2 = -r/5 = -0.4: J v = 0 after one solve and a second solve applies
// nothing. (Jolt, without r on body 2, gets (0.8, -0.2) here and converges to
// (0.6667, -0.3333) over its iterations.) With r = 1 both give (0.5, -0.5).
class GearSpecExampleTest : public ::testing::TestWithParam<const GearKernels*> {};

TEST_P(GearSpecExampleTest, EqualSpheresRatioTwoGiveZeroPointEightAndMinusZeroPointFour) {
  const GearKernels& kernels = *GetParam();
  for (const auto& [ratio, expected1, expected2] :
       {std::tuple{2.0f, 0.8, -0.4}, std::tuple{1.0f, 0.5, -0.5}}) {
    BodyBlocks bodies({MotionType::kDynamic, MotionType::kDynamic}, 1);
    BodyState sphere;  // solid sphere, m = 1, radius 1: I = 0.4, I^-1 = 2.5
    sphere.inv_mass = 1.0f;
    sphere.inv_inertia_diagonal = {2.5f, 2.5f, 2.5f};
    sphere.angular_velocity = {0.0f, 0.0f, 1.0f};
    bodies.Set(0, 0, sphere);
    sphere.angular_velocity = {0.0f, 0.0f, 0.0f};
    sphere.position = {3.0f, 0.0f, 0.0f};
    bodies.Set(0, 1, sphere);
    const PartBinding gear = BindPart(bodies, "spur_gears", PartKind::kGear, 0, 1);
    PartBlocks<GearGeometry> geometry(1);
    PartBlocks<GearLanes> part(1);
    SetLaneVec3(geometry[0].hinge_axis1, 0, Vec3d(0, 0, 1));
    SetLaneVec3(geometry[0].hinge_axis2, 0, Vec3d(0, 0, 1));
    geometry[0].ratio[0] = ratio;
    kernels.calculate_properties(PairInBlock(bodies, gear, 0), geometry[0], part[0]);
    EXPECT_TRUE(kernels.solve_velocity(PairInBlock(bodies, gear, 0), geometry[0], part[0]));
    const std::string label = "r = " + std::to_string(ratio);
    ExpectVec3Near(ToVec3d(bodies.Get(0, 0).angular_velocity), Vec3d(0, 0, expected1),
                   Tolerance(1.0), label + ", gear 1");
    ExpectVec3Near(ToVec3d(bodies.Get(0, 1).angular_velocity), Vec3d(0, 0, expected2),
                   Tolerance(1.0), label + ", gear 2");
    EXPECT_NEAR(GetTotalLambda(part, 0), -1.0 / (2.5 * (1.0 + ratio * ratio)), Tolerance(1.0))
        << label;
    // J v is zero now: the second solve adds at most rounding.
    const BodyState w1 = bodies.Get(0, 0), w2 = bodies.Get(0, 1);
    kernels.solve_velocity(PairInBlock(bodies, gear, 0), geometry[0], part[0]);
    ExpectVec3Near(ToVec3d(bodies.Get(0, 0).angular_velocity), ToVec3d(w1.angular_velocity),
                   Tolerance(1.0), label + ", gear 1 after a second solve");
    ExpectVec3Near(ToVec3d(bodies.Get(0, 1).angular_velocity), ToVec3d(w2.angular_velocity),
                   Tolerance(1.0), label + ", gear 2 after a second solve");
  }
}

INSTANTIATE_TEST_SUITE_P(EveryTarget, GearSpecExampleTest,
                         ::testing::ValuesIn(SupportedKernels<GearKernels>()),
                         TableName<GearKernels>);

TEST(GearBinding, StaticBodyIsRefusedNamingTheConstraint) {
  const BodyBlocks bodies({MotionType::kDynamic, MotionType::kStatic}, 4);
  try {
    BindPart(bodies, "spur_gears", PartKind::kGear, 0, 1);
    FAIL() << "a gear with a static gear 2 was accepted";
  } catch (const SceneError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("spur_gears"), std::string::npos) << message;
    EXPECT_NE(message.find("body2 (gear 2) = body 1"), std::string::npos) << message;
    EXPECT_NE(message.find("static"), std::string::npos) << message;
  }
}

}  // namespace
}  // namespace manyworlds::testing
