// Joint coordinates and motor forces (Batch::GetJointCoordinates,
// GetMotorForces) against values computed here independently from the
// worlds' body states and the scene's settings, and against motion whose
// coordinates are known: a wheel driven through many turns, a saturated motor.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <vector>

#include "manyworlds/batch.h"
#include "manyworlds/scenes.h"

namespace manyworlds {
namespace {

using Quat = Eigen::Quaterniond;
using Vec = Eigen::Vector3d;

constexpr std::size_t kWorlds = 37;
constexpr double kTwoPi = 6.283185307179586;

std::vector<float> StateOf(const Batch& batch) {
  std::vector<float> state(batch.world_count() * batch.body_count() * kStateFloatsPerBody);
  batch.GetState(state);
  return state;
}

std::vector<float> CoordinatesOf(const Batch& batch, std::size_t constraint) {
  std::vector<float> out(batch.world_count() * batch.JointCoordinateCount(constraint));
  batch.GetJointCoordinates(constraint, out);
  return out;
}

struct BodyState {
  Vec x, v, w;
  Quat q;
};
BodyState BodyOf(const std::vector<float>& state, const Batch& batch, std::size_t world,
                 std::size_t body) {
  const float* s = &state[(world * batch.body_count() + body) * kStateFloatsPerBody];
  return {Vec(s[0], s[1], s[2]), Vec(s[7], s[8], s[9]), Vec(s[10], s[11], s[12]),
          Quat(s[6], s[3], s[4], s[5]).normalized()};
}

double Fold(double a) { return std::remainder(a, kTwoPi); }

// Cartpole: the rail (slider along X from the origin) reads the cart's x and
// v_x; the pole hinge (about Z) reads the pole's turn about Z relative to the
// cart, 0.1 rad from upright at the start, and its rate. Pushed at random, the
// pole falls and swings through +-pi (it hangs at pi): the unwrapped angle
// must stay continuous and fold back to the angle.
TEST(JointCoordinatesTest, CartpoleRailAndHingeMatchTheBodies) {
  Batch batch(MakeScene("cartpole"), kWorlds);
  ASSERT_THAT(batch.JointCoordinateNames(0), ::testing::ElementsAre("position", "velocity"));
  ASSERT_THAT(batch.JointCoordinateNames(1),
              ::testing::ElementsAre("angle", "unwrapped_angle", "angular_velocity"));
  ASSERT_EQ(batch.JointCoordinatesPerWorld(), 5u);
  {  // before any step: the scene's pose
    const std::vector<float> hinge = CoordinatesOf(batch, 1);
    EXPECT_NEAR(hinge[0], 0.1, 1e-6);
    EXPECT_NEAR(hinge[1], 0.1, 1e-6);
  }
  const SceneActions actions("cartpole");
  std::vector<float> previous_unwrapped(kWorlds, 0.1f);
  std::size_t wraps = 0;
  for (std::uint64_t step = 0; step < 400; ++step) {
    actions.Apply(batch, step, 3);
    batch.Step(StepSettings{});
    const std::vector<float> state = StateOf(batch);
    const std::vector<float> rail = CoordinatesOf(batch, 0), hinge = CoordinatesOf(batch, 1);
    std::vector<float> all(kWorlds * 5);
    batch.GetJointCoordinates(all);
    for (std::size_t w = 0; w < kWorlds; ++w) {
      const BodyState cart = BodyOf(state, batch, w, 1), pole = BodyOf(state, batch, w, 2);
      // Float rounding of a handful of operations on O(1) values.
      EXPECT_NEAR(rail[w * 2], cart.x.x(), 1e-5);
      EXPECT_NEAR(rail[w * 2 + 1], cart.v.x(), 1e-5);
      const Quat relative = cart.q.conjugate() * pole.q;
      const double angle = Fold(2.0 * std::atan2(relative.z(), relative.w()));
      const double rate = (pole.w - cart.w).dot(cart.q * Vec::UnitZ());
      const double theta = hinge[w * 3], unwrapped = hinge[w * 3 + 1];
      // Near +-pi the two foldings may pick opposite signs of the same angle.
      EXPECT_NEAR(Fold(theta - angle), 0.0, 1e-4) << "world " << w << " step " << step;
      EXPECT_NEAR(hinge[w * 3 + 2], rate, 1e-4);
      EXPECT_NEAR(Fold(unwrapped - theta), 0.0, 1e-4);
      // dt * |w| stays far below pi here: any jump is a miscounted turn.
      EXPECT_LT(std::abs(unwrapped - previous_unwrapped[w]), 1.0) << "world " << w;
      wraps += std::abs(unwrapped) > M_PI && std::abs(previous_unwrapped[w]) <= M_PI;
      previous_unwrapped[w] = static_cast<float>(unwrapped);
      for (std::size_t i = 0; i < 2; ++i) EXPECT_EQ(all[w * 5 + i], rail[w * 2 + i]);
      for (std::size_t i = 0; i < 3; ++i) EXPECT_EQ(all[w * 5 + 2 + i], hinge[w * 3 + i]);
    }
  }
  EXPECT_GT(wraps, 0u) << "no pole passed through +-pi: the turn count was not exercised";
}

// A wheel on a hinge about Z driven by a velocity motor at 12 rad/s with a
// 2 N m torque limit and no damping: the motor saturates while spinning up
// (torque 2), then holds 12 rad/s with no torque; over 10 s the wheel makes
// ~16 turns, which the unwrapped angle counts.
TEST(JointCoordinatesTest, AWheelDrivenThroughManyTurnsIsCountedAndItsMotorTorqueRead) {
  Scene scene;
  BodySettings ground;
  ground.motion_type = MotionType::kStatic;
  BodySettings wheel;
  wheel.inertia_diagonal = {0.5f, 0.5f, 0.5f};
  wheel.angular_damping = 0.0f;  // Jolt's default 0.05 would cost 0.3 N m at speed
  scene.AddBody(ground);
  scene.AddBody(wheel);
  HingeConstraintSettings axle;
  axle.body1 = 0;
  axle.body2 = 1;
  axle.hinge_axis1 = axle.hinge_axis2 = {0, 0, 1};
  axle.normal_axis1 = axle.normal_axis2 = {1, 0, 0};
  axle.motor_state = MotorState::kVelocity;
  axle.target_angular_velocity = 12.0f;
  axle.motor.min_force_limit = -2.0f;
  axle.motor.max_force_limit = 2.0f;
  scene.AddConstraint(axle);
  StepSettings no_gravity;
  no_gravity.gravity = {0, 0, 0};
  Batch batch(scene, kWorlds);
  ASSERT_EQ(batch.MotorForceCount(0), 1u);
  std::vector<float> torque(kWorlds);
  // Spin-up: 2 N m on 0.5 kg m^2 reaches 12 rad/s after 3 s.
  batch.Step(no_gravity);
  batch.GetMotorForces(0, torque);
  EXPECT_NEAR(torque[5], 2.0, 1e-4);
  double angle = 0.0, previous = 0.0;
  for (int step = 1; step < 600; ++step) {
    batch.Step(no_gravity);
    const std::vector<float> hinge = CoordinatesOf(batch, 0);
    EXPECT_GE(hinge[5 * 3 + 1], previous - 1e-4) << "step " << step;  // never unwinds
    previous = hinge[5 * 3 + 1];
    angle = hinge[5 * 3 + 1];
  }
  // theta(t) = 2 t^2 for t < 3 s (alpha = 4 rad/s^2), then 18 + 12 (t - 3).
  EXPECT_NEAR(angle, 18.0 + 12.0 * 7.0, 0.5);
  EXPECT_GT(angle / kTwoPi, 15.0);
  const std::vector<float> hinge = CoordinatesOf(batch, 0);
  EXPECT_NEAR(hinge[5 * 3 + 2], 12.0, 1e-3);
  EXPECT_NEAR(Fold(hinge[5 * 3 + 1] - hinge[5 * 3]), 0.0, 1e-3);
  batch.GetMotorForces(0, torque);
  EXPECT_NEAR(torque[5], 0.0, 1e-3);  // at speed, without friction, no torque is needed

  // A reset world starts counting from the scene's pose again.
  std::vector<std::uint8_t> mask(kWorlds, 0);
  mask[5] = 1;
  batch.Reset(mask);
  EXPECT_NEAR(CoordinatesOf(batch, 0)[5 * 3 + 1], 0.0, 1e-6);
  EXPECT_NEAR(CoordinatesOf(batch, 0)[6 * 3 + 1], angle, 0.5);
}

// Ragdoll: swing-twist joints read Jolt's decomposition of body 2's
// constraint frame relative to body 1's; with the bodies at rest in the
// scene's pose every angle is 0, and the angles stay within the joints'
// limits (plus solver slack) while the motors move the limbs.
TEST(JointCoordinatesTest, RagdollSwingTwistAnglesStartAtZeroAndRespectTheLimits) {
  const Scene scene = MakeScene("ragdoll");
  Batch batch(scene, kWorlds);
  const SceneActions actions("ragdoll");
  std::vector<std::size_t> swing_twists;
  for (std::size_t c = 0; c < batch.constraint_count(); ++c) {
    if (std::holds_alternative<SwingTwistConstraintSettings>(scene.constraints()[c])) {
      swing_twists.push_back(c);
      for (const float value : CoordinatesOf(batch, c)) EXPECT_NEAR(value, 0.0, 1e-5);
    }
  }
  ASSERT_FALSE(swing_twists.empty());
  for (std::uint64_t step = 0; step < 120; ++step) {
    actions.Apply(batch, step, 5);
    batch.Step(StepSettings{});
  }
  for (const std::size_t c : swing_twists) {
    const auto& s = std::get<SwingTwistConstraintSettings>(scene.constraints()[c]);
    const std::vector<float> values = CoordinatesOf(batch, c);
    for (std::size_t w = 0; w < kWorlds; ++w) {
      const float* v = &values[w * 6];
      EXPECT_GE(v[0], s.twist_min_angle - 0.05) << "constraint " << c;
      EXPECT_LE(v[0], s.twist_max_angle + 0.05) << "constraint " << c;
      EXPECT_LE(std::abs(v[1]), s.plane_half_cone_angle + 0.05) << "constraint " << c;
      EXPECT_LE(std::abs(v[2]), s.normal_half_cone_angle + 0.05) << "constraint " << c;
    }
  }
}

TEST(JointCoordinatesTest, WrongSizesAndIndicesAreRefused) {
  Batch batch(MakeScene("cartpole"), 4);
  std::vector<float> small(3);
  EXPECT_THROW(batch.GetJointCoordinates(1, small), std::invalid_argument);
  EXPECT_THROW(batch.GetJointCoordinates(small), std::invalid_argument);
  EXPECT_THROW(batch.JointCoordinateCount(9), std::out_of_range);
  EXPECT_EQ(batch.MotorForceCount(1), 0u);  // the cartpole's hinge has no motor
}

}  // namespace
}  // namespace manyworlds
