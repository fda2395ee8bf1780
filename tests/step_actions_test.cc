// Batch::Step(settings, io) with StepIo::actions (batch.h, StepAction):
// forces, torques and motor targets written inside the step's pass, block
// by block, give exactly the bits of the separate calls (SetForces(body),
// SetTorques(body), SetTargetVelocities, SetTargetPositions) before Step,
// on one and two threads, with resets and outputs in the same call; target
// positions are clamped into each world's limits as the separate call
// does; a non-finite action flags its world only; a refused action changes
// nothing; a stopped step still writes the actions for the next one.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <random>
#include <stop_token>
#include <string>
#include <tuple>
#include <vector>

#include "manyworlds/batch.h"
#include "manyworlds/error.h"
#include "manyworlds/scenes.h"

namespace manyworlds {
namespace {

using ::testing::HasSubstr;
namespace rs = reference_scene;

constexpr int kSteps = 24;

template <class T>
bool SameBits(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0;
}

std::vector<std::byte> Bytes(const Batch& batch) {
  const BatchSnapshot snapshot = batch.Snapshot();
  return {snapshot.bytes().begin(), snapshot.bytes().end()};
}

bool SameHealth(const Batch& a, const Batch& b) {
  return std::equal(a.WorldHealth().begin(), a.WorldHealth().end(), b.WorldHealth().begin());
}

// The cartpole with a position motor on the rail (limits +-0.5 m, so that
// targets beyond them are clamped) and a velocity motor on the pole hinge:
// every action kind on a slider's and a hinge's lanes.
Scene MotorisedCartpole() {
  Scene scene = MakeScene("cartpole");
  auto& rail = std::get<SliderConstraintSettings>(scene.constraints()[rs::kRail]);
  rail.limits_min = -0.5f;
  rail.limits_max = 0.5f;
  rail.motor_state = MotorState::kPosition;
  rail.motor.max_force_limit = 50.0f;
  rail.motor.min_force_limit = -50.0f;
  auto& hinge = std::get<HingeConstraintSettings>(scene.constraints()[rs::kPoleHinge]);
  hinge.motor_state = MotorState::kVelocity;
  hinge.motor.max_force_limit = 2.0f;  // N m
  hinge.motor.min_force_limit = -2.0f;
  return scene;
}

// One step's actions, drawn: a force on the cart, a torque on the pole,
// rail targets in [-1, 1] m (half of them beyond the limits), hinge target
// velocities; and the same as StepActions.
struct Actions {
  std::vector<float> forces, torques, positions, velocities;

