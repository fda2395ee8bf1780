// RackAndPinionConstraintPart kernels, every verb, every lane against the
// scalar reference, on every Highway target this CPU supports, for 1, 7, 16
// and 1000 worlds and every allowed motion-type pairing (static is refused).
#include <gtest/gtest.h>

#include <memory>
#include <optional>
#include <vector>

#include "batch/part_binding.h"
#include "batch/part_state.h"
#include "batch/world_blocks.h"
#include "manyworlds/error.h"
#include "kernels/rack_and_pinion.h"
#include "reference/rack_and_pinion_part.h"
#include "tests/test_support.h"

namespace manyworlds::testing {
namespace {

using RefRackAndPinion = reference::RackAndPinionPart<double>;

// Regular lanes; lanes with a tiny K (~1e-8: near-immovable pinion, tiny
// ratio), where 1/K is huge but exact to float precision since K is a scalar;
// exactly singular lanes (ratio 0 and no pinion inertia: K == 0); lanes
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

class RackAndPinionTest : public PartTestBase<RackAndPinionKernels> {
 protected:
  void SetUp() override {
    SetUpBodies("rack", PartKind::kRackAndPinion);
    const std::size_t world_count = GetParam().world_count;
    const std::size_t blocks = bodies_->block_count();
    geometry_ = std::make_unique<PartBlocks<RackAndPinionGeometry>>(blocks);
    parts_ = std::make_unique<PartBlocks<RackAndPinionLanes>>(blocks);
    error_ = std::make_unique<PartBlocks<LaneArray>>(blocks);
    reference_.resize(world_count);
    for (std::size_t world = 0; world < world_count; ++world) FillWorld(world);
  }

  void FillWorld(std::size_t world) {
    Random random(7654321u + 104729u * unsigned(world));
    BodyState pinion = RandomBodyState(random);
    BodyState rack = RandomBodyState(random);
    // Ratios of both signs over four decades (teeth / length in Jolt's terms).
    double ratio = (random.Uniform(0, 1) < 0.5 ? -1 : 1) * random.LogUniform(0.01, 100.0);
    switch (KindOfWorld(world)) {
      case LaneKind::kTinyMass:
        pinion.inv_inertia_diagonal = {1e-8f, 1e-8f, 1e-8f};
        ratio = 1e-4;
        break;
      case LaneKind::kSingular:
        pinion.inv_inertia_diagonal = {0.f, 0.f, 0.f};
        ratio = 0.0;
        break;
      default: break;
    }
    bodies_->Set(world, 0, pinion);
    bodies_->Set(world, 1, rack);
    const std::size_t block = world / kLaneWidth, lane = world % kLaneWidth;
    RackAndPinionGeometry& g = (*geometry_)[block];
    SetLaneVec3(g.hinge_axis, lane, random.UnitVector());
    SetLaneVec3(g.slider_axis, lane, random.UnitVector());
    g.ratio[lane] = float(ratio);
    (*error_)[block][lane] = float(random.Uniform(-0.3, 0.3));
    SetTotalLambda(*parts_, world, float(random.Uniform(-1, 1)));
  }

  const RackAndPinionGeometry& G(std::size_t w) const { return (*geometry_)[Block(w)]; }
  Vec3d HingeAxis(std::size_t w) const { return LaneVec3(G(w).hinge_axis, Lane(w)); }
  Vec3d SliderAxis(std::size_t w) const { return LaneVec3(G(w).slider_axis, Lane(w)); }
  double Ratio(std::size_t w) const { return G(w).ratio[Lane(w)]; }
  double Error(std::size_t w) const { return (*error_)[Block(w)][Lane(w)]; }
  double Lambda(std::size_t world) const { return GetTotalLambda(*parts_, world); }

  void CalculateProperties() {
    for (std::size_t block = 0; block < blocks(); ++block) {
      kernels_->calculate_properties(Pair(block), (*geometry_)[block],
                                                     (*parts_)[block]);
    }
    for (std::size_t w = 0; w < worlds(); ++w) {
      reference_[w].SetTotalLambda(Lambda(w));
      reference_[w].CalculateConstraintProperties(Body(w, 0), HingeAxis(w), Body(w, 1),
                                                  SliderAxis(w), Ratio(w));
    }
  }

  void DeactivateFlaggedLanes() {
    DeactivateWorlds(*parts_, reference_,
                     [](std::size_t w) { return KindOfWorld(w) == LaneKind::kDeactivatedByFlag; });
  }

  // Runs one verb on kernel and reference from the same body state and
  // impulse and compares every lane. K is a scalar, so no condition factor.
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

  void SolveVelocity() {
    CompareVerb(
        "velocity solve",
        [&](std::size_t block) {
          return kernels_->solve_velocity(Pair(block), (*geometry_)[block],
                                                          (*parts_)[block]);
        },
        [&](std::size_t w, RefBody& b1, RefBody& b2) {
          return reference_[w].SolveVelocityConstraint(b1, b2, HingeAxis(w),
                                                       SliderAxis(w), Ratio(w));
        });
  }

  void SolvePosition(float baumgarte) {
    CompareVerb(
        "position solve",
        [&](std::size_t block) {
          return kernels_->solve_position(Pair(block), (*error_)[block],
                                                          (*parts_)[block], baumgarte);
        },
        [&](std::size_t w, RefBody& b1, RefBody& b2) {
          return reference_[w].SolvePositionConstraint(b1, b2, Error(w), baumgarte);
        });
  }

