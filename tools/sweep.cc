// `manyworlds sweep`: error against run time (see sweep.h).

#include "tools/sweep.h"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <ctime>  // also POSIX clock_gettime
#include <filesystem>
#include <fstream>
#include <limits>
#include <span>
#include <sstream>
#include <stdexcept>
#include <string>
#include <system_error>
#include <vector>

#include "batch/plan.h"
#include "manyworlds/batch.h"
#include "manyworlds/mass_range.h"
#include "manyworlds/scene.h"
#include "manyworlds/scenes.h"
#include "reference/world.h"
#include "tools/options.h"
#include "tools/subprocess.h"
#include "tools/sweep_metrics.h"
#include "tools/sweep_report.h"

namespace manyworlds::tools {

std::vector<std::string> SweepSceneIds() { return AllSceneIds(); }

namespace {

using Clock = std::chrono::steady_clock;

// The step settings every knob setting starts from: the spec's defaults, or
// a stress scene's own dt.
StepSettings BaseSettings(const std::string& id) { return SceneStepSettings(id); }

// ---- the settings swept


struct KnobValues {
  std::vector<int> substeps, velocity_iterations, position_iterations;
};

KnobValues ValuesOf(bool small, JointSolver solver) {
  // The exact solve's position iterations are Newton steps, of which the
  // heavy chains need 4 to 30 (docs/stepping.md; 0 and 1 give its cheapest
  // settings, for the fronts); its velocity iterations are
  // the block Gauss-Seidel passes around motors, friction and limits (they
  // change nothing in scenes without those, which Sweep skips).
  if (solver == JointSolver::kExact) {
    if (small) return {{1, 2}, {2, 10}, {2, 4}};
    return {{1, 2, 4, 8}, {1, 2, 4, 10}, {0, 1, 2, 4, 10, 30}};
  }
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



StepSettings StepSettingsOf(const std::string& id, const Knobs& k) {
  StepSettings settings = BaseSettings(id);
  settings.substeps = k.substeps;
  settings.velocity_iterations = k.velocity_iterations;
  settings.position_iterations = k.position_iterations;
  return settings;
}

// The reference of the trajectory error: dt/16 and 4x the default iterations.
StepSettings FineSettings(const std::string& id) {
  StepSettings settings = BaseSettings(id);
  settings.substeps = 16 * kDefaultKnobs.substeps;
  settings.velocity_iterations = 4 * kDefaultKnobs.velocity_iterations;
  settings.position_iterations = 4 * kDefaultKnobs.position_iterations;
  return settings;
}

// ---- options


std::vector<std::string> SplitIds(const std::string& text) {
  std::vector<std::string> ids;
  std::stringstream stream(text);
  for (std::string id; std::getline(stream, id, ',');) {
    if (!id.empty()) ids.push_back(id);
  }
  return ids;
}

SweepConfig ConfigOf(int argc, char** argv) {
  const Options options(argc, argv,
                        {"--scenes", "--worlds", "--sample-worlds", "--seconds", "--passes",
                         "--min-time", "--threads", "--grid", "--out", "--seed",
                         "--mass-range-limit", "--solver"},
                        {"--small", "--overwrite"});
  SweepConfig config;
  config.small = options.Has("--small");
  config.overwrite = options.Has("--overwrite");
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
  config.mass_range_limit = tools::MassRangeLimitOption(options);
  const std::string solver = options.Text("--solver", "gauss-seidel");
  if (solver == "exact") {
    config.solver = JointSolver::kExact;
    config.full_grid = true;  // its own values (ValuesOf), every combination
    for (const std::string& id : config.scenes) {
      const StepPlan plan = CompilePlan(MakeScene(id));
      if (!plan.exact.available()) {
        throw UsageError("--solver exact: scene '" + id + "' cannot be solved exactly (" +
                         plan.exact.unavailable + "); pass --scenes without it");
      }
    }
  } else if (solver != "gauss-seidel") {
    throw UsageError("--solver = '" + solver + "': expected 'gauss-seidel' or 'exact'");
  }
  config.out = options.Text("--out", "sweep");
  for (int i = 0; i < argc; ++i) {
    if (i != 0) config.command_line += ' ';
    config.command_line += argv[i];
  }
  return config;
}

// ---- measurements


// Body states of the sample worlds stepped by reference::World<double> with
// FineSettings(id): [step][world][body][13], StateField order.
class ReferenceTrajectory {
 public:
  ReferenceTrajectory(const Scene& scene, const SceneActions& actions, const StepSettings& fine,
                      std::size_t worlds, std::uint64_t steps, std::uint64_t seed)
      : worlds_(worlds), stride_(scene.bodies().size() * kStateFloatsPerBody),
        states_(steps * worlds * stride_) {
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
double TimeSteps(const Scene& scene, const SceneActions& actions, const SweepConfig& config,
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
void MeasureAccuracy(const Scene& scene, const SceneActions& actions, const SweepConfig& config,
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

// ---- the output folder

// The files the sweep writes in its output folder; gnuplot adds the plots.
constexpr const char* kCsvFile = "sweep.csv";
constexpr const char* kMarkdownFile = "sweep.md";
constexpr const char* kGnuplotFile = "sweep.gp";

// Creates the output folder, refuses to replace an earlier report without
// --overwrite, and proves that the folder takes a new file: before the
// stepping (minutes with the defaults) rather than after it. Throws naming
// the folder or the file.
void PrepareOutputFolder(const SweepConfig& config) {
  const std::filesystem::path& folder = config.out;
  std::error_code error;
  std::filesystem::create_directories(folder, error);
  if (error) {
    throw std::runtime_error("cannot create the output folder '" + folder.string() +
                             "': " + error.message());
  }
  if (!config.overwrite) {
    std::vector<std::string> files = {kCsvFile, kMarkdownFile, kGnuplotFile};
    for (const std::string& scene : config.scenes) files.push_back(PlotFileName(scene));
    for (const std::string& file : files) {
      const std::filesystem::path path = folder / file;
      // symlink_status: a link to nowhere would be replaced too.
      if (std::filesystem::exists(std::filesystem::symlink_status(path, error))) {
        throw std::runtime_error("'" + path.string() +
                                 "' exists: pass --overwrite to replace the earlier report");
      }
    }
  }
  // A file of our own, created and removed: whatever would refuse the
  // reports (permissions, a read-only mount, no inode left) refuses it now.
  const std::filesystem::path probe = folder / (".sweep-probe-" + std::to_string(::getpid()));
  const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
  if (fd < 0) {
    throw std::runtime_error("cannot write to the output folder '" + folder.string() +
                             "': " + std::strerror(errno));
  }
  ::close(fd);
  std::filesystem::remove(probe, error);
}

// Writes one report file with `write` and checks that every byte reached
// it: a full disk or a file-size limit shows only when the stream is flushed
// and closed. Throws naming the file, which it removes: a truncated CSV
// must not pass for a report.
template <typename Write>
void WriteReport(const std::filesystem::path& path, Write write) {
  errno = 0;
  std::ofstream file(path);
  write(file);
  file.close();
  if (file) return;
  const int code = errno;
  std::error_code ignored;
  std::filesystem::remove(path, ignored);
  throw std::runtime_error("could not write '" + path.string() + "'" +
                           (code != 0 ? std::string(": ") + std::strerror(code) : ""));
}

}  // namespace

int Sweep(int argc, char** argv) {
  const SweepConfig config = ConfigOf(argc, argv);
  PrepareOutputFolder(config);
  const auto started = Clock::now();
  const std::vector<Knobs> settings =
      SettingsOf(ValuesOf(config.small, config.solver), config.full_grid);

  // Errors first, setting by setting. Then the cost, in passes over every
  // setting of every scene, each keeping its fastest pass: on a shared
  // machine a busy minute then slows one pass of many settings rather than
  // every measurement of a few.
  std::vector<Row> rows;
  std::vector<Scene> scenes;
  std::vector<std::size_t> scene_of_row;  // index into scenes
  for (const std::string& id : config.scenes) {
    Scene& scene = scenes.emplace_back(MakeScene(id));
    // The remedy changes the scene, so the batch and its reference both step
    // the limited one: the rows are the solver's error on it (the model's
    // error is docs/stability.md's).
    if (config.mass_range_limit != 0) LimitMassRange(scene, float(config.mass_range_limit));
    const SceneActions actions(id);
    const std::uint64_t steps = StepsPerRun(config, BaseSettings(id));
    const ReferenceTrajectory reference(scene, actions, FineSettings(id), config.sample_worlds,
                                        steps, config.seed);
    // The exact solve's velocity iterations only count the passes around
    // motors, friction and limits: without those its other values would be
    // the default's rows again.
    const bool velocity_iterations_count =
        config.solver != JointSolver::kExact || !CompilePlan(scene).exact.inequality.empty();
    for (const Knobs& knobs : settings) {
      if (!velocity_iterations_count &&
          knobs.velocity_iterations != kDefaultKnobs.velocity_iterations) {
        continue;
      }
      Row row;
      row.scene = id;
      row.knobs = knobs;
      row.settings = StepSettingsOf(id, knobs);
      row.settings.solver = config.solver;
      MeasureAccuracy(scene, actions, config, steps, row.settings, reference, row);
      std::printf("%-14s %-12s position error RMS %-9s velocity RMS %-9s trajectory RMS %-9s m\n",
                  id.c_str(), SettingText(knobs).c_str(), Number(row.position.Rms()).c_str(),
                  Number(row.velocity.Rms()).c_str(),
                  Number(row.trajectory_position.Rms()).c_str());
      std::fflush(stdout);
      rows.push_back(std::move(row));
      scene_of_row.push_back(scenes.size() - 1);
    }
  }
  Machine machine;
  for (int pass = 0; pass < config.passes; ++pass) {
    const auto pass_start = Clock::now();
    for (std::size_t i = 0; i < rows.size(); ++i) {
      Row& row = rows[i];
      const double ns =
          TimeSteps(scenes[scene_of_row[i]], SceneActions(row.scene), config,
                    StepsPerRun(config, row.settings), row.settings, machine);
      row.ns_per_world_step = pass == 0 ? ns : std::min(row.ns_per_world_step, ns);
    }
    std::printf("timing pass %d of %d: %.1f s\n", pass + 1, config.passes,
                std::chrono::duration<double>(Clock::now() - pass_start).count());
    std::fflush(stdout);
  }
  const double wall = std::chrono::duration<double>(Clock::now() - started).count();

  WriteReport(config.out / kCsvFile,
              [&](std::ostream& csv) { WriteCsv(csv, rows, config, machine); });
  WriteReport(config.out / kMarkdownFile,
              [&](std::ostream& md) { WriteMarkdown(md, rows, config, machine, wall); });
  WriteReport(config.out / kGnuplotFile,
              [&](std::ostream& gp) { WriteGnuplot(gp, rows, config, machine); });
  std::printf("wrote %s/sweep.csv, sweep.md, sweep.gp (%zu settings, %.1f s)\n",
              config.out.c_str(), rows.size(), wall);
  const std::filesystem::path gnuplot = FindOnPath("gnuplot");
  if (gnuplot.empty()) {
    std::printf("gnuplot not found: no plots (apt-get install gnuplot-nox, then run "
                "'gnuplot sweep.gp' in %s)\n",
                config.out.c_str());
    return 0;
  }
  // In the folder: sweep.gp names its PNGs relative to it.
  RunInFolder(gnuplot, {kGnuplotFile}, config.out);
  std::printf("plotted %zu scene(s): %s/<scene>.png ('/' in an id as '_')\n",
              config.scenes.size(),
              config.out.c_str());
  return 0;
}

}  // namespace manyworlds::tools
