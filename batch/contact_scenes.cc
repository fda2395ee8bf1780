// The contact scenes (docs/scenes.md, "Contact scenes"; docs/contacts.md):
// shapes on a ground plane, each there to check one thing a contact must do.

#include <array>
#include <cstdint>
#include <cmath>
#include <stdexcept>
#include <string>

#include "batch/scene_bodies.h"
#include "batch/scene_ids.h"
#include "manyworlds/scenes.h"

namespace manyworlds {
namespace {

using scene_bodies::Dynamic;

enum class ContactId { kBoxDrop, kSphereRoll, kPile, kBoxStack, kBoxPile, kHopper, kQuadruped };

struct ContactEntry {
  std::string_view id;
  ContactId scene;
  std::string_view description;
};
constexpr std::array<ContactEntry, 7> kContactScenes{{
    {"box-drop", ContactId::kBoxDrop,
     "a box dropped corner first on the ground: lands, settles, no jitter or drift"},
    {"sphere-roll", ContactId::kSphereRoll,
     "a sliding sphere on the ground: friction brings it to rolling at 5/7 of its speed"},
    {"pile", ContactId::kPile,
     "3 spheres and 3 capsules dropped on each other and the ground: shapes that touch"},
    {"box-stack", ContactId::kBoxStack,
     "5 boxes stacked a little askew on the ground: stands for 10 s, no creep"},
    {"box-pile", ContactId::kBoxPile,
     "2 boxes, 2 spheres and 2 capsules dropped on each other: boxes with every shape"},
    {"hopper", ContactId::kHopper,
     "MuJoCo's planar hopper: 4 capsules, 3 hinge position motors, feet on the ground"},
    {"quadruped", ContactId::kQuadruped,
     "after MuJoCo's ant: a ball torso on 4 two-hinge capsule legs, 8 position motors"},
}};

const ContactEntry* FindContact(std::string_view id) {
  for (const ContactEntry& entry : kContactScenes) {
    if (entry.id == id) return &entry;
  }
  return nullptr;
}

// The ground: a static plane through the origin, normal +Y, friction 1 (so a
// contact's friction sqrt(1 mu) is set by the other shape alone).
BodySettings Ground() {
  BodySettings ground = scene_bodies::StaticWorld();
  ground.name = "ground";
  ground.shape.type = ShapeType::kPlane;
  ground.shape.friction = 1.0f;
  return ground;
}

Scene BoxDrop() {
  Scene scene;
  scene.AddBody(Ground());
  // 1 kg, half extents 0.5 m: I = m (2h)^2 / 6 about every axis. Turned
  // 0.3 rad about (1, 0, 1)/sqrt(2), so it lands on a corner, then an edge.
  const double half_angle = 0.15, s = std::sin(half_angle) / std::sqrt(2.0);
  BodySettings box = Dynamic("box", 1.0f, {1.0f / 6, 1.0f / 6, 1.0f / 6}, {0.0f, 2.0f, 0.0f},
                             {float(s), 0.0f, float(s), float(std::cos(half_angle))});
  box.shape.type = ShapeType::kBox;
  box.shape.half_extents = {0.5f, 0.5f, 0.5f};
  box.shape.friction = 0.25f;  // mu = 0.5 with the ground
  scene.AddBody(box);
  return scene;
}

Scene SphereRoll() {
  Scene scene;
  scene.AddBody(Ground());
  // A solid sphere, 1 kg, radius 0.5 m (I = 2/5 m r^2), touching the ground,
  // sliding at 5 m/s along X without spin: it rolls after
  // t = (2/7) v0 / (mu g) = 0.73 s, at 5/7 v0.
  BodySettings sphere = Dynamic("sphere", 1.0f, {0.1f, 0.1f, 0.1f}, {0.0f, 0.5f, 0.0f});
  sphere.linear_velocity = {5.0f, 0.0f, 0.0f};
  sphere.shape.type = ShapeType::kSphere;
  sphere.shape.radius = 0.5f;
  sphere.shape.friction = 0.04f;  // mu = 0.2 with the ground
  scene.AddBody(sphere);
  return scene;
}

// A turn by `angle` about the axis in the XZ plane at `heading` from X.
Quaternion TiltInXZ(double angle, double heading) {
  const double s = std::sin(angle / 2);
  return {float(std::cos(heading) * s), 0.0f, float(std::sin(heading) * s),
          float(std::cos(angle / 2))};
}

// Spheres (r 0.3 m) and capsules (r 0.2 m, 0.8 m long) of 1 kg and
// assorted tilts, dropped from 1-3 m so that they land on each other, roll
// and come to rest on the ground in a heap.
Scene Pile() {
  Scene scene;
  scene.AddBody(Ground());
  for (int i = 0; i < 6; ++i) {
    const float x = 0.25f * float(i % 3) - 0.25f, z = 0.2f * float(i % 2) - 0.1f;
    const float y = 1.0f + 0.45f * float(i);
    // About an axis in the XZ plane, a different tilt for each body.
    const Quaternion tilt = TiltInXZ(0.5 + 0.4 * i, 1.3 * i);
    BodySettings body;
    if (i % 2 == 0) {
      body = Dynamic("sphere" + std::to_string(i / 2), 1.0f, {0.036f, 0.036f, 0.036f},
                     {x, y, z}, tilt);
      body.shape.type = ShapeType::kSphere;
      body.shape.radius = 0.3f;
    } else {
      // I of a 0.8 m rod of 1 kg across, of a 0.2 m cylinder along.
      body = Dynamic("capsule" + std::to_string(i / 2), 1.0f, {0.063f, 0.02f, 0.063f},
                     {x, y, z}, tilt);
      body.shape.type = ShapeType::kCapsule;
      body.shape.radius = 0.2f;
      body.shape.half_height = 0.2f;
    }
    body.shape.friction = 0.5f;
    body.shape.restitution = 0.3f;
    scene.AddBody(body);
  }
  return scene;
}

// Five boxes (half extents 0.4 x 0.25 x 0.3 m, 24 kg: 200 kg/m^3) stacked
// 1 mm apart, each shifted 1-2 cm and turned a little about Y (0.1 rad per
// level, so each pair's faces overlap in an octagon whose 8 points are
// pruned to 4), friction 0.5.
Scene BoxStack() {
  Scene scene;
  scene.AddBody(Ground());
  const Float3 half{0.4f, 0.25f, 0.3f};
  const float mass = 24.0f;
  // I of a cuboid: m (b^2 + c^2) / 3 with half extents a, b, c.
  const Float3 inertia{mass * (half[1] * half[1] + half[2] * half[2]) / 3.0f,
                       mass * (half[0] * half[0] + half[2] * half[2]) / 3.0f,
                       mass * (half[0] * half[0] + half[1] * half[1]) / 3.0f};
  for (int i = 0; i < 5; ++i) {
    const double yaw = 0.1 * i;
    const Quaternion turn{0.0f, float(std::sin(yaw / 2)), 0.0f, float(std::cos(yaw / 2))};
    const Float3 position{0.015f * float(i % 2), half[1] + float(i) * (2.0f * half[1] + 0.001f),
                          -0.01f * float(i % 3)};
    BodySettings box = Dynamic("box" + std::to_string(i), mass, inertia, position, turn);
    box.shape.type = ShapeType::kBox;
    box.shape.half_extents = half;
    box.shape.friction = 0.5f;
    scene.AddBody(box);
  }
  return scene;
}

// Two boxes, two spheres and two capsules of 1-4 kg with assorted tilts,
// dropped from 0.5-2.5 m onto each other: every pair of shape types meets.
Scene BoxPile() {
  Scene scene;
  scene.AddBody(Ground());
  for (int i = 0; i < 6; ++i) {
    const float x = 0.2f * float(i % 3) - 0.2f, z = 0.15f * float(i % 2) - 0.07f;
    const float y = 0.5f + 0.4f * float(i);
    const Quaternion tilt = TiltInXZ(0.4 + 0.5 * i, 1.1 * i);
    BodySettings body;
    const std::string n = std::to_string(i / 3);
    switch (i % 3) {
      case 0:  // a 0.5 x 0.3 x 0.4 m box of 4 kg
        body = Dynamic("box" + n, 4.0f, {0.083f, 0.137f, 0.113f}, {x, y, z}, tilt);
        body.shape.type = ShapeType::kBox;
        body.shape.half_extents = {0.25f, 0.15f, 0.2f};
        break;
      case 1:  // a sphere of radius 0.2 m, 1 kg
        body = Dynamic("sphere" + n, 1.0f, {0.016f, 0.016f, 0.016f}, {x, y, z}, tilt);
        body.shape.type = ShapeType::kSphere;
        body.shape.radius = 0.2f;
        break;
      default:  // a capsule of radius 0.15 m, 0.7 m long, 2 kg
        body = Dynamic("capsule" + n, 2.0f, {0.07f, 0.0225f, 0.07f}, {x, y, z}, tilt);
        body.shape.type = ShapeType::kCapsule;
        body.shape.radius = 0.15f;
        body.shape.half_height = 0.2f;
        break;
    }
    body.shape.friction = 0.5f;
    body.shape.restitution = 0.2f;
    scene.AddBody(body);
  }
  return scene;
}

// MuJoCo's default geom density (kg/m^3), which its hopper and ant use.
constexpr double kDensity = 1000.0;
// The walkers' shapes touch the ground (group 1) but not each other.
constexpr std::uint32_t kLimbGroup = 2;

using Vector = std::array<double, 3>;

double Length(const Vector& v) { return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); }

// The rotation taking +Y to the unit vector d (shortest arc), as (x, y, z, w).
Quaternion YTo(const Vector& d) {
  // q = (Y x d, 1 + Y.d) normalised; d = -Y turns about X.
  const double w = 1.0 + d[1];
  if (w < 1e-9) return {1.0f, 0.0f, 0.0f, 0.0f};
  const double x = d[2], z = -d[0];  // Y x d = (d_z, 0, -d_x)
  const double n = std::sqrt(x * x + z * z + w * w);
  return {float(x / n), 0.0f, float(z / n), float(w / n)};
}

// A solid capsule of density kDensity from `from` to `to` (its core
// segment), a body whose centre of mass is the segment's middle; the shape's
// Y axis and the inertia's principal axis lie along the segment. Cylinder of
// length L and two half balls: I_axis = m_c r^2/2 + m_s 2r^2/5, I_across =
// m_c (L^2/12 + r^2/4) + m_s (2r^2/5 + L^2/4 + 3Lr/8).
BodySettings Capsule(std::string name, const Vector& from, const Vector& to, double radius) {
  const Vector d{to[0] - from[0], to[1] - from[1], to[2] - from[2]};
  const double length = Length(d);
  const double pi = std::acos(-1.0);
  const double cylinder = kDensity * pi * radius * radius * length;
  const double ball = kDensity * 4.0 / 3.0 * pi * radius * radius * radius;
  const double along = cylinder * radius * radius / 2 + ball * 2 * radius * radius / 5;
  const double across = cylinder * (length * length / 12 + radius * radius / 4) +
                        ball * (2 * radius * radius / 5 + length * length / 4 +
                                3 * length * radius / 8);
  const Quaternion axis = YTo({d[0] / length, d[1] / length, d[2] / length});
  BodySettings body = Dynamic(std::move(name), float(cylinder + ball),
                              {float(across), float(along), float(across)},
                              {float((from[0] + to[0]) / 2), float((from[1] + to[1]) / 2),
                               float((from[2] + to[2]) / 2)});
  body.inertia_rotation = axis;
  body.shape.type = ShapeType::kCapsule;
  body.shape.radius = float(radius);
  body.shape.half_height = float(length / 2);
  body.shape.rotation = axis;
  body.shape.friction = 1.0f;  // mu = 1 with the ground: MuJoCo's walkers use 0.9-1
  body.shape.collision_group = kLimbGroup;
  body.shape.collision_mask = 1;
  return body;
}

// A hinge between two bodies at `point` about `axis` (world space, the
// scene's initial pose), limited to [min, max] rad, with a position motor
// (critically damped 8 Hz spring) of at most `max_torque` N m: the walkers'
// actuators, driven by position targets.
HingeConstraintSettings MotorHinge(std::string name, std::size_t body1, std::size_t body2,
                                   const Vector& point, const Vector& axis, double min,
                                   double max, float max_torque) {
  HingeConstraintSettings hinge;
  hinge.name = std::move(name);
  hinge.body1 = body1;
  hinge.body2 = body2;
  hinge.point1 = hinge.point2 = {float(point[0]), float(point[1]), float(point[2])};
  const double n = Length(axis);
  hinge.hinge_axis1 = hinge.hinge_axis2 = {float(axis[0] / n), float(axis[1] / n),
                                           float(axis[2] / n)};
  // A normal: any unit vector across the axis.
  const Vector across = std::abs(axis[1]) < 0.9 * n ? Vector{-axis[2], 0, axis[0]}
                                                    : Vector{axis[1], -axis[0], 0};
  const double m = Length(across);
  hinge.normal_axis1 = hinge.normal_axis2 = {float(across[0] / m), float(across[1] / m),
                                             float(across[2] / m)};
  hinge.limits_min = float(min);
  hinge.limits_max = float(max);
  hinge.motor_state = MotorState::kPosition;
  hinge.motor.spring.frequency_or_stiffness = 8.0f;
  hinge.motor.spring.damping = 1.0f;
  hinge.motor.min_force_limit = -max_torque;
  hinge.motor.max_force_limit = max_torque;
  return hinge;
}

// MuJoCo's hopper.xml (Gymnasium's Hopper), Y up instead of Z up (MuJoCo's
// (x, y, z) is our (x, -z, y)), moving in the XY plane: the torso may only
// move along X and Y and turn about Z (MuJoCo's rootx, rootz and rooty
// joints). Capsules: torso 1.45 -> 1.05 m (r 0.05), thigh 1.05 -> 0.6
// (0.05), leg 0.6 -> 0.1 (0.04), foot from x -0.13 to 0.26 at 0.1 (0.06).
// Hinges about Z at the joints, limits thigh and leg [-150, 0] deg, foot
// [-45, 45] deg; MuJoCo's gear-200 torque motors become position motors of
// at most 200 N m. Differences from MuJoCo: no joint damping or armature,
// Jolt's hard contacts instead of soft ones, no self-collision.
Scene Hopper() {
  const double deg = std::acos(-1.0) / 180.0;
  Scene scene;
  scene.AddBody(Ground());
  BodySettings torso = Capsule("torso", {0, 1.45, 0}, {0, 1.05, 0}, 0.05);
  torso.allowed_dofs = AllowedDofs::kPlane2D;
  const std::size_t t = scene.AddBody(torso);
  const std::size_t thigh = scene.AddBody(Capsule("thigh", {0, 1.05, 0}, {0, 0.6, 0}, 0.05));
  const std::size_t leg = scene.AddBody(Capsule("leg", {0, 0.6, 0}, {0, 0.1, 0}, 0.04));
  const std::size_t foot = scene.AddBody(Capsule("foot", {-0.13, 0.1, 0}, {0.26, 0.1, 0}, 0.06));
  const Vector z{0, 0, 1};
  scene.AddConstraint(MotorHinge("thigh joint", t, thigh, {0, 1.05, 0}, z, -150 * deg, 0, 200));
  scene.AddConstraint(MotorHinge("leg joint", thigh, leg, {0, 0.6, 0}, z, -150 * deg, 0, 200));
  scene.AddConstraint(MotorHinge("foot joint", leg, foot, {0, 0.1, 0}, z, -45 * deg, 45 * deg, 200));
  return scene;
}

// After MuJoCo's ant.xml (Gymnasium's Ant), Y up: a ball torso (r 0.25,
// centre 0.75 m up) and four legs along the ground's diagonals, each a thigh
// capsule (0.28 -> 0.57 m out, r 0.08) on a hip hinge about the vertical
// ([-30, 30] deg) and a shin capsule from the knee 0.4 m further out and
// 0.4 m down (r 0.08) on a knee hinge across the leg ([-40, 40] deg about
// that bent rest pose). The ant's hip capsules (fixed to its torso) are
// folded into the thighs. MuJoCo's gear-150 torque motors become position
// motors of at most 150 N m. Differences from MuJoCo as for the hopper.
Scene Quadruped() {
  const double deg = std::acos(-1.0) / 180.0;
  const double pi = std::acos(-1.0);
  Scene scene;
  scene.AddBody(Ground());
  const double height = 0.75;
  const double r = 0.25;
  const double ball = kDensity * 4.0 / 3.0 * pi * r * r * r;
  BodySettings torso = Dynamic("torso", float(ball),
                               {float(0.4 * ball * r * r), float(0.4 * ball * r * r),
                                float(0.4 * ball * r * r)},
                               {0.0f, float(height), 0.0f});
  torso.shape.type = ShapeType::kSphere;
  torso.shape.radius = float(r);
  torso.shape.friction = 1.0f;
  torso.shape.collision_group = kLimbGroup;
  torso.shape.collision_mask = 1;
  const std::size_t t = scene.AddBody(torso);
  // Legs along the diagonals (x, z) = (+-1, +-1)/sqrt(2) of the ground plane
  // (MuJoCo's (x, y)), front legs at +x.
  const std::array<std::array<double, 2>, 4> directions{{{1, 1}, {-1, 1}, {-1, -1}, {1, -1}}};
  const std::array<const char*, 4> names{{"front left", "back left", "back right", "front right"}};
  for (std::size_t i = 0; i < 4; ++i) {
    const double dx = directions[i][0] / std::sqrt(2.0), dz = directions[i][1] / std::sqrt(2.0);
    const auto out = [&](double distance) {
      return Vector{distance * dx, height, distance * dz};
    };
    const std::string name = names[i];
    const std::size_t thigh = scene.AddBody(Capsule(name + " thigh", out(0.28), out(0.57), 0.08));
    // The shin runs out and down, as the ant's ankle at rest: 0.4 m out
    // from the knee and 0.4 m down (MuJoCo's shin points along the diagonal
    // with the knee bent by its limit).
    const Vector knee = out(0.57);
    const Vector foot{knee[0] + 0.4 * dx, knee[1] - 0.4, knee[2] + 0.4 * dz};
    const std::size_t shin = scene.AddBody(Capsule(name + " shin", knee, foot, 0.08));
    scene.AddConstraint(
        MotorHinge(name + " hip", t, thigh, out(0.28), {0, 1, 0}, -30 * deg, 30 * deg, 150));
    scene.AddConstraint(
        MotorHinge(name + " knee", thigh, shin, knee, {-dz, 0, dx}, -40 * deg, 40 * deg, 150));
  }
  return scene;
}

}  // namespace

