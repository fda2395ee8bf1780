// RotationEulerConstraintPart kernels, every verb and the rest-rotation
// helpers, every lane against the scalar reference, on every Highway target
// this CPU supports, for 1, 7, 16 and 1000 worlds and every motion-type
// pairing. Lanes with rotations locked about world axes exercise the
// zero-column fix.
#include <gtest/gtest.h>

#include <array>
#include <memory>
#include <vector>

#include "batch/part_binding.h"
#include "batch/part_state.h"
#include "batch/world_blocks.h"
#include "kernels/rotation_euler.h"
#include "reference/rotation_euler_part.h"
#include "tests/test_support.h"
#include "tests/three_row_test_support.h"

namespace manyworlds::testing {
namespace {

using RefRotationEuler = reference::RotationEulerPart<double>;

// kAtRest: equal exact rotations and r0^-1 = identity, so C == 0 exactly.
// kNearSingular: both inverse inertias ~1e-3 about one common world direction
//   (cond(K) ~1e4).
// kLockedAxes: every dynamic body's rotation locked about the same one or two
//   world axes (exact zero rows and columns of I^-1): K has zero columns and
//   the fix replaces them by identity columns.
// kZeroInertia: all inverse inertias zero: K == 0 becomes the identity; the
//   lane is active but moves nothing.
// kSingularAfterFix: an exact rank-1 K (one free axis along the y-z
//   diagonal; the x column is fixed, y and z stay equal): deactivated.
// kDeactivatedByFlag: deactivated explicitly after CalculateProperties.
enum class LaneKind {
  kRegular,
  kAtRest,
  kNearSingular,
  kLockedAxes,
  kZeroInertia,
  kDeactivatedByFlag,
  kSingularAfterFix
};

LaneKind KindOfWorld(std::size_t world) {
  switch (world % 8) {
    case 2: return LaneKind::kAtRest;
    case 3: return LaneKind::kNearSingular;
    case 4: return LaneKind::kLockedAxes;
    case 5: return LaneKind::kZeroInertia;
    case 6: return LaneKind::kDeactivatedByFlag;
    case 7: return LaneKind::kSingularAfterFix;
    default: return LaneKind::kRegular;
  }
}

class RotationEulerTest : public PartTestBase<RotationEulerKernels> {
 protected:
  void SetUp() override {
    SetUpBodies("fixed_rotation", PartKind::kRotationEuler);
    parts_ = std::make_unique<PartBlocks<RotationEulerLanes>>(blocks());
    inv_initial_orientation_ = std::make_unique<PartBlocks<QuatLanes>>(blocks());
    reference_.resize(worlds());
    locked_axes_.resize(worlds());
    for (std::size_t world = 0; world < worlds(); ++world) FillWorld(world);
  }

  bool Dynamic(std::size_t body) const {
    return bodies_->motion_type(body) == MotionType::kDynamic;
  }

