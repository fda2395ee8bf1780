// MuJoCo 2.2.2 side by side with manyworlds' Batch, in one run: throughput
// on the same worlds, threads, steps and actions, and each engine's
// trajectory error against its own fine-step reference (docs/benchmarks.md).
//
// Throughput, for cartpole, chain16 and rackpinion (bench/mujoco_scenes.h;
// chain16 with two MuJoCo models, ball joints and hinges) and the contact
// scenes hopper and quadruped (MuJoCo's hopper and ant, Y up: soft contacts
// and position actuators against our hard contacts and position motors),
// N in {64, 4096} worlds, T in {1, 2} threads:
//   mujoco/<scene>/worlds:<N>/threads:<T>  one mjData per thread; thread t
//       steps its N/T worlds one after the other: load the world's state
//       (qpos, qvel, qacc_warmstart, time) into its mjData, set the action,
//       mj_step, store the state back. Threads come from a TBB arena of T,
//       one task per thread's half.
//   batch/<scene>/worlds:<N>/threads:<T>   Batch::Step of the same N worlds
//       (float, dispatched SIMD target, the spec's step settings).
//   batch_tolerance/<scene>/...  the same with StepSettings::velocity_tolerance
//       1e-3 (each world's velocity passes stop once one changes its
//       velocities by at most 1e-3 m/s and rad/s; MuJoCo stops its solver
//       on a tolerance too); a table of its own after the main one.
// Both run back to back per (scene, N, T), so their ratio sees the same load.
// Cartpole gets CartpoleForce(seed 1, world, step) on the cart in both
// engines, hopper and quadruped a position target per motor,
// SceneActions(id).Target(i, world, step, 1), as our motor's target and
// MuJoCo's actuator's ctrl; the step counter runs on through warm-up and
// trials in both. items_per_second = world-steps/s.
//
// Accuracy, for cartpole, chain16 and rackpinion only (the contact scenes
// under random targets are chaotic), after 1 s and 5 s (60 and 300 steps),
// RMS over the first --accuracy-worlds=K worlds (default 8; the worlds
// differ only in cartpole's forces):
//   MuJoCo:     the benchmark model vs the same model at dt/16 (forces held
//               for the 16 substeps), tolerance 1e-12, 400 iterations (double);
//   manyworlds: Batch (float, dt, 10 + 2 iterations) vs reference::World<double>
//               with 16 substeps of dt/16 and 40 + 8 iterations, and the same
//               Batch with the velocity tolerance ("ours tol err").
// A spin check (2 threads summing a counter vs 1) runs before and after.
// Exits with 1 when any world of any benchmark or accuracy run was
// non-finite, MuJoCo warned (e.g. an unstable simulation it reset), a
// world stepped through a shared mjData differed from one stepped in its own,
// or the masses MuJoCo computed for the contact scenes' bodies are not ours
// (both printed before the benchmarks).
//
//   mujoco_bench [--accuracy-worlds=K] [Google Benchmark flags]

#include <benchmark/benchmark.h>
#include <tbb/parallel_for.h>
#include <tbb/partitioner.h>
#include <tbb/task_arena.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "manyworlds/batch.h"
#include "manyworlds/scene.h"
#include "manyworlds/scenes.h"

#include "bench/mujoco_scenes.h"
#include "bench/scene_bench_support.h"
#include "reference/world.h"

