// MJCF of the reference scenes for MuJoCo 2.2.2, loaded through its VFS.
// Written from docs/scenes.md and MuJoCo's MJCF documentation.

#include "bench/mujoco_scenes.h"

#include <algorithm>
#include <array>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <variant>

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

// ------------------------------------------------------------ contact scenes
//
// hopper and quadruped (batch/contact_scenes.cc), for throughput only. Body
// frames are not turned, so every axis below is a world axis; positions are
// written in world coordinates at the initial pose and made relative to the
// body's frame (its parent's frame plus `pos`) by Local.

using Vec3 = std::array<double, 3>;

std::string Triple(const Vec3& v) {
  return Number(v[0]) + " " + Number(v[1]) + " " + Number(v[2]);
}

Vec3 Local(const Vec3& world, const Vec3& frame) {
  return {world[0] - frame[0], world[1] - frame[1], world[2] - frame[2]};
}

// A capsule geom of density 1000 (the default below) by its core segment.
std::string CapsuleGeom(const std::string& name, const Vec3& from, const Vec3& to, double radius,
                        const Vec3& frame) {
  return "<geom name='" + name + "' type='capsule' fromto='" + Triple(Local(from, frame)) + " " +
         Triple(Local(to, frame)) + "' size='" + Number(radius) + "'/>";
}

// Our motor's spring on constraint `c`, in absolute units. Our position
// motor is Jolt's: a soft angle constraint whose spring is given as a
// frequency f (8 Hz) and damping ratio zeta (1), turned into a stiffness
// k = m (2 pi f)^2 and a damping c = 2 m zeta (2 pi f) with m the angle
// row's effective mass, 1 / (a . (I1^-1 + I2^-1) a): the two bodies' own
// inverse inertias about the hinge axis a (kernels/spring-inl.h). Ours
// recomputes m every step, but a hinge's axis is fixed in both bodies, so m
// stays what it is at the initial pose, computed here.
struct MotorSpring {
  double stiffness = 0;  // N m / rad
  double damping = 0;    // N m s / rad
};

Vec3 Rotate(const Quaternion& q, const Vec3& v) {  // q = (x, y, z, w)
  const double x = q[0], y = q[1], z = q[2], w = q[3];
  // v + 2 w (u x v) + 2 u x (u x v), u = (x, y, z)
  const Vec3 t{2 * (y * v[2] - z * v[1]), 2 * (z * v[0] - x * v[2]), 2 * (x * v[1] - y * v[0])};
  return {v[0] + w * t[0] + (y * t[2] - z * t[1]), v[1] + w * t[1] + (z * t[0] - x * t[2]),
          v[2] + w * t[2] + (x * t[1] - y * t[0])};
}

Quaternion Conjugate(const Quaternion& q) { return {-q[0], -q[1], -q[2], q[3]}; }

// a . I^-1 a for body `body` of the scene at its initial pose.
double InverseInertiaAbout(const BodySettings& body, const Vec3& axis) {
  // Into the principal frame: the body's rotation, then the inertia's.
  const Vec3 a = Rotate(Conjugate(body.inertia_rotation),
                        Rotate(Conjugate(body.rotation), axis));
  double sum = 0;
  for (int k = 0; k < 3; ++k) sum += a[k] * a[k] / double(body.inertia_diagonal[k]);
  return sum;
}

MotorSpring OurMotorSpring(const Scene& scene, std::size_t c) {
  const auto& hinge = std::get<HingeConstraintSettings>(scene.constraints()[c]);
  const Vec3 axis{hinge.hinge_axis1[0], hinge.hinge_axis1[1], hinge.hinge_axis1[2]};
  const double mass = 1.0 / (InverseInertiaAbout(scene.bodies()[hinge.body1], axis) +
                             InverseInertiaAbout(scene.bodies()[hinge.body2], axis));
  const double omega = 2.0 * std::numbers::pi * double(hinge.motor.spring.frequency_or_stiffness);
  return {mass * omega * omega, 2.0 * mass * double(hinge.motor.spring.damping) * omega};
}

