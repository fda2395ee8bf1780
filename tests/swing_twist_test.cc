// SwingTwistConstraintPart kernels, every verb, every lane against
// reference/swing_twist_part.h, on every Highway target this CPU supports,
// for 1, 7, 16 and 1000 worlds, every motion-type pairing of the two bodies
// and every configuration of SwingTwistConfigs() (cone / pyramid; locked,
// limited and free axes). The decomposition and the clamp on their own are in
// swing_twist_clamp_test.cc.
#include <gtest/gtest.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "batch/part_binding.h"
#include "batch/part_state.h"
#include "batch/world_blocks.h"
#include "kernels/swing_twist.h"
#include "reference/swing_twist_part.h"
#include "tests/swing_twist_test_support.h"
#include "tests/test_support.h"

namespace manyworlds::testing {
namespace {

// What kind of lane a world is. Rotations: inside the limits, outside them,
// each axis either way, twist near a half turn, or an exact half-turn swing
// (s == 0: body 1 and both constraint frames identity). Some worlds have
// immovable dynamic bodies (every row K == 0, a singular rotation-Euler K),
// some are deactivated explicitly after CalculateProperties.
enum class LaneKind {
  kInside, kOutside, kMixed, kTwistNearHalfTurn, kHalfTurnSwing, kSingular, kDeactivatedByFlag
};

LaneKind KindOfWorld(std::size_t world) {
  switch (world % 8) {
    case 1: return LaneKind::kInside;
    case 2: return LaneKind::kOutside;
    case 3: return LaneKind::kTwistNearHalfTurn;
    case 5: return LaneKind::kSingular;
    case 6: return LaneKind::kDeactivatedByFlag;
    case 7: return LaneKind::kHalfTurnSwing;
    default: return LaneKind::kMixed;
  }
}

RotationKind RotationKindOf(LaneKind kind) {
  switch (kind) {
    case LaneKind::kInside: return RotationKind::kInside;
    case LaneKind::kOutside:
    case LaneKind::kSingular:
    case LaneKind::kDeactivatedByFlag: return RotationKind::kOutside;
    case LaneKind::kTwistNearHalfTurn: return RotationKind::kTwistNearHalfTurn;
    default: return RotationKind::kMixed;
  }
}

std::array<float, 4> Float4(const Quatd& q) {
  return {float(q.x()), float(q.y()), float(q.z()), float(q.w())};
}
Quatd FloatRotation(Random& random) { return ToFloatUnit(random.Rotation()); }

class SwingTwistTest : public PartTestBase<SwingTwistKernels> {
 protected:
  void SetUp() override { SetUpBodies("ragdoll_joint", PartKind::kSwingTwist); }

  // Fresh bodies, limits, frames and impulses for one configuration.
  void FillWorlds(std::size_t config_index) {
    named_ = &SwingTwistConfigs()[config_index];
    const std::size_t block_count = blocks();
    angles_ = std::make_unique<PartBlocks<SwingTwistLimitAngles>>(block_count);
    limits_ = std::make_unique<PartBlocks<SwingTwistLimitLanes>>(block_count);
    geometry_ = std::make_unique<PartBlocks<SwingTwistGeometry>>(block_count);
    parts_ = std::make_unique<PartBlocks<SwingTwistLanes>>(block_count);
    reference_.assign(worlds(), RefSwingTwist());
    condition_.assign(worlds(), 1.0);
    for (std::size_t w = 0; w < worlds(); ++w) FillWorld(w, config_index);
    for (std::size_t block = 0; block < block_count; ++block) {
      kernels_->set_limits(Config(), (*angles_)[block], (*limits_)[block]);
    }
  }

