// The Batch API: bad scenes are refused with the body / constraint and field
// named, the plan runs and stores only what a scene has, state and
// parameters round-trip per world.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <functional>
#include <string>
#include <vector>

#include "batch/constraint_lanes.h"
#include "batch/plan.h"
#include "kernels/body_lanes.h"
#include "manyworlds/batch.h"
#include "manyworlds/error.h"
#include "manyworlds/scenes.h"
#include "reference/world.h"

namespace manyworlds {
namespace {

using ::testing::AllOf;
using ::testing::HasSubstr;

// A static anchor and one dynamic box hinged to it.
Scene HingeScene() {
  Scene scene;
  BodySettings world;
  world.name = "ground";
  world.motion_type = MotionType::kStatic;
  scene.AddBody(world);
  BodySettings box;
  box.name = "box";
  box.position = {0, -1, 0};
  scene.AddBody(box);
  HingeConstraintSettings hinge;
  hinge.name = "elbow";
  hinge.body1 = 0;
  hinge.body2 = 1;
  hinge.hinge_axis1 = hinge.hinge_axis2 = {0, 0, 1};
  hinge.normal_axis1 = hinge.normal_axis2 = {1, 0, 0};
  scene.AddConstraint(hinge);
  return scene;
}

HingeConstraintSettings& Hinge(Scene& scene) {
  return std::get<HingeConstraintSettings>(scene.constraints()[0]);
}

// Expects building a batch of `scene` to throw a SceneError whose message
// names every one of `words`.
void ExpectRefused(const Scene& scene, std::vector<std::string> words) {
  try {
    Batch batch(scene, 4);
    FAIL() << "the scene was accepted";
  } catch (const SceneError& error) {
    for (const std::string& word : words) {
      EXPECT_THAT(error.what(), HasSubstr(word));
    }
  }
}

struct BadSceneCase {
  std::string name;
  std::function<void(Scene&)> spoil;
  std::vector<std::string> words;  // what the message must name
};

void PrintTo(const BadSceneCase& c, std::ostream* out) { *out << c.name; }

class BadSceneTest : public ::testing::TestWithParam<BadSceneCase> {};

TEST_P(BadSceneTest, IsRefusedNamingTheCulprit) {
  Scene scene = HingeScene();
  GetParam().spoil(scene);
  ExpectRefused(scene, GetParam().words);
}

INSTANTIATE_TEST_SUITE_P(
    Cases, BadSceneTest,
    ::testing::Values(
        BadSceneCase{"ZeroMass", [](Scene& s) { s.bodies()[1].mass = 0; }, {"'box'", "mass"}},
        BadSceneCase{"NanMass", [](Scene& s) { s.bodies()[1].mass = NAN; }, {"'box'", "mass"}},
        BadSceneCase{"NegativeInertia",
                     [](Scene& s) { s.bodies()[1].inertia_diagonal[2] = -1; },
                     {"'box'", "inertia_diagonal[2]"}},
        BadSceneCase{"InfinitePosition",
                     [](Scene& s) { s.bodies()[1].position[0] = INFINITY; },
                     {"'box'", "position"}},
        BadSceneCase{"ZeroRotation", [](Scene& s) { s.bodies()[1].rotation = {0, 0, 0, 0}; },
                     {"'box'", "rotation"}},
        BadSceneCase{"ZeroInertiaRotation",
                     [](Scene& s) { s.bodies()[1].inertia_rotation = {0, 0, 0, 0}; },
                     {"'box'", "inertia_rotation"}},
        BadSceneCase{"ZeroAxis", [](Scene& s) { Hinge(s).hinge_axis1 = {0, 0, 0}; },
                     {"'elbow'", "hinge_axis1"}},
        BadSceneCase{"NanAxis", [](Scene& s) { Hinge(s).normal_axis2 = {NAN, 0, 0}; },
                     {"'elbow'", "normal_axis2"}},
        BadSceneCase{"AxesNotPerpendicular",
                     [](Scene& s) { Hinge(s).normal_axis1 = {0, 1, 1}; },
                     {"'elbow'", "hinge_axis1", "normal_axis1"}},
        BadSceneCase{"BodyOutOfRange", [](Scene& s) { Hinge(s).body2 = 7; },
                     {"'elbow'", "body2", "7"}},
        BadSceneCase{"SameBody", [](Scene& s) { Hinge(s).body2 = 0; }, {"'elbow'", "body2"}},
        BadSceneCase{"TwoNonDynamicBodies",
                     [](Scene& s) { s.bodies()[1].motion_type = MotionType::kKinematic; },
                     {"'elbow'", "non-dynamic"}},
        BadSceneCase{"HingeLimitBeyondPi", [](Scene& s) { Hinge(s).limits_max = 4.0f; },
                     {"'elbow'", "limits_max"}},
        BadSceneCase{"HingeMinAboveZero", [](Scene& s) { Hinge(s).limits_min = 0.5f; },
                     {"'elbow'", "limits_min"}},
        BadSceneCase{"PositionMotorWithoutSpring",
                     [](Scene& s) {
                       Hinge(s).motor_state = MotorState::kPosition;
                       Hinge(s).motor.spring.frequency_or_stiffness = 0;
                     },
                     {"'elbow'", "motor.spring"}},
        BadSceneCase{"MotorLimitsInverted",
                     [](Scene& s) {
                       Hinge(s).motor.min_force_limit = 1;
                       Hinge(s).motor.max_force_limit = -1;
                     },
                     {"'elbow'", "min_force_limit"}},
        BadSceneCase{"NegativeFriction", [](Scene& s) { Hinge(s).max_friction_torque = -1; },
                     {"'elbow'", "max_friction_torque"}},
        BadSceneCase{"SliderAxisParallelToNormal",
                     [](Scene& s) {
                       SliderConstraintSettings slider;
                       slider.name = "rail";
                       slider.body1 = 0;
                       slider.body2 = 1;
                       slider.normal_axis1 = slider.slider_axis1;
                       s.AddConstraint(slider);
                     },
                     {"'rail'", "slider_axis1", "normal_axis1"}},
        BadSceneCase{"SliderMinAboveZero",
                     [](Scene& s) {
                       SliderConstraintSettings slider;
                       slider.name = "rail";
                       slider.body1 = 0;
                       slider.body2 = 1;
                       slider.limits_min = 1;
                       s.AddConstraint(slider);
                     },
                     {"'rail'", "limits_min"}},
        BadSceneCase{"GearWithStaticBody",
                     [](Scene& s) {
                       GearConstraintSettings gear;
                       gear.name = "cog";
                       gear.body1 = 0;
                       gear.body2 = 1;
                       s.AddConstraint(gear);
                     },
                     {"'cog'", "body1", "static"}},
        BadSceneCase{"GearHelperOfWrongType",
                     [](Scene& s) {
                       BodySettings second = s.bodies()[1];
                       second.name = "wheel";
                       s.AddBody(second);
                       GearConstraintSettings gear;
                       gear.name = "cog";
                       gear.body1 = 1;
                       gear.body2 = 2;
                       gear.hinge1 = 0;
                       gear.hinge2 = 2;  // the gear itself
                       s.AddConstraint(gear);
                     },
                     {"'cog'", "hinge2"}},
        BadSceneCase{"DistanceMinAboveMax",
                     [](Scene& s) {
                       DistanceConstraintSettings rope;
                       rope.name = "rope";
                       rope.body1 = 0;
                       rope.body2 = 1;
                       rope.min_distance = 2;
                       rope.max_distance = 1;
                       s.AddConstraint(rope);
                     },
                     {"'rope'", "min_distance", "max_distance"}},
        BadSceneCase{"DistanceNanBound",
                     [](Scene& s) {
                       DistanceConstraintSettings rope;
                       rope.name = "rope";
                       rope.body1 = 0;
                       rope.body2 = 1;
                       rope.max_distance = NAN;
                       s.AddConstraint(rope);
                     },
                     {"'rope'", "max_distance"}},
        BadSceneCase{"PulleyNonPositiveRatio",
                     [](Scene& s) {
                       PulleyConstraintSettings pulley;
                       pulley.name = "hoist";
                       pulley.body1 = 1;
                       pulley.body2 = 0;
                       pulley.ratio = 0;
                       s.AddConstraint(pulley);
                     },
                     {"'hoist'", "ratio"}},
        BadSceneCase{"ConeAngleBeyondPi",
                     [](Scene& s) {
                       ConeConstraintSettings cone;
                       cone.name = "socket";
                       cone.body1 = 0;
                       cone.body2 = 1;
                       cone.half_cone_angle = 3.5f;
                       s.AddConstraint(cone);
                     },
                     {"'socket'", "half_cone_angle"}},
        BadSceneCase{"ConeZeroTwistAxis",
                     [](Scene& s) {
                       ConeConstraintSettings cone;
                       cone.name = "socket";
                       cone.body1 = 0;
                       cone.body2 = 1;
                       cone.twist_axis2 = {0, 0, 0};
                       s.AddConstraint(cone);
                     },
                     {"'socket'", "twist_axis2"}},
        BadSceneCase{"SwingTwistTwistInverted",
                     [](Scene& s) {
                       SwingTwistConstraintSettings joint;
                       joint.name = "hip";
                       joint.body1 = 0;
                       joint.body2 = 1;
                       joint.twist_min_angle = 0.5f;
                       joint.twist_max_angle = -0.5f;
                       s.AddConstraint(joint);
                     },
                     {"'hip'", "twist_min_angle"}},
        BadSceneCase{"SwingTwistPlaneNotPerpendicular",
                     [](Scene& s) {
                       SwingTwistConstraintSettings joint;
                       joint.name = "hip";
                       joint.body1 = 0;
                       joint.body2 = 1;
                       joint.plane_axis2 = joint.twist_axis2;
                       s.AddConstraint(joint);
                     },
                     {"'hip'", "twist_axis2", "plane_axis2"}},
        BadSceneCase{"NonFiniteLimitsSpring",
                     [](Scene& s) { Hinge(s).limits_spring.damping = INFINITY; },
                     {"'elbow'", "limits_spring"}},
        BadSceneCase{"SwingTwistPositionMotorWithoutSpring",
                     [](Scene& s) {
                       SwingTwistConstraintSettings joint;
                       joint.name = "hip";
                       joint.body1 = 0;
                       joint.body2 = 1;
                       joint.swing_motor_state = MotorState::kPosition;
                       joint.swing_motor.spring.frequency_or_stiffness = 0;
                       s.AddConstraint(joint);
                     },
                     {"'hip'", "swing_motor.spring"}},
        BadSceneCase{"SwingTwistZeroTargetOrientation",
                     [](Scene& s) {
                       SwingTwistConstraintSettings joint;
                       joint.name = "hip";
                       joint.body1 = 0;
                       joint.body2 = 1;
                       joint.target_orientation = {0, 0, 0, 0};
                       s.AddConstraint(joint);
                     },
                     {"'hip'", "target_orientation"}},
        BadSceneCase{"PathWithOnePoint",
                     [](Scene& s) {
                       PathConstraintSettings path;
                       path.name = "rail";
                       path.body1 = 0;
                       path.body2 = 1;
                       path.path = {PathPoint{}};
                       s.AddConstraint(path);
                     },
                     {"'rail'", "path", "at least 2"}},
        BadSceneCase{"PathNormalAlongTangent",
                     [](Scene& s) {
                       PathConstraintSettings path;
                       path.name = "rail";
                       path.body1 = 0;
                       path.body2 = 1;
                       path.path = {PathPoint{}, PathPoint{{1, 0, 0}, {1, 0, 0}, {2, 0, 0}}};
                       s.AddConstraint(path);
                     },
                     {"'rail'", "path[1].normal"}},
        BadSceneCase{"LoopingPathRepeatsItsStart",
                     [](Scene& s) {
                       PathConstraintSettings path;
                       path.name = "rail";
                       path.body1 = 0;
                       path.body2 = 1;
                       path.looping = true;
                       path.path = {PathPoint{}, PathPoint{{1, 0, 0}}, PathPoint{}};
                       s.AddConstraint(path);
                     },
                     {"'rail'", "looping"}},
        BadSceneCase{"SixDofNanLimit",
                     [](Scene& s) {
                       SixDofConstraintSettings joint;
                       joint.name = "mount";
                       joint.body1 = 0;
                       joint.body2 = 1;
                       joint.limit_max[4] = NAN;
                       s.AddConstraint(joint);
                     },
                     {"'mount'", "limit_max[4]"}},
        BadSceneCase{"SixDofAxesNotPerpendicular",
                     [](Scene& s) {
                       SixDofConstraintSettings joint;
                       joint.name = "mount";
                       joint.body1 = 0;
                       joint.body2 = 1;
                       joint.axis_y2 = {1, 1, 0};
                       s.AddConstraint(joint);
                     },
                     {"'mount'", "axis_x2", "axis_y2"}},
        BadSceneCase{"SixDofNegativeFriction",
                     [](Scene& s) {
                       SixDofConstraintSettings joint;
                       joint.name = "mount";
                       joint.body1 = 0;
                       joint.body2 = 1;
                       joint.max_friction[2] = -1;
                       s.AddConstraint(joint);
                     },
                     {"'mount'", "max_friction[2]"}},
        BadSceneCase{"SixDofMotorLimitsInverted",
                     [](Scene& s) {
                       SixDofConstraintSettings joint;
                       joint.name = "mount";
                       joint.body1 = 0;
                       joint.body2 = 1;
                       joint.motor_state[5] = MotorState::kVelocity;
                       joint.motor[5].min_force_limit = 1;
                       joint.motor[5].max_force_limit = -1;
                       s.AddConstraint(joint);
                     },
                     {"'mount'", "motor[5].min_force_limit"}}),
    [](const auto& info) { return info.param.name; });

// The ragdoll under random elbow and knee targets every step for 10 s: every
// world stays finite and healthy, and no joint opens or passes a limit by
// more than 0.1 (m or rad): one step of a limb turning at 6 rad/s, which the
// position phase then pulls back (measured worst 0.045).
TEST(ScenesTest, RagdollStaysAssembledForTenSeconds) {
  const Scene scene = MakeReferenceScene("ragdoll");
  const SceneActions actions("ragdoll");
  constexpr std::size_t kWorlds = 40;
  Batch batch(scene, kWorlds);
  float worst = 0.0f;
  for (std::uint64_t step = 0; step < 600; ++step) {
    actions.Apply(batch, step, 7);
    batch.Step(StepSettings{});
    ASSERT_EQ(batch.UnhealthyWorldCount(), 0u) << "step " << step;
    for (std::size_t w = 0; w < kWorlds; ++w) worst = std::max(worst, batch.MaxConstraintError(w));
  }
  EXPECT_LT(worst, 0.1f);
  RecordProperty("worst_constraint_error", std::to_string(worst));
  std::printf("ragdoll: worst constraint error over 10 s and %zu worlds: %.4f\n", kWorlds,
              double(worst));
}

// Jolt's defaults for negative distance bounds (spec 3, Distance), with the
// two bodies 2 m apart: both negative, a rod of 2 m (error 0); min only,
// min(2, max = 1.5) = 1.5 = max, so the rope is 0.5 m too long at once; max
// only, max(2, min = 1) = 2 (error 0). A wrong resolution (e.g. leaving -1
// in place, or min > max) shows up as a different constraint error; the
// reference resolves them independently and must agree.
// Drives of swing-twist and six-DOF constraints are set per axis: the
// single-value hinge / slider setters refuse them naming the right ones, and a
// zero target orientation is refused before anything is written.
TEST(BatchTest, MultiAxisDrivesAreSetPerAxis) {
  Scene scene = HingeScene();
  SwingTwistConstraintSettings joint;
  joint.name = "hip";
  joint.body1 = 0;
  joint.body2 = 1;
  joint.twist_motor_state = MotorState::kVelocity;
  const std::size_t hip = scene.AddConstraint(joint);
  SixDofConstraintSettings mount;
  mount.name = "mount";
  mount.body1 = 0;
  mount.body2 = 1;
  mount.motor_state[0] = MotorState::kVelocity;
  const std::size_t six_dof = scene.AddConstraint(mount);
  Batch batch(scene, 4);
  for (const std::size_t c : {hip, six_dof}) {
    try {
      batch.SetTargetPosition(0, c, 0.1f);
      ADD_FAILURE() << "SetTargetPosition accepted constraint " << c;
    } catch (const SceneError& error) {
      EXPECT_THAT(error.what(), HasSubstr("SetTargetOrientation"));
    }
  }
  EXPECT_THROW(batch.SetTargetOrientation(0, hip, {0, 0, 0, 0}), SceneError);
  EXPECT_THROW(batch.SetTargetTranslation(0, hip, {0, 0, 0}), SceneError);  // not a six-DOF
  EXPECT_THROW(batch.SetTargetAngularVelocity(0, six_dof, {1, 0, 0}), SceneError);  // no drive
  batch.SetTargetAngularVelocity(1, hip, {1, 0, 0});
  batch.SetTargetLinearVelocity(2, six_dof, {0.5f, 0, 0});
  batch.Step(StepSettings{});
  EXPECT_EQ(batch.UnhealthyWorldCount(), 0u);
}

TEST(BatchTest, DistanceBoundsDefaultToTheInitialLength) {
  struct Case {
    float min, max;
    double expected_min, expected_max, expected_error;
  };
  for (const Case& c : {Case{-1, -1, 2, 2, 0}, Case{-1, 1.5f, 1.5, 1.5, 0.5},
                        Case{1, -1, 1, 2, 0}}) {
    SCOPED_TRACE("min " + std::to_string(c.min) + ", max " + std::to_string(c.max));
    Scene scene;
    BodySettings ground;
    ground.motion_type = MotionType::kStatic;
    scene.AddBody(ground);
    BodySettings ball;
    ball.position = {0, -2, 0};
    scene.AddBody(ball);
    DistanceConstraintSettings distance;
    distance.body1 = 0;
    distance.body2 = 1;
    distance.point2 = {0, -2, 0};
    distance.min_distance = c.min;
    distance.max_distance = c.max;
    scene.AddConstraint(distance);
    Batch batch(scene, 3);
    EXPECT_NEAR(batch.MaxConstraintError(2), c.expected_error, 1e-6);
    const reference::World<double> world(scene);
    const auto& reference =
        std::get<reference::DistanceConstraint<double>>(world.constraint(0));
    EXPECT_DOUBLE_EQ(reference.min_distance(), c.expected_min);
    EXPECT_DOUBLE_EQ(reference.max_distance(), c.expected_max);
  }
}

TEST(BatchTest, ZeroWorldsAndBadStepSettingsAreRefused) {
  EXPECT_THROW(Batch(HingeScene(), 0), SceneError);
  Batch batch(HingeScene(), 3);
  StepSettings settings;
  settings.delta_time = 0;
  EXPECT_THAT([&] { batch.Step(settings); },
              ::testing::ThrowsMessage<SceneError>(HasSubstr("delta_time")));
  settings = StepSettings{};
  settings.substeps = 0;
  EXPECT_THAT([&] { batch.Step(settings); },
              ::testing::ThrowsMessage<SceneError>(HasSubstr("substeps")));
  settings = StepSettings{};
  settings.velocity_iterations = -1;
  EXPECT_THAT([&] { batch.Step(settings); },
              ::testing::ThrowsMessage<SceneError>(HasSubstr("velocity_iterations")));
}

// A scene pays only for what it has: the plan's parts and the bytes per block
// are exactly those of its constraints' features.
TEST(PlanTest, StorageAndPartsAreOnlyWhatTheSceneUses) {
  Scene scene = HingeScene();
  StepPlan plain = CompilePlan(scene);
  ASSERT_EQ(plain.constraints.size(), 1u);
  EXPECT_FALSE(plain.constraints[0].has_limits());
  EXPECT_FALSE(plain.constraints[0].has_motor());
  EXPECT_EQ(plain.constraints[0].PartsInOrder(), "point hinge_rotation");
  // 2 bodies, motion lanes for the dynamic one only, one bare hinge, and the
  // per-world health flags every block has.
  EXPECT_EQ(plain.block_bytes, 2 * sizeof(BodyLanes) + sizeof(BodyMotionLanes) +
                                   sizeof(HingeConstraintLanes) + sizeof(WorldHealthLanes));
  // What the hinge's setup recomputes is in the thread's scratch, past the
  // stored block, and its two parts' impulses are carried in and out of it.
  EXPECT_EQ(plain.scratch_bytes, sizeof(HingeConstraintScratch));
  EXPECT_EQ(plain.constraints[0].scratch_offset, plain.block_bytes);
  ASSERT_EQ(plain.carried.size(), 2u);
  EXPECT_EQ(plain.carried[0].bytes, sizeof(PointLanes::Persistent));
  EXPECT_EQ(plain.carried[1].bytes, sizeof(HingeRotationLanes::Persistent));
  for (const CarriedState& carried : plain.carried) {
    EXPECT_LE(carried.home + carried.bytes, plain.block_bytes);
    EXPECT_GE(carried.scratch, plain.block_bytes);
    EXPECT_LE(carried.scratch + carried.bytes, plain.working_bytes());
  }

  Hinge(scene).limits_min = -1.0f;
  Hinge(scene).motor_state = MotorState::kVelocity;
  StepPlan full = CompilePlan(scene);
  EXPECT_EQ(full.constraints[0].PartsInOrder(),
            "angle(velocity motor) point hinge_rotation angle(limits)");
  EXPECT_EQ(full.block_bytes,
            plain.block_bytes + sizeof(AngularLimitLanes) + sizeof(AngularMotorLanes));

  Hinge(scene).motor_state = MotorState::kOff;
  Hinge(scene).max_friction_torque = 0.5f;
  EXPECT_EQ(CompilePlan(scene).constraints[0].PartsInOrder(),
            "angle(friction) point hinge_rotation angle(limits)");
}

TEST(PlanTest, PrintedPlanNamesBodiesPartsAndSkippedPhases) {
  Batch batch(MakeReferenceScene("cartpole"), 5);
  const std::string plan = batch.Plan();
  EXPECT_THAT(plan, AllOf(HasSubstr("dual_axis rotation_euler"), HasSubstr("point hinge_rotation"),
                          HasSubstr("bytes per world"), HasSubstr(batch.SimdTarget())));
  Scene lonely;
  lonely.AddBody(BodySettings{});
  Batch free_fall(lonely, 1);
  EXPECT_THAT(free_fall.Plan(), HasSubstr("(skipped: no constraint)"));
}

TEST(BatchTest, StateRoundTripsAndResetRestoresTheScene) {
  const Scene scene = MakeReferenceScene("chain16");
  Batch batch(scene, 20);
  std::vector<float> initial(batch.world_count() * batch.body_count() * kStateFloatsPerBody);
  batch.GetState(initial);
  for (int i = 0; i < 10; ++i) batch.Step({});
  std::vector<float> moved(initial.size());
  batch.GetState(moved);
  EXPECT_NE(moved, initial);

  batch.SetState(moved);
  std::vector<float> again(initial.size());
  batch.GetState(again);
  for (std::size_t i = 0; i < moved.size(); ++i) {
    // Rotations are renormalised on the way in: one rounding of a unit quaternion.
    EXPECT_NEAR(again[i], moved[i], 2 * FLT_EPSILON) << i;
  }

  std::vector<std::uint8_t> mask(batch.world_count(), 0);
  mask[4] = 1;
  batch.Reset(mask);
  batch.GetState(again);
  const std::size_t per_world = batch.body_count() * kStateFloatsPerBody;
  for (std::size_t w = 0; w < batch.world_count(); ++w) {
    const auto& expected = w == 4 ? initial : moved;
    for (std::size_t i = 0; i < per_world; ++i) {
      ASSERT_NEAR(again[w * per_world + i], expected[w * per_world + i], 2 * FLT_EPSILON)
          << "world " << w << " float " << i;
    }
  }

  std::vector<float> positions(batch.world_count() * batch.body_count() * 3);
  batch.GetField(StateField::kPosition, positions);
  EXPECT_EQ(positions[3 * 3 + 0], again[3 * kStateFloatsPerBody + 0]);  // world 0, body 3, x
}

// Every field read alone is bit for bit its columns of GetState, in every
// world (a partial last block) and body; under the sanitizers (CI runs
// batch_test instrumented) this also checks the fields past the position
// are read without indexing past a LaneArray (a UBSan report the fuzzer
// found in GetField(kLinearVelocity)).
TEST(BatchTest, EveryFieldIsItsColumnsOfTheState) {
  Batch batch(MakeScene("ragdoll"), 21);
  for (int i = 0; i < 5; ++i) batch.Step({});
  const std::size_t bodies = batch.body_count();
  std::vector<float> state(batch.world_count() * bodies * kStateFloatsPerBody);
  batch.GetState(state);
  for (const StateField field : {StateField::kPosition, StateField::kRotation,
                                 StateField::kLinearVelocity, StateField::kAngularVelocity}) {
    const std::size_t size = StateFieldSize(field), offset = StateFieldOffset(field);
    std::vector<float> values(batch.world_count() * bodies * size, -1.0f);
    batch.GetField(field, values);
    for (std::size_t row = 0; row < batch.world_count() * bodies; ++row) {
      ASSERT_EQ(std::memcmp(&values[row * size], &state[row * kStateFloatsPerBody + offset],
                            size * sizeof(float)),
                0)
          << "field at offset " << offset << ", world " << row / bodies << ", body "
          << row % bodies;
    }
  }
}

// One world's reads are bit for bit its rows of the whole-batch reads (the
// recorder reads only the worlds it records this way); a world past the end
// and a wrong size are refused.
TEST(BatchTest, OneWorldsReadsAreItsRowsOfTheBatchReads) {
  Batch batch(MakeScene("ragdoll"), 21);
  for (int i = 0; i < 5; ++i) batch.Step({});
  const std::size_t state_row = batch.body_count() * kStateFloatsPerBody;
  const std::size_t joint_row = batch.JointCoordinatesPerWorld();
  std::vector<float> state(batch.world_count() * state_row), joints(batch.world_count() * joint_row);
  batch.GetState(state);
  batch.GetJointCoordinates(joints);
  std::vector<float> world_state(state_row), world_joints(joint_row);
  for (std::size_t w = 0; w < batch.world_count(); ++w) {
    batch.GetWorldState(w, world_state);
    batch.GetWorldJointCoordinates(w, world_joints);
    ASSERT_EQ(std::memcmp(world_state.data(), &state[w * state_row], state_row * sizeof(float)), 0)
        << "state of world " << w;
    ASSERT_EQ(std::memcmp(world_joints.data(), &joints[w * joint_row], joint_row * sizeof(float)),
              0)
        << "joint coordinates of world " << w;
  }
  EXPECT_THROW(batch.GetWorldState(21, world_state), std::out_of_range);
  EXPECT_THROW(batch.GetWorldJointCoordinates(21, world_joints), std::out_of_range);
  world_state.pop_back();
  EXPECT_THROW(batch.GetWorldState(0, world_state), std::invalid_argument);
}

TEST(BatchTest, PerWorldParametersChangeOnlyTheirWorld) {
  Scene scene = HingeScene();
  Hinge(scene).limits_min = -0.5f;
  Hinge(scene).limits_max = 0.5f;
  Hinge(scene).motor_state = MotorState::kVelocity;
  Hinge(scene).motor.min_force_limit = -100;
  Hinge(scene).motor.max_force_limit = 100;
  Batch batch(scene, 3);
  batch.SetTargetVelocity(1, 0, 1.0f);   // world 1 turns
  batch.SetLimits(2, 0, -kPi, kPi);      // world 2 free, target 0
  for (int i = 0; i < 120; ++i) batch.Step({});
  std::vector<float> state(3 * 2 * kStateFloatsPerBody);
  batch.GetState(state);
  auto angular_z = [&](std::size_t w) { return state[(w * 2 + 1) * kStateFloatsPerBody + 12]; };
  EXPECT_NEAR(angular_z(0), 0.0f, 1e-4f);
  // World 1 spins at 1 rad/s until its limit at 0.5 rad stops it (after 0.5 s).
  EXPECT_NEAR(angular_z(1), 0.0f, 1e-3f);
  EXPECT_NEAR(angular_z(2), 0.0f, 1e-4f);
  EXPECT_GT(batch.MaxConstraintError(1), -1.0f);

  // Refusals name the constraint and the setting.
  EXPECT_THAT([&] { batch.SetRatio(0, 0, 2.0f); },
              ::testing::ThrowsMessage<SceneError>(HasSubstr("'elbow'")));
  EXPECT_THAT([&] { batch.SetLimits(0, 0, 0.5f, 1.0f); },
              ::testing::ThrowsMessage<SceneError>(HasSubstr("limits_min")));
  EXPECT_THAT([&] { batch.SetLimitsSpring(0, 0, 5.0f, 0.5f); },
              ::testing::ThrowsMessage<SceneError>(HasSubstr("limits_spring")));
  EXPECT_THROW(batch.SetForce(3, 1, {0, 0, 0}), std::out_of_range);
  EXPECT_THAT([&] { batch.SetForce(0, 0, {1, 0, 0}); },
              ::testing::ThrowsMessage<SceneError>(HasSubstr("'ground'")));
}

TEST(BatchTest, ForcesActForOneStepAndMatchNewton) {
  Scene scene;
  BodySettings ball;
  ball.mass = 2.0f;
  ball.linear_damping = 0;
  scene.AddBody(ball);
  Batch batch(scene, 2);
  StepSettings settings;
  settings.gravity = {0, 0, 0};
  batch.SetForce(1, 0, {6.0f, 0, 0});
  batch.Step(settings);
  batch.Step(settings);
  std::vector<float> state(2 * kStateFloatsPerBody);
  batch.GetState(state);
  // dv = F dt / m in the first step only; float rounding of one product.
  EXPECT_NEAR(state[kStateFloatsPerBody + 7], 6.0f / 2.0f / 60.0f, 1e-7f);
  EXPECT_EQ(state[7], 0.0f);
}

}  // namespace
}  // namespace manyworlds

