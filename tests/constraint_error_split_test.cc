// Batch::MaxConstraintErrorSplit: a world's constraint position error with
// metres and radians apart (the report of `manyworlds run`). Checked against
// the existing mixed figure, Batch::MaxConstraintError, which must be the
// larger of the two parts on every scene, and on states written by hand
// whose linear and angular errors are known.
//
// Tolerance: states are float, errors double; inputs of order 0.01-1 carry
// float rounding of ~1e-7 relative, so 1e-6 separates a right figure from a
// wrong unit or a swapped part (which would miss by 0.03 or more).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "manyworlds/batch.h"
#include "manyworlds/scene.h"
#include "manyworlds/scenes.h"

namespace manyworlds {
namespace {

constexpr double kTolerance = 1e-6;

// The 13 state floats of body `body` of world `world` set to a position and a
// rotation (x, y, z, w) at rest.
void SetPose(Batch& batch, std::size_t world, std::size_t body, Float3 x, Quaternion q) {
  std::vector<float> state(batch.world_count() * batch.body_count() * kStateFloatsPerBody);
  batch.GetState(state);
  float* s = &state[(world * batch.body_count() + body) * kStateFloatsPerBody];
  const float values[7] = {x[0], x[1], x[2], q[0], q[1], q[2], q[3]};
  std::copy(values, values + 7, s);
  batch.SetState(state);
}

Quaternion AboutAxis(int axis, double angle) {
  Quaternion q{0.0f, 0.0f, 0.0f, float(std::cos(angle / 2))};
  q[axis] = float(std::sin(angle / 2));
  return q;
}

// A static ground and a 1 kg box at the origin on a hinge about Z there.
Scene HingeAtOrigin() {
  Scene scene;
  BodySettings ground;
  ground.motion_type = MotionType::kStatic;
  scene.AddBody(ground);
  scene.AddBody(BodySettings{});
  HingeConstraintSettings hinge;
  hinge.body1 = 0;
  hinge.body2 = 1;
  hinge.hinge_axis1 = hinge.hinge_axis2 = {0, 0, 1};
  hinge.normal_axis1 = hinge.normal_axis2 = {1, 0, 0};
  scene.AddConstraint(hinge);
  return scene;
}

TEST(ConstraintErrorSplit, HingeSeparatesAnchorMetresFromAxisRadians) {
  Batch batch(HingeAtOrigin(), 3);
  // World 1: the box 0.03 m off the anchor along X and tilted 0.2 rad about X,
  // so its hinge axis is 0.2 rad from the ground's.
  SetPose(batch, 1, 1, {0.03f, 0, 0}, AboutAxis(0, 0.2));
  const ConstraintErrorSplit moved = batch.MaxConstraintErrorSplit(1);
  EXPECT_NEAR(moved.linear, 0.03, kTolerance);
  EXPECT_NEAR(moved.angular, 0.2, kTolerance);
  EXPECT_FLOAT_EQ(batch.MaxConstraintError(1), 0.2f);
  // World 2: turned about the hinge axis only, which the hinge allows.
  SetPose(batch, 2, 1, {0, 0, 0}, AboutAxis(2, 1.0));
  EXPECT_NEAR(batch.MaxConstraintErrorSplit(2).linear, 0.0, kTolerance);
  EXPECT_NEAR(batch.MaxConstraintErrorSplit(2).angular, 0.0, kTolerance);
  // World 0 untouched: the initial pose satisfies the hinge.
  EXPECT_NEAR(batch.MaxConstraintErrorSplit(0).linear, 0.0, kTolerance);
  EXPECT_NEAR(batch.MaxConstraintErrorSplit(0).angular, 0.0, kTolerance);
}

TEST(ConstraintErrorSplit, RackAndPinionCouplingIsAngular) {
  using namespace reference_scene;
  Batch batch(MakeReferenceScene("rackpinion"), 1);
  // The rack slid 0.02 m along its free axis X, the pinion not turned: the
  // slider and hinge hold exactly, the coupling theta - 10 d is off by 0.2 rad.
  SetPose(batch, 0, kRack, {0.02f, 0, 0}, {0, 0, 0, 1});
  const ConstraintErrorSplit error = batch.MaxConstraintErrorSplit(0);
  EXPECT_NEAR(error.linear, 0.0, kTolerance);
  EXPECT_NEAR(error.angular, 0.2, kTolerance);
}

TEST(ConstraintErrorSplit, BallJointsHaveNoAngularError) {
  Batch batch(MakeReferenceScene("chain16"), 1);
  // Link 0 turned 0.5 rad about Y at its COM: its two anchors move off
  // their partners' (metres), and a ball joint has no angular row.
  SetPose(batch, 0, 1, {0.25f, 0, 0}, AboutAxis(1, 0.5));
  const ConstraintErrorSplit error = batch.MaxConstraintErrorSplit(0);
  EXPECT_EQ(error.angular, 0.0);
  // An anchor 0.25 m from the COM turned by 0.5 rad moves the chord
  // 2 * 0.25 sin(0.25), at both ends of the link.
  EXPECT_NEAR(error.linear, 0.5 * std::sin(0.25), kTolerance);
}

// On every scene, stepped with its actions, the larger part is exactly the
// mixed figure the library reported before the split.
TEST(ConstraintErrorSplit, LargerPartIsMaxConstraintErrorOnEveryScene) {
  constexpr std::size_t kWorlds = 20;
  double largest_linear = 0.0, largest_angular = 0.0;
  for (const std::string& id : AllSceneIds()) {
    SCOPED_TRACE(id);
    Batch batch(MakeScene(id), kWorlds);
    const SceneActions actions(id);
    for (std::uint64_t step = 0; step < 30; ++step) {
      actions.Apply(batch, step, 1);
      batch.Step(SceneStepSettings(id));
    }
    for (std::size_t w = 0; w < kWorlds; ++w) {
      const ConstraintErrorSplit error = batch.MaxConstraintErrorSplit(w);
      ASSERT_TRUE(std::isfinite(error.linear) && std::isfinite(error.angular));
      EXPECT_GE(error.linear, 0.0);
      EXPECT_GE(error.angular, 0.0);
      EXPECT_EQ(float(std::max(error.linear, error.angular)), batch.MaxConstraintError(w))
          << "world " << w;
      largest_linear = std::max(largest_linear, error.linear);
      largest_angular = std::max(largest_angular, error.angular);
    }
  }
  // The chains drift in metres and the couplings in radians within 30 steps:
  // a split that read nothing (all zeros) in either part would show here.
  EXPECT_GT(largest_linear, 1e-6);
  EXPECT_GT(largest_angular, 1e-6);
}

TEST(ConstraintErrorSplit, WorldOutOfRangeIsRefused) {
  const Batch batch(HingeAtOrigin(), 2);
  EXPECT_ANY_THROW(batch.MaxConstraintErrorSplit(2));
}

}  // namespace
}  // namespace manyworlds
