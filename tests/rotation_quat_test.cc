// RotationQuatConstraintPart kernels, every verb, every lane against the
// scalar reference, on every Highway target this CPU supports, for 1, 7, 16
// and 1000 worlds and every motion-type pairing.
#include <gtest/gtest.h>

#include <array>
#include <memory>
#include <vector>

#include "batch/part_binding.h"
#include "batch/part_state.h"
#include "batch/world_blocks.h"
#include "kernels/rotation_quat.h"
#include "reference/rotation_quat_part.h"
#include "tests/test_support.h"
#include "tests/three_row_test_support.h"

namespace manyworlds::testing {
namespace {

using RefRotationQuat = reference::RotationQuatPart<double>;

// kAtRest: equal exact rotations and r0^-1 = identity, so C == 0 exactly.
// kNearSingular: both inverse inertias ~1e-3 about one common world direction
//   (cond(K) ~1e4).
// kLargeError: the error rotation is up to 2 rad instead of 0.5, far from the
//   linearisation point of the Jacobian.
// kSingular: no inverse inertia at all: K == 0, deactivated.
// kDeactivatedByFlag: deactivated explicitly after CalculateProperties.
enum class LaneKind {
  kRegular,
  kAtRest,
  kNearSingular,
  kLargeError,
  kSingular,
  kDeactivatedByFlag
};

LaneKind KindOfWorld(std::size_t world) {
  switch (world % 8) {
    case 2: return LaneKind::kAtRest;
    case 3: return LaneKind::kNearSingular;
    case 4: return LaneKind::kLargeError;
    case 5: return LaneKind::kSingular;
    case 6: return LaneKind::kDeactivatedByFlag;
    default: return LaneKind::kRegular;
  }
}

class RotationQuatTest : public PartTestBase<RotationQuatKernels> {
 protected:
  void SetUp() override {
    SetUpBodies("fixed_rotation_exact", PartKind::kRotationQuat);
    parts_ = std::make_unique<PartBlocks<RotationQuatLanes>>(blocks());
    inv_initial_orientation_ = std::make_unique<PartBlocks<QuatLanes>>(blocks());
    reference_.resize(worlds());
    for (std::size_t world = 0; world < worlds(); ++world) FillWorld(world);
  }

  bool Dynamic(std::size_t body) const {
    return bodies_->motion_type(body) == MotionType::kDynamic;
  }

  void FillWorld(std::size_t world) {
    Random random(1414213u + 7919u * unsigned(world));
    BodyState body[2] = {RandomBodyState(random), RandomBodyState(random)};
    double max_error_angle = 0.5;
    switch (KindOfWorld(world)) {
      case LaneKind::kAtRest:  // exact, so q1* q2 r0^-1 is exactly the identity
        body[0].rotation = body[1].rotation = ToFloat4(ExactRotation(random));
        break;
      case LaneKind::kNearSingular: {
        const Quatd principal_axes = random.Rotation();
        for (BodyState& b : body) {
          b.inertia_rotation = ToFloat4(ToQuatd(b.rotation).conjugate() * principal_axes);
          b.inv_inertia_diagonal[0] = 1e-3f;
        }
        break;
      }
      case LaneKind::kLargeError: max_error_angle = 2.0; break;
      case LaneKind::kSingular:
        body[0].inv_inertia_diagonal = body[1].inv_inertia_diagonal = {0.f, 0.f, 0.f};
        break;
      default: break;
    }
    bodies_->Set(world, 0, body[0]);
    bodies_->Set(world, 1, body[1]);
    const Quatd r0_inv =
        KindOfWorld(world) == LaneKind::kAtRest
            ? Quatd::Identity()
            : NearRestInverseInitialOrientation(random, ToQuatd(body[0].rotation),
                                                ToQuatd(body[1].rotation), max_error_angle);
    SetLaneQuat((*inv_initial_orientation_)[Block(world)], Lane(world), r0_inv);
    SetTotalLambda(*parts_, world,
                   {float(random.Uniform(-1, 1)), float(random.Uniform(-1, 1)),
                    float(random.Uniform(-1, 1))});
  }

