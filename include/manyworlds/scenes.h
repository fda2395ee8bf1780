// The reference scenes of the project's benchmarks and accuracy reports
// (docs/scenes.md), built exactly as the brief's scenes-and-metrics spec
// describes them, and their per-step actions.
//
//   Scene scene = MakeReferenceScene("cartpole");
//   Batch batch(scene, 4096);
//   const SceneActions actions("cartpole");
//   for (std::uint64_t step = 0; step < 1000; ++step) {
//     actions.Apply(batch, step, /*seed=*/1);  // a random force on every cart
//     batch.Step(StepSettings{});              // gravity, dt, iterations: spec defaults
//   }
//
// Units SI. Gravity, dt and iterations are step settings (StepSettings{} holds
// the spec's defaults); every body has damping 0 and Jolt's other defaults.
// An action depends only on (seed, world, step), never on the batch size,
// the thread count or the order in which worlds are visited, so a world of a
// batch and the same world stepped alone by the scalar reference see the
// same forces.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "manyworlds/batch.h"
#include "manyworlds/scene.h"

namespace manyworlds {

// cartpole, chain16, chain16-r100, chain16-r1000, chain64, rackpinion,
// geartrain, ragdoll, linkage, in that order.
std::vector<std::string> ReferenceSceneIds();

// The scene `id` (one of ReferenceSceneIds()). Throws std::invalid_argument
// naming the unknown id and listing the valid ones.
Scene MakeReferenceScene(std::string_view id);

// The chains of chain16, chain16-r100, chain16-r1000 and chain64 at any
// length and mass ratio: `links` rods 0.5 m long (1 kg) along X, released
// from horizontal, ball-jointed end to end and to the world at the origin,
// the last link's mass and inertia times `last_link_scale` (chain16-r100 is
// MakeChain(16, 100)). For mass-ratio studies (docs/accuracy.md). Throws
// std::invalid_argument naming `links` (0 or over 4096) or
// `last_link_scale` (outside [1e-30, 1e30], NaN).
Scene MakeChain(std::size_t links, float last_link_scale);

// The stress scenes of the spec (numerical stability, docs/scenes.md and
// docs/stability.md): chain16-r1000, chain64, spring-0.1, spring-0.25,
// spring-0.5, spring-1.0, spin-unstable, flywheel, singular-hinge-90,
// singular-hinge-180, singular-fixed-90, singular-fixed-180,
// singular-slider-90, singular-rackpinion, singular-cone,
// singular-swingtwist, dt-1e-4, dt-1/15, mass-range, mass-range-hanging,
// far-1e4. None has an action. Each is meant to be stepped with SceneStepSettings(id).
std::vector<std::string> StressSceneIds();

// The stress scene `id` (one of StressSceneIds(); chain16-r1000 and chain64
// are the reference scenes). Throws std::invalid_argument naming the unknown
// id and listing the valid ones.
Scene MakeStressScene(std::string_view id);

// The contact scenes (docs/scenes.md, docs/contacts.md): box-drop,
// sphere-roll, pile, hopper, quadruped. Shapes on a ground plane; the
// walkers (hopper, quadruped) take random motor targets (SceneActions), the
// others have no action.
std::vector<std::string> ContactSceneIds();
// The contact scene `id` (one of ContactSceneIds()). Throws
// std::invalid_argument naming the unknown id and listing the valid ones.
Scene MakeContactScene(std::string_view id);
// The step settings a reference or stress scene is run with: StepSettings{}
// (the spec's defaults) for every scene except dt-1e-4 (delta_time 1e-4 s)
// and dt-1/15 (1/15 s). Throws std::invalid_argument for an unknown id, as
// MakeScene.
StepSettings SceneStepSettings(std::string_view id);

// Every scene id, reference then stress then contact (each once), and the
// scene of any of them (MakeReferenceScene, MakeStressScene or
// MakeContactScene): what the main program, the benchmarks and the accuracy
// sweep accept. Throws std::invalid_argument for an unknown id: "unknown
// scene 'ID'; valid ids: reference scenes cartpole, ...; stress scenes
// chain16-r1000, ...; contact scenes box-drop, ...", every id grouped.
std::vector<std::string> AllSceneIds();
Scene MakeScene(std::string_view id);

// What scene `id` (any of AllSceneIds()) is there to test, in a short phrase
// for listings (`manyworlds scenes`, Python, docs; docs/scenes.md has the
// full specification). Throws std::invalid_argument for an unknown id, as
// MakeScene.
std::string SceneDescription(std::string_view id);

// A force (N, world space, through the centre of mass) on one body of one
// world, acting during the next step.
struct BodyForce {
  std::size_t body = 0;
  Float3 force{0, 0, 0};
};

// A motor's position target (hinge: rad) for one constraint of one world,
// for the next step.
struct MotorTarget {
  std::size_t constraint = 0;
  float position = 0.0f;
};

// The action of a reference scene each step, drawn per (seed, world, step)
// by a splitmix64 hash. cartpole: a force on the cart along X, uniform in
// [-10, 10) N. ragdoll: a position target for every elbow and knee motor,
// uniform in the hinge's limits. Every other scene (stress scenes too): no
// action.
class SceneActions {
 public:
  // Throws std::invalid_argument for an unknown id, as MakeScene.
  explicit SceneActions(std::string_view id);

