// The stress scenes of the spec (MakeStressScene, docs/stability.md): every
// one runs 10 s of simulated time at its SceneStepSettings on a batch of 17
// worlds (a full block and one world of a second block, the rest padding),
// and must stay finite, keep its energy within a stated bound and its joints
// within a stated error; singular starts must reach their rest pose within a
// stated time; the springs must follow the implicit-Euler recursion; the
// unstable-axis spin is compared with the exact motion. Where Jolt's
// algorithm fails a bound at the default settings, the test asserts the
// bound with the remedy docs/stability.md names (substeps, the gyroscopic
// step, the mass-range limit) and prints both. Every run prints "figures"
// lines (also recorded as test properties) that docs/stability.md quotes:
//
//   ./build/tests/stress_test | grep figures
//
// The worlds of a batch hold the same scene and get no actions, so every
// world must end bit-identical to world 0 (a partial block computes as a full
// one); the figures are world 0's.
//
// Bounds, and why:
//  - energy E = sum over dynamic bodies of 1/2 m v^2 + 1/2 w.I w - m g.x, plus
//    1/2 k d^2 of the spring scenes. Nothing in these scenes adds energy
//    except singular-rackpinion's motor, and Jolt's velocity solve, position
//    projection and implicit springs only remove it, so E may exceed its start
//    by float rounding only: kEnergyRounding x S, S the largest kinetic or
//    potential energy seen (rounding of each body's state, summed over up to
//    64 bodies). The motor may add the kinetic energy of its target speed.
//    Torn joints are the exception (MassRangeHangingIsNotHeldByJoltsSolver):
//    a position step that pulls links hundreds of metres back together can
//    raise them, so that test has its own, measured bound.
//  - joints: Batch::MaxConstraintError (m or rad) at every step after the
//    first second. Chains: kChainJointError, a tenth of a 0.5 m link, "the
//    chain holds together". Single joints: kRestError.
//  - rest: the time after which MaxConstraintError stays below kRestError.
//
// Each bound was checked to fail once by planting a bug (see the commit that
// added this file): a 2 % stiffer spring in the recursion, a rest error of
// 1e-6, a chain remedy of 2 substeps.

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <numbers>
#include <ostream>
#include <string>
#include <variant>
#include <vector>

#include "manyworlds/batch.h"
#include "manyworlds/mass_range.h"
#include "manyworlds/scenes.h"
#include "reference/world.h"

