// Contacts of the scalar reference world (reference/contact_constraint.h,
// docs/contacts.md), in float and double, read through the reference's contact
// accessors: the manifolds (point counts, points, normal, separation), the
// normal impulses, which pairs make slots and in what order, and the scenes
// the reference refuses; for spheres and capsules with each other, the one
// point against the geometry of the closest points of their cores.
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
#include <vector>

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

// ------------------------------------------ spheres and capsules: the points

// Geometry of docs/contacts.md "Points of a pair of spheres and capsules": two
// bodies in zero gravity stepped once; the slot's manifold (found at the start
// of that step, from the scene's poses) is read. The expected points come
// from the shapes' geometry: the closest points s1, s2 of the cores (by hand,
// or for general skew segments by a brute-force search), n = (s2 − s1)/L,
// p1 = s1 + r1 n, p2 = s2 − r2 n, separation L − r1 − r2. Tolerance 1e-6 m: a
// few float roundings of lengths below 2 m (a normalisation, a clamp, a
// projection); in double it is far tighter.
constexpr double kPointTolerance = 1e-6;

using Vec3d = Vec3<double>;

Vec3d ToVec3d(const Float3& v) { return Vec3d(v[0], v[1], v[2]); }

// A body's shape centre and core segment a..b in world space, in double from
// the scene's floats (a sphere: a = b = the centre).
struct Segment {
  Vec3d a, b;
};
Segment CoreOf(const BodySettings& body) {
  const Quat<double> q = Quat<double>(body.rotation[3], body.rotation[0], body.rotation[1],
                                      body.rotation[2])
                             .normalized();
  const Vec3d centre = ToVec3d(body.position) + q * ToVec3d(body.shape.position);
  const Quat<double> shape_q =
      q * Quat<double>(body.shape.rotation[3], body.shape.rotation[0], body.shape.rotation[1],
                       body.shape.rotation[2]);
  const double h = body.shape.type == ShapeType::kCapsule ? double(body.shape.half_height) : 0.0;
  const Vec3d axis = shape_q * Vec3d::UnitY();
  return {centre - h * axis, centre + h * axis};
}

// Closest points of two segments by brute force, independent of the doc's
// formulas: |s2 − s1| is convex in (t1, t2) on [0, 1]², and so is its minimum
// over t2 as a function of t1; nested ternary searches (200 halvings by 2/3
// each: 1e-35) find the minimum. Only for segments far from parallel (the
// minimum is then unique).
std::pair<Vec3d, Vec3d> BruteClosestPoints(const Segment& s1, const Segment& s2) {
  const auto point1 = [&](double t) { return Vec3d(s1.a + t * (s1.b - s1.a)); };
  const auto point2 = [&](double t) { return Vec3d(s2.a + t * (s2.b - s2.a)); };
  const auto best_t2 = [&](double t1) {
    double lo = 0.0, hi = 1.0;
    for (int i = 0; i < 200; ++i) {
      const double m1 = lo + (hi - lo) / 3.0, m2 = hi - (hi - lo) / 3.0;
      if ((point2(m1) - point1(t1)).norm() <= (point2(m2) - point1(t1)).norm()) {
        hi = m2;
      } else {
        lo = m1;
      }
    }
    return (lo + hi) / 2.0;
  };
  const auto distance = [&](double t1) { return (point2(best_t2(t1)) - point1(t1)).norm(); };
  double lo = 0.0, hi = 1.0;
  for (int i = 0; i < 200; ++i) {
    const double m1 = lo + (hi - lo) / 3.0, m2 = hi - (hi - lo) / 3.0;
    if (distance(m1) <= distance(m2)) {
      hi = m2;
    } else {
      lo = m1;
    }
  }
  const double t1 = (lo + hi) / 2.0;
  return {point1(t1), point2(best_t2(t1))};
}

// The slot of a scene of just `body0` and `body1` (zero gravity, one step).
template <class T>
struct PairManifold {
  int count = 0;
  Vec3d normal, point1, point2;
  double separation = 0.0;
  int max_points = 0;
};

