// MJCF of the reference scenes for MuJoCo 2.2.2, loaded through its VFS.
// Written from docs/scenes.md and MuJoCo's MJCF documentation.

#include "bench/mujoco_scenes.h"

#include <cstdio>
#include <cstring>
#include <stdexcept>

#include "manyworlds/scenes.h"

namespace manyworlds::bench {
namespace {

constexpr double kDt = 1.0 / 60.0;
constexpr int kFineSubsteps = 16;

std::string Number(double value) {
  char text[40];
  std::snprintf(text, sizeof text, "%.17g", value);
  return text;
}

// <option>: Y-up gravity as in the spec. The benchmark model keeps MuJoCo's
// default solver (Newton, 100 iterations, tolerance 1e-8); the fine
// reference gets dt/16 and a much tighter solve, so that what remains of its
// error is small against the benchmark model's.
std::string Option(MujocoResolution resolution, const char* integrator) {
  const bool fine = resolution == MujocoResolution::kFine;
  return std::string("<option timestep='") + Number(fine ? kDt / kFineSubsteps : kDt) +
         "' gravity='0 -9.81 0' integrator='" + integrator + "' solver='Newton' iterations='" +
         (fine ? "400" : "100") + "' tolerance='" + (fine ? "1e-12" : "1e-8") + "'/>";
}

// Slide joint cart + hinge pole. Joints in generalised coordinates are exact,
// so nothing needs damping; the semi-implicit Euler integrator (MuJoCo's
// default, like Jolt's) is stable here. The pole starts at 0.1 rad through
// the keyframe (hinge qpos = the pole's angle from upright, as in our hinge).
std::string CartpoleXml(MujocoResolution resolution) {
  return "<mujoco model='cartpole'>" + Option(resolution, "Euler") +
         "<worldbody>"
         "<body name='cart' pos='0 0 0'>"
         "<joint name='rail' type='slide' axis='1 0 0'/>"
         "<inertial pos='0 0 0' mass='1' diaginertia='0.1 0.1 0.1'/>"
         "<body name='pole' pos='0 0 0'>"
         "<joint name='pole hinge' type='hinge' axis='0 0 1'/>"
         "<inertial pos='0 0.5 0' mass='0.1' diaginertia='0.0084 0.0001 0.0084'/>"
         "</body></body></worldbody>"
         "<keyframe><key qpos='0 0.1'/></keyframe>"
         "</mujoco>";
}

// 16 links nested as a kinematic tree, each hanging from a ball joint at its
// start (the world origin for link 0, the previous link's end otherwise),
// released from horizontal. Undamped, this chain gains energy and blows up
// within 2-7 s at dt 1/60 with every MuJoCo integrator (Euler 2.1 s,
// implicit 5.4 s, RK4 6.4 s). Checked on this build machine over 10 s:
//   Euler:    unstable with damping up to 1 N m s/rad or armature up to
//             0.5 kg m^2; stable from damping 2 or armature 1 (heavy: damping
//             2 drains most of the chain's energy in 10 s);
//   implicit: unstable with damping 0.01 and 0.02, stable with 0.05 and 0.1
//             (also over 60 s).
// So: ball joints (as ours), integrator 'implicit' (implicit in velocity,
// which also treats the Coriolis terms implicitly) and joint damping
// 0.1 N m s/rad, twice the smallest stable value found, for
// margin. Our chain16 has no
// damping; the trajectories therefore differ from ours by design, and each
// engine is compared only with its own fine reference.
//
// chain16-hinge: the same with hinges about Z (16 DOFs instead of 48). The
// same damping and integrator are needed (implicit: unstable undamped and
// with 0.02, stable with 0.05 and 0.1 over 60 s; Euler unstable up to 0.1),
// and since the motion is planar it follows the ball chain's trajectory.
std::string Chain16Xml(MujocoResolution resolution, bool hinge) {
  std::string xml = std::string("<mujoco model='") + (hinge ? "chain16-hinge" : "chain16") +
                    "'>" + Option(resolution, "implicit") + "<worldbody>";
  const char* joint = hinge ? "<joint type='hinge' axis='0 0 1' damping='0.1'/>"
                            : "<joint type='ball' damping='0.1'/>";
  for (int i = 0; i < 16; ++i) {
    xml += std::string("<body name='link") + std::to_string(i) + "' pos='" +
           (i == 0 ? "0" : "0.5") + " 0 0'>" + joint +
           "<inertial pos='0.25 0 0' mass='1' diaginertia='0.001 0.0208 0.0208'/>";
  }
  for (int i = 0; i < 16; ++i) xml += "</body>";
  return xml + "</worldbody></mujoco>";
}

// Pinion on a hinge about Z at (0, 0.1, 0), rack on a slide joint along X,
// coupled by a joint equality: rack = 0.1 * pinion angle (polycoef a1 = 0.1,
// i.e. theta - 10 d = 0 as in ours), MuJoCo's default soft constraint
// (solref 0.02 1, solimp defaults). Jolt's velocity motor (2 rad/s, |torque|
// <= 5 N m) is a velocity actuator with ctrl 2, forcerange +-5 and gain
// kv = 1.5 N m s/rad = the coupled inertia about the hinge (0.005 + 2 * 0.1^2
// = 0.025 kg m^2) / dt; with the Euler integrator any such gain rings (the
// pinion speed oscillates between -7 and 9 rad/s), so 'implicit', which
// integrates the actuator's velocity gain implicitly: the pinion reaches
// 1.53 rad/s after one step and 1.99 rad/s after 1 s. Jolt's motor, a hard
// velocity constraint, reaches 2 rad/s in the first step.
std::string RackPinionXml(MujocoResolution resolution) {
  return "<mujoco model='rackpinion'>" + Option(resolution, "implicit") +
         "<worldbody>"
         "<body name='pinion' pos='0 0.1 0'>"
         "<joint name='pinion hinge' type='hinge' axis='0 0 1'/>"
         "<inertial pos='0 0 0' mass='1' diaginertia='0.005 0.005 0.005'/>"
         "</body>"
         "<body name='rack' pos='0 0 0'>"
         "<joint name='rack slider' type='slide' axis='1 0 0'/>"
         "<inertial pos='0 0 0' mass='2' diaginertia='0.01 0.1 0.1'/>"
         "</body></worldbody>"
         "<equality><joint joint1='rack slider' joint2='pinion hinge' "
         "polycoef='0 0.1 0 0 0'/></equality>"
         "<actuator><velocity name='pinion motor' joint='pinion hinge' kv='1.5' "
         "ctrllimited='false' forcelimited='true' forcerange='-5 5'/></actuator>"
         "</mujoco>";
}

}  // namespace

std::vector<std::string> MujocoSceneIds() { return {"cartpole", "chain16", "rackpinion"}; }

std::vector<std::string> MujocoModelsOf(std::string_view scene) {
  if (scene == "chain16") return {"chain16", "chain16-hinge"};
  return {std::string(scene)};
}

std::string MujocoXml(std::string_view id, MujocoResolution resolution) {
  if (id == "cartpole") return CartpoleXml(resolution);
  if (id == "chain16") return Chain16Xml(resolution, false);
  if (id == "chain16-hinge") return Chain16Xml(resolution, true);
  if (id == "rackpinion") return RackPinionXml(resolution);
  throw std::invalid_argument("no MuJoCo model of scene '" + std::string(id) +
                              "' (cartpole, chain16, chain16-hinge, rackpinion)");
}

MujocoModel LoadMujocoXml(const std::string& xml) {
  // mjVFS holds fixed arrays of file names (~2 MB): too big for the stack.
  const auto vfs = std::make_unique<mjVFS>();
  mj_defaultVFS(vfs.get());
  const char* name = "scene.xml";
  if (mj_makeEmptyFileVFS(vfs.get(), name, int(xml.size())) != 0) {
    throw std::runtime_error("MuJoCo VFS: cannot make a file of " + std::to_string(xml.size()) +
                             " bytes");
  }
  const int file = mj_findFileVFS(vfs.get(), name);
  std::memcpy(vfs->filedata[file], xml.data(), xml.size());
  char error[1024] = "";
  mjModel* model = mj_loadXML(name, vfs.get(), error, sizeof error);
  mj_deleteVFS(vfs.get());
  if (model == nullptr) throw std::runtime_error(std::string("MuJoCo mj_loadXML: ") + error);
  return MujocoModel(model);
}

MujocoData MakeMujocoData(std::string_view id, const mjModel* model) {
  MujocoData data(mj_makeData(model));
  if (!data) throw std::runtime_error("MuJoCo mj_makeData failed");
  if (model->nkey > 0) {
    mj_resetDataKeyframe(model, data.get(), 0);
  } else {
    mj_resetData(model, data.get());
  }
  if (id == "rackpinion") data->ctrl[0] = 2.0;  // motor target, rad/s
  return data;
}

void ApplyMujocoAction(std::string_view id, const mjModel* /*model*/, mjData* data,
                       std::uint64_t world, std::uint64_t step, std::uint64_t seed) {
  if (id == "cartpole") {
    // Body 1 is the cart; xfrc_applied is (force, torque) at the COM, world frame.
    data->xfrc_applied[6 * 1 + 0] = double(CartpoleForce(seed, world, step));
  }
}

std::vector<Observable> SceneObservables(std::string_view id) {
  if (id == "cartpole") return {{"cart x (m)", 1, false}, {"pole angle (rad)", 1, true}};
  if (id == "rackpinion") return {{"rack x (m)", 1, false}, {"pinion angle (rad)", 1, true}};
  if (id == "chain16" || id == "chain16-hinge") return {{"last link COM (m)", 3, false}};
  throw std::invalid_argument("no observables for scene '" + std::string(id) + "'");
}

BodyPose MujocoPose(const mjData* data, int body) {
  BodyPose pose{};
  for (int i = 0; i < 3; ++i) pose.position[i] = data->xipos[3 * body + i];
  // MuJoCo stores w, x, y, z.
  const mjtNum* q = data->xquat + 4 * body;
  pose.rotation[0] = q[1];
  pose.rotation[1] = q[2];
  pose.rotation[2] = q[3];
  pose.rotation[3] = q[0];
  return pose;
}

}  // namespace manyworlds::bench
