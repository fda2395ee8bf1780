// Energy with the exact joint solve (issue 18's targets, docs/accuracy.md):
// the free linkage (a closed loop of two hinges and two ball joints with a
// geared flywheel) released from rest, chain16 released from horizontal,
// and the heavy chains. The velocity solve projects onto the joints'
// tangent at the step's start, which alone removes the O(dt) normal
// velocity the curved path builds up within a step: the linkage then loses
// about half of the energy its swing exchanges in 10 s, chain16 1.15 % of
// M g L in 1 s. The curvature correction (StepSettings::
// exact_curvature_velocity, on by default) gives that velocity back. What
// the tests hold: with it, both targets (the linkage within 5 % over 10 s,
// chain16 under 1 % of M g L in its first second); the remaining loss is
// still first order, at a constant 13x smaller (doubling the substeps
// halves it, within a third); no run gains energy (it would be an
// instability), the heavy chains included, where the correction fades out
// (kExactCurvatureTransverseLimit) and their joints hold; without it the
// exact solve loses no more than Gauss-Seidel at Jolt's defaults; and the
// corrected path is closer to the converged solution (cartpole).
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
  double largest_gain = 0;     // max over steps of E(t) - E(0) (J), 0 if never above
  double largest_kinetic = 0;  // max over steps of the kinetic energy (J)
  float largest_joint_error = 0;  // max over steps of Batch::MaxConstraintError (m or rad)
};

EnergyRun RunScene(const std::string& id, JointSolver solver, int steps, int substeps,
                   bool curvature = true, int newton_steps = 2) {
  const Scene scene = MakeReferenceScene(id);
  Batch batch(scene, 1, BatchOptions{1});
  StepSettings settings;
  settings.solver = solver;
  settings.substeps = substeps;
  settings.exact_curvature_velocity = curvature;
  if (solver == JointSolver::kExact) settings.position_iterations = newton_steps;
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
    run.largest_gain = std::max(run.largest_gain, change);
    run.largest_joint_error = std::max(run.largest_joint_error, batch.MaxConstraintError(0));
    run.largest_kinetic = std::max(run.largest_kinetic, energy({0, 0, 0}));
  }
  return run;
}

constexpr int kTenSeconds = 600;  // steps of 1/60 s

TEST(ExactSolveEnergyTest, TheLinkageKeepsItsEnergyWithinFivePercentOverTenSeconds) {
  const EnergyRun gauss_seidel = RunScene("linkage", JointSolver::kGaussSeidel, kTenSeconds, 1);
  const EnergyRun uncorrected =
      RunScene("linkage", JointSolver::kExact, kTenSeconds, 1, /*curvature=*/false);
  std::printf("linkage, 10 s, 1 substep: worst drift Gauss-Seidel %.4f J (%.1f %%), exact "
              "without the curvature correction %.4f J (%.1f %%)\n",
              gauss_seidel.worst_drift, 100 * gauss_seidel.worst_drift / gauss_seidel.largest_kinetic,
              uncorrected.worst_drift, 100 * uncorrected.worst_drift / uncorrected.largest_kinetic);
  EXPECT_LE(uncorrected.worst_drift, gauss_seidel.worst_drift);
  double previous = 0;
  for (int substeps : {1, 2, 4, 8}) {
    const EnergyRun exact = RunScene("linkage", JointSolver::kExact, kTenSeconds, substeps);
    std::printf("linkage, 10 s, %d substeps: largest kinetic energy %.4f J; worst drift exact "
                "%.4f J (%.1f %%), at the end %+.4f J\n",
                substeps, exact.largest_kinetic, exact.worst_drift,
                100 * exact.worst_drift / exact.largest_kinetic, exact.final_change);
    ASSERT_GT(exact.largest_kinetic, 1.0);  // it swings
    EXPECT_LE(exact.final_change, 1e-3 * exact.largest_kinetic);  // no gain at the end
    if (substeps == 1) {
      // Issue 18's target (measured 3.5 %, against 46.9 % without the
      // correction).
      EXPECT_LE(exact.worst_drift, 0.05 * exact.largest_kinetic);
    } else {
      // First order: half the step, half the loss (measured 0.45, 0.50, 0.50).
      EXPECT_LE(exact.worst_drift, 0.67 * previous) << substeps << " substeps";
    }
    previous = exact.worst_drift;
  }
}