template <class T>
PairManifold<T> ManifoldOf(const BodySettings& body0, const BodySettings& body1) {
  Scene scene;
  scene.AddBody(body0);
  scene.AddBody(body1);
  World<T> world(scene);
  PairManifold<T> out;
  EXPECT_EQ(world.contact_count(), 1u);
  if (world.contact_count() != 1u) return out;
  world.Step(ZeroGravity());
  const ContactConstraint<T>& contact = world.contact(0);
  out.count = contact.PointCount();
  out.max_points = contact.MaxPointCount();
  out.normal = contact.Normal().template cast<double>();
  if (out.count > 0) {
    out.point1 = contact.Point1(0).template cast<double>();
    out.point2 = contact.Point2(0).template cast<double>();
    out.separation = double(contact.Separation(0));
  }
  return out;
}

// The one point of cores' closest points s1, s2 (body order), radii r1, r2,
// normal n (n = (s2 − s1)/L, or the fallback when L = 0).
template <class T>
void ExpectOnePoint(const PairManifold<T>& m, const Vec3d& s1, const Vec3d& s2, double r1,
                    double r2, const Vec3d& n, double tolerance = kPointTolerance) {
  ASSERT_EQ(m.count, 1);
  EXPECT_EQ(m.max_points, 1);
  EXPECT_LE((m.normal - n).norm(), tolerance) << m.normal.transpose() << " vs " << n.transpose();
  const Vec3d p1 = s1 + r1 * n, p2 = s2 - r2 * n;
  EXPECT_LE((m.point1 - p1).norm(), tolerance) << m.point1.transpose() << " vs " << p1.transpose();
  EXPECT_LE((m.point2 - p2).norm(), tolerance) << m.point2.transpose() << " vs " << p2.transpose();
  EXPECT_NEAR(m.separation, (s2 - s1).dot(n) - r1 - r2, tolerance);
}

template <class T>
void ExpectOnePoint(const PairManifold<T>& m, const Vec3d& s1, const Vec3d& s2, double r1,
                    double r2) {
  ExpectOnePoint(m, s1, s2, r1, r2, Vec3d((s2 - s1).normalized()));
}

BodySettings SphereAt(double radius, Vec3d c) {
  return Sphere(float(radius), {float(c.x()), float(c.y()), float(c.z())});
}
BodySettings CapsuleAt(double radius, double half_height, Vec3d c, Quaternion rotation) {
  BodySettings capsule =
      Capsule(float(radius), float(half_height), {float(c.x()), float(c.y()), float(c.z())});
  capsule.rotation = rotation;
  return capsule;
}
// Body Y along world −X: kYToX, then 180° about Z (exact in float).
constexpr Quaternion kYToMinusX{0.5f, -0.5f, 0.5f, 0.5f};
constexpr Quaternion kIdentity{0.0f, 0.0f, 0.0f, 1.0f};

// Sphere–sphere: the point on the line of centres, kept while the surfaces
// are less than D = 0.02 m apart; n from body 1 (the lower index) to body 2.
TYPED_TEST(ReferenceContactTest, SphereSpherePointOnTheLineOfCentres) {
  using T = TypeParam;
  const Vec3d c1(1.0, 2.0, 3.0), u = Vec3d(2.0, -1.0, 2.0) / 3.0;  // |u| = 1
  const double r1 = 0.5, r2 = 0.3;
  for (const double gap : {0.0, 0.015, 0.025}) {
    SCOPED_TRACE(gap);
    const BodySettings a = SphereAt(r1, c1), b = SphereAt(r2, c1 + (r1 + r2 + gap) * u);
    const Vec3d ca = ToVec3d(a.position), cb = ToVec3d(b.position);  // as the world has them
    const PairManifold<T> m = ManifoldOf<T>(a, b);
    if (gap > kSpeculative) {
      EXPECT_EQ(m.count, 0);
      continue;
    }
    ExpectOnePoint(m, ca, cb, r1, r2);
    EXPECT_NEAR(m.separation, gap, kPointTolerance);
    // The other body order: n from the (now first) small sphere to the big one.
    const PairManifold<T> swapped = ManifoldOf<T>(b, a);
    ExpectOnePoint(swapped, cb, ca, r2, r1);
    EXPECT_LE((swapped.normal + u).norm(), kPointTolerance);
  }
}

// Concentric spheres: δ = 0 gives no direction; the fallback is +Y.
TYPED_TEST(ReferenceContactTest, ConcentricSpheresFallBackToPlusY) {
  using T = TypeParam;
  const Vec3d c(1.0, 2.0, 3.0);
  const PairManifold<T> m = ManifoldOf<T>(SphereAt(0.5, c), SphereAt(0.3, c));
  const Vec3d cf = ToVec3d(SphereAt(0.5, c).position);
  ExpectOnePoint(m, cf, cf, 0.5, 0.3, Vec3d::UnitY());
  EXPECT_NEAR(m.separation, -0.8, kPointTolerance);
}