// The walkers' models share this: Y up, dt 1/60 s, geoms of density 1000
// with friction 1 (MuJoCo's default; a contact takes the larger of its two
// geoms' frictions, and condim 3 uses only the sliding one), the ground as
// the only thing a limb touches: limbs contype 0 conaffinity 1, the ground
// contype 1 conaffinity 0 (two geoms collide when contype1 & conaffinity2
// or contype2 & conaffinity1), as ours (limbs in group 2, mask 1).
// Contacts, joint limits and solver are MuJoCo's defaults: soft
// constraints (solref 0.02 1, which MuJoCo raises to a time constant of
// 2 dt = 0.033 s at this step; solimp 0.9 0.95 0.001), pyramidal friction
// cones, Newton; ours are hard (Jolt's contacts and limits, Baumgarte).
//
// Motors: MuJoCo 2.2.2's position actuator is a pure spring, kp (ctrl -
// qpos), clipped to forcerange; its damping must come from the joint. Our
// motor is specified by a frequency, not a stiffness: its k depends on the
// two bodies' inertias, so no one kp fits all joints. Each actuator gets
// kp = our motor's k and its joint damping = our motor's c
// (OurMotorSpring), so both engines apply the same spring-damper law between
// the same two bodies: kp 100, 103, 108 N m/rad and damping 4.0, 4.1,
// 4.3 N m s/rad (hopper thigh, leg, foot); kp 281 (hips) and 247 N m/rad
// (knees), damping 11.2 and 9.8 N m s/rad (quadruped). What still differs:
// ours clips spring and damping together to +-200 / +-150 N m and solves
// them implicitly, inside the iterative constraint solve; MuJoCo clips only
// the spring, integrates it explicitly and the joint damping implicitly
// (below), and joint damping is not clipped. No armature (Gymnasium's
// hopper and ant use armature 1 and damping 1, which here would be 10-25x
// the limbs' own inertias). The hopper's root joints, the quadruped's free
// joint: undamped, as ours.
//
// Integrator: 'Euler', MuJoCo's default (and Gymnasium's hopper's and ant's):
// semi-implicit, and in 2.2.2 already implicit in the joint damping
// ((M + dt B) qacc = f), which is what the stiff motor needs; 'implicit'
// adds only the velocity derivatives of the other forces, at 1.5-1.8x the
// cost here. Checked on this machine, 64 worlds under the random
// targets for 60 s (3600 steps), no armature, damping as a fraction of the
// above:
//   hopper:    Euler and implicit unstable undamped (MuJoCo warns "Nan,
//              Inf or huge value in QACC" within 0.4-4 s); Euler unstable
//              at 0.25, stable at 0.5, 1 and 2 (1: also 64 worlds x 10000
//              steps, 1024 x 3600, 4096 x 600);
//   quadruped: stable with Euler and implicit from 0 (undamped) to 2
//              (1: also 64 x 10000, 512 x 3600).
// Contacts are soft: at this step the hopper's deepest contact is about 1 cm
// on average and up to 15 cm at hard landings, the quadruped's 1 cm and up
// to 7 cm. In both engines the quadruped's torso ends up resting on the
// ground (the random targets do not make it stand) and the hopper falls.
std::string WalkerHeader(const char* model, MujocoResolution resolution) {
  return std::string("<mujoco model='") + model + "'><compiler angle='radian'/>" +
         Option(resolution, "Euler") +
         "<default><geom density='1000' friction='1 0.005 0.0001' condim='3' contype='0' "
         "conaffinity='1'/></default>"
         "<worldbody><geom name='ground' type='plane' size='50 50 1' zaxis='0 1 0' "
         "contype='1' conaffinity='0'/>";
}

// A limited hinge at world point `point` about `axis`, damped as our motor
// on constraint `c`.
std::string MotorJoint(const Scene& scene, std::size_t c, const Vec3& point, const Vec3& axis,
                       const Vec3& frame) {
  const auto& hinge = std::get<HingeConstraintSettings>(scene.constraints()[c]);
  return "<joint name='" + hinge.name + "' type='hinge' pos='" + Triple(Local(point, frame)) +
         "' axis='" + Triple(axis) + "' limited='true' range='" + Number(hinge.limits_min) + " " +
         Number(hinge.limits_max) + "' damping='" + Number(OurMotorSpring(scene, c).damping) +
         "'/>";
}

// One position actuator per motor, in constraint order (actuator i drives
// constraint i's hinge; MakeMujocoData checks it).
std::string MotorActuators(const Scene& scene) {
  std::string xml = "<actuator>";
  for (std::size_t c = 0; c < scene.constraints().size(); ++c) {
    const auto& hinge = std::get<HingeConstraintSettings>(scene.constraints()[c]);
    xml += "<position name='" + hinge.name + "' joint='" + hinge.name + "' kp='" +
           Number(OurMotorSpring(scene, c).stiffness) +
           "' ctrllimited='false' forcelimited='true' forcerange='" +
           Number(hinge.motor.min_force_limit) + " " + Number(hinge.motor.max_force_limit) +
           "'/>";
  }
  return xml + "</actuator>";
}

