// The stress scenes of the spec (docs/scenes.md, "Stress scenes"): stiff
// springs, fast spins, singular starts, extreme steps, masses and coordinates.
// Each must stay finite and bounded for 10 s at its step settings
// (tests/stress_test.cc); docs/stability.md has their figures.

#include <array>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

#include "manyworlds/scenes.h"

#include "batch/scene_bodies.h"
#include "batch/scene_ids.h"

namespace manyworlds {
namespace {

constexpr Float3 kX{1, 0, 0}, kY{0, 1, 0}, kZ{0, 0, 1};
constexpr float kDefaultDt = 1.0f / 60.0f;

enum class StressId {
  kChain16R1000, kChain64, kSpring0_1, kSpring0_25, kSpring0_5, kSpring1_0, kSpinUnstable,
  kFlywheel, kSingularHinge90, kSingularHinge180, kSingularFixed90, kSingularFixed180,
  kSingularSlider90, kSingularRackPinion, kSingularCone, kSingularSwingTwist, kDt1e4, kDt1_15,
  kMassRange, kMassRangeHanging, kFar1e4
};

// Each stress scene with what it is there to test (SceneDescription).
struct StressEntry {
  std::string_view id;
  StressId scene;
  std::string_view description;
};
constexpr std::array<StressEntry, 21> kStressScenes{{
    {"chain16-r1000", StressId::kChain16R1000, "the reference scene: mass ratio 1000"},
    {"chain64", StressId::kChain64, "the reference scene: a 64-joint chain"},
    {"spring-0.1", StressId::kSpring0_1, "stiff distance spring at 0.1 of Nyquist (3 Hz)"},
    {"spring-0.25", StressId::kSpring0_25, "stiff distance spring at 0.25 of Nyquist (7.5 Hz)"},
    {"spring-0.5", StressId::kSpring0_5, "stiff distance spring at 0.5 of Nyquist (15 Hz)"},
    {"spring-1.0", StressId::kSpring1_0, "distance spring at the Nyquist edge (30 Hz)"},
    {"spin-unstable", StressId::kSpinUnstable,
     "free body spun about its intermediate axis: the flip Jolt leaves out"},
    {"flywheel", StressId::kFlywheel, "hinged disc at Jolt's maximum angular velocity"},
    {"singular-hinge-90", StressId::kSingularHinge90,
     "hinge starting with its axes 90 deg apart"},
    {"singular-hinge-180", StressId::kSingularHinge180,
     "hinge starting with anti-parallel axes"},
    {"singular-fixed-90", StressId::kSingularFixed90,
     "fixed joint starting 90 deg from its rest pose"},
    {"singular-fixed-180", StressId::kSingularFixed180,
     "fixed joint starting 180 deg from its rest pose"},
    {"singular-slider-90", StressId::kSingularSlider90,
     "slider starting with its axis 90 deg from the rail's"},
    {"singular-rackpinion", StressId::kSingularRackPinion,
     "rack and pinion with the hinge axis parallel to the slider axis"},
    {"singular-cone", StressId::kSingularCone, "cone joint starting with anti-parallel twist axes"},
    {"singular-swingtwist", StressId::kSingularSwingTwist,
     "swing-twist joint starting at a swing of pi"},
    {"dt-1e-4", StressId::kDt1e4, "chain16 at a tiny step, dt 1e-4 s"},
    {"dt-1/15", StressId::kDt1_15, "chain16 at a large step, dt 1/15 s"},
    {"mass-range", StressId::kMassRange,
     "10-link whip, 1e6 kg at the anchor down to 1e-3 kg at the tip"},
    {"mass-range-hanging", StressId::kMassRangeHanging,
     "10-link chain, 1e6 kg hanging from 1e-3 kg"},
    {"far-1e4", StressId::kFar1e4, "chain16 1e4 m from the origin: float precision"},
}};

const StressEntry* FindStress(std::string_view id) {
  for (const StressEntry& entry : kStressScenes) {
    if (entry.id == id) return &entry;
  }
  return nullptr;
}

using scene_bodies::Dynamic;
using scene_bodies::StaticWorld;

// A rotation of `angle` rad about the unit `axis`, as (x, y, z, w).
Quaternion AxisAngle(Float3 axis, double angle) {
  const double s = std::sin(angle / 2);
  return {float(axis[0] * s), float(axis[1] * s), float(axis[2] * s), float(std::cos(angle / 2))};
}

// A unit cube of 1 kg (inertia 1/6 about every axis) with its centre of mass
// on the joint at the origin, turned `angle` rad about `axis` from the
// joint's rest pose (identity): gravity exerts no torque about the joint, so
// only the constraint turns it back.
BodySettings TurnedCube(Float3 axis, double angle) {
  constexpr float kInertia = 1.0f / 6.0f;
  return Dynamic("cube", 1.0f, {kInertia, kInertia, kInertia}, {0, 0, 0},
                 AxisAngle(axis, angle));
}

// spring-<fraction>: a 1 kg sphere (r = 0.5, inertia 0.1), gravity factor 0,
// 1 m along X from the static world's origin, tied to it by a distance
// constraint with min = max = 0 and a limits spring of frequency
// fraction / dt / 2 at dt 1/60 s (fraction 1 is the Nyquist edge) and damping
// ratio 0 (the implicit-Euler spring still damps; tests/stress_test.cc
// compares with its recursion).
Scene Spring(float fraction) {
  Scene scene;
  scene.AddBody(StaticWorld());
  BodySettings sphere =
      Dynamic("sphere", 1.0f, {0.1f, 0.1f, 0.1f}, {stress_scene::kSpringStart, 0, 0});
  sphere.gravity_factor = 0.0f;
  const std::size_t body = scene.AddBody(sphere);
  DistanceConstraintSettings spring;
  spring.name = "spring";
  spring.body1 = 0;
  spring.body2 = body;
  spring.point1 = {0, 0, 0};
  spring.point2 = sphere.position;
  spring.min_distance = spring.max_distance = 0.0f;
  spring.limits_spring.mode = SpringMode::kFrequencyAndDamping;
  spring.limits_spring.frequency_or_stiffness = fraction / kDefaultDt / 2.0f;
  spring.limits_spring.damping = 0.0f;
  scene.AddConstraint(spring);
  return scene;
}

// A free body with inertia (1, 2, 3), no gravity, spun at 40 rad/s about its
// middle (unstable) axis Y, tilted 0.01 rad towards X so the flip of the
// intermediate axis theorem starts within a fraction of a second (the exact
// motion flips 19 times in 10 s).
Scene SpinUnstable() {
  using stress_scene::kSpinRate, stress_scene::kSpinTilt;
  Scene scene;
  scene.AddBody(StaticWorld());
  BodySettings body = Dynamic("spinner", 1.0f, {1.0f, 2.0f, 3.0f}, {0, 0, 0});
  body.gravity_factor = 0.0f;
  body.angular_velocity = {kSpinRate * std::sin(kSpinTilt), kSpinRate * std::cos(kSpinTilt), 0};
  scene.AddBody(body);
  return scene;
}

// A flywheel (disc of 10 kg, radius 0.3: inertia 0.225, 0.225, 0.45) on a
// hinge about Z through its centre of mass at (0, 1, 0), spinning at Jolt's
// default max angular velocity 0.25 pi 60 rad/s (0.785 rad per step).
Scene Flywheel() {
  Scene scene;
  scene.AddBody(StaticWorld());
  BodySettings wheel = Dynamic("flywheel", 10.0f, {0.225f, 0.225f, 0.45f}, {0, 1, 0});
  wheel.angular_velocity = {0, 0, wheel.max_angular_velocity};
  const std::size_t body = scene.AddBody(wheel);
  HingeConstraintSettings hinge;
  hinge.name = "axle";
  hinge.body1 = 0;
  hinge.body2 = body;
  hinge.point1 = hinge.point2 = wheel.position;
  hinge.hinge_axis1 = hinge.hinge_axis2 = kZ;
  hinge.normal_axis1 = hinge.normal_axis2 = kX;
  scene.AddConstraint(hinge);
  return scene;
}

// The frames of the singular starts are given in body space (the static world
// is at the origin, so its body space is world space): both bodies' frames
// are the identity, so the rest pose is the cube at identity rotation, and
// the cube starts turned away from it.

// Hinge about Z with limits +-0.01 rad (Jolt's ConstraintSingularityTest), the
// cube turned `angle` about X: its hinge axis 90 deg (perpendicular) or
// 180 deg (anti-parallel) from the world's.
Scene SingularHinge(double angle) {
  Scene scene;
  scene.AddBody(StaticWorld());
  const std::size_t body = scene.AddBody(TurnedCube(kX, angle));
  HingeConstraintSettings hinge;
  hinge.name = "hinge";
  hinge.body1 = 0;
  hinge.body2 = body;
  hinge.space = ConstraintSpace::kLocalToBodyCOM;
  hinge.hinge_axis1 = hinge.hinge_axis2 = kZ;
  hinge.normal_axis1 = hinge.normal_axis2 = kX;
  hinge.limits_min = -0.01f;
  hinge.limits_max = 0.01f;
  scene.AddConstraint(hinge);
  return scene;
}

// Fixed constraint, the cube turned `angle` about X from the weld's rest pose.
Scene SingularFixed(double angle) {
  Scene scene;
  scene.AddBody(StaticWorld());
  const std::size_t body = scene.AddBody(TurnedCube(kX, angle));
  FixedConstraintSettings weld;
  weld.name = "weld";
  weld.body1 = 0;
  weld.body2 = body;
  weld.space = ConstraintSpace::kLocalToBodyCOM;
  scene.AddConstraint(weld);
  return scene;
}

// Slider along X (normal Y), limits [-1, 1] m so nothing the correction leaves
// carries the cube away; the cube turned 90 deg about Z, so its slider axis
// starts along Y, perpendicular to the world's.
Scene SingularSlider() {
  Scene scene;
  scene.AddBody(StaticWorld());
  const std::size_t body = scene.AddBody(TurnedCube(kZ, 0.5 * std::acos(-1.0)));
  SliderConstraintSettings slider;
  slider.name = "slider";
  slider.body1 = 0;
  slider.body2 = body;
  slider.space = ConstraintSpace::kLocalToBodyCOM;
  slider.slider_axis1 = slider.slider_axis2 = kX;
  slider.normal_axis1 = slider.normal_axis2 = kY;
  slider.limits_min = -1.0f;
  slider.limits_max = 1.0f;
  scene.AddConstraint(slider);
  return scene;
}

// rackpinion with the pinion's hinge axis along X, parallel to the rack's
// slider axis (a screw): pinion hinge about X at (0, 0.1, 0) with the velocity
// motor of rackpinion (2 rad/s, +-5 N m), rack slider along X, coupling
// theta - 10 d = 0 with position correction.
Scene SingularRackPinion() {
  Scene scene;
  scene.AddBody(StaticWorld());
  const std::size_t pinion =
      scene.AddBody(Dynamic("pinion", 1.0f, {0.005f, 0.005f, 0.005f}, {0, 0.1f, 0}));
  const std::size_t rack = scene.AddBody(Dynamic("rack", 2.0f, {0.01f, 0.1f, 0.1f}, {0, 0, 0}));
  HingeConstraintSettings hinge;
  hinge.name = "pinion hinge";
  hinge.body1 = 0;
  hinge.body2 = pinion;
  hinge.point1 = hinge.point2 = {0, 0.1f, 0};
  hinge.hinge_axis1 = hinge.hinge_axis2 = kX;
  hinge.normal_axis1 = hinge.normal_axis2 = kY;
  hinge.motor_state = MotorState::kVelocity;
  hinge.target_angular_velocity = 2.0f;
  hinge.motor.min_force_limit = -5.0f;
  hinge.motor.max_force_limit = 5.0f;
  const std::size_t hinge_index = scene.AddConstraint(hinge);
  SliderConstraintSettings slider;
  slider.name = "rack slider";
  slider.body1 = 0;
  slider.body2 = rack;
  slider.slider_axis1 = slider.slider_axis2 = kX;
  slider.normal_axis1 = slider.normal_axis2 = kY;
  const std::size_t slider_index = scene.AddConstraint(slider);
  RackAndPinionConstraintSettings coupling;
  coupling.name = "rack and pinion";
  coupling.body1 = pinion;
  coupling.body2 = rack;
  coupling.hinge_axis1 = kX;
  coupling.slider_axis2 = kX;
  coupling.ratio = 10.0f;
  coupling.hinge = hinge_index;
  coupling.slider = slider_index;
  scene.AddConstraint(coupling);
  return scene;
}

// Cone of half angle 0.5 rad about X, the cube turned 180 deg about Y: the
// twist axes start anti-parallel, where t2 x t1 = 0 and the rotation axis
// falls back to the initial perpendicular.
Scene SingularCone() {
  Scene scene;
  scene.AddBody(StaticWorld());
  const std::size_t body = scene.AddBody(TurnedCube(kY, std::acos(-1.0)));
  ConeConstraintSettings cone;
  cone.name = "cone";
  cone.body1 = 0;
  cone.body2 = body;
  cone.space = ConstraintSpace::kLocalToBodyCOM;
  cone.twist_axis1 = cone.twist_axis2 = kX;
  cone.half_cone_angle = 0.5f;
  scene.AddConstraint(cone);
  return scene;
}

// Swing-twist (cone swing 0.5 / 0.5 rad, twist +-0.3 rad; twist X, plane Z),
// the cube turned 180 deg about the plane axis Z: a swing of pi, where the
// swing-twist decomposition has x = w = 0.
Scene SingularSwingTwist() {
  Scene scene;
  scene.AddBody(StaticWorld());
  const std::size_t body = scene.AddBody(TurnedCube(kZ, std::acos(-1.0)));
  SwingTwistConstraintSettings joint;
  joint.name = "swing twist";
  joint.body1 = 0;
  joint.body2 = body;
  joint.space = ConstraintSpace::kLocalToBodyCOM;
  joint.twist_axis1 = joint.twist_axis2 = kX;
  joint.plane_axis1 = joint.plane_axis2 = kZ;
  joint.swing_type = SwingType::kCone;
  joint.normal_half_cone_angle = joint.plane_half_cone_angle = 0.5f;
  joint.twist_min_angle = -0.3f;
  joint.twist_max_angle = 0.3f;
  scene.AddConstraint(joint);
  return scene;
}

// mass-range and mass-range-hanging: chain16's geometry with kMassRangeLinks
// links, masses 1e-3 to 1e6 kg a factor 10 apart (inertia scaled with the
// mass), released from horizontal. mass-range has the 1e6 kg link at the
// anchor and the 1e-3 kg link at the free end (a tapered whip);
// mass-range-hanging the other way round (1e6 kg hanging from 1e-3 kg).
Scene MassRange(bool heavy_at_anchor) {
  constexpr std::size_t kLinks = stress_scene::kMassRangeLinks;
  Scene scene = MakeReferenceScene("chain16");
  scene.bodies().resize(kLinks + 1);
  scene.constraints().resize(kLinks);
  for (std::size_t i = 0; i < kLinks; ++i) {
    BodySettings& link = scene.bodies()[i + 1];
    const double decade = heavy_at_anchor ? 6.0 - double(i) : double(i) - 3.0;
    const float scale = float(std::pow(10.0, decade));
    link.mass *= scale;
    for (float& inertia : link.inertia_diagonal) inertia *= scale;
  }
  return scene;
}

// far-1e4: chain16 with every body and anchor shifted by kFarOffset on each
// axis (the static world stays at the origin; its anchors are 1.7e4 m away).
Scene Far() {
  constexpr float d = stress_scene::kFarOffset;
  Scene scene = MakeReferenceScene("chain16");
  for (std::size_t i = 1; i < scene.bodies().size(); ++i) {
    for (float& x : scene.bodies()[i].position) x += d;
  }
  for (ConstraintSettings& settings : scene.constraints()) {
    PointConstraintSettings& ball = std::get<PointConstraintSettings>(settings);
    for (float* point : {ball.point1.data(), ball.point2.data()}) {
      for (int k = 0; k < 3; ++k) point[k] += d;
    }
  }
  return scene;
}

}  // namespace

std::vector<std::string> StressSceneIds() {
  std::vector<std::string> ids;
  for (const StressEntry& entry : kStressScenes) ids.emplace_back(entry.id);
  return ids;
}

Scene MakeStressScene(std::string_view id) {
  const StressEntry* entry = FindStress(id);
  if (entry == nullptr) {
    std::string valid;
    for (const StressEntry& stress : kStressScenes) {
      valid += (valid.empty() ? "" : ", ") + std::string(stress.id);
    }
    throw std::invalid_argument("unknown stress scene '" + std::string(id) +
                                "'; valid ids: " + valid);
  }
  const double pi = std::acos(-1.0);
  switch (entry->scene) {
    case StressId::kChain16R1000: return MakeReferenceScene("chain16-r1000");
    case StressId::kChain64: return MakeReferenceScene("chain64");
    case StressId::kSpring0_1: return Spring(0.1f);
    case StressId::kSpring0_25: return Spring(0.25f);
    case StressId::kSpring0_5: return Spring(0.5f);
    case StressId::kSpring1_0: return Spring(1.0f);
    case StressId::kSpinUnstable: return SpinUnstable();
    case StressId::kFlywheel: return Flywheel();
    case StressId::kSingularHinge90: return SingularHinge(pi / 2);
    case StressId::kSingularHinge180: return SingularHinge(pi);
    case StressId::kSingularFixed90: return SingularFixed(pi / 2);
    case StressId::kSingularFixed180: return SingularFixed(pi);
    case StressId::kSingularSlider90: return SingularSlider();
    case StressId::kSingularRackPinion: return SingularRackPinion();
    case StressId::kSingularCone: return SingularCone();
    case StressId::kSingularSwingTwist: return SingularSwingTwist();
    case StressId::kDt1e4:
    case StressId::kDt1_15: return MakeReferenceScene("chain16");
    case StressId::kMassRange: return MassRange(/*heavy_at_anchor=*/true);
    case StressId::kMassRangeHanging: return MassRange(/*heavy_at_anchor=*/false);
    case StressId::kFar1e4: return Far();
  }
  throw std::logic_error("MakeStressScene: unhandled scene id");
}

StepSettings SceneStepSettings(std::string_view id) {
  StepSettings settings;
  if (const StressEntry* entry = FindStress(id)) {
    if (entry->scene == StressId::kDt1e4) settings.delta_time = 1.0e-4f;
    if (entry->scene == StressId::kDt1_15) settings.delta_time = 1.0f / 15.0f;
    return settings;
  }
  for (const std::string& reference : ReferenceSceneIds()) {
    if (reference == id) return settings;
  }
  if (!scene_ids::ContactSceneDescription(id).empty()) return settings;
  scene_ids::ThrowUnknownScene(id);
}

std::string_view scene_ids::StressSceneDescription(std::string_view id) {
  const StressEntry* entry = FindStress(id);
  return entry == nullptr ? std::string_view() : entry->description;
}

}  // namespace manyworlds
