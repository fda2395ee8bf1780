// Writers of the sweep's reports (see sweep_report.h).

#include "tools/sweep_report.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <iterator>
#include <sstream>

namespace manyworlds::tools {

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

std::string SettingText(const Knobs& k) {
  return std::to_string(k.substeps) + " / " + std::to_string(k.velocity_iterations) + " / " +
         std::to_string(k.position_iterations);
}

std::uint64_t StepsPerRun(const SweepConfig& config, const StepSettings& settings) {
  return std::max<std::uint64_t>(
      1, std::uint64_t(std::llround(config.seconds / double(settings.delta_time))));
}

std::string Number(double value) {
  if (std::isnan(value)) return "nan";
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", value);
  return text;
}

namespace {


std::string CsvRow(const Row& r, const SweepConfig& config, const Machine& machine) {
  std::ostringstream line;
  const auto optional = [](bool present, double value) {
    return present ? Number(value) : std::string();
  };
  line << r.scene << ',' << KnobLabel(r.knobs) << ',' << r.knobs.substeps << ','
       << r.knobs.velocity_iterations << ',' << r.knobs.position_iterations << ','
       << Number(double(r.settings.delta_time)) << ',' << config.worlds << ','
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

// Text on one line: a line break in a gnuplot script ends the command (or the
// comment) and starts a new one.
std::string OneLine(std::string text) {
  std::replace_if(text.begin(), text.end(), [](char c) { return c == '\n' || c == '\r'; }, ' ');
  return text;
}

// Text as a gnuplot string. Single quotes: gnuplot substitutes neither
// `command` nor @macro in them, and only '' is special.
std::string GnuplotString(const std::string& text) {
  std::string quoted = "'";
  for (const char c : OneLine(text)) {
    if (c == '\'') {
      quoted += "''";
    } else {
      quoted += c;
    }
  }
  return quoted + '\'';
}

// Text as a gnuplot comment line; a backslash at its end would continue the
// comment onto the next line.
std::string GnuplotComment(const std::string& text) {
  const std::string line = OneLine(text);
  return "# " + line + (line.ends_with('\\') ? " \n" : "\n");
}

std::string DataLine(const Row& r, int knob_value) {
  const auto number = [](double v) { return std::isnan(v) ? std::string("NaN") : Number(v); };
  std::string line = std::to_string(knob_value) + ' ' + number(r.ns_per_world_step);
  for (const PlotMetric& metric : kPlotMetrics) {
    line += ' ' + (metric.applies(r) ? number(metric.value(r)) : std::string("NaN"));
  }
  return line + ' ' + (KnobLabel(r.knobs) == "default" ? '1' : '0') + '\n';
}

}  // namespace

std::string PlotFileName(std::string scene) {
  // '/' (dt-1/15) would name a folder.
  std::replace(scene.begin(), scene.end(), '/', '_');
  return scene + ".png";
}

std::string SweepCsvHeader() {
  return "scene,knob,substeps,velocity_iterations,position_iterations,dt,worlds,threads,"
         "simd_target,ns_per_world_step,position_error_max,position_error_rms,"
         "velocity_residual_max,velocity_residual_rms,trajectory_position_rms,"
         "trajectory_position_max,trajectory_rotation_rms,trajectory_rotation_max,"
         "energy_drift_max,energy_drift_final,coupling_error_max,coupling_error_rms,"
         "unhealthy_worlds";
}

void WriteCsv(std::ostream& csv, const std::vector<Row>& rows, const SweepConfig& config,
              const Machine& machine) {
  csv << SweepCsvHeader() << '\n';
  for (const Row& r : rows) csv << CsvRow(r, config, machine) << '\n';
}

void WriteMarkdown(std::ostream& md, const std::vector<Row>& rows, const SweepConfig& config,
                   const Machine& machine, double wall_seconds) {
  md << "# Error against run time\n\n"
     << "`" << config.command_line << "`, " << UtcNow() << ", " << Number(wall_seconds)
     << " s wall.\n\n"
     << "- cost: ns per world-step of `Batch::Step`, " << config.worlds << " worlds, "
     << machine.threads << " thread(s), SIMD target " << machine.target << " ("
     << machine.lanes << " float lanes), float, actions every step, timed with "
     << machine.clock << "; the fastest of " << config.passes
     << " pass(es) over every setting, each an untimed warm-up round and then rounds of "
     << Number(config.seconds) << " s simulated until " << Number(config.min_time) << " s\n"
     << "- errors: over " << config.sample_worlds << " worlds and every step of "
     << Number(config.seconds) << " s simulated; trajectory against "
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
  if (config.mass_range_limit != 0) {
    md << "- scenes changed by the mass-range limit " << Number(config.mass_range_limit)
       << " (`LimitMassRange`, docs/stability.md) before stepping; batch and reference step "
          "the changed scene\n";
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
       << "dt " << Number(double(first->settings.delta_time)) << " s ("
       << StepsPerRun(config, first->settings) << " steps), Baumgarte "
       << Number(double(first->settings.baumgarte)) << ".\n\n"
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

void WriteGnuplot(std::ostream& gp, const std::vector<Row>& rows, const SweepConfig& config,
                  const Machine& machine) {
  gp << "# Error against ns per world-step, one curve per knob: written by\n"
     << GnuplotComment(config.command_line) << "# Run: gnuplot sweep.gp (in this directory).\n"
     << "set terminal pngcairo noenhanced size 1500,900 font ',10'\n"
     << "set logscale xy\nset grid\nset format y '%.0e'\nset key below horizontal\n"
     << "set xlabel "
     << GnuplotString("ns per world-step (" + std::to_string(config.worlds) + " worlds, " +
                      std::to_string(machine.threads) + " thread(s), " + machine.target + ")")
     << '\n';
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
    gp << "set output " << GnuplotString(PlotFileName(scene)) << '\n'
       << "set multiplot layout " << (panels.size() + 2) / 3 << ",3 title "
       << GnuplotString(scene +
                        ": error against cost, one knob varied at a time from the default "
                        "(labels: its value)")
       << '\n';
    for (int m : panels) {
      const int column = kFirstMetricColumn + m;
      gp << "set title " << GnuplotString(kPlotMetrics[m].title) << "\nplot ";
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

}  // namespace manyworlds::tools