// Sphere–capsule: a capsule (r 0.3, h 0.5) along X at the origin, core
// a = (−0.5, 0, 0) to b = (0.5, 0, 0); a sphere (r 0.19) whose centre is 0.5
// from the core (separation 0.01): over the segment's interior the core point
// is the centre's foot on the axis, beyond either end that end.
TYPED_TEST(ReferenceContactTest, SphereCapsuleNearestPointOfTheSegment) {
  using T = TypeParam;
  const double rc = 0.3, rs = 0.19;
  const BodySettings capsule = CapsuleAt(rc, 0.5, Vec3d::Zero(), kYToX);
  struct Case {
    const char* name;
    Vec3d centre;  // the sphere's
    Vec3d core;    // the nearest point of the capsule's core
  };
  for (const Case& c : {Case{"interior", {0.2, 0.3, 0.4}, {0.2, 0.0, 0.0}},
                        Case{"beyond b", {0.8, 0.4, 0.0}, {0.5, 0.0, 0.0}},
                        Case{"beyond a", {-0.8, 0.0, -0.4}, {-0.5, 0.0, 0.0}}}) {
    SCOPED_TRACE(c.name);
    const BodySettings sphere = SphereAt(rs, c.centre);
    const Vec3d centre = ToVec3d(sphere.position);
    // Capsule first: n from the capsule to the sphere.
    const PairManifold<T> m = ManifoldOf<T>(capsule, sphere);
    ExpectOnePoint(m, c.core, centre, rc, rs);
    EXPECT_NEAR(m.separation, 0.01, kPointTolerance);
    // Sphere first: n from the sphere to the capsule.
    ExpectOnePoint(ManifoldOf<T>(sphere, capsule), centre, c.core, rs, rc);
  }
  // 0.03 apart (r 0.17): beyond D, no point.
  EXPECT_EQ(ManifoldOf<T>(capsule, SphereAt(0.17, {0.2, 0.3, 0.4})).count, 0);
  // A sphere centred on the core: δ = 0 and not two capsules, so +Y.
  const BodySettings inside = SphereAt(rs, {0.25, 0.0, 0.0});
  ExpectOnePoint(ManifoldOf<T>(capsule, inside), Vec3d(0.25, 0.0, 0.0), Vec3d(0.25, 0.0, 0.0), rc,
                 rs, Vec3d::UnitY());
}

// Capsule–capsule, core segments crossing: capsule 1 (r 0.2) along X at the
// origin, capsule 2 (r 0.25) along Y centred at (0.25, 0.25, 0): both cores
// pass through (0.25, 0, 0), L = 0 (every coordinate here is exact in float).
// The fallback normal is across both segments, normalize(d1 × d2) as it
// comes: crossing cores have no side "towards" the other (their centres are
// level along d1 × d2), so the sign follows the shapes' axes, a fixed rule.
TYPED_TEST(ReferenceContactTest, CrossingCapsulesFallBackToTheCrossProduct) {
  using T = TypeParam;
  const double r1 = 0.2, r2 = 0.25;
  const Vec3d meet(0.25, 0.0, 0.0);
  BodySettings along_x = CapsuleAt(r1, 0.5, Vec3d::Zero(), kYToX);
  BodySettings along_y = CapsuleAt(r2, 0.5, {0.25, 0.25, 0.0}, kIdentity);
  // d1 × d2 = X × Y = +Z. The point: s1 = s2 = meet, separation −(r1 + r2).
  const PairManifold<T> m = ManifoldOf<T>(along_x, along_y);
  ExpectOnePoint(m, meet, meet, r1, r2, Vec3d::UnitZ());
  EXPECT_NEAR(m.separation, -(r1 + r2), kPointTolerance);
  // The other body order: d1 × d2 = Y × X = −Z.
  ExpectOnePoint(ManifoldOf<T>(along_y, along_x), meet, meet, r2, r1, -Vec3d::UnitZ());
  // The same shapes on a body whose centre of mass sits off its shape:
  // still +Z (the bodies' centres play no part).
  along_x.position = {0.0f, 0.0f, 1.0f};
  along_x.shape.position = {-1.0f, 0.0f, 0.0f};
  ExpectOnePoint(ManifoldOf<T>(along_x, along_y), meet, meet, r1, r2, Vec3d::UnitZ());
}

