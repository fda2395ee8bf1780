// AngleConstraintPart kernels, every verb and every CalculateProperties variant
// (x spring mode), every lane against the scalar reference, on every Highway
// target this CPU supports, for 1, 7, 16 and 1000 worlds and every motion-type
// pairing; invariants of the solves; and the analytic spring trajectory.
#include <gtest/gtest.h>

#include <cfloat>
#include <memory>
#include <vector>

#include "batch/part_binding.h"
#include "batch/part_state.h"
#include "batch/world_blocks.h"
#include "kernels/angle.h"
#include "reference/angle_part.h"
#include "tests/spring_row_test_support.h"
#include "tests/test_support.h"

namespace manyworlds::testing {
namespace {

using RefAngle = reference::AnglePart<double>;

class AngleTest : public PartTestBase<AngleKernels> {
 protected:
  void SetUp() override {
    SetUpBodies("hinge_limit", PartKind::kAngle);
    geometry_ = std::make_unique<PartBlocks<AngleGeometry>>(blocks());
    parts_ = std::make_unique<PartBlocks<AngleLanes>>(blocks());
    FillAllWorlds();
  }

  // Every variant starts from the same random worlds, impulses and a fresh part.
  void FillAllWorlds() {
    *parts_ = PartBlocks<AngleLanes>(blocks());
    reference_.assign(worlds(), RefAngle{});
    for (std::size_t world = 0; world < worlds(); ++world) FillWorld(world);
  }

  // Random and different in every world; the reference reads back the float
  // values the blocks hold, so both start from identical inputs.
  void FillWorld(std::size_t world) {
    Random random(1357911u + 7919u * unsigned(world));
    BodyState body1 = RandomBodyState(random);
    BodyState body2 = RandomBodyState(random);
    const RowKind kind = KindOfRowWorld(world);
    if (kind == RowKind::kNearSingular) {
      body1.inv_mass = body2.inv_mass = 1e-6f;
      body1.inv_inertia_diagonal = body2.inv_inertia_diagonal = {1e-6f, 1e-6f, 1e-6f};
    } else if (kind == RowKind::kSingular) {
      body1.inv_mass = body2.inv_mass = 0.0f;
      body1.inv_inertia_diagonal = body2.inv_inertia_diagonal = {0.f, 0.f, 0.f};
    }
    bodies_->Set(world, 0, body1);
    bodies_->Set(world, 1, body2);
    AngleGeometry& g = (*geometry_)[Block(world)];
    SetLaneVec3(g.axis, Lane(world), random.UnitVector());
    SetRandomRowSettings(random, kind, RowSettingsOf(g), Lane(world));
    SetTotalLambda(*parts_, world, float(random.Uniform(-1, 1)));
  }

  const AngleGeometry& G(std::size_t w) const { return (*geometry_)[Block(w)]; }
  const AngleProperties& P(std::size_t w) const { return (*parts_)[Block(w)].properties; }
  Vec3d Axis(std::size_t w) const { return LaneVec3(G(w).axis, Lane(w)); }
  double Error(std::size_t w) const { return G(w).error[Lane(w)]; }
  double Bias(std::size_t w) const { return G(w).bias[Lane(w)]; }
  double MinLambda(std::size_t w) const { return G(w).min_lambda[Lane(w)]; }
  double MaxLambda(std::size_t w) const { return G(w).max_lambda[Lane(w)]; }
  reference::SpringSettings<double> Settings(std::size_t w, SpringMode mode) const {
    return {ToReference(mode), G(w).spring.frequency_or_stiffness[Lane(w)],
            G(w).spring.damping[Lane(w)]};
  }
  double Lambda(std::size_t world) const { return GetTotalLambda(*parts_, world); }

  void KernelProperties(const VariantCase& v, std::size_t block) {
    const AngleGeometry& g = (*geometry_)[block];
    AngleLanes& part = (*parts_)[block];
    switch (v.variant) {
      case Variant::kBias: return kernels_->calculate_properties(Pair(block), g, part);
      case Variant::kFrequencyAndDamping:
        return kernels_->calculate_properties_with_frequency_and_damping(Pair(block), g, part,
                                                                         kDeltaTime);
      case Variant::kStiffnessAndDamping:
        return kernels_->calculate_properties_with_stiffness_and_damping(Pair(block), g, part,
                                                                         kDeltaTime);
      case Variant::kForLimit:
        return kernels_->calculate_properties_for_limit(Pair(block), g, part, kDeltaTime,
                                                        v.mode);
      case Variant::kForMotor:
        return kernels_->calculate_properties_for_motor(Pair(block), g, part, kDeltaTime,
                                                        v.mode);
    }
  }

