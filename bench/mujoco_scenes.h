// MuJoCo 2.2.2 models of three reference scenes (cartpole, chain16,
// rackpinion) and two contact scenes (hopper, quadruped; throughput only)
// for the side-by-side benchmark (bench/mujoco_bench.cc,
// docs/benchmarks.md), and the quantities both engines are compared on.
//
// The models follow docs/scenes.md body for body: same masses, inertias,
// COMs, joint anchors and axes, gravity (0, -9.81, 0) and dt 1/60 s, and the
// bodies are numbered as in MakeReferenceScene (0 = world, cartpole 1 cart
// 2 pole, chain16 link i = body i + 1, rackpinion 1 pinion 2 rack), so one
// observation function serves both engines. Where MuJoCo needs more than the
// spec (damping, an actuator gain, an integrator), the MJCF in
// mujoco_scenes.cc says what and why. The contact scenes' models follow
// batch/contact_scenes.cc geom for geom (capsules and a sphere of density
// 1000 from which MuJoCo computes the masses; CompareMujocoMasses checks
// them against ours), with position actuators for our position motors.
#pragma once

#include <mujoco/mujoco.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <numbers>
#include <string>
#include <string_view>
#include <vector>

namespace manyworlds::bench {

struct MujocoModelDeleter {
  void operator()(mjModel* model) const { mj_deleteModel(model); }
};
struct MujocoDataDeleter {
  void operator()(mjData* data) const { mj_deleteData(data); }
};
using MujocoModel = std::unique_ptr<mjModel, MujocoModelDeleter>;
using MujocoData = std::unique_ptr<mjData, MujocoDataDeleter>;

// The reference scenes with MuJoCo models: cartpole, chain16, rackpinion.
// Compared on throughput and accuracy.
std::vector<std::string> MujocoSceneIds();

// The contact scenes with MuJoCo models: hopper, quadruped (Y-up versions of
// MuJoCo's hopper and ant, batch/contact_scenes.cc). Throughput only: under
// random motor targets every step their motion is chaotic, so there is no
// SceneObservables for them. Their bodies are numbered as ours (0 = world or
// ground; hopper 1 torso 2 thigh 3 leg 4 foot; quadruped 1 torso, then per
// leg thigh and shin) and actuator i drives our constraint i's hinge.
std::vector<std::string> MujocoContactSceneIds();

// MujocoSceneIds() then MujocoContactSceneIds(): what is benchmarked.
std::vector<std::string> MujocoThroughputSceneIds();

// The MuJoCo models of scene `scene`: its own id, and for chain16
// also "chain16-hinge" (hinges about Z instead of ball joints: the spec's
// peer list names a hinge chain, and our chain16 released in the XY plane
// moves in that plane, so both MuJoCo models follow the same trajectory at
// very different cost).
std::vector<std::string> MujocoModelsOf(std::string_view scene);

enum class MujocoResolution {
  kBenchmark,  // dt 1/60 s, MuJoCo's default solver settings
  kFine,       // dt/16, solver tolerance 1e-12 and 400 iterations: the reference
};

// The MJCF text of model `id` (see MujocoModelsOf). Throws
// std::invalid_argument for another id.
std::string MujocoXml(std::string_view id, MujocoResolution resolution);

// Compiles MJCF text through MuJoCo's virtual file system (2.2.2 has no
// mj_loadXMLString). Throws std::runtime_error with MuJoCo's message.
MujocoModel LoadMujocoXml(const std::string& xml);

// A new mjData in the scene's initial state (keyframe 0 when the model has
// one, e.g. the cartpole's pole at 0.1 rad) with constant controls set.
// For hopper and quadruped it also checks that actuator i is named as, and
// moves the joint named as, our constraint i (std::logic_error if not).
MujocoData MakeMujocoData(std::string_view id, const mjModel* model);

// Sets the per-step action of world `world` for its next mj_step: cartpole, a
// force along X through the cart's COM (xfrc_applied), exactly
// CartpoleForce(seed, world, step); hopper and quadruped, every actuator's
// ctrl to our motor's position target, exactly
// SceneActions(id).Target(i, world, step, seed) (rad); other scenes none
// (their controls are constant, set by MakeMujocoData).
void ApplyMujocoAction(std::string_view id, const mjModel* model, mjData* data,
                       std::uint64_t world, std::uint64_t step, std::uint64_t seed);

// One body of a contact scene: our mass and principal inertias against the
// ones MuJoCo computed from the geoms (density 1000), inertias sorted.
struct MassComparison {
  std::string body;
  double mass_ours = 0, mass_mujoco = 0;
  double inertia_ours[3] = {0, 0, 0}, inertia_mujoco[3] = {0, 0, 0};
};

// Every moving body of contact scene `id` (one of MujocoContactSceneIds())
// in `model` (its MuJoCo model) against MakeContactScene(id).
std::vector<MassComparison> CompareMujocoMasses(std::string_view id, const mjModel* model);

// ------------------------------------------------------------- observables

// One compared quantity: `components` consecutive values of an observation
// vector; its error is the Euclidean norm of their differences (angles: the
// difference wrapped into (-pi, pi]).
struct Observable {
  std::string name;
  std::size_t components = 1;
  bool angle = false;
};

// Centre of mass (world) and orientation (x, y, z, w) of one body.
struct BodyPose {
  double position[3];
  double rotation[4];
};

// What is compared per scene (docs/benchmarks.md):
//   cartpole    cart x (m); pole angle about Z (rad)
//   chain16     COM of the last link (m, 3 components; also chain16-hinge)
//   rackpinion  rack x (m); pinion angle about Z (rad)
std::vector<Observable> SceneObservables(std::string_view id);

// Angle about Z of a rotation that is (nearly) about Z only.
inline double AngleAboutZ(const BodyPose& pose) {
  return 2.0 * std::atan2(pose.rotation[2], pose.rotation[3]);
}

// The values of SceneObservables(id), concatenated, from `pose(body)`.
template <class PoseOf>
std::vector<double> Observe(std::string_view id, PoseOf&& pose) {
  if (id == "cartpole") return {pose(1).position[0], AngleAboutZ(pose(2))};
  if (id == "rackpinion") return {pose(2).position[0], AngleAboutZ(pose(1))};
  const BodyPose last = pose(16);  // chain16
  return {last.position[0], last.position[1], last.position[2]};
}

// Squared error of each observable between two observation vectors.
inline std::vector<double> SquaredErrors(const std::vector<Observable>& observables,
                                         const std::vector<double>& a,
                                         const std::vector<double>& b) {
  std::vector<double> errors;
  std::size_t at = 0;
  for (const Observable& o : observables) {
    double sum = 0;
    for (std::size_t c = 0; c < o.components; ++c, ++at) {
      double d = a[at] - b[at];
      if (o.angle) d = std::remainder(d, 2.0 * std::numbers::pi);
      sum += d * d;
    }
    errors.push_back(sum);
  }
  return errors;
}

// The pose of body `body` in MuJoCo data whose kinematics are current (call
// mj_kinematics after mj_step: mj_step leaves xipos at the step's start).
BodyPose MujocoPose(const mjData* data, int body);

}  // namespace manyworlds::bench
