// HingeRotationConstraintPart kernels, every verb, every lane against the
// scalar reference, on every Highway target this CPU supports, for 1, 7, 16
// and 1000 worlds and every motion-type pairing of the two bodies. Lanes cover
// Jolt's axes repair (>= 90 deg apart, perpendicular, anti-parallel) and both
// sides and the tie of GetNormalizedPerpendicular's |x| > |y| choice; one test
// checks the repair and the choice from their definitions, without the
// reference.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <vector>

#include "batch/part_binding.h"
#include "batch/part_state.h"
#include "batch/world_blocks.h"
#include "kernels/hinge_rotation.h"
#include "reference/hinge_rotation_part.h"
#include "tests/test_support.h"

namespace manyworlds::testing {
namespace {

using RefHingeRotation = reference::HingeRotationPart<double>;

// Jolt's repair threshold (spec 2.5); inputs keep a1.a2 far from it, so float
// and double agree on which side a lane is.
constexpr double kRepairBelowDot = 1e-3;

enum class LaneKind {
  kAligned,              // a2 within ~0.5 rad of a1: the running hinge
  kRandomAxes,           // any angle, repaired or not
  kBeyond90Degrees,      // a1.a2 in [-0.95, -0.05]: repaired
  kPerpendicular,        // a1.a2 ~ 0: repaired
  kJustBelow90Degrees,   // a1.a2 = 0.05: not repaired
  kAntiParallel,         // a2 = -a1 exactly: perp(a1) replaces the plane
  kNearlyAntiParallel,   // |a2 - (a1.a2) a1|^2 ~ 1e-8 < 1e-6: perp(a1) too
  kAntiParallelTieInA1,  // a2 = -a1, |a1.x| == |a1.y|: perp(a1)'s tie
  kTieInA2,              // |a2.x| == |a2.y| exactly: perp takes (0, z, -y)
  kNearTieInA2,          // |a2.x| one ulp above |a2.y|: perp takes (z, 0, -x)
  kNearSingular,         // weak inertia axis across the hinge: cond(K) ~ 1e3
  kSingular,             // no inertia at all: det == 0
  kDeactivatedByFlag,
};

LaneKind KindOfWorld(std::size_t world) {
  static constexpr LaneKind kKinds[16] = {
      LaneKind::kAligned,         LaneKind::kRandomAxes,
      LaneKind::kBeyond90Degrees, LaneKind::kPerpendicular,
      LaneKind::kJustBelow90Degrees, LaneKind::kAntiParallel,
      LaneKind::kNearlyAntiParallel, LaneKind::kAntiParallelTieInA1,
      LaneKind::kTieInA2,         LaneKind::kNearTieInA2,
      LaneKind::kNearSingular,    LaneKind::kSingular,
      LaneKind::kDeactivatedByFlag, LaneKind::kAligned,
      LaneKind::kRandomAxes,      LaneKind::kAligned};
  return kKinds[world % 16];
}

// Unit vector rounded to float, so kernel and reference share it exactly.
Vec3d FloatUnit(const Vec3d& v) { return ToFloat(v.normalized()); }

// b rotated towards a random perpendicular by `angle`.
Vec3d Tilted(Random& random, const Vec3d& b, double angle) {
  return std::cos(angle) * b + std::sin(angle) * random.Perpendicular(b);
}

class HingeRotationTest : public PartTestBase<HingeRotationKernels> {
 protected:
  void SetUp() override {
    SetUpBodies("hinge", PartKind::kHingeRotation);
    const std::size_t world_count = GetParam().world_count;
    geometry_ = std::make_unique<PartBlocks<HingeRotationGeometry>>(blocks());
    parts_ = std::make_unique<PartBlocks<HingeRotationLanes>>(blocks());
    reference_.resize(world_count);
    for (std::size_t world = 0; world < world_count; ++world) FillWorld(world);
  }