// Capsule–capsule, skew: closest points of segments at an angle, inside both
// or clamped to an end, against the brute-force search. The second radius is
// chosen so the surfaces are 0.01 apart. Points 1e-5: the closest points of
// segments at angle θ move by the rounding over sin θ (θ ≥ 30° here).
TYPED_TEST(ReferenceContactTest, SkewCapsulesClosestPointsOfTheSegments) {
  using T = TypeParam;
  struct Case {
    Float3 axis1;
    double angle1;
    Vec3d centre1;
    double h1;
    Float3 axis2;
    double angle2;
    Vec3d centre2;
    double h2;
  };
  const double r1 = 0.2;
  for (const Case& c : {
           // Perpendicular, interior of both: s1 = (0.25, 0, 0), s2 = (0.25, 0.46, 0).
           Case{{0, 0, 1}, kPiD / 2, {0.0, 0.0, 0.0}, 0.5, {1, 0, 0}, kPiD / 2, {0.25, 0.46, 0.0}, 0.5},
           // General angles, both interior.
           Case{{0, 0, 1}, 0.7, {0.0, 0.0, 0.0}, 0.5, {1, 0, 0}, 1.2, {0.3, 0.7, 0.2}, 0.4},
           // Segment 2 ends before reaching segment 1's line: clamped to its end.
           Case{{0, 0, 1}, kPiD / 2, {0.0, 0.0, 0.0}, 0.5, {1, 0, 0}, kPiD / 2, {0.25, 0.3, 0.65}, 0.5},
           // Both clamped: the ends nearest each other.
           Case{{1, 0, 0}, 0.9, {0.1, 0.2, 0.3}, 0.3, {0, 0, 1}, 2.1, {0.9, 0.9, 0.4}, 0.35},
       }) {
    BodySettings b1 = Capsule(float(r1), float(c.h1),
                              {float(c.centre1.x()), float(c.centre1.y()), float(c.centre1.z())});
    b1.rotation = RotationAbout(c.axis1, c.angle1);
    BodySettings b2 = Capsule(0.1f, float(c.h2),
                              {float(c.centre2.x()), float(c.centre2.y()), float(c.centre2.z())});
    b2.rotation = RotationAbout(c.axis2, c.angle2);
    const auto [s1, s2] = BruteClosestPoints(CoreOf(b1), CoreOf(b2));
    const double distance = (s2 - s1).norm();
    SCOPED_TRACE("s1 " + std::to_string(s1.x()) + " " + std::to_string(s1.y()) + " " +
                 std::to_string(s1.z()) + ", L " + std::to_string(distance));
    ASSERT_GT(distance, r1 + 0.05);  // room for a second radius
    b2.shape.radius = float(distance - r1 - 0.01);
    const double r2 = b2.shape.radius;
    ExpectOnePoint(ManifoldOf<T>(b1, b2), s1, s2, r1, r2, Vec3d((s2 - s1).normalized()), 1e-5);
    // Both orders give the same pair of points, swapped, and n reversed.
    ExpectOnePoint(ManifoldOf<T>(b2, b1), s2, s1, r2, r1, Vec3d((s1 - s2).normalized()), 1e-5);
  }
}