TEST(ExactSolveEnergyTest, Chain16LosesUnderOnePercentOfMglInItsFirstSecond) {
  // chain16: 16 links of 1 kg, 8 m, released from horizontal: M g L with
  // L the length, the scale of docs/accuracy.md's energy figures.
  constexpr double kMgl = 16 * 9.81 * 8;
  const EnergyRun exact = RunScene("chain16", JointSolver::kExact, 60, 1);
  const EnergyRun uncorrected = RunScene("chain16", JointSolver::kExact, 60, 1, false);
  const EnergyRun gauss_seidel = RunScene("chain16", JointSolver::kGaussSeidel, 60, 1);
  for (const auto& [name, run] : {std::pair{"exact", exact},
                                  std::pair{"exact without the curvature correction", uncorrected},
                                  std::pair{"gauss_seidel", gauss_seidel}}) {
    std::printf("chain16, 1 s, %s: E(1 s) - E(0) %+.2f J = %+.2f %% of M g L\n", name,
                run.final_change, 100 * run.final_change / kMgl);
    // Energy is lost, never gained (a gain would be an instability).
    EXPECT_LE(run.largest_gain, 1e-3 * kMgl) << name;
  }
  // Issue 18's target (measured 0.47 %; 1.15 % without the correction).
  EXPECT_GE(exact.final_change, -0.01 * kMgl);
  EXPECT_LE(uncorrected.final_change, gauss_seidel.final_change * 0.5);
}

// The heavy chains pull their light links hard enough that an explicit
// correction of their transverse swing would feed energy in until they
// come apart (chain16-r100 within a second without the fade-out); the
// correction fades out there (kExactCurvatureTransverseLimit). Over 10 s
// with it: no energy gained, every joint within a millimetre.
TEST(ExactSolveEnergyTest, TheHeavyChainsGainNoEnergyWithTheCorrection) {
  for (const auto& [id, newton_steps] :
       {std::pair{"chain16", 4}, std::pair{"chain16-r100", 4}, std::pair{"chain16-r1000", 30},
        std::pair{"chain64", 4}}) {
    const EnergyRun run = RunScene(id, JointSolver::kExact, kTenSeconds, 1, true, newton_steps);
    std::printf("%s, 10 s: E(10 s) - E(0) %+.1f J, largest gain %.3f J, largest kinetic energy "
                "%.0f J, largest joint error %.2e\n",
                id, run.final_change, run.largest_gain, run.largest_kinetic,
                double(run.largest_joint_error));
    EXPECT_LE(run.largest_gain, 1e-3 * run.largest_kinetic) << id;
    EXPECT_LE(run.largest_joint_error, 1e-3f) << id;
  }
}

// Energy is not the only gain: the velocity the correction keeps is the one
// the path needs, so the motion follows the converged solution more closely.
// cartpole released from its start (the pole 0.1 rad off upright, no cart
// force) against the exact solve at 256 substeps with 10 Newton steps
// (converged: with and without the correction it agrees to 5e-3 m over 2 s):
// measured RMS of the largest body distance over 2 s, 0.014 m with the
// correction and 0.18 m without, whose pole falls behind as it loses speed.
TEST(ExactSolveEnergyTest, TheCorrectionFollowsTheConvergedSolutionMoreClosely) {
  const Scene scene = MakeReferenceScene("cartpole");
  const auto trajectory = [&](bool curvature, int substeps, int newton_steps) {
    Batch batch(scene, 1, BatchOptions{1});
    StepSettings settings;
    settings.solver = JointSolver::kExact;
    settings.substeps = substeps;
    settings.position_iterations = newton_steps;
    settings.exact_curvature_velocity = curvature;
    std::vector<float> state(batch.body_count() * kStateFloatsPerBody);
    std::vector<float> positions;
    for (int step = 0; step < 120; ++step) {
      batch.Step(settings);
      batch.GetState(state);
      for (std::size_t b = 0; b < batch.body_count(); ++b) {
        for (int i = 0; i < 3; ++i) positions.push_back(state[b * kStateFloatsPerBody + i]);
      }
    }
    return positions;
  };
  const std::vector<float> converged = trajectory(false, 256, 10);
  const auto rms_error = [&](const std::vector<float>& run) {
    double sum = 0;
    const std::size_t per_step = run.size() / 120;
    for (std::size_t step = 0; step < 120; ++step) {
      double largest = 0;
      for (std::size_t b = 0; b < per_step / 3; ++b) {
        double squared = 0;
        for (int i = 0; i < 3; ++i) {
          const std::size_t k = step * per_step + b * 3 + std::size_t(i);
          squared += (double(run[k]) - converged[k]) * (double(run[k]) - converged[k]);
        }
        largest = std::max(largest, squared);
      }
      sum += largest;
    }
    return std::sqrt(sum / 120);
  };
  const double with = rms_error(trajectory(true, 1, 4));
  const double without = rms_error(trajectory(false, 1, 4));
  std::printf("cartpole, 2 s against 256 substeps: RMS %.4f m with the correction, %.4f m "
              "without\n",
              with, without);
  EXPECT_LT(with, 0.25 * without);
}

}  // namespace
}  // namespace manyworlds