  void FillWorld(std::size_t world) {
    Random random(3141592u + 6700417u * unsigned(world));
    BodyState body1 = RandomBodyState(random);
    BodyState body2 = RandomBodyState(random);
    const auto sign = [&] { return random.Uniform(0, 1) < 0.5 ? -1.0 : 1.0; };
    Vec3d a1 = FloatUnit(random.UnitVector());
    Vec3d a2;
    switch (KindOfWorld(world)) {
      case LaneKind::kRandomAxes: a2 = FloatUnit(random.UnitVector()); break;
      case LaneKind::kBeyond90Degrees:
        a2 = FloatUnit(Tilted(random, a1, std::acos(random.Uniform(-0.95, -0.05))));
        break;
      case LaneKind::kPerpendicular: a2 = FloatUnit(random.Perpendicular(a1)); break;
      case LaneKind::kJustBelow90Degrees: a2 = FloatUnit(Tilted(random, a1, std::acos(0.05))); break;
      case LaneKind::kAntiParallel: a2 = -a1; break;
      case LaneKind::kNearlyAntiParallel: a2 = FloatUnit(-Tilted(random, a1, 1e-4)); break;
      case LaneKind::kAntiParallelTieInA1:
        a1 = FloatUnit(Vec3d(sign(), sign(), random.Uniform(-1.5, 1.5)));
        a2 = -a1;
        break;
      case LaneKind::kTieInA2:
        a2 = FloatUnit(Vec3d(sign(), sign(), random.Uniform(-1.5, 1.5)));
        a1 = FloatUnit(Tilted(random, a2, random.Uniform(0, 0.5)));
        break;
      case LaneKind::kNearTieInA2: {
        a2 = FloatUnit(Vec3d(sign(), sign(), random.Uniform(-1.5, 1.5)));
        const float x = std::nextafter(std::abs(float(a2.y())), 2.0f);
        a2.x() = std::copysign(double(x), a2.x());
        a1 = FloatUnit(Tilted(random, a2, random.Uniform(0, 0.5)));
        break;
      }
      case LaneKind::kNearSingular: {
        // Both bodies share a rotation whose local z is a1; their weak
        // inertia axis (local y) lies across the hinge, so K's eigenvalues
        // are ~1 and ~1e-3.
        body2.rotation = body1.rotation;
        for (BodyState* body : {&body1, &body2}) {
          body->inertia_rotation = {0.f, 0.f, 0.f, 1.f};
          const float scale = float(random.LogUniform(0.3, 3.0));
          body->inv_inertia_diagonal = {scale, 1e-3f * scale, scale};
        }
        a1 = FloatUnit(ToQuatd(body1.rotation) * Vec3d(0, 0, 1));
        a2 = FloatUnit(Tilted(random, a1, 0.01));
        break;
      }
      case LaneKind::kSingular:
        body1.inv_inertia_diagonal = body2.inv_inertia_diagonal = {0.f, 0.f, 0.f};
        a2 = FloatUnit(Tilted(random, a1, random.Uniform(0, 0.5)));
        break;
      default: a2 = FloatUnit(Tilted(random, a1, random.Uniform(0, 0.5))); break;
    }
    bodies_->Set(world, 0, body1);
    bodies_->Set(world, 1, body2);
    HingeRotationGeometry& g = (*geometry_)[Block(world)];
    SetLaneVec3(g.hinge_axis1, Lane(world), a1);
    SetLaneVec3(g.hinge_axis2, Lane(world), a2);
    SetTotalLambda(*parts_, world,
                   {float(random.Uniform(-1, 1)), float(random.Uniform(-1, 1))});
  }

  const HingeRotationGeometry& G(std::size_t w) const { return (*geometry_)[Block(w)]; }
  Vec3d A1(std::size_t w) const { return LaneVec3(G(w).hinge_axis1, Lane(w)); }
  Vec3d A2(std::size_t w) const { return LaneVec3(G(w).hinge_axis2, Lane(w)); }
  const HingeRotationLanes& Part(std::size_t w) const { return (*parts_)[Block(w)]; }
  Vec2d Lambda(std::size_t world) const {
    const auto l = GetTotalLambda(*parts_, world);
    return Vec2d(l[0], l[1]);
  }
  bool Repaired(std::size_t w) const { return A1(w).dot(A2(w)) <= kRepairBelowDot; }
  // How much the repair amplifies float rounding of the axes: normalising
  // the part of a2 across a1 divides by its length (perp(a1) replaces it
  // below 1e-3).
  double AxisCondition(std::size_t w) const {
    if (!Repaired(w)) return 1.0;
    const Vec3d across = A2(w) - A1(w).dot(A2(w)) * A1(w);
    return across.squaredNorm() < 1e-6 ? 1.0 : 1.0 / across.norm();
  }
  // cond(K) of the reference's effective mass (1 for deactivated lanes),
  // times the axes' own amplification.
  double ConditionOf(std::size_t w) const {
    const Mat22d& k_inv = reference_[w].EffectiveMass();
    return (k_inv.isZero(0.0) ? 1.0 : Condition<2>(k_inv)) * AxisCondition(w);
  }

