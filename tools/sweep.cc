// `manyworlds sweep`: error against run time (see sweep.h).

#include "tools/sweep.h"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <ctime>  // also POSIX clock_gettime
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <span>
#include <sstream>
#include <string>
#include <vector>

#include "manyworlds/batch.h"
#include "manyworlds/scene.h"
#include "manyworlds/scenes.h"
#include "reference/world.h"
#include "tools/options.h"
#include "tools/sweep_metrics.h"

namespace manyworlds::tools {

std::vector<std::string> SweepSceneIds() { return ReferenceSceneIds(); }

namespace {

using Clock = std::chrono::steady_clock;

// The step settings every knob setting starts from: the spec's defaults for
// every reference scene.
StepSettings BaseSettings() { return StepSettings{}; }

// ---- the settings swept

struct Knobs {
  int substeps = 1;
  int velocity_iterations = 10;
  int position_iterations = 2;
};
constexpr Knobs kDefaultKnobs{};

struct KnobValues {
  std::vector<int> substeps, velocity_iterations, position_iterations;
};

KnobValues ValuesOf(bool small) {
  if (small) return {{1, 2}, {1, 10}, {0, 2}};
  return {{1, 2, 4, 8}, {1, 2, 4, 8, 10}, {0, 1, 2}};
}

// One knob at a time from the default (the default itself once), or every
// combination. One-at-a-time gives the curves of the plots at a tenth of the
// grid's cost; the grid shows how the knobs combine.
std::vector<Knobs> SettingsOf(const KnobValues& values, bool full_grid) {
  std::vector<Knobs> settings;
  if (full_grid) {
    for (int s : values.substeps) {
      for (int v : values.velocity_iterations) {
        for (int p : values.position_iterations) settings.push_back({s, v, p});
      }
    }
    return settings;
  }
  settings.push_back(kDefaultKnobs);
  for (int s : values.substeps) {
    if (s != kDefaultKnobs.substeps) settings.push_back({s, kDefaultKnobs.velocity_iterations,
                                                         kDefaultKnobs.position_iterations});
  }
  for (int v : values.velocity_iterations) {
    if (v != kDefaultKnobs.velocity_iterations) {
      settings.push_back({kDefaultKnobs.substeps, v, kDefaultKnobs.position_iterations});
    }
  }
  for (int p : values.position_iterations) {
    if (p != kDefaultKnobs.position_iterations) {
      settings.push_back({kDefaultKnobs.substeps, kDefaultKnobs.velocity_iterations, p});
    }
  }
  return settings;
}

// The knobs of the plots' curves: a setting lies on a knob's curve when every
// other knob has its default value.
enum class Knob { kSubsteps, kVelocityIterations, kPositionIterations };
constexpr Knob kKnobs[] = {Knob::kSubsteps, Knob::kVelocityIterations,
                           Knob::kPositionIterations};

const char* KnobName(Knob knob) {
  switch (knob) {
    case Knob::kSubsteps: return "substeps";
    case Knob::kVelocityIterations: return "velocity_iterations";
    case Knob::kPositionIterations: return "position_iterations";
  }
  return "";
}

int KnobValue(const Knobs& k, Knob knob) {
  switch (knob) {
    case Knob::kSubsteps: return k.substeps;
    case Knob::kVelocityIterations: return k.velocity_iterations;
    case Knob::kPositionIterations: return k.position_iterations;
  }
  return 0;
}

const char* CurveTitle(Knob knob) {
  switch (knob) {
    case Knob::kSubsteps: return "substeps";
    case Knob::kVelocityIterations: return "velocity iterations";
    case Knob::kPositionIterations: return "position iterations";
  }
  return "";
}

bool OnCurve(const Knobs& k, Knob knob) {
  for (Knob other : kKnobs) {
    if (other != knob && KnobValue(k, other) != KnobValue(kDefaultKnobs, other)) return false;
  }
  return true;
}

// The CSV's knob column: which curve the setting belongs to.
std::string KnobLabel(const Knobs& k) {
  std::string label;
  int differing = 0;
  for (Knob knob : kKnobs) {
    if (KnobValue(k, knob) != KnobValue(kDefaultKnobs, knob)) {
      ++differing;
      label = KnobName(knob);
    }
  }
  return differing == 0 ? "default" : differing == 1 ? label : "grid";
}

StepSettings StepSettingsOf(const Knobs& k) {
  StepSettings settings = BaseSettings();
  settings.substeps = k.substeps;
  settings.velocity_iterations = k.velocity_iterations;
  settings.position_iterations = k.position_iterations;
  return settings;
}

// The reference of the trajectory error: dt/16 and 4x the default iterations.
StepSettings FineSettings() {
  StepSettings settings = BaseSettings();
  settings.substeps = 16 * kDefaultKnobs.substeps;
  settings.velocity_iterations = 4 * kDefaultKnobs.velocity_iterations;
  settings.position_iterations = 4 * kDefaultKnobs.position_iterations;
  return settings;
}

// ---- options

// Every field is set by ConfigOf, which holds the defaults.
struct Config {
  std::vector<std::string> scenes;
  std::size_t worlds = 0;
  std::size_t sample_worlds = 0;
  double seconds = 0.0;
  int passes = 0;
  double min_time = 0.0;
  int threads = 0;
  bool full_grid = false;
  bool small = false;
  std::uint64_t seed = 0;
  std::filesystem::path out;
  std::string command_line;
};

std::vector<std::string> SplitIds(const std::string& text) {
  std::vector<std::string> ids;
  std::stringstream stream(text);
  for (std::string id; std::getline(stream, id, ',');) {
    if (!id.empty()) ids.push_back(id);
  }
  return ids;
}

Config ConfigOf(int argc, char** argv) {
  const Options options(argc, argv,
                        {"--scenes", "--worlds", "--sample-worlds", "--seconds", "--passes",
                         "--min-time", "--threads", "--grid", "--out", "--seed"},
                        {"--small"});
  Config config;
  config.small = options.Has("--small");
  // --small: the smoke test's size, a few seconds in all.
  config.scenes = SplitIds(options.Text(
      "--scenes", config.small ? "rackpinion,chain16" : ""));
  if (config.scenes.empty()) config.scenes = SweepSceneIds();
  const std::vector<std::string> known = SweepSceneIds();
  for (const std::string& id : config.scenes) {
    if (std::find(known.begin(), known.end(), id) == known.end()) {
      std::string list;
      for (const std::string& k : known) list += (list.empty() ? "" : ", ") + k;
      throw UsageError("--scenes: unknown scene '" + id + "' (known: " + list + ")");
    }
  }
  config.worlds = options.Number("--worlds", config.small ? 64 : 1024, 1, std::uint64_t(1) << 24);
  config.sample_worlds =
      options.Number("--sample-worlds", config.small ? 4 : 16, 1, 4096);
  config.sample_worlds = std::min(config.sample_worlds, config.worlds);
  // 1 s: long enough for drift to show, short enough that the chains' chaos
  // (they are multiple pendulums) does not swamp the trajectory error.
  config.seconds = options.Real("--seconds", config.small ? 0.25 : 1.0, 1e-3, 3600.0);
  config.passes = int(options.Number("--passes", config.small ? 1 : 3, 1, 1000));
  config.min_time = options.Real("--min-time", config.small ? 0.01 : 0.1, 0.0, 3600.0);
  config.threads = int(options.Number("--threads", 1, 0, 4096));
  const std::string grid = options.Text("--grid", "knobs");
  if (grid != "knobs" && grid != "full") {
    throw UsageError("--grid = '" + grid + "': expected 'knobs' or 'full'");
  }
  config.full_grid = grid == "full";
  config.seed = options.Number("--seed", 1, 0, UINT64_MAX);
  config.out = options.Text("--out", "sweep");
  for (int i = 0; i < argc; ++i) config.command_line += (i ? " " : "") + std::string(argv[i]);
  return config;
}

// ---- measurements

// Max and RMS of a non-negative error over many samples; a non-finite sample
// (a world that blew up) makes both NaN, so it cannot pass for accuracy.
class ErrorStats {
 public:
  void Add(double e) {
    if (!std::isfinite(e)) {
      non_finite_ = true;
      return;
    }
    max_ = std::max(max_, e);
    sum_squares_ += e * e;
    ++count_;
  }
  double Max() const { return non_finite_ ? kNaN : max_; }
  double Rms() const {
    return non_finite_ || count_ == 0 ? kNaN : std::sqrt(sum_squares_ / double(count_));
  }

