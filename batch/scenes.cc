// The reference scenes (docs/scenes.md; the brief's scenes-and-metrics spec).

#include "manyworlds/scenes.h"

#include "batch/hash.h"
#include "batch/scene_bodies.h"
#include "batch/scene_ids.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>
#include <variant>

namespace manyworlds {
namespace {

constexpr Float3 kX{1, 0, 0}, kY{0, 1, 0}, kZ{0, 0, 1};

// The scene id in a form that can be switched on.
enum class SceneId { kCartpole, kChain16, kChain16R100, kChain16R1000, kChain64, kRackPinion,
                     kGearTrain, kRagdoll, kLinkage };

// Each scene with what it is there to test (SceneDescription; docs/scenes.md
// has the full specification).
struct SceneEntry {
  std::string_view id;
  SceneId scene;
  std::string_view description;
};
constexpr std::array<SceneEntry, 9> kScenes{{
    {"cartpole", SceneId::kCartpole,
     "slider and hinge under a random cart force every step (RL control loop)"},
    {"chain16", SceneId::kChain16, "16 ball joints released from horizontal: a long chain"},
    {"chain16-r100", SceneId::kChain16R100,
     "chain16 with a 100x heavier last link: mass ratio 100"},
    {"chain16-r1000", SceneId::kChain16R1000,
     "chain16 with a 1000x heavier last link: mass ratio 1000 (also a stress scene)"},
    {"chain64", SceneId::kChain64,
     "64 ball joints: convergence of a long chain (also a stress scene)"},
    {"rackpinion", SceneId::kRackPinion,
     "hinge velocity motor driving a slider through a rack-and-pinion coupling"},
    {"geartrain", SceneId::kGearTrain,
     "hinge velocity motor driving a second hinge through a gear coupling"},
    {"ragdoll", SceneId::kRagdoll,
     "floating humanoid: swing-twist limits, hinge position motors with random targets"},
    {"linkage", SceneId::kLinkage,
     "free closed loop of two hinges and two ball joints with a geared flywheel: loop energy"},
}};

SceneId ParseId(std::string_view id) {
  std::string valid;
  for (const SceneEntry& entry : kScenes) {
    if (entry.id == id) return entry.scene;
    valid += (valid.empty() ? "" : ", ") + std::string(entry.id);
  }
  throw std::invalid_argument("unknown reference scene '" + std::string(id) +
                              "'; valid ids: " + valid);
}

using scene_bodies::Dynamic;
using scene_bodies::StaticWorld;

// A hinge about Z through `point` (world space), normal axes X in both bodies
// unless given.
HingeConstraintSettings HingeAboutZ(std::string name, std::size_t body1, std::size_t body2,
                                    Float3 point, Float3 normal2 = kX) {
  HingeConstraintSettings hinge;
  hinge.name = std::move(name);
  hinge.body1 = body1;
  hinge.body2 = body2;
  hinge.space = ConstraintSpace::kWorldSpace;
  hinge.point1 = hinge.point2 = point;
  hinge.hinge_axis1 = hinge.hinge_axis2 = kZ;
  hinge.normal_axis1 = kX;
  hinge.normal_axis2 = normal2;
  return hinge;
}

// A velocity motor: target (rad/s), torque limited to [-max, max] (N m).
void VelocityMotor(HingeConstraintSettings& hinge, float target, float max_torque) {
  hinge.motor_state = MotorState::kVelocity;
  hinge.target_angular_velocity = target;
  hinge.motor.min_force_limit = -max_torque;
  hinge.motor.max_force_limit = max_torque;
}

// A slider along X (normal Y) through `point` (world space).
SliderConstraintSettings SliderAlongX(std::string name, std::size_t body1, std::size_t body2,
                                      Float3 point) {
  SliderConstraintSettings slider;
  slider.name = std::move(name);
  slider.body1 = body1;
  slider.body2 = body2;
  slider.space = ConstraintSpace::kWorldSpace;
  slider.point1 = slider.point2 = point;
  slider.slider_axis1 = slider.slider_axis2 = kX;
  slider.normal_axis1 = slider.normal_axis2 = kY;
  return slider;
}

Scene Cartpole() {
  using namespace reference_scene;
  constexpr double kAngle = 0.1;  // rad about Z, the pole's start
  const double c = std::cos(kAngle), s = std::sin(kAngle);
  Scene scene;
  scene.AddBody(StaticWorld());
  scene.AddBody(Dynamic("cart", 1.0f, {0.1f, 0.1f, 0.1f}, {0, 0, 0}));
  // Rod along Y, COM 0.5 above the hinge (the cart's COM), rotated 0.1 rad
  // about Z: COM = R (0, 0.5, 0).
  BodySettings pole = Dynamic("pole", 0.1f, {0.0084f, 0.0001f, 0.0084f},
                              {float(-0.5 * s), float(0.5 * c), 0.0f});
  pole.rotation = {0.0f, 0.0f, float(std::sin(kAngle / 2)), float(std::cos(kAngle / 2))};
  scene.AddBody(pole);
  scene.AddConstraint(SliderAlongX("rail", kWorld, kCart, {0, 0, 0}));
  // Normal axis 2 is the pole's X axis, R (1, 0, 0): the hinge angle is the
  // pole's angle from upright, 0.1 rad at the start.
  scene.AddConstraint(
      HingeAboutZ("pole hinge", kCart, kPole, {0, 0, 0}, {float(c), float(s), 0.0f}));
  return scene;
}

// `links` rods 0.5 m long along X, COM of link i at (0.25 + 0.5 i, 0, 0),
// ball joints world-link0 at the origin and link i-link i+1 at 0.5 (i + 1);
// the last link's mass and inertia times `last_scale`.
Scene Chain(std::size_t links, float last_scale) {
  constexpr float kMass = 1.0f;
  constexpr Float3 kInertia{0.001f, 0.0208f, 0.0208f};
  Scene scene;
  scene.AddBody(StaticWorld());
  for (std::size_t i = 0; i < links; ++i) {
    const float scale = i + 1 == links ? last_scale : 1.0f;
    scene.AddBody(Dynamic("link" + std::to_string(i), kMass * scale,
                          {kInertia[0] * scale, kInertia[1] * scale, kInertia[2] * scale},
                          {0.25f + 0.5f * float(i), 0.0f, 0.0f}));
  }
  for (std::size_t i = 0; i < links; ++i) {
    PointConstraintSettings ball;
    ball.name = i == 0 ? std::string("world-link0")
                       : "link" + std::to_string(i - 1) + "-link" + std::to_string(i);
    ball.body1 = i;  // the world, then link i - 1
    ball.body2 = i + 1;
    ball.space = ConstraintSpace::kWorldSpace;
    ball.point1 = ball.point2 = {0.5f * float(i), 0.0f, 0.0f};
    scene.AddConstraint(ball);
  }
  return scene;
}

Scene RackPinion() {
  using namespace reference_scene;
  Scene scene;
  scene.AddBody(StaticWorld());
  scene.AddBody(Dynamic("pinion", 1.0f, {0.005f, 0.005f, 0.005f}, {0.0f, 0.1f, 0.0f}));
  scene.AddBody(Dynamic("rack", 2.0f, {0.01f, 0.1f, 0.1f}, {0, 0, 0}));
  HingeConstraintSettings hinge =
      HingeAboutZ("pinion hinge", kWorld, kPinion, {0.0f, 0.1f, 0.0f});
  VelocityMotor(hinge, 2.0f, 5.0f);
  const std::size_t hinge_index = scene.AddConstraint(hinge);
  const std::size_t slider_index =
      scene.AddConstraint(SliderAlongX("rack slider", kWorld, kRack, {0, 0, 0}));
  RackAndPinionConstraintSettings rack;
  rack.name = "rack and pinion";
  rack.body1 = kPinion;
  rack.body2 = kRack;
  rack.space = ConstraintSpace::kWorldSpace;
  rack.hinge_axis1 = kZ;
  rack.slider_axis2 = kX;
  rack.ratio = 10.0f;  // rad/m: 1 rad of pinion = 0.1 m of rack
  rack.hinge = hinge_index;
  rack.slider = slider_index;
  scene.AddConstraint(rack);
  return scene;
}

Scene GearTrain() {
  using namespace reference_scene;
  // Disc-like gears of radius 0.1 and 0.2 (I = m r^2 / 2), meshing: axles 0.3 apart.
  constexpr Float3 kAxle1{0, 0, 0}, kAxle2{0.3f, 0, 0};
  Scene scene;
  scene.AddBody(StaticWorld());
  scene.AddBody(Dynamic("gear1", 1.0f, {0.005f, 0.005f, 0.005f}, kAxle1));
  scene.AddBody(Dynamic("gear2", 2.0f, {0.04f, 0.04f, 0.04f}, kAxle2));
  HingeConstraintSettings hinge1 = HingeAboutZ("gear1 hinge", kWorld, kGear1, kAxle1);
  VelocityMotor(hinge1, 2.0f, 5.0f);
  const std::size_t hinge1_index = scene.AddConstraint(hinge1);
  const std::size_t hinge2_index =
      scene.AddConstraint(HingeAboutZ("gear2 hinge", kWorld, kGear2, kAxle2));
  GearConstraintSettings gear;
  gear.name = "gear";
  gear.body1 = kGear1;
  gear.body2 = kGear2;
  gear.space = ConstraintSpace::kWorldSpace;
  gear.hinge_axis1 = gear.hinge_axis2 = kZ;
  gear.ratio = 2.0f;  // theta1 + 2 theta2 = 0
  gear.hinge1 = hinge1_index;
  gear.hinge2 = hinge2_index;
  scene.AddConstraint(gear);
  return scene;
}

Scene Linkage() {
  using namespace reference_scene;
  // A crank-rocker four-bar (crank 0.3, coupler 0.92, rocker 0.6, ground 1:
  // Grashof, transmission angle within 49-116 degrees, so its rows never
  // become dependent) whose coupler is on ball joints: two parallel hinges
  // and two ball joints close the loop without the redundant rows of four
  // parallel hinges. A flywheel turns twice as fast as the crank. Released
  // from rest with the crank horizontal, gravity swings it back and forth.
  Scene scene;
  scene.AddBody(StaticWorld());
  scene.AddBody(Dynamic("crank", 1.0f, {0.001f, 0.008f, 0.008f}, {0.15f, 0, 0}));
  scene.AddBody(Dynamic("coupler", 1.5f, {0.05f, 0.06f, 0.1f}, {0.65f, 0.3f, 0}));
  scene.AddBody(Dynamic("rocker", 1.2f, {0.036f, 0.002f, 0.036f}, {1.0f, 0.3f, 0}));
  scene.AddBody(Dynamic("flywheel", 3.0f, {0.03f, 0.03f, 0.05f}, {-0.5f, 0, 0}));
  scene.AddConstraint(HingeAboutZ("crank hinge", kWorld, kCrank, {0, 0, 0}));
  const auto ball = [&](std::string name, std::size_t body1, std::size_t body2, Float3 point) {
    PointConstraintSettings joint;
    joint.name = std::move(name);
    joint.body1 = body1;
    joint.body2 = body2;
    joint.space = ConstraintSpace::kWorldSpace;
    joint.point1 = joint.point2 = point;
    scene.AddConstraint(joint);
  };
  ball("crank-coupler", kCrank, kCoupler, {0.3f, 0, 0});
  ball("coupler-rocker", kCoupler, kRocker, {1.0f, 0.6f, 0});
  scene.AddConstraint(HingeAboutZ("rocker hinge", kWorld, kRocker, {1.0f, 0, 0}));
  scene.AddConstraint(HingeAboutZ("flywheel hinge", kWorld, kFlywheel, {-0.5f, 0, 0}));
  GearConstraintSettings gear;
  gear.name = "flywheel gear";
  gear.body1 = kFlywheel;
  gear.body2 = kCrank;
  gear.space = ConstraintSpace::kWorldSpace;
  gear.hinge_axis1 = gear.hinge_axis2 = kZ;
  gear.ratio = 2.0f;  // theta_flywheel + 2 theta_crank = 0
  gear.hinge1 = kFlywheelHinge;
  gear.hinge2 = kCrankHinge;
  scene.AddConstraint(gear);
  return scene;
}

// A rod-like limb of mass m and length L along Y: inertia m L^2 / 12 across
// it, a tenth of that along it.
BodySettings Limb(std::string name, float mass, float length, Float3 position) {
  const float across = mass * length * length / 12.0f;
  BodySettings body = Dynamic(std::move(name), mass, {across, 0.1f * across, across}, position);
  body.gravity_factor = 0.0f;  // floating
  return body;
}

// A ragdoll joint at `point` (world space), twist axis `twist`, plane axis Z.
SwingTwistConstraintSettings Joint(std::string name, std::size_t body1, std::size_t body2,
                                   Float3 point, Float3 twist, float normal_half_cone,
                                   float plane_half_cone, float twist_min, float twist_max) {
  SwingTwistConstraintSettings joint;
  joint.name = std::move(name);
  joint.body1 = body1;
  joint.body2 = body2;
  joint.point1 = joint.point2 = point;
  joint.twist_axis1 = joint.twist_axis2 = twist;
  joint.plane_axis1 = joint.plane_axis2 = kZ;
  joint.swing_type = SwingType::kCone;
  joint.normal_half_cone_angle = normal_half_cone;
  joint.plane_half_cone_angle = plane_half_cone;
  joint.twist_min_angle = twist_min;
  joint.twist_max_angle = twist_max;
  return joint;
}

// A hinge about X at `point` with limits and a position motor (2 Hz, critically
// damped, +-max_torque): an elbow or a knee.
HingeConstraintSettings MotorHinge(std::string name, std::size_t body1, std::size_t body2,
                                   Float3 point, float min, float max, float max_torque) {
  HingeConstraintSettings hinge;
  hinge.name = std::move(name);
  hinge.body1 = body1;
  hinge.body2 = body2;
  hinge.point1 = hinge.point2 = point;
  hinge.hinge_axis1 = hinge.hinge_axis2 = kX;
  hinge.normal_axis1 = hinge.normal_axis2 = {0, -1, 0};
  hinge.limits_min = min;
  hinge.limits_max = max;
  hinge.motor_state = MotorState::kPosition;
  hinge.motor.min_force_limit = -max_torque;
  hinge.motor.max_force_limit = max_torque;
  return hinge;
}

// An 11-body humanoid floating in space (gravity factor 0), 1.8 m tall:
// pelvis, chest and head on swing-twist joints (waist, neck), arms and legs
// on swing-twist shoulders and hips and position-motor hinges at the elbows
// and knees (reference_scene::kRagdollMotors).
Scene Ragdoll() {
  Scene scene;
  const std::size_t pelvis = scene.AddBody(Limb("pelvis", 10.0f, 0.3f, {0, 1.0f, 0}));
  const std::size_t chest = scene.AddBody(Limb("chest", 15.0f, 0.4f, {0, 1.35f, 0}));
  const std::size_t head = scene.AddBody(Limb("head", 5.0f, 0.25f, {0, 1.75f, 0}));
  scene.AddConstraint(Joint("waist", pelvis, chest, {0, 1.15f, 0}, kY, 0.4f, 0.4f, -0.3f, 0.3f));
  scene.AddConstraint(Joint("neck", chest, head, {0, 1.62f, 0}, kY, 0.5f, 0.5f, -0.6f, 0.6f));
  for (const float side : {-1.0f, 1.0f}) {
    const std::string s = side < 0 ? " left" : " right";
    const float arm_x = 0.22f * side, leg_x = 0.1f * side;
    const std::size_t upper_arm = scene.AddBody(Limb("upper arm" + s, 2.0f, 0.3f, {arm_x, 1.35f, 0}));
    const std::size_t lower_arm = scene.AddBody(Limb("lower arm" + s, 1.5f, 0.3f, {arm_x, 1.05f, 0}));
    const std::size_t upper_leg = scene.AddBody(Limb("upper leg" + s, 7.0f, 0.4f, {leg_x, 0.7f, 0}));
    const std::size_t lower_leg = scene.AddBody(Limb("lower leg" + s, 4.0f, 0.4f, {leg_x, 0.3f, 0}));
    scene.AddConstraint(Joint("shoulder" + s, chest, upper_arm, {arm_x, 1.5f, 0}, {0, -1, 0},
                              1.2f, 0.8f, -0.5f, 0.5f));
    scene.AddConstraint(MotorHinge("elbow" + s, upper_arm, lower_arm, {arm_x, 1.2f, 0}, -2.5f,
                                   0.0f, 30.0f));
    scene.AddConstraint(Joint("hip" + s, pelvis, upper_leg, {leg_x, 0.9f, 0}, {0, -1, 0}, 0.9f,
                              0.5f, -0.3f, 0.3f));
    scene.AddConstraint(MotorHinge("knee" + s, upper_leg, lower_leg, {leg_x, 0.5f, 0}, 0.0f,
                                   2.5f, 60.0f));
  }
  return scene;
}

// The cartpole's force: a hash of (seed, step), shared by every world of a
// step, then of the world; its top 24 bits are a float in [0, 1) without
// rounding, scaled to [-10, 10) N.
std::uint64_t StepKey(std::uint64_t seed, std::uint64_t step) {
  return SplitMix64(SplitMix64(seed) ^ step);
}
// The top 24 bits of the world's hash: a float in [0, 1) without rounding.
float UnitOf(std::uint64_t key, std::uint64_t world) {
  return float(SplitMix64(key ^ world) >> 40) * 0x1p-24f;
}
float ForceOf(std::uint64_t step_key, std::uint64_t world) {
  return -10.0f + 20.0f * UnitOf(step_key, world);
}

}  // namespace

Scene MakeChain(std::size_t links, float last_link_scale) {
  if (links == 0 || links > 4096) {
    throw std::invalid_argument("MakeChain: links must be 1 to 4096 (got " +
                                std::to_string(links) + ")");
  }
  // The last link's mass (1 kg) and smallest inertia (0.001 kg m^2) times the
  // scale stay normal floats, far from overflow.
  if (!(last_link_scale >= 1e-30f && last_link_scale <= 1e30f)) {
    throw std::invalid_argument("MakeChain: last_link_scale must be in [1e-30, 1e30] (got " +
                                std::to_string(last_link_scale) + ")");
  }
  return Chain(links, last_link_scale);
}

std::vector<std::string> ReferenceSceneIds() {
  std::vector<std::string> ids;
  for (const SceneEntry& entry : kScenes) ids.emplace_back(entry.id);
  return ids;
}

Scene MakeReferenceScene(std::string_view id) {
  switch (ParseId(id)) {
    case SceneId::kCartpole: return Cartpole();
    case SceneId::kChain16: return Chain(16, 1.0f);
    case SceneId::kChain16R100: return Chain(16, 100.0f);
    case SceneId::kChain16R1000: return Chain(16, 1000.0f);
    case SceneId::kChain64: return Chain(64, 1.0f);
    case SceneId::kRackPinion: return RackPinion();
    case SceneId::kGearTrain: return GearTrain();
    case SceneId::kRagdoll: return Ragdoll();
    case SceneId::kLinkage: return Linkage();
  }
  throw std::logic_error("MakeReferenceScene: unhandled scene id");
}

float CartpoleForce(std::uint64_t seed, std::uint64_t world, std::uint64_t step) {
  return ForceOf(StepKey(seed, step), world);
}

std::vector<std::string> AllSceneIds() {
  std::vector<std::string> ids = ReferenceSceneIds();
  for (const std::string& id : StressSceneIds()) {
    if (std::find(ids.begin(), ids.end(), id) == ids.end()) ids.push_back(id);
  }
  for (const std::string& id : ContactSceneIds()) ids.push_back(id);
  return ids;
}

Scene MakeScene(std::string_view id) {
  for (const std::string& reference : ReferenceSceneIds()) {
    if (reference == id) return MakeReferenceScene(id);
  }
  if (!scene_ids::ContactSceneDescription(id).empty()) return MakeContactScene(id);
  if (scene_ids::StressSceneDescription(id).empty()) scene_ids::ThrowUnknownScene(id);
  return MakeStressScene(id);
}

std::string SceneDescription(std::string_view id) {
  for (const SceneEntry& entry : kScenes) {
    if (entry.id == id) return std::string(entry.description);
  }
  const std::string_view contact = scene_ids::ContactSceneDescription(id);
  if (!contact.empty()) return std::string(contact);
  const std::string_view stress = scene_ids::StressSceneDescription(id);
  if (stress.empty()) scene_ids::ThrowUnknownScene(id);
  return std::string(stress);
}

void scene_ids::ThrowUnknownScene(std::string_view id) {
  const auto list = [](const std::vector<std::string>& ids) {
    std::string text;
    for (const std::string& one : ids) text += (text.empty() ? "" : ", ") + one;
    return text;
  };
  throw std::invalid_argument("unknown scene '" + std::string(id) +
                              "'; valid ids: reference scenes " + list(ReferenceSceneIds()) +
                              "; stress scenes " + list(StressSceneIds()) +
                              "; contact scenes " + list(ContactSceneIds()));
}

SceneActions::SceneActions(std::string_view id) {
  const auto stress = StressSceneIds();
  const auto references = ReferenceSceneIds();
  const bool stress_only = std::find(stress.begin(), stress.end(), id) != stress.end() &&
                           std::find(references.begin(), references.end(), id) ==
                               references.end();
  if (stress_only) return;  // no stress scene has an action
  if (!scene_ids::ContactSceneDescription(id).empty()) {
    // The walkers: a target anywhere within the limits for every hinge with
    // a position motor (the ragdoll's actions); the other contact scenes
    // have none.
    const Scene scene = MakeContactScene(id);
    for (std::size_t c = 0; c < scene.constraints().size(); ++c) {
      const auto* hinge = std::get_if<HingeConstraintSettings>(&scene.constraints()[c]);
      if (hinge != nullptr && hinge->motor_state == MotorState::kPosition) {
        targets_.push_back({c, hinge->limits_min, hinge->limits_max});
      }
    }
    return;
  }
  if (std::find(references.begin(), references.end(), id) == references.end()) {
    scene_ids::ThrowUnknownScene(id);
  }
  const SceneId scene = ParseId(id);
  if (scene == SceneId::kCartpole) {
    forces_per_world_ = 1;
    body_ = reference_scene::kCart;
  } else if (scene == SceneId::kRagdoll) {
    namespace rs = reference_scene;
    targets_ = {{rs::kLeftElbow, -2.5f, 0.0f},
                {rs::kLeftKnee, 0.0f, 2.5f},
                {rs::kRightElbow, -2.5f, 0.0f},
                {rs::kRightKnee, 0.0f, 2.5f}};
  }
}

MotorTarget SceneActions::Target(std::size_t i, std::uint64_t world, std::uint64_t step,
                                 std::uint64_t seed) const {
  if (i >= targets_.size()) {
    throw std::out_of_range("SceneActions::Target: index " + std::to_string(i) + " but " +
                            std::to_string(targets_.size()) + " target(s) per world");
  }
  const TargetRange& range = targets_[i];
  // A key per (seed, step, motor), then the world's uniform value in [0, 1).
  const float unit = UnitOf(SplitMix64(StepKey(seed, step) ^ (0xA5A5ull + i)), world);
  return MotorTarget{range.constraint, range.min + (range.max - range.min) * unit};
}

BodyForce SceneActions::Force(std::size_t i, std::uint64_t world, std::uint64_t step,
                              std::uint64_t seed) const {
  if (i >= forces_per_world_) {
    throw std::out_of_range("SceneActions::Force: index " + std::to_string(i) + " but " +
                            std::to_string(forces_per_world_) + " force(s) per world");
  }
  return BodyForce{body_, {CartpoleForce(seed, world, step), 0.0f, 0.0f}};
}

void SceneActions::Apply(Batch& batch, std::uint64_t step, std::uint64_t seed,
                         std::uint64_t first_world) const {
  const std::size_t worlds = batch.world_count();
  if (forces_per_world_ != 0) {
    const std::uint64_t key = StepKey(seed, step);
    std::vector<float> forces(worlds * 3, 0.0f);
    for (std::size_t world = 0; world < worlds; ++world) {
      forces[world * 3] = ForceOf(key, first_world + world);
    }
    batch.SetForces(body_, forces);
  }
  std::vector<float> targets(worlds);
  for (std::size_t i = 0; i < targets_.size(); ++i) {
    for (std::size_t world = 0; world < worlds; ++world) {
      targets[world] = Target(i, first_world + world, step, seed).position;
    }
    batch.SetTargetPositions(targets_[i].constraint, targets);
  }
}

void ApplyReferenceActions(std::string_view id, Batch& batch, std::uint64_t step,
                           std::uint64_t seed) {
  SceneActions(id).Apply(batch, step, seed);
}

}  // namespace manyworlds
