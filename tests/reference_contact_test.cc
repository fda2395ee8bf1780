// Contacts of the scalar reference world (reference/contact_constraint.h,
// docs/contacts.md), in float and double, read through the reference's contact
// accessors: the manifolds (point counts, points, normal, separation), the
// normal impulses, which pairs make slots and in what order, and the scenes
// the reference refuses.
//
// What the bodies do in these scenes (Jolt's own contact tests from
// ../shared/docs/jolt-contacts.md §12 where they apply to a plane, an incline,
// a rolling sphere, resting capsules and boxes) is checked on every stepper,
// the batch included, in tests/contact_behaviour_test.cc; a test here named
// <Name>Manifold(s) checks the manifolds of that file's test <Name> (the same
// scene and steps, tests/contact_test_scenes.h), and the comments of the
// others name their counterpart there.
//
// Shared setup as Jolt's PhysicsTestContext: the floor is a static body with
// a plane shape at y = 0 (body 0, so it is body 1 of its slots and n = +Y),
// zero damping, dt = 1/60, g = −9.81 m/s², density 1000 kg/m³. Every
// expectation comes from the physics or from the spec's formulas, never from
// running this code; each tolerance says why it is what it is.
#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

#include "manyworlds/batch.h"
#include "manyworlds/scene.h"
#include "reference/world.h"
#include "tests/contact_test_scenes.h"

