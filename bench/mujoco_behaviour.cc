// MuJoCo 2.2.2 against manyworlds on what contacts DO (docs/benchmarks.md,
// "Contact behaviour: resting and sliding"), where mujoco_bench compares
// only what they cost. The same scenes in both engines, dt 1/60 s, one world
// each; ours with the default step settings (StepSettings{}), MuJoCo with
// its defaults (soft contacts, pyramidal cones, condim 3, default
// solref/solimp, Newton, Euler). Both print a table: quantity, ours,
// MuJoCo, the analytic value where there is one, and a note.
//
//   1. Resting: a box (1 kg, half extents 0.5 m), a sphere (r 0.5 m) and a
//      capsule lying flat (r 0.25 m, core 1 m along X) dropped with their
//      lowest point 0.1 m above a ground plane (the box also from 0.5 m):
//      how deep they sit below the surface after 5 s, with what each
//      engine's model predicts, and how much they still move over the last
//      second (depth range, largest speed and angular speed).
//   2. Incline: the box released at rest on the ground plane tilted by 30
//      degrees about Z (tan 30 = 0.577 > 0.5: it slides): the distance it
//      slid down the slope after 1 s against g (sin a - mu cos a) t^2 / 2,
//      how many of those 60 steps had no contact and how far it rose off
//      the plane; tilted by 20 degrees (tan 20 = 0.364 < 0.5: it must stay),
//      how far it crept in 1 s and 5 s. Released 1 um inside the plane, and
//      again exactly touching and 1 um above (MuJoCo's results depend on it).
//
// Friction: the pair's is 0.5 in both engines. MuJoCo combines two geoms'
// frictions by their maximum, ours (Jolt's) by sqrt(mu1 mu2): both geoms
// (shapes) get 0.5, which both rules turn into 0.5; the program checks that
// every MuJoCo contact carries 0.5.
//
// Exits with 1 when MuJoCo warns, a state is non-finite, a MuJoCo contact
// has another friction or a frame whose tangents miss the slope (a pyramidal
// cone gives the full mu only along them), or ours misses what it must do
// (each check says why; the table prints what is measured):
//   - resting depth: what our discrete free fall predicts, within 0.1 mm
//     (docs/contacts.md: a body that starts a step within
//     speculative_contact_distance of the ground is stopped on the surface;
//     one faster than that lands inside by the rest of its last free step,
//     and penetration within penetration_slop is never pushed out), and
//     less than the slop;
//   - no jitter at rest: speeds over the last second below 1e-3 m/s (rad/s);
//   - sliding at 30 degrees: within 1 % of semi-implicit Euler's distance
//     a dt^2 n (n + 1) / 2 (while it slides, the friction impulse is mu
//     times the normal impulse), and no step without contact;
//   - creep at 20 degrees below 1 mm after 5 s (static friction holds).
//
//   mujoco_behaviour

#include <mujoco/mujoco.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "manyworlds/batch.h"
#include "manyworlds/scene.h"

#include "bench/mujoco_scenes.h"

