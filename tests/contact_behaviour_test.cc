// The physics of contacts (docs/contacts.md) as the bodies show it, on every
// stepper: the scalar reference (reference/world.h) in float and double, and
// the SIMD batch on every Highway target this CPU runs (one test instance per
// stepper, named after it; see tests/stepper_adapters.h; the batch runs 20
// identical worlds and checks bitwise that all agree with world 0, which the
// assertions read). Jolt's own contact tests (../shared/docs/jolt-contacts.md
// §12) where they apply to a plane or to spheres and capsules together, and
// physics Jolt does not test (an incline, a rolling sphere, resting capsules
// and boxes, stacks of spheres and capsules, momentum in a glancing hit).
//
// The manifolds of these scenes (point counts and points, normal impulses,
// slot order and filter) and the scenes the reference refuses are checked on
// the reference's contact accessors in tests/reference_contact_test.cc; the
// scenes are shared (tests/contact_test_scenes.h).
//
// Every expectation comes from the physics or from the spec's formulas, never
// from running this code; each tolerance says why it is what it is. A
// tolerance that is a rounding bound of the precision holds the batch (float)
// to the float bound. Measured worst deviations (worst relative to the bound
// over a test's cases) are printed per stepper as "[measured] ..." lines at the
// end of each test (and recorded in the XML output).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <map>
#include <memory>
#include <string>
#include <utility>

#include "manyworlds/batch.h"
#include "manyworlds/scene.h"
#include "reference/math.h"
#include "tests/contact_test_scenes.h"
#include "tests/measurements.h"
#include "tests/stepper_adapters.h"