  void FillWorld(std::size_t world, std::size_t config_index) {
    Random random(7654321u + 7919u * unsigned(world) + 104729u * unsigned(config_index));
    const LaneKind kind = KindOfWorld(world);
    const LimitAngles limits = RandomLimitAngles(random, Config());
    SetLaneLimitAngles((*angles_)[Block(world)], Lane(world), limits);
    SetReferenceLimits(reference_[world], Config(), limits);
    BodyState body1 = RandomBodyState(random), body2 = RandomBodyState(random);
    if (kind == LaneKind::kSingular) {
      body1.inv_inertia_diagonal = body2.inv_inertia_diagonal = {0.f, 0.f, 0.f};
    }
    Quatd c1 = FloatRotation(random), c2 = FloatRotation(random);
    bool half_turn = kind == LaneKind::kHalfTurnSwing;
    for (int attempt = 0;; ++attempt) {
      ASSERT_LT(attempt, 500) << "no rotation clear of the clamp's boundaries for "
                              << ConfigLabel(world);
      Quatd q1 = ToQuatd(body1.rotation), q2;
      if (half_turn) {  // q = (0, 0.6, 0.8, 0) exactly
        q1 = c1 = c2 = Quatd::Identity();
        q2 = Quatd(0.0, 0.0, 0.6f, 0.8f);
      } else {
        const Quatd q = RandomRelativeRotation(random, Config(), limits, RotationKindOf(kind));
        q2 = q1 * c1 * q * c2.conjugate();
      }
      body1.rotation = Float4(q1);
      body2.rotation = Float4(half_turn ? q2 : ToFloatUnit(q2));
      // The rotation the reference sees, from the float values.
      const Quatd q = reference::SwingTwistConstraintRotation(
          ToReference(body1, MotionType::kDynamic), c1, ToReference(body2, MotionType::kDynamic),
          c2);
      const RotationCheck check = CheckRotation(Config(), reference_[world], q, half_turn);
      if (check.clear) {
        condition_[world] = check.condition;
        break;
      }
      half_turn = false;  // its limits leave a decision unclear: a random rotation instead
      if (kind == LaneKind::kHalfTurnSwing) {
        c1 = FloatRotation(random);
        c2 = FloatRotation(random);
      }
    }
    bodies_->Set(world, 0, body1);
    bodies_->Set(world, 1, body2);
    SetLaneQuat((*geometry_)[Block(world)].constraint_to_body1, Lane(world), c1);
    SetLaneQuat((*geometry_)[Block(world)].constraint_to_body2, Lane(world), c2);
    SetLambda(world, Vec3d(random.Uniform(-1, 1), random.Uniform(-1, 1), random.Uniform(-1, 1)));
  }

  const SwingTwistConfig& Config() const { return named_->config; }
  std::string ConfigLabel(std::size_t world) const {
    return std::string(named_->name) + ", world " + std::to_string(world);
  }
  Quatd C1(std::size_t w) const {
    return LaneQuat((*geometry_)[Block(w)].constraint_to_body1, Lane(w));
  }
  Quatd C2(std::size_t w) const {
    return LaneQuat((*geometry_)[Block(w)].constraint_to_body2, Lane(w));
  }

  Vec3d Lambda(std::size_t w) const {
    const SwingTwistLanes::Persistent& p = (*parts_)[Block(w)].persistent;
    return Vec3d(p.swing_y_lambda[Lane(w)], p.swing_z_lambda[Lane(w)], p.twist_lambda[Lane(w)]);
  }
  void SetLambda(std::size_t w, const Vec3d& lambda) {
    SwingTwistLanes::Persistent& p = (*parts_)[Block(w)].persistent;
    p.swing_y_lambda[Lane(w)] = float(lambda.x());
    p.swing_z_lambda[Lane(w)] = float(lambda.y());
    p.twist_lambda[Lane(w)] = float(lambda.z());
  }

  // cond(I1^-1 + I2^-1) of the temporary rotation-Euler part (1 if singular).
  double EulerCondition(std::size_t w) const {
    Mat33d k = Mat33d::Zero();
    for (std::size_t body = 0; body < 2; ++body) {
      const RefBody b = Body(w, body);
      if (b.IsDynamic()) k += b.InverseInertia();
    }
    const double c = Condition<3>(k);
    return std::isfinite(c) ? c : 1.0;
  }

  void CalculateProperties() {
    for (std::size_t block = 0; block < blocks(); ++block) {
      kernels_->calculate_properties(Pair(block), Config(), (*geometry_)[block],
                                     (*limits_)[block], (*parts_)[block]);
    }
    for (std::size_t w = 0; w < worlds(); ++w) {
      const RefBody b1 = Body(w, 0), b2 = Body(w, 1);
      reference_[w].SetTotalLambda(Lambda(w));
      reference_[w].CalculateConstraintProperties(
          b1, b2, reference::SwingTwistConstraintRotation(b1, C1(w), b2, C2(w)),
          b1.rotation * C1(w));
    }
  }