  Quatd InvInitialOrientation(std::size_t w) const {
    return LaneQuat((*inv_initial_orientation_)[Block(w)], Lane(w));
  }
  Vec3d Lambda(std::size_t world) const {
    const auto l = GetTotalLambda(*parts_, world);
    return Vec3d(l[0], l[1], l[2]);
  }
  // cond(K) of the reference's effective mass; 1 for deactivated lanes.
  double ConditionOf(std::size_t world) const {
    const Mat33d& k_inv = reference_[world].EffectiveMass();
    return k_inv.isZero(0.0) ? 1.0 : Condition<3>(k_inv);
  }
  bool ExpectedInactive(std::size_t w) const {
    return KindOfWorld(w) == LaneKind::kSingular || (!Dynamic(0) && !Dynamic(1));
  }

  void CalculateProperties() {
    for (std::size_t block = 0; block < blocks(); ++block) {
      kernels_->calculate_properties(Pair(block), (*inv_initial_orientation_)[block],
                                     (*parts_)[block]);
    }
    for (std::size_t w = 0; w < worlds(); ++w) {
      reference_[w].SetTotalLambda(Lambda(w));
      reference_[w].CalculateConstraintProperties(Body(w, 0), Body(w, 1),
                                                  InvInitialOrientation(w));
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
          return kernels_->solve_position(Pair(block), (*inv_initial_orientation_)[block],
                                          (*parts_)[block], baumgarte);
        },
        [&](std::size_t w, RefBody& b1, RefBody& b2) {
          return reference_[w].SolvePositionConstraint(b1, b2, InvInitialOrientation(w),
                                                       baumgarte);
        });
  }