 private:
  static constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  double max_ = 0.0, sum_squares_ = 0.0;
  std::size_t count_ = 0;
  bool non_finite_ = false;
};

struct Row {
  std::string scene;
  Knobs knobs;
  double ns_per_world_step = 0.0;
  ErrorStats position, velocity, trajectory_position, trajectory_rotation, energy, coupling;
  bool has_energy = false, has_coupling = false;
  double energy_drift_final = 0.0;  // signed, mean over the sample worlds (J)
  std::size_t unhealthy_worlds = 0;
};

// Body states of the sample worlds stepped by reference::World<double> with
// FineSettings(): [step][world][body][13], StateField order.
class ReferenceTrajectory {
 public:
  ReferenceTrajectory(const Scene& scene, const SceneActions& actions, std::size_t worlds,
                      std::uint64_t steps, std::uint64_t seed)
      : worlds_(worlds), stride_(scene.bodies().size() * kStateFloatsPerBody),
        states_(steps * worlds * stride_) {
    const StepSettings fine = FineSettings();
    for (std::size_t w = 0; w < worlds; ++w) {
      reference::World<double> world(scene);
      for (std::uint64_t step = 0; step < steps; ++step) {
        actions.ApplyTo(world, w, step, seed);
        world.Step(fine);
        double* out = &states_[(step * worlds + w) * stride_];
        for (std::size_t b = 0; b < world.body_count(); ++b, out += kStateFloatsPerBody) {
          const reference::Body<double>& body = world.body(b);
          const double values[kStateFloatsPerBody] = {
              body.position.x(),         body.position.y(),         body.position.z(),
              body.rotation.x(),         body.rotation.y(),         body.rotation.z(),
              body.rotation.w(),         body.linear_velocity.x(),  body.linear_velocity.y(),
              body.linear_velocity.z(),  body.angular_velocity.x(), body.angular_velocity.y(),
              body.angular_velocity.z()};
          std::copy(std::begin(values), std::end(values), out);
        }
      }
    }
  }