  std::unique_ptr<PartBlocks<RackAndPinionGeometry>> geometry_;
  std::unique_ptr<PartBlocks<RackAndPinionLanes>> parts_;
  std::unique_ptr<PartBlocks<LaneArray>> error_;
  std::vector<RefRackAndPinion> reference_;
};

TEST_P(RackAndPinionTest, CalculatePropertiesMatchesReference) {
  CalculateProperties();
  LaneFlags active;
  for (std::size_t w = 0; w < worlds(); ++w) {
    const RackAndPinionLanes& part = (*parts_)[Block(w)];
    const RefRackAndPinion& ref = reference_[w];
    const std::size_t lane = Lane(w);
    // I1^-1 a: scale = largest inverse inertia (|a| = 1).
    ExpectVec3Near(LaneVec3(part.inv_i1_hinge_axis, lane), ref.InvI1HingeAxis(),
                   Tolerance(Body(w, 0).inv_inertia_diagonal.maxCoeff()),
                   WorldLabel(w, "I1^-1 a"));
    ExpectVec3Near(LaneVec3(part.ratio_inv_m2_slider_axis, lane), ref.RatioInvM2SliderAxis(),
                   Tolerance(std::abs(Ratio(w)) * Body(w, 1).inv_mass),
                   WorldLabel(w, "r m2^-1 b"));
    EXPECT_NEAR(part.effective_mass[lane], ref.EffectiveMass(),
                Tolerance(ref.EffectiveMass()))
        << "1/K of world " << w;
    if (lane == 0) kernels_->is_active(part, active);
    EXPECT_EQ(active[lane] != 0.0f, ref.IsActive()) << "IsActive of world " << w;
    if (KindOfWorld(w) == LaneKind::kSingular) {
      EXPECT_EQ(active[lane], 0.0f) << "singular world " << w << " is active";
      EXPECT_EQ(Lambda(w), 0.0) << "singular world " << w << " keeps an impulse";
    }
  }
}

TEST_P(RackAndPinionTest, WarmStartScalesAndAppliesImpulse) {
  CalculateProperties();
  WarmStart(0.75f);
}

TEST_P(RackAndPinionTest, WarmStartWithRatioZeroAppliesNothing) {
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

TEST_P(RackAndPinionTest, VelocitySolveMatchesReferenceAndZeroesVelocityError) {
  CalculateProperties();
  DeactivateFlaggedLanes();
  WarmStart(1.0f);
  for (int iteration = 0; iteration < 3; ++iteration) SolveVelocity();
  // Invariant: the scalar solve is exact, so J v = a.w1 - r b.v2 is zero to
  // rounding of its two terms in every active lane.
  for (std::size_t w = 0; w < worlds(); ++w) {
    if (!reference_[w].IsActive()) continue;
    const RefBody b1 = Body(w, 0), b2 = Body(w, 1);
    const double jv = reference::RackAndPinionVelocityError(b1, b2, HingeAxis(w),
                                                            SliderAxis(w), Ratio(w));
    const double scale = b1.angular_velocity.norm() +
                         std::abs(Ratio(w)) * b2.linear_velocity.norm();
    EXPECT_LE(std::abs(jv), Tolerance(scale)) << "J v after the velocity solve of world " << w;
  }
}

TEST_P(RackAndPinionTest, PositionSolveMatchesReferenceAndMovesOnlyDynamicBodies) {
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

TEST_P(RackAndPinionTest, DeactivatedAndSingularLanesStayFiniteAndApplyNothing) {
  CalculateProperties();
  DeactivateFlaggedLanes();
  const BodyBlocks before = *bodies_;
  for (std::size_t block = 0; block < blocks(); ++block) {
    kernels_->warm_start(Pair(block), (*parts_)[block], 1.0f);
    kernels_->solve_velocity(Pair(block), (*geometry_)[block], (*parts_)[block]);
    kernels_->solve_position(Pair(block), (*error_)[block], (*parts_)[block],
                                             0.2f);
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

TEST_P(RackAndPinionTest, GetSetSaveRestoreOfAccumulatedImpulse) {
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

std::vector<PartCase<RackAndPinionKernels>> AllCases() {
  static const std::vector<std::pair<MotionType, MotionType>> pairings = {
      {MotionType::kDynamic, MotionType::kDynamic},
      {MotionType::kKinematic, MotionType::kDynamic},
      {MotionType::kDynamic, MotionType::kKinematic},
      {MotionType::kKinematic, MotionType::kKinematic},
  };
  return AllPartCases<RackAndPinionKernels>(pairings);
}

INSTANTIATE_TEST_SUITE_P(EveryTarget, RackAndPinionTest, ::testing::ValuesIn(AllCases()),
                         PartCaseName<RackAndPinionKernels>);

TEST(RackAndPinionBinding, StaticBodyIsRefusedNamingTheConstraint) {
  const BodyBlocks bodies({MotionType::kStatic, MotionType::kDynamic}, 4);
  try {
    BindPart(bodies, "pinion_drive", PartKind::kRackAndPinion, 0, 1);
    FAIL() << "a rack-and-pinion with a static pinion was accepted";
  } catch (const SceneError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("pinion_drive"), std::string::npos) << message;
    EXPECT_NE(message.find("body1 (pinion) = body 0"), std::string::npos) << message;
    EXPECT_NE(message.find("static"), std::string::npos) << message;
  }
}

}  // namespace
}  // namespace manyworlds::testing
