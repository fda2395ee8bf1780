// The metrics of `manyworlds sweep` on states written by hand: mechanical
// energy, pose error, which scenes conserve energy and which constraints are
// couplings (tools/sweep_metrics.h), and the library's per-constraint position
// error and velocity residual that the sweep reads (Batch::ConstraintError,
// Batch::ConstraintVelocityError).
//
// Tolerance: states are float, metrics double. Inputs of order 1 carry float
// rounding of ~1e-7 relative (sin/cos of an angle, 0.02 m, 9.81f), so values
// of order 1-100 agree with the exact figure within 1e-6 (order 1) or 1e-5
// (order 100); a wrong formula misses by far more (a lever arm, a sign, a
// factor 1/2 change the results by 0.1 or more).

#include <gtest/gtest.h>

#include <cmath>
#include <initializer_list>
#include <memory>
#include <vector>

#include "manyworlds/batch.h"
#include "manyworlds/scene.h"
#include "manyworlds/scenes.h"
#include "tools/sweep.h"
#include "tools/sweep_metrics.h"

namespace manyworlds::tools {
namespace {

constexpr double kTolerance = 1e-6;
const Float3 kGravity{0.0f, -9.81f, 0.0f};

// One body's 13 state floats: position, rotation (x, y, z, w), v, w.
std::vector<float> BodyState(Float3 x, Quaternion q, Float3 v, Float3 w) {
  return {x[0], x[1], x[2], q[0], q[1], q[2], q[3], v[0], v[1], v[2], w[0], w[1], w[2]};
}

Quaternion AboutAxis(int axis, double angle) {
  Quaternion q{0.0f, 0.0f, 0.0f, float(std::cos(angle / 2))};
  q[axis] = float(std::sin(angle / 2));
  return q;
}

Scene OneBodyScene() {
  Scene scene;
  BodySettings ground;
  ground.motion_type = MotionType::kStatic;
  scene.AddBody(ground);
  BodySettings body;
  body.mass = 2.0f;
  body.inertia_diagonal = {1.0f, 2.0f, 3.0f};
  body.gravity_factor = 0.5f;
  body.linear_damping = body.angular_damping = 0.0f;
  scene.AddBody(body);
  return scene;
}

TEST(MechanicalEnergy, KineticRotationalAndPotentialOfAKnownState) {
  const Scene scene = OneBodyScene();
  // The static body's state is ignored: give it a velocity and height that
  // would show if it were counted.
  std::vector<float> state = BodyState({0, 5, 0}, {0, 0, 0, 1}, {7, 0, 0}, {0, 0, 0});
  const std::vector<float> body = BodyState({0, 3, 0}, {0, 0, 0, 1}, {1, 0, 0}, {0, 0, 2});
  state.insert(state.end(), body.begin(), body.end());
  const double g = double(9.81f);
  // 1/2 m v^2 = 1, 1/2 I_z w^2 = 1/2 3 4 = 6, -m g_factor g.x = 2 0.5 g 3.
  EXPECT_NEAR(MechanicalEnergy(scene, state, kGravity), 1.0 + 6.0 + 3.0 * g, kTolerance * 100);
}

TEST(MechanicalEnergy, AngularVelocityIsTakenInThePrincipalFrame) {
  const Scene scene = OneBodyScene();
  std::vector<float> state = BodyState({0, 0, 0}, {0, 0, 0, 1}, {0, 0, 0}, {0, 0, 0});
  // Turned 90 degrees about X, the body's Z axis points along world -Y: a
  // spin about world Y is a spin about the body's Z axis (I = 3), not Y (2).
  const std::vector<float> body = BodyState({0, 0, 0}, AboutAxis(0, M_PI / 2), {0, 0, 0},
                                            {0, 2, 0});
  state.insert(state.end(), body.begin(), body.end());
  EXPECT_NEAR(MechanicalEnergy(scene, state, kGravity), 0.5 * 3.0 * 4.0, kTolerance);

  // The inertia rotation turns the principal axes within the body: with it
  // also 90 degrees about X, the principal frame is turned 180 degrees about
  // X in all, principal Y lies along world -Y, and the same spin is about
  // the I = 2 axis.
  Scene rotated = scene;
  rotated.bodies()[1].inertia_rotation = AboutAxis(0, M_PI / 2);
  EXPECT_NEAR(MechanicalEnergy(rotated, state, kGravity), 0.5 * 2.0 * 4.0, kTolerance);
}

TEST(EnergyIsConserved, OnlyTheChainsAndTheLinkageOfTheReferenceScenes) {
  for (const std::string& id : ReferenceSceneIds()) {
    const bool free = id.starts_with("chain") || id == "linkage";
    EXPECT_EQ(EnergyIsConserved(MakeReferenceScene(id), SceneActions(id)), free) << id;
  }
  Scene damped = MakeReferenceScene("chain16");
  damped.bodies()[3].angular_damping = 0.05f;
  EXPECT_FALSE(EnergyIsConserved(damped, SceneActions("chain16")));
}

TEST(CouplingConstraints, TheGearAndTheRackWithTheirHelpers) {
  EXPECT_EQ(CouplingConstraints(MakeReferenceScene("rackpinion")),
            std::vector<std::size_t>{reference_scene::kRackAndPinion});
  EXPECT_EQ(CouplingConstraints(MakeReferenceScene("geartrain")),
            std::vector<std::size_t>{reference_scene::kGear});
  EXPECT_TRUE(CouplingConstraints(MakeReferenceScene("cartpole")).empty());
}

TEST(BodyPoseError, LargestDistanceAndAngleOverMovingBodies) {
  const Scene scene = OneBodyScene();
  std::vector<float> state = BodyState({9, 9, 9}, {0, 0, 0, 1}, {0, 0, 0}, {0, 0, 0});
  const Quaternion q = AboutAxis(2, 0.2);
  // -q is the same rotation as q: the angle must be the short way, 0.2 rad.
  const std::vector<float> body =
      BodyState({1.3f, 2.4f, 3.0f}, {-q[0], -q[1], -q[2], -q[3]}, {0, 0, 0}, {0, 0, 0});
  state.insert(state.end(), body.begin(), body.end());
  // The static body's pose differs wildly and is ignored.
  const std::vector<double> reference = {0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0,
                                         1, 2, 3, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0};
  const PoseError error = BodyPoseError(scene, state, reference);
  EXPECT_NEAR(error.position, 0.5, kTolerance);
  EXPECT_NEAR(error.rotation, 0.2, kTolerance);
}

// One world of a reference scene with some bodies' states replaced.
class KnownState {
 public:
  explicit KnownState(const char* id) : batch_(MakeReferenceScene(id), 1) {
    state_.resize(batch_.body_count() * kStateFloatsPerBody);
    batch_.GetState(state_);
  }
  void Set(std::size_t body, Float3 x, Quaternion q, Float3 v, Float3 w) {
    const std::vector<float> s = BodyState(x, q, v, w);
    std::copy(s.begin(), s.end(), state_.begin() + body * kStateFloatsPerBody);
    batch_.SetState(state_);
  }
  const Batch& batch() const { return batch_; }