  void CalculateProperties() {
    for (std::size_t block = 0; block < blocks(); ++block) {
      kernels_->calculate_properties(Pair(block), (*geometry_)[block], (*parts_)[block]);
    }
    for (std::size_t w = 0; w < worlds(); ++w) {
      reference_[w].SetTotalLambda(Lambda(w));
      reference_[w].CalculateConstraintProperties(Body(w, 0), A1(w), Body(w, 1), A2(w));
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
        for (float& c : state.angular_velocity) c += float(random.Uniform(-1, 1));
        bodies_->Set(w, body, state);
      }
    }
  }

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
          kernels_->warm_start(Pair(block), (*parts_)[block], ratio);
          return false;
        },
        [&](std::size_t w, RefBody& b1, RefBody& b2) {
          reference_[w].WarmStart(b1, b2, ratio);
          return false;
        });
  }

  // J v = ((b2 x a1).(w2 - w1), (c2 x a1).(w2 - w1)); when the terms of a row
  // nearly cancel, its float rounding relative to |J v| grows by
  // |w1 - w2| / |J v| (|e x a1| <= 1), and dL = -K^-1 J v inherits that.
  double VelocityErrorCancellation(std::size_t w) const {
    const RefBody b1 = Body(w, 0), b2 = Body(w, 1);
    const Vec2d jv = reference::HingeRotationVelocityError(b1, A1(w), b2, A2(w));
    const double terms = std::sqrt(2.0) * (b1.AngularVelocity() - b2.AngularVelocity()).norm();
    return std::clamp(terms / jv.norm(), 1.0, 1e12);
  }

  void SolveVelocity() {
    std::vector<double> condition(worlds());
    for (std::size_t w = 0; w < worlds(); ++w) {
      condition[w] = ConditionOf(w) * VelocityErrorCancellation(w);
    }
    PartHooks hooks = Hooks();
    hooks.condition = [&](std::size_t w) { return condition[w]; };
    CompareVerbOnEveryLane(
        "velocity solve", *bodies_, hooks,
        [&](std::size_t block) { return kernels_->solve_velocity(Pair(block), (*parts_)[block]); },
        [&](std::size_t w, RefBody& b1, RefBody& b2) {
          return reference_[w].SolveVelocityConstraint(b1, b2);
        });
  }

  // The repaired a2 is only 0.0101 of a1 away from 90 deg, so the second
  // row e x a1 is ~1/100 of the first and C = (a1.b2, a1.c2) lies along it:
  // L = -beta K^-1 C is ~100x larger than the rotation P it produces, and
  // float rounding of L (already cond(K) times eps) reaches P amplified by
  // that ratio. Jolt's float code has the same error there; the repair itself
  // is checked precisely by AxesRepairAndPerpendicularChoiceFollowJolt.
  PartHooks PositionHooks() {
    PartHooks hooks = Hooks();
    hooks.condition = [this](std::size_t w) {
      constexpr double kRepairedRowRatio = 0.01 / 0.99;
      return ConditionOf(w) * (Repaired(w) ? 1.0 / kRepairedRowRatio : 1.0);
    };
    return hooks;
  }

  void SolvePosition(float baumgarte) {
    CompareVerbOnEveryLane(
        "position solve", *bodies_, PositionHooks(),
        [&](std::size_t block) {
          return kernels_->solve_position(Pair(block), (*parts_)[block], baumgarte);
        },
        [&](std::size_t w, RefBody& b1, RefBody& b2) {
          return reference_[w].SolvePositionConstraint(b1, b2, baumgarte);
        });
  }

  std::unique_ptr<PartBlocks<HingeRotationGeometry>> geometry_;
  std::unique_ptr<PartBlocks<HingeRotationLanes>> parts_;
  std::vector<RefHingeRotation> reference_;
};