namespace manyworlds::stepper_test {
namespace {

using namespace ::manyworlds::contact_test;  // NOLINT(google-build-using-namespace)

// ---------------------------------------------------------------- helpers

// Angle (rad) of the rotation between two unit quaternions, from the relative
// rotation's components (acos of a dot product near 1 would be good to only
// ~1e-3 rad in float).
double AngleBetween(const Quatd& a, const Quatd& b) {
  const Quatd relative = a.conjugate() * b;
  return 2.0 * std::atan2(relative.vec().norm(), std::abs(relative.w()));
}

// Position tolerance of a body falling ~5 m in T: float spacing at 5 m is
// 4.8e-7, and ~120 rounded additions may stack to ~3e-5 at worst; double is
// exact to far below 1e-9. The batch is float.
double FallTolerance(const StepperKind& kind) { return kind.is_double ? 1e-9 : 3e-5; }

// Parameter: the stepper (reference float / double, batch per target).
class ContactBehaviourTest : public ::testing::TestWithParam<StepperKind> {
 protected:
  void SetUp() override { Measurements::Get().Clear(); }
  void TearDown() override { Measurements::Get().Print(GetParam().name); }
  std::unique_ptr<Stepper> Make(const Scene& scene) const { return GetParam().make(scene); }
};

// ------------------------------------------------ Jolt: CollisionElastic (×3)

// A unit sphere, e = 1, dropped so it reaches y = 1 − 1e-4 after 1 s: before
// the hit its velocity is g t; the hit step reflects it with no gravity gained
// (the Δv_f compensation); 1 s later it is back where it started, at rest.
void CollisionElasticCase(const StepperKind& kind, double delta_time, int substeps,
                          bool gravity_as_force) {
  SCOPED_TRACE("delta_time " + std::to_string(delta_time) + ", substeps " +
               std::to_string(substeps) + (gravity_as_force ? ", gravity as a force" : ""));
  const ElasticDrop drop = MakeElasticDrop(delta_time, substeps);
  StepSettings settings = drop.settings;
  const double g = drop.g;
  const std::unique_ptr<Stepper> world = kind.make(drop.scene);
  const double start = world->Position(1).y();  // start_y rounded to float
  const double hit_y = start + PredictFall(-g, drop.substep, 1.0);
  if (gravity_as_force) settings.gravity = {0.0f, 0.0f, 0.0f};
  const auto step = [&](const StepSettings& s) {
    if (gravity_as_force) world->SetForce(1, Vec3d(0.0, -drop.mass * g, 0.0));
    world->Step(s);
  };
  const auto simulate = [&](double seconds) {
    const int steps = int(std::lround(seconds / delta_time));
    for (int i = 0; i < steps; ++i) step(settings);
  };

  simulate(1.0);
  EXPECT_AT_MOST("fall_position", Distance(world->Position(1), 0.0, hit_y, 0.0),
                 FallTolerance(kind));
  // Not yet hit: free fall (Jolt's 1e-4; float velocity ~10 m/s is good to 1e-5).
  EXPECT_AT_MOST("fall_velocity", Distance(world->LinearVelocity(1), 0.0, -g, 0.0), 1e-4);

  step(SingleStep(settings));
  // Reflected, without the gravity of the hit substep (Jolt's 1e-4).
  EXPECT_AT_MOST("reflected_velocity", Distance(world->LinearVelocity(1), 0.0, g, 0.0), 1e-4);

  simulate(1.0);
  // Symplectic Euler is time-symmetric here: the rise retraces the fall.
  EXPECT_AT_MOST("return_position", Distance(world->Position(1), 0.0, start, 0.0),
                 FallTolerance(kind));
  EXPECT_AT_MOST("return_velocity", Distance(world->LinearVelocity(1), 0.0, 0.0, 0.0), 1e-4);
}

TEST_P(ContactBehaviourTest, CollisionElastic) {
  CollisionElasticCase(GetParam(), 1.0 / 60.0, 1, false);
  CollisionElasticCase(GetParam(), 2.0 / 60.0, 2, false);
  CollisionElasticCase(GetParam(), 4.0 / 60.0, 4, false);
  CollisionElasticCase(GetParam(), 1.0 / 60.0, 1, true);
  CollisionElasticCase(GetParam(), 4.0 / 60.0, 4, true);
}

// ---------------------------------------------- Jolt: CollisionInelastic (×3)

// e = 0: all velocity is lost in the hit and the sphere stays where it hit.
void CollisionInelasticCase(const StepperKind& kind, double delta_time, int substeps) {
  SCOPED_TRACE("delta_time " + std::to_string(delta_time) + ", substeps " +
               std::to_string(substeps));
  const std::unique_ptr<Stepper> world = kind.make(InelasticDropScene(delta_time, substeps));
  const StepSettings settings = Settings(delta_time, substeps);

  Simulate(*world, settings, 1.0);
  world->Step(SingleStep(settings));
  // Jolt's tolerances (1e-4).
  EXPECT_AT_MOST("hit_velocity", Distance(world->LinearVelocity(1), 0.0, 0.0, 0.0), 1e-4);
  EXPECT_AT_MOST("hit_position", Distance(world->Position(1), 0.0, kInelasticHitY, 0.0), 1e-4);

  Simulate(*world, settings, 1.0);
  EXPECT_AT_MOST("rest_velocity", Distance(world->LinearVelocity(1), 0.0, 0.0, 0.0), 1e-4);
  EXPECT_AT_MOST("rest_position", Distance(world->Position(1), 0.0, kInelasticHitY, 0.0), 1e-4);
}

TEST_P(ContactBehaviourTest, CollisionInelastic) {
  CollisionInelasticCase(GetParam(), 1.0 / 60.0, 1);
  CollisionInelasticCase(GetParam(), 2.0 / 60.0, 2);
  CollisionInelasticCase(GetParam(), 4.0 / 60.0, 4);
}

// ------------------------------------------ Jolt: PenetrationSlop1/2/3 (×3)

// A box of half extent 1 placed `depth` into the floor, 1 s: up to the slop a
// penetration is left alone (the box does not move at all); beyond it the
// position phase pushes the box out to exactly the slop.
void PenetrationSlopCase(const StepperKind& kind, double depth, double expected_depth,
                         double delta_time, int substeps) {
  SCOPED_TRACE("depth " + std::to_string(depth) + ", substeps " + std::to_string(substeps));
  const std::unique_ptr<Stepper> world = kind.make(SunkBoxScene(depth));
  Simulate(*world, Settings(delta_time, substeps), 1.0);
  // Jolt's tolerances: position 1e-5; velocities "zero" (Jolt's default 1e-6;
  // here 1e-5: four corner rows share the weight by Gauss-Seidel, so the
  // residual is a few float roundings of the 0.16 m/s gravity step).
  EXPECT_AT_MOST("position", Distance(world->Position(1), 0.0, 1.0 - expected_depth, 0.0), 1e-5);
  EXPECT_AT_MOST("linear_velocity", Distance(world->LinearVelocity(1), 0.0, 0.0, 0.0), 1e-5);
  EXPECT_AT_MOST("angular_velocity", Distance(world->AngularVelocity(1), 0.0, 0.0, 0.0), 1e-5);
}

TEST_P(ContactBehaviourTest, PenetrationSlop) {
  for (const auto& [delta_time, substeps] :
       {std::pair{1.0 / 60.0, 1}, std::pair{2.0 / 60.0, 2}, std::pair{4.0 / 60.0, 4}}) {
    PenetrationSlopCase(GetParam(), kSlop, kSlop, delta_time, substeps);              // 1
    PenetrationSlopCase(GetParam(), 2.0 * kSlop, kSlop, delta_time, substeps);        // 2
    PenetrationSlopCase(GetParam(), 0.1 * kSlop, 0.1 * kSlop, delta_time, substeps);  // 3
  }
}

// --------------------------------- speculative contacts (Jolt, zero gravity)

// 1.1 × the speculative distance above, falling 1 m per step: no contact at
// the start of step 1, so both tunnel 1 m in; step 2 finds them.
TEST_P(ContactBehaviourTest, OutsideOfSpeculativeContactDistance) {
  const double gap = 1.1 * kSpeculative, velocity = -1.0 / kDt;
  const std::unique_ptr<Stepper> world = Make(BoxAndSphere(gap, velocity));
  world->Step(ZeroGravity());
  // Unimpeded (Jolt 1e-6; float at 1 m is good to 1e-7 per operation).
  EXPECT_AT_MOST("box_tunnelled", Distance(world->Position(1), 0.0, 1.0 + gap - 1.0, 0.0), 1e-6);
  EXPECT_AT_MOST("sphere_tunnelled", Distance(world->Position(2), 3.0, 1.0 + gap - 1.0, 0.0),
                 1e-6);

  world->Step(ZeroGravity());
  // e = 0 and already penetrating: the approach is stopped dead.
  EXPECT_AT_MOST("box_velocity", std::abs(world->LinearVelocity(1).y()), 1e-4);
  EXPECT_AT_MOST("sphere_velocity", std::abs(world->LinearVelocity(2).y()), 1e-4);
  // The sphere (one row through its centre, K = 1/m) is pushed out by the
  // position phase: C = max(s + slop, −0.2) = −0.2 in both passes, each moving
  // it β·0.2 = 0.04 m: 0.08 m in all (float: 1e-6 at ~0.1 m).
  EXPECT_MEASURED_NEAR("sphere_pushed_out", world->Position(2).y(), gap + 0.08, 1e-6);
}

// 0.9 × the speculative distance above, falling 1 m per step, e = 0: the
// speculative contact lets it close the gap exactly (v = −gap/dt) and land on
// the floor; the next step it rests.
TEST_P(ContactBehaviourTest, InsideSpeculativeContactDistanceNoRestitution) {
  const double gap = 0.9 * kSpeculative, velocity = -1.0 / kDt;
  const std::unique_ptr<Stepper> world = Make(BoxAndSphere(gap, velocity));
  const std::size_t box = 1, sphere = 2;
  world->Step(ZeroGravity());
  // Jolt's tolerances: box 1e-3 / 0.05 (four corner rows by Gauss-Seidel),
  // sphere 1e-6 / 1e-4 (one row).
  EXPECT_AT_MOST("box_position_1", Distance(world->Position(box), 0.0, 1.0, 0.0), 1e-3);
  EXPECT_AT_MOST("box_velocity_1", Distance(world->LinearVelocity(box), 0.0, -gap / kDt, 0.0),
                 0.05);
  EXPECT_AT_MOST("box_angular_velocity_1",
                 Distance(world->AngularVelocity(box), 0.0, 0.0, 0.0), 0.05);
  EXPECT_AT_MOST("sphere_position_1", Distance(world->Position(sphere), 3.0, 1.0, 0.0), 1e-6);
  EXPECT_AT_MOST("sphere_velocity_1",
                 Distance(world->LinearVelocity(sphere), 0.0, -gap / kDt, 0.0), 1e-4);
  EXPECT_AT_MOST("sphere_angular_velocity_1",
                 Distance(world->AngularVelocity(sphere), 0.0, 0.0, 0.0), 1e-6);

  world->Step(ZeroGravity());
  EXPECT_AT_MOST("box_position_2", Distance(world->Position(box), 0.0, 1.0, 0.0), 1e-3);
  EXPECT_AT_MOST("box_velocity_2", Distance(world->LinearVelocity(box), 0.0, 0.0, 0.0), 0.05);
  EXPECT_AT_MOST("box_angular_velocity_2",
                 Distance(world->AngularVelocity(box), 0.0, 0.0, 0.0), 0.05);
  EXPECT_AT_MOST("sphere_position_2", Distance(world->Position(sphere), 3.0, 1.0, 0.0), 1e-4);
  EXPECT_AT_MOST("sphere_velocity_2", Distance(world->LinearVelocity(sphere), 0.0, 0.0, 0.0),
                 1e-4);
  EXPECT_AT_MOST("sphere_angular_velocity_2",
                 Distance(world->AngularVelocity(sphere), 0.0, 0.0, 0.0), 1e-6);
}

// The same with e = 1: the bounce is decided at setup from the current
// position, so the bodies travel the gap for free and leave from where they
// started, at the reflected velocity.
TEST_P(ContactBehaviourTest, InsideSpeculativeContactDistanceWithRestitution) {
  const double gap = 0.9 * kSpeculative, velocity = -1.0 / kDt;
  const std::unique_ptr<Stepper> world = Make(BoxAndSphere(gap, velocity, 1.0f));
  const std::size_t box = 1, sphere = 2;
  world->Step(ZeroGravity());
  // Jolt's tolerances: box 0.01 / 0.1 / 0.02, sphere 1e-5 / 2e-4.
  EXPECT_AT_MOST("box_position", Distance(world->Position(box), 0.0, 1.0 + gap + 1.0, 0.0),
                 0.01);
  EXPECT_AT_MOST("box_velocity", Distance(world->LinearVelocity(box), 0.0, -velocity, 0.0),
                 0.1);
  EXPECT_AT_MOST("box_angular_velocity",
                 Distance(world->AngularVelocity(box), 0.0, 0.0, 0.0), 0.02);
  EXPECT_AT_MOST("sphere_position",
                 Distance(world->Position(sphere), 3.0, 1.0 + gap + 1.0, 0.0), 1e-5);
  EXPECT_AT_MOST("sphere_velocity",
                 Distance(world->LinearVelocity(sphere), 0.0, -velocity, 0.0), 2e-4);
  EXPECT_AT_MOST("sphere_angular_velocity",
                 Distance(world->AngularVelocity(sphere), 0.0, 0.0, 0.0), 1e-6);
}

// e = 1, no restitution threshold, approaching at 0.9·gap per step: the first
// step's speculative row is slack (no impulse at all, the velocity bit for bit
// unchanged); in the second the gap closes within the step and it bounces.
TEST_P(ContactBehaviourTest, InsideSpeculativeContactDistanceWithRestitutionNoHit) {
  const double gap = 0.9 * kSpeculative, velocity = -0.9 * gap / kDt;
  const std::unique_ptr<Stepper> world = Make(BoxAndSphere(gap, velocity, 1.0f));
  StepSettings settings = ZeroGravity();
  settings.min_velocity_for_restitution = 0.0f;
  const double before = world->LinearVelocity(2).y();
  world->Step(settings);
  EXPECT_EQ(world->LinearVelocity(2).y(), before);
  world->Step(settings);
  // Reflected: b = e·v_n, no forces to compensate (one row: rounding only).
  EXPECT_MEASURED_NEAR("reflected_velocity", world->LinearVelocity(2).y(), -velocity, 1e-5);
}

// Moving away at 1 m per step from 0.9 × the speculative distance: contacts
// are made (speculative), yet the bodies move unimpeded (bit for bit).
TEST_P(ContactBehaviourTest, InsideSpeculativeContactDistanceMovingAway) {
  const double gap = 0.9 * kSpeculative, velocity = 1.0 / kDt;
  const std::unique_ptr<Stepper> world = Make(BoxAndSphere(gap, velocity));
  const Vec3d box_velocity = world->LinearVelocity(1);
  const Vec3d sphere_velocity = world->LinearVelocity(2);
  world->Step(ZeroGravity());
  EXPECT_EQ(world->LinearVelocity(1), box_velocity);
  EXPECT_EQ(world->LinearVelocity(2), sphere_velocity);
  EXPECT_EQ(world->AngularVelocity(1), Vec3d::Zero());
  EXPECT_AT_MOST("box_position", Distance(world->Position(1), 0.0, 1.0 + gap + 1.0, 0.0), 1e-6);
  EXPECT_AT_MOST("sphere_position", Distance(world->Position(2), 3.0, 1.0 + gap + 1.0, 0.0),
                 1e-6);
}

// --------------------------------------------- restitution threshold, slop

// Touching the floor, e = 1, zero gravity: an approach of 0.9 m/s is below
// min_velocity_for_restitution (1 m/s) and is stopped; 1.1 m/s bounces back.
TEST_P(ContactBehaviourTest, MinVelocityForRestitution) {
  for (const double speed : {0.9, 1.1}) {
    SCOPED_TRACE(speed);
    Scene scene;
    scene.AddBody(Floor(0.2f, 1.0f));
    BodySettings sphere = Sphere(1.0f, {0.0f, 1.0f, 0.0f});
    sphere.linear_velocity = {0.0f, float(-speed), 0.0f};
    scene.AddBody(sphere);
    const std::unique_ptr<Stepper> world = Make(scene);
    world->Step(ZeroGravity());
    const double expected = speed > 1.0 ? speed : 0.0;
    EXPECT_MEASURED_NEAR(speed > 1.0 ? "bounced_velocity" : "stopped_velocity",
                         world->LinearVelocity(1).y(), expected, 1e-6);
  }
}

// Zero gravity, at rest: a sphere 15 mm in (within the slop) is left exactly
// where it is; one 0.5 m in rises 2 passes × β × max_penetration = 0.08 m in
// one step, with its velocity untouched (the position phase moves poses only).
TEST_P(ContactBehaviourTest, PositionPhaseSlopAndMaxPenetration) {
  for (const double depth : {0.015, 0.5}) {
    SCOPED_TRACE(depth);
    Scene scene;
    scene.AddBody(Floor());
    scene.AddBody(Sphere(1.0f, {0.0f, float(1.0 - depth), 0.0f}));
    const std::unique_ptr<Stepper> world = Make(scene);
    const Vec3d start = world->Position(1);
    world->Step(ZeroGravity());
    if (depth < kSlop) {
      EXPECT_EQ(world->Position(1), start);
    } else {
      EXPECT_MEASURED_NEAR("pushed_out", world->Position(1).y(), 1.0 - depth + 0.08, 1e-6);
    }
    EXPECT_EQ(world->LinearVelocity(1), Vec3d::Zero());
    EXPECT_EQ(world->AngularVelocity(1), Vec3d::Zero());
  }
}

// ----------------------------------- Jolt: ActivationDeactivation (no sleep)

// A box of half 0.5 dropped from y = 5 comes to rest on its face at y = 0.5:
// Jolt's check is within 1.1·slop after 5 s. The landing may sink it up to
// the slop (never pushed out further), it never floats above the floor.
TEST_P(ContactBehaviourTest, BoxDroppedComesToRest) {
  const std::unique_ptr<Stepper> world = Make(DroppedBoxScene());
  Simulate(*world, Settings(), 5.0);
  const double y = world->Position(1).y();
  EXPECT_AT_MOST("position", Distance(world->Position(1), 0.0, 0.5, 0.0), 1.1 * kSlop);
  EXPECT_GE(y, 0.5 - kSlop - 1e-4);  // 0.1 mm for convergence
  EXPECT_LE(y, 0.5 + 1e-6);
  Report("sunk", 0.5 - y, kSlop + 1e-4);
  Report("floating", y - 0.5, 1e-6);
  // At rest (no sleeping: residuals of the last Gauss-Seidel pass only).
  EXPECT_AT_MOST("linear_velocity", Distance(world->LinearVelocity(1), 0.0, 0.0, 0.0), 1e-4);
  EXPECT_AT_MOST("angular_velocity", Distance(world->AngularVelocity(1), 0.0, 0.0, 0.0), 1e-4);
  // Fell flat, stays flat (a symmetric landing).
  EXPECT_AT_MOST("rotation", AngleBetween(world->Rotation(1), Quatd::Identity()), 1e-4);
}

// --------------------------------------------------------- Jolt: Friction

// A box of half 1, 1 mm into the floor, sliding at 20 m/s in 12 directions,
// μ = sqrt(0.9·0.8): compared after 60 steps with v −= μ g dt v̂ (stopping at
// 0), x += v dt. Jolt's tolerances: position and rotation 1e-2, velocity 2e-2,
// angular velocity 1e-2.
TEST_P(ContactBehaviourTest, Friction) {
  const double mu = std::sqrt(double(0.9f) * double(0.8f));
  for (int degrees = 0; degrees < 360; degrees += 30) {
    SCOPED_TRACE(degrees);
    const double angle = degrees * kPiD / 180.0;
    const double dx = std::cos(angle), dz = -std::sin(angle);  // rotation about Y of +X
    Scene scene;
    scene.AddBody(Floor(0.9f));
    BodySettings box = Box({1.0f, 1.0f, 1.0f}, {0.0f, 0.999f, 0.0f});
    box.rotation = RotationAbout({0, 1, 0}, angle);
    box.linear_velocity = {float(20.0 * dx), 0.0f, float(20.0 * dz)};
    box.shape.friction = 0.8f;
    scene.AddBody(box);
    const std::unique_ptr<Stepper> world = Make(scene);
    const Quatd start_rotation = world->Rotation(1);
    double speed = 20.0, distance = 0.0;
    for (int i = 0; i < 60; ++i) {
      world->Step(Settings());
      speed = std::max(0.0, speed - mu * kG * kDt);
      distance += speed * kDt;
    }
    EXPECT_AT_MOST("position", Distance(world->Position(1), distance * dx, 0.999, distance * dz),
                   1e-2);
    EXPECT_AT_MOST("rotation", AngleBetween(world->Rotation(1), start_rotation), 1e-2);
    EXPECT_AT_MOST("linear_velocity",
                   Distance(world->LinearVelocity(1), speed * dx, 0.0, speed * dz), 2e-2);
    EXPECT_AT_MOST("angular_velocity", Distance(world->AngularVelocity(1), 0.0, 0.0, 0.0), 1e-2);
  }
}

// ------------------------------------------------- Jolt: AngularFriction

// A box of half 1 spinning at 10 rad/s about Y on the floor, μ = sqrt(0.2·0.3):
// the angular row brakes it at dω/dt = I⁻¹ μ Σ d_i Λn_i / dt = I⁻¹ μ √2 m g
// (corners √2 from the anchor; I = 2m/3), each step ω −= that·dt. Jolt's
// tolerances: ω 5e-3, rotation 2e-3, position 1e-4, linear velocity 4e-4.
TEST_P(ContactBehaviourTest, AngularFriction) {
  const double mu = std::sqrt(double(0.2f) * double(0.3f));
  const std::unique_ptr<Stepper> world = Make(SpinningBoxScene());
  const double deceleration = 1.5 * std::sqrt(2.0) * mu * kG;  // (3/(2m)) μ √2 m g
  double omega = 10.0, angle = 0.0;
  for (int i = 0; i < 60; ++i) {
    world->Step(Settings());
    omega = std::max(0.0, omega - deceleration * kDt);
    angle += omega * kDt;
  }
  EXPECT_GT(omega, 0.0);  // still spinning: the test sees the friction torque
  EXPECT_AT_MOST("angular_velocity", Distance(world->AngularVelocity(1), 0.0, omega, 0.0), 5e-3);
  const Quatd expected = reference::QuatFromAxisAngle<double>(Vec3d::UnitY(), angle);
  EXPECT_AT_MOST("rotation", AngleBetween(world->Rotation(1), expected), 2e-3);
  EXPECT_AT_MOST("position", Distance(world->Position(1), 0.0, 0.999, 0.0), 1e-4);
  EXPECT_AT_MOST("linear_velocity", Distance(world->LinearVelocity(1), 0.0, 0.0, 0.0), 4e-4);
}

// ----------------------------------------------------------------- incline

// A box of half 0.5 on a plane tilted by θ about Z (1 mm in, within the slop),
// μ the same on both shapes. It rests iff tan θ ≤ μ; otherwise it slides down
// at a = g (sin θ − μ cos θ), which after N steps of symplectic Euler is
// d = a dt² N (N + 1) / 2. Runs 1 s (`iterations` velocity passes, warm start
// on or off) and returns the distance travelled down the slope and the speed.
struct Slide {
  double distance;      // m, down the slope
  double speed;         // m/s at the end
  double speed_gained;  // m/s down the slope from step 10 to step 60
};

Slide InclineSlide(const StepperKind& kind, double theta, float mu, int iterations = 10,
                   bool warm_start = true) {
  const double n_x = -std::sin(theta), n_y = std::cos(theta);  // plane normal
  const std::unique_ptr<Stepper> world = kind.make(InclineScene(theta, mu));
  const Vec3d start = world->Position(1);
  const StepSettings settings = InclineSettings(iterations, warm_start);
  const auto velocity_down = [&] {
    const Vec3d v = world->LinearVelocity(1);
    return -(v.x() * std::cos(theta) + v.y() * std::sin(theta));
  };
  Simulate(*world, settings, 10 * kDt);
  const double early = velocity_down();
  Simulate(*world, settings, 50 * kDt);
  const Vec3d moved = world->Position(1) - start;
  // It neither leaves the plane nor sinks into it beyond what is left alone:
  // with 10 passes the normal rows converge (0.1 mm); one pass a step does not
  // converge, and the position phase lets up to the slop stand.
  EXPECT_AT_MOST("off_plane", std::abs(moved.x() * n_x + moved.y() * n_y),
                 iterations >= 10 ? 1e-4 : kSlop);
  // Down the slope: −(cos θ, sin θ, 0).
  return {-(moved.x() * std::cos(theta) + moved.y() * std::sin(theta)),
          world->LinearVelocity(1).norm(), velocity_down() - early};
}

double SlideDistance(double theta, double mu, double seconds) {
  const double a = kG * (std::sin(theta) - mu * std::cos(theta));
  const double n = std::round(seconds / kDt);
  return a * kDt * kDt * n * (n + 1.0) / 2.0;
}

TEST_P(ContactBehaviourTest, BlockOnIncline) {
  const double deg = kPiD / 180.0;
  // Rests: tan 20° = 0.364 < 0.5, tan 30° = 0.577 < 0.6. The sliding
  // distances below are ≥ 0.1 m, so 0.1 mm separates resting from sliding;
  // at rest the speed is the solver's residual (1e-5 m/s).
  for (const auto& [degrees, mu] : {std::pair{20.0, 0.5f}, std::pair{30.0, 0.6f}}) {
    SCOPED_TRACE(std::to_string(degrees) + " " + std::to_string(mu));
    const Slide slide = InclineSlide(GetParam(), degrees * deg, mu);
    EXPECT_AT_MOST("rest_distance", std::abs(slide.distance), 1e-4);
    EXPECT_AT_MOST("rest_speed", slide.speed, 1e-5);
  }
  // Slides: tan 30° > 0.55 and > 0.3. Once sliding (steps 10 to 60) the
  // speed grows by exactly a·50 dt: 1e-4 relative, so μ off by 2e-5 at 0.55
  // would fail. The distance within 1%: the first step's friction limit comes
  // from normal impulses not yet converged (they share the weight among four
  // corners, Gauss-Seidel over 10 passes), which lags the slide by
  // ~0.7 mm/s there; the continuous a t²/2 (1.7% short) would still fail.
  for (const float mu : {0.55f, 0.3f}) {
    SCOPED_TRACE(mu);
    const Slide slide = InclineSlide(GetParam(), 30 * deg, mu);
    const double a = kG * (std::sin(30 * deg) - double(mu) * std::cos(30 * deg));
    EXPECT_MEASURED_NEAR("speed_gained", slide.speed_gained, a * 50 * kDt, 1e-4 * a * 50 * kDt);
    const double expected = SlideDistance(30 * deg, mu, 1.0);
    EXPECT_MEASURED_NEAR("slide_distance", slide.distance, expected, 1e-2 * expected);
  }
}

// Warm starting with point matching is what lets one velocity pass hold a box
// on an incline: the normal impulses carried over from the last step give the
// friction its limit in the only pass. Without warm start the limit is zero in
// that pass every step and the box slides as if frictionless, a = g sin θ.
TEST_P(ContactBehaviourTest, WarmStartHoldsBoxOnInclineWithOnePass) {
  const double theta = 20.0 * kPiD / 180.0;
  const double frictionless = SlideDistance(theta, 0.0, 1.0);  // 1.71 m
  // Held: the first step has nothing to carry over and slides freely
  // (g sin θ dt² = 0.9 mm), the next few with the first step's unconverged
  // impulses; 5 mm is 0.3% of the frictionless slide. At rest by the end.
  const Slide held = InclineSlide(GetParam(), theta, 0.8f, 1, true);
  EXPECT_AT_MOST("held_distance", std::abs(held.distance), 5e-3);
  EXPECT_AT_MOST("held_speed", held.speed, 1e-4);
  const Slide free = InclineSlide(GetParam(), theta, 0.8f, 1, false);
  EXPECT_MEASURED_NEAR("free_distance", free.distance, frictionless, 5e-3 * frictionless);
}

// What the warm start carries is the whole solution of a resting contact:
// once a box rests on an incline (tan θ < μ), the last step's impulses
// (normal ones by point matching, friction ones because the manifold existed)
// are exactly those that balance gravity, so with no velocity pass at all the
// warm start alone holds it. Without the friction carry-over it would slide
// frictionless (g sin θ: 1.7 m in 1 s), without the normal one sink.
TEST_P(ContactBehaviourTest, WarmStartAloneHoldsRestingBox) {
  const double theta = 20.0 * kPiD / 180.0;
  const std::unique_ptr<Stepper> world = Make(InclineScene(theta, 0.8f));
  Simulate(*world, Settings(), 1.0);  // settles with 10 passes
  const Vec3d settled = world->Position(1);
  StepSettings warm_start_only = Settings();
  warm_start_only.velocity_iterations = 0;
  Simulate(*world, warm_start_only, 1.0);
  // Each step re-applies impulses that cancel that step's gravity to float
  // rounding (~1e-7 relative of 0.16 m/s); 1e-5 m over 60 steps.
  EXPECT_AT_MOST("drift", Distance(world->Position(1), settled.x(), settled.y(), settled.z()),
                 1e-5);
  EXPECT_AT_MOST("speed", world->LinearVelocity(1).norm(), 1e-5);
}

// ---------------------------------------------------------- rolling sphere

// A solid sphere (r 0.5) sliding at v0 = 5 m/s without spin, μ = 0.5: friction
// brakes it at μ g and spins it up at 5 μ g / (2 r) until v = ω r, after
// t* = 2 v0 / (7 μ g) = 0.29 s; then it rolls on at 5/7 v0 (angular momentum
// about the contact point is conserved) with no more friction.
TEST_P(ContactBehaviourTest, SphereRollsWithoutSlipping) {
  const double r = kRollingRadius, v0 = kRollingSpeed, mu = kRollingFriction;
  const std::unique_ptr<Stepper> world = Make(RollingSphereScene());
  // Sliding (10 steps < t*/dt = 17.5): full friction each step. 1e-4: one
  // friction row at its limit μ m g dt, float roundings on 5 m/s.
  Simulate(*world, Settings(), 10 * kDt);
  const double t = 10 * kDt;
  EXPECT_MEASURED_NEAR("sliding_velocity", world->LinearVelocity(1).x(), v0 - mu * kG * t, 1e-4);
  EXPECT_MEASURED_NEAR("sliding_spin", world->AngularVelocity(1).z(), -2.5 * mu * kG / r * t,
                       1e-4);
  // Rolling: v = 5/7 v0, no slip at the contact (v + ω_z r = 0).
  Simulate(*world, Settings(), 1.0 - t);
  const double rolling = 5.0 / 7.0 * v0;
  EXPECT_MEASURED_NEAR("rolling_velocity", world->LinearVelocity(1).x(), rolling, 1e-4);
  EXPECT_MEASURED_NEAR("slip", world->LinearVelocity(1).x() + world->AngularVelocity(1).z() * r,
                       0.0, 1e-5);
  // And it keeps rolling: no loss over another second.
  Simulate(*world, Settings(), 1.0);
  EXPECT_MEASURED_NEAR("rolling_velocity_later", world->LinearVelocity(1).x(), rolling, 1e-4);
  EXPECT_MEASURED_NEAR("height", world->Position(1).y(), r, 1e-5);
}

// ------------------------------------------------------ capsules and boxes

// A capsule (r 0.3, h 0.5) lying along X on the floor (both ends touch) rests.
TEST_P(ContactBehaviourTest, CapsuleLyingRests) {
  const std::unique_ptr<Stepper> world = Make(LyingCapsuleScene());
  world->Step(Settings());
  Simulate(*world, Settings(), 2.0);
  EXPECT_AT_MOST("position", Distance(world->Position(1), 0.0, 0.3, 0.0), 1e-5);
  EXPECT_AT_MOST("linear_velocity", Distance(world->LinearVelocity(1), 0.0, 0.0, 0.0), 1e-5);
  EXPECT_AT_MOST("angular_velocity", Distance(world->AngularVelocity(1), 0.0, 0.0, 0.0), 1e-5);
}

// A box (half 0.5, 0.3, 0.4) on the floor rests where it is.
TEST_P(ContactBehaviourTest, BoxRestingStaysPut) {
  const std::unique_ptr<Stepper> world = Make(RestingBoxScene());
  Simulate(*world, Settings(), 1.0);
  EXPECT_AT_MOST("position", Distance(world->Position(1), 0.0, 0.3, 0.0), 1e-5);
}

// A box (half 0.5) turned 30° about Z, its lowest edge 1 mm above the floor:
// its centre of mass is beside the edge, so it tips onto its face and rests
// there.
TEST_P(ContactBehaviourTest, TiltedBoxOnEdgeFallsFlat) {
  const std::unique_ptr<Stepper> world = Make(BoxOnEdgeScene());
  world->Step(Settings());
  Simulate(*world, Settings(), 3.0);
  // Flat: one of the box's axes is vertical (within 1e-2 rad).
  const Eigen::Matrix3d rotation = world->Rotation(1).toRotationMatrix();
  double largest = 0.0;
  for (int k = 0; k < 3; ++k) largest = std::max(largest, std::abs(rotation(1, k)));
  EXPECT_GE(largest, std::cos(1e-2));
  Report("tilt_from_flat", std::acos(std::min(1.0, largest)), 1e-2);
  EXPECT_MEASURED_NEAR("height", world->Position(1).y(), 0.5, kSlop);
}

// A plane of a higher index than the sphere is body 2 of the slot (n points
// from the sphere to the plane, −Y); the sphere rests the same.
TEST_P(ContactBehaviourTest, PlaneAsBodyTwoHoldsTheSphere) {
  const std::unique_ptr<Stepper> world = Make(SphereOnLaterFloorScene());
  Simulate(*world, Settings(), 1.0);
  EXPECT_AT_MOST("position", Distance(world->Position(0), 0.0, 1.0, 0.0), 1e-5);
}

// ------------------------------------------- spheres and capsules together

// Jolt's CollisionElasticDynamic (×3), zero gravity: two equal unit spheres
// meet head on at 5 and −10 m/s (tests/contact_test_scenes.h,
// HeadOnSpheresScene). With e = 1 a head-on elastic collision of equal
// masses exchanges the velocities (Jolt's 1e-5); with e = 0 they move on
// together at the mean velocity, −2.5 m/s (momentum m·5 − m·10 conserved; the
// speculative row first lets the 0.01 m gap close, the next substep stops the
// rest). Either way there is no spin (the normal goes through both centres).
// After the hit substep the spheres keep their velocities: with e = 1 they
// fly apart (x = x0 + 8·v_before·dt + (N − 8)·v_after·dt after N substeps:
// the bounce is decided at the start of substep 8 and the bodies cover that
// substep at the new velocities); with e = 0 they stay touching.
void CollisionElasticDynamicCase(const StepperKind& kind, double delta_time, int substeps,
                                 float restitution) {
  SCOPED_TRACE("delta_time " + std::to_string(delta_time) + ", substeps " +
               std::to_string(substeps) + ", e " + std::to_string(restitution));
  const Scene scene = HeadOnSpheresScene(restitution);
  const std::unique_ptr<Stepper> world = kind.make(scene);
  const double x1 = world->Position(0).x(), x2 = world->Position(1).x();
  StepSettings settings = Settings(delta_time, substeps);
  settings.gravity = {0.0f, 0.0f, 0.0f};
  Simulate(*world, settings, 1.0);
  const double after1 = restitution > 0.0f ? kHeadOnV2 : 0.5 * (kHeadOnV1 + kHeadOnV2);
  const double after2 = restitution > 0.0f ? kHeadOnV1 : 0.5 * (kHeadOnV1 + kHeadOnV2);
  // 1e-5 m/s (Jolt's): one row through the centres, float roundings on 10 m/s.
  EXPECT_AT_MOST("velocity_1", Distance(world->LinearVelocity(0), after1, 0.0, 0.0), 1e-5);
  EXPECT_AT_MOST("velocity_2", Distance(world->LinearVelocity(1), after2, 0.0, 0.0), 1e-5);
  EXPECT_AT_MOST("angular_velocity_1", world->AngularVelocity(0).norm(), 1e-5);
  EXPECT_AT_MOST("angular_velocity_2", world->AngularVelocity(1).norm(), 1e-5);
  if (restitution > 0.0f) {
    // The world's substep is float(delta_time)/substeps = float(1/60) for all
    // three (halving is exact). Float: 60 rounded additions at |x| < 16
    // (half-spacing 9.5e-7) stay under 6e-5; double: exact to 1e-9.
    const double dt = double(float(delta_time)) / substeps;
    const int n = int(std::lround(1.0 / dt)), hit = kHeadOnHitSubstep;
    const double expected1 = x1 + hit * kHeadOnV1 * dt + (n - hit) * after1 * dt;
    const double expected2 = x2 + hit * kHeadOnV2 * dt + (n - hit) * after2 * dt;
    const double tolerance = kind.is_double ? 1e-9 : 6e-5;
    EXPECT_AT_MOST("position_1", Distance(world->Position(0), expected1, 0.0, 0.0), tolerance);
    EXPECT_AT_MOST("position_2", Distance(world->Position(1), expected2, 0.0, 0.0), tolerance);
  }
}

TEST_P(ContactBehaviourTest, CollisionElasticDynamic) {
  for (const float e : {1.0f, 0.0f}) {
    CollisionElasticDynamicCase(GetParam(), 1.0 / 60.0, 1, e);
    CollisionElasticDynamicCase(GetParam(), 2.0 / 60.0, 2, e);
    CollisionElasticDynamicCase(GetParam(), 4.0 / 60.0, 4, e);
  }
}

// Jolt's MinVelocityForRestitution with two spheres, zero gravity: a unit
// sphere at 1 m/s touches an equal one at rest, e = 1. Threshold 0.99 m/s
// (1 m/s exceeds it): elastic, the velocities are exchanged; 1.01 m/s: no
// bounce, the approach is stopped and both move on at 0.5 m/s. Checked after
// the first step and again 1 s later (nothing else acts). Jolt's 1e-6: one
// row, a few float roundings of 1 m/s.
TEST_P(ContactBehaviourTest, MinVelocityForRestitutionSpheres) {
  for (const float threshold : {0.99f, 1.01f}) {
    SCOPED_TRACE(threshold);
    const std::unique_ptr<Stepper> world = Make(TouchingSpheresScene(1.0));
    StepSettings settings = ZeroGravity();
    settings.min_velocity_for_restitution = threshold;
    const bool bounces = threshold < 1.0f;
    const double after1 = bounces ? 0.0 : 0.5, after2 = bounces ? 1.0 : 0.5;
    world->Step(settings);
    EXPECT_AT_MOST("velocity_1", Distance(world->LinearVelocity(0), after1, 0.0, 0.0), 1e-6);
    EXPECT_AT_MOST("velocity_2", Distance(world->LinearVelocity(1), after2, 0.0, 0.0), 1e-6);
    Simulate(*world, settings, 1.0);
    EXPECT_AT_MOST("velocity_1_later", Distance(world->LinearVelocity(0), after1, 0.0, 0.0),
                   1e-6);
    EXPECT_AT_MOST("velocity_2_later", Distance(world->LinearVelocity(1), after2, 0.0, 0.0),
                   1e-6);
  }
}

// A 3-body stack (SphereOnCapsuleScene): a capsule lying along X on the floor
// and a sphere exactly above its middle; it stays as placed for 5 s. The
// balance is unstable across the capsule (a ball on a free roller: in the YZ
// plane V = −m_s g (R + r) β²/2 for the sphere's angle β on the roller, and
// the motion grows as e^{λt}, λ ≈ 3.6 s⁻¹ with these masses). It holds because
// the scene is exactly mirror-symmetric about z = 0 with nothing across it:
// the capsule's axis is exactly along X (kYToX is exact in float), every
// centre, normal and point has z = 0, and products with exact zeros stay zero
// in any arithmetic; a stepper that made up a z component would fail here.
// At rest from the first step, 1e-5 m / 1e-5 m/s / 1e-5 rad: the two contacts
// hold both weights, the solver's residual is as the lying capsule's alone
// (CapsuleLyingRests).
TEST_P(ContactBehaviourTest, SphereOnCapsuleStaysPut) {
  const std::unique_ptr<Stepper> world = Make(SphereOnCapsuleScene());
  const Quatd capsule_rotation = world->Rotation(1);
  Simulate(*world, Settings(), 5.0);
  EXPECT_AT_MOST("capsule_position", Distance(world->Position(1), 0.0, kStackCapsuleY, 0.0), 1e-5);
  EXPECT_AT_MOST("sphere_position", Distance(world->Position(2), 0.0, kStackSphereY, 0.0), 1e-5);
  EXPECT_AT_MOST("capsule_rotation", AngleBetween(world->Rotation(1), capsule_rotation), 1e-5);
  EXPECT_AT_MOST("sphere_rotation", AngleBetween(world->Rotation(2), Quatd::Identity()), 1e-5);
  for (const std::size_t body : {std::size_t(1), std::size_t(2)}) {
    const std::string name = body == 1 ? "capsule" : "sphere";
    EXPECT_AT_MOST(name + "_velocity", world->LinearVelocity(body).norm(), 1e-5);
    EXPECT_AT_MOST(name + "_angular_velocity", world->AngularVelocity(body).norm(), 1e-5);
  }
}

// Two capsules crossing at right angles (CrossedCapsulesScene): one lying
// along X on the floor, the other along Z across its middle. Placed
// symmetrically they stay put, but this balance is unstable: the upper
// capsule is a plank across a free roller (a rola-bola board). In the YZ
// plane, with ψ the lower capsule's rolling angle and θ the upper one's tilt,
// rolling contacts give the potential V = m_u g ((R − t)/2 θ² − R ψ θ) (R, t
// = 0.3 m the radii), a saddle (det = −(m_u g R)² < 0); with the scene's masses
// and inertias (M_ψψ = 5 m R² + I_axis, M_θθ = m t² + I_across, M_ψθ = 2 m R t)
// the linearised motion grows as e^{λt}, λ = 2.25 s⁻¹. An asymmetry at float
// rounding (1e-8: e.g. a target contracting a·b − c·d into an FMA, which
// rounds differently on the two sides of the mirror) grows ×9.5 in 1 s but
// ×8e4 in 5 s, so this holds 1 s (5 s would need millimetres). At rest from
// the first step, 1e-5 m / 1e-5 m/s / 1e-5 rad: the first step's Gauss-Seidel
// (no impulses yet, the weight shared by two floor points solved one after
// the other) sinks the pair a few µm, which the warm start then holds.
TEST_P(ContactBehaviourTest, CrossedCapsulesStayPut) {
  const std::unique_ptr<Stepper> world = Make(CrossedCapsulesScene());
  const Quatd lower_rotation = world->Rotation(1), upper_rotation = world->Rotation(2);
  Simulate(*world, Settings(), 1.0);
  EXPECT_AT_MOST("lower_position", Distance(world->Position(1), 0.0, kLowerCapsuleY, 0.0), 1e-5);
  EXPECT_AT_MOST("upper_position", Distance(world->Position(2), 0.0, kUpperCapsuleY, 0.0), 1e-5);
  EXPECT_AT_MOST("lower_rotation", AngleBetween(world->Rotation(1), lower_rotation), 1e-5);
  EXPECT_AT_MOST("upper_rotation", AngleBetween(world->Rotation(2), upper_rotation), 1e-5);
  for (const std::size_t body : {std::size_t(1), std::size_t(2)}) {
    const std::string name = body == 1 ? "lower" : "upper";
    EXPECT_AT_MOST(name + "_velocity", world->LinearVelocity(body).norm(), 1e-5);
    EXPECT_AT_MOST(name + "_angular_velocity", world->AngularVelocity(body).norm(), 1e-5);
  }
}

// A glancing hit (GlancingSphereCapsuleScene): zero gravity, no friction, e =
// 0.5; a sphere flying at 6 m/s strikes a free capsule off its middle and at
// an angle. Contact impulses come in equal and opposite pairs, so the total
// linear momentum m_s v_s + m_c v_c stays m_s·(0, 0, −6) through the hit and
// after (1 s). Tolerance relative to |p0|: in float each applied impulse Δ
// changes the momentum by ~Δ·(m·m⁻¹ − 1) plus the velocities' rounding,
// ~1e-7 of |p0| per application over a few tens of them: 1e-5; in double
// 1e-12. That a hit happened and was glancing: the sphere leaves with an
// upward velocity, the capsule moves and spins.
TEST_P(ContactBehaviourTest, GlancingSphereCapsuleConservesMomentum) {
  const Scene scene = GlancingSphereCapsuleScene();
  const double capsule_mass = scene.bodies()[0].mass, sphere_mass = scene.bodies()[1].mass;
  const std::unique_ptr<Stepper> world = Make(scene);
  const Vec3d p0 = capsule_mass * world->LinearVelocity(0) + sphere_mass * world->LinearVelocity(1);
  const double tolerance = (GetParam().is_double ? 1e-12 : 1e-5) * p0.norm();
  double worst = 0.0;
  for (int i = 0; i < 60; ++i) {
    world->Step(ZeroGravity());
    const Vec3d p = capsule_mass * world->LinearVelocity(0) + sphere_mass * world->LinearVelocity(1);
    worst = std::max(worst, (p - p0).norm());
  }
  EXPECT_AT_MOST("momentum_error", worst, tolerance);
  // Deflected up and sideways; the capsule pushed away and turning.
  EXPECT_GT(world->LinearVelocity(1).y(), 0.5);
  EXPECT_GT(capsule_mass * world->LinearVelocity(0).norm(), 0.1 * p0.norm());
  EXPECT_GT(world->AngularVelocity(0).norm(), 0.1);
}

// ------------------------------------------- stability (issue 19, item 6)

// Friction 0 and 10 on a 30° incline: frictionless, the box slides at
// g sin θ exactly (the same symplectic-Euler distance, 1e-2 relative as
// BlockOnIncline's slides); with μ = 10 it rests at 30° and at 40° (a cube
// tips over beyond 45°, whatever its friction).
TEST_P(ContactBehaviourTest, FrictionZeroAndTen) {
  const double deg = kPiD / 180.0;
  const Slide frictionless = InclineSlide(GetParam(), 30 * deg, 0.0f);
  const double expected = SlideDistance(30 * deg, 0.0, 1.0);
  EXPECT_MEASURED_NEAR("frictionless_distance", frictionless.distance, expected,
                       1e-2 * expected);
  for (const double degrees : {30.0, 40.0}) {
    SCOPED_TRACE(degrees);
    const Slide sticky = InclineSlide(GetParam(), degrees * deg, 10.0f);
    EXPECT_AT_MOST("sticky_distance", std::abs(sticky.distance), 1e-4);
    EXPECT_AT_MOST("sticky_speed", sticky.speed, 1e-4);
  }
}

// A unit sphere started half its radius deep in the floor: the velocity phase
// adds no push-out speed (a penetrating point's bias is 0), the position
// phase moves it out by at most 2 x β x 0.2 m per step until the slop is left,
// so within 1 s it rests at the slop's depth, and no step leaves it with a
// speed beyond the 1 m of gravity's dt accumulates (it never flies off).
TEST_P(ContactBehaviourTest, DeepInitialPenetrationIsPushedOutCalmly) {
  Scene scene;
  scene.AddBody(Floor());
  scene.AddBody(Sphere(1.0f, {0.0f, 0.5f, 0.0f}));
  const std::unique_ptr<Stepper> world = Make(scene);
  double fastest = 0.0;
  for (int i = 0; i < 60; ++i) {
    world->Step(Settings());
    fastest = std::max(fastest, world->LinearVelocity(1).norm());
  }
  EXPECT_AT_MOST("fastest", fastest, 0.2);
  EXPECT_MEASURED_NEAR("depth", 1.0 - world->Position(1).y(), kSlop, 1e-3);
  EXPECT_AT_MOST("rest_speed", world->LinearVelocity(1).norm(), 1e-4);
}

// Mass ratio 100: a 100 kg ball resting on a 1 kg capsule lying on the floor
// (spheres and capsules only: boxes do not meet each other yet), both free
// to move only up and down (a ball on a cylinder is otherwise unstable and
// rolls off, which is not what this tests). The light capsule between
// carries 101 kg to the floor; Gauss-Seidel converges slowly at this ratio,
// so each step may leave some penetration, which the position phase keeps
// within the slop: after 5 s each contact is at most the slop and a
// millimetre deep, and both are at rest to 1 cm/s.
TEST_P(ContactBehaviourTest, HeavyBallOnLightCapsule) {
  Scene scene;
  scene.AddBody(Floor());
  BodySettings capsule = Capsule(0.3f, 0.5f, {0.0f, 0.3f, 0.0f});
  capsule.rotation = kYToX;
  capsule.mass = 1.0f;
  capsule.inertia_diagonal = {0.05f, 0.05f, 0.05f};
  capsule.allowed_dofs = AllowedDofs::kTranslationY;
  scene.AddBody(capsule);
  BodySettings ball = Sphere(0.25f, {0.0f, 0.85f, 0.0f});
  ball.mass = 100.0f;
  ball.inertia_diagonal = {2.5f, 2.5f, 2.5f};
  ball.allowed_dofs = AllowedDofs::kTranslationY;
  scene.AddBody(ball);
  const std::unique_ptr<Stepper> world = Make(scene);
  Simulate(*world, Settings(), 5.0);
  const double capsule_y = world->Position(1).y(), ball_y = world->Position(2).y();
  EXPECT_AT_MOST("floor_depth", std::abs(capsule_y - 0.3), kSlop + 1e-3);
  EXPECT_AT_MOST("ball_depth", std::abs(ball_y - capsule_y - 0.55), kSlop + 1e-3);
  EXPECT_AT_MOST("ball_speed", world->LinearVelocity(2).norm(), 1e-2);
  EXPECT_AT_MOST("capsule_speed", world->LinearVelocity(1).norm(), 1e-2);
}

// ------------------------- speculative distance from velocity (beyond Jolt)

// A unit sphere and a tumbling box dropped from 1 km (hitting at 140 m/s,
// 2.3 m per step) and from 2 m. With Jolt's fixed speculative distance each
// is caught only once inside the floor, and the position phase leaves it at
// the slop (more than 1 mm deep, at most slop + 1 mm). With
// speculative_contacts_from_velocity the contact is there a step early and
// each lands on the surface: never more than 1 mm deep (the resting
// target, which float rounding of the speculative bias s/dt meets by far).
TEST_P(ContactBehaviourTest, SpeculativeContactsFromVelocityLandOnTheSurface) {
  for (const double height : {1000.0, 2.0}) {
    for (const bool from_velocity : {false, true}) {
      Scene scene;
      scene.AddBody(Floor());
      // Each meets the floor (group 1) only, not the other.
      BodySettings sphere = Sphere(1.0f, {0.0f, float(height), 0.0f});
      sphere.shape.collision_group = 2;
      sphere.shape.collision_mask = 1;
      scene.AddBody(sphere);
      BodySettings box = Box({0.5f, 0.5f, 0.5f}, {5.0f, float(height), 0.0f});
      box.angular_velocity = {2.0f, 0.0f, 1.0f};
      box.shape.collision_group = 2;
      box.shape.collision_mask = 1;
      scene.AddBody(box);
      const std::unique_ptr<Stepper> world = Make(scene);
      StepSettings settings;
      settings.speculative_contacts_from_velocity = from_velocity;
      double deepest_sphere = 0.0;
      const int steps = height > 10.0 ? 1000 : 300;
      for (int i = 0; i < steps; ++i) {
        world->Step(settings);
        deepest_sphere = std::max(deepest_sphere, 1.0 - world->Position(1).y());
      }
      const std::string tag = std::string(from_velocity ? "from_velocity" : "fixed") + "_" +
                              std::to_string(int(height));
      const double sphere_depth = 1.0 - world->Position(1).y();
      // The box rests on a face: its lowest corner's depth.
      const Quatd q = world->Rotation(2);
      double lowest = 1e9;
      for (int corner = 0; corner < 8; ++corner) {
        const Vec3d local((corner & 1) ? 0.5 : -0.5, (corner & 2) ? 0.5 : -0.5,
                          (corner & 4) ? 0.5 : -0.5);
        lowest = std::min(lowest, (world->Position(2) + q * local).y());
      }
      if (from_velocity) {
        EXPECT_AT_MOST(tag + "_sphere_deepest", deepest_sphere, 1e-3);
        EXPECT_AT_MOST(tag + "_box_depth", -lowest, 1e-3);
      } else if (height > 10.0) {
        EXPECT_GT(sphere_depth, 1e-3) << tag;
        EXPECT_AT_MOST(tag + "_sphere_depth", sphere_depth, kSlop + 1e-3);
      }
      EXPECT_AT_MOST(tag + "_sphere_speed", world->LinearVelocity(1).norm(), 1e-3);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Steppers, ContactBehaviourTest, ::testing::ValuesIn(AllStepperKinds()),
                         [](const ::testing::TestParamInfo<StepperKind>& info) {
                           return info.param.name;
                         });

}  // namespace
}  // namespace manyworlds::stepper_test