 private:
  Batch batch_;
  std::vector<float> state_;
};

TEST(CouplingError, RackAndPinionOfAKnownState) {
  using namespace reference_scene;
  KnownState world("rackpinion");
  // Pinion turned 0.3 rad about +Z, rack moved 0.02 m along +X:
  // theta - r d = 0.3 - 10 0.02 = 0.1 rad.
  world.Set(kPinion, {0, 0.1f, 0}, AboutAxis(2, 0.3), {0, 0, 0}, {0, 0, 2});
  world.Set(kRack, {0.02f, 0, 0}, {0, 0, 0, 1}, {0.15f, 0.2f, 0}, {0, 0, 0});
  EXPECT_NEAR(world.batch().ConstraintError(0, kRackAndPinion), 0.1, kTolerance);
  // Velocities: w_pinion . a - r v_rack . b = 2 - 10 0.15 = 0.5 rad/s.
  EXPECT_NEAR(world.batch().ConstraintVelocityError(0, kRackAndPinion), 0.5, kTolerance);
  // The rack slides along X freely; the 0.2 m/s along Y violates its slider.
  EXPECT_NEAR(world.batch().ConstraintVelocityError(0, kRackSlider), 0.2, kTolerance);
}

TEST(CouplingError, GearTrainOfAKnownState) {
  using namespace reference_scene;
  KnownState world("geartrain");
  // theta1 + r theta2 = 0.4 + 2 (-0.1) = 0.2 rad; w1 + r w2 = 1 + 2 (-0.25) = 0.5.
  world.Set(kGear1, {0, 0, 0}, AboutAxis(2, 0.4), {0, 0, 0}, {0, 0, 1});
  world.Set(kGear2, {0.3f, 0, 0}, AboutAxis(2, -0.1), {0, 0, 0}, {0, 0, -0.25f});
  EXPECT_NEAR(world.batch().ConstraintError(0, kGear), 0.2, kTolerance);
  EXPECT_NEAR(world.batch().ConstraintVelocityError(0, kGear), 0.5, kTolerance);
}

TEST(VelocityResidual, BallJointUsesTheLeverArm) {
  KnownState world("chain16");
  // Link 0 (body 1, COM at (0.25, 0, 0)) spinning at 4 rad/s about Z with its
  // COM moving at 1 m/s along Y turns about the anchor at the origin: the
  // anchor does not move, so the joint is satisfied.
  world.Set(1, {0.25f, 0, 0}, {0, 0, 0, 1}, {0, 1, 0}, {0, 0, 4});
  EXPECT_NEAR(world.batch().ConstraintVelocityError(0, 0), 0.0, kTolerance);
  // Without the spin the anchor moves with the COM: 1 m/s.
  world.Set(1, {0.25f, 0, 0}, {0, 0, 0, 1}, {0, 1, 0}, {0, 0, 0});
  EXPECT_NEAR(world.batch().ConstraintVelocityError(0, 0), 1.0, kTolerance);
}

TEST(VelocityResidual, HingeAllowsOnlyRotationAboutItsAxis) {
  using namespace reference_scene;
  KnownState world("cartpole");
  const Float3 pole_com{-0.04992f, 0.49750f, 0.0f};
  world.Set(kPole, pole_com, AboutAxis(2, 0.1), {0, 0, 0}, {0, 0, 3});
  // About the hinge axis Z the pole may turn, but its COM is still: the
  // anchor at the cart's COM moves with w x r, 3 |r| = 3 0.5 m/s.
  EXPECT_NEAR(world.batch().ConstraintVelocityError(0, kPoleHinge), 3.0 * 0.5, 1e-4);
  // A spin about X breaks the hinge's rotation rows: 1 rad/s (above the
  // anchor's 0.4975 m/s).
  world.Set(kPole, pole_com, AboutAxis(2, 0.1), {0, 0, 0}, {1, 0, 0});
  EXPECT_NEAR(world.batch().ConstraintVelocityError(0, kPoleHinge), 1.0, kTolerance);
}

// A dynamic body at (0, 1, 0) held to the static world by a six-DOF joint at
// its centre of mass, with the given axes fixed (the others free).
class SixDofWorld {
 public:
  explicit SixDofWorld(std::initializer_list<SixDofAxis> fixed) {
    Scene scene;
    BodySettings ground;
    ground.motion_type = MotionType::kStatic;
    scene.AddBody(ground);
    BodySettings body;
    body.position = {0, 1, 0};
    scene.AddBody(body);
    SixDofConstraintSettings joint;
    joint.body1 = 0;
    joint.body2 = 1;
    joint.position1 = joint.position2 = {0, 1, 0};
    for (SixDofAxis axis : fixed) joint.MakeFixedAxis(axis);
    scene.AddConstraint(joint);
    batch_ = std::make_unique<Batch>(scene, 1);
  }
  // The joint's velocity residual with the body at rest in its initial pose
  // but for velocities v and w.
  double Residual(Float3 v, Float3 w) {
    std::vector<float> state = BodyState({0, 0, 0}, {0, 0, 0, 1}, {0, 0, 0}, {0, 0, 0});
    const std::vector<float> body = BodyState({0, 1, 0}, {0, 0, 0, 1}, v, w);
    state.insert(state.end(), body.begin(), body.end());
    batch_->SetState(state);
    return batch_->ConstraintVelocityError(0, 0);
  }

