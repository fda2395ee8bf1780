// The opt-in gyroscopic step (StepSettings::gyroscopic, reference/gyroscopic.h,
// kernels/integration-inl.h) in the batch on every Highway target this CPU
// runs, against the scalar reference:
//  (a) free bodies with uneven inertias (one with rotated principal axes),
//      spinning at up to Jolt's max angular velocity about oblique axes, a
//      flywheel on a hinge spun off its principal axis, a body whose rotation
//      DOFs are restricted (skipped by the step) and a point-jointed pair:
//      every lane matches the float and the double reference after one step
//      from the lane's state, at every step of 2 s, with gyroscopic on;
//  (b) with gyroscopic on, the step keeps a free body's kinetic energy and
//      |I w| (the invariants of Euler's equations) to float rounding.
// The off path is the unchanged Jolt integration: determinism_test and
// scene_comparison_test hold it bit for bit.

#include <gtest/gtest.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "manyworlds/batch.h"
#include "manyworlds/scene.h"
#include "reference/world.h"
#include "tests/lane_vs_reference.h"
#include "tests/step_targets.h"

namespace manyworlds {
namespace {

constexpr int kSteps = 120;
constexpr std::size_t kWorlds = 20;  // two blocks, the second mostly padding

// Tolerance per body, as scene_comparison_test: kStepTolerance FLT_EPSILON x
// scale (its trajectories' 16), or twice the float reference's own distance
// from the double reference for that body in the same run, whichever is
// larger. Velocities are compared against the length of their vector, not
// component by component (Compare's scale): the gyroscopic step turns w, so
// every component's rounding is of the order of FLT_EPSILON |w| and a small
// component of a 40 rad/s spin would otherwise be held to its own size.
constexpr double kStepTolerance = 16.0;

BodySettings Free(const char* name, float mass, Float3 inertia, Float3 position,
                  Quaternion rotation, Float3 spin) {
  BodySettings body;
  body.name = name;
  body.mass = mass;
  body.inertia_diagonal = inertia;
  body.position = position;
  body.rotation = rotation;
  body.angular_velocity = spin;
  body.linear_damping = body.angular_damping = 0.0f;
  return body;
}

// Compare(), with the velocity deviation scaled by max(1, |v|) and
// max(1, |w|) of the whole vectors (see the tolerance above).
template <class T>
Deviation CompareTurningBody(const float* lane, const reference::Body<T>& body) {
  Deviation d = Compare(lane, body);
  d.velocity = 0;
  for (const auto& [offset, want] :
       {std::pair{7, body.linear_velocity}, std::pair{10, body.angular_velocity}}) {
    const double scale = FLT_EPSILON * std::max(1.0, double(want.norm()));
    for (int i = 0; i < 3; ++i) {
      const double error = std::abs(double(lane[offset + i]) - double(want[i]));
      d.velocity = std::max(d.velocity, error / scale);
    }
  }
  return d;
}

Scene GyroscopicScene() {
  Scene scene;
  BodySettings ground;
  ground.name = "world";
  ground.motion_type = MotionType::kStatic;
  scene.AddBody(ground);
  // Intermediate-axis spinner, and a body with rotated principal axes.
  BodySettings spinner =
      Free("spinner", 1, {1, 2, 3}, {0, 0, 0}, {0, 0, 0, 1}, {0.4f, 40.0f, 0.3f});
  spinner.gravity_factor = 0;
  scene.AddBody(spinner);
  BodySettings tilted = Free("tilted", 2, {0.1f, 0.5f, 1.2f}, {2, 0, 0},
                             {0.1f, 0.2f, -0.3f, 0.927362f}, {-20.0f, 30.0f, 25.0f});
  tilted.inertia_rotation = {0.2f, -0.1f, 0.3f, 0.927362f};
  scene.AddBody(tilted);
  // A flywheel on a hinge about Z, spun with a component off the axis.
  const std::size_t wheel = scene.AddBody(
      Free("wheel", 10, {0.225f, 0.225f, 0.45f}, {0, 2, 0}, {0, 0, 0, 1}, {3.0f, 0.0f, 45.0f}));
  HingeConstraintSettings axle;
  axle.body1 = 0;
  axle.body2 = wheel;
  axle.point1 = axle.point2 = {0, 2, 0};
  axle.hinge_axis1 = axle.hinge_axis2 = {0, 0, 1};
  axle.normal_axis1 = axle.normal_axis2 = {1, 0, 0};
  scene.AddConstraint(axle);
  // Rotation about Z only: the step must leave it alone.
  BodySettings planar =
      Free("planar", 1, {0.2f, 0.4f, 0.6f}, {-2, 0, 0}, {0, 0, 0, 1}, {0, 0, 10.0f});
  planar.allowed_dofs = AllowedDofs::kPlane2D;
  scene.AddBody(planar);
  // Two uneven bodies on a ball joint, hanging from the world.
  const std::size_t a = scene.AddBody(
      Free("a", 1, {0.05f, 0.2f, 0.3f}, {0, -1, 0}, {0, 0, 0, 1}, {5.0f, 12.0f, -7.0f}));
  const std::size_t b = scene.AddBody(
      Free("b", 3, {0.4f, 0.1f, 0.6f}, {0, -2, 0}, {0, 0, 0, 1}, {-9.0f, 4.0f, 15.0f}));
  PointConstraintSettings top, middle;
  top.body1 = 0;
  top.body2 = a;
  top.point1 = top.point2 = {0, -0.5f, 0};
  middle.body1 = a;
  middle.body2 = b;
  middle.point1 = middle.point2 = {0, -1.5f, 0};
  scene.AddConstraint(top);
  scene.AddConstraint(middle);
  return scene;
}

class GyroscopicTargetTest : public ::testing::TestWithParam<std::int64_t> {};

TEST_P(GyroscopicTargetTest, EveryLaneMatchesTheReferenceStepByStep) {
  const Scene scene = GyroscopicScene();
  Batch batch(scene, kWorlds, BatchOptions{1, 0, GetParam()});
  const std::size_t per_world = batch.body_count() * kStateFloatsPerBody;
  std::vector<float> state(kWorlds * per_world);
  batch.GetState(state);
  // Each world spins its bodies at its own rate (0.6x to 1.05x), so lanes differ.
  for (std::size_t w = 0; w < kWorlds; ++w) {
    for (std::size_t body = 1; body < batch.body_count(); ++body) {
      float* spin = state.data() + w * per_world + body * kStateFloatsPerBody + 10;
      for (int k = 0; k < 3; ++k) spin[k] *= 0.6f + 0.45f * float(w) / float(kWorlds - 1);
    }
  }
  batch.SetState(state);
  StepSettings settings;
  settings.gyroscopic = true;
  std::vector<reference::World<float>> float_worlds(kWorlds, reference::World<float>(scene));
  std::vector<reference::World<double>> double_worlds(kWorlds, reference::World<double>(scene));
  std::vector<Deviation> to_float(batch.body_count()), to_double(batch.body_count()),
      float_to_double(batch.body_count());
  for (int step = 0; step < kSteps; ++step) {
    batch.GetState(state);
    for (std::size_t w = 0; w < kWorlds; ++w) {
      SyncReferenceWorld(float_worlds[w], batch, w, state.data() + w * per_world);
      SyncReferenceWorld(double_worlds[w], batch, w, state.data() + w * per_world);
      float_worlds[w].Step(settings);
      double_worlds[w].Step(settings);
    }
    batch.Step(settings);
    ASSERT_EQ(batch.UnhealthyWorldCount(), 0u) << "step " << step;
    batch.GetState(state);
    for (std::size_t w = 0; w < kWorlds; ++w) {
      for (std::size_t b = 0; b < batch.body_count(); ++b) {
        const float* lane = state.data() + w * per_world + b * kStateFloatsPerBody;
        to_float[b].Max(CompareTurningBody(lane, float_worlds[w].body(b)));
        to_double[b].Max(CompareTurningBody(lane, double_worlds[w].body(b)));
        float_to_double[b].Max(CompareTurningBody(
            FloatStateArray(float_worlds[w].body(b)).data(), double_worlds[w].body(b)));
      }
    }
  }
  for (std::size_t b = 0; b < batch.body_count(); ++b) {
    const Deviation& own = float_to_double[b];
    std::printf("gyroscopic scene on %s, body %zu: worst one-step deviation in FLT_EPSILON x "
                "scale: float ref (x %.1f, q %.1f, v %.1f), double ref (x %.1f, q %.1f, v %.1f), "
                "float ref from double (x %.1f, q %.1f, v %.1f)\n",
                batch.SimdTarget(), b, to_float[b].position, to_float[b].rotation,
                to_float[b].velocity, to_double[b].position, to_double[b].rotation,
                to_double[b].velocity, own.position, own.rotation, own.velocity);
    const auto bound = [](double own_gap) { return std::max(kStepTolerance, 2.0 * own_gap); };
    for (const Deviation* d : {&to_float[b], &to_double[b]}) {
      const char* against = d == &to_float[b] ? "reference<float>" : "reference<double>";
      EXPECT_LT(d->position, bound(own.position)) << "body " << b << " position vs " << against;
      EXPECT_LT(d->rotation, bound(own.rotation)) << "body " << b << " rotation vs " << against;
      EXPECT_LT(d->velocity, bound(own.velocity)) << "body " << b << " velocity vs " << against;
    }
  }
}

// (b): the spinner alone (no constraint touches it, gravity factor 0), so only
// the gyroscopic step changes its w. Its kinetic energy 1/2 w.I w and |I w|
// in the body frame are invariants of the exact motion and of the implicit
// midpoint rule; the step's energy rescale keeps the first to rounding (a few
// FLT_EPSILON per step, 4 per step allowed over the 120 steps: 480 FLT_EPSILON
// relative), and two Newton steps keep the second to the same order while
// h|w| = 0.67 rad is small against the inertia ratio 3 (measured over the
// 120 steps: energy 2.6e-5 to 3.0e-5, |I w| 1.3e-5 to 1.5e-5, bound 5.7e-5).
TEST_P(GyroscopicTargetTest, FreeSpinKeepsEnergyAndMomentumMagnitude) {
  const Scene scene = GyroscopicScene();
  Batch batch(scene, kWorlds, BatchOptions{1, 0, GetParam()});
  const std::size_t per_world = batch.body_count() * kStateFloatsPerBody;
  std::vector<float> state(kWorlds * per_world);
  const auto invariants = [&](double& energy, double& momentum) {
    batch.GetState(state);
    reference::World<double> world(scene);
    SetReferenceState(world, state.data());
    const reference::Body<double>& body = world.body(1);
    const reference::Vec3<double> w = body.rotation.conjugate() * body.angular_velocity;
    const reference::Vec3<double> iw(w.x() * 1, w.y() * 2, w.z() * 3);
    energy = 0.5 * w.dot(iw);
    momentum = iw.norm();
  };
  double energy0, momentum0;
  invariants(energy0, momentum0);
  StepSettings settings;
  settings.gyroscopic = true;
  double worst_energy = 0, worst_momentum = 0;
  for (int step = 0; step < kSteps; ++step) {
    batch.Step(settings);
    double energy, momentum;
    invariants(energy, momentum);
    worst_energy = std::max(worst_energy, std::abs(energy / energy0 - 1));
    worst_momentum = std::max(worst_momentum, std::abs(momentum / momentum0 - 1));
  }
  std::printf("spinner on %s: worst relative change over %d steps: energy %.3g, |I w| %.3g\n",
              batch.SimdTarget(), kSteps, worst_energy, worst_momentum);
  EXPECT_LT(worst_energy, 4.0 * kSteps * FLT_EPSILON);
  EXPECT_LT(worst_momentum, 4.0 * kSteps * FLT_EPSILON);
}

INSTANTIATE_TEST_SUITE_P(EveryTarget, GyroscopicTargetTest,
                         ::testing::ValuesIn(SupportedStepTargets()),
                         [](const auto& info) { return std::string(hwy::TargetName(info.param)); });

}  // namespace
}  // namespace manyworlds