// Capsule–capsule, parallel (Δ = 0): the closest points are not unique while
// the segments overlap along their direction; the point is at the middle of
// the overlap of segment 2 projected on segment 1. Capsule 1 (r 0.2) along X
// at the origin, x ∈ [−0.5, 0.5]; capsule 2 (r 0.19) along ±X, 0.4 above.
TYPED_TEST(ReferenceContactTest, ParallelCapsulesMiddleOfTheOverlap) {
  using T = TypeParam;
  const double r1 = 0.2, r2 = 0.19;
  const BodySettings lower = CapsuleAt(r1, 0.5, Vec3d::Zero(), kYToX);
  struct Case {
    const char* name;
    double half_height, x;  // capsule 2's: x ∈ [x − h, x + h]
    Quaternion rotation;
    double middle;  // of the overlap
  };
  for (const Case& c : {Case{"overlapping", 0.5, 0.5, kYToX, 0.25},  // [0, 0.5]
                        Case{"overlapping, antiparallel", 0.5, 0.5, kYToMinusX, 0.25},
                        Case{"inside", 0.2, -0.1, kYToX, -0.1},  // [−0.3, 0.1]
                        Case{"covering", 1.0, 0.25, kYToMinusX, 0.0}}) {  // [−0.5, 0.5]
    SCOPED_TRACE(c.name);
    const BodySettings upper = CapsuleAt(r2, c.half_height, {c.x, 0.4, 0.0}, c.rotation);
    const PairManifold<T> m = ManifoldOf<T>(lower, upper);
    ExpectOnePoint(m, Vec3d(c.middle, 0.0, 0.0), Vec3d(c.middle, 0.4, 0.0), r1, r2);
    EXPECT_NEAR(m.separation, 0.01, kPointTolerance);
  }
  // Overlapping on one line (L = 0, d1 × d2 = 0): the fallback +Y.
  const BodySettings inline_capsule = CapsuleAt(r2, 0.5, {0.5, 0.0, 0.0}, kYToX);
  ExpectOnePoint(ManifoldOf<T>(lower, inline_capsule), Vec3d(0.25, 0.0, 0.0),
                 Vec3d(0.25, 0.0, 0.0), r1, r2, Vec3d::UnitY());
}

// Parallel, not overlapping: the nearest ends. Capsule 2 (r 0.21) along X at
// (1.3, 0.3, 0), x ∈ [0.8, 1.8]: s1 = b1 = (0.5, 0, 0), s2 = a2 = (0.8, 0.3, 0),
// L = 0.3 √2 = 0.424, separation 0.014.
TYPED_TEST(ReferenceContactTest, ParallelCapsulesNotOverlappingNearestEnds) {
  using T = TypeParam;
  const PairManifold<T> m = ManifoldOf<T>(CapsuleAt(0.2, 0.5, Vec3d::Zero(), kYToX),
                                          CapsuleAt(0.21, 0.5, {1.3, 0.3, 0.0}, kYToX));
  ExpectOnePoint(m, Vec3d(0.5, 0.0, 0.0), Vec3d(0.8, 0.3, 0.0), 0.2, 0.21);
  EXPECT_NEAR(m.separation, 0.3 * std::sqrt(2.0) - 0.41, kPointTolerance);
  // (0.03, 0.03, 0) further apart: L = 0.467, beyond D.
  EXPECT_EQ(ManifoldOf<T>(CapsuleAt(0.2, 0.5, Vec3d::Zero(), kYToX),
                          CapsuleAt(0.21, 0.5, {1.33, 0.33, 0.0}, kYToX))
                .count,
            0);
}

// End to end: the two nearest ends, in line (along X and along Y) and at a
// right angle (an L: capsule 2 along Z beginning 0.3 beyond capsule 1's end).
TYPED_TEST(ReferenceContactTest, CapsulesEndToEnd) {
  using T = TypeParam;
  {
    SCOPED_TRACE("in line along X");
    const PairManifold<T> m = ManifoldOf<T>(CapsuleAt(0.2, 0.5, Vec3d::Zero(), kYToX),
                                            CapsuleAt(0.2, 0.5, {1.41, 0.0, 0.0}, kYToX));
    ExpectOnePoint(m, Vec3d(0.5, 0.0, 0.0), Vec3d(0.91, 0.0, 0.0), 0.2, 0.2);
    EXPECT_NEAR(m.separation, 0.01, kPointTolerance);
  }
  {
    SCOPED_TRACE("in line along Y, standing");
    const PairManifold<T> m = ManifoldOf<T>(CapsuleAt(0.2, 0.5, Vec3d::Zero(), kIdentity),
                                            CapsuleAt(0.2, 0.5, {0.0, 1.41, 0.0}, kIdentity));
    ExpectOnePoint(m, Vec3d(0.0, 0.5, 0.0), Vec3d(0.0, 0.91, 0.0), 0.2, 0.2);
  }
  {
    SCOPED_TRACE("at a right angle");
    // Capsule 2 along Z at (0.8, 0, 0.7): z ∈ [0.2, 1.2]; s2 = (0.8, 0, 0.2),
    // L = √(0.3² + 0.2²) = 0.3606, separation 0.0106 with r 0.2 and 0.15.
    const PairManifold<T> m = ManifoldOf<T>(CapsuleAt(0.2, 0.5, Vec3d::Zero(), kYToX),
                                            CapsuleAt(0.15, 0.5, {0.8, 0.0, 0.7}, kYToZ));
    ExpectOnePoint(m, Vec3d(0.5, 0.0, 0.0), Vec3d(0.8, 0.0, 0.2), 0.2, 0.15);
  }
}