namespace manyworlds::bench {
namespace {

constexpr std::size_t kWorldCounts[] = {64, 4096};
constexpr int kThreadCounts[] = {1, 2};
constexpr std::uint64_t kOneSecond = 60, kFiveSeconds = 300;  // steps of 1/60 s
constexpr int kFineSubsteps = 16;
// batch_tolerance/...: the batch with StepSettings::velocity_tolerance, each
// world stopping its velocity passes once a pass changes its velocities by
// at most this (m/s, rad/s); its accuracy is printed next to the default's.
constexpr float kBenchVelocityTolerance = 1e-3f;

StepSettings ToleranceSettings() {
  StepSettings settings;
  settings.velocity_tolerance = kBenchVelocityTolerance;
  return settings;
}

std::atomic<int> mujoco_warnings{0};

// MuJoCo's default handler prints and appends to MUJOCO_LOG.TXT in the
// working directory; count instead (main fails on any) and print a few.
void CountMujocoWarning(const char* message) {
  if (mujoco_warnings.fetch_add(1) < 5) std::fprintf(stderr, "MuJoCo warning: %s\n", message);
}

std::string Name(const char* engine, const std::string& scene, std::size_t worlds, int threads) {
  return std::string(engine) + "/" + scene + "/worlds:" + std::to_string(worlds) +
         "/threads:" + std::to_string(threads);
}

// ------------------------------------------------------------- MuJoCo worlds

// N worlds of one MuJoCo model stepped through one mjData per thread. A
// world's state between steps is qpos, qvel, qacc_warmstart (the solver's
// warm start, so a world steps exactly as it would in its own mjData) and
// time; the models have no activations or mocap bodies.
class MujocoWorlds {
 public:
  MujocoWorlds(const std::string& id, std::size_t worlds, int threads)
      : id_(id),
        model_(LoadMujocoXml(MujocoXml(id, MujocoResolution::kBenchmark))),
        worlds_(worlds),
        threads_(threads),
        arena_(threads) {
    if (model_->na != 0 || model_->nmocap != 0) {
      throw std::logic_error("MujocoWorlds keeps no activations or mocap state");
    }
    nq_ = std::size_t(model_->nq);
    nv_ = std::size_t(model_->nv);
    stride_ = nq_ + 2 * nv_ + 1;
    for (int t = 0; t < threads; ++t) data_.push_back(MakeMujocoData(id, model_.get()));
    states_.resize(worlds * stride_);
    for (std::size_t w = 0; w < worlds; ++w) Save(data_[0].get(), w);
  }

  // One step of every world: task t of T, with mjData t, steps worlds
  // [t N / T, (t + 1) N / T) one after the other.
  void Step(std::uint64_t step) {
    arena_.execute([&] {
      tbb::parallel_for(
          0, threads_,
          [&](int t) {
            mjData* data = data_[std::size_t(t)].get();
            const std::size_t begin = worlds_ * std::size_t(t) / std::size_t(threads_);
            const std::size_t end = worlds_ * std::size_t(t + 1) / std::size_t(threads_);
            for (std::size_t w = begin; w < end; ++w) {
              Load(data, w);
              ApplyMujocoAction(id_, model_.get(), data, w, step, kSceneSeed);
              mj_step(model_.get(), data);
              Save(data, w);
            }
          },
          tbb::static_partitioner());
    });
  }

  // The world's qpos and qvel after the last Step.
  const double* QPos(std::size_t world) const { return &states_[world * stride_]; }
  const double* QVel(std::size_t world) const { return &states_[world * stride_ + nq_]; }
  std::size_t nq() const { return nq_; }
  std::size_t nv() const { return nv_; }

  std::size_t NonFiniteWorlds() const {
    std::size_t count = 0;
    for (std::size_t w = 0; w < worlds_; ++w) {
      const double* s = &states_[w * stride_];
      count += !std::all_of(s, s + stride_, [](double x) { return std::isfinite(x); });
    }
    return count;
  }

 private:
  void Load(mjData* data, std::size_t world) const {
    const double* s = &states_[world * stride_];
    std::memcpy(data->qpos, s, nq_ * sizeof(double));
    std::memcpy(data->qvel, s + nq_, nv_ * sizeof(double));
    std::memcpy(data->qacc_warmstart, s + nq_ + nv_, nv_ * sizeof(double));
    data->time = s[nq_ + 2 * nv_];
  }
  void Save(const mjData* data, std::size_t world) {
    double* s = &states_[world * stride_];
    std::memcpy(s, data->qpos, nq_ * sizeof(double));
    std::memcpy(s + nq_, data->qvel, nv_ * sizeof(double));
    std::memcpy(s + nq_ + nv_, data->qacc_warmstart, nv_ * sizeof(double));
    s[nq_ + 2 * nv_] = data->time;
  }