// MuJoCo's hopper as ours (contact_scenes.cc), Y up: torso 1.45 -> 1.05 m
// (r 0.05), thigh 1.05 -> 0.6 (0.05), leg 0.6 -> 0.1 (0.04), foot from
// x -0.13 to 0.26 at 0.1 (0.06), hinges about Z at 1.05, 0.6 and 0.1 m
// (thigh and leg [-150, 0] deg, foot [-45, 45] deg). The torso moves in the
// XY plane: slide X, slide Y and a hinge about Z through its centre of mass
// (1.25 m; Gymnasium's rootx, rootz, rooty), as our torso's allowed DOFs.
std::string HopperXml(MujocoResolution resolution) {
  const Scene scene = MakeContactScene("hopper");
  const Vec3 z{0, 0, 1};
  const Vec3 torso{0, 1.25, 0};
  return WalkerHeader("hopper", resolution) + "<body name='torso' pos='" + Triple(torso) +
         "'>"
         "<joint name='rootx' type='slide' axis='1 0 0'/>"
         "<joint name='rooty' type='slide' axis='0 1 0'/>"
         "<joint name='rootz' type='hinge' axis='0 0 1'/>" +
         CapsuleGeom("torso", {0, 1.45, 0}, {0, 1.05, 0}, 0.05, torso) +
         "<body name='thigh'>" + MotorJoint(scene, 0, {0, 1.05, 0}, z, torso) +
         CapsuleGeom("thigh", {0, 1.05, 0}, {0, 0.6, 0}, 0.05, torso) +
         "<body name='leg'>" + MotorJoint(scene, 1, {0, 0.6, 0}, z, torso) +
         CapsuleGeom("leg", {0, 0.6, 0}, {0, 0.1, 0}, 0.04, torso) +
         "<body name='foot'>" + MotorJoint(scene, 2, {0, 0.1, 0}, z, torso) +
         CapsuleGeom("foot", {-0.13, 0.1, 0}, {0.26, 0.1, 0}, 0.06, torso) +
         "</body></body></body></body></worldbody>" + MotorActuators(scene) + "</mujoco>";
}

// After MuJoCo's ant, as ours: a free ball torso (r 0.25) 0.75 m up, four
// legs along the ground's diagonals (x, z) = (+-1, +-1)/sqrt(2), each a
// thigh capsule 0.28 -> 0.57 m out (r 0.08) on a hip hinge about Y at 0.28
// ([-30, 30] deg) and a shin capsule from the knee 0.4 m out and 0.4 m down
// (r 0.08) on a knee hinge about (-z, 0, x) ([-40, 40] deg).
std::string QuadrupedXml(MujocoResolution resolution) {
  const Scene scene = MakeContactScene("quadruped");
  const Vec3 torso{0, 0.75, 0};
  std::string xml = WalkerHeader("quadruped", resolution) + "<body name='torso' pos='" +
                    Triple(torso) + "'><freejoint name='root'/>" +
                    "<geom name='torso' type='sphere' size='0.25'/>";
  const double directions[4][2] = {{1, 1}, {-1, 1}, {-1, -1}, {1, -1}};
  for (std::size_t i = 0; i < 4; ++i) {
    const double dx = directions[i][0] / std::sqrt(2.0), dz = directions[i][1] / std::sqrt(2.0);
    const auto out = [&](double distance) {
      return Vec3{distance * dx, torso[1], distance * dz};
    };
    const Vec3 knee = out(0.57);
    const Vec3 foot{knee[0] + 0.4 * dx, knee[1] - 0.4, knee[2] + 0.4 * dz};
    const std::string leg = std::to_string(i);
    xml += "<body name='thigh " + leg + "'>" +
           MotorJoint(scene, 2 * i, out(0.28), {0, 1, 0}, torso) +
           CapsuleGeom("thigh " + leg, out(0.28), knee, 0.08, torso) + "<body name='shin " +
           leg + "'>" + MotorJoint(scene, 2 * i + 1, knee, {-dz, 0, dx}, torso) +
           CapsuleGeom("shin " + leg, knee, foot, 0.08, torso) + "</body></body>";
  }
  return xml + "</body></worldbody>" + MotorActuators(scene) + "</mujoco>";
}

bool IsContactModel(std::string_view id) { return id == "hopper" || id == "quadruped"; }

