// `manyworlds sweep`: error against run time (issue 6, item 4).
//
// For every scene of SweepSceneIds() and every setting of substeps (1, 2, 4,
// 8), velocity iterations (1, 2, 4, 8, 10) and position iterations (0, 1, 2)
// -- one knob at a time from the default 1 / 10 / 2, or with --grid full every
// combination -- it measures:
//
//   cost      ns per world-step of Batch::Step (actions applied every step):
//             a batch of --worlds worlds on --threads threads, stepped
//             --seconds of simulated time per round: an untimed warm-up
//             round, then rounds until --min-time of timed stepping (at least
//             one). Timed in --passes passes over every setting of every
//             scene after all errors are measured; the fastest round of all
//             passes is reported (the least disturbed on a shared machine);
//   accuracy  over the first --sample-worlds worlds (the same worlds: a
//             world's bits do not depend on the batch size), after every step
//             of the same --seconds:
//             - position error of every constraint (Batch::ConstraintError),
//               max and RMS over constraints, worlds and steps;
//             - velocity residual |J v| of every constraint's equality rows
//               (Batch::ConstraintVelocityError), max and RMS likewise;
//             - trajectory error: body positions (m) and rotations (rad)
//               against reference::World<double> of the same world with dt/16
//               (16 substeps per step, same actions) and 4x the default
//               iterations (40 velocity, 8 position), RMS and max;
//             - energy drift |E(t) - E(0)| (kinetic + potential), max, and the
//               signed drift at the end, for scenes that conserve energy
//               (EnergyIsConserved: the chains);
//             - coupling error |theta1 + r theta2| (gear) or |theta1 - r d2|
//               (rack and pinion), max and RMS.
//
// --mass-range-limit R first applies LimitMassRange(scene, R) to every scene
// (the remedy of docs/stability.md); batch and reference then step the same
// limited scene.
//
// Before it steps anything it creates DIR (--out), refuses to replace an
// earlier report there (sweep.csv, sweep.md, sweep.gp, a scene's PNG) unless
// --overwrite, and creates and removes a file there: an earlier report or a
// folder it cannot write to is an error naming it (exit code 1) then, not
// after the sweep.
//
// Writes DIR/sweep.csv (every setting), DIR/sweep.md (the tables) and
// DIR/sweep.gp, a gnuplot script drawing DIR/<scene>.png: each metric against
// ns per world-step, one curve per knob. A file not written in full (a full
// disk shows at flush and close) is an error naming it (exit code 1) and is
// removed; "wrote" is printed only once all three are. gnuplot runs when it
// is on PATH, as `gnuplot sweep.gp` in DIR and without a shell
// (tools/subprocess.h), so any folder name works; without it the CSV and
// Markdown are still written (exit code 0).
#pragma once

#include <string>
#include <vector>

namespace manyworlds::tools {

// The scenes the sweep runs by default. The stress scenes join here.
std::vector<std::string> SweepSceneIds();

// The command; argv[1] is "sweep". Throws UsageError for bad options.
int Sweep(int argc, char** argv);

}  // namespace manyworlds::tools