 private:
  std::unique_ptr<Batch> batch_;
};

TEST(VelocityResidual, SixDofCountsOnlyItsFixedAxes) {
  using enum SixDofAxis;
  // Every translation fixed: the anchor's velocity, 1 m/s; spinning about
  // the anchor (the COM) is free.
  SixDofWorld point({kTranslationX, kTranslationY, kTranslationZ});
  EXPECT_NEAR(point.Residual({0, 1, 0}, {0, 0, 5}), 1.0, kTolerance);
  // X free, Y and Z fixed: sliding along X is allowed, 0.5 m/s along Y not.
  SixDofWorld slider({kTranslationY, kTranslationZ});
  EXPECT_NEAR(slider.Residual({2, 0, 0}, {0, 0, 0}), 0.0, kTolerance);
  EXPECT_NEAR(slider.Residual({2, 0.5f, 0}, {0, 0, 0}), 0.5, kTolerance);
  // Every rotation fixed, translations free: 3 rad/s of spin.
  SixDofWorld no_rotation({kRotationX, kRotationY, kRotationZ});
  EXPECT_NEAR(no_rotation.Residual({4, 0, 0}, {0, 0, 3}), 3.0, kTolerance);
}

TEST(Sweep, SceneListStartsWithTheReferenceScenes) {
  const std::vector<std::string> reference = ReferenceSceneIds();
  const std::vector<std::string> swept = SweepSceneIds();
  ASSERT_GE(swept.size(), reference.size());
  EXPECT_TRUE(std::equal(reference.begin(), reference.end(), swept.begin()));
}

}  // namespace
}  // namespace manyworlds::tools
