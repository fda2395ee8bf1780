// The exact joint solve's own test scenes (tests/exact_solve_test.cc): a
// floating star, a closed ring, links carried by a kinematic body, every row
// group kind (gears, a rack and pinion, six-DOF shortcuts, rods), bounded
// rows around the solve, and a body with restricted DOFs; ExactScene finds
// them, and the reference, stress and mixed scenes, by id.
#pragma once

#include <cstddef>
#include <string>
#include <utility>

#include "batch/scene_bodies.h"
#include "manyworlds/scene.h"
#include "manyworlds/scenes.h"
#include "tests/mixed_scenes.h"

namespace manyworlds::exact_scenes {

using scene_bodies::Dynamic;
using scene_bodies::StaticWorld;

inline PointConstraintSettings Ball(std::string name, std::size_t body1, std::size_t body2,
                             Float3 point) {
  PointConstraintSettings ball;
  ball.name = std::move(name);
  ball.body1 = body1;
  ball.body2 = body2;
  ball.point1 = ball.point2 = point;
  return ball;
}

// A floating star: a hub with three arms and no static body. The hub's three
// joints couple pairwise (a clique), which eliminates without fill.
inline Scene Star() {
  Scene scene;
  // Weightless, so that it stays near the origin where float measures the
  // joints' gaps to 1e-6 m.
  BodySettings hub = Dynamic("hub", 3.0f, {0.05f, 0.04f, 0.06f}, {0, 0, 0});
  hub.gravity_factor = 0.0f;
  scene.AddBody(hub);
  const Float3 ends[3] = {{0.6f, 0, 0}, {0, 0.6f, 0}, {0, 0, 0.6f}};
  for (std::size_t arm = 0; arm < 3; ++arm) {
    const Float3 centre{2 * ends[arm][0], 2 * ends[arm][1], 2 * ends[arm][2]};
    BodySettings body = Dynamic("arm" + std::to_string(arm), 0.5f, {0.01f, 0.02f, 0.015f}, centre);
    body.gravity_factor = 0.0f;
    scene.AddBody(body);
    scene.AddConstraint(Ball("hub-arm" + std::to_string(arm), 0, arm + 1, ends[arm]));
  }
  return scene;
}

// A closed loop of four links on ball joints, hung from the world at one
// corner: the ring of joints needs fill.
inline Scene Ring() {
  Scene scene;
  scene.AddBody(StaticWorld());
  const Float3 corners[4] = {{0, 0, 0}, {1, 0, 0}, {1, -1, 0.3f}, {0, -1, 0.3f}};
  for (std::size_t i = 0; i < 4; ++i) {
    const Float3& a = corners[i];
    const Float3& b = corners[(i + 1) % 4];
    scene.AddBody(Dynamic("link" + std::to_string(i), 1.0f + 0.3f * float(i),
                          {0.01f, 0.08f, 0.08f},
                          {0.5f * (a[0] + b[0]), 0.5f * (a[1] + b[1]), 0.5f * (a[2] + b[2])}));
  }
  scene.AddConstraint(Ball("world-link0", 0, 1, corners[0]));
  for (std::size_t i = 0; i < 4; ++i) {
    scene.AddConstraint(Ball("link" + std::to_string(i) + "-link" + std::to_string((i + 1) % 4),
                             i + 1, (i + 1) % 4 + 1, corners[(i + 1) % 4]));
  }
  return scene;
}

// Three links hung from a kinematic body that moves and turns: its velocity
// enters the right-hand side, it is no unknown, and the solve never moves it.
inline Scene Carried() {
  Scene scene;
  BodySettings carrier;
  carrier.name = "carrier";
  carrier.motion_type = MotionType::kKinematic;
  carrier.linear_velocity = {0.5f, 0.0f, 0.2f};
  carrier.angular_velocity = {0.0f, 1.0f, 0.0f};
  scene.AddBody(carrier);
  for (std::size_t i = 0; i < 3; ++i) {
    scene.AddBody(Dynamic("link" + std::to_string(i), 0.8f, {0.02f, 0.003f, 0.02f},
                          {0.1f * float(i), -0.25f - 0.5f * float(i), 0.0f}));
    scene.AddConstraint(Ball("joint" + std::to_string(i), i, i + 1,
                             {0.1f * float(i) - 0.05f, -0.5f * float(i), 0.0f}));
  }
  return scene;
}

inline constexpr Float3 kZ{0, 0, 1};

inline HingeConstraintSettings HingeAboutZ(std::string name, std::size_t body1, std::size_t body2,
                                    Float3 point) {
  HingeConstraintSettings hinge;
  hinge.name = std::move(name);
  hinge.body1 = body1;
  hinge.body2 = body2;
  hinge.point1 = hinge.point2 = point;
  hinge.hinge_axis1 = hinge.hinge_axis2 = kZ;
  hinge.normal_axis1 = hinge.normal_axis2 = {1, 0, 0};
  return hinge;
}

// Every other group kind: two gears (ratio 1.3, so that the wrapped angles
// would break the coupling) on hinges, a weight fixed off the second gear's
// axle (gravity turns the train), and a pinion driving a rack on a slider.
inline Scene Geared() {
  Scene scene;
  scene.AddBody(StaticWorld());
  scene.AddBody(Dynamic("gear1", 1.0f, {0.005f, 0.005f, 0.005f}, {0, 0, 0}));
  scene.AddBody(Dynamic("gear2", 2.0f, {0.04f, 0.04f, 0.03f}, {0.3f, 0, 0}));
  scene.AddBody(Dynamic("weight", 0.5f, {0.002f, 0.002f, 0.002f}, {0.3f, 0.15f, 0}));
  scene.AddBody(Dynamic("pinion", 1.0f, {0.005f, 0.005f, 0.004f}, {0, 0.5f, 0}));
  scene.AddBody(Dynamic("rack", 2.0f, {0.01f, 0.1f, 0.1f}, {0, 0.4f, 0}));
  const std::size_t hinge1 = scene.AddConstraint(HingeAboutZ("gear1 hinge", 0, 1, {0, 0, 0}));
  const std::size_t hinge2 = scene.AddConstraint(HingeAboutZ("gear2 hinge", 0, 2, {0.3f, 0, 0}));
  GearConstraintSettings gear;
  gear.name = "gear";
  gear.body1 = 1;
  gear.body2 = 2;
  gear.hinge_axis1 = gear.hinge_axis2 = kZ;
  gear.ratio = 1.3f;
  gear.hinge1 = hinge1;
  gear.hinge2 = hinge2;
  scene.AddConstraint(gear);
  FixedConstraintSettings fixed;
  fixed.name = "weight on gear2";
  fixed.body1 = 2;
  fixed.body2 = 3;
  fixed.point1 = fixed.point2 = {0.3f, 0.15f, 0};
  scene.AddConstraint(fixed);
  const std::size_t pinion_hinge =
      scene.AddConstraint(HingeAboutZ("pinion hinge", 0, 4, {0, 0.5f, 0}));
  SliderConstraintSettings slider;
  slider.name = "rack slider";
  slider.body1 = 0;
  slider.body2 = 5;
  slider.point1 = slider.point2 = {0, 0.4f, 0};
  slider.slider_axis1 = slider.slider_axis2 = {1, 0, 0};
  slider.normal_axis1 = slider.normal_axis2 = {0, 1, 0};
  const std::size_t rack_slider = scene.AddConstraint(slider);
  RackAndPinionConstraintSettings rack;
  rack.name = "rack and pinion";
  rack.body1 = 4;
  rack.body2 = 5;
  rack.hinge_axis1 = kZ;
  rack.slider_axis2 = {1, 0, 0};
  rack.ratio = 10.0f;
  rack.hinge = pinion_hinge;
  rack.slider = rack_slider;
  scene.AddConstraint(rack);
  return scene;
}

// Bounded rows around the exact solve: a two-link pendulum on hinges with
// hard limits (the first link swings into them), friction on the second
// hinge, and a cart on a slider with hard limits and a position motor,
// hanging the pendulum.
inline Scene Limited() {
  Scene scene;
  scene.AddBody(StaticWorld());
  scene.AddBody(Dynamic("cart", 2.0f, {0.02f, 0.02f, 0.02f}, {0, 0, 0}));
  scene.AddBody(Dynamic("link1", 1.0f, {0.001f, 0.02f, 0.02f}, {0.25f, 0, 0}));
  scene.AddBody(Dynamic("link2", 0.5f, {0.0005f, 0.01f, 0.01f}, {0.75f, 0, 0}));
  SliderConstraintSettings slider;
  slider.name = "cart slider";
  slider.body1 = 0;
  slider.body2 = 1;
  slider.limits_min = -0.05f;
  slider.limits_max = 0.1f;
  slider.motor_state = MotorState::kPosition;
  slider.target_position = 0.08f;
  slider.motor.min_force_limit = -20.0f;
  slider.motor.max_force_limit = 20.0f;
  scene.AddConstraint(slider);
  HingeConstraintSettings first = HingeAboutZ("first hinge", 1, 2, {0, 0, 0});
  first.limits_min = -0.6f;
  first.limits_max = 0.3f;
  scene.AddConstraint(first);
  HingeConstraintSettings second = HingeAboutZ("second hinge", 2, 3, {0.5f, 0, 0});
  second.limits_min = -0.4f;
  second.limits_max = 0.4f;
  second.max_friction_torque = 0.5f;
  scene.AddConstraint(second);
  return scene;
}

// A body whose allowed DOFs lock axes, between free ones: a link held in the
// XY plane (kPlane2D) hung from a free link on a ball joint and carrying a
// free link on a hinge about Z (two groups share its masked mass and
// inertia), started out of the plane (the free top's pivot), so that the
// locks act. A restricted body is a constraint to the world too: more of
// them easily close a loop that turns singular (a body allowed only to turn
// about Z on a ball joint with the free top made this scene's Newton steps
// diverge after a second in some worlds).
inline Scene Restricted() {
  Scene scene;
  scene.AddBody(StaticWorld());
  scene.AddBody(Dynamic("free top", 1.0f, {0.01f, 0.02f, 0.02f}, {0.25f, 0, 0.05f}));
  BodySettings planar = Dynamic("planar", 2.0f, {0.02f, 0.03f, 0.04f}, {0.75f, 0, 0});
  planar.allowed_dofs = AllowedDofs::kPlane2D;
  scene.AddBody(planar);
  scene.AddBody(Dynamic("free bottom", 0.5f, {0.004f, 0.01f, 0.01f}, {1.25f, 0.1f, 0}));
  scene.AddConstraint(Ball("world-top", 0, 1, {0, 0, 0.05f}));
  scene.AddConstraint(Ball("top-planar", 1, 2, {0.5f, 0, 0.02f}));
  scene.AddConstraint(HingeAboutZ("planar-bottom", 2, 3, {1.0f, 0.05f, 0}));
  return scene;
}

// A six-DOF constraint with its frames' X and Y axes the same on both
// bodies and every axis free until the scene fixes some.
inline SixDofConstraintSettings SixDof(std::string name, std::size_t body1, std::size_t body2,
                                Float3 axis_x, Float3 axis_y) {
  SixDofConstraintSettings six_dof;
  six_dof.name = std::move(name);
  six_dof.body1 = body1;
  six_dof.body2 = body2;
  six_dof.axis_x1 = six_dof.axis_x2 = axis_x;
  six_dof.axis_y1 = six_dof.axis_y2 = axis_y;
  for (std::size_t i = 0; i < kSixDofAxes; ++i) six_dof.MakeFreeAxis(SixDofAxis(i));
  return six_dof;
}

// Six-DOF constraints whose all-fixed shortcuts are the exact solve's
// groups: a link hung from the world with every translation fixed at an
// offset and every rotation free (a point group on body 1's anchor moved by
// c1 min), a second link welded to it with every axis fixed at offsets (a
// point and a rotation group; frames turned away from the bodies' axes), and
// a third on a ball joint below. Only groups: the tolerance test holds it.
inline Scene Welded() {
  Scene scene;
  scene.AddBody(StaticWorld());
  scene.AddBody(Dynamic("upper", 1.2f, {0.02f, 0.01f, 0.02f}, {0.05f, -0.3f, 0.0f}));
  scene.AddBody(Dynamic("welded", 0.7f, {0.01f, 0.006f, 0.012f}, {0.1f, -0.75f, 0.05f}));
  scene.AddBody(Dynamic("lower", 0.4f, {0.004f, 0.002f, 0.004f}, {0.1f, -1.25f, 0.05f}));
  SixDofConstraintSettings pivot = SixDof("offset pivot", 0, 1, {0.0f, 0.6f, 0.8f}, {1, 0, 0});
  const float offsets[3] = {0.03f, -0.02f, 0.01f};
  for (std::size_t i = 0; i < 3; ++i) pivot.limit_min[i] = pivot.limit_max[i] = offsets[i];
  scene.AddConstraint(pivot);
  SixDofConstraintSettings weld = SixDof("offset weld", 1, 2, {0, 0, 1}, {1, 0, 0});
  weld.space = ConstraintSpace::kLocalToBodyCOM;
  weld.position1 = {0.0f, -0.2f, 0.02f};
  weld.position2 = {-0.05f, 0.2f, -0.03f};
  weld.swing_type = SwingType::kPyramid;  // a cone's swing limits would be +-|max|
  const float weld_offsets[6] = {0.02f, 0.0f, -0.01f, 0.1f, -0.05f, 0.2f};
  for (std::size_t i = 0; i < kSixDofAxes; ++i) {
    weld.limit_min[i] = weld.limit_max[i] = weld_offsets[i];
  }
  scene.AddConstraint(weld);
  scene.AddConstraint(Ball("welded-lower", 2, 3, {0.1f, -1.0f, 0.05f}));
  return scene;
}

// A six-DOF carriage on a rail with every rotation fixed (the rotation group)
// and translation free along X, fixed along Y and Z (two axis rows solved by
// Gauss-Seidel around the solve, always on: no threshold switches them), a
// pendulum hinged below it.
inline Scene Slide() {
  Scene scene;
  scene.AddBody(StaticWorld());
  scene.AddBody(Dynamic("carriage", 2.0f, {0.05f, 0.07f, 0.06f}, {0.0f, 0.0f, 0.0f}));
  scene.AddBody(Dynamic("pendulum", 0.6f, {0.01f, 0.002f, 0.01f}, {0.0f, -0.5f, 0.0f}));
  SixDofConstraintSettings rail = SixDof("rail", 0, 1, {0.8f, 0.0f, 0.6f}, {0, 1, 0});
  rail.MakeFixedAxis(SixDofAxis::kTranslationY);
  rail.MakeFixedAxis(SixDofAxis::kTranslationZ);
  for (std::size_t i = 3; i < kSixDofAxes; ++i) rail.MakeFixedAxis(SixDofAxis(i));
  scene.AddConstraint(rail);
  scene.AddConstraint(HingeAboutZ("carriage-pendulum", 1, 2, {0.0f, -0.05f, 0.0f}));
  return scene;
}

// Rigid distance constraints (rods) whose rows the exact solve factors: a
// chain of three links hung from the world by rods between their ends
// (lever arms turn the links), and a triangle of rods closing a loop between
// the last two links and a weight. Only groups: the tolerance test holds it.
inline Scene Rods() {
  Scene scene;
  scene.AddBody(StaticWorld());
  const auto rod = [&](std::string name, std::size_t body1, std::size_t body2, Float3 point1,
                       Float3 point2) {
    DistanceConstraintSettings rod;
    rod.name = std::move(name);
    rod.body1 = body1;
    rod.body2 = body2;
    rod.point1 = point1;
    rod.point2 = point2;  // both bounds negative: a rod of the initial length
    scene.AddConstraint(rod);
  };
  for (std::size_t i = 0; i < 3; ++i) {
    const float y = -0.4f - 0.5f * float(i);
    scene.AddBody(Dynamic("link" + std::to_string(i), 0.6f + 0.2f * float(i),
                          {0.01f, 0.003f, 0.01f}, {0.05f * float(i), y, 0.0f}));
    rod("rod" + std::to_string(i), i, i + 1, {0.05f * float(i) - 0.02f, y + 0.35f, 0.03f},
        {0.05f * float(i), y + 0.2f, 0.0f});
  }
  scene.AddBody(Dynamic("weight", 0.5f, {0.002f, 0.002f, 0.002f}, {0.4f, -1.6f, 0.1f}));
  rod("link1-weight", 2, 4, {0.05f, -0.95f, 0.0f}, {0.38f, -1.6f, 0.1f});
  rod("link2-weight", 3, 4, {0.1f, -1.55f, 0.0f}, {0.4f, -1.58f, 0.1f});
  return scene;
}

inline Scene ExactScene(const std::string& id) {
  if (id == "restricted") return Restricted();
  if (id == "star") return Star();
  if (id == "ring") return Ring();
  if (id == "carried") return Carried();
  if (id == "geared") return Geared();
  if (id == "limited") return Limited();
  if (id == "welded") return Welded();
  if (id == "slide") return Slide();
  if (id == "rods") return Rods();
  // more_types (distance, pulley, cone, swing-twist, six-DOF and path
  // constraints), a reference or a stress scene.
  return test_scenes::SceneById(id);
}

}  // namespace manyworlds::exact_scenes