std::vector<std::string> ContactSceneIds() {
  std::vector<std::string> ids;
  for (const ContactEntry& entry : kContactScenes) ids.emplace_back(entry.id);
  return ids;
}

Scene MakeContactScene(std::string_view id) {
  const ContactEntry* entry = FindContact(id);
  if (entry == nullptr) {
    std::string valid;
    for (const ContactEntry& contact : kContactScenes) {
      valid += (valid.empty() ? "" : ", ") + std::string(contact.id);
    }
    throw std::invalid_argument("unknown contact scene '" + std::string(id) +
                                "'; valid ids: " + valid);
  }
  switch (entry->scene) {
    case ContactId::kBoxDrop: return BoxDrop();
    case ContactId::kSphereRoll: return SphereRoll();
    case ContactId::kPile: return Pile();
    case ContactId::kBoxStack: return BoxStack();
    case ContactId::kBoxPile: return BoxPile();
    case ContactId::kHopper: return Hopper();
    case ContactId::kQuadruped: return Quadruped();
  }
  throw std::logic_error("MakeContactScene: unhandled scene id");
}

std::string_view scene_ids::ContactSceneDescription(std::string_view id) {
  const ContactEntry* entry = FindContact(id);
  return entry == nullptr ? std::string_view() : entry->description;
}

}  // namespace manyworlds