  void ReferenceProperties(const VariantCase& v, std::size_t w) {
    RefAngle& ref = reference_[w];
    const RefBody b1 = Body(w, 0), b2 = Body(w, 1);
    const double dt = kDeltaTime;
    const double f = G(w).spring.frequency_or_stiffness[Lane(w)];
    const double d = G(w).spring.damping[Lane(w)];
    switch (v.variant) {
      case Variant::kBias:
        return ref.CalculateConstraintProperties(b1, b2, Axis(w), Bias(w));
      case Variant::kFrequencyAndDamping:
        return ref.CalculateConstraintPropertiesWithFrequencyAndDamping(
            dt, b1, b2, Axis(w), Bias(w), Error(w), f, d);
      case Variant::kStiffnessAndDamping:
        return ref.CalculateConstraintPropertiesWithStiffnessAndDamping(
            dt, b1, b2, Axis(w), Bias(w), Error(w), f, d);
      case Variant::kForLimit:
        return ref.CalculateConstraintPropertiesWithSettingsForLimit(
            dt, b1, b2, Axis(w), Bias(w), Error(w), Settings(w, v.mode));
      case Variant::kForMotor:
        return ref.CalculateConstraintPropertiesWithSettingsForMotor(
            dt, b1, b2, Axis(w), Bias(w), Error(w), Settings(w, v.mode));
    }
  }

  // The motor variant is defined (Jolt asserts) only with stiffness or damping.
  void PrepareVariant(const VariantCase& v) {
    FillAllWorlds();
    if (v.variant != Variant::kForMotor) return;
    for (std::size_t block = 0; block < blocks(); ++block) {
      MeetMotorPrecondition(v.mode, (*geometry_)[block].spring);
    }
  }

  void CalculateProperties(const VariantCase& v) {
    for (std::size_t w = 0; w < worlds(); ++w) reference_[w].SetTotalLambda(Lambda(w));
    for (std::size_t block = 0; block < blocks(); ++block) KernelProperties(v, block);
    for (std::size_t w = 0; w < worlds(); ++w) ReferenceProperties(v, w);
  }

  void ExpectPropertiesMatchReference() {
    LaneFlags active;
    for (std::size_t w = 0; w < worlds(); ++w) {
      const AngleProperties& p = P(w);
      const RefAngle& ref = reference_[w];
      const std::size_t lane = Lane(w);
      // I^-1 a: scale = |I^-1|, at most the largest diagonal entry (|a| = 1).
      ExpectVec3Near(LaneVec3(p.inv_i1_axis, lane), ref.InvI1Axis(),
                     Tolerance(Body(w, 0).inv_inertia_diagonal.maxCoeff()),
                     WorldLabel(w, "I1^-1 a"));
      ExpectVec3Near(LaneVec3(p.inv_i2_axis, lane), ref.InvI2Axis(),
                     Tolerance(Body(w, 1).inv_inertia_diagonal.maxCoeff()),
                     WorldLabel(w, "I2^-1 a"));
      // K is a sum of non-negative terms: no cancellation, so 1/K, the
      // softness and the bias are accurate relative to their own size.
      EXPECT_NEAR(p.effective_mass[lane], ref.EffectiveMass(), Tolerance(ref.EffectiveMass()))
          << "effective mass of world " << w;
      EXPECT_NEAR(p.spring.softness[lane], ref.Spring().Softness(),
                  Tolerance(ref.Spring().Softness()))
          << "softness of world " << w;
      EXPECT_NEAR(p.spring.bias[lane], ref.Spring().Bias(),
                  Tolerance(std::abs(Bias(w)) + std::abs(ref.Spring().Bias() - Bias(w))))
          << "bias of world " << w;
      EXPECT_EQ(Lambda(w), ref.GetTotalLambda()) << "impulse of world " << w;
      if (lane == 0) kernels_->is_active((*parts_)[Block(w)], active);
      EXPECT_EQ(active[lane] != 0.0f, ref.IsActive()) << "IsActive of world " << w;
    }
  }