// ----------------------------- spheres and capsules: impulses of the scenes

// The hit of HeadOnSpheres (CollisionElasticDynamic): one point on the line
// of centres (n = +X from the left sphere to the right one), 0.01 m apart.
// Equal masses m: one row of effective mass m/2 through both centres, v_n =
// −15 m/s. e = 1: Λ = (m/2)(15 + 15) = 15 m (the exchange); e = 0: the
// speculative row lets the gap close, Λ = (m/2)(15 − s/dt) = (m/2)(15 − 0.6).
// Relative 1e-5: s is the difference of float positions near 2 (1e-6 m, so
// s/dt to 6e-5 of 14.4 m/s... 4e-6 relative) plus a few roundings.
TYPED_TEST(ReferenceContactTest, HeadOnSpheresManifold) {
  using T = TypeParam;
  for (const float e : {1.0f, 0.0f}) {
    SCOPED_TRACE(e);
    const Scene scene = HeadOnSpheresScene(e);
    const double mass = scene.bodies()[0].mass;
    World<T> world(scene);
    for (int i = 0; i < kHeadOnHitSubstep; ++i) {
      world.Step(ZeroGravity());
      ASSERT_EQ(world.contact(0).PointCount(), 0) << i;
    }
    world.Step(ZeroGravity());
    const ContactConstraint<T>& contact = world.contact(0);
    ASSERT_EQ(contact.PointCount(), 1);
    EXPECT_LE(Distance(contact.Normal(), 1.0, 0.0, 0.0), 1e-6);
    const double separation = kHeadOnGap - (kHeadOnV1 - kHeadOnV2) * kHeadOnHitSubstep * kDt;
    EXPECT_NEAR(double(contact.Separation(0)), separation, 1e-5);
    EXPECT_NEAR(double(contact.Point1(0).y()), 0.0, 1e-6);
    const double expected = e > 0.0f ? mass * (kHeadOnV1 - kHeadOnV2)
                                     : mass / 2.0 * (kHeadOnV1 - kHeadOnV2 - separation / kDt);
    EXPECT_NEAR(double(contact.NormalImpulse(0)), expected, 1e-5 * expected);
  }
}

// MinVelocityForRestitution with two touching spheres (1 m/s into one at
// rest, e = 1, equal masses m): above the threshold (0.99 m/s) the row
// bounces, Λ = (m/2)(1 + 1) = m; below it (1.01) it stops the approach,
// Λ = (m/2)·1. Relative 1e-6: one row, a few roundings.
TYPED_TEST(ReferenceContactTest, MinVelocityForRestitutionSpheresManifold) {
  using T = TypeParam;
  for (const float threshold : {0.99f, 1.01f}) {
    SCOPED_TRACE(threshold);
    const Scene scene = TouchingSpheresScene(1.0);
    const double mass = scene.bodies()[0].mass;
    World<T> world(scene);
    StepSettings settings = ZeroGravity();
    settings.min_velocity_for_restitution = threshold;
    world.Step(settings);
    const ContactConstraint<T>& contact = world.contact(0);
    ASSERT_EQ(contact.PointCount(), 1);
    EXPECT_LE(Distance(contact.Point1(0), 0.0, 0.0, 0.0), 1e-6);
    EXPECT_NEAR(double(contact.Separation(0)), 0.0, 1e-6);
    const double expected = threshold < 1.0f ? mass : mass / 2.0;
    EXPECT_NEAR(double(contact.NormalImpulse(0)), expected, 1e-6 * expected);
  }
}