  std::string id_;
  MujocoModel model_;
  std::size_t worlds_;
  int threads_;
  tbb::task_arena arena_;
  std::vector<MujocoData> data_;
  std::size_t nq_ = 0, nv_ = 0, stride_ = 0;
  std::vector<double> states_;
};

bool IsContactScene(const std::string& id) {
  const std::vector<std::string> contact = MujocoContactSceneIds();
  return std::find(contact.begin(), contact.end(), id) != contact.end();
}

// Untimed steps of a contact scene's MuJoCo worlds before the warm-up: 2 s,
// after which the walkers have landed and their contacts are what they stay
// (the quadruped from ~0.25 contacts per step in the air to ~3.75 lying on
// the ground). MuJoCo's cost per step grows with its contacts (the
// quadruped's 2-3x from the first steps to then), and at 4096 worlds a
// benchmark times only the first ~40 steps, so without this it would time
// mostly the cheap fall. The batch needs none: its cost per step stayed the
// same from the fall to lying on the ground (a fixed contact slot per shape
// pair), and it runs hundreds of steps anyway.
constexpr std::uint64_t kContactSettleSteps = 120;

// As RunBatch: built and warmed up by the first trial run, stepped on by the
// later ones.
void RunMujoco(benchmark::State& state, const std::string& name, const std::string& id,
               std::size_t worlds, int threads) {
  struct Run {
    std::string name;
    std::unique_ptr<MujocoWorlds> worlds;
    std::uint64_t step = 0;
  };
  static Run run;
  if (run.name != name) {
    run = Run{};
    run.worlds = std::make_unique<MujocoWorlds>(id, worlds, threads);
    run.name = name;
    const std::uint64_t settle = IsContactScene(id) ? kContactSettleSteps : 0;
    for (std::uint64_t step = 0; step < settle; ++step) run.worlds->Step(step);
    run.step = settle + WarmUp([&](std::uint64_t step) { run.worlds->Step(settle + step); });
  }
  for (auto _ : state) run.worlds->Step(run.step++);
  const std::size_t unsound = run.worlds->NonFiniteWorlds();
  NonFiniteWorldTally() += unsound;
  state.SetItemsProcessed(std::int64_t(state.iterations()) * std::int64_t(worlds));
  state.counters["threads"] = double(threads);
  state.counters["mujoco_warnings"] = double(mujoco_warnings.load());
  if (unsound) state.counters["nonfinite_worlds"] = double(unsound);
}

// Swapping worlds through one mjData per thread must step each world exactly
// as its own mjData would (else the benchmark would time something else):
// 5 worlds on 2 threads for 60 steps (the contact scenes 300, in which they
// land and push off the ground under their random targets) against 5
// separate mjData, qpos and qvel bit for bit. A contact scene's check counts
// only if its worlds touched the ground (contacts in some step).
bool MujocoSwapMatchesOwnData() {
  constexpr std::size_t kWorlds = 5;
  bool same = true;
  for (const std::string& id : MujocoThroughputSceneIds()) {
    const bool contact = IsContactScene(id);
    const std::uint64_t steps = contact ? kFiveSeconds : kOneSecond;
    for (const std::string& model_id : MujocoModelsOf(id)) {
      MujocoWorlds swapped(model_id, kWorlds, 2);
      const MujocoModel model = LoadMujocoXml(MujocoXml(model_id, MujocoResolution::kBenchmark));
      std::vector<MujocoData> own;
      for (std::size_t w = 0; w < kWorlds; ++w) {
        own.push_back(MakeMujocoData(model_id, model.get()));
      }
      std::size_t steps_with_contacts = 0;  // over all worlds
      for (std::uint64_t step = 0; step < steps; ++step) {
        swapped.Step(step);
        for (std::size_t w = 0; w < kWorlds; ++w) {
          ApplyMujocoAction(model_id, model.get(), own[w].get(), w, step, kSceneSeed);
          mj_step(model.get(), own[w].get());
          steps_with_contacts += own[w]->ncon > 0;
        }
      }
      for (std::size_t w = 0; w < kWorlds; ++w) {
        if (std::memcmp(swapped.QPos(w), own[w]->qpos, swapped.nq() * sizeof(double)) != 0 ||
            std::memcmp(swapped.QVel(w), own[w]->qvel, swapped.nv() * sizeof(double)) != 0) {
          std::printf("MuJoCo %s world %zu: stepping through a shared mjData differs from its "
                      "own mjData\n", model_id.c_str(), w);
          same = false;
        }
      }
      if (contact) {
        std::printf("MuJoCo %s: %zu of %zu world-steps of the shared-mjData check had "
                    "contacts\n", model_id.c_str(), steps_with_contacts,
                    std::size_t(steps) * kWorlds);
        if (steps_with_contacts == 0) same = false;
      }
    }
  }
  return same;
}

// MuJoCo computes the contact scenes' masses and inertias from their geoms
// (density 1000); they must be ours (batch/contact_scenes.cc computes them
// the same way, in float): prints every body, returns false when a mass or
// principal inertia differs by more than 1e-5 relative.
bool MujocoMassesMatchOurs() {
  bool match = true;
  std::printf("masses (kg) and principal inertias (kg m^2), ours / MuJoCo's from its geoms:\n");
  for (const std::string& id : MujocoContactSceneIds()) {
    const MujocoModel model = LoadMujocoXml(MujocoXml(id, MujocoResolution::kBenchmark));
    for (const MassComparison& row : CompareMujocoMasses(id, model.get())) {
      const auto close = [](double ours, double mujoco) {
        return std::abs(ours - mujoco) <= 1e-5 * std::abs(mujoco);
      };
      bool same = close(row.mass_ours, row.mass_mujoco);
      for (int k = 0; k < 3; ++k) same = same && close(row.inertia_ours[k], row.inertia_mujoco[k]);
      match = match && same;
      std::printf("  %-10s %-18s %8.4f / %8.4f   %.4g %.4g %.4g / %.4g %.4g %.4g%s\n",
                  id.c_str(), row.body.c_str(), row.mass_ours, row.mass_mujoco,
                  row.inertia_ours[0], row.inertia_ours[1], row.inertia_ours[2],
                  row.inertia_mujoco[0], row.inertia_mujoco[1], row.inertia_mujoco[2],
                  same ? "" : "  DIFFERENT");
    }
  }
  return match;
}

void RegisterAll() {
  for (const std::string& id : MujocoThroughputSceneIds()) {
    for (const std::size_t worlds : kWorldCounts) {
      for (const int threads : kThreadCounts) {
        for (const std::string& model : MujocoModelsOf(id)) {
          const std::string mujoco = Name("mujoco", model, worlds, threads);
          benchmark::RegisterBenchmark(mujoco.c_str(),
                                       [=](benchmark::State& state) {
                                         RunMujoco(state, mujoco, model, worlds, threads);
                                       })
              ->UseRealTime();
        }
        const std::string batch = Name("batch", id, worlds, threads);
        benchmark::RegisterBenchmark(batch.c_str(),
                                     [=](benchmark::State& state) {
                                       RunBatch(state, batch, id, worlds, threads);
                                     })
            ->UseRealTime();
        const std::string tolerant = Name("batch_tolerance", id, worlds, threads);
        benchmark::RegisterBenchmark(tolerant.c_str(),
                                     [=](benchmark::State& state) {
                                       RunBatch(state, tolerant, id, worlds, threads, 0,
                                                2.0 * (1ull << 30), ToleranceSettings());
                                     })
            ->UseRealTime();
      }
    }
  }
}

// ------------------------------------------------------------------ accuracy

// Per observable: summed squared errors over worlds at 1 s and 5 s, and
// world 0's coarse values (to show what the error is relative to).
struct Accuracy {
  std::vector<double> squared_1s, squared_5s;
  std::vector<double> world0_1s, world0_5s;
  std::size_t worlds = 0;
  bool finite = true;
};

void Accumulate(Accuracy& a, const std::vector<Observable>& observables, std::uint64_t steps,
                std::size_t world, const std::vector<double>& coarse,
                const std::vector<double>& fine) {
  const std::vector<double> e = SquaredErrors(observables, coarse, fine);
  std::vector<double>& sums = steps == kOneSecond ? a.squared_1s : a.squared_5s;
  if (sums.empty()) sums.assign(e.size(), 0.0);
  for (std::size_t i = 0; i < e.size(); ++i) {
    sums[i] += e[i];
    a.finite = a.finite && std::isfinite(e[i]);
  }
  if (world == 0) (steps == kOneSecond ? a.world0_1s : a.world0_5s) = coarse;
}

Accuracy MujocoAccuracy(const std::string& id, std::size_t worlds) {
  const std::vector<Observable> observables = SceneObservables(id);
  const MujocoModel coarse_model = LoadMujocoXml(MujocoXml(id, MujocoResolution::kBenchmark));
  const MujocoModel fine_model = LoadMujocoXml(MujocoXml(id, MujocoResolution::kFine));
  Accuracy a;
  a.worlds = worlds;
  for (std::size_t w = 0; w < worlds; ++w) {
    const MujocoData coarse = MakeMujocoData(id, coarse_model.get());
    const MujocoData fine = MakeMujocoData(id, fine_model.get());
    for (std::uint64_t step = 0; step < kFiveSeconds; ++step) {
      ApplyMujocoAction(id, coarse_model.get(), coarse.get(), w, step, kSceneSeed);
      mj_step(coarse_model.get(), coarse.get());
      ApplyMujocoAction(id, fine_model.get(), fine.get(), w, step, kSceneSeed);
      for (int s = 0; s < kFineSubsteps; ++s) mj_step(fine_model.get(), fine.get());
      if (step + 1 == kOneSecond || step + 1 == kFiveSeconds) {
        // mj_step leaves the Cartesian poses at the start of the step.
        mj_kinematics(coarse_model.get(), coarse.get());
        mj_kinematics(fine_model.get(), fine.get());
        const auto pose_coarse = [&](int b) { return MujocoPose(coarse.get(), b); };
        const auto pose_fine = [&](int b) { return MujocoPose(fine.get(), b); };
        Accumulate(a, observables, step + 1, w, Observe(id, pose_coarse),
                   Observe(id, pose_fine));
      }
    }
  }
  return a;
}

// Each of `settings`' batches against the same fine reference, in order.
std::vector<Accuracy> ManyworldsAccuracy(const std::string& id, std::size_t worlds,
                                         const std::vector<StepSettings>& settings) {
  const std::vector<Observable> observables = SceneObservables(id);
  const Scene scene = MakeReferenceScene(id);
  const SceneActions actions(id);
  const StepSettings coarse;
  StepSettings fine_settings;
  fine_settings.substeps = kFineSubsteps;  // dt/16 each, forces held for all 16
  fine_settings.velocity_iterations = 4 * coarse.velocity_iterations;
  fine_settings.position_iterations = 4 * coarse.position_iterations;
  std::vector<std::unique_ptr<Batch>> batches;
  for (std::size_t i = 0; i < settings.size(); ++i) {
    batches.push_back(std::make_unique<Batch>(scene, worlds, BatchOptions{.threads = 1}));
  }
  std::vector<std::unique_ptr<reference::World<double>>> fine;
  for (std::size_t w = 0; w < worlds; ++w) {
    fine.push_back(std::make_unique<reference::World<double>>(scene));
  }
  const std::size_t floats_per_world = scene.bodies().size() * kStateFloatsPerBody;
  std::vector<float> state(worlds * floats_per_world);
  std::vector<Accuracy> accuracy(settings.size());
  for (Accuracy& a : accuracy) a.worlds = worlds;
  for (std::uint64_t step = 0; step < kFiveSeconds; ++step) {
    for (std::size_t i = 0; i < batches.size(); ++i) {
      actions.Apply(*batches[i], step, kSceneSeed);
      batches[i]->Step(settings[i]);
    }
    for (std::size_t w = 0; w < worlds; ++w) {
      actions.ApplyTo(*fine[w], w, step, kSceneSeed);
      fine[w]->Step(fine_settings);
    }
    if (step + 1 != kOneSecond && step + 1 != kFiveSeconds) continue;
    for (std::size_t i = 0; i < batches.size(); ++i) {
      batches[i]->GetState(state);
      for (std::size_t w = 0; w < worlds; ++w) {
        const float* s = &state[w * floats_per_world];
        const auto pose_coarse = [&](int b) {
          const float* body = s + std::size_t(b) * kStateFloatsPerBody;
          BodyPose pose{};
          for (int k = 0; k < 3; ++k) pose.position[k] = body[k];
          for (int k = 0; k < 4; ++k) pose.rotation[k] = body[3 + k];
          return pose;
        };
        const auto pose_fine = [&](int b) {
          const reference::Body<double>& body = fine[w]->body(std::size_t(b));
          return BodyPose{{body.position.x(), body.position.y(), body.position.z()},
                          {body.rotation.x(), body.rotation.y(), body.rotation.z(),
                           body.rotation.w()}};
        };
        Accumulate(accuracy[i], observables, step + 1, w, Observe(id, pose_coarse),
                   Observe(id, pose_fine));
      }
    }
  }
  return accuracy;
}

// One line per observable and time: both engines' RMS errors and world 0's
// values (a vector quantity as its length).
void PrintAccuracyRows(const std::string& model, const Accuracy& m, const Accuracy& o,
                       const Accuracy& tolerant) {
  const std::vector<Observable> observables = SceneObservables(model);
  for (const bool five : {false, true}) {
    std::size_t at = 0;  // index of the observable's first value
    for (std::size_t i = 0; i < observables.size(); ++i) {
      const auto rms = [&](const Accuracy& a) {
        return std::sqrt((five ? a.squared_5s : a.squared_1s)[i] / double(a.worlds));
      };
      const auto value = [&](const Accuracy& a) {
        const std::vector<double>& v = five ? a.world0_5s : a.world0_1s;
        double sum = 0;
        for (std::size_t c = 0; c < observables[i].components; ++c) sum += v[at + c] * v[at + c];
        return observables[i].components == 1 ? v[at] : std::sqrt(sum);
      };
      std::printf("%-14s %-20s %3ds %14.3e %14.3e %14.3e %12.4g %12.4g\n", model.c_str(),
                  observables[i].name.c_str(), five ? 5 : 1, rms(m), rms(o), rms(tolerant),
                  value(m), value(o));
      at += observables[i].components;
    }
  }
}

// Prints both engines' errors; returns false when any is not finite.
bool RunAccuracy(std::size_t worlds) {
  std::printf(
      "\ntrajectory error against each engine's own fine reference, RMS over worlds 0..%zu "
      "(seed %llu), after 1 s and 5 s; 'value' = the benchmark model's world 0 (angles wrapped "
      "into (-pi, pi], the COM as its distance from the origin); ours = chain16 (ball joints) "
      "for both MuJoCo chains\n"
      "  MuJoCo:     benchmark model (dt 1/60) vs the same model at dt/16, tolerance 1e-12, 400 "
      "iterations\n"
      "  manyworlds: Batch, float, dt 1/60, 10 + 2 iterations vs reference::World<double>, 16 "
      "substeps of dt/16, 40 + 8 iterations; 'ours tol err': the same with velocity_tolerance "
      "%g\n",
      worlds - 1, static_cast<unsigned long long>(kSceneSeed), double(kBenchVelocityTolerance));
  std::printf("%-14s %-20s %4s %14s %14s %14s %12s %12s\n", "MuJoCo model", "quantity", "t",
              "MuJoCo err", "ours err", "ours tol err", "MuJoCo value", "ours value");
  bool finite = true;
  for (const std::string& id : MujocoSceneIds()) {
    const std::vector<Accuracy> batches =
        ManyworldsAccuracy(id, worlds, {StepSettings{}, ToleranceSettings()});
    const Accuracy& ours = batches[0];
    const Accuracy& tolerant = batches[1];
    finite = finite && ours.finite && tolerant.finite;
    for (const std::string& model : MujocoModelsOf(id)) {
      const Accuracy mujoco = MujocoAccuracy(model, worlds);
      finite = finite && mujoco.finite;
      PrintAccuracyRows(model, mujoco, ours, tolerant);
    }
  }
  std::fflush(stdout);
  return finite;
}

// ------------------------------------------------------------------- table

// One line: MuJoCo model `model` vs our batch of reference scene `id`.
void PrintRateRow(const RecordingReporter& r, const std::string& model, const std::string& id,
                  std::size_t worlds) {
  const auto rate = [&](const char* engine, const std::string& scene, int threads) {
    return r.WorldStepsPerSecond(Name(engine, scene, worlds, threads), worlds);
  };
  const double m1 = rate("mujoco", model, 1), b1 = rate("batch", id, 1);
  const double m2 = rate("mujoco", model, 2), b2 = rate("batch", id, 2);
  if (std::isnan(m1) && std::isnan(b1) && std::isnan(m2) && std::isnan(b2)) return;
  // The 1-thread ratio also per CPU second of the benchmark thread, which
  // leaves out what other work on a shared machine took from either run.
  const double cpu_ratio =
      r.WorldStepsPerCpuSecond(Name("batch", id, worlds, 1), worlds) /
      r.WorldStepsPerCpuSecond(Name("mujoco", model, worlds, 1), worlds);
  std::printf("%-14s %7zu %12s %12s %9s %9s %12s %12s %9s %11s %11s\n", model.c_str(), worlds,
              Figure(m1, "%.4g").c_str(), Figure(b1, "%.4g").c_str(),
              Figure(b1 / m1, "%.1fx").c_str(), Figure(cpu_ratio, "%.1fx").c_str(),
              Figure(m2, "%.4g").c_str(),
              Figure(b2, "%.4g").c_str(), Figure(b2 / m2, "%.1fx").c_str(),
              Figure(m2 / m1, "%.2fx").c_str(), Figure(b2 / b1, "%.2fx").c_str());
}

void PrintTable(const RecordingReporter& r) {
  const Batch probe(MakeReferenceScene("cartpole"), 1, BatchOptions{.threads = 1});
  std::printf(
      "\nworld-steps/s (median), MuJoCo %d (double, one mjData per thread) vs manyworlds "
      "Batch (float, target %s, %zu lanes, 10 velocity + 2 position iterations), dt 1/60 s, "
      "same worlds, threads, steps and actions; ratio = batch / MuJoCo; both chain16 models "
      "are compared with our chain16 (ball joints); hopper and quadruped: MuJoCo's soft "
      "contacts and position actuators vs our hard contacts and position motors, the same "
      "random targets\n",
      mj_version(), probe.SimdTarget(), probe.SimdLanes());
  std::printf("%-14s %7s %12s %12s %9s %9s %12s %12s %9s %11s %11s\n", "MuJoCo model",
              "worlds", "MuJoCo 1T", "batch 1T", "ratio", "(CPU)", "MuJoCo 2T", "batch 2T",
              "ratio", "MuJoCo 2/1", "batch 2/1");
  for (const std::string& id : MujocoThroughputSceneIds()) {
    for (const std::string& model : MujocoModelsOf(id)) {
      for (const std::size_t worlds : kWorldCounts) PrintRateRow(r, model, id, worlds);
    }
  }
  std::printf(
      "\nthe batch with velocity_tolerance %g (each world's velocity iterations stop after a "
      "pass that changed its velocities by at most that), world-steps/s (median); 'vs MuJoCo' = "
      "batch_tolerance / MuJoCo, 'vs default' = batch_tolerance / batch\n",
      double(kBenchVelocityTolerance));
  std::printf("%-14s %7s %14s %11s %11s %14s %11s %11s\n", "MuJoCo model", "worlds",
              "tolerance 1T", "vs MuJoCo", "vs default", "tolerance 2T", "vs MuJoCo",
              "vs default");
  for (const std::string& id : MujocoThroughputSceneIds()) {
    for (const std::string& model : MujocoModelsOf(id)) {
      for (const std::size_t worlds : kWorldCounts) {
        const auto rate = [&](const char* engine, const std::string& scene, int threads) {
          return r.WorldStepsPerSecond(Name(engine, scene, worlds, threads), worlds);
        };
        const double t1 = rate("batch_tolerance", id, 1), t2 = rate("batch_tolerance", id, 2);
        if (std::isnan(t1) && std::isnan(t2)) continue;
        std::printf("%-14s %7zu %14s %11s %11s %14s %11s %11s\n", model.c_str(), worlds,
                    Figure(t1, "%.4g").c_str(), Figure(t1 / rate("mujoco", model, 1), "%.1fx").c_str(),
                    Figure(t1 / rate("batch", id, 1), "%.2fx").c_str(), Figure(t2, "%.4g").c_str(),
                    Figure(t2 / rate("mujoco", model, 2), "%.1fx").c_str(),
                    Figure(t2 / rate("batch", id, 2), "%.2fx").c_str());
      }
    }
  }
  std::fflush(stdout);
}

// Takes --accuracy-worlds=K out of argv (Google Benchmark rejects flags it
// does not know); returns K.
std::size_t TakeAccuracyWorlds(int& argc, char** argv) {
  const char* flag = "--accuracy-worlds=";
  std::size_t worlds = 8;
  int out = 1;
  for (int i = 1; i < argc; ++i) {
    if (std::strncmp(argv[i], flag, std::strlen(flag)) == 0) {
      const long value = std::strtol(argv[i] + std::strlen(flag), nullptr, 10);
      if (value < 1 || value > 4096) {
        throw std::invalid_argument(std::string("bad ") + argv[i] + " (1..4096)");
      }
      worlds = std::size_t(value);
    } else {
      argv[out++] = argv[i];
    }
  }
  argc = out;
  return worlds;
}

}  // namespace
}  // namespace manyworlds::bench