  void DeactivateFlaggedLanes() {
    DeactivateWorlds(*parts_, reference_,
                     [](std::size_t w) { return KindOfRowWorld(w) == RowKind::kDeactivatedByFlag; });
  }

  // K is a scalar, so 1/K is as accurate as K; what amplifies rounding is
  // the cancellation in the velocity solve's -J v - (softness L + b), whose
  // condition number SolveVelocity() sets per world (1 for the other verbs).
  PartHooks Hooks() {
    return MakePartHooks(reference_, [this](std::size_t w) { return Lambda(w); },
                         [this](std::size_t w) {
                           return velocity_condition_.empty() ? 1.0 : velocity_condition_[w];
                         });
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

  // Condition number of the sum -J v - (softness L + b) before a velocity
  // solve: the sum of its terms' sizes over the size of the sum. After the
  // first iteration the sum is nearly zero while its terms are not, and the
  // impulse's rounding error is relative to the terms.
  double VelocityCondition(std::size_t w) const {
    const RefBody b1 = Body(w, 0), b2 = Body(w, 1);
    const RefAngle& ref = reference_[w];
    const double jv = reference::AngleVelocityError(b1, b2, Axis(w));
    const double magnitude = b1.AngularVelocity().norm() + b2.AngularVelocity().norm();
    const double velocity_bias = ref.Spring().GetBias(ref.GetTotalLambda());
    const double sum = std::abs(jv + velocity_bias);
    const double terms = magnitude + std::abs(ref.Spring().Softness() * ref.GetTotalLambda()) +
                         std::abs(ref.Spring().Bias());
    return sum > 0.0 ? std::max(1.0, terms / sum) : 1.0;
  }

  // After the first iteration of a step a single row is solved to rounding:
  // whether float rounding leaves an impulse of exactly zero in all 16 lanes
  // is then no property of the kernel, so later iterations compare the
  // "any lane applied" flag only where `compare_applied`.
  void SolveVelocity(bool compare_applied = true) {
    std::vector<bool> reference_applied(blocks(), false);
    velocity_condition_.resize(worlds());
    for (std::size_t w = 0; w < worlds(); ++w) {
      reference_[w].SetTotalLambda(Lambda(w));
      velocity_condition_[w] = VelocityCondition(w);
    }
    CompareVerbOnEveryLane(
        "velocity solve", *bodies_, Hooks(),
        [&](std::size_t block) {
          // CompareVerbOnEveryLane runs the reference of every world first.
          const bool applied =
              kernels_->solve_velocity(Pair(block), (*geometry_)[block], (*parts_)[block]);
          return compare_applied ? applied : bool(reference_applied[block]);
        },
        [&](std::size_t w, RefBody& b1, RefBody& b2) {
          const bool applied = reference_[w].SolveVelocityConstraint(
              b1, b2, Axis(w), MinLambda(w), MaxLambda(w));
          if (applied) reference_applied[Block(w)] = true;
          return applied;
        });
    velocity_condition_.clear();
  }

  void SolvePosition(float baumgarte) {
    CompareVerbOnEveryLane(
        "position solve", *bodies_, Hooks(),
        [&](std::size_t block) {
          return kernels_->solve_position(Pair(block), (*geometry_)[block], (*parts_)[block],
                                          baumgarte);
        },
        [&](std::size_t w, RefBody& b1, RefBody& b2) {
          return reference_[w].SolvePositionConstraint(b1, b2, Error(w), baumgarte);
        });
  }

  std::unique_ptr<PartBlocks<AngleGeometry>> geometry_;
  std::unique_ptr<PartBlocks<AngleLanes>> parts_;
  std::vector<RefAngle> reference_;
  std::vector<double> velocity_condition_;  // empty: 1 in every world
};

TEST_P(AngleTest, CalculatePropertiesMatchesReferenceInEveryVariant) {
  for (const VariantCase& v : AllVariants()) {
    SCOPED_TRACE(v.name);
    PrepareVariant(v);
    CalculateProperties(v);
    ExpectPropertiesMatchReference();
    for (std::size_t w = 0; w < worlds(); ++w) {
      const bool singular = KindOfRowWorld(w) == RowKind::kSingular ||
                            (bodies_->motion_type(0) != MotionType::kDynamic &&
                             bodies_->motion_type(1) != MotionType::kDynamic);
      if (singular) {
        EXPECT_EQ(P(w).effective_mass[Lane(w)], 0.0f) << "singular world " << w;
        EXPECT_EQ(Lambda(w), 0.0) << "singular world " << w << " keeps an impulse";
      }
    }
  }
}

// Jolt asserts that a motor spring has stiffness or damping; a lane that has
// neither is hard here (as in the two dedicated variants), never NaN.
TEST_P(AngleTest, MotorWithoutStiffnessOrDampingIsHard) {
  for (const SpringMode mode : {SpringMode::kFrequencyAndDamping, SpringMode::kStiffnessAndDamping,
                                SpringMode::kMassNormalizedStiffnessAndDamping}) {
    SCOPED_TRACE(SpringModeName(mode));
    FillAllWorlds();
    for (std::size_t block = 0; block < blocks(); ++block) {
      (*geometry_)[block].spring = SpringSettingsLanes{};  // all zero
    }
    for (std::size_t w = 0; w < worlds(); ++w) reference_[w].SetTotalLambda(Lambda(w));
    for (std::size_t block = 0; block < blocks(); ++block) {
      kernels_->calculate_properties_for_motor(Pair(block), (*geometry_)[block],
                                               (*parts_)[block], kDeltaTime, mode);
    }
    for (std::size_t w = 0; w < worlds(); ++w) {
      ReferenceProperties({Variant::kBias, mode, "bias"}, w);
    }
    ExpectPropertiesMatchReference();
  }
}

TEST_P(AngleTest, WarmStartScalesAndAppliesImpulse) {
  for (const VariantCase& v : AllVariants()) {
    SCOPED_TRACE(v.name);
    PrepareVariant(v);
    CalculateProperties(v);
    WarmStart(0.75f);
  }
}

TEST_P(AngleTest, WarmStartWithRatioZeroAppliesNothing) {
  const VariantCase& v = AllVariants()[3];  // for_limit: soft and hard lanes
  PrepareVariant(v);
  CalculateProperties(v);
  const BodyBlocks before = *bodies_;
  for (std::size_t block = 0; block < blocks(); ++block) {
    kernels_->warm_start(Pair(block), (*parts_)[block], 0.0f);
  }
  for (std::size_t w = 0; w < worlds(); ++w) EXPECT_EQ(Lambda(w), 0.0) << "world " << w;
  ExpectBodiesUnchanged(before, [](std::size_t, std::size_t) { return true; },
                        "warm start with ratio 0");
}

TEST_P(AngleTest, VelocitySolveMatchesReferenceClampsAndSatisfiesTheRow) {
  for (const VariantCase& v : AllVariants()) {
    SCOPED_TRACE(v.name);
    PrepareVariant(v);
    CalculateProperties(v);
    DeactivateFlaggedLanes();
    WarmStart(1.0f);
    for (int iteration = 0; iteration < 3; ++iteration) SolveVelocity(iteration == 0);
    for (std::size_t w = 0; w < worlds(); ++w) {
      // Limit clamping: the accumulated impulse never leaves [min, max].
      EXPECT_GE(Lambda(w), MinLambda(w)) << "impulse below its minimum in world " << w;
      EXPECT_LE(Lambda(w), MaxLambda(w)) << "impulse above its maximum in world " << w;
      // Where the last solve was not clamped, the row holds exactly:
      // J v + softness L + b = 0 (J v = -b for a hard row, 0 when b = 0).
      if (!reference_[w].IsActive() || Lambda(w) == MinLambda(w) || Lambda(w) == MaxLambda(w)) {
        continue;
      }
      const RefBody b1 = Body(w, 0), b2 = Body(w, 1);
      const double jv = reference::AngleVelocityError(b1, b2, Axis(w));
      const double softness = P(w).spring.softness[Lane(w)];
      const double bias = P(w).spring.bias[Lane(w)];
      const double speed = std::max(b1.angular_velocity.norm(), b2.angular_velocity.norm());
      const double row = jv + softness * Lambda(w) + bias;
      EXPECT_LE(std::abs(row),
                Tolerance(speed + std::abs(softness * Lambda(w)) + std::abs(bias)))
          << "J v + softness L + b after the velocity solve of world " << w;
    }
  }
}

TEST_P(AngleTest, PositionSolveMatchesReferenceAndSkipsSoftAndZeroErrorLanes) {
  for (const VariantCase& v : AllVariants()) {
    SCOPED_TRACE(v.name);
    PrepareVariant(v);
    CalculateProperties(v);
    DeactivateFlaggedLanes();
    const BodyBlocks before = *bodies_;
    SolvePosition(0.2f);
    ExpectBodiesUnchanged(
        before,
        [&](std::size_t w, std::size_t body) {
          return bodies_->motion_type(body) != MotionType::kDynamic || Error(w) == 0.0 ||
                 P(w).spring.softness[Lane(w)] != 0.0f;
        },
        "position solve of a soft lane, a zero error or a non-dynamic body");
  }
}

TEST_P(AngleTest, DeactivatedAndSingularLanesStayFiniteAndApplyNothing) {
  const VariantCase& v = AllVariants()[1];  // with frequency and damping
  PrepareVariant(v);
  CalculateProperties(v);
  const PartBlocks<AngleLanes> calculated = *parts_;
  DeactivateFlaggedLanes();
  const BodyBlocks before = *bodies_;
  for (std::size_t block = 0; block < blocks(); ++block) {
    kernels_->warm_start(Pair(block), (*parts_)[block], 1.0f);
    kernels_->solve_velocity(Pair(block), (*geometry_)[block], (*parts_)[block]);
    kernels_->solve_position(Pair(block), (*geometry_)[block], (*parts_)[block], 0.2f);
  }
  for (std::size_t w = 0; w < worlds(); ++w) {
    if (reference_[w].IsActive()) continue;
    EXPECT_EQ(Lambda(w), 0.0) << "inactive world " << w;
    EXPECT_EQ(P(w).effective_mass[Lane(w)], 0.0f) << "inactive world " << w;
    // Jolt's Deactivate leaves the SpringPart as it was (spec 1.3).
    const AngleProperties& was = calculated[Block(w)].properties;
    EXPECT_EQ(P(w).spring.softness[Lane(w)], was.spring.softness[Lane(w)]) << "world " << w;
    EXPECT_EQ(P(w).spring.bias[Lane(w)], was.spring.bias[Lane(w)]) << "world " << w;
  }
  ExpectBodiesUnchanged(
      before, [&](std::size_t w, std::size_t) { return !reference_[w].IsActive(); },
      "inactive lane");
}

TEST_P(AngleTest, GetSetSaveRestoreOfAccumulatedImpulse) {
  const VariantCase& v = AllVariants()[3];
  PrepareVariant(v);
  CalculateProperties(v);
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

std::vector<PartCase<AngleKernels>> AllCases() {
  static const std::vector<std::pair<MotionType, MotionType>> pairings = {
      {MotionType::kDynamic, MotionType::kDynamic},
      {MotionType::kDynamic, MotionType::kStatic},
      {MotionType::kStatic, MotionType::kDynamic},
      {MotionType::kKinematic, MotionType::kDynamic},
      {MotionType::kDynamic, MotionType::kKinematic},
      {MotionType::kKinematic, MotionType::kStatic},
  };
  return AllPartCases<AngleKernels>(pairings);
}

INSTANTIATE_TEST_SUITE_P(EveryTarget, AngleTest, ::testing::ValuesIn(AllCases()),
                         PartCaseName<AngleKernels>);

// ------------------------------------------------------------ analytic check

// The angular twin of Jolt's TestDistanceSpring (and a clean version of
// TestHingeSpring, spec 6): a body rotated 100 degrees from its rest angle
// about a fixed world axis a = +z, no gravity, held to the static world by a
// spring of f = 2 Hz, zeta = 0.1, 120 steps of 1/60 s, C = theta. Each lane has
// its own (isotropic) inertia, so K = 1/I whatever the orientation and the
// test integrates theta += w dt itself instead of the quaternion. Jolt's step
// order: properties, warm start, 10 velocity iterations, integration, 2
// position iterations (which a soft row must skip).
class AngleSpringTest : public ::testing::TestWithParam<const AngleKernels*> {};

TEST_P(AngleSpringTest, OneBodySpringFollowsImplicitEulerRecursion) {
  const AngleKernels& kernels = *GetParam();
  const double start_angle = 100.0 * M_PI / 180.0;
  for (const VariantCase& v : SpringVariants()) {
    SCOPED_TRACE(v.name);
    BodyBlocks bodies({MotionType::kStatic, MotionType::kDynamic}, kLaneWidth);
    const PartBinding spring = BindPart(bodies, "spring", PartKind::kAngle, 0, 1);
    PartBlocks<AngleGeometry> geometry(1);
    PartBlocks<AngleLanes> part(1);
    LaneArray angle;
    Random random(86420u);
    std::vector<SpringTrajectoryPoint> expected(kLaneWidth, {start_angle, 0.0});
    std::vector<double> k_over_i(kLaneWidth), c_over_i(kLaneWidth);
    for (std::size_t lane = 0; lane < kLaneWidth; ++lane) {
      BodyState body;
      const float inv_inertia = float(random.LogUniform(0.01, 10.0));
      body.inv_mass = 1.0f;
      body.inv_inertia_diagonal = {inv_inertia, inv_inertia, inv_inertia};
      bodies.Set(lane, 1, body);
      angle[lane] = float(start_angle);
      AngleGeometry& g = geometry[0];
      SetLaneVec3(g.axis, lane, Vec3d::UnitZ());
      g.min_lambda[lane] = -FLT_MAX;
      g.max_lambda[lane] = FLT_MAX;
      AnalyticSpringParameters(v.mode, 1.0 / inv_inertia, g.spring.frequency_or_stiffness[lane],
                               g.spring.damping[lane]);
      SpringPerUnitMass(v.mode, g.spring.frequency_or_stiffness[lane], g.spring.damping[lane],
                        inv_inertia, k_over_i[lane], c_over_i[lane]);
    }
    BodyPair pair = PairInBlock(bodies, spring, 0);
    BodyLanes& body = *pair.body2;
    AngleGeometry& g = geometry[0];
    for (int step = 0; step < 120; ++step) {
      g.error = angle;
      switch (v.variant) {
        case Variant::kFrequencyAndDamping:
          kernels.calculate_properties_with_frequency_and_damping(pair, g, part[0], kDeltaTime);
          break;
        case Variant::kStiffnessAndDamping:
          kernels.calculate_properties_with_stiffness_and_damping(pair, g, part[0], kDeltaTime);
          break;
        case Variant::kForLimit:
          kernels.calculate_properties_for_limit(pair, g, part[0], kDeltaTime, v.mode);
          break;
        default:
          kernels.calculate_properties_for_motor(pair, g, part[0], kDeltaTime, v.mode);
          break;
      }
      kernels.warm_start(pair, part[0], 1.0f);
      for (int i = 0; i < 10; ++i) kernels.solve_velocity(pair, g, part[0]);
      for (std::size_t lane = 0; lane < kLaneWidth; ++lane) {
        angle[lane] += kDeltaTime * body.angular_velocity.z[lane];
      }
      for (int i = 0; i < 2; ++i) {
        EXPECT_FALSE(kernels.solve_position(pair, g, part[0], 0.2f)) << "step " << step;
      }
      for (std::size_t lane = 0; lane < kLaneWidth; ++lane) {
        expected[lane] = ImplicitEulerSpringStep(expected[lane], kDeltaTime, k_over_i[lane],
                                                 c_over_i[lane]);
        EXPECT_NEAR(angle[lane], expected[lane].x, 5e-6)
            << "angle of lane " << lane << " after step " << step + 1;
        EXPECT_EQ(body.angular_velocity.x[lane], 0.0f) << "lane " << lane;
        EXPECT_EQ(body.angular_velocity.y[lane], 0.0f) << "lane " << lane;
        EXPECT_EQ(body.linear_velocity.x[lane], 0.0f) << "lane " << lane;
      }
    }
  }
}

INSTANTIATE_TEST_SUITE_P(EveryTarget, AngleSpringTest,
                         ::testing::ValuesIn(SupportedKernels<AngleKernels>()),
                         TableName<AngleKernels>);

}  // namespace
}  // namespace manyworlds::testing