namespace manyworlds::bench {
namespace {

constexpr double kDt = 1.0 / 60.0;
constexpr double kGravity = 9.81;
constexpr double kFriction = 0.5;  // each shape's and geom's, and so the pair's
constexpr int kRestSteps = 300;    // 5 s
constexpr int kLastSecond = 60;    // steps
constexpr int kSlideSteps = 60;    // 1 s
constexpr int kCreepSteps = 300;   // 5 s
constexpr double kDropHeight = 0.1;      // m, lowest point above the ground
constexpr double kHighDropHeight = 0.5;  // m
// The incline's box starts with its bottom face this far above the plane:
// 1 um inside, so that MuJoCo finds all four corners in the first step.
// Released exactly touching, the corners' distances are rounding errors of
// either sign, and at 30 degrees MuJoCo's first step finds two of the four
// (the table shows that release, and 1 um above, too).
constexpr double kInclineGap = -1e-6;  // m

std::atomic<int> mujoco_warnings{0};

void CountMujocoWarning(const char* message) {
  if (mujoco_warnings.fetch_add(1) < 5) std::fprintf(stderr, "MuJoCo warning: %s\n", message);
}

// ------------------------------------------------------------------ geometry

using Vec3 = std::array<double, 3>;
using Quat = std::array<double, 4>;  // x, y, z, w (ours); MuJoCo's is w, x, y, z

double Dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
double Norm(const Vec3& a) { return std::sqrt(Dot(a, a)); }
Vec3 Add(const Vec3& a, const Vec3& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
Vec3 Sub(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Vec3 Scale(const Vec3& a, double s) { return {a[0] * s, a[1] * s, a[2] * s}; }

Vec3 Rotate(const Quat& q, const Vec3& v) {
  const double x = q[0], y = q[1], z = q[2], w = q[3];
  // v + 2 w (u x v) + 2 u x (u x v), u = (x, y, z)
  const Vec3 t{2 * (y * v[2] - z * v[1]), 2 * (z * v[0] - x * v[2]), 2 * (x * v[1] - y * v[0])};
  return {v[0] + w * t[0] + (y * t[2] - z * t[1]), v[1] + w * t[1] + (z * t[0] - x * t[2]),
          v[2] + w * t[2] + (x * t[1] - y * t[0])};
}

// The ground turned by `tilt` about Z: its +Y (the plane's outward normal)
// becomes (-sin tilt, cos tilt, 0). The released body is turned the same.
Quat Tilt(double tilt) { return {0, 0, std::sin(tilt / 2), std::cos(tilt / 2)}; }
Vec3 GroundNormal(double tilt) { return {-std::sin(tilt), std::cos(tilt), 0}; }
// Down the slope: gravity's part along the plane, normalised.
Vec3 Downhill(double tilt) { return {-std::cos(tilt), -std::sin(tilt), 0}; }

std::string Number(double value) {
  char text[40];
  std::snprintf(text, sizeof text, "%.17g", value);
  return text;
}

// ------------------------------------------------------------------ the body

enum class ShapeKind { kBox, kSphere, kCapsule };

// The dropped or released body: 1 kg, uniform density, principal axes the
// body's axes, the shape centred on the centre of mass.
struct TestBody {
  const char* name;
  ShapeKind kind;
  double half_extent = 0;  // box (a cube)
  double radius = 0;       // sphere, capsule
  double half_height = 0;  // capsule: its core runs along the body's X
  Vec3 inertia{};          // kg m^2
};

TestBody Box() {
  // I = m (2h)^2 / 6 about every axis.
  return {"box", ShapeKind::kBox, 0.5, 0, 0, {1.0 / 6, 1.0 / 6, 1.0 / 6}};
}

TestBody Sphere() {
  // I = 2/5 m r^2.
  return {"sphere", ShapeKind::kSphere, 0, 0.5, 0, {0.1, 0.1, 0.1}};
}

TestBody Capsule() {
  // A cylinder (radius r, length H = 2 h) and two hemispheres, of one
  // density: along the axis m_c r^2 / 2 + m_s 2 r^2 / 5; across,
  // m_c (r^2 / 4 + H^2 / 12) + m_s (2 r^2 / 5 + H^2 / 4 + 3 H r / 8).
  const double r = 0.25, h = 0.5, length = 2 * h;
  const double cylinder = std::numbers::pi * r * r * length;
  const double ball = 4.0 / 3.0 * std::numbers::pi * r * r * r;
  const double m_c = cylinder / (cylinder + ball), m_s = ball / (cylinder + ball);
  const double along = m_c * r * r / 2 + m_s * 2 * r * r / 5;
  const double across = m_c * (r * r / 4 + length * length / 12) +
                        m_s * (2 * r * r / 5 + length * length / 4 + 3 * length * r / 8);
  return {"capsule", ShapeKind::kCapsule, 0, r, h, {along, across, across}};
}

// The shape is the set of points within `CoreRadius` of the convex hull of
// `CorePoints` (body frame): box corners and 0, the sphere's centre and r,
// the capsule's core ends and r.
std::vector<Vec3> CorePoints(const TestBody& body) {
  if (body.kind == ShapeKind::kBox) {
    std::vector<Vec3> corners;
    const double h = body.half_extent;
    for (const double x : {-h, h}) {
      for (const double y : {-h, h}) {
        for (const double z : {-h, h}) corners.push_back({x, y, z});
      }
    }
    return corners;
  }
  if (body.kind == ShapeKind::kSphere) return {{0, 0, 0}};
  return {{-body.half_height, 0, 0}, {body.half_height, 0, 0}};
}

double CoreRadius(const TestBody& body) {
  return body.kind == ShapeKind::kBox ? 0.0 : body.radius;
}

// How deep the shape's lowest point lies below the ground plane (through the
// origin, outward normal n), with its centre at x turned by q: positive
// below the surface, negative above.
double Depth(const TestBody& body, const Vec3& x, const Quat& q, const Vec3& n) {
  double lowest = std::numeric_limits<double>::infinity();
  for (const Vec3& p : CorePoints(body)) lowest = std::min(lowest, Dot(n, Add(x, Rotate(q, p))));
  return CoreRadius(body) - lowest;
}

// ------------------------------------------------------------------ a run

// One release: the body turned as the ground (tilt about Z), its lowest
// point `gap` above the plane along the normal (negative: inside), at rest.
struct Release {
  TestBody body;
  double tilt = 0;  // rad
  double gap = 0;   // m
  int steps = 0;
};

Vec3 StartPosition(const Release& r) {
  const Vec3 n = GroundNormal(r.tilt);
  // At the origin the lowest point is Depth(...) below the plane.
  const double lift = Depth(r.body, {0, 0, 0}, Tilt(r.tilt), n) + r.gap;
  return Scale(n, lift);
}

// The body after each step ([0] the release).
struct Sample {
  Vec3 position;
  Quat rotation;
  double speed = 0;          // m/s
  double angular_speed = 0;  // rad/s
  int contacts = 0;          // points (ours) or contacts (MuJoCo) the step used
};
using Trajectory = std::vector<Sample>;

bool Finite(const Trajectory& t) {
  for (const Sample& s : t) {
    for (const double v : s.position) {
      if (!std::isfinite(v)) return false;
    }
    for (const double v : s.rotation) {
      if (!std::isfinite(v)) return false;
    }
    if (!std::isfinite(s.speed) || !std::isfinite(s.angular_speed)) return false;
  }
  return true;
}

// ---- ours: a static plane turned by the tilt, the body on it.

Quaternion ToFloat(const Quat& q) { return {float(q[0]), float(q[1]), float(q[2]), float(q[3])}; }
Float3 ToFloat(const Vec3& v) { return {float(v[0]), float(v[1]), float(v[2])}; }

Scene OurScene(const Release& r) {
  Scene scene;
  BodySettings ground;
  ground.name = "ground";
  ground.motion_type = MotionType::kStatic;
  ground.rotation = ToFloat(Tilt(r.tilt));
  ground.shape.type = ShapeType::kPlane;
  ground.shape.friction = float(kFriction);
  scene.AddBody(ground);

  BodySettings body;
  body.name = r.body.name;
  body.mass = 1.0f;
  body.inertia_diagonal = ToFloat(r.body.inertia);
  body.position = ToFloat(StartPosition(r));
  body.rotation = ToFloat(Tilt(r.tilt));
  // No damping, as the built-in scenes (and MuJoCo's free joint): Jolt's
  // default 0.05 / s would slow the slide by about 1 % a second.
  body.linear_damping = 0.0f;
  body.angular_damping = 0.0f;
  body.shape.friction = float(kFriction);
  switch (r.body.kind) {
    case ShapeKind::kBox:
      body.shape.type = ShapeType::kBox;
      body.shape.half_extents = ToFloat(Vec3{r.body.half_extent, r.body.half_extent,
                                             r.body.half_extent});
      break;
    case ShapeKind::kSphere:
      body.shape.type = ShapeType::kSphere;
      body.shape.radius = float(r.body.radius);
      break;
    case ShapeKind::kCapsule:
      // Our capsule's core runs along the shape's Y: turned -90 degrees
      // about Z onto the body's X.
      body.shape.type = ShapeType::kCapsule;
      body.shape.radius = float(r.body.radius);
      body.shape.half_height = float(r.body.half_height);
      body.shape.rotation = ToFloat(Quat{0, 0, -std::sqrt(0.5), std::sqrt(0.5)});
      break;
  }
  scene.AddBody(body);
  return scene;
}

Trajectory RunOurs(const Release& r, const StepSettings& settings) {
  Batch batch(OurScene(r), 1, BatchOptions{.threads = 1});
  std::vector<float> state(batch.body_count() * kStateFloatsPerBody);
  std::vector<float> contacts(batch.ContactSlotCount() * Batch::kContactFloats);
  Trajectory trajectory;
  const auto record = [&] {
    batch.GetWorldState(0, state);
    batch.GetContacts(contacts);  // one slot: ground and body; [0] its points
    const float* s = &state[kStateFloatsPerBody];  // body 1
    Sample sample;
    sample.position = {s[0], s[1], s[2]};
    sample.rotation = {s[3], s[4], s[5], s[6]};
    sample.speed = Norm({s[7], s[8], s[9]});
    sample.angular_speed = Norm({s[10], s[11], s[12]});
    sample.contacts = int(contacts[0]);
    trajectory.push_back(sample);
  };
  record();
  for (int step = 0; step < r.steps; ++step) {
    batch.Step(settings);
    record();
  }
  return trajectory;
}

// ---- MuJoCo: a plane geom turned by the tilt, the body on a free joint.

// Only gravity and the step are set; everything else is MuJoCo's default
// (integrator Euler, solver Newton, 100 iterations, tolerance 1e-8, cone
// pyramidal, impratio 1, condim 3, solref 0.02 1, solimp 0.9 0.95 0.001 0.5
// 2, margin 0). Both geoms get friction 0.5 (sliding; MuJoCo's defaults for
// torsion and rolling, which condim 3 does not use).
std::string MujocoReleaseXml(const Release& r) {
  const Vec3 n = GroundNormal(r.tilt), x = StartPosition(r);
  const Quat q = Tilt(r.tilt);
  const std::string friction = "friction='" + Number(kFriction) + " 0.005 0.0001'";
  std::string geom;
  switch (r.body.kind) {
    case ShapeKind::kBox:
      geom = "type='box' size='" + Number(r.body.half_extent) + " " +
             Number(r.body.half_extent) + " " + Number(r.body.half_extent) + "'";
      break;
    case ShapeKind::kSphere:
      geom = "type='sphere' size='" + Number(r.body.radius) + "'";
      break;
    case ShapeKind::kCapsule:
      geom = "type='capsule' size='" + Number(r.body.radius) + "' fromto='" +
             Number(-r.body.half_height) + " 0 0 " + Number(r.body.half_height) + " 0 0'";
      break;
  }
  return "<mujoco model='behaviour'><option timestep='" + Number(kDt) +
         "' gravity='0 " + Number(-kGravity) + " 0'/><worldbody>"
         "<geom name='ground' type='plane' size='50 50 1' zaxis='" + Number(n[0]) + " " +
         Number(n[1]) + " " + Number(n[2]) + "' " + friction + "/>"
         "<body name='" + r.body.name + "' pos='" + Number(x[0]) + " " + Number(x[1]) + " " +
         Number(x[2]) + "' quat='" + Number(q[3]) + " " + Number(q[0]) + " " + Number(q[1]) +
         " " + Number(q[2]) + "'><freejoint/>"
         "<inertial pos='0 0 0' mass='1' diaginertia='" + Number(r.body.inertia[0]) + " " +
         Number(r.body.inertia[1]) + " " + Number(r.body.inertia[2]) + "'/>"
         "<geom name='" + r.body.name + "' " + geom + " " + friction + "/>"
         "</body></worldbody></mujoco>";
}

// What MuJoCo's contacts were: every contact of every step, and the last
// step's (found at its start).
struct MujocoContacts {
  bool friction_as_set = true;  // every contact's sliding friction kFriction
  double slope_alignment = 1;   // min over contacts of max |tangent . downhill|
  int last_count = 0;
  double last_deepest = 0;      // -min dist (m) of the last step: MuJoCo's own depth
  double last_diag = 0;         // efc_diagApprox of the last step's first row
};

Trajectory RunMujoco(const Release& r, MujocoContacts& contacts) {
  const MujocoModel model = LoadMujocoXml(MujocoReleaseXml(r));
  MujocoData data(mj_makeData(model.get()));
  if (!data) throw std::runtime_error("MuJoCo mj_makeData failed");
  mj_resetData(model.get(), data.get());
  contacts = MujocoContacts{};
  const Vec3 downhill = Downhill(r.tilt);
  Trajectory trajectory;
  const auto record = [&] {
    const mjtNum* q = data->qpos;  // free joint: position, then w, x, y, z
    const mjtNum* v = data->qvel;  // linear (world), angular (body frame)
    Sample sample;
    sample.position = {q[0], q[1], q[2]};
    sample.rotation = {q[4], q[5], q[6], q[3]};
    sample.speed = Norm({v[0], v[1], v[2]});
    sample.angular_speed = Norm({v[3], v[4], v[5]});
    sample.contacts = data->ncon;
    trajectory.push_back(sample);
  };
  record();
  for (int step = 0; step < r.steps; ++step) {
    mj_step(model.get(), data.get());
    record();
    contacts.last_count = data->ncon;
    contacts.last_deepest = 0;
    for (int i = 0; i < data->ncon; ++i) {
      const mjContact& c = data->contact[i];
      contacts.friction_as_set = contacts.friction_as_set && c.friction[0] == kFriction;
      // frame: the normal, then the two tangents (rows). A pyramidal cone
      // gives the full mu only along its tangents: the slope must be one.
      double alignment = 0;
      for (int t = 1; t < 3; ++t) {
        const Vec3 tangent{c.frame[3 * t], c.frame[3 * t + 1], c.frame[3 * t + 2]};
        alignment = std::max(alignment, std::abs(Dot(tangent, downhill)));
      }
      contacts.slope_alignment = std::min(contacts.slope_alignment, alignment);
      contacts.last_deepest = std::max(contacts.last_deepest, -c.dist);
    }
    contacts.last_diag = data->nefc > 0 ? data->efc_diagApprox[0] : 0;
  }
  return trajectory;
}

// ------------------------------------------------------------------ predictions

// Ours (docs/contacts.md): the lowest point falls freely (semi-implicit
// Euler: v -= g dt, then x += v dt) while it starts a step at least D =
// speculative_contact_distance above the ground; the first step that
// starts within D has a contact whose speculative bias lets the body reach
// the surface and no further. So it rests on the surface, unless the last
// free step already took it below: then it stays that deep, since
// penetration within penetration_slop is never pushed out.
double OurLandingDepth(double gap, const StepSettings& settings) {
  const double dt = double(settings.delta_time), d = double(settings.speculative_contact_distance);
  double height = gap, v = 0;
  while (height >= d) {
    v -= kGravity * dt;
    height += v * dt;
  }
  return std::max(0.0, -height);
}

// MuJoCo's soft contacts in a steady state (MuJoCo's documentation,
// "Computation", soft constraints; the parameters below are what its
// efc_R and efc_KBIP hold here). A constraint row with regulariser
// R = (1 - d) / d * diagApprox (its approximate inverse effective mass)
// solves (A + R) f = a_ref - a0 with a_ref = -b v - k d r (v the row's
// velocity, r = -depth its position), k = 1 / (dmax^2 T^2 zeta^2),
// b = 2 / (dmax T), T = solref[0] raised to 2 dt (MuJoCo's "refsafe"),
// zeta = solref[1], and the impedance d(depth) rising from solimp[0] at
// depth 0 to solimp[1] = dmax at solimp[2] (midpoint solimp[3], power
// solimp[4]). In a steady state (constant velocity) the bodies do not
// accelerate, so A f = -a0 and each active row has R f = a_ref.
//
// A pyramidal cone of condim 3 makes each contact four rows, its edges
// n +- mu t1 and n +- mu t2, each with unit normal part, all at the
// contact's depth. `diag` is MuJoCo's efc_diagApprox of an edge (read from
// its data; 2 mu^2 (1 + mu^2) / m here).
class MujocoSoftContact {
 public:
  MujocoSoftContact(const mjModel* model, double diag) : diag_(diag) {
    const mjtNum* solref = model->geom_solref;  // the geoms' defaults
    const mjtNum* solimp = model->geom_solimp;
    const double timeconst = std::max(solref[0], 2 * model->opt.timestep), zeta = solref[1];
    d0_ = solimp[0];
    dmax_ = solimp[1];
    width_ = solimp[2];
    mid_ = solimp[3];
    power_ = solimp[4];
    k_ = 1 / (dmax_ * dmax_ * timeconst * timeconst * zeta * zeta);
    b_ = 2 / (dmax_ * timeconst);
  }

  double Impedance(double depth) const {
    const double x = std::min(1.0, depth / width_);
    const double y = x <= mid_ ? std::pow(x, power_) / std::pow(mid_, power_ - 1)
                               : 1 - std::pow(1 - x, power_) / std::pow(1 - mid_, power_ - 1);
    return d0_ + y * (dmax_ - d0_);
  }
  double Regulariser(double depth) const {
    const double d = Impedance(depth);
    return (1 - d) / d * diag_;
  }

  // The depth at which a row without velocity carries `edge_force`:
  // R f = k d depth, by bisection.
  double Depth(double edge_force) const {
    double lo = 0, hi = 1;
    for (int i = 0; i < 200; ++i) {
      const double middle = (lo + hi) / 2;
      const double excess = k_ * Impedance(middle) * middle - Regulariser(middle) * edge_force;
      (excess > 0 ? hi : lo) = middle;
    }
    return (lo + hi) / 2;
  }

  // At rest on flat ground: the weight m g spreads evenly over the 4 N
  // edges of N contacts (by symmetry, for these shapes).
  double RestDepth(double mass, int contacts) const {
    return Depth(mass * kGravity / (4.0 * contacts));
  }

  // The steady creep (m/s) of a box resting on N contacts on a slope
  // tilted by `tilt`, friction mu, the slope along a tangent (checked): the
  // edge whose friction would push down the slope carries nothing, as in
  // MuJoCo's solution, so per contact the up-slope edge carries f_up with
  // mu f_up = m g sin(tilt) / N, the two edges across the slope f_c each
  // with f_up + 2 f_c = m g cos(tilt) / N. The cross edges do not move:
  // R f_c = k d depth; the up-slope edge moves at -mu v: R f_up = b mu v +
  // k d depth. So v = R (f_up - f_c) / (b mu), R at the cross edges' depth.
  double Creep(double mass, int contacts, double tilt, double mu) const {
    const double f_up = mass * kGravity * std::sin(tilt) / (contacts * mu);
    const double f_c = (mass * kGravity * std::cos(tilt) / contacts - f_up) / 2;
    return Regulariser(Depth(f_c)) * (f_up - f_c) / (b_ * mu);
  }

 private:
  double diag_, d0_, dmax_, width_, mid_, power_, k_, b_;
};

// ------------------------------------------------------------------ table

struct Row {
  std::string quantity;
  std::string ours, mujoco, analytic, note;
};

std::string Figure(double value, const char* format) {
  char text[64];
  std::snprintf(text, sizeof text, format, value);
  return text;
}

void PrintTable(const std::vector<Row>& rows) {
  int width = 8;
  for (const Row& r : rows) width = std::max(width, int(r.quantity.size()));
  std::printf("%-*s %10s %10s %10s  %s\n", width, "quantity", "ours", "MuJoCo", "analytic",
              "note");
  for (const Row& r : rows) {
    std::printf("%-*s %10s %10s %10s  %s\n", width, r.quantity.c_str(), r.ours.c_str(),
                r.mujoco.c_str(), r.analytic.c_str(), r.note.c_str());
  }
}

// Over the last second of a trajectory: depth range, largest speeds.
struct Jitter {
  double depth_range = 0, speed = 0, angular_speed = 0;
};

Jitter LastSecond(const TestBody& body, const Trajectory& t, const Vec3& n) {
  Jitter j;
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (std::size_t i = t.size() - kLastSecond; i < t.size(); ++i) {
    const double depth = Depth(body, t[i].position, t[i].rotation, n);
    lo = std::min(lo, depth);
    hi = std::max(hi, depth);
    j.speed = std::max(j.speed, t[i].speed);
    j.angular_speed = std::max(j.angular_speed, t[i].angular_speed);
  }
  j.depth_range = hi - lo;
  return j;
}

// Distance along the slope from the release, and the whole displacement.
double Downslope(const Trajectory& t, int step, double tilt) {
  return Dot(Sub(t[std::size_t(step)].position, t[0].position), Downhill(tilt));
}
double Displacement(const Trajectory& t, int step) {
  return Norm(Sub(t[std::size_t(step)].position, t[0].position));
}

class Checks {
 public:
  void Expect(bool ok, const std::string& what) {
    if (!ok) {
      failures_.push_back(what);
    }
  }
  bool Report() const {
    for (const std::string& f : failures_) std::printf("FAILED: %s\n", f.c_str());
    return failures_.empty();
  }

 private:
  std::vector<std::string> failures_;
};

// The first second of a slide: steps that used no contact, and how far the
// lowest point rose above the plane.
struct Chatter {
  int steps_without_contact = 0;
  double lift = 0;  // m
};

Chatter FirstSecond(const TestBody& body, const Trajectory& t, double tilt) {
  Chatter c;
  for (std::size_t i = 1; i <= std::size_t(kSlideSteps) && i < t.size(); ++i) {
    c.steps_without_contact += t[i].contacts == 0;
    c.lift = std::max(c.lift, -Depth(body, t[i].position, t[i].rotation, GroundNormal(tilt)));
  }
  return c;
}

void PrintDefaults(const StepSettings& settings) {
  const Release probe{Sphere(), 0, kDropHeight, 0};
  const MujocoModel model = LoadMujocoXml(MujocoReleaseXml(probe));
  const mjtNum* solref = model->geom_solref;
  const mjtNum* solimp = model->geom_solimp;
  std::printf(
      "MuJoCo %d.%d.%d, its defaults: soft contacts (solref %g %g, time constant raised to 2 dt = "
      "%.4f s; solimp %g %g %g %g %g), %s cones, condim %d, integrator %s, solver %s (%d "
      "iterations, tolerance %g), impratio %g, margin %g; free joint, no damping\n",
      mj_version() / 100, mj_version() / 10 % 10, mj_version() % 10, solref[0], solref[1],
      std::max(solref[0], 2 * model->opt.timestep),
      solimp[0], solimp[1], solimp[2], solimp[3], solimp[4],
      model->opt.cone == mjCONE_PYRAMIDAL ? "pyramidal" : "elliptic", model->geom_condim[0],
      model->opt.integrator == mjINT_EULER ? "Euler" : "not Euler",
      model->opt.solver == mjSOL_NEWTON ? "Newton" : "not Newton", model->opt.iterations,
      model->opt.tolerance, model->opt.impratio, model->geom_margin[0]);
  std::printf(
      "ours: hard contacts (Jolt's), StepSettings{}: dt %.4f s, %d velocity + %d position "
      "iterations, Baumgarte %g, speculative_contact_distance %g m, penetration_slop %g m; "
      "bodies undamped\n",
      double(settings.delta_time), settings.velocity_iterations, settings.position_iterations,
      double(settings.baumgarte), double(settings.speculative_contact_distance),
      double(settings.penetration_slop));
  std::printf(
      "friction: every geom and shape %g; MuJoCo combines two geoms' by max(mu1, mu2) = %g, "
      "ours (Jolt's) by sqrt(mu1 mu2) = %g\n"
      "bodies: 1 kg; box half extents 0.5 m, sphere r 0.5 m, capsule r 0.25 m with a 1 m core "
      "lying along X; gravity 9.81 m/s^2, dt 1/60 s\n\n",
      kFriction, std::max(kFriction, kFriction), std::sqrt(kFriction * kFriction));
}

int Run() {
  mju_user_warning = CountMujocoWarning;
  const StepSettings settings;  // dt 1/60 s, 10 + 2 iterations, D = slop = 2 cm
  PrintDefaults(settings);
  Checks checks;
  std::vector<Row> rows;
  bool finite = true;
  const auto run_both = [&](const Release& r, Trajectory& ours, Trajectory& mujoco,
                            MujocoContacts& contacts) {
    ours = RunOurs(r, settings);
    mujoco = RunMujoco(r, contacts);
    finite = finite && Finite(ours) && Finite(mujoco);
    checks.Expect(contacts.friction_as_set,
                  std::string(r.body.name) + ": a MuJoCo contact's friction is not " +
                      Number(kFriction));
    checks.Expect(contacts.slope_alignment > 1 - 1e-9,
                  std::string(r.body.name) +
                      ": the slope is not along a tangent of MuJoCo's contact frame");
  };

  // ---- 1. resting on flat ground
  const auto rest = [&](const TestBody& body, double gap) {
    Trajectory ours, mujoco;
    MujocoContacts contacts;
    run_both(Release{body, 0, gap, kRestSteps}, ours, mujoco, contacts);
    const Vec3 n = GroundNormal(0);
    const double depth_ours = Depth(body, ours.back().position, ours.back().rotation, n);
    const double depth_mujoco = Depth(body, mujoco.back().position, mujoco.back().rotation, n);
    const double predicted = OurLandingDepth(gap, settings);
    const double soft =
        MujocoSoftContact(LoadMujocoXml(MujocoReleaseXml(Release{body, 0, gap, 0})).get(),
                          contacts.last_diag)
            .RestDepth(1.0, std::max(1, contacts.last_count));
    const Jitter j_ours = LastSecond(body, ours, n), j_mujoco = LastSecond(body, mujoco, n);
    const std::string label = std::string(body.name) + ", dropped " + Figure(gap, "%.1f m") + ": ";
    rows.push_back({label + "depth after 5 s (mm)", Figure(1e3 * depth_ours, "%.3f"),
                    Figure(1e3 * depth_mujoco, "%.3f"), "0 (rigid)",
                    "expected ours " + Figure(1e3 * predicted, "%.3f") + " (landing), MuJoCo " +
                        Figure(1e3 * soft, "%.3f") + " (soft, " +
                        std::to_string(contacts.last_count) +
                        (contacts.last_count == 1 ? " contact" : " contacts") + "; its own dist " +
                        Figure(1e3 * contacts.last_deepest, "%.3f") + ")"});
    rows.push_back({label + "depth range 4-5 s (mm)", Figure(1e3 * j_ours.depth_range, "%.1e"),
                    Figure(1e3 * j_mujoco.depth_range, "%.1e"), "0", ""});
    rows.push_back({label + "max speed 4-5 s (m/s)", Figure(j_ours.speed, "%.1e"),
                    Figure(j_mujoco.speed, "%.1e"), "0", ""});
    rows.push_back({label + "max angular speed 4-5 s (rad/s)",
                    Figure(j_ours.angular_speed, "%.1e"), Figure(j_mujoco.angular_speed, "%.1e"),
                    "0", ""});
    checks.Expect(std::abs(depth_ours - predicted) <= 1e-4,
                  label + "ours rests " + Figure(1e3 * depth_ours, "%.3f") +
                      " mm deep, not the predicted " + Figure(1e3 * predicted, "%.3f") + " mm");
    checks.Expect(depth_ours < double(settings.penetration_slop),
                  label + "ours rests deeper than the penetration slop");
    checks.Expect(j_ours.speed < 1e-3 && j_ours.angular_speed < 1e-3,
                  label + "ours still moves in the last second");
  };
  rest(Box(), kDropHeight);
  rest(Sphere(), kDropHeight);
  rest(Capsule(), kDropHeight);
  rest(Box(), kHighDropHeight);
  // Beyond Jolt: with the speculative distance grown by the approach speed
  // (docs/contacts.md, Settings) the contact is there a step early and the
  // fast box lands on the surface: the 1 mm resting target.
  {
    StepSettings grown = settings;
    grown.speculative_contacts_from_velocity = true;
    const Trajectory ours = RunOurs(Release{Box(), 0, kHighDropHeight, kRestSteps}, grown);
    finite = finite && Finite(ours);
    const double depth =
        Depth(Box(), ours.back().position, ours.back().rotation, GroundNormal(0));
    rows.push_back({"box, dropped 0.5 m, speculative_contacts_from_velocity: depth after 5 s (mm)",
                    Figure(1e3 * depth, "%.3f"), "-", "0 (rigid)",
                    "the contact is found one step early"});
    checks.Expect(depth < 1e-3, "with speculative_contacts_from_velocity the box dropped 0.5 m "
                                "rests " + Figure(1e3 * depth, "%.3f") + " mm deep, not < 1 mm");
  }

  // ---- 2. the box on an incline
  const auto degrees = [](double d) { return d * std::numbers::pi / 180; };
  const auto release_name = [](double gap) -> std::string {
    if (gap == 0) return "exactly touching";
    return std::string("1 um ") + (gap < 0 ? "inside" : "above");
  };
  {
    const double tilt = degrees(30);
    const double a = kGravity * (std::sin(tilt) - kFriction * std::cos(tilt));
    const double t = kSlideSteps * kDt;
    const double analytic = a * t * t / 2;
    const double discrete = a * kDt * kDt * kSlideSteps * (kSlideSteps + 1) / 2;
    for (const double gap : {kInclineGap, 0.0, -kInclineGap}) {
      Trajectory ours, mujoco;
      MujocoContacts contacts;
      run_both(Release{Box(), tilt, gap, kSlideSteps}, ours, mujoco, contacts);
      const double d_ours = Downslope(ours, kSlideSteps, tilt);
      const double d_mujoco = Downslope(mujoco, kSlideSteps, tilt);
      const std::string label = "30 deg, " + release_name(gap) + ": ";
      rows.push_back({label + "slid in 1 s (m)", Figure(d_ours, "%.4f"), Figure(d_mujoco, "%.4f"),
                      Figure(analytic, "%.4f"),
                      "vs analytic ours " + Figure(100 * (d_ours / analytic - 1), "%+.1f %%") +
                          ", MuJoCo " + Figure(100 * (d_mujoco / analytic - 1), "%+.1f %%") +
                          "; discrete " + Figure(discrete, "%.4f") + ": ours " +
                          Figure(100 * (d_ours / discrete - 1), "%+.3f %%")});
      const Chatter c_ours = FirstSecond(Box(), ours, tilt);
      const Chatter c_mujoco = FirstSecond(Box(), mujoco, tilt);
      rows.push_back({label + "steps without contact (of 60)",
                      std::to_string(c_ours.steps_without_contact),
                      std::to_string(c_mujoco.steps_without_contact), "0", ""});
      rows.push_back({label + "lift off the plane in 1 s (mm)", Figure(1e3 * c_ours.lift, "%.3f"),
                      Figure(1e3 * c_mujoco.lift, "%.3f"), "0",
                      "the lowest corner's largest height above the plane"});
      // Nothing lifts our sliding box: the contact's bias is max(0, s/dt)
      // (it never pushes apart beyond separation 0), restitution is 0, and
      // penetration within the slop is not pushed out, so the box keeps
      // its contact every step.
      checks.Expect(c_ours.steps_without_contact == 0 && c_ours.lift < 1e-4,
                    label + "ours left the plane while sliding");
      checks.Expect(std::abs(d_ours / discrete - 1) < 0.01,
                    label + "ours slid " + Figure(d_ours, "%.4f") + " m, not within 1 % of " +
                        Figure(discrete, "%.4f") + " m");
    }
  }
  {
    const double tilt = degrees(20);
    for (const double gap : {kInclineGap, 0.0, -kInclineGap}) {
      Trajectory ours, mujoco;
      MujocoContacts contacts;
      run_both(Release{Box(), tilt, gap, kCreepSteps}, ours, mujoco, contacts);
      const std::string label = "20 deg, " + release_name(gap) + ": ";
      for (const int steps : {kSlideSteps, kCreepSteps}) {
        if (gap != kInclineGap && steps != kCreepSteps) continue;
        rows.push_back({label + "crept in " + std::to_string(steps / 60) + " s (mm)",
                        Figure(1e3 * Downslope(ours, steps, tilt), "%.3f"),
                        Figure(1e3 * Downslope(mujoco, steps, tilt), "%.3f"), "0",
                        "down the slope; whole displacement ours " +
                            Figure(1e3 * Displacement(ours, steps), "%.3f") + ", MuJoCo " +
                            Figure(1e3 * Displacement(mujoco, steps), "%.3f")});
      }
      if (gap == kInclineGap) {
        const Jitter j_ours = LastSecond(Box(), ours, GroundNormal(tilt));
        const Jitter j_mujoco = LastSecond(Box(), mujoco, GroundNormal(tilt));
        const double creep =
            MujocoSoftContact(LoadMujocoXml(MujocoReleaseXml(Release{Box(), tilt, gap, 0})).get(),
                              contacts.last_diag)
                .Creep(1.0, std::max(1, contacts.last_count), tilt, kFriction);
        rows.push_back({label + "max speed 4-5 s (m/s)", Figure(j_ours.speed, "%.2e"),
                        Figure(j_mujoco.speed, "%.2e"), "0",
                        "the creep's speed; expected MuJoCo " + Figure(creep, "%.2e") +
                            " (soft friction, " + std::to_string(contacts.last_count) +
                            " contacts)"});
      }
      checks.Expect(Displacement(ours, kCreepSteps) < 1e-3,
                    label + "ours crept " + Figure(1e3 * Displacement(ours, kCreepSteps), "%.3f") +
                        " mm in 5 s");
    }
  }

  PrintTable(rows);
  checks.Expect(finite, "a state was not finite");
  checks.Expect(mujoco_warnings.load() == 0, "MuJoCo warned");
  if (!checks.Report()) return 1;
  std::printf("\nall checks passed\n");
  return 0;
}

}  // namespace
}  // namespace manyworlds::bench

int main() {
  try {
    return manyworlds::bench::Run();
  } catch (const std::exception& e) {
    std::fprintf(stderr, "mujoco_behaviour: %s\n", e.what());
    return 1;
  }
}