// A stack on the floor after `seconds`: the upper body (2) rests on the lower
// one (1) at one point on the lower one's top (2 lower_y up), n = +Y,
// carrying the upper body's weight per step; the lower one's two floor points
// carry both weights; the upper body does not touch the floor. Relative 1e-4
// (one row through the centres of mass) and 1e-3 (the two floor points, as
// the lying capsule's).
template <class T>
void ExpectStackManifolds(const Scene& scene, double lower_y, double seconds) {
  const double lower_mass = scene.bodies()[1].mass, upper_mass = scene.bodies()[2].mass;
  World<T> world(scene);
  Simulate(world, Settings(), seconds);
  ASSERT_EQ(world.contact_count(), 3u);
  const ContactConstraint<T>& floor_lower = world.contact(0);
  const ContactConstraint<T>& floor_upper = world.contact(1);
  const ContactConstraint<T>& lower_upper = world.contact(2);
  EXPECT_EQ(lower_upper.body1(), 1u);
  EXPECT_EQ(lower_upper.body2(), 2u);
  EXPECT_EQ(floor_upper.PointCount(), 0);
  ASSERT_EQ(floor_lower.PointCount(), 2);
  ASSERT_EQ(lower_upper.PointCount(), 1);
  EXPECT_LE(Distance(lower_upper.Normal(), 0.0, 1.0, 0.0), 1e-5);
  EXPECT_LE(Distance(lower_upper.Point1(0), 0.0, 2.0 * lower_y, 0.0), 1e-4);
  const double upper_weight = upper_mass * kG * kDt;
  const double both_weights = (lower_mass + upper_mass) * kG * kDt;
  EXPECT_NEAR(double(lower_upper.NormalImpulse(0)), upper_weight, 1e-4 * upper_weight);
  EXPECT_NEAR(NormalImpulseSum(floor_lower), both_weights, 1e-3 * both_weights);
}

// SphereOnCapsuleStaysPut (5 s): a sphere on a capsule lying on the floor.
TYPED_TEST(ReferenceContactTest, SphereOnCapsuleManifolds) {
  ExpectStackManifolds<TypeParam>(SphereOnCapsuleScene(), kStackCapsuleY, 5.0);
}

// CrossedCapsulesStayPut (1 s): a capsule across another lying on the floor.
TYPED_TEST(ReferenceContactTest, CrossedCapsulesManifolds) {
  ExpectStackManifolds<TypeParam>(CrossedCapsulesScene(), kLowerCapsuleY, 1.0);
}

// GlancingSphereCapsuleConservesMomentum: when the sphere reaches the
// capsule, the one point lies on the capsule's cylinder (0.3 from its axis,
// the X axis) with n across the axis (n_x = 0, the point 0.3 along it from
// the middle, inside the segment), and the normal impulse pushes (Λ > 0).
TYPED_TEST(ReferenceContactTest, GlancingSphereCapsuleManifold) {
  using T = TypeParam;
  World<T> world(GlancingSphereCapsuleScene());
  int step = 0;
  while (world.contact(0).PointCount() == 0 && step < 60) {
    world.Step(ZeroGravity());
    ++step;
  }
  const ContactConstraint<T>& contact = world.contact(0);
  ASSERT_EQ(contact.PointCount(), 1);
  EXPECT_EQ(contact.MaxPointCount(), 1);
  EXPECT_NEAR(double(contact.Normal().x()), 0.0, 1e-6);
  const Vec3d p1 = contact.Point1(0).template cast<double>();
  EXPECT_NEAR(std::hypot(p1.y(), p1.z()), 0.3, 1e-6);
  EXPECT_NEAR(p1.x(), 0.3, 1e-6);
  EXPECT_GT(double(contact.Normal().y()), 0.0);
  EXPECT_GT(double(contact.Normal().z()), 0.0);
  EXPECT_GT(double(contact.NormalImpulse(0)), 0.0);
}