namespace manyworlds::reference {
namespace {

using namespace ::manyworlds::contact_test;  // NOLINT(google-build-using-namespace)

template <class T>
class ReferenceContactTest : public ::testing::Test {};
using Scalars = ::testing::Types<float, double>;
TYPED_TEST_SUITE(ReferenceContactTest, Scalars);

template <class T>
double NormalImpulseSum(const ContactConstraint<T>& contact) {
  double sum = 0.0;
  for (int k = 0; k < contact.PointCount(); ++k) sum += double(contact.NormalImpulse(k));
  return sum;
}

// ------------------------------------------------ Jolt: CollisionElastic (×3)

// The hit step of the elastic drop (a unit sphere, e = 1) makes one point.
template <class T>
void CollisionElasticManifold(double delta_time, int substeps, bool gravity_as_force) {
  SCOPED_TRACE("delta_time " + std::to_string(delta_time) + ", substeps " +
               std::to_string(substeps) + (gravity_as_force ? ", gravity as a force" : ""));
  const ElasticDrop drop = MakeElasticDrop(delta_time, substeps);
  StepSettings settings = drop.settings;
  World<T> world(drop.scene);
  if (gravity_as_force) settings.gravity = {0.0f, 0.0f, 0.0f};
  const auto step = [&](const StepSettings& s) {
    if (gravity_as_force) world.SetForce(1, Vec3<T>(T(0), T(-drop.mass * drop.g), T(0)));
    world.Step(s);
  };
  const int steps = int(std::lround(1.0 / delta_time));
  for (int i = 0; i < steps; ++i) step(settings);
  step(SingleStep(settings));
  EXPECT_EQ(world.contact(0).PointCount(), 1);
}

TYPED_TEST(ReferenceContactTest, CollisionElasticManifold) {
  CollisionElasticManifold<TypeParam>(1.0 / 60.0, 1, false);
  CollisionElasticManifold<TypeParam>(2.0 / 60.0, 2, false);
  CollisionElasticManifold<TypeParam>(4.0 / 60.0, 4, false);
  CollisionElasticManifold<TypeParam>(1.0 / 60.0, 1, true);
  CollisionElasticManifold<TypeParam>(4.0 / 60.0, 4, true);
}

// ---------------------------------------------- Jolt: CollisionInelastic (×3)

// e = 0, 1 s after the hit: the sphere's one point lies below the centre,
// normal +Y, body 1 the floor, and at rest the normal impulse of a substep
// carries the sphere's weight.
template <class T>
void CollisionInelasticManifold(double delta_time, int substeps) {
  SCOPED_TRACE("delta_time " + std::to_string(delta_time) + ", substeps " +
               std::to_string(substeps));
  const double substep = delta_time / substeps;
  const Scene scene = InelasticDropScene(delta_time, substeps);
  const double mass = scene.bodies()[1].mass;
  World<T> world(scene);
  const StepSettings settings = Settings(delta_time, substeps);
  Simulate(world, settings, 1.0);
  world.Step(SingleStep(settings));
  Simulate(world, settings, 1.0);

  const ContactConstraint<T>& contact = world.contact(0);
  EXPECT_EQ(contact.body1(), 0u);
  EXPECT_EQ(contact.body2(), 1u);
  ASSERT_EQ(contact.PointCount(), 1);
  EXPECT_LE(Distance(contact.Normal(), 0.0, 1.0, 0.0), 1e-6);
  // The floor's point is the sphere's lowest point projected: the origin.
  EXPECT_LE(Distance(contact.Point1(0), 0.0, 0.0, 0.0), 1e-4);
  EXPECT_NEAR(double(contact.Separation(0)), -1e-4, 2e-5);  // the hit penetration
  // Resting: one substep's impulse is the weight's, m g dt (relative 1e-4:
  // one row through the centre of mass, solved to rounding).
  EXPECT_NEAR(double(contact.NormalImpulse(0)), mass * kG * substep, 1e-4 * mass * kG * substep);
}

TYPED_TEST(ReferenceContactTest, CollisionInelasticManifold) {
  CollisionInelasticManifold<TypeParam>(1.0 / 60.0, 1);
  CollisionInelasticManifold<TypeParam>(2.0 / 60.0, 2);
  CollisionInelasticManifold<TypeParam>(4.0 / 60.0, 4);
}

// ------------------------------------------ Jolt: PenetrationSlop1/2/3 (×3)

// A box of half extent 1 placed `depth` into the floor keeps its whole bottom
// face in contact for 1 s.
TYPED_TEST(ReferenceContactTest, PenetrationSlopManifold) {
  using T = TypeParam;
  for (const auto& [delta_time, substeps] :
       {std::pair{1.0 / 60.0, 1}, std::pair{2.0 / 60.0, 2}, std::pair{4.0 / 60.0, 4}}) {
    for (const double depth : {kSlop, 2.0 * kSlop, 0.1 * kSlop}) {
      World<T> world(SunkBoxScene(depth));
      Simulate(world, Settings(delta_time, substeps), 1.0);
      EXPECT_EQ(world.contact(0).PointCount(), 4) << depth << " " << substeps;
    }
  }
}

// --------------------------------- speculative contacts (Jolt, zero gravity)

// 1.1 × the speculative distance above, falling 1 m per step: no contact at
// the start of step 1; step 2 finds them.
TYPED_TEST(ReferenceContactTest, OutsideOfSpeculativeContactDistanceManifolds) {
  using T = TypeParam;
  const double gap = 1.1 * kSpeculative, velocity = -1.0 / kDt;
  World<T> world(BoxAndSphere(gap, velocity));
  ASSERT_EQ(world.contact_count(), 2u);
  world.Step(ZeroGravity());
  EXPECT_EQ(world.contact(0).PointCount(), 0);
  EXPECT_EQ(world.contact(1).PointCount(), 0);
  world.Step(ZeroGravity());
  EXPECT_EQ(world.contact(0).PointCount(), 4);  // the whole bottom face
  EXPECT_EQ(world.contact(1).PointCount(), 1);
}

// 0.9 × the speculative distance above, falling 1 m per step, e = 0: the
// speculative contacts exist from the first step and stay.
TYPED_TEST(ReferenceContactTest, InsideSpeculativeContactDistanceNoRestitutionManifolds) {
  using T = TypeParam;
  const double gap = 0.9 * kSpeculative, velocity = -1.0 / kDt;
  World<T> world(BoxAndSphere(gap, velocity));
  for (int step = 0; step < 2; ++step) {
    world.Step(ZeroGravity());
    EXPECT_EQ(world.contact(0).PointCount(), 4) << step;
    EXPECT_EQ(world.contact(1).PointCount(), 1) << step;
  }
}

// e = 1, no restitution threshold, approaching at 0.9·gap per step: the first
// step's speculative row is slack, so its impulse is exactly zero.
TYPED_TEST(ReferenceContactTest, InsideSpeculativeContactDistanceWithRestitutionNoHitManifold) {
  using T = TypeParam;
  const double gap = 0.9 * kSpeculative, velocity = -0.9 * gap / kDt;
  World<T> world(BoxAndSphere(gap, velocity, 1.0f));
  StepSettings settings = ZeroGravity();
  settings.min_velocity_for_restitution = 0.0f;
  world.Step(settings);
  ASSERT_EQ(world.contact(1).PointCount(), 1);
  EXPECT_EQ(world.contact(1).NormalImpulse(0), T(0));
}

// Moving away at 1 m per step from 0.9 × the speculative distance: contacts
// are made (speculative), yet with no impulse; the next step they are out of
// range and the manifolds are gone.
TYPED_TEST(ReferenceContactTest, InsideSpeculativeContactDistanceMovingAwayManifolds) {
  using T = TypeParam;
  const double gap = 0.9 * kSpeculative, velocity = 1.0 / kDt;
  World<T> world(BoxAndSphere(gap, velocity));
  world.Step(ZeroGravity());
  EXPECT_EQ(world.contact(0).PointCount(), 4);
  EXPECT_EQ(world.contact(1).PointCount(), 1);
  EXPECT_EQ(NormalImpulseSum(world.contact(0)), 0.0);
  EXPECT_EQ(NormalImpulseSum(world.contact(1)), 0.0);
  world.Step(ZeroGravity());
  EXPECT_EQ(world.contact(0).PointCount(), 0);
  EXPECT_EQ(world.contact(1).PointCount(), 0);
}

// ----------------------------------- Jolt: ActivationDeactivation (no sleep)

// The box dropped from y = 5 rests on its face after 5 s: its four corners
// carry exactly its weight.
TYPED_TEST(ReferenceContactTest, BoxDroppedComesToRestManifold) {
  using T = TypeParam;
  const Scene scene = DroppedBoxScene();
  const double mass = scene.bodies()[1].mass;
  World<T> world(scene);
  Simulate(world, Settings(), 5.0);
  const ContactConstraint<T>& contact = world.contact(0);
  EXPECT_EQ(contact.PointCount(), 4);
  EXPECT_NEAR(NormalImpulseSum(contact), mass * kG * kDt, 1e-3 * mass * kG * kDt);
}

// ------------------------------------------------- Jolt: AngularFriction

// The spinning box keeps its four corners on the floor for 60 steps.
TYPED_TEST(ReferenceContactTest, AngularFrictionManifold) {
  using T = TypeParam;
  World<T> world(SpinningBoxScene());
  for (int i = 0; i < 60; ++i) world.Step(Settings());
  EXPECT_EQ(world.contact(0).PointCount(), 4);
}

// ----------------------------------------------------------------- incline

// The box on an incline (BlockOnIncline, WarmStartHoldsBoxOnInclineWithOnePass)
// keeps four points for the whole second, resting or sliding.
TYPED_TEST(ReferenceContactTest, InclineManifold) {
  using T = TypeParam;
  const double deg = kPiD / 180.0;
  struct Case {
    double degrees;
    float mu;
    int iterations;
    bool warm_start;
  };
  for (const Case& c : {Case{20.0, 0.5f, 10, true}, Case{30.0, 0.6f, 10, true},
                        Case{30.0, 0.55f, 10, true}, Case{30.0, 0.3f, 10, true},
                        Case{20.0, 0.8f, 1, true}, Case{20.0, 0.8f, 1, false}}) {
    World<T> world(InclineScene(c.degrees * deg, c.mu));
    Simulate(world, InclineSettings(c.iterations, c.warm_start), 60 * kDt);
    EXPECT_EQ(world.contact(0).PointCount(), 4)
        << c.degrees << " " << c.mu << " " << c.iterations << " " << c.warm_start;
  }
}

// The box held on the incline by the warm start alone keeps its four points.
TYPED_TEST(ReferenceContactTest, WarmStartAloneHoldsRestingBoxManifold) {
  using T = TypeParam;
  World<T> world(InclineScene(20.0 * kPiD / 180.0, 0.8f));
  Simulate(world, Settings(), 1.0);  // settles with 10 passes
  StepSettings warm_start_only = Settings();
  warm_start_only.velocity_iterations = 0;
  Simulate(world, warm_start_only, 1.0);
  EXPECT_EQ(world.contact(0).PointCount(), 4);
}

// ---------------------------------------------------------- rolling sphere

// The sliding, then rolling sphere keeps its one point for 2 s.
TYPED_TEST(ReferenceContactTest, SphereRollsWithoutSlippingManifold) {
  using T = TypeParam;
  World<T> world(RollingSphereScene());
  Simulate(world, Settings(), 10 * kDt);
  Simulate(world, Settings(), 1.0 - 10 * kDt);
  Simulate(world, Settings(), 1.0);
  EXPECT_EQ(world.contact(0).PointCount(), 1);
}

// ------------------------------------------------------ capsule manifolds

// A capsule (r 0.3, h 0.5) lying along X on the floor: both ends touch (two
// points); resting (CapsuleLyingRests), the two points carry its weight.
TYPED_TEST(ReferenceContactTest, CapsuleLyingGetsTwoPoints) {
  using T = TypeParam;
  const Scene scene = LyingCapsuleScene();
  const double mass = scene.bodies()[1].mass;
  World<T> world(scene);
  world.Step(Settings());
  const ContactConstraint<T>& contact = world.contact(0);
  ASSERT_EQ(contact.PointCount(), 2);
  // The ends a = c − h â, b = c + h â in that order, â = −X here.
  EXPECT_LE(Distance(contact.Point2(0), 0.5, 0.0, 0.0), 1e-6);
  EXPECT_LE(Distance(contact.Point2(1), -0.5, 0.0, 0.0), 1e-6);
  Simulate(world, Settings(), 2.0);
  EXPECT_EQ(contact.PointCount(), 2);
  EXPECT_NEAR(NormalImpulseSum(contact), mass * kG * kDt, 1e-3 * mass * kG * kDt);
}

// The 2 cm capsule projection slop: tilted so one end is 1 cm higher, both ends
// still make points; 3 cm higher, only the lower end. Standing, the lower end.
TYPED_TEST(ReferenceContactTest, CapsuleTiltAndStanding) {
  using T = TypeParam;
  const double r = 0.3, h = 0.5;
  for (const double rise : {0.01, 0.03}) {
    const double tilt = std::asin(rise / (2.0 * h));
    Scene scene;
    scene.AddBody(Floor());
    // Lower end's bottom on the floor: y_c = h sin(tilt) + r cos(tilt) (the
    // two-point case's point lies r·ŵ below the end, ŵ tilted with the axis).
    BodySettings capsule =
        Capsule(float(r), float(h), {0.0f, float(h * std::sin(tilt) + r * std::cos(tilt)), 0.0f});
    capsule.rotation = RotationAbout({0, 0, 1}, kPiD / 2.0 - tilt);
    scene.AddBody(capsule);
    World<T> world(scene);
    world.Step(ZeroGravity());
    const ContactConstraint<T>& contact = world.contact(0);
    ASSERT_EQ(contact.PointCount(), rise < 0.02 ? 2 : 1) << rise;
    if (rise < 0.02) {
      // The lower end a = c − h â, â = (−cos t, sin t, 0); its point goes down
      // r ŵ, ŵ = n_p without its part along â = (sin t, cos t, 0): at
      // x = h cos t − r sin t on the floor (r n_p would be 3 mm off in x).
      EXPECT_NEAR(double(contact.Point2(0).x()), h * std::cos(tilt) - r * std::sin(tilt), 1e-5);
      EXPECT_NEAR(double(contact.Point2(0).y()), 0.0, 1e-6);
    }
  }
  Scene scene;
  scene.AddBody(Floor());
  scene.AddBody(Capsule(float(r), float(h), {0.0f, float(h + r), 0.0f}));
  World<T> world(scene);
  world.Step(Settings());
  ASSERT_EQ(world.contact(0).PointCount(), 1);
  EXPECT_LE(Distance(world.contact(0).Point2(0), 0.0, 0.0, 0.0), 1e-6);  // below the lower end
}

// ---------------------------------------------------------- box manifolds

// A box (half 0.5, 0.3, 0.4) resting on the floor (BoxRestingStaysPut): its
// bottom face's four corners carry its weight.
TYPED_TEST(ReferenceContactTest, BoxRestingGetsFourPoints) {
  using T = TypeParam;
  const Scene scene = RestingBoxScene();
  const double mass = scene.bodies()[1].mass;
  World<T> world(scene);
  Simulate(world, Settings(), 1.0);
  const ContactConstraint<T>& contact = world.contact(0);
  ASSERT_EQ(contact.PointCount(), 4);
  // Polygon order of the bottom face (k = Y, u = X, v = Z): (−,−), (+,−), (+,+), (−,+).
  EXPECT_LE(Distance(contact.Point2(0), -0.5, 0.0, -0.4), 1e-5);
  EXPECT_LE(Distance(contact.Point2(1), 0.5, 0.0, -0.4), 1e-5);
  EXPECT_LE(Distance(contact.Point2(2), 0.5, 0.0, 0.4), 1e-5);
  EXPECT_LE(Distance(contact.Point2(3), -0.5, 0.0, 0.4), 1e-5);
  EXPECT_NEAR(NormalImpulseSum(contact), mass * kG * kDt, 1e-3 * mass * kG * kDt);
}

// A box (half 0.5) turned 30° about Z, its lowest edge 1 mm above the floor:
// the face towards the floor has two corners within reach (the other two are
// 0.5 m up), so 2 points. It tips onto its face (TiltedBoxOnEdgeFallsFlat)
// and rests there with 4 points.
TYPED_TEST(ReferenceContactTest, TiltedBoxOnEdgeGetsTwoPointsThenFour) {
  using T = TypeParam;
  World<T> world(BoxOnEdgeScene());
  world.Step(Settings());
  const ContactConstraint<T>& contact = world.contact(0);
  ASSERT_EQ(contact.PointCount(), 2);
  // Both on the lowest edge, x = 0.5 (sin 30° − cos 30°) = −0.183.
  for (int k = 0; k < 2; ++k) {
    EXPECT_NEAR(double(contact.Point2(k).x()), 0.5 * (std::sin(kEdgeTilt) - std::cos(kEdgeTilt)),
                1e-5);
    EXPECT_NEAR(double(contact.Point2(k).y()), 0.001, 1e-6);  // the 1 mm gap
  }
  Simulate(world, Settings(), 3.0);
  EXPECT_EQ(contact.PointCount(), 4);
}

// Which corners are kept: a box (half 0.5) on one bottom edge, its bottom
// face tilted so the far edge is `rise` up. The manifold exists (the near
// edge touches) and keeps the corners with φ < D + 1 mm = 0.021 m: the far
// edge at 0.015 and at 0.0205 (kept only by the 1 mm tolerance) gives 4
// points, at 0.0215 and 0.025 it gives 2.
TYPED_TEST(ReferenceContactTest, BoxKeepsCornersWithinSpeculativeDistancePlusTolerance) {
  using T = TypeParam;
  for (const double rise : {0.015, 0.0205, 0.0215, 0.025}) {
    const double tilt = std::asin(rise / 1.0);  // the face is 1 m wide
    Scene scene;
    scene.AddBody(Floor());
    // Near (lower) edge on the floor: the centre 0.5 (cos t + sin t) up.
    BodySettings box =
        Box({0.5f, 0.5f, 0.5f}, {0.0f, float(0.5 * (std::cos(tilt) + std::sin(tilt))), 0.0f});
    box.rotation = RotationAbout({0, 0, 1}, tilt);
    scene.AddBody(box);
    World<T> world(scene);
    world.Step(ZeroGravity());
    EXPECT_EQ(world.contact(0).PointCount(), rise < 0.021 ? 4 : 2) << rise;
  }
}

// ---------------------------------------------- slots: order, body order

// A plane of a higher index than the sphere is body 2: n points from the
// sphere to the plane (−Y), the first point is on the sphere, and resting, its
// impulse carries the sphere's weight (the sphere's rest is checked in
// PlaneAsBodyTwoHoldsTheSphere).
TYPED_TEST(ReferenceContactTest, PlaneAsBodyTwoFlipsTheNormal) {
  using T = TypeParam;
  const Scene scene = SphereOnLaterFloorScene();
  const double mass = scene.bodies()[0].mass;
  World<T> world(scene);
  Simulate(world, Settings(), 1.0);
  ASSERT_EQ(world.contact_count(), 1u);
  const ContactConstraint<T>& contact = world.contact(0);
  EXPECT_EQ(contact.body1(), 0u);
  EXPECT_EQ(contact.body2(), 1u);
  EXPECT_LE(Distance(contact.Normal(), 0.0, -1.0, 0.0), 1e-6);
  ASSERT_EQ(contact.PointCount(), 1);
  EXPECT_LE(Distance(contact.Point1(0), 0.0, 0.0, 0.0), 1e-5);
  EXPECT_NEAR(double(contact.NormalImpulse(0)), mass * kG * kDt, 1e-4 * mass * kG * kDt);
}

TYPED_TEST(ReferenceContactTest, SlotsFollowTheFilterInPairOrder) {
  using T = TypeParam;
  Scene scene;
  BodySettings a = Sphere(0.5f, {0.0f, 2.0f, 0.0f});
  a.name = "a";
  a.shape.collision_group = 2;
  a.shape.collision_mask = 1;
  scene.AddBody(a);                                       // 0
  scene.AddBody(Floor());                                 // 1
  BodySettings b = Box({0.5f, 0.5f, 0.5f}, {3.0f, 2.0f, 0.0f});
  b.shape.collision_group = 4;
  b.shape.collision_mask = 1;
  scene.AddBody(b);                                       // 2
  BodySettings kinematic = Sphere(0.5f, {6.0f, 2.0f, 0.0f});
  kinematic.motion_type = MotionType::kKinematic;
  kinematic.shape.collision_mask = 1;  // meets the floor only
  scene.AddBody(kinematic);                               // 3: no dynamic body with the floor
  BodySettings no_shape = Sphere(0.5f, {9.0f, 2.0f, 0.0f});
  no_shape.shape.type = ShapeType::kNone;
  scene.AddBody(no_shape);                                // 4
  BodySettings other_group = Sphere(0.5f, {12.0f, 2.0f, 0.0f});
  other_group.shape.collision_group = 8;
  other_group.shape.collision_mask = 8;                   // does not meet the floor's group 1
  scene.AddBody(other_group);                             // 5
  World<T> world(scene);
  ASSERT_EQ(world.contact_count(), 2u);
  EXPECT_EQ(world.contact(0).body1(), 0u);
  EXPECT_EQ(world.contact(0).body2(), 1u);
  EXPECT_EQ(world.contact(1).body1(), 1u);
  EXPECT_EQ(world.contact(1).body2(), 2u);
}

// Bodies joined by a constraint do not collide, unless a shape says so.
TYPED_TEST(ReferenceContactTest, JoinedBodiesDoNotCollideUnlessAsked) {
  using T = TypeParam;
  Scene scene;
  scene.AddBody(Floor());
  scene.AddBody(Sphere(0.5f, {0.0f, 2.0f, 0.0f}));
  PointConstraintSettings joint;
  joint.body1 = 0;
  joint.body2 = 1;
  joint.point1 = joint.point2 = {0.0f, 2.0f, 0.0f};
  scene.AddConstraint(joint);
  EXPECT_EQ(World<T>(scene).contact_count(), 0u);
  scene.bodies()[1].shape.collide_with_joined = true;
  EXPECT_EQ(World<T>(scene).contact_count(), 1u);
}

// ---------------------------------------------------------------- refusals

TYPED_TEST(ReferenceContactTest, RefusesPlaneOnNonStaticBody) {
  using T = TypeParam;
  for (const MotionType type : {MotionType::kDynamic, MotionType::kKinematic}) {
    Scene scene;
    BodySettings wall = Floor();
    wall.name = "wall";
    wall.motion_type = type;
    scene.AddBody(wall);
    scene.AddBody(Sphere(0.5f, {0.0f, 2.0f, 0.0f}));
    try {
      World<T> world(scene);
      ADD_FAILURE() << "a plane on a non-static body was accepted";
    } catch (const std::invalid_argument& error) {
      EXPECT_NE(std::string(error.what()).find("wall"), std::string::npos) << error.what();
    }
  }
}

TYPED_TEST(ReferenceContactTest, RefusesUnsupportedPairNamingBothBodies) {
  using T = TypeParam;
  Scene scene;
  scene.AddBody(Floor());
  BodySettings a = Sphere(0.5f, {0.0f, 2.0f, 0.0f});
  a.name = "left ball";
  BodySettings b = Box({0.5f, 0.5f, 0.5f}, {3.0f, 2.0f, 0.0f});
  b.name = "right box";
  scene.AddBody(a);
  scene.AddBody(b);
  try {
    World<T> world(scene);
    ADD_FAILURE() << "a sphere-box pair was accepted";
  } catch (const std::invalid_argument& error) {
    const std::string what = error.what();
    EXPECT_NE(what.find("left ball"), std::string::npos) << what;
    EXPECT_NE(what.find("right box"), std::string::npos) << what;
  }
  // In groups that do not meet, the same scene is fine.
  scene.bodies()[1].shape.collision_group = 2;
  scene.bodies()[1].shape.collision_mask = 1;
  scene.bodies()[2].shape.collision_group = 4;
  scene.bodies()[2].shape.collision_mask = 1;
  EXPECT_EQ(World<T>(scene).contact_count(), 2u);
}

TYPED_TEST(ReferenceContactTest, RefusesExactSolverAndBadContactSettings) {
  using T = TypeParam;
  Scene scene;
  scene.AddBody(Floor());
  scene.AddBody(Sphere(0.5f, {0.0f, 2.0f, 0.0f}));
  World<T> world(scene);
  StepSettings exact = Settings();
  exact.solver = JointSolver::kExact;
  EXPECT_THROW(world.Step(exact), std::invalid_argument);
  EXPECT_EQ(world.body(1).position.y(), T(2));  // refused before anything moved
  for (float StepSettings::*field :
       {&StepSettings::speculative_contact_distance, &StepSettings::penetration_slop,
        &StepSettings::max_penetration_distance, &StepSettings::min_velocity_for_restitution}) {
    for (const float bad : {-0.01f, std::numeric_limits<float>::infinity(),
                            std::numeric_limits<float>::quiet_NaN()}) {
      StepSettings settings = Settings();
      settings.*field = bad;
      EXPECT_THROW(world.Step(settings), std::invalid_argument) << bad;
    }
  }
  // The exact solve without contact slots still runs.
  Scene no_contacts;
  no_contacts.AddBody(Sphere(0.5f, {0.0f, 2.0f, 0.0f}));
  World<T> free_world(no_contacts);
  EXPECT_NO_THROW(free_world.Step(exact));
}

}  // namespace
}  // namespace manyworlds::reference