  Actions(std::size_t worlds, std::mt19937_64& rng)
      : forces(worlds * 3), torques(worlds * 3), positions(worlds), velocities(worlds) {
    std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
    for (auto& f : forces) f = 10.0f * unit(rng);
    for (auto& t : torques) t = unit(rng);
    for (auto& p : positions) p = unit(rng);
    for (auto& v : velocities) v = 3.0f * unit(rng);
  }
  void ApplySeparately(Batch& batch) const {
    batch.SetForces(rs::kCart, forces);
    batch.SetTorques(rs::kPole, torques);
    batch.SetTargetPositions(rs::kRail, positions);
    batch.SetTargetVelocities(rs::kPoleHinge, velocities);
  }
  std::vector<StepAction> AsStepActions() const {
    return {{ActionKind::kForce, rs::kCart, forces},
            {ActionKind::kTorque, rs::kPole, torques},
            {ActionKind::kTargetPosition, rs::kRail, positions},
            {ActionKind::kTargetVelocity, rs::kPoleHinge, velocities}};
  }
};

class StepActionsTest : public ::testing::TestWithParam<std::tuple<std::size_t, int>> {};

// Two batches, the same actions, resets and reads; one with separate calls,
// the other with one fused call. Some steps put a NaN into one world's
// force or target: its world is flagged alike in both. After every step
// the state, the joint coordinates, the health and the whole snapshot
// (targets, impulses, pending-input notes) agree bit for bit.
TEST_P(StepActionsTest, FusedActionsGiveTheBitsOfTheSeparateCalls) {
  const auto [worlds, threads] = GetParam();
  const Scene scene = MotorisedCartpole();
  BatchOptions options;
  options.threads = threads;
  Batch separate(scene, worlds, options), fused(scene, worlds, options);
  const std::size_t state_floats = worlds * separate.body_count() * kStateFloatsPerBody;
  std::vector<float> state_a(state_floats), state_b(state_floats, -1.0f);
  std::vector<float> joints_a(worlds * separate.JointCoordinatesPerWorld());
  std::vector<float> joints_b(joints_a.size(), -1.0f);
  std::mt19937_64 rng(5);
  std::bernoulli_distribution done(0.05);
  for (int step = 0; step < kSteps; ++step) {
    Actions actions(worlds, rng);
    if (step == 3) actions.forces[3 * 7] = NAN;     // world 7, then reset at step 5
    if (step == 8) actions.positions[worlds - 1] = NAN;  // clamping keeps NaN
    std::vector<std::uint8_t> mask(worlds);
    for (auto& m : mask) m = done(rng) ? 1 : 0;
    if (step == 3) mask[7] = 0;  // flagged, not reset (a reset clears the flag)
    if (step == 8) mask[worlds - 1] = 0;
    if (step == 5) mask[7] = 1;

    actions.ApplySeparately(separate);
    separate.Step(StepSettings{});
    separate.Reset(mask);
    separate.GetState(state_a);
    separate.GetJointCoordinates(joints_a);

    const std::vector<StepAction> step_actions = actions.AsStepActions();
    StepIo io;
    io.actions = step_actions;
    io.reset_mask = mask;
    io.state_out = state_b;
    io.joints_out = joints_b;
    ASSERT_TRUE(fused.Step(StepSettings{}, io));

    ASSERT_TRUE(SameBits(state_a, state_b)) << "step " << step;
    ASSERT_TRUE(SameBits(joints_a, joints_b)) << "step " << step;
    ASSERT_TRUE(SameHealth(separate, fused)) << "step " << step;
    ASSERT_TRUE(SameBits(Bytes(separate), Bytes(fused))) << "step " << step;
    if (step == 3) {
      EXPECT_NE(fused.WorldHealth()[7] & kNonFiniteInput, 0);
    }
    if (step == 8) {
      EXPECT_NE(fused.WorldHealth()[worlds - 1] & kNonFiniteInput, 0);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(WorldsAndThreads, StepActionsTest,
                         // 40: a partial last block; 1030: many blocks per thread
                         ::testing::Combine(::testing::Values(std::size_t{40}, std::size_t{1030}),
                                            ::testing::Values(1, 2)));

// The fused target positions are clamped into each world's own limits
// (SetLimits per world), not the scene's: a world with limits +-0.1 m holds
// its rail's motor target at 0.1 for a target of 1 m; an infinite target
// is clamped to the limit like any other.
TEST(StepActionsTest, TargetPositionsAreClampedIntoEachWorldsLimits) {
  const std::size_t worlds = 20;
  Batch separate(MotorisedCartpole(), worlds), fused(MotorisedCartpole(), worlds);
  for (Batch* batch : {&separate, &fused}) batch->SetLimits(3, rs::kRail, -0.1f, 0.1f);
  std::vector<float> targets(worlds, 1.0f);
  targets[4] = INFINITY;  // clamped to 0.5: a finite target, not a flagged world
  separate.SetTargetPositions(rs::kRail, targets);
  const StepAction action{ActionKind::kTargetPosition, rs::kRail, targets};
  StepIo io;
  io.actions = {&action, 1};
  for (int step = 0; step < 100; ++step) {
    separate.Step(StepSettings{});
    fused.Step(StepSettings{}, io);
  }
  EXPECT_TRUE(SameBits(Bytes(separate), Bytes(fused)));
  EXPECT_EQ(fused.UnhealthyWorldCount(), 0u);
  // The cart (slider position, coordinate 0) settles at its world's limit.
  std::vector<float> rail(worlds * fused.JointCoordinateCount(rs::kRail));
  fused.GetJointCoordinates(rs::kRail, rail);
  const std::size_t count = fused.JointCoordinateCount(rs::kRail);
  EXPECT_NEAR(rail[3 * count], 0.1f, 0.02f);  // its limit (spring-free: hard stop)
  EXPECT_NEAR(rail[4 * count], 0.5f, 0.02f);  // the scene's limit
}

// Every refusal names the action (its index in StepIo::actions) and what is
// wrong, and leaves the batch and the outputs untouched, even when other
// actions before it were fine.
TEST(StepActionsTest, RefusalsNameTheActionAndChangeNothing) {
  const std::size_t worlds = 40;
  Batch batch(MotorisedCartpole(), worlds);
  batch.Step(StepSettings{});
  const std::vector<float> per_world(worlds, 0.5f), vec3(worlds * 3, 0.5f);
  const std::vector<float> short_vec3(worlds * 3 - 1, 0.5f);
  std::vector<float> state_out(worlds * batch.body_count() * kStateFloatsPerBody, 7.0f);
  const std::vector<float> untouched = state_out;
  struct Refused {
    StepAction action;
    const char* message;
  };
  const std::vector<Refused> refused = {
      {{ActionKind::kForce, rs::kWorld, vec3}, "applies to dynamic bodies only"},
      {{ActionKind::kForce, 9, vec3}, "body 9"},
      {{ActionKind::kTorque, rs::kPole, short_vec3}, "Step actions[1]: expected 120 floats"},
      {{ActionKind::kTargetVelocity, 5, per_world}, "constraint 5"},
      {{ActionKind::kTargetPosition, rs::kRail, vec3}, "Step actions[1]: expected 40 floats"},
      {{ActionKind(9), rs::kCart, vec3}, "not an ActionKind"},
  };
  const std::vector<std::byte> before = Bytes(batch);
  for (const Refused& r : refused) {
    const std::vector<StepAction> actions = {{ActionKind::kForce, rs::kCart, vec3}, r.action};
    StepIo io;
    io.actions = actions;
    io.state_out = state_out;
    try {
      batch.Step(StepSettings{}, io);
      ADD_FAILURE() << "not refused: " << r.message;
    } catch (const std::exception& e) {
      EXPECT_THAT(e.what(), HasSubstr(r.message));
    }
    EXPECT_TRUE(SameBits(before, Bytes(batch))) << r.message;
    EXPECT_TRUE(SameBits(untouched, state_out)) << r.message;
  }
  // A constraint without a motor: the gear-free cartpole's rail.
  Batch plain(MakeScene("cartpole"), worlds);
  const StepAction no_motor{ActionKind::kTargetVelocity, rs::kRail, per_world};
  StepIo io;
  io.actions = {&no_motor, 1};
  EXPECT_THROW(
      {
        try {
          plain.Step(StepSettings{}, io);
        } catch (const SceneError& e) {
          EXPECT_THAT(e.what(), HasSubstr("needs a motor or friction"));
          throw;
        }
      },
      SceneError);
}

// A stop requested before the step: no block steps, but every block gets
// its actions, so the next step acts as if they had been set separately.
TEST(StepActionsTest, AStoppedStepKeepsTheActionsForTheNextStep) {
  const std::size_t worlds = 40;
  Batch separate(MotorisedCartpole(), worlds), fused(MotorisedCartpole(), worlds);
  std::mt19937_64 rng(9);
  const Actions actions(worlds, rng);
  const std::vector<StepAction> step_actions = actions.AsStepActions();
  StepIo io;
  io.actions = step_actions;
  std::stop_source stop;
  stop.request_stop();
  EXPECT_FALSE(fused.Step(StepSettings{}, io, stop.get_token()));
  actions.ApplySeparately(separate);
  EXPECT_FALSE(separate.Step(StepSettings{}, stop.get_token()));
  EXPECT_TRUE(SameBits(Bytes(separate), Bytes(fused)));  // kNotStepped in both
  separate.Step(StepSettings{});
  fused.Step(StepSettings{});
  EXPECT_TRUE(SameBits(Bytes(separate), Bytes(fused)));
}

// A swing-twist joint with position drives and a six-DOF joint with
// velocity drives on every axis: the drive targets' StepActions.
Scene DrivenJoints() {
  Scene scene;
  BodySettings ground;
  ground.motion_type = MotionType::kStatic;
  scene.AddBody(ground);
  BodySettings limb;
  limb.position = {1.0f, 0.0f, 0.0f};
  scene.AddBody(limb);
  limb.position = {-1.0f, 0.5f, 0.0f};
  scene.AddBody(limb);
  SwingTwistConstraintSettings shoulder;
  shoulder.body1 = 0;
  shoulder.body2 = 1;
  shoulder.normal_half_cone_angle = shoulder.plane_half_cone_angle = 1.0f;
  shoulder.twist_min_angle = -1.0f;
  shoulder.twist_max_angle = 1.0f;
  shoulder.swing_motor_state = shoulder.twist_motor_state = MotorState::kPosition;
  scene.AddConstraint(shoulder);
  SixDofConstraintSettings mount;
  mount.body1 = 0;
  mount.body2 = 2;
  for (std::size_t axis = 0; axis < kSixDofAxes; ++axis) {
    mount.motor_state[axis] = MotorState::kVelocity;
    mount.motor[axis].min_force_limit = -5.0f;
    mount.motor[axis].max_force_limit = 5.0f;
  }
  scene.AddConstraint(mount);
  return scene;
}

// Every drive-target kind, fused and separate (per-world setters for one
// batch, the array setters for the other two), with NaN in one world:
// the same bits every step; a zero quaternion in one world is refused by
// name and nothing is written.
TEST(StepActionsTest, DriveTargetsGiveTheBitsOfTheSeparateCalls) {
  const std::size_t worlds = 40;
  const Scene scene = DrivenJoints();
  Batch per_world(scene, worlds), arrays(scene, worlds), fused(scene, worlds);
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
  for (int step = 0; step < 12; ++step) {
    std::vector<float> orientations(worlds * 4), spins(worlds * 3), moves(worlds * 3),
        speeds(worlds * 3);
    for (auto* values : {&orientations, &spins, &moves, &speeds}) {
      for (float& v : *values) v = unit(rng);
    }
    if (step == 4) spins[3 * 11 + 1] = NAN;
    for (std::size_t w = 0; w < worlds; ++w) {
      per_world.SetTargetOrientation(w, 0, {orientations[4 * w], orientations[4 * w + 1],
                                            orientations[4 * w + 2], orientations[4 * w + 3]});
      per_world.SetTargetAngularVelocity(w, 0, {spins[3 * w], spins[3 * w + 1], spins[3 * w + 2]});
      per_world.SetTargetTranslation(w, 1, {moves[3 * w], moves[3 * w + 1], moves[3 * w + 2]});
      per_world.SetTargetLinearVelocity(w, 1, {speeds[3 * w], speeds[3 * w + 1], speeds[3 * w + 2]});
      per_world.SetTargetAngularVelocity(w, 1, {spins[3 * w], spins[3 * w + 1], spins[3 * w + 2]});
    }
    arrays.SetTargetOrientations(0, orientations);
    arrays.SetTargetAngularVelocities(0, spins);
    arrays.SetTargetTranslations(1, moves);
    arrays.SetTargetLinearVelocities(1, speeds);
    arrays.SetTargetAngularVelocities(1, spins);
    const std::vector<StepAction> actions = {{ActionKind::kTargetOrientation, 0, orientations},
                                             {ActionKind::kTargetAngularVelocity, 0, spins},
                                             {ActionKind::kTargetTranslation, 1, moves},
                                             {ActionKind::kTargetLinearVelocity, 1, speeds},
                                             {ActionKind::kTargetAngularVelocity, 1, spins}};
    StepIo io;
    io.actions = actions;
    per_world.Step(StepSettings{});
    arrays.Step(StepSettings{});
    fused.Step(StepSettings{}, io);
    ASSERT_TRUE(SameBits(Bytes(per_world), Bytes(fused))) << "step " << step;
    ASSERT_TRUE(SameBits(Bytes(arrays), Bytes(fused))) << "step " << step;
    if (step == 4) {
      EXPECT_NE(fused.WorldHealth()[11] & kNonFiniteInput, 0);
    }
  }
  std::vector<float> orientations(worlds * 4, 0.5f);
  for (int i = 0; i < 4; ++i) orientations[4 * 23 + i] = 0.0f;
  const std::vector<std::byte> before = Bytes(fused);
  const StepAction zero{ActionKind::kTargetOrientation, 0, orientations};
  StepIo io;
  io.actions = {&zero, 1};
  try {
    fused.Step(StepSettings{}, io);
    ADD_FAILURE() << "a zero quaternion in world 23 was not refused";
  } catch (const SceneError& e) {
    EXPECT_THAT(e.what(), HasSubstr("in world 23: target orientation is a zero quaternion"));
  }
  EXPECT_THROW(fused.SetTargetOrientations(0, orientations), SceneError);
  EXPECT_TRUE(SameBits(before, Bytes(fused)));
  // Drives a constraint does not have are refused by name.
  EXPECT_THROW(fused.SetTargetTranslations(0, std::vector<float>(worlds * 3)), SceneError);
  EXPECT_THROW(fused.SetTargetVelocities(1, std::vector<float>(worlds)), SceneError);
}

}  // namespace
}  // namespace manyworlds