  void DeactivateFlaggedLanes() {
    DeactivateWorlds(*parts_, reference_,
                     [](std::size_t w) { return KindOfWorld(w) == LaneKind::kDeactivatedByFlag; });
  }

  PartHooks Hooks(bool position) {
    return {[this](std::size_t w) -> Eigen::VectorXd { return Lambda(w); },
            [this](std::size_t w) -> Eigen::VectorXd { return reference_[w].GetTotalLambda(); },
            [this](std::size_t w) { reference_[w].SetTotalLambda(Lambda(w)); },
            [this, position](std::size_t w) {
              return condition_[w] * (position ? EulerCondition(w) : 1.0);
            }};
  }

  void WarmStart(float ratio) {
    CompareVerbOnEveryLane(
        "warm start", *bodies_, Hooks(false),
        [&](std::size_t block) {
          kernels_->warm_start(Pair(block), Config(), (*parts_)[block], ratio);
          return false;
        },
        [&](std::size_t w, RefBody& b1, RefBody& b2) {
          reference_[w].WarmStart(b1, b2, ratio);
          return false;
        });
  }

  // One velocity iteration, compared lane by lane. Every value it computes
  // is a chain of roundings of angular velocities (|w1|, |w2|) and of
  // impulses: a row's new total L + dL is rounded before the applied impulse
  // (L + dL) - L is formed, as in Jolt, so the impulse carries an error of
  // FLT_EPSILON |L| even when dL is tiny, and dL = m_eff a.(w1 - w2) one of
  // FLT_EPSILON m_eff (|w1| + |w2|) (cancellation). The tolerance's scale is
  // the sum of those sizes, mapped to velocity through |I^-1 a|; times the
  // lane's condition (its axes' rounding amplification). Positions, linear
  // velocities and rotations must stay bit-identical (angular rows only).
  // After the first iteration the rows are solved to rounding, and whether
  // float rounding leaves every impulse of a block exactly zero is no
  // property of the kernel: `compare_applied` = false skips that flag.
  void SolveVelocity(bool compare_applied) {
    std::vector<RefBody> b1(worlds()), b2(worlds());
    std::vector<Vec3d> lambda_before(worlds());
    std::vector<bool> applied(blocks(), false);
    const BodyBlocks before = *bodies_;
    for (std::size_t w = 0; w < worlds(); ++w) {
      b1[w] = Body(w, 0);
      b2[w] = Body(w, 1);
      lambda_before[w] = Lambda(w);
      reference_[w].SetTotalLambda(Lambda(w));
    }
    // Sizes before the solve.
    std::vector<double> velocity_scale(worlds()), impulse_scale(worlds());
    for (std::size_t w = 0; w < worlds(); ++w) {
      const double speed = b1[w].AngularVelocity().norm() + b2[w].AngularVelocity().norm();
      velocity_scale[w] = speed;
      impulse_scale[w] = lambda_before[w].cwiseAbs().maxCoeff();
      for (const auto* row : {&reference_[w].SwingYPart(), &reference_[w].SwingZPart(),
                              &reference_[w].TwistPart()}) {
        impulse_scale[w] = std::max(impulse_scale[w], row->EffectiveMass() * speed);
      }
      if (reference_[w].SolveVelocityConstraint(b1[w], b2[w])) applied[Block(w)] = true;
    }
    for (std::size_t block = 0; block < blocks(); ++block) {
      const bool kernel_applied =
          kernels_->solve_velocity(Pair(block), Config(), (*parts_)[block]);
      if (compare_applied) {
        EXPECT_EQ(kernel_applied, applied[block]) << "'any lane applied' of block " << block;
      }
    }
    for (std::size_t w = 0; w < worlds(); ++w) {
      const RefSwingTwist& ref = reference_[w];
      const Vec3d lambda_after = ref.GetTotalLambda();
      const double impulses = impulse_scale[w] + lambda_after.cwiseAbs().maxCoeff();
      EXPECT_LE((Lambda(w) - lambda_after).cwiseAbs().maxCoeff(),
                Tolerance(impulses, condition_[w]))
          << "velocity solve: impulses of " << ConfigLabel(w);
      for (std::size_t body = 0; body < 2; ++body) {
        const RefBody& expected = body == 0 ? b1[w] : b2[w];
        double inv_i_a = 0;
        for (const auto* row : {&ref.SwingYPart(), &ref.SwingZPart(), &ref.TwistPart()}) {
          inv_i_a = std::max(inv_i_a, (body == 0 ? row->InvI1Axis() : row->InvI2Axis()).norm());
        }
        const BodyState actual = bodies_->Get(w, body), was = before.Get(w, body);
        const double scale = velocity_scale[w] + expected.AngularVelocity().norm() +
                             3.0 * inv_i_a * impulses;
        ExpectVec3Near(ToVec3d(actual.angular_velocity), expected.angular_velocity,
                       Tolerance(scale, condition_[w]),
                       "velocity solve, angular velocity of body " + std::to_string(body) +
                           ", " + ConfigLabel(w));
        EXPECT_TRUE(actual.linear_velocity == was.linear_velocity &&
                    actual.position == was.position && actual.rotation == was.rotation)
            << "velocity solve changed more than the angular velocity of body " << body << ", "
            << ConfigLabel(w);
      }
    }
  }