namespace manyworlds {
namespace {

constexpr std::size_t kWorlds = 17;
constexpr double kSeconds = 10.0;
constexpr double kInfinity = std::numeric_limits<double>::infinity();
constexpr double kEnergyRounding = 64.0 * FLT_EPSILON;
constexpr double kChainJointError = 0.05;
// The constraint error under which a singular start counts as back at rest:
// 1e-3 rad (0.06 deg) or 1 mm, far above float rounding of the unit-size
// cubes (1e-7) and below anything a user would see.
constexpr double kRestError = 1e-3;
// Baumgarte (beta 0.2, 2 position iterations) removes 1 - 0.8^2 = 36 % of an
// error per step, so pi rad falls below kRestError in ln(pi / 1e-3) /
// -ln(0.64) = 18 steps (0.3 s); allowed 1 s, because the first steps from a
// singular start turn about fallback axes and the cone's position row acts on
// cos(angle), whose slope vanishes at 180 degrees.
constexpr double kRestTime = 1.0;

struct V3 {
  double x, y, z;
};
double Dot(V3 a, V3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
V3 Cross(V3 a, V3 b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
V3 Add(V3 a, V3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
V3 Sub(V3 a, V3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
V3 Scale(V3 a, double s) { return {a.x * s, a.y * s, a.z * s}; }
double Length(V3 a) { return std::sqrt(Dot(a, a)); }

// v rotated by the unit quaternion (x, y, z, w), or by its inverse.
V3 Rotate(const float* q, V3 v, bool inverse = false) {
  const double sign = inverse ? -1.0 : 1.0;
  const V3 u{sign * q[0], sign * q[1], sign * q[2]};
  return Add(v, Scale(Cross(u, Add(Cross(u, v), Scale(v, q[3]))), 2.0));
}

// One body of a world's state ([body][13]).
struct BodyState {
  V3 position;
  const float* rotation;
  V3 linear, angular;
};
BodyState BodyOf(const std::vector<float>& state, std::size_t body) {
  const float* s = state.data() + body * kStateFloatsPerBody;
  return {{s[0], s[1], s[2]}, s + 3, {s[7], s[8], s[9]}, {s[10], s[11], s[12]}};
}

// w in the body frame and I w in the world frame (inertia diagonal in the
// body frame: every stress scene has inertia_rotation identity).
V3 BodyAngularVelocity(const BodyState& body) { return Rotate(body.rotation, body.angular, true); }
V3 AngularMomentum(const BodySettings& settings, const BodyState& body) {
  const V3 w = BodyAngularVelocity(body);
  const Float3& i = settings.inertia_diagonal;
  return Rotate(body.rotation, {i[0] * w.x, i[1] * w.y, i[2] * w.z});
}

struct Energy {
  double kinetic = 0, potential = 0;
  double total() const { return kinetic + potential; }
};

// The spring of a spring-* scene: the sphere's COM is the anchor, so the
// row's inverse effective mass is 1/m and k = m (2 pi f)^2.
double SpringStiffness(const Scene& scene, const DistanceConstraintSettings& spring) {
  const double omega = 2.0 * std::numbers::pi * spring.limits_spring.frequency_or_stiffness;
  return scene.bodies()[spring.body2].mass * omega * omega;
}

Energy EnergyOf(const Scene& scene, const std::vector<float>& state, const StepSettings& s) {
  Energy e;
  const V3 g{s.gravity[0], s.gravity[1], s.gravity[2]};
  for (std::size_t b = 0; b < scene.bodies().size(); ++b) {
    const BodySettings& settings = scene.bodies()[b];
    if (settings.motion_type != MotionType::kDynamic) continue;
    const BodyState body = BodyOf(state, b);
    const V3 w = BodyAngularVelocity(body);
    const Float3& i = settings.inertia_diagonal;
    e.kinetic += 0.5 * settings.mass * Dot(body.linear, body.linear) +
                 0.5 * (i[0] * w.x * w.x + i[1] * w.y * w.y + i[2] * w.z * w.z);
    e.potential -= settings.mass * settings.gravity_factor * Dot(g, body.position);
  }
  for (const ConstraintSettings& c : scene.constraints()) {
    const auto* spring = std::get_if<DistanceConstraintSettings>(&c);
    if (spring == nullptr || !spring->limits_spring.HasStiffness()) continue;
    const V3 d = Sub(BodyOf(state, spring->body2).position,
                     {spring->point1[0], spring->point1[1], spring->point1[2]});
    e.potential += 0.5 * SpringStiffness(scene, *spring) * Dot(d, d);
  }
  return e;
}

// What one 10 s run measured (world 0).
struct Figures {
  bool finite = true;            // every world healthy after every step
  bool worlds_identical = true;  // every world's final state equals world 0's bits
  double energy_start = 0, energy_max = -kInfinity, energy_end = 0;
  double energy_scale = 0;     // S: the largest |kinetic| or |potential| seen
  double joint_error_max = 0;  // after the first second
  double rest_time = 0;        // last time the joint error was >= kRestError
};

// Steps `scene` for 10 s on kWorlds worlds with `settings`; `each_step(step,
// world0)` sees world 0's state after every step.
Figures RunScene(const Scene& scene, const StepSettings& settings,
                 const std::function<void(long, const std::vector<float>&)>& each_step = {}) {
  Batch batch(scene, kWorlds);
  const long steps = std::lround(kSeconds / double(settings.delta_time));
  const long one_second = std::lround(1.0 / double(settings.delta_time));
  const std::size_t floats = batch.body_count() * kStateFloatsPerBody;
  std::vector<float> state(kWorlds * floats), world0(floats);
  Figures f;
  batch.GetState(state);
  std::copy_n(state.begin(), floats, world0.begin());
  f.energy_start = EnergyOf(scene, world0, settings).total();
  for (long step = 0; step < steps; ++step) {
    batch.Step(settings);
    if (batch.UnhealthyWorldCount() != 0) {
      f.finite = false;
      return f;
    }
    batch.GetState(state);
    std::copy_n(state.begin(), floats, world0.begin());
    const Energy e = EnergyOf(scene, world0, settings);
    f.energy_max = std::max(f.energy_max, e.total());
    f.energy_scale = std::max({f.energy_scale, std::abs(e.kinetic), std::abs(e.potential)});
    f.energy_end = e.total();
    const double error = batch.MaxConstraintError(0);
    if (step + 1 >= one_second) f.joint_error_max = std::max(f.joint_error_max, error);
    if (error >= kRestError) f.rest_time = double(step + 1) * double(settings.delta_time);
    if (each_step) each_step(step, world0);
  }
  for (std::size_t w = 1; w < kWorlds; ++w) {
    f.worlds_identical &= std::equal(world0.begin(), world0.end(), state.begin() + w * floats);
  }
  return f;
}
Figures RunScene(const std::string& id, const StepSettings& settings,
                 const std::function<void(long, const std::vector<float>&)>& each_step = {}) {
  return RunScene(MakeStressScene(id), settings, each_step);
}

void Report(const std::string& id, const std::string& what, double value) {
  std::string key = id + "." + what;
  ::testing::Test::RecordProperty(key, std::to_string(value));
  std::printf("figures %-22s %-28s %.4g\n", id.c_str(), what.c_str(), value);
}

void ReportFigures(const std::string& id, const std::string& settings, const Figures& f) {
  const std::string prefix = settings.empty() ? "" : settings + ".";
  Report(id, prefix + "finite", f.finite ? 1 : 0);
  if (!f.finite) return;
  // S = 0: nothing moved at all (the singular starts are turned back by
  // position steps alone, which leave no velocity).
  const double scale = f.energy_scale > 0 ? f.energy_scale : 1.0;
  Report(id, prefix + "energy_growth_over_S", (f.energy_max - f.energy_start) / scale);
  Report(id, prefix + "energy_change_over_S", (f.energy_end - f.energy_start) / scale);
  Report(id, prefix + "energy_S_J", f.energy_scale);
  Report(id, prefix + "max_joint_error_after_1s", f.joint_error_max);
  Report(id, prefix + "rest_time_s", f.rest_time);
}

struct Expectation {
  const char* id;
  double joint_error;     // bound at the default settings; kInfinity where Jolt fails it
  double rest_time;       // s; kInfinity where the scene does not start off its rest pose
  double energy_added;    // J a motor may add
  int remedy_substeps;    // substeps that meet kChainJointError where Jolt fails it (0: none)
  float remedy_mass_range;  // LimitMassRange's max_ratio the remedy also needs (0: none)
  const char* why;
};

// gtest prints a parameter with this, instead of its bytes.
void PrintTo(const Expectation& x, std::ostream* os) { *os << x.id; }

// clang-format off
const Expectation kExpectations[] = {
  {"chain16-r1000", kInfinity, kInfinity, 0, 8, 0.0f,
   "Gauss-Seidel cannot stop the 1000 kg link with 10 iterations at 60 Hz: the chain tears"},
  {"chain64", kInfinity, kInfinity, 0, 16, 0.0f, "joints open by half a link at 60 Hz"},
  {"spring-0.1", kInfinity, kInfinity, 0, 0, 0.0f, "soft: SpringsFollowTheImplicitEulerRecursion"},
  {"spring-0.25", kInfinity, kInfinity, 0, 0, 0.0f, "soft: SpringsFollowTheImplicitEulerRecursion"},
  {"spring-0.5", kInfinity, kInfinity, 0, 0, 0.0f, "soft: SpringsFollowTheImplicitEulerRecursion"},
  {"spring-1.0", kInfinity, kInfinity, 0, 0, 0.0f, "soft: SpringsFollowTheImplicitEulerRecursion"},
  {"spin-unstable", kRestError, kInfinity, 0, 0, 0.0f, "no joints; the flip: UnstableAxisSpin"},
  {"flywheel", kRestError, kInfinity, 0, 0, 0.0f, "hinge about the principal axis through the COM"},
  {"singular-hinge-90", kRestError, kRestTime, 0, 0, 0.0f, "kRestTime"},
  {"singular-hinge-180", kRestError, kRestTime, 0, 0, 0.0f, "kRestTime"},
  {"singular-fixed-90", kRestError, kRestTime, 0, 0, 0.0f, "kRestTime"},
  {"singular-fixed-180", kRestError, kRestTime, 0, 0, 0.0f, "kRestTime"},
  {"singular-slider-90", kRestError, kRestTime, 0, 0, 0.0f, "kRestTime"},
  // The motor drives the pinion and, through the coupling, the rack: inertia
  // I = 0.005 + 2 / 10^2 = 0.025 kg m^2 about the pinion axis. Its impulse in
  // one step is at most 5 N m x dt, which the warm start may apply on top of
  // a converged speed, so the speed stays below 2 + 5 dt / I = 5.33 rad/s and
  // the energy added below 1/2 I 5.33^2 = 0.36 J (at the target: 0.05 J;
  // measured peak 0.059 J, the step after the start overshooting by 8 %).
  {"singular-rackpinion", kRestError, kRestTime, 0.36, 0, 0.0f, "a screw: coupling error"},
  {"singular-cone", kRestError, kRestTime, 0, 0, 0.0f, "kRestTime"},
  {"singular-swingtwist", kRestError, kRestTime, 0, 0, 0.0f, "kRestTime"},
  {"dt-1e-4", kChainJointError, kInfinity, 0, 0, 0.0f, "chain16 at 1e4 steps per second holds"},
  {"dt-1/15", kInfinity, kInfinity, 0, 16, 0.0f, "chain16 at 15 Hz tears"},
  {"mass-range", kInfinity, kInfinity, 0, 32, 0.0f, "the 1e-3 kg tip whips at 60 m/s"},
  // Substeps alone do not hold it (MassRangeHangingIsNotHeldByJoltsSolver):
  // the remedy raises the links under 1e3 kg to 1e3 kg first (LimitMassRange).
  {"mass-range-hanging", kInfinity, kInfinity, 0, 8, 1e3f,
   "1e6 kg hanging from 1e-3 kg: Gauss-Seidel converges at the mass ratio"},
  {"far-1e4", kInfinity, kInfinity, 0, 4, 0.0f, "as chain16 at the origin (0.10 m at 60 Hz)"},
};
// clang-format on

class StressTest : public ::testing::TestWithParam<Expectation> {};

// `energy_growth`: what E may gain beyond x.energy_added, in units of S
// (rounding, except for the torn chain below).
void ExpectBounded(const Expectation& x, const Figures& f, double joint_error,
                   double energy_growth = kEnergyRounding) {
  ASSERT_TRUE(f.finite) << x.id;
  EXPECT_TRUE(f.worlds_identical) << x.id;
  EXPECT_LE(f.energy_max - f.energy_start, x.energy_added + energy_growth * f.energy_scale)
      << x.id << ": energy grew";
  EXPECT_LE(f.joint_error_max, joint_error) << x.id << ": " << x.why;
  EXPECT_LE(f.rest_time, x.rest_time) << x.id << ": " << x.why;
}

TEST_P(StressTest, FiniteAndBoundedFor10Seconds) {
  const Expectation& x = GetParam();
  const Figures f = RunScene(x.id, SceneStepSettings(x.id));
  ReportFigures(x.id, "", f);
  ExpectBounded(x, f, x.joint_error);
}

// Where Jolt's algorithm tears a chain at the default settings, substeps (Jolt's
// collision steps: dt / n each, every phase per substep), after the mass-range
// limit where the scene's masses span more than Gauss-Seidel can pass on,
// hold it within kChainJointError. Instantiated for those scenes only. The
// energy bound is the limited scene's (its masses are what the batch steps).
class StressRemedyTest : public StressTest {};

TEST_P(StressRemedyTest, TheRemedyHoldsTheJoints) {
  const Expectation& x = GetParam();
  StepSettings settings = SceneStepSettings(x.id);
  settings.substeps = x.remedy_substeps;
  Scene scene = MakeStressScene(x.id);
  std::string remedy = "substeps" + std::to_string(x.remedy_substeps);
  if (x.remedy_mass_range != 0.0f) {
    ASSERT_FALSE(LimitMassRange(scene, x.remedy_mass_range).empty()) << x.id;
    remedy += ".mass_range" + std::to_string(std::lround(x.remedy_mass_range));
  }
  const Figures f = RunScene(scene, settings);
  ReportFigures(x.id, remedy, f);
  ExpectBounded(x, f, kChainJointError);
}

std::vector<Expectation> Remedied() {
  std::vector<Expectation> remedied;
  for (const Expectation& x : kExpectations) {
    if (x.remedy_substeps != 0) remedied.push_back(x);
  }
  return remedied;
}

std::string Name(const ::testing::TestParamInfo<Expectation>& info) {
  std::string name = info.param.id;
  for (char& c : name) {
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  }
  return name;
}

INSTANTIATE_TEST_SUITE_P(Scenes, StressTest, ::testing::ValuesIn(kExpectations), Name);
INSTANTIATE_TEST_SUITE_P(Scenes, StressRemedyTest, ::testing::ValuesIn(Remedied()), Name);

TEST(StressScenes, EveryStressSceneHasAnExpectation) {
  std::vector<std::string> covered;
  for (const Expectation& x : kExpectations) covered.emplace_back(x.id);
  EXPECT_EQ(covered, StressSceneIds());
}

// The heaviest link (1e6 kg) hangs from links down to 1e-3 kg: each joint's
// effective mass is the light body's, so a velocity iteration moves the heavy
// links by about the mass ratio of the impulse they need, and the unchanged
// scene falls apart whatever the substeps or iterations (docs/stability.md;
// StressRemedyTest holds it after LimitMassRange). Asserted as the documented
// failure, so that a change that fixes it updates the docs: the world stays
// finite and the 1e6 kg link falls nearly freely (the joint error after 10 s
// is over 100 m; free fall from rest covers 490 m) with 1, 8, 20 and 32
// substeps.
// Energy: with the joints torn, the position steps that pull the links back
// together feed the heavy links' swing, so E is not bounded by rounding as
// in the other scenes. Measured over 10 s at 1, 2, 4, 8, 12, 16, 20, 24, 28,
// 32, 40, 48 and 64 substeps: E never exceeded its start at ten of them, and
// rose by 1.2e-4 S at 20, 2.0e-4 S at 40 and 2.8e-5 S at 64 (S as in
// ExpectBounded). kTornChainEnergyGrowth is 5x the largest, so this test
// follows the scene rather than the rounding of one trajectory (which any
// change of the step's rounding moves); 20 is among the counts it runs.
constexpr double kTornChainEnergyGrowth = 1e-3;

TEST(StressScenes, MassRangeHangingIsNotHeldByJoltsSolver) {
  const Expectation& x = kExpectations[19];
  ASSERT_STREQ(x.id, "mass-range-hanging");
  for (const int substeps : {1, 8, 20, 32}) {
    StepSettings settings = SceneStepSettings(x.id);
    settings.substeps = substeps;
    const Figures f = RunScene(x.id, settings);
    ReportFigures(x.id, "substeps" + std::to_string(substeps), f);
    SCOPED_TRACE("substeps " + std::to_string(substeps));
    ExpectBounded(x, f, kInfinity, kTornChainEnergyGrowth);
    EXPECT_GT(f.joint_error_max, 100.0);
  }
}

// What the mass-range limit costs: it changes the scene, so its error is how
// far the 1e6 kg load's path moves with it. The path with limit L against the
// path with 10 L, largest distance over the first 2 s (later the ten-link
// swing is chaotic and any change grows), in the double reference at 64
// substeps, where the limited scenes hold their joints to 4 mm (so the
// solver's own error does not hide the model's).
// Asserted: raising the limit converges (1e3 -> 1e4 moves the load less than
// half as far as 1e2 -> 1e3), and the remedy's limit 1e3 moves it less than
// kChainJointError, the solver error the remedies are held to. The figures
// are docs/stability.md's (at 256 substeps: 0.083 and 0.0084 m).
TEST(StressScenes, TheMassRangeLimitMovesTheLoadLittle) {
  const char* id = "mass-range-hanging";
  constexpr int kSteps = 120;
  const auto load_path = [&](float limit) {
    Scene scene = MakeStressScene(id);
    LimitMassRange(scene, limit);
    reference::World<double> world(scene);
    StepSettings settings = SceneStepSettings(id);
    settings.substeps = 64;
    const std::size_t load = scene.bodies().size() - 1;
    std::vector<reference::Vec3<double>> path;
    for (int step = 0; step < kSteps; ++step) {
      world.Step(settings);
      path.push_back(world.body(load).position);
    }
    return path;
  };
  const auto largest_distance = [](const auto& a, const auto& b) {
    double d = 0;
    for (std::size_t i = 0; i < a.size(); ++i) d = std::max(d, (a[i] - b[i]).norm());
    return d;
  };
  const auto path_1e2 = load_path(1e2f), path_1e3 = load_path(1e3f), path_1e4 = load_path(1e4f);
  const double moved_1e2 = largest_distance(path_1e2, path_1e3);
  const double moved_1e3 = largest_distance(path_1e3, path_1e4);
  Report(id, "mass_range100.load_moved_2s_m", moved_1e2);
  Report(id, "mass_range1000.load_moved_2s_m", moved_1e3);
  EXPECT_LT(moved_1e3, 0.5 * moved_1e2);
  EXPECT_LT(moved_1e3, kChainJointError);
}

// The implicit-Euler spring recursion of Jolt's TestDistanceSpring (spec 6),
// v' = (v - h k/m x) / (1 + h c/m + h^2 k/m), x' = x + h v', with c = 0 and
// k/m = (2 pi f)^2, in double, once per substep (h = dt / substeps). The
// sphere's x follows it at every step within 8 FLT_EPSILON x0 / (1 - rho):
// each substep rounds x through about eight float operations (effective mass,
// bias, impulse, velocity, position, warm start), and the recursion shrinks
// an earlier error by at most rho = 1 / sqrt(1 + (h omega)^2) per substep
// (the modulus of its eigenvalues), so the errors sum to at most that
// geometric series. y and z stay exactly 0 (the row is along X).
//
// The undamped spring (zeta 0) should keep its energy; the implicit-Euler
// recursion loses a factor rho^2 per substep, which is Jolt's algorithm, not
// rounding: the figures give the energy left after 1 s, with 1 and with 4
// substeps (the remedy: rho^(2n) per step tends to 1 - (omega dt)^2 / n).
TEST(StressScenes, SpringsFollowTheImplicitEulerRecursion) {
  for (const char* id : {"spring-0.1", "spring-0.25", "spring-0.5", "spring-1.0"}) {
    for (const int substeps : {1, 4}) {
      SCOPED_TRACE(std::string(id) + ", substeps " + std::to_string(substeps));
      const Scene scene = MakeStressScene(id);
      const auto& spring = std::get<DistanceConstraintSettings>(scene.constraints()[0]);
      StepSettings settings = SceneStepSettings(id);
      settings.substeps = substeps;
      const double h = double(settings.delta_time) / substeps;
      const double omega = 2.0 * std::numbers::pi * spring.limits_spring.frequency_or_stiffness;
      const double rho = 1.0 / std::sqrt(1.0 + h * h * omega * omega);
      const double x0 = stress_scene::kSpringStart;
      const double tolerance = 8.0 * FLT_EPSILON * x0 / (1.0 - rho);
      const double energy0 = 0.5 * omega * omega * x0 * x0;  // per kg
      const long one_second = std::lround(1.0 / double(settings.delta_time));
      double x = x0, v = 0, worst = 0, energy_after_1s = 0;
      bool off_axis = false;
      const Figures f = RunScene(id, settings, [&](long step, const std::vector<float>& state) {
        for (int i = 0; i < substeps; ++i) {
          v = (v - h * omega * omega * x) / (1.0 + h * h * omega * omega);
          x += h * v;
        }
        const BodyState sphere = BodyOf(state, stress_scene::kBody);
        worst = std::max(worst, std::abs(sphere.position.x - x));
        off_axis |= sphere.position.y != 0.0 || sphere.position.z != 0.0;
        if (step + 1 == one_second) {
          energy_after_1s = 0.5 * (Dot(sphere.linear, sphere.linear) +
                                   omega * omega * Dot(sphere.position, sphere.position));
        }
      });
      const std::string label = "substeps" + std::to_string(substeps) + ".";
      Report(id, label + "max_error_vs_recursion_m", worst);
      Report(id, label + "recursion_tolerance_m", tolerance);
      Report(id, label + "energy_left_after_1s", energy_after_1s / energy0);
      if (substeps == 1) {
        Report(id, "spring_frequency_hz", spring.limits_spring.frequency_or_stiffness);
        Report(id, "decay_per_step_rho", rho);
      }
      ASSERT_TRUE(f.finite);
      EXPECT_LE(worst, tolerance);
      EXPECT_FALSE(off_axis);
    }
  }
}

// Euler's equations of a torque-free body in its principal frame, I w' = -w x
// I w, by classical RK4 with 1e-4 s steps in double (its error over 10 s is
// far below anything compared here): the exact motion of spin-unstable.
struct ExactSpin {
  V3 inertia, w;
  void Advance(double dt) {
    const auto f = [&](V3 a) {
      const V3 t = Cross(a, {inertia.x * a.x, inertia.y * a.y, inertia.z * a.z});
      return V3{-t.x / inertia.x, -t.y / inertia.y, -t.z / inertia.z};
    };
    constexpr double kH = 1e-4;
    for (long i = 0, n = std::lround(dt / kH); i < n; ++i) {
      const V3 k1 = f(w), k2 = f(Add(w, Scale(k1, kH / 2))), k3 = f(Add(w, Scale(k2, kH / 2))),
               k4 = f(Add(w, Scale(k3, kH)));
      w = Add(w, Scale(Add(Add(k1, Scale(Add(k2, k3), 2.0)), k4), kH / 6));
    }
  }
};

// What the spin of spin-unstable did: sign changes of w about the middle axis
// in the body frame (flips), the time of the first, the worst relative change
// of the kinetic energy and of the world angular momentum.
struct Spin {
  int flips = 0;
  double first_flip = kInfinity, energy_drift = 0, momentum_drift = 0;
};

Spin RunSpin(const StepSettings& settings, const std::string& label) {
  const Scene scene = MakeStressScene("spin-unstable");
  const BodySettings& body = scene.bodies()[stress_scene::kBody];
  const V3 w0{body.angular_velocity[0], body.angular_velocity[1], body.angular_velocity[2]};
  const Float3& i = body.inertia_diagonal;
  const V3 l0{i[0] * w0.x, i[1] * w0.y, i[2] * w0.z};
  const double e0 = 0.5 * Dot(w0, l0);
  Spin spin;
  double sign = 1;
  const auto each_step = [&](long step, const std::vector<float>& s) {
    const BodyState state = BodyOf(s, stress_scene::kBody);
    const V3 w = BodyAngularVelocity(state);
    const V3 l = AngularMomentum(body, state);
    spin.energy_drift = std::max(
        spin.energy_drift,
        std::abs(0.5 * (i[0] * w.x * w.x + i[1] * w.y * w.y + i[2] * w.z * w.z) / e0 - 1));
    spin.momentum_drift = std::max(spin.momentum_drift, Length(Sub(l, l0)) / Length(l0));
    if (w.y * sign < 0) {
      sign = -sign;
      ++spin.flips;
      spin.first_flip = std::min(spin.first_flip, double(step + 1) * settings.delta_time);
    }
  };
  const Figures f = RunScene("spin-unstable", settings, each_step);
  EXPECT_TRUE(f.finite) << label;
  Report("spin-unstable", label + ".flips", spin.flips);
  Report("spin-unstable", label + ".first_flip_s", spin.first_flip);
  Report("spin-unstable", label + ".energy_drift_rel", spin.energy_drift);
  Report("spin-unstable", label + ".world_momentum_drift_rel", spin.momentum_drift);
  return spin;
}

// Jolt's integration has no gyroscopic term: w stays fixed in the world and
// the body turns about it, so w stays on the middle axis in the body frame and
// the body never flips, while the exact motion flips 19 times in 10 s. With
// StepSettings::gyroscopic the flips come back: the same count within one (a
// flip may move across the end of the window), the first within two steps of
// the exact time, the kinetic energy kept to rounding (4 FLT_EPSILON per step
// over 600 steps). The world angular momentum is printed, not bounded: with
// the gyroscopic step the rotation update (w at the end of the step held for
// the whole step) is first order in h, so L turns by up to a quarter at 60 Hz
// (docs/stability.md).
TEST(StressScenes, UnstableAxisSpin) {
  const Scene scene = MakeStressScene("spin-unstable");
  const BodySettings& body = scene.bodies()[stress_scene::kBody];
  ExactSpin exact{{body.inertia_diagonal[0], body.inertia_diagonal[1], body.inertia_diagonal[2]},
                  {body.angular_velocity[0], body.angular_velocity[1], body.angular_velocity[2]}};
  int exact_flips = 0;
  double exact_first = kInfinity, sign = 1;
  const double h = SceneStepSettings("spin-unstable").delta_time;
  for (int step = 0; step < std::lround(kSeconds / h); ++step) {
    exact.Advance(h);
    if (exact.w.y * sign < 0) {
      sign = -sign;
      ++exact_flips;
      exact_first = std::min(exact_first, (step + 1) * h);
    }
  }
  Report("spin-unstable", "exact.flips", exact_flips);
  Report("spin-unstable", "exact.first_flip_s", exact_first);
  ASSERT_GE(exact_flips, 10);

  const Spin jolt = RunSpin(SceneStepSettings("spin-unstable"), "default");
  EXPECT_EQ(jolt.flips, 0) << "Jolt's integration has no gyroscopic term";

  StepSettings gyroscopic = SceneStepSettings("spin-unstable");
  gyroscopic.gyroscopic = true;
  const Spin remedy = RunSpin(gyroscopic, "gyroscopic");
  EXPECT_NEAR(remedy.flips, exact_flips, 1);
  EXPECT_NEAR(remedy.first_flip, exact_first, 2 * h);
  EXPECT_LT(remedy.energy_drift, 4.0 * FLT_EPSILON * kSeconds / h);

  gyroscopic.substeps = 4;  // for the docs' table: the momentum error is first order
  RunSpin(gyroscopic, "gyroscopic_substeps4");
}

}  // namespace
}  // namespace manyworlds
