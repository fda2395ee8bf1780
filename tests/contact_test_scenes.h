// Scenes and settings of the contact tests, shared by the tests of a contact's
// physics on every stepper (tests/contact_behaviour_test.cc: body states only)
// and the tests of the reference's manifolds (tests/reference_contact_test.cc:
// points, impulses, slots), which run the same scenes.
//
// Shared setup as Jolt's PhysicsTestContext: the floor is a static body with
// a plane shape at y = 0 (body 0, so it is body 1 of its slots and n = +Y),
// zero damping, dt = 1/60, g = −9.81 m/s², density 1000 kg/m³.
#pragma once

#include <cmath>
#include <cstddef>

#include "manyworlds/batch.h"
#include "manyworlds/scene.h"
#include "reference/math.h"

namespace manyworlds::contact_test {

inline constexpr double kDensity = 1000.0;  // kg/m³, Jolt's default
inline constexpr double kG = 9.81;          // m/s²
inline constexpr double kDt = 1.0 / 60.0;   // s
inline constexpr double kPiD = 3.14159265358979323846;
inline constexpr double kSlop = 0.02;         // StepSettings::penetration_slop default
inline constexpr double kSpeculative = 0.02;  // StepSettings::speculative_contact_distance default

// ---------------------------------------------------------------- bodies

inline BodySettings Floor(float friction = 0.2f, float restitution = 0.0f) {
  BodySettings body;
  body.name = "floor";
  body.motion_type = MotionType::kStatic;
  body.shape.type = ShapeType::kPlane;
  body.shape.friction = friction;
  body.shape.restitution = restitution;
  return body;
}

inline BodySettings Dynamic(Float3 position, double mass, Float3 inertia) {
  BodySettings body;
  body.mass = float(mass);
  body.inertia_diagonal = inertia;
  body.position = position;
  body.linear_damping = 0.0f;
  body.angular_damping = 0.0f;
  return body;
}

// Solid sphere: m = ρ 4/3 π r³, I = 2/5 m r².
inline BodySettings Sphere(float radius, Float3 position) {
  const double r = radius;
  const double mass = kDensity * 4.0 / 3.0 * kPiD * r * r * r;
  const float inertia = float(0.4 * mass * r * r);
  BodySettings body = Dynamic(position, mass, {inertia, inertia, inertia});
  body.name = "sphere";
  body.shape.type = ShapeType::kSphere;
  body.shape.radius = radius;
  return body;
}

// Solid box: m = ρ 8 hx hy hz, I_x = m/3 (hy² + hz²), ...
inline BodySettings Box(Float3 half, Float3 position) {
  const double hx = half[0], hy = half[1], hz = half[2];
  const double mass = kDensity * 8.0 * hx * hy * hz;
  BodySettings body = Dynamic(position, mass,
                              {float(mass / 3.0 * (hy * hy + hz * hz)),
                               float(mass / 3.0 * (hx * hx + hz * hz)),
                               float(mass / 3.0 * (hx * hx + hy * hy))});
  body.name = "box";
  body.shape.type = ShapeType::kBox;
  body.shape.half_extents = half;
  return body;
}

// Capsule along the body's Y axis. Mass and inertia as a solid cylinder of the
// same radius and length 2(h + r): these tests do not depend on them.
inline BodySettings Capsule(float radius, float half_height, Float3 position) {
  const double r = radius, length = 2.0 * (half_height + radius);
  const double mass = kDensity * kPiD * r * r * length;
  const float across = float(mass * (3.0 * r * r + length * length) / 12.0);
  BodySettings body = Dynamic(position, mass, {across, float(0.5 * mass * r * r), across});
  body.name = "capsule";
  body.shape.type = ShapeType::kCapsule;
  body.shape.radius = radius;
  body.shape.half_height = half_height;
  return body;
}

// Rotations by ±120° about (1, 1, 1)/√3, which permute the axes: exact in
// float (components ±0.5), so a capsule turned by one has its axis exactly
// along a world axis (RotationAbout(..., π/2) is off by a float rounding).
inline constexpr Quaternion kYToX{-0.5f, -0.5f, -0.5f, 0.5f};  // body Y along world +X
inline constexpr Quaternion kYToZ{0.5f, 0.5f, 0.5f, 0.5f};     // body Y along world +Z

inline Quaternion RotationAbout(Float3 axis, double angle) {
  const double s = std::sin(angle / 2.0);
  return {float(axis[0] * s), float(axis[1] * s), float(axis[2] * s), float(std::cos(angle / 2.0))};
}

// ---------------------------------------------------------------- stepping

inline StepSettings Settings(double delta_time = kDt, int substeps = 1) {
  StepSettings settings;
  settings.delta_time = float(delta_time);
  settings.substeps = substeps;
  return settings;
}

inline StepSettings ZeroGravity() {
  StepSettings settings = Settings();
  settings.gravity = {0.0f, 0.0f, 0.0f};
  return settings;
}

// One step of one substep (Jolt's SimulateSingleStep).
inline StepSettings SingleStep(const StepSettings& settings) {
  StepSettings single = settings;
  single.delta_time = settings.delta_time / float(settings.substeps);
  single.substeps = 1;
  return single;
}

// Steps `seconds` of `settings`; World is a reference::World<T> or a
// stepper_test::Stepper.
template <class World>
void Simulate(World& world, const StepSettings& settings, double seconds) {
  const int steps = int(std::lround(seconds / double(settings.delta_time)));
  for (int i = 0; i < steps; ++i) world.Step(settings);
}

// Jolt's PredictPosition: symplectic Euler with the substep, in double.
inline double PredictFall(double acceleration, double substep, double seconds) {
  const int steps = int(std::lround(seconds / substep));
  double position = 0.0, velocity = 0.0;
  for (int i = 0; i < steps; ++i) {
    velocity += acceleration * substep;
    position += velocity * substep;
  }
  return position;
}

template <class T>
double Distance(const reference::Vec3<T>& a, double x, double y, double z) {
  return std::sqrt((double(a.x()) - x) * (double(a.x()) - x) +
                   (double(a.y()) - y) * (double(a.y()) - y) +
                   (double(a.z()) - z) * (double(a.z()) - z));
}

// ---------------------------------------------------------------- scenes

// Jolt's CollisionElastic: a unit sphere, e = 1, dropped so it reaches
// y = 1 − 1e-4 after 1 s of `settings` (body 1).
struct ElasticDrop {
  StepSettings settings;
  double g;        // m/s², the settings' (float) gravity
  double substep;  // s, the settings' (float) substep
  Scene scene;
  double mass;  // kg, the sphere's
};

inline ElasticDrop MakeElasticDrop(double delta_time, int substeps) {
  ElasticDrop drop;
  drop.settings = Settings(delta_time, substeps);
  // The world's g and substep are the float settings'; predicted with those.
  drop.g = -double(drop.settings.gravity[1]);
  drop.substep = double(drop.settings.delta_time) / substeps;
  const double start_y = 1.0 - 1e-4 - PredictFall(-drop.g, drop.substep, 1.0);
  drop.scene.AddBody(Floor());
  BodySettings sphere = Sphere(1.0f, {0.0f, float(start_y), 0.0f});
  sphere.shape.restitution = 1.0f;
  drop.mass = sphere.mass;
  drop.scene.AddBody(sphere);
  return drop;
}

// Jolt's CollisionInelastic: a unit sphere, e = 0, dropped so it reaches
// y = kInelasticHitY after 1 s of steps of delta_time / substeps (body 1).
inline constexpr double kInelasticHitY = 1.0 - 1e-4;
inline Scene InelasticDropScene(double delta_time, int substeps) {
  const double substep = delta_time / substeps;
  const double start_y = kInelasticHitY - PredictFall(-kG, substep, 1.0);
  Scene scene;
  scene.AddBody(Floor());
  scene.AddBody(Sphere(1.0f, {0.0f, float(start_y), 0.0f}));
  return scene;
}

// Jolt's PenetrationSlop: a box of half extent 1 placed `depth` into the floor.
inline Scene SunkBoxScene(double depth) {
  Scene scene;
  scene.AddBody(Floor());
  scene.AddBody(Box({1.0f, 1.0f, 1.0f}, {0.0f, float(1.0 - depth), 0.0f}));
  return scene;
}

// A box (half 1) and a sphere (r 1) side by side, `gap` above the floor, both
// moving at `velocity` (m/s, +Y up). Their groups do not meet each other,
// only the floor, so each test's slots are the two with the floor.
inline Scene BoxAndSphere(double gap, double velocity, float restitution = 0.0f) {
  Scene scene;
  scene.AddBody(Floor(0.2f, restitution));
  BodySettings box = Box({1.0f, 1.0f, 1.0f}, {0.0f, float(1.0 + gap), 0.0f});
  BodySettings sphere = Sphere(1.0f, {3.0f, float(1.0 + gap), 0.0f});
  for (BodySettings* body : {&box, &sphere}) {
    body->linear_velocity = {0.0f, float(velocity), 0.0f};
    body->shape.restitution = restitution;
    body->shape.collision_mask = 1;  // the floor's group only
  }
  box.shape.collision_group = 2;
  sphere.shape.collision_group = 4;
  scene.AddBody(box);
  scene.AddBody(sphere);
  return scene;
}

// Jolt's ActivationDeactivation: a box of half 0.5 dropped from y = 5.
inline Scene DroppedBoxScene() {
  Scene scene;
  scene.AddBody(Floor());
  scene.AddBody(Box({0.5f, 0.5f, 0.5f}, {0.0f, 5.0f, 0.0f}));
  return scene;
}

// Jolt's AngularFriction: a box of half 1, 1 mm into the floor, spinning at
// 10 rad/s about Y, μ = sqrt(0.2·0.3).
inline Scene SpinningBoxScene() {
  Scene scene;
  scene.AddBody(Floor(0.2f));
  BodySettings box = Box({1.0f, 1.0f, 1.0f}, {0.0f, 0.999f, 0.0f});
  box.angular_velocity = {0.0f, 10.0f, 0.0f};
  box.shape.friction = 0.3f;
  scene.AddBody(box);
  return scene;
}

// A box of half 0.5 on a plane tilted by θ about Z, 1 mm in (within the slop),
// turned with the plane, μ the same on both shapes.
inline Scene InclineScene(double theta, float mu) {
  const double n_x = -std::sin(theta), n_y = std::cos(theta);  // plane normal
  Scene scene;
  BodySettings floor = Floor(mu);
  floor.rotation = RotationAbout({0, 0, 1}, theta);
  scene.AddBody(floor);
  BodySettings box = Box({0.5f, 0.5f, 0.5f}, {float(0.499 * n_x), float(0.499 * n_y), 0.0f});
  box.rotation = floor.rotation;
  box.shape.friction = mu;
  scene.AddBody(box);
  return scene;
}

inline StepSettings InclineSettings(int iterations, bool warm_start) {
  StepSettings settings = Settings();
  settings.velocity_iterations = iterations;
  settings.warm_start = warm_start;
  return settings;
}

// A solid sphere (r 0.5) on the floor sliding at 5 m/s along X without spin,
// μ = 0.5.
inline constexpr double kRollingRadius = 0.5, kRollingSpeed = 5.0, kRollingFriction = 0.5;
inline Scene RollingSphereScene() {
  Scene scene;
  scene.AddBody(Floor(float(kRollingFriction)));
  BodySettings sphere = Sphere(float(kRollingRadius), {0.0f, float(kRollingRadius), 0.0f});
  sphere.linear_velocity = {float(kRollingSpeed), 0.0f, 0.0f};
  sphere.shape.friction = float(kRollingFriction);
  scene.AddBody(sphere);
  return scene;
}

// A capsule (r 0.3, h 0.5) lying along X on the floor.
inline Scene LyingCapsuleScene() {
  Scene scene;
  scene.AddBody(Floor());
  BodySettings capsule = Capsule(0.3f, 0.5f, {0.0f, 0.3f, 0.0f});
  capsule.rotation = RotationAbout({0, 0, 1}, kPiD / 2.0);  // body Y (capsule axis) along X
  scene.AddBody(capsule);
  return scene;
}

// A box (half 0.5, 0.3, 0.4) resting on the floor.
inline Scene RestingBoxScene() {
  Scene scene;
  scene.AddBody(Floor());
  scene.AddBody(Box({0.5f, 0.3f, 0.4f}, {0.0f, 0.3f, 0.0f}));
  return scene;
}

// A box (half 0.5) turned 30° about Z, its lowest edge 1 mm above the floor.
inline constexpr double kEdgeTilt = 30.0 * kPiD / 180.0;
inline Scene BoxOnEdgeScene() {
  const double lowest = 0.5 * (std::cos(kEdgeTilt) + std::sin(kEdgeTilt));
  Scene scene;
  scene.AddBody(Floor());
  BodySettings box = Box({0.5f, 0.5f, 0.5f}, {0.0f, float(lowest + 0.001), 0.0f});
  box.rotation = RotationAbout({0, 0, 1}, kEdgeTilt);
  scene.AddBody(box);
  return scene;
}

// A unit sphere resting at y = 1 on a floor of a higher index (body 0, the
// floor body 1).
inline Scene SphereOnLaterFloorScene() {
  Scene scene;
  scene.AddBody(Sphere(1.0f, {0.0f, 1.0f, 0.0f}));
  scene.AddBody(Floor());
  return scene;
}

// ------------------------------------------- spheres and capsules together

// Jolt's CollisionElasticDynamic, zero gravity: two unit spheres on the X axis
// moving towards each other at 5 m/s (body 0, x < 0) and −10 m/s (body 1), both
// with restitution e. Their surfaces start kHeadOnGap apart: at 15 m/s the gap
// is 0.01 m (inside the speculative distance) at the start of substep 8 (from
// 0; 1/60 s each) and 0.26 m at the start of substep 7, so they meet in
// substep 8.
inline constexpr double kHeadOnGap = 2.01, kHeadOnV1 = 5.0, kHeadOnV2 = -10.0;
inline constexpr int kHeadOnHitSubstep = 8;
inline Scene HeadOnSpheresScene(float restitution) {
  Scene scene;
  const float x = float(1.0 + kHeadOnGap / 2.0);
  BodySettings left = Sphere(1.0f, {-x, 0.0f, 0.0f});
  BodySettings right = Sphere(1.0f, {x, 0.0f, 0.0f});
  left.linear_velocity = {float(kHeadOnV1), 0.0f, 0.0f};
  right.linear_velocity = {float(kHeadOnV2), 0.0f, 0.0f};
  left.shape.restitution = right.shape.restitution = restitution;
  scene.AddBody(left);
  scene.AddBody(right);
  return scene;
}

// Jolt's MinVelocityForRestitution with two spheres: unit spheres touching at
// the origin (centres x = ∓1), e = 1, body 0 moving at `speed` along +X into
// body 1 at rest; zero gravity.
inline Scene TouchingSpheresScene(double speed) {
  Scene scene;
  BodySettings moving = Sphere(1.0f, {-1.0f, 0.0f, 0.0f});
  BodySettings resting = Sphere(1.0f, {1.0f, 0.0f, 0.0f});
  moving.linear_velocity = {float(speed), 0.0f, 0.0f};
  moving.shape.restitution = resting.shape.restitution = 1.0f;
  scene.AddBody(moving);
  scene.AddBody(resting);
  return scene;
}

// A 3-body stack: the floor (0), a capsule (r 0.3, h 0.5) lying along X on it
// (1, centre y = 0.3), a sphere (r 0.25) on top exactly above the capsule's
// middle (2, centre y = 0.3 + 0.3 + 0.25 = 0.85).
inline constexpr double kStackCapsuleY = 0.3, kStackSphereY = 0.85;
inline Scene SphereOnCapsuleScene() {
  Scene scene;
  scene.AddBody(Floor());
  BodySettings capsule = Capsule(0.3f, 0.5f, {0.0f, float(kStackCapsuleY), 0.0f});
  capsule.rotation = kYToX;
  scene.AddBody(capsule);
  scene.AddBody(Sphere(0.25f, {0.0f, float(kStackSphereY), 0.0f}));
  return scene;
}

// Two capsules (r 0.3, h 0.5) crossing at right angles: one lying along X on
// the floor (1, centre y = 0.3), the other along Z resting across its middle
// (2, centre y = 0.9).
inline constexpr double kLowerCapsuleY = 0.3, kUpperCapsuleY = 0.9;
inline Scene CrossedCapsulesScene() {
  Scene scene;
  scene.AddBody(Floor());
  BodySettings lower = Capsule(0.3f, 0.5f, {0.0f, float(kLowerCapsuleY), 0.0f});
  lower.rotation = kYToX;
  scene.AddBody(lower);
  BodySettings upper = Capsule(0.3f, 0.5f, {0.0f, float(kUpperCapsuleY), 0.0f});
  upper.rotation = kYToZ;
  scene.AddBody(upper);
  return scene;
}

// Zero gravity, no friction (μ = 0 on both), e = 0.5: a capsule (r 0.3, h 0.5)
// at rest along X at the origin (0) and a sphere (r 0.25) flying at 6 m/s
// along −Z (1), 0.35 m above the capsule's axis and 0.3 m along it from the
// middle: it strikes the cylinder 0.55 m from the axis at an angle (the normal
// (0, 0.35, 0.42)/0.55 at the hit), spinning the capsule up.
inline Scene GlancingSphereCapsuleScene() {
  Scene scene;
  BodySettings capsule = Capsule(0.3f, 0.5f, {0.0f, 0.0f, 0.0f});
  capsule.rotation = kYToX;
  BodySettings sphere = Sphere(0.25f, {0.3f, 0.35f, 1.5f});
  sphere.linear_velocity = {0.0f, 0.0f, -6.0f};
  for (BodySettings* body : {&capsule, &sphere}) {
    body->shape.friction = 0.0f;
    body->shape.restitution = 0.5f;
  }
  scene.AddBody(capsule);
  scene.AddBody(sphere);
  return scene;
}

}  // namespace manyworlds::contact_test