  void SolvePosition(float baumgarte) {
    CompareVerbOnEveryLane(
        "position solve", *bodies_, Hooks(true),
        [&](std::size_t block) {
          return kernels_->solve_position(Pair(block), Config(), (*geometry_)[block],
                                          (*limits_)[block], baumgarte);
        },
        [&](std::size_t w, RefBody& b1, RefBody& b2) {
          const Quatd q = reference::SwingTwistConstraintRotation(b1, C1(w), b2, C2(w));
          return reference_[w].SolvePositionConstraint(b1, b2, q, C1(w), C2(w), baumgarte);
        });
  }

  // Runs `body` once per configuration, with fresh worlds.
  template <class Body>
  void ForEachConfig(Body body) {
    for (std::size_t c = 0; c < SwingTwistConfigs().size(); ++c) {
      SCOPED_TRACE(SwingTwistConfigs()[c].name);
      FillWorlds(c);
      if (HasFatalFailure()) return;
      body();
    }
  }

  const NamedSwingTwistConfig* named_ = nullptr;
  std::unique_ptr<PartBlocks<SwingTwistLimitAngles>> angles_;
  std::unique_ptr<PartBlocks<SwingTwistLimitLanes>> limits_;
  std::unique_ptr<PartBlocks<SwingTwistGeometry>> geometry_;
  std::unique_ptr<PartBlocks<SwingTwistLanes>> parts_;
  std::vector<RefSwingTwist> reference_;
  std::vector<double> condition_;  // rounding amplification of the lane's axes
};

TEST_P(SwingTwistTest, CalculatePropertiesMatchesReference) {
  ForEachConfig([&] {
    std::vector<Vec3d> lambda_before(worlds());
    for (std::size_t w = 0; w < worlds(); ++w) lambda_before[w] = Lambda(w);
    CalculateProperties();
    LaneFlags active;
    int rows_on[3] = {0, 0, 0}, rows_off[3] = {0, 0, 0};
    for (std::size_t w = 0; w < worlds(); ++w) {
      const SwingTwistLanes& part = (*parts_)[Block(w)];
      const RefSwingTwist& ref = reference_[w];
      const std::size_t lane = Lane(w);
      if (lane == 0) kernels_->is_active(part, active);
      const std::string label = ConfigLabel(w);
      EXPECT_EQ(active[lane] != 0.0f, ref.IsActive()) << "IsActive, " << label;
      const double condition = condition_[w];
      const struct {
        const char* name;
        const SwingTwistRowLanes& row;
        const reference::AnglePart<double>& expected;
        const Vec3d& expected_axis;
        const reference::AxisLimit<double>& limit;
        int index;
      } rows[] = {
          {"swing Y", part.swing_y, ref.SwingYPart(), ref.SwingYAxis(), ref.SwingYLimit(), 0},
          {"swing Z", part.swing_z, ref.SwingZPart(), ref.SwingZAxis(), ref.SwingZLimit(), 1},
          {"twist", part.twist, ref.TwistPart(), ref.TwistAxis(), ref.TwistLimit(), 2}};
      for (const auto& r : rows) {
        const std::string row_label = std::string(r.name) + " row, " + label;
        const bool on = r.row.properties.effective_mass[lane] != 0.0f;
        ++(on ? rows_on : rows_off)[r.index];
        ASSERT_EQ(on, r.expected.IsActive()) << row_label << ": active";
        if (!on) {
          // Off rows: everything zero, the impulse cleared (Deactivate).
          EXPECT_EQ(Lambda(w)(r.index), 0.0) << row_label;
          EXPECT_EQ(LaneVec3(r.row.properties.inv_i1_axis, lane), Vec3d::Zero()) << row_label;
          EXPECT_EQ(LaneVec3(r.row.properties.inv_i2_axis, lane), Vec3d::Zero()) << row_label;
          continue;
        }
        // Scale 1 (unit axis), amplified by the lane's condition.
        ExpectVec3Near(LaneVec3(r.row.axis, lane), r.expected_axis, Tolerance(1.0, condition),
                       row_label + ", axis");
        const double inertia1 = Body(w, 0).inv_inertia_diagonal.maxCoeff();
        const double inertia2 = Body(w, 1).inv_inertia_diagonal.maxCoeff();
        ExpectVec3Near(LaneVec3(r.row.properties.inv_i1_axis, lane), r.expected.InvI1Axis(),
                       Tolerance(inertia1, condition), row_label + ", I1^-1 a");
        ExpectVec3Near(LaneVec3(r.row.properties.inv_i2_axis, lane), r.expected.InvI2Axis(),
                       Tolerance(inertia2, condition), row_label + ", I2^-1 a");
        EXPECT_NEAR(r.row.properties.effective_mass[lane], r.expected.EffectiveMass(),
                    Tolerance(r.expected.EffectiveMass(), condition))
            << row_label << ", effective mass";
        EXPECT_EQ(r.row.max_lambda[lane] == FLT_MAX, std::isinf(RefSwingTwist::MaxLambda(r.limit)))
            << row_label << ", impulse range";
        EXPECT_EQ(r.row.max_lambda[lane] == 0.0f, RefSwingTwist::MaxLambda(r.limit) == 0.0)
            << row_label << ", impulse range";
        // The impulse of an active row is kept for the warm start.
        EXPECT_EQ(Lambda(w)(r.index), lambda_before[w](r.index)) << row_label;
      }
    }
    // The inputs reach both sides of every per-lane decision: with 1000
    // worlds, each row the configuration can switch on is on somewhere, and
    // each row that depends on a clamp is off somewhere too.
    if (worlds() < 1000 || GetParam().motion1 != MotionType::kDynamic) return;
    const bool y_locked = Config().swing_y == AxisLimitKind::kLocked;
    const bool z_locked = Config().swing_z == AxisLimitKind::kLocked;
    const bool both_free =
        Config().swing_y == AxisLimitKind::kFree && Config().swing_z == AxisLimitKind::kFree;
    const bool can_be_on[3] = {!both_free, y_locked || z_locked,
                               Config().twist != AxisLimitKind::kFree};
    const bool always_on[3] = {y_locked, z_locked, Config().twist == AxisLimitKind::kLocked};
    for (int i = 0; i < 3; ++i) {
      if (!can_be_on[i]) continue;
      EXPECT_GT(rows_on[i], 0) << "row " << i << " never on";
      // Rows are off in the singular worlds (1 in 8) anyway: a clamp-driven
      // row must be off in more.
      if (!always_on[i]) {
        EXPECT_GT(rows_off[i], int(worlds() / 8) + 1) << "row " << i << " never off by its clamp";
      }
    }
  });
}

TEST_P(SwingTwistTest, WarmStartScalesAndAppliesImpulses) {
  ForEachConfig([&] {
    CalculateProperties();
    WarmStart(0.75f);
  });
}

TEST_P(SwingTwistTest, WarmStartWithRatioZeroAppliesNothing) {
  ForEachConfig([&] {
    CalculateProperties();
    const BodyBlocks before = *bodies_;
    for (std::size_t block = 0; block < blocks(); ++block) {
      kernels_->warm_start(Pair(block), Config(), (*parts_)[block], 0.0f);
    }
    for (std::size_t w = 0; w < worlds(); ++w) {
      EXPECT_EQ(Lambda(w), Vec3d::Zero()) << ConfigLabel(w);
    }
    ExpectBodiesUnchanged(before, [](std::size_t, std::size_t) { return true; },
                          "warm start with ratio 0");
  });
}

TEST_P(SwingTwistTest, VelocitySolveMatchesReference) {
  ForEachConfig([&] {
    CalculateProperties();
    DeactivateFlaggedLanes();
    WarmStart(1.0f);
    for (int iteration = 0; iteration < 3; ++iteration) SolveVelocity(iteration == 0);
    // Invariant: a locked twist row is two-sided and solved last, so after a
    // solve its J v is zero to rounding in every lane where it is active.
    if (Config().twist != AxisLimitKind::kLocked) return;
    for (std::size_t w = 0; w < worlds(); ++w) {
      if (!reference_[w].TwistPart().IsActive()) continue;
      const RefBody b1 = Body(w, 0), b2 = Body(w, 1);
      const double jv = reference::SwingTwistVelocityError(reference_[w], b1, b2).z();
      // Scale as in SolveVelocity: velocities and the impulse's rounding
      // (FLT_EPSILON |L|) through I^-1 a.
      const reference::AnglePart<double>& twist = reference_[w].TwistPart();
      const double scale = b1.AngularVelocity().norm() + b2.AngularVelocity().norm() +
                           std::abs(Lambda(w).z()) *
                               (twist.InvI1Axis().norm() + twist.InvI2Axis().norm());
      EXPECT_LE(std::abs(jv), Tolerance(scale, condition_[w]))
          << "J v of the locked twist row, " << ConfigLabel(w);
    }
  });
}

TEST_P(SwingTwistTest, PositionSolveMatchesReference) {
  ForEachConfig([&] {
    SolvePosition(0.2f);
    SolvePosition(0.2f);  // a second step from the moved bodies
  });
}

TEST_P(SwingTwistTest, DeactivatedAndSingularLanesStayFiniteAndApplyNothing) {
  ForEachConfig([&] {
    CalculateProperties();
    DeactivateFlaggedLanes();
    const BodyBlocks before = *bodies_;
    for (std::size_t block = 0; block < blocks(); ++block) {
      kernels_->warm_start(Pair(block), Config(), (*parts_)[block], 1.0f);
      kernels_->solve_velocity(Pair(block), Config(), (*parts_)[block]);
    }
    for (std::size_t w = 0; w < worlds(); ++w) {
      if (!reference_[w].IsActive()) {
        EXPECT_EQ(Lambda(w), Vec3d::Zero()) << ConfigLabel(w);
      }
    }
    ExpectBodiesUnchanged(
        before, [&](std::size_t w, std::size_t) { return !reference_[w].IsActive(); },
        "inactive lane");
  });
}

TEST_P(SwingTwistTest, SaveRestoreOfTheThreeImpulsesIsBitExact) {
  ForEachConfig([&] {
    CalculateProperties();
    WarmStart(1.0f);
    const auto saved = SavePartState(*parts_);
    std::vector<Vec3d> at_save(worlds());
    for (std::size_t w = 0; w < worlds(); ++w) at_save[w] = Lambda(w);
    for (std::size_t block = 0; block < blocks(); ++block) {  // changes active impulses
      kernels_->solve_velocity(Pair(block), Config(), (*parts_)[block]);
    }
    RestorePartState(*parts_, saved);
    for (std::size_t w = 0; w < worlds(); ++w) {
      EXPECT_EQ(Lambda(w), at_save[w]) << ConfigLabel(w);
    }
  });
}

std::vector<PartCase<SwingTwistKernels>> AllCases() {
  static const std::vector<std::pair<MotionType, MotionType>> pairings = {
      {MotionType::kDynamic, MotionType::kDynamic},
      {MotionType::kDynamic, MotionType::kStatic},
      {MotionType::kStatic, MotionType::kDynamic},
      {MotionType::kKinematic, MotionType::kDynamic},
      {MotionType::kDynamic, MotionType::kKinematic},
      {MotionType::kKinematic, MotionType::kStatic},
  };
  return AllPartCases<SwingTwistKernels>(pairings);
}

INSTANTIATE_TEST_SUITE_P(EveryTarget, SwingTwistTest, ::testing::ValuesIn(AllCases()),
                         PartCaseName<SwingTwistKernels>);

}  // namespace
}  // namespace manyworlds::testing