// The scene's actions, built once per id (SceneActions builds the scene).
const SceneActions& ContactActions(std::string_view id) {
  static const SceneActions hopper("hopper");
  static const SceneActions quadruped("quadruped");
  return id == "hopper" ? hopper : quadruped;
}

}  // namespace

std::vector<std::string> MujocoSceneIds() { return {"cartpole", "chain16", "rackpinion"}; }

std::vector<std::string> MujocoContactSceneIds() { return {"hopper", "quadruped"}; }

std::vector<std::string> MujocoThroughputSceneIds() {
  std::vector<std::string> ids = MujocoSceneIds();
  for (const std::string& id : MujocoContactSceneIds()) ids.push_back(id);
  return ids;
}

std::vector<std::string> MujocoModelsOf(std::string_view scene) {
  if (scene == "chain16") return {"chain16", "chain16-hinge"};
  return {std::string(scene)};
}

std::string MujocoXml(std::string_view id, MujocoResolution resolution) {
  if (id == "cartpole") return CartpoleXml(resolution);
  if (id == "chain16") return Chain16Xml(resolution, false);
  if (id == "chain16-hinge") return Chain16Xml(resolution, true);
  if (id == "rackpinion") return RackPinionXml(resolution);
  if (id == "hopper") return HopperXml(resolution);
  if (id == "quadruped") return QuadrupedXml(resolution);
  throw std::invalid_argument("no MuJoCo model of scene '" + std::string(id) +
                              "' (cartpole, chain16, chain16-hinge, rackpinion, hopper, "
                              "quadruped)");
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
  if (IsContactModel(id)) {
    // ApplyMujocoAction writes ctrl[constraint]: actuator i must drive
    // constraint i's hinge, and every target must have its actuator.
    const Scene scene = MakeContactScene(id);
    const SceneActions& actions = ContactActions(id);
    bool same = std::size_t(model->nu) == scene.constraints().size();
    for (std::size_t i = 0; same && i < actions.targets_per_world(); ++i) {
      const std::size_t c = actions.Target(i, 0, 0, 0).constraint;
      const auto& hinge = std::get<HingeConstraintSettings>(scene.constraints()[c]);
      const char* actuator = mj_id2name(model, mjOBJ_ACTUATOR, int(c));
      const char* joint = mj_id2name(model, mjOBJ_JOINT, model->actuator_trnid[2 * c]);
      same = actuator != nullptr && joint != nullptr && hinge.name == actuator &&
             hinge.name == joint;
    }
    if (!same) {
      throw std::logic_error("MuJoCo model " + std::string(id) +
                             ": actuators are not in the order of our motors");
    }
  }
  return data;
}

void ApplyMujocoAction(std::string_view id, const mjModel* /*model*/, mjData* data,
                       std::uint64_t world, std::uint64_t step, std::uint64_t seed) {
  if (id == "cartpole") {
    // Body 1 is the cart; xfrc_applied is (force, torque) at the COM, world frame.
    data->xfrc_applied[6 * 1 + 0] = double(CartpoleForce(seed, world, step));
  } else if (IsContactModel(id)) {
    // Target i is the position target of constraint t.constraint's hinge,
    // which actuator t.constraint drives (checked by MakeMujocoData).
    const SceneActions& actions = ContactActions(id);
    for (std::size_t i = 0; i < actions.targets_per_world(); ++i) {
      const MotorTarget t = actions.Target(i, world, step, seed);
      data->ctrl[t.constraint] = double(t.position);
    }
  }
}

std::vector<MassComparison> CompareMujocoMasses(std::string_view id, const mjModel* model) {
  const Scene scene = MakeContactScene(id);
  if (std::size_t(model->nbody) != scene.bodies().size()) {
    throw std::logic_error("MuJoCo model " + std::string(id) + " has " +
                           std::to_string(model->nbody) + " bodies, ours " +
                           std::to_string(scene.bodies().size()));
  }
  std::vector<MassComparison> rows;
  for (std::size_t b = 1; b < scene.bodies().size(); ++b) {
    const BodySettings& ours = scene.bodies()[b];
    MassComparison row;
    row.body = ours.name;
    row.mass_ours = ours.mass;
    row.mass_mujoco = model->body_mass[b];
    for (int k = 0; k < 3; ++k) {
      row.inertia_ours[k] = ours.inertia_diagonal[std::size_t(k)];
      row.inertia_mujoco[k] = model->body_inertia[3 * b + std::size_t(k)];
    }
    std::sort(row.inertia_ours, row.inertia_ours + 3);
    std::sort(row.inertia_mujoco, row.inertia_mujoco + 3);
    rows.push_back(row);
  }
  return rows;
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