  std::unique_ptr<PartBlocks<RotationQuatLanes>> parts_;
  std::unique_ptr<PartBlocks<QuatLanes>> inv_initial_orientation_;
  std::vector<RefRotationQuat> reference_;
};

TEST_P(RotationQuatTest, CalculatePropertiesMatchesReference) {
  CalculateProperties();
  LaneFlags active;
  for (std::size_t w = 0; w < worlds(); ++w) {
    const RotationQuatLanes& part = (*parts_)[Block(w)];
    const RefRotationQuat& ref = reference_[w];
    const std::size_t lane = Lane(w);
    // |I^-1 JP^T| <= |I^-1| |JP|, |I^-1| <= its largest diagonal entry, |JP| <= 1.
    ExpectMat33Near(LaneMat33(part.inv_i1_jp_transposed, lane), ref.InvI1JPt(),
                    Tolerance(Body(w, 0).inv_inertia_diagonal.maxCoeff()),
                    WorldLabel(w, "I1^-1 JP^T"));
    ExpectMat33Near(LaneMat33(part.inv_i2_jp_transposed, lane), ref.InvI2JPt(),
                    Tolerance(Body(w, 1).inv_inertia_diagonal.maxCoeff()),
                    WorldLabel(w, "I2^-1 JP^T"));
    const Mat33d& k_inv = ref.EffectiveMass();
    ExpectMat33Near(LaneSym33(part.effective_mass, lane), k_inv,
                    Tolerance(k_inv.cwiseAbs().maxCoeff(), ConditionOf(w)),
                    WorldLabel(w, "K^-1"));
    const Mat33d& k_inv_jp = ref.EffectiveMassJP();
    ExpectMat33Near(LaneMat33(part.effective_mass_jp, lane), k_inv_jp,
                    Tolerance(k_inv_jp.cwiseAbs().maxCoeff(), ConditionOf(w)),
                    WorldLabel(w, "K^-1 JP"));
    if (lane == 0) kernels_->is_active(part, active);
    EXPECT_EQ(active[lane] != 0.0f, ref.IsActive()) << "IsActive of world " << w;
    EXPECT_EQ(active[lane] == 0.0f, ExpectedInactive(w)) << "IsActive of world " << w;
    if (ExpectedInactive(w)) {
      EXPECT_EQ(Lambda(w), Vec3d::Zero()) << "singular world " << w << " keeps an impulse";
      EXPECT_TRUE(LaneMat33(part.effective_mass_jp, lane).isZero(0.0))
          << "K^-1 JP of singular world " << w;
    }
  }
}

TEST_P(RotationQuatTest, WarmStartScalesAndAppliesImpulse) {
  CalculateProperties();
  WarmStart(0.75f);
}

TEST_P(RotationQuatTest, WarmStartWithRatioZeroAppliesNothing) {
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

// Only the first iteration is compared with the reference (later ones solve
// for the rounding residual of the first; see point_test.cc).
TEST_P(RotationQuatTest, VelocitySolveMatchesReferenceAndZeroesVelocityError) {
  CalculateProperties();
  DeactivateFlaggedLanes();
  WarmStart(1.0f);
  // The rounding of the solve is relative to the velocities it cancels.
  std::vector<double> speed(worlds());
  for (std::size_t w = 0; w < worlds(); ++w) {
    speed[w] = std::max(Body(w, 0).AngularVelocity().norm(), Body(w, 1).AngularVelocity().norm());
  }
  SolveVelocity();
  // Invariant: J v = JP (w2 - w1) = 0 in every active lane.
  for (std::size_t w = 0; w < worlds(); ++w) {
    if (!reference_[w].IsActive()) continue;
    const Vec3d jv = reference::RotationQuatVelocityError(Body(w, 0), Body(w, 1),
                                                          InvInitialOrientation(w));
    EXPECT_LE(jv.cwiseAbs().maxCoeff(), Tolerance(speed[w], ConditionOf(w)))
        << "J v after the velocity solve of world " << w;
  }
}

TEST_P(RotationQuatTest, PositionSolveMatchesReference) {
  CalculateProperties();
  DeactivateFlaggedLanes();
  SolvePosition(0.2f);
}

TEST_P(RotationQuatTest, DeactivatedAndSingularLanesStayFiniteAndApplyNothing) {
  CalculateProperties();
  DeactivateFlaggedLanes();
  const BodyBlocks before = *bodies_;
  for (std::size_t block = 0; block < blocks(); ++block) {
    kernels_->warm_start(Pair(block), (*parts_)[block], 1.0f);
    kernels_->solve_velocity(Pair(block), (*parts_)[block]);
    kernels_->solve_position(Pair(block), (*inv_initial_orientation_)[block],
                             (*parts_)[block], 0.2f);
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

TEST_P(RotationQuatTest, PositionSolveAtRestMovesNothing) {
  CalculateProperties();
  const BodyBlocks before = *bodies_;
  for (std::size_t block = 0; block < blocks(); ++block) {
    kernels_->solve_position(Pair(block), (*inv_initial_orientation_)[block],
                             (*parts_)[block], 0.2f);
  }
  ExpectBodiesUnchanged(
      before, [&](std::size_t w, std::size_t) { return KindOfWorld(w) == LaneKind::kAtRest; },
      "lane at rest (C == 0)");
}

TEST_P(RotationQuatTest, GetSetSaveRestoreOfAccumulatedImpulse) {
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

std::vector<PartCase<RotationQuatKernels>> AllCases() {
  static const std::vector<std::pair<MotionType, MotionType>> pairings = {
      {MotionType::kDynamic, MotionType::kDynamic},
      {MotionType::kDynamic, MotionType::kStatic},
      {MotionType::kStatic, MotionType::kDynamic},
      {MotionType::kKinematic, MotionType::kDynamic},
      {MotionType::kDynamic, MotionType::kKinematic},
      {MotionType::kKinematic, MotionType::kStatic},
  };
  return AllPartCases<RotationQuatKernels>(pairings);
}

INSTANTIATE_TEST_SUITE_P(EveryTarget, RotationQuatTest, ::testing::ValuesIn(AllCases()),
                         PartCaseName<RotationQuatKernels>);

}  // namespace
}  // namespace manyworlds::testing