TEST_P(HingeRotationTest, CalculatePropertiesMatchesReference) {
  CalculateProperties();
  LaneFlags active;
  for (std::size_t w = 0; w < worlds(); ++w) {
    const HingeRotationLanes& part = Part(w);
    const RefHingeRotation& ref = reference_[w];
    const std::size_t lane = Lane(w);
    const double axes = Tolerance(1.0, AxisCondition(w));  // unit vectors
    ExpectVec3Near(LaneVec3(part.a1, lane), ref.A1(), 0.0, WorldLabel(w, "a1"));
    ExpectVec3Near(LaneVec3(part.b2, lane), ref.B2(), axes, WorldLabel(w, "b2"));
    ExpectVec3Near(LaneVec3(part.c2, lane), ref.C2(), axes, WorldLabel(w, "c2"));
    ExpectVec3Near(LaneVec3(part.b2_x_a1, lane), ref.B2xA1(), axes, WorldLabel(w, "b2 x a1"));
    ExpectVec3Near(LaneVec3(part.c2_x_a1, lane), ref.C2xA1(), axes, WorldLabel(w, "c2 x a1"));
    // |I^-1| <= largest diagonal entry; |e x a1| <= 1.
    const double inertia1 = Tolerance(Body(w, 0).inv_inertia_diagonal.maxCoeff(), AxisCondition(w));
    const double inertia2 = Tolerance(Body(w, 1).inv_inertia_diagonal.maxCoeff(), AxisCondition(w));
    ExpectVec3Near(LaneVec3(part.inv_i1_b2_x_a1, lane), ref.InvI1() * ref.B2xA1(), inertia1,
                   WorldLabel(w, "I1^-1 (b2 x a1)"));
    ExpectVec3Near(LaneVec3(part.inv_i1_c2_x_a1, lane), ref.InvI1() * ref.C2xA1(), inertia1,
                   WorldLabel(w, "I1^-1 (c2 x a1)"));
    ExpectVec3Near(LaneVec3(part.inv_i2_b2_x_a1, lane), ref.InvI2() * ref.B2xA1(), inertia2,
                   WorldLabel(w, "I2^-1 (b2 x a1)"));
    ExpectVec3Near(LaneVec3(part.inv_i2_c2_x_a1, lane), ref.InvI2() * ref.C2xA1(), inertia2,
                   WorldLabel(w, "I2^-1 (c2 x a1)"));
    const Mat22d& k_inv = ref.EffectiveMass();
    const double k_tolerance = Tolerance(k_inv.cwiseAbs().maxCoeff(), ConditionOf(w));
    EXPECT_NEAR(part.effective_mass.xx[lane], k_inv(0, 0), k_tolerance) << "K^-1 of world " << w;
    EXPECT_NEAR(part.effective_mass.xy[lane], k_inv(0, 1), k_tolerance) << "K^-1 of world " << w;
    EXPECT_NEAR(part.effective_mass.yy[lane], k_inv(1, 1), k_tolerance) << "K^-1 of world " << w;
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

// The repair and the perpendicular choice from their definitions (spec 2.5),
// read back from the kernel's basis: a2' = b2 x c2 is the axis it used.
TEST_P(HingeRotationTest, AxesRepairAndPerpendicularChoiceFollowJolt) {
  CalculateProperties();
  // 0.01 / |0.99 p + 0.01 a1| with unit p _|_ a1: a1.a2' of every repaired lane.
  const double repaired_dot = 0.01 / std::hypot(0.99, 0.01);
  for (std::size_t w = 0; w < worlds(); ++w) {
    const Vec3d a1 = A1(w), a2 = A2(w);
    const Vec3d b2 = LaneVec3(Part(w).b2, Lane(w)), c2 = LaneVec3(Part(w).c2, Lane(w));
    const Vec3d used_a2 = b2.cross(c2);
    const double tolerance = Tolerance(1.0, AxisCondition(w));
    EXPECT_NEAR(used_a2.norm(), 1.0, tolerance) << WorldLabel(w, "|b2 x c2|");
    EXPECT_NEAR(b2.dot(c2), 0.0, tolerance) << WorldLabel(w, "b2 . c2");
    // Jolt's perpendicular zeroes exactly one of x, y.
    EXPECT_TRUE(b2.x() == 0.0 || b2.y() == 0.0) << WorldLabel(w, "b2") << ": " << b2.transpose();
    if (!Repaired(w)) {
      ExpectVec3Near(used_a2, a2, tolerance, WorldLabel(w, "unrepaired a2"));
      // a2 is the float input, so the |x| > |y| choice is exact: ties take (0, z, -y).
      if (std::abs(a2.x()) > std::abs(a2.y())) {
        EXPECT_EQ(b2.y(), 0.0) << WorldLabel(w, "b2 with |a2.x| > |a2.y|");
      } else {
        EXPECT_EQ(b2.x(), 0.0) << WorldLabel(w, "b2 with |a2.x| <= |a2.y|");
      }
      continue;
    }
    // Repaired: just inside 90 deg of a1, in the plane of a1 and the part of
    // a2 across it, or of a1 and perp(a1) where a2 = -a1.
    EXPECT_NEAR(a1.dot(used_a2), repaired_dot, tolerance) << WorldLabel(w, "a1 . repaired a2");
    Vec3d across = a2 - a1.dot(a2) * a1;
    if (across.squaredNorm() < 1e-6) {
      across = std::abs(a1.x()) > std::abs(a1.y())
                   ? Vec3d(a1.z(), 0, -a1.x()) / std::hypot(a1.x(), a1.z())
                   : Vec3d(0, a1.z(), -a1.y()) / std::hypot(a1.y(), a1.z());
    }
    const Vec3d expected = (0.99 * across.normalized() + 0.01 * a1).normalized();
    ExpectVec3Near(used_a2, expected, tolerance, WorldLabel(w, "repaired a2"));
  }
}

TEST_P(HingeRotationTest, WarmStartScalesAndAppliesImpulse) {
  CalculateProperties();
  WarmStart(0.75f);
}

TEST_P(HingeRotationTest, WarmStartWithRatioZeroAppliesNothing) {
  CalculateProperties();
  const BodyBlocks before = *bodies_;
  for (std::size_t block = 0; block < blocks(); ++block) {
    kernels_->warm_start(Pair(block), (*parts_)[block], 0.0f);
  }
  for (std::size_t w = 0; w < worlds(); ++w) {
    EXPECT_EQ(Lambda(w), Vec2d::Zero()) << "world " << w;
  }
  ExpectBodiesUnchanged(before, [](std::size_t, std::size_t) { return true; },
                        "warm start with ratio 0");
}

TEST_P(HingeRotationTest, VelocitySolveMatchesReferenceAndZeroesVelocityError) {
  CalculateProperties();
  DeactivateFlaggedLanes();
  WarmStart(1.0f);
  for (int iteration = 0; iteration < 3; ++iteration) {
    KickVelocities(17u + unsigned(iteration));
    SolveVelocity();
  }
  // Invariant: one solve of an exactly inverted 2x2 system leaves J v = 0 (to
  // rounding, amplified by cond(K)) in every active lane.
  for (std::size_t w = 0; w < worlds(); ++w) {
    if (!reference_[w].IsActive()) continue;
    const RefBody b1 = Body(w, 0), b2 = Body(w, 1);
    const Vec2d jv = reference::HingeRotationVelocityError(b1, A1(w), b2, A2(w));
    const double speed = std::max(b1.angular_velocity.norm(), b2.angular_velocity.norm());
    EXPECT_LE(jv.cwiseAbs().maxCoeff(), Tolerance(speed, ConditionOf(w)))
        << "J v after the velocity solve of world " << w;
  }
}

TEST_P(HingeRotationTest, PositionSolveMatchesReferenceAndMovesOnlyDynamicBodies) {
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

TEST_P(HingeRotationTest, DeactivatedAndSingularLanesStayFiniteAndApplyNothing) {
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
      EXPECT_EQ(Lambda(w), Vec2d::Zero()) << "inactive world " << w;
    }
  }
  ExpectBodiesUnchanged(
      before, [&](std::size_t w, std::size_t) { return !reference_[w].IsActive(); },
      "inactive lane");
}

TEST_P(HingeRotationTest, GetSetSaveRestoreOfAccumulatedImpulse) {
  CalculateProperties();
  for (std::size_t w = 0; w < worlds(); ++w) {
    const std::array<float, 2> value{float(w) + 0.25f, -float(w)};
    SetTotalLambda(*parts_, w, value);
    EXPECT_EQ(GetTotalLambda(*parts_, w), value);
  }
  WarmStart(1.0f);
  const auto saved = SavePartState(*parts_);
  std::vector<std::array<float, 2>> at_save;
  for (std::size_t w = 0; w < worlds(); ++w) at_save.push_back(GetTotalLambda(*parts_, w));
  KickVelocities(5u);
  SolveVelocity();  // changes the impulses
  RestorePartState(*parts_, saved);
  for (std::size_t w = 0; w < worlds(); ++w) {
    const auto restored = GetTotalLambda(*parts_, w);
    EXPECT_TRUE(BitEqual(&restored, &at_save[w], sizeof(restored))) << "world " << w;
  }
}

std::vector<PartCase<HingeRotationKernels>> AllCases() {
  static const std::vector<std::pair<MotionType, MotionType>> pairings = {
      {MotionType::kDynamic, MotionType::kDynamic},
      {MotionType::kDynamic, MotionType::kStatic},
      {MotionType::kStatic, MotionType::kDynamic},
      {MotionType::kKinematic, MotionType::kDynamic},
      {MotionType::kDynamic, MotionType::kKinematic},
      {MotionType::kKinematic, MotionType::kStatic},
  };
  return AllPartCases<HingeRotationKernels>(pairings);
}

INSTANTIATE_TEST_SUITE_P(EveryTarget, HingeRotationTest, ::testing::ValuesIn(AllCases()),
                         PartCaseName<HingeRotationKernels>);

}  // namespace
}  // namespace manyworlds::testing