namespace manyworlds {
namespace {

// The README's complete example ("Using the library"; ctest package compiles
// and runs it as written), here with checks: the motor turns the pole and
// the reset world is back at the scene's start.
TEST(BatchTest, ReadmeExampleRuns) {
  Scene scene;
  BodySettings ground;  ground.motion_type = MotionType::kStatic;
  BodySettings pole;    pole.mass = 0.1f;  pole.inertia_diagonal = {0.0084f, 0.0001f, 0.0084f};
  pole.position = {0, 0.5f, 0};
  const std::size_t g = scene.AddBody(ground), p = scene.AddBody(pole);
  HingeConstraintSettings hinge;
  hinge.body1 = g;  hinge.body2 = p;
  hinge.hinge_axis1 = hinge.hinge_axis2 = {0, 0, 1};
  hinge.normal_axis1 = hinge.normal_axis2 = {1, 0, 0};
  hinge.motor_state = MotorState::kVelocity;
  hinge.motor.min_force_limit = -5;  hinge.motor.max_force_limit = 5;
  const std::size_t h = scene.AddConstraint(hinge);

  Batch batch(scene, 4096);
  std::vector<float> targets(4096, 1.0f), state(4096 * batch.body_count() * kStateFloatsPerBody);
  batch.SetTargetVelocities(h, targets);
  for (int i = 0; i < 30; ++i) batch.Step(StepSettings{});
  batch.GetState(state);
  std::vector<float> joint(4096 * batch.JointCoordinateCount(h));
  batch.GetJointCoordinates(h, joint);
  std::vector<std::uint8_t> done(4096, 0);  done[7] = 1;
  batch.Reset(done);
  batch.SetMassProperties(3, p, 0.12f, {0.01f, 0.0001f, 0.01f});

  // The motor's 5 N m could add 2.5 rad/s per step to the pole (0.0334 kg m^2
  // about the hinge), so the target is reachable; the motor row and the
  // point row share the pole, so Gauss-Seidel needs a few warm-started steps:
  // after 30 steps (0.5 s, gravity pulling on the tilting pole) the spin is
  // the target within the 10 iterations' residual (measured 1.6e-5).
  const float spin = state[(0 * batch.body_count() + p) * kStateFloatsPerBody + 12];
  EXPECT_NEAR(spin, 1.0f, 1e-4f);
  EXPECT_NEAR(joint[0 * 3 + 2], spin, 1e-5f);  // the hinge's rate is the pole's spin
  std::vector<float> after(state.size());
  batch.GetState(after);
  EXPECT_EQ(after[(7 * batch.body_count() + p) * kStateFloatsPerBody + 12], 0.0f);
  EXPECT_EQ(after[(8 * batch.body_count() + p) * kStateFloatsPerBody + 12], spin);

  const BatchSnapshot saved = batch.Snapshot();
  batch.Step(StepSettings{});
  batch.Restore(saved);
  std::vector<float> restored(state.size());
  batch.GetState(restored);
  EXPECT_EQ(restored, after);
}

}  // namespace
}  // namespace manyworlds