  void FillWorld(std::size_t world) {
    Random random(3141592u + 7919u * unsigned(world));
    BodyState body[2] = {RandomBodyState(random), RandomBodyState(random)};
    const std::array<float, 4> identity{0.f, 0.f, 0.f, 1.f};
    switch (KindOfWorld(world)) {
      case LaneKind::kAtRest:  // exact, so q2 r0^-1 q1* is exactly the identity
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
      case LaneKind::kLockedAxes: {
        const int first = int(world / 8) % 3;
        locked_axes_[world] = {first};
        if (world % 16 == 12) locked_axes_[world].push_back((first + 1) % 3);
        for (std::size_t b = 0; b < 2; ++b) {
          if (!Dynamic(b)) continue;
          LockRotationAbout(locked_axes_[world], random, body[b]);
          for (const int axis : locked_axes_[world]) body[b].angular_velocity[axis] = 0.0f;
        }
        break;
      }
      case LaneKind::kZeroInertia:
        body[0].inv_inertia_diagonal = body[1].inv_inertia_diagonal = {0.f, 0.f, 0.f};
        break;
      case LaneKind::kSingularAfterFix: {
        // The first dynamic body gets I^-1 = d c c^T with c = (0, 1/2, 1/2)
        // exactly: the non-unit inertia rotation (1/2, 0, 0, 1/2) has that as
        // its second column. The other body has no inertia.
        const std::size_t free_body = Dynamic(0) ? 0 : 1;
        body[free_body].rotation = identity;
        body[free_body].inertia_rotation = {0.5f, 0.f, 0.f, 0.5f};
        body[free_body].inv_inertia_diagonal = {0.f, float(random.LogUniform(0.1, 10)), 0.f};
        body[1 - free_body].inv_inertia_diagonal = {0.f, 0.f, 0.f};
        break;
      }
      default: break;
    }
    bodies_->Set(world, 0, body[0]);
    bodies_->Set(world, 1, body[1]);
    const Quatd r0_inv =
        KindOfWorld(world) == LaneKind::kAtRest
            ? Quatd::Identity()
            : NearRestInverseInitialOrientation(random, ToQuatd(body[0].rotation),
                                                ToQuatd(body[1].rotation), 0.5);
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
  // cond(K) (after the fix) of the reference's effective mass; 1 for
  // deactivated lanes.
  double ConditionOf(std::size_t world) const {
    const Mat33d& k_inv = reference_[world].EffectiveMass();
    return k_inv.isZero(0.0) ? 1.0 : Condition<3>(k_inv);
  }
  bool ExpectedInactive(std::size_t w) const {
    return KindOfWorld(w) == LaneKind::kSingularAfterFix && (Dynamic(0) || Dynamic(1));
  }

  void CalculateProperties() {
    for (std::size_t block = 0; block < blocks(); ++block) {
      kernels_->calculate_properties(Pair(block), (*parts_)[block]);
    }
    for (std::size_t w = 0; w < worlds(); ++w) {
      reference_[w].SetTotalLambda(Lambda(w));
      reference_[w].CalculateConstraintProperties(Body(w, 0), Body(w, 1));
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

  void RunEveryVerbOnKernelsOnly() {
    for (std::size_t block = 0; block < blocks(); ++block) {
      kernels_->warm_start(Pair(block), (*parts_)[block], 1.0f);
      for (int iteration = 0; iteration < 3; ++iteration) {
        kernels_->solve_velocity(Pair(block), (*parts_)[block]);
      }
      kernels_->solve_position(Pair(block), (*inv_initial_orientation_)[block],
                               (*parts_)[block], 0.2f);
    }
  }

  std::unique_ptr<PartBlocks<RotationEulerLanes>> parts_;
  std::unique_ptr<PartBlocks<QuatLanes>> inv_initial_orientation_;
  std::vector<RefRotationEuler> reference_;
  std::vector<std::vector<int>> locked_axes_;  // world axes, per world
};

TEST_P(RotationEulerTest, CalculatePropertiesMatchesReference) {
  CalculateProperties();
  LaneFlags active;
  for (std::size_t w = 0; w < worlds(); ++w) {
    const RotationEulerLanes& part = (*parts_)[Block(w)];
    const RefRotationEuler& ref = reference_[w];
    const std::size_t lane = Lane(w);
    // |I^-1| <= its largest diagonal entry.
    ExpectMat33Near(LaneSym33(part.inv_i1, lane), ref.InvI1(),
                    Tolerance(Body(w, 0).inv_inertia_diagonal.maxCoeff()),
                    WorldLabel(w, "I1^-1"));
    ExpectMat33Near(LaneSym33(part.inv_i2, lane), ref.InvI2(),
                    Tolerance(Body(w, 1).inv_inertia_diagonal.maxCoeff()),
                    WorldLabel(w, "I2^-1"));
    const Mat33d& k_inv = ref.EffectiveMass();
    ExpectMat33Near(LaneSym33(part.effective_mass, lane), k_inv,
                    Tolerance(k_inv.cwiseAbs().maxCoeff(), ConditionOf(w)),
                    WorldLabel(w, "K^-1"));
    if (lane == 0) kernels_->is_active(part, active);
    EXPECT_EQ(active[lane] != 0.0f, ref.IsActive()) << "IsActive of world " << w;
    EXPECT_EQ(active[lane] == 0.0f, ExpectedInactive(w)) << "IsActive of world " << w;
    if (ExpectedInactive(w)) {
      EXPECT_EQ(Lambda(w), Vec3d::Zero()) << "singular world " << w << " keeps an impulse";
    }
  }
}

TEST_P(RotationEulerTest, WarmStartScalesAndAppliesImpulse) {
  CalculateProperties();
  WarmStart(0.75f);
}

TEST_P(RotationEulerTest, WarmStartWithRatioZeroAppliesNothing) {
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
TEST_P(RotationEulerTest, VelocitySolveMatchesReferenceAndZeroesVelocityError) {
  CalculateProperties();
  DeactivateFlaggedLanes();
  WarmStart(1.0f);
  // The rounding of the solve is relative to the velocities it cancels.
  std::vector<double> speed(worlds());
  for (std::size_t w = 0; w < worlds(); ++w) {
    speed[w] = std::max(Body(w, 0).AngularVelocity().norm(), Body(w, 1).AngularVelocity().norm());
  }
  SolveVelocity();
  // Invariant: J v = w2 - w1 = 0 in every active lane, except about locked
  // axes (K's zero columns), which keep their velocity difference.
  for (std::size_t w = 0; w < worlds(); ++w) {
    if (!reference_[w].IsActive()) continue;
    const Vec3d jv = reference::RotationEulerVelocityError(Body(w, 0), Body(w, 1));
    const Mat33d k = reference_[w].InvI1() + reference_[w].InvI2();
    for (int axis = 0; axis < 3; ++axis) {
      if (k.col(axis).isZero(0.0)) continue;
      EXPECT_LE(std::abs(jv(axis)), Tolerance(speed[w], ConditionOf(w)))
          << "J v about axis " << axis << " after the velocity solve of world " << w;
    }
  }
}

TEST_P(RotationEulerTest, PositionSolveMatchesReference) {
  CalculateProperties();
  DeactivateFlaggedLanes();
  SolvePosition(0.2f);
}

// Zero-column fix: every impulse goes through I^-1, whose rows are exactly
// zero on the locked axes, so no angular velocity appears about them.
TEST_P(RotationEulerTest, LockedAxisStaysLocked) {
  CalculateProperties();
  RunEveryVerbOnKernelsOnly();
  for (std::size_t w = 0; w < worlds(); ++w) {
    for (std::size_t body = 0; body < 2; ++body) {
      if (!Dynamic(body)) continue;
      for (const int axis : locked_axes_[w]) {
        EXPECT_EQ(bodies_->Get(w, body).angular_velocity[axis], 0.0f)
            << "angular velocity of body " << body << " about locked axis " << axis
            << " of world " << w;
      }
    }
  }
}

TEST_P(RotationEulerTest, InactiveAndImmovableLanesApplyNothing) {
  CalculateProperties();
  DeactivateFlaggedLanes();
  const BodyBlocks before = *bodies_;
  RunEveryVerbOnKernelsOnly();
  for (std::size_t w = 0; w < worlds(); ++w) {
    if (!reference_[w].IsActive()) {
      EXPECT_EQ(Lambda(w), Vec3d::Zero()) << "inactive world " << w;
    }
  }
  // Zero-inertia lanes are active (K = E after the fix) but I^-1 = 0.
  ExpectBodiesUnchanged(
      before,
      [&](std::size_t w, std::size_t) {
        return !reference_[w].IsActive() || KindOfWorld(w) == LaneKind::kZeroInertia;
      },
      "inactive or zero-inertia lane");
}

TEST_P(RotationEulerTest, PositionSolveAtRestMovesNothing) {
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

TEST_P(RotationEulerTest, GetSetSaveRestoreOfAccumulatedImpulse) {
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

// r0^-1 from the bodies, from body-space frames (X/Y and X/Z; some worlds with
// equal frames, which must give exactly the identity) and the conversion of
// world-space frames, against the reference helpers. Frames may come out as
// q or -q (different branch rules of the matrix-to-quaternion conversion);
// both are the same rest rotation.
TEST_P(RotationEulerTest, InverseInitialOrientationHelpersMatchReference) {
  PartBlocks<std::array<Vec3Lanes, 4>> frames(blocks());
  PartBlocks<QuatLanes> from_bodies(blocks()), from_xy(blocks()), from_xz(blocks()),
      world_to_local(blocks());
  for (std::size_t w = 0; w < worlds(); ++w) {
    Random random(1618033u + 7919u * unsigned(w));
    const Vec3d x1 = ToFloat(random.UnitVector()), x2 = ToFloat(random.UnitVector());
    Vec3d axes[4] = {x1, ToFloat(random.Perpendicular(x1)), x2,
                     ToFloat(random.Perpendicular(x2))};
    if (w % 5 == 0) axes[2] = axes[0], axes[3] = axes[1];
    for (int i = 0; i < 4; ++i) SetLaneVec3(frames[Block(w)][i], Lane(w), axes[i]);
    SetLaneQuat(world_to_local[Block(w)], Lane(w), random.Rotation());
  }
  std::vector<Quatd> world_space(worlds());
  for (std::size_t w = 0; w < worlds(); ++w) {
    world_space[w] = LaneQuat(world_to_local[Block(w)], Lane(w));
  }
  for (std::size_t block = 0; block < blocks(); ++block) {
    const std::array<Vec3Lanes, 4>& f = frames[block];
    kernels_->inverse_initial_orientation_from_bodies(Pair(block), from_bodies[block]);
    // The same axes serve as X/Y and as X/Z frames.
    kernels_->inverse_initial_orientation_from_frames_xy(f[0], f[1], f[2], f[3], from_xy[block]);
    kernels_->inverse_initial_orientation_from_frames_xz(f[0], f[1], f[2], f[3], from_xz[block]);
    kernels_->inverse_initial_orientation_world_to_local(Pair(block), world_to_local[block]);
  }
  for (std::size_t w = 0; w < worlds(); ++w) {
    const RefBody b1 = Body(w, 0), b2 = Body(w, 1);
    const std::size_t lane = Lane(w);
    ExpectQuatNear(LaneQuat(from_bodies[Block(w)], lane),
                   reference::InvInitialOrientation(b1, b2), Tolerance(1.0),
                   WorldLabel(w, "r0^-1 from bodies"));
    Vec3d a[4];
    for (int i = 0; i < 4; ++i) a[i] = LaneVec3(frames[Block(w)][i], lane);
    ExpectSameRotation(LaneQuat(from_xy[Block(w)], lane),
                       reference::InvInitialOrientationXY(a[0], a[1], a[2], a[3]),
                       Tolerance(1.0), WorldLabel(w, "r0^-1 from X/Y frames"));
    ExpectSameRotation(LaneQuat(from_xz[Block(w)], lane),
                       reference::InvInitialOrientationXZ(a[0], a[1], a[2], a[3]),
                       Tolerance(1.0), WorldLabel(w, "r0^-1 from X/Z frames"));
    if (w % 5 == 0) {
      for (const QuatLanes* q : {&from_xy[Block(w)], &from_xz[Block(w)]}) {
        EXPECT_EQ(LaneQuat(*q, lane).coeffs(), Quatd::Identity().coeffs())
            << "equal frames of world " << w << " must give exactly the identity";
      }
    }
    ExpectQuatNear(LaneQuat(world_to_local[Block(w)], lane),
                   reference::InvInitialOrientationFromWorldSpace(world_space[w], b1.rotation,
                                                                 b2.rotation),
                   Tolerance(1.0), WorldLabel(w, "r0^-1 from world-space frames"));
  }
}

std::vector<PartCase<RotationEulerKernels>> AllCases() {
  static const std::vector<std::pair<MotionType, MotionType>> pairings = {
      {MotionType::kDynamic, MotionType::kDynamic},
      {MotionType::kDynamic, MotionType::kStatic},
      {MotionType::kStatic, MotionType::kDynamic},
      {MotionType::kKinematic, MotionType::kDynamic},
      {MotionType::kDynamic, MotionType::kKinematic},
      {MotionType::kKinematic, MotionType::kStatic},
  };
  return AllPartCases<RotationEulerKernels>(pairings);
}

INSTANTIATE_TEST_SUITE_P(EveryTarget, RotationEulerTest, ::testing::ValuesIn(AllCases()),
                         PartCaseName<RotationEulerKernels>);

}  // namespace
}  // namespace manyworlds::testing