// Slots: spheres and capsules with each other and with the floor, in pair
// order, whatever the motion types as long as one body is dynamic.
TYPED_TEST(ReferenceContactTest, SpheresAndCapsulesMakeSlots) {
  using T = TypeParam;
  Scene scene;
  scene.AddBody(Floor());                                                  // 0
  scene.AddBody(Sphere(0.5f, {0.0f, 2.0f, 0.0f}));                         // 1
  scene.AddBody(Capsule(0.3f, 0.5f, {3.0f, 2.0f, 0.0f}));                  // 2
  BodySettings static_sphere = Sphere(0.5f, {6.0f, 2.0f, 0.0f});
  static_sphere.motion_type = MotionType::kStatic;
  scene.AddBody(static_sphere);                                            // 3
  BodySettings kinematic_capsule = Capsule(0.3f, 0.5f, {9.0f, 2.0f, 0.0f});
  kinematic_capsule.motion_type = MotionType::kKinematic;
  scene.AddBody(kinematic_capsule);                                        // 4
  World<T> world(scene);
  // Every pair but (0, 3), (0, 4), (3, 4): no dynamic body.
  const std::vector<std::pair<std::size_t, std::size_t>> expected = {
      {0, 1}, {0, 2}, {1, 2}, {1, 3}, {1, 4}, {2, 3}, {2, 4}};
  ASSERT_EQ(world.contact_count(), expected.size());
  for (std::size_t k = 0; k < expected.size(); ++k) {
    EXPECT_EQ(world.contact(k).body1(), expected[k].first) << k;
    EXPECT_EQ(world.contact(k).body2(), expected[k].second) << k;
  }
  EXPECT_EQ(world.contact(0).MaxPointCount(), 1);  // floor–sphere
  EXPECT_EQ(world.contact(1).MaxPointCount(), 2);  // floor–capsule
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

// A box with a sphere, capsule or box (either order) was refused by name
// before box pairs were built; now each such pair makes a slot: with the
// floor, 3 slots in pair order, the pair's last, body 1 the lower index,
// holding at most 1 point (sphere), 2 (capsule) or 4 (box) whichever body the
// box is. In groups that do not meet, only the floor's 2. Two planes: both
// bodies are static (a plane is on a static body only), so the pair makes no
// slot at all and is not refused.
TYPED_TEST(ReferenceContactTest, BoxPairsMakeSlots) {
  using T = TypeParam;
  const BodySettings sphere = Sphere(0.5f, {0.0f, 2.0f, 0.0f});
  const BodySettings capsule = Capsule(0.3f, 0.5f, {0.0f, 2.0f, 0.0f});
  const BodySettings box = Box({0.5f, 0.5f, 0.5f}, {3.0f, 2.0f, 0.0f});
  struct Case {
    const char* name;
    BodySettings left, right;
    int max_points;
  };
  for (const Case& c : {Case{"sphere-box", sphere, box, 1}, Case{"box-sphere", box, sphere, 1},
                        Case{"capsule-box", capsule, box, 2}, Case{"box-capsule", box, capsule, 2},
                        Case{"box-box", box, box, 4}}) {
    SCOPED_TRACE(c.name);
    Scene scene;
    scene.AddBody(Floor());
    BodySettings a = c.left, b = c.right;
    a.position = {0.0f, 2.0f, 0.0f};
    b.position = {3.0f, 2.0f, 0.0f};
    scene.AddBody(a);
    scene.AddBody(b);
    World<T> world(scene);
    ASSERT_EQ(world.contact_count(), 3u);
    const ContactConstraint<T>& pair = world.contact(2);
    EXPECT_EQ(pair.body1(), 1u);
    EXPECT_EQ(pair.body2(), 2u);
    EXPECT_EQ(pair.MaxPointCount(), c.max_points);
    world.Step(Settings());
    EXPECT_EQ(pair.PointCount(), 0);  // 3 m apart
    // In groups that do not meet, only the floor's slots.
    scene.bodies()[1].shape.collision_group = 2;
    scene.bodies()[1].shape.collision_mask = 1;
    scene.bodies()[2].shape.collision_group = 4;
    scene.bodies()[2].shape.collision_mask = 1;
    EXPECT_EQ(World<T>(scene).contact_count(), 2u);
  }
  Scene planes;
  planes.AddBody(Floor());
  BodySettings wall = Floor();
  wall.rotation = RotationAbout({0, 0, 1}, kPiD / 2.0);
  planes.AddBody(wall);
  EXPECT_EQ(World<T>(planes).contact_count(), 0u);
}

TYPED_TEST(ReferenceContactTest, RefusesBadContactSettings) {
  using T = TypeParam;
  Scene scene;
  scene.AddBody(Floor());
  scene.AddBody(Sphere(0.5f, {0.0f, 2.0f, 0.0f}));
  World<T> world(scene);
  StepSettings exact = Settings();
  exact.solver = JointSolver::kExact;
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
  EXPECT_EQ(world.body(1).position.y(), T(2));  // refused before anything moved
  // JointSolver::kExact is accepted with contacts (without joints the step
  // is Gauss-Seidel's; exact_solve_test checks the exact solve with joints
  // and contacts, the quadruped): the sphere falls onto the floor and rests,
  // landing deeper than the slop and pushed back to it (float rounding of a
  // 0.5 m coordinate aside).
  for (int i = 0; i < 120; ++i) world.Step(exact);
  EXPECT_NEAR(double(world.body(1).position.y()), 0.5, kSlop + 1e-6);
}

}  // namespace
}  // namespace manyworlds::reference