  bool empty() const { return forces_per_world_ == 0 && targets_.empty(); }
  std::size_t forces_per_world() const { return forces_per_world_; }
  std::size_t targets_per_world() const { return targets_.size(); }

  // The i-th force (i < forces_per_world()) of world `world` at `step`.
  BodyForce Force(std::size_t i, std::uint64_t world, std::uint64_t step,
                  std::uint64_t seed) const;

  // The i-th motor target (i < targets_per_world()) of world `world` at `step`.
  MotorTarget Target(std::size_t i, std::uint64_t world, std::uint64_t step,
                     std::uint64_t seed) const;

  // Sets the forces and targets of every world of the batch for its next Step.
  // Local world i gets the actions of world first_world + i: a shard of a
  // larger batch (ShardedBatch, docs/scale-out.md) passes its first global
  // world, so that every world sees the same actions whatever the sharding.
  void Apply(Batch& batch, std::uint64_t step, std::uint64_t seed,
             std::uint64_t first_world = 0) const;

  // The same forces for world `world_index`, given to one world of a scalar
  // stepper with SetForce(body, Vec3) and body(i).position of that Vec3 type
  // (reference::World<float> or <double>).
  template <class World>
  void ApplyTo(World& world, std::uint64_t world_index, std::uint64_t step,
               std::uint64_t seed) const {
    using Vec = std::decay_t<decltype(world.body(0).position)>;
    using Scalar = typename Vec::Scalar;
    for (std::size_t i = 0; i < forces_per_world_; ++i) {
      const BodyForce f = Force(i, world_index, step, seed);
      world.SetForce(f.body, Vec(Scalar(f.force[0]), Scalar(f.force[1]), Scalar(f.force[2])));
    }
    for (std::size_t i = 0; i < targets_.size(); ++i) {
      const MotorTarget t = Target(i, world_index, step, seed);
      world.SetTargetPosition(t.constraint, Scalar(t.position));
    }
  }

 private:
  // A motor driven by the actions: its constraint and target range.
  struct TargetRange {
    std::size_t constraint;
    float min, max;
  };
  std::size_t forces_per_world_ = 0;
  std::size_t body_ = 0;
  std::vector<TargetRange> targets_;
};

// SceneActions(id).Apply(batch, step, seed).
void ApplyReferenceActions(std::string_view id, Batch& batch, std::uint64_t step,
                           std::uint64_t seed);

// The cartpole's cart force along X (N) of world `world` at `step`: uniform in
// [-10, 10), a function of (seed, world, step) only.
float CartpoleForce(std::uint64_t seed, std::uint64_t world, std::uint64_t step);

// Body and constraint indices of the reference scenes, for tests and tools.
namespace reference_scene {
inline constexpr std::size_t kWorld = 0;  // the static world body of every scene
// cartpole
inline constexpr std::size_t kCart = 1, kPole = 2;
inline constexpr std::size_t kRail = 0, kPoleHinge = 1;
// chain*: link i is body i + 1; constraint i joins body i and body i + 1.
// rackpinion
inline constexpr std::size_t kPinion = 1, kRack = 2;
inline constexpr std::size_t kPinionHinge = 0, kRackSlider = 1, kRackAndPinion = 2;
// geartrain
inline constexpr std::size_t kGear1 = 1, kGear2 = 2;
inline constexpr std::size_t kGear1Hinge = 0, kGear2Hinge = 1, kGear = 2;
// ragdoll: bodies pelvis 0, chest 1, head 2, then per side (left, right)
// upper arm, lower arm, upper leg, lower leg; constraints waist 0, neck 1,
// then per side shoulder, elbow, hip, knee.
inline constexpr std::size_t kPelvis = 0;
inline constexpr std::size_t kLeftElbow = 3, kLeftKnee = 5, kRightElbow = 7, kRightKnee = 9;
// linkage
inline constexpr std::size_t kCrank = 1, kCoupler = 2, kRocker = 3, kFlywheel = 4;
inline constexpr std::size_t kCrankHinge = 0, kCrankCoupler = 1, kCouplerRocker = 2,
                             kRockerHinge = 3, kFlywheelHinge = 4, kFlywheelGear = 5;
}  // namespace reference_scene

// Body and constraint indices of the stress scenes.
namespace stress_scene {
// spring-*, spin-unstable, flywheel, singular-*: the one moving body (for
// singular-rackpinion the pinion; the rack is body 2), held by constraint 0
// (for singular-rackpinion: pinion hinge 0, rack slider 1, coupling 2).
inline constexpr std::size_t kBody = 1;
inline constexpr std::size_t kRack = 2;
// spring-*: the sphere starts this far along X from the anchor at the origin
// (m), at rest; damping ratio 0.
inline constexpr float kSpringStart = 1.0f;
// spin-unstable: |w| (rad/s) and the tilt of w from the middle axis Y
// towards X (rad) that seeds the flip.
inline constexpr float kSpinRate = 40.0f, kSpinTilt = 0.01f;
// far-1e4: every body and anchor of chain16 shifted by this much on each axis (m).
inline constexpr float kFarOffset = 1.0e4f;
// mass-range: link i (from the anchor) has mass 10^(6 - i) kg;
// mass-range-hanging: 10^(i - 3) kg; i = 0..kMassRangeLinks-1.
inline constexpr std::size_t kMassRangeLinks = 10;
}  // namespace stress_scene

}  // namespace manyworlds
