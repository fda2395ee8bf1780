// What `manyworlds sweep` measured and how it is reported (see sweep.h): the
// knob settings, one row of measurements per scene and setting, and the
// writers of sweep.csv, sweep.md and sweep.gp.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <ostream>
#include <string>
#include <vector>

#include "manyworlds/batch.h"

namespace manyworlds::tools {

// ---- the settings swept

struct Knobs {
  int substeps = 1;
  int velocity_iterations = 10;
  int position_iterations = 2;
};
inline constexpr Knobs kDefaultKnobs{};

// The knobs of the plots' curves: a setting lies on a knob's curve when every
// other knob has its default value.
enum class Knob { kSubsteps, kVelocityIterations, kPositionIterations };
inline constexpr Knob kKnobs[] = {Knob::kSubsteps, Knob::kVelocityIterations,
                                  Knob::kPositionIterations};

const char* KnobName(Knob knob);    // as in the CSV: "velocity_iterations"
const char* CurveTitle(Knob knob);  // as in the plots: "velocity iterations"
int KnobValue(const Knobs& k, Knob knob);
bool OnCurve(const Knobs& k, Knob knob);
// The CSV's knob column: "default", the one knob that differs from the
// default, or "grid" when several do.
std::string KnobLabel(const Knobs& k);
std::string SettingText(const Knobs& k);  // "1 / 10 / 2"

// ---- the command's options

// Every field is set by the command's option parsing, which holds the defaults.
struct SweepConfig {
  std::vector<std::string> scenes;
  std::size_t worlds = 0;
  std::size_t sample_worlds = 0;
  double seconds = 0.0;
  int passes = 0;
  double min_time = 0.0;
  int threads = 0;
  bool full_grid = false;
  bool small = false;
  bool overwrite = false;  // replace an earlier report in `out`
  std::uint64_t seed = 0;
  double mass_range_limit = 0.0;  // LimitMassRange on every scene first; 0: off
  // --solver exact: every setting with JointSolver::kExact (position
  // iterations are then its Newton steps; velocity iterations its block
  // Gauss-Seidel passes around bounded rows, nothing without them).
  JointSolver solver = JointSolver::kGaussSeidel;
  std::filesystem::path out;
  std::string command_line;
};

// Steps of one run: the simulated seconds at the settings' dt.
std::uint64_t StepsPerRun(const SweepConfig& config, const StepSettings& settings);

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
  // A scene without rows of a kind (spin-unstable has no constraint) has no
  // error of that kind: 0, as Max().
  double Rms() const {
    if (non_finite_) return kNaN;
    return count_ == 0 ? 0.0 : std::sqrt(sum_squares_ / double(count_));
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
  StepSettings settings;  // the knobs applied to the scene's step settings
  double ns_per_world_step = 0.0;
  ErrorStats position, velocity, trajectory_position, trajectory_rotation, energy, coupling;
  bool has_energy = false, has_coupling = false;
  double energy_drift_final = 0.0;  // signed, mean over the sample worlds (J)
  std::size_t unhealthy_worlds = 0;
};

struct Machine {
  std::string target;
  std::size_t lanes = 0;
  int threads = 0;
  std::string clock;  // what the cost was timed with
};

// ---- reports

std::string Number(double value);  // %.4g, or "nan"

// The CSV header line (without newline).
std::string SweepCsvHeader();
void WriteCsv(std::ostream& csv, const std::vector<Row>& rows, const SweepConfig& config,
              const Machine& machine);
// `wall_seconds`: what the whole sweep took.
void WriteMarkdown(std::ostream& md, const std::vector<Row>& rows, const SweepConfig& config,
                   const Machine& machine, double wall_seconds);
// The plot of a scene in the report's folder: <scene>.png, '/' in the id as '_'.
std::string PlotFileName(std::string scene);
// A gnuplot script with the data inline, drawing PlotFileName(scene) in its
// directory.
void WriteGnuplot(std::ostream& gp, const std::vector<Row>& rows, const SweepConfig& config,
                  const Machine& machine);

}  // namespace manyworlds::tools
