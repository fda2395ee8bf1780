// Energy with the exact joint solve (issue 18's targets, docs/accuracy.md):
// the free linkage (a closed loop of two hinges and two ball joints with a
// geared flywheel) released from rest, and chain16 released from
// horizontal. Neither target is met at 1 substep (the linkage loses about
// half of the energy its swing exchanges in 10 s, chain16 1.15 % of M g L in
// 1 s): the velocity solve projects onto the joints' tangent at the step's
// start, which removes the O(dt) normal velocity the curved path builds up.
// What the tests hold: the loss is that first-order discretisation error
// (doubling the substeps halves it, within a third), no run gains energy
// (it would be an instability), and the exact solve loses no more than
// Gauss-Seidel at Jolt's defaults.
//
// The drift is |E(t) - E(0)| at the end of each step, E kinetic plus
// gravitational (tools::MechanicalEnergy, double sums of float states); for
// the linkage it is taken relative to the largest kinetic energy of the run
// (the energy the swing exchanges; E's zero is arbitrary).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <span>
#include <string>
#include <vector>

#include "manyworlds/batch.h"
#include "manyworlds/scenes.h"
#include "tools/sweep_metrics.h"

namespace manyworlds {
namespace {

struct EnergyRun {
  double worst_drift = 0;      // max over steps of |E(t) - E(0)| (J), world 0
  double final_change = 0;     // E(end) - E(0) (J), signed
  double largest_kinetic = 0;  // max over steps of the kinetic energy (J)
};

EnergyRun RunScene(const std::string& id, JointSolver solver, int steps, int substeps) {
  const Scene scene = MakeReferenceScene(id);
  Batch batch(scene, 1, BatchOptions{1});
  StepSettings settings;
  settings.solver = solver;
  settings.substeps = substeps;
  std::vector<float> state(batch.body_count() * kStateFloatsPerBody);
  const auto energy = [&](Float3 gravity) {
    return tools::MechanicalEnergy(scene, std::span<const float>(state), gravity);
  };
  batch.GetState(state);
  const double start = energy(settings.gravity);
  EnergyRun run;
  for (int step = 0; step < steps; ++step) {
    batch.Step(settings);
    batch.GetState(state);
    const double change = energy(settings.gravity) - start;
    run.worst_drift = std::max(run.worst_drift, std::abs(change));
    run.final_change = change;
    run.largest_kinetic = std::max(run.largest_kinetic, energy({0, 0, 0}));
  }
  return run;
}

constexpr int kTenSeconds = 600;  // steps of 1/60 s

TEST(ExactSolveEnergyTest, TheLinkageLosesEnergyAtFirstOrderInTheStep) {
  const EnergyRun gauss_seidel = RunScene("linkage", JointSolver::kGaussSeidel, kTenSeconds, 1);
  double previous = 0;
  for (int substeps : {1, 2, 4, 8}) {
    const EnergyRun exact = RunScene("linkage", JointSolver::kExact, kTenSeconds, substeps);
    std::printf("linkage, 10 s, %d substeps: largest kinetic energy %.4f J; worst drift exact "
                "%.4f J (%.1f %%), at the end %+.4f J\n",
                substeps, exact.largest_kinetic, exact.worst_drift,
                100 * exact.worst_drift / exact.largest_kinetic, exact.final_change);
    ASSERT_GT(exact.largest_kinetic, 1.0);  // it swings
    EXPECT_LE(exact.final_change, 1e-3 * exact.largest_kinetic);  // no gain
    if (substeps == 1) {
      std::printf("linkage, 10 s, Gauss-Seidel: worst drift %.4f J (%.1f %%), at the end %+.4f J\n",
                  gauss_seidel.worst_drift,
                  100 * gauss_seidel.worst_drift / gauss_seidel.largest_kinetic,
                  gauss_seidel.final_change);
      EXPECT_LE(exact.worst_drift, gauss_seidel.worst_drift);
    } else {
      // First order: half the step, half the loss (measured 0.62, 0.57, 0.54).
      EXPECT_LE(exact.worst_drift, 0.67 * previous) << substeps << " substeps";
    }
    previous = exact.worst_drift;
  }
}

TEST(ExactSolveEnergyTest, Chain16LossPerSecondIsMeasured) {
  // chain16: 16 links of 1 kg, 8 m, released from horizontal: M g L with
  // L the length, the scale of docs/accuracy.md's energy figures.
  constexpr double kMgl = 16 * 9.81 * 8;
  for (JointSolver solver : {JointSolver::kExact, JointSolver::kGaussSeidel}) {
    const EnergyRun run = RunScene("chain16", solver, 60, 1);
    std::printf("chain16, 1 s, %s: E(1 s) - E(0) %+.2f J = %+.2f %% of M g L\n",
                JointSolverName(solver), run.final_change, 100 * run.final_change / kMgl);
    // Energy is lost, never gained (a gain would be an instability).
    EXPECT_LE(run.final_change, 1e-3 * kMgl);
  }
}

}  // namespace
}  // namespace manyworlds