  std::span<const double> State(std::uint64_t step, std::size_t world) const {
    return std::span<const double>(states_).subspan((step * worlds_ + world) * stride_, stride_);
  }

 private:
  std::size_t worlds_, stride_;
  std::vector<double> states_;
};

struct Machine {
  std::string target;
  std::size_t lanes = 0;
  int threads = 0;
  std::string clock;  // what the cost was timed with
};

// Seconds of CPU time used by this process so far. On 1 thread that is the
// cost of the steps alone: the time other programs on a shared machine take
// the core away does not count (wall time on this build machine varied 2x
// between passes of the same setting).
double ProcessCpuSeconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

double WallSeconds() {
  return std::chrono::duration<double>(Clock::now().time_since_epoch()).count();
}

// ns per world-step of Batch::Step with the scene's actions, one pass (see
// sweep.h): an untimed warm-up round, then timed rounds until --min-time;
// the fastest round. Process CPU time on 1 thread, wall time on more (where
// CPU time would add up the threads).
double TimeSteps(const Scene& scene, const SceneActions& actions, const Config& config,
                 std::uint64_t steps, const StepSettings& settings, Machine& machine) {
  Batch batch(scene, config.worlds, BatchOptions{.threads = config.threads});
  const bool cpu_time = batch.threads() == 1;
  machine = Machine{batch.SimdTarget(), batch.SimdLanes(), batch.threads(),
                    cpu_time ? "process CPU time" : "wall time"};
  const auto now = cpu_time ? ProcessCpuSeconds : WallSeconds;
  const std::vector<std::uint8_t> every_world(config.worlds, 1);
  double fastest = std::numeric_limits<double>::infinity(), timed = 0.0;
  for (int round = 0; round < 2 || timed < config.min_time; ++round) {
    batch.Reset(every_world);  // every round times the same steps
    const double start = now();
    for (std::uint64_t step = 0; step < steps; ++step) {
      actions.Apply(batch, step, config.seed);
      batch.Step(settings);
    }
    const double seconds = now() - start;
    if (round == 0) continue;  // warm-up: page faults, caches, TBB's threads
    fastest = std::min(fastest, seconds);
    timed += seconds;
  }
  return fastest * 1e9 / (double(config.worlds) * double(steps));
}

// The accuracy metrics of one setting over the sample worlds (see sweep.h).
void MeasureAccuracy(const Scene& scene, const SceneActions& actions, const Config& config,
                     std::uint64_t steps, const StepSettings& settings,
                     const ReferenceTrajectory& reference, Row& row) {
  const std::size_t worlds = config.sample_worlds;
  Batch batch(scene, worlds, BatchOptions{.threads = 1});
  const std::size_t stride = batch.body_count() * kStateFloatsPerBody;
  std::vector<float> state(worlds * stride);
  const auto world_state = [&](std::size_t w) {
    return std::span<const float>(state).subspan(w * stride, stride);
  };
  const std::vector<std::size_t> couplings = CouplingConstraints(scene);
  row.has_energy = EnergyIsConserved(scene, actions);
  row.has_coupling = !couplings.empty();

  batch.GetState(state);
  std::vector<double> initial_energy(worlds);
  for (std::size_t w = 0; w < worlds; ++w) {
    initial_energy[w] = MechanicalEnergy(scene, world_state(w), settings.gravity);
  }
  std::vector<std::uint8_t> ever_unhealthy(worlds, 0);
  double final_drift = 0.0;
  for (std::uint64_t step = 0; step < steps; ++step) {
    actions.Apply(batch, step, config.seed);
    batch.Step(settings);
    batch.GetState(state);
    const std::span<const std::uint8_t> health = batch.WorldHealth();
    for (std::size_t w = 0; w < worlds; ++w) {
      ever_unhealthy[w] |= health[w];
      for (std::size_t c = 0; c < batch.constraint_count(); ++c) {
        row.position.Add(batch.ConstraintError(w, c));
        row.velocity.Add(batch.ConstraintVelocityError(w, c));
      }
      for (std::size_t c : couplings) row.coupling.Add(batch.ConstraintError(w, c));
      const PoseError pose = BodyPoseError(scene, world_state(w), reference.State(step, w));
      row.trajectory_position.Add(pose.position);
      row.trajectory_rotation.Add(pose.rotation);
      if (row.has_energy) {
        const double drift =
            MechanicalEnergy(scene, world_state(w), settings.gravity) - initial_energy[w];
        row.energy.Add(std::abs(drift));
        if (step + 1 == steps) final_drift += drift;
      }
    }
  }
  row.energy_drift_final = final_drift / double(worlds);
  row.unhealthy_worlds =
      std::size_t(std::count_if(ever_unhealthy.begin(), ever_unhealthy.end(),
                                [](std::uint8_t bits) { return bits != 0; }));
}

// ---- output

std::string Number(double value) {
  if (std::isnan(value)) return "nan";
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", value);
  return text;
}

std::string CsvRow(const Row& r, const Config& config, const Machine& machine) {
  std::ostringstream line;
  const auto optional = [](bool present, double value) {
    return present ? Number(value) : std::string();
  };
  line << r.scene << ',' << KnobLabel(r.knobs) << ',' << r.knobs.substeps << ','
       << r.knobs.velocity_iterations << ',' << r.knobs.position_iterations << ','
       << Number(double(BaseSettings().delta_time)) << ',' << config.worlds << ','
       << machine.threads << ',' << machine.target << ',' << Number(r.ns_per_world_step) << ','
       << Number(r.position.Max()) << ',' << Number(r.position.Rms()) << ','
       << Number(r.velocity.Max()) << ',' << Number(r.velocity.Rms()) << ','
       << Number(r.trajectory_position.Rms()) << ',' << Number(r.trajectory_position.Max())
       << ',' << Number(r.trajectory_rotation.Rms()) << ','
       << Number(r.trajectory_rotation.Max()) << ',' << optional(r.has_energy, r.energy.Max())
       << ',' << optional(r.has_energy, r.energy_drift_final) << ','
       << optional(r.has_coupling, r.coupling.Max()) << ','
       << optional(r.has_coupling, r.coupling.Rms()) << ',' << r.unhealthy_worlds;
  return line.str();
}

std::string UtcNow() {
  const std::time_t now = std::time(nullptr);
  std::tm utc{};
  gmtime_r(&now, &utc);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%d %H:%M UTC", &utc);
  return text;
}

std::string SettingText(const Knobs& k) {
  return std::to_string(k.substeps) + " / " + std::to_string(k.velocity_iterations) + " / " +
         std::to_string(k.position_iterations);
}

void WriteMarkdown(std::ostream& md, const std::vector<Row>& rows, const Config& config,
                   const Machine& machine, std::uint64_t steps, double wall_seconds) {
  const StepSettings base = BaseSettings();
  md << "# Error against run time\n\n"
     << "`" << config.command_line << "`, " << UtcNow() << ", " << Number(wall_seconds)
     << " s wall.\n\n"
     << "- cost: ns per world-step of `Batch::Step`, " << config.worlds << " worlds, "
     << machine.threads << " thread(s), SIMD target " << machine.target << " ("
     << machine.lanes << " float lanes), float, dt " << Number(double(base.delta_time))
     << " s, Baumgarte " << Number(double(base.baumgarte))
     << ", actions every step, timed with " << machine.clock << "; the fastest of "
     << config.passes
     << " pass(es) over every setting, each an untimed warm-up round and then rounds of "
     << steps << " steps until " << Number(config.min_time) << " s\n"
     << "- errors: over " << config.sample_worlds << " worlds and every step of "
     << Number(config.seconds) << " s simulated (" << steps << " steps); trajectory against "
     << "`reference::World<double>` with dt/16 (16 substeps) and 40 velocity + 8 position "
     << "iterations\n"
     << "- setting: substeps / velocity iterations / position iterations (default 1 / 10 / "
        "2); position error in m for linear rows and rad for angular rows, velocity residual "
        "in m/s and rad/s (largest row group per constraint, over constraints, worlds and "
        "steps); energy drift |E(t) - E(0)| in J; coupling error in rad\n";
  if (config.full_grid) {
    md << "- the tables list the settings on the knobs' curves; sweep.csv has every "
          "combination\n";
  }
  std::vector<std::string> scenes;
  for (const Row& r : rows) {
    if (std::find(scenes.begin(), scenes.end(), r.scene) == scenes.end()) {
      scenes.push_back(r.scene);
    }
  }
  for (const std::string& scene : scenes) {
    const Row* first = nullptr;
    for (const Row& r : rows) {
      if (r.scene == scene) {
        first = &r;
        break;
      }
    }
    md << "\n## " << scene << "\n\n"
       << "| setting | ns / world-step | position error max | position error RMS | "
          "velocity residual RMS | trajectory RMS (m) | trajectory RMS (rad) |";
    if (first->has_energy) md << " energy drift max (J) | energy drift at end (J) |";
    if (first->has_coupling) md << " coupling error max (rad) | coupling error RMS (rad) |";
    md << " unhealthy worlds |\n|---|---|---|---|---|---|---|";
    if (first->has_energy) md << "---|---|";
    if (first->has_coupling) md << "---|---|";
    md << "---|\n";
    for (const Row& r : rows) {
      if (r.scene != scene || KnobLabel(r.knobs) == "grid") continue;
      md << "| " << SettingText(r.knobs) << " | " << Number(r.ns_per_world_step) << " | "
         << Number(r.position.Max()) << " | " << Number(r.position.Rms()) << " | "
         << Number(r.velocity.Rms()) << " | " << Number(r.trajectory_position.Rms()) << " | "
         << Number(r.trajectory_rotation.Rms()) << " |";
      if (r.has_energy) {
        md << ' ' << Number(r.energy.Max()) << " | " << Number(r.energy_drift_final) << " |";
      }
      if (r.has_coupling) {
        md << ' ' << Number(r.coupling.Max()) << " | " << Number(r.coupling.Rms()) << " |";
      }
      md << ' ' << r.unhealthy_worlds << " |\n";
    }
  }
}

// A gnuplot identifier from a scene id (chain16-r100 -> chain16_r100).
std::string Identifier(std::string id) {
  std::replace_if(
      id.begin(), id.end(), [](char c) { return !std::isalnum(static_cast<unsigned char>(c)); },
      '_');
  return id;
}

// The metrics plotted, one panel each; `applies` false: not measured for
// this scene.
struct PlotMetric {
  const char* title;
  double (*value)(const Row&);
  bool (*applies)(const Row&);
};
bool Always(const Row&) { return true; }
const PlotMetric kPlotMetrics[] = {
    {"position error RMS (m, rad)", [](const Row& r) { return r.position.Rms(); }, Always},
    {"position error max (m, rad)", [](const Row& r) { return r.position.Max(); }, Always},
    {"velocity residual |Jv| RMS (m/s, rad/s)", [](const Row& r) { return r.velocity.Rms(); },
     Always},
    {"trajectory error RMS (m)", [](const Row& r) { return r.trajectory_position.Rms(); },
     Always},
    {"trajectory error RMS (rad)", [](const Row& r) { return r.trajectory_rotation.Rms(); },
     Always},
    {"energy drift max (J)", [](const Row& r) { return r.energy.Max(); },
     [](const Row& r) { return r.has_energy; }},
    {"coupling error RMS (rad)", [](const Row& r) { return r.coupling.Rms(); },
     [](const Row& r) { return r.has_coupling; }},
};
constexpr int kMetricCount = int(std::size(kPlotMetrics));

// Data block columns (1-based, as gnuplot counts): 1 the knob's value, 2 ns
// per world-step, then one per metric (NaN where it does not apply), last
// whether it is the default setting (labelled once, not once per curve).
constexpr int kFirstMetricColumn = 3;
constexpr int kDefaultColumn = kFirstMetricColumn + kMetricCount;

std::string DataLine(const Row& r, int knob_value) {
  const auto number = [](double v) { return std::isnan(v) ? std::string("NaN") : Number(v); };
  std::string line = std::to_string(knob_value) + ' ' + number(r.ns_per_world_step);
  for (const PlotMetric& metric : kPlotMetrics) {
    line += ' ' + (metric.applies(r) ? number(metric.value(r)) : std::string("NaN"));
  }
  return line + ' ' + (KnobLabel(r.knobs) == "default" ? '1' : '0') + '\n';
}

void WriteGnuplot(std::ostream& gp, const std::vector<Row>& rows, const Config& config,
                  const Machine& machine) {
  gp << "# Error against ns per world-step, one curve per knob: written by\n"
     << "# " << config.command_line << "\n# Run: gnuplot sweep.gp (in this directory).\n"
     << "set terminal pngcairo noenhanced size 1500,900 font ',10'\n"
     << "set logscale xy\nset grid\nset format y '%.0e'\nset key below horizontal\n"
     << "set xlabel 'ns per world-step (" << config.worlds << " worlds, " << machine.threads
     << " thread(s), " << machine.target << ")'\n";
  std::vector<std::string> scenes;
  for (const Row& r : rows) {
    if (std::find(scenes.begin(), scenes.end(), r.scene) == scenes.end()) {
      scenes.push_back(r.scene);
    }
  }
  for (const std::string& scene : scenes) {
    const std::string id = Identifier(scene);
    for (Knob knob : kKnobs) {
      gp << '$' << id << '_' << KnobName(knob) << " << EOD\n";
      std::vector<const Row*> curve;
      for (const Row& r : rows) {
        if (r.scene == scene && OnCurve(r.knobs, knob)) curve.push_back(&r);
      }
      std::sort(curve.begin(), curve.end(), [knob](const Row* a, const Row* b) {
        return KnobValue(a->knobs, knob) < KnobValue(b->knobs, knob);
      });
      for (const Row* r : curve) gp << DataLine(*r, KnobValue(r->knobs, knob));
      gp << "EOD\n";
    }
    gp << '$' << id << "_default << EOD\n";
    for (const Row& r : rows) {
      if (r.scene == scene && KnobLabel(r.knobs) == "default") gp << DataLine(r, 0);
    }
    gp << "EOD\n";
    if (config.full_grid) {
      gp << '$' << id << "_grid << EOD\n";
      for (const Row& r : rows) {
        if (r.scene == scene) gp << DataLine(r, 0);
      }
      gp << "EOD\n";
    }
    // A panel only for a metric with a positive value somewhere: a log axis
    // cannot show zeros (e.g. geartrain's gears never leave their axles, so
    // its position trajectory error is exactly 0); the table has them.
    std::vector<int> panels;
    for (int m = 0; m < kMetricCount; ++m) {
      for (const Row& r : rows) {
        if (r.scene == scene && kPlotMetrics[m].applies(r) && kPlotMetrics[m].value(r) > 0.0) {
          panels.push_back(m);
          break;
        }
      }
    }
    gp << "set output '" << scene << ".png'\n"
       << "set multiplot layout " << (panels.size() + 2) / 3 << ",3 title '" << scene
       << ": error against cost, one knob varied at a time from the default (labels: its "
          "value)'\n";
    for (int m : panels) {
      const int column = kFirstMetricColumn + m;
      gp << "set title '" << kPlotMetrics[m].title << "'\nplot ";
      if (config.full_grid) {
        gp << '$' << id << "_grid using 2:" << column
           << " with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', ";
      }
      const char* colours[] = {"#1f77b4", "#d62728", "#2ca02c"};
      for (int k = 0; k < 3; ++k) {
        const std::string data = '$' + id + '_' + KnobName(kKnobs[k]);
        gp << (k ? ", " : "") << data << " using 2:" << column
           << " with linespoints pt 7 lc rgb '" << colours[k] << "' title '"
           << CurveTitle(kKnobs[k]) << "', " << data << " using 2:" << column << ":($"
           << kDefaultColumn << " > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6"
           << " tc rgb '" << colours[k] << "' notitle";
      }
      gp << ", $" << id << "_default using 2:" << column
         << " with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'\n";
    }
    gp << "unset multiplot\n";
  }
}

bool GnuplotInstalled() { return std::system("command -v gnuplot > /dev/null 2>&1") == 0; }

}  // namespace

std::string SweepCsvHeader() {
  return "scene,knob,substeps,velocity_iterations,position_iterations,dt,worlds,threads,"
         "simd_target,ns_per_world_step,position_error_max,position_error_rms,"
         "velocity_residual_max,velocity_residual_rms,trajectory_position_rms,"
         "trajectory_position_max,trajectory_rotation_rms,trajectory_rotation_max,"
         "energy_drift_max,energy_drift_final,coupling_error_max,coupling_error_rms,"
         "unhealthy_worlds";
}

int Sweep(int argc, char** argv) {
  const Config config = ConfigOf(argc, argv);
  const auto started = Clock::now();
  const std::vector<Knobs> settings = SettingsOf(ValuesOf(config.small), config.full_grid);
  const std::uint64_t steps = std::max<std::uint64_t>(
      1, std::uint64_t(std::llround(config.seconds / double(BaseSettings().delta_time))));

  // Errors first, setting by setting. Then the cost, in passes over every
  // setting of every scene, each keeping its fastest pass: on a shared
  // machine a busy minute then slows one pass of many settings rather than
  // every measurement of a few.
  std::vector<Row> rows;
  std::vector<Scene> scenes;
  for (const std::string& id : config.scenes) {
    const Scene& scene = scenes.emplace_back(MakeReferenceScene(id));
    const SceneActions actions(id);
    const ReferenceTrajectory reference(scene, actions, config.sample_worlds, steps,
                                        config.seed);
    for (const Knobs& knobs : settings) {
      Row row;
      row.scene = id;
      row.knobs = knobs;
      MeasureAccuracy(scene, actions, config, steps, StepSettingsOf(knobs), reference, row);
      std::printf("%-14s %-12s position error RMS %-9s velocity RMS %-9s trajectory RMS %-9s m\n",
                  id.c_str(), SettingText(knobs).c_str(), Number(row.position.Rms()).c_str(),
                  Number(row.velocity.Rms()).c_str(),
                  Number(row.trajectory_position.Rms()).c_str());
      std::fflush(stdout);
      rows.push_back(std::move(row));
    }
  }
  Machine machine;
  for (int pass = 0; pass < config.passes; ++pass) {
    const auto pass_start = Clock::now();
    for (std::size_t i = 0; i < rows.size(); ++i) {
      Row& row = rows[i];
      const double ns =
          TimeSteps(scenes[i / settings.size()], SceneActions(row.scene), config, steps,
                    StepSettingsOf(row.knobs), machine);
      row.ns_per_world_step = pass == 0 ? ns : std::min(row.ns_per_world_step, ns);
    }
    std::printf("timing pass %d of %d: %.1f s\n", pass + 1, config.passes,
                std::chrono::duration<double>(Clock::now() - pass_start).count());
    std::fflush(stdout);
  }
  const double wall = std::chrono::duration<double>(Clock::now() - started).count();

  std::filesystem::create_directories(config.out);
  {
    std::ofstream csv(config.out / "sweep.csv");
    csv << SweepCsvHeader() << '\n';
    for (const Row& r : rows) csv << CsvRow(r, config, machine) << '\n';
  }
  {
    std::ofstream md(config.out / "sweep.md");
    WriteMarkdown(md, rows, config, machine, steps, wall);
  }
  {
    std::ofstream gp(config.out / "sweep.gp");
    WriteGnuplot(gp, rows, config, machine);
  }
  std::printf("wrote %s/sweep.csv, sweep.md, sweep.gp (%zu settings, %.1f s)\n",
              config.out.c_str(), rows.size(), wall);
  if (!GnuplotInstalled()) {
    std::printf("gnuplot not found: no plots (apt-get install gnuplot-nox, then run "
                "'gnuplot sweep.gp' in %s)\n",
                config.out.c_str());
    return 0;
  }
  const std::string plot = "cd '" + config.out.string() + "' && gnuplot sweep.gp";
  if (std::system(plot.c_str()) != 0) {
    std::fprintf(stderr, "manyworlds: gnuplot failed on %s/sweep.gp\n", config.out.c_str());
    return 1;
  }
  std::printf("plotted %zu scene(s): %s/<scene>.png\n", config.scenes.size(),
              config.out.c_str());
  return 0;
}

}  // namespace manyworlds::tools