int main(int argc, char** argv) {
  using namespace manyworlds::bench;
  std::size_t accuracy_worlds = 0;
  try {
    accuracy_worlds = TakeAccuracyWorlds(argc, argv);
  } catch (const std::invalid_argument& e) {
    std::fprintf(stderr, "mujoco_bench: %s\n", e.what());
    return 2;
  }
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 2;
  mju_user_warning = CountMujocoWarning;
  const bool swap_ok = MujocoSwapMatchesOwnData();
  std::printf("MuJoCo worlds swapped through one mjData per thread step bit for bit as in their "
              "own mjData: %s\n", swap_ok ? "yes" : "NO");
  const bool masses_ok = MujocoMassesMatchOurs();
  RegisterAll();
  PrintSpin("before", SpinRatio());
  const int color = isatty(fileno(stdout)) ? benchmark::ConsoleReporter::OO_Color : 0;
  RecordingReporter reporter(benchmark::ConsoleReporter::OutputOptions(
      benchmark::ConsoleReporter::OO_Tabular | color));
  benchmark::RunSpecifiedBenchmarks(&reporter);
  std::cout.flush();
  PrintTable(reporter);
  PrintSpin("after", SpinRatio());
  const bool accuracy_finite = RunAccuracy(accuracy_worlds);
  benchmark::Shutdown();
  const std::size_t nonfinite = NonFiniteWorldTally();
  const int warnings = mujoco_warnings.load();
  if (nonfinite != 0 || warnings != 0 || !accuracy_finite || !swap_ok || !masses_ok) {
    std::printf("FAILED: %zu non-finite worlds in benchmarks, %d MuJoCo warnings, accuracy "
                "errors %s, shared mjData %s, contact scenes' masses %s\n",
                nonfinite, warnings, accuracy_finite ? "finite" : "NOT finite",
                swap_ok ? "exact" : "NOT exact", masses_ok ? "ours" : "NOT ours");
    return 1;
  }
  std::printf("all worlds finite, no MuJoCo warnings\n");
  return 0;
}
