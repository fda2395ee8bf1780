// Input an adversarial user gives (issue 21): infinite limits, tiny or huge
// step sizes, per-world setters given what the scene refuses, enum values
// out of range, absurd thread counts, moved-from batches, concurrent calls,
// a forced SIMD target while another thread builds a Batch, stale
// non-finite-input flags and interrupted steps. Each is either refused by
// name with nothing written, or accepted with a defined meaning and every
// world healthy.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <atomic>
#include <cfloat>
#include <cmath>
#include <cstring>
#include <functional>
#include <limits>
#include <stop_token>
#include <string>
#include <thread>
#include <vector>

#include "batch/step_kernels.h"
#include "hwy/targets.h"
#include "manyworlds/batch.h"
#include "manyworlds/error.h"
#include "manyworlds/scenes.h"

namespace manyworlds {
namespace {

using ::testing::HasSubstr;

constexpr float kInf = std::numeric_limits<float>::infinity();
constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr std::size_t kWorlds = 40;

// A static ground (body 0) and a box 1 m above it (body 1).
Scene GroundAndBox() {
  Scene scene;
  BodySettings ground;
  ground.name = "ground";
  ground.motion_type = MotionType::kStatic;
  BodySettings box;
  box.name = "box";
  box.position = {0, 1, 0};
  scene.AddBody(ground);
  scene.AddBody(box);
  return scene;
}

// The box on a slider along X from the ground, with a position motor.
Scene SliderScene(float min, float max) {
  Scene scene = GroundAndBox();
  SliderConstraintSettings slider;
  slider.name = "rail";
  slider.body1 = 0;
  slider.body2 = 1;
  slider.point1 = slider.point2 = {0, 1, 0};
  slider.limits_min = min;
  slider.limits_max = max;
  slider.motor_state = MotorState::kPosition;
  slider.target_position = 0.5f;
  scene.AddConstraint(slider);
  return scene;
}

// The box on a six-DOF joint: X limited by `min_x, max_x`, Y and Z fixed.
Scene SixDofScene(float min_x, float max_x) {
  Scene scene = GroundAndBox();
  SixDofConstraintSettings six;
  six.name = "six";
  six.body1 = 0;
  six.body2 = 1;
  six.position1 = six.position2 = {0, 1, 0};
  six.limit_min[0] = min_x;
  six.limit_max[0] = max_x;
  six.MakeFixedAxis(SixDofAxis::kTranslationY);
  six.MakeFixedAxis(SixDofAxis::kTranslationZ);
  scene.AddConstraint(six);
  return scene;
}

// Every byte a Batch holds, as a "nothing was written" witness.
std::vector<std::byte> Bytes(const Batch& batch) {
  const BatchSnapshot snapshot = batch.Snapshot();
  return {snapshot.bytes().begin(), snapshot.bytes().end()};
}

std::vector<float> StateOf(const Batch& batch) {
  std::vector<float> state(batch.world_count() * batch.body_count() * kStateFloatsPerBody);
  batch.GetState(state);
  return state;
}

// Expects `call` to throw SceneError naming every word, and `batch` to hold
// the same bytes afterwards.
void ExpectRefusedUnchanged(Batch& batch, const std::function<void()>& call,
                            std::vector<std::string> words) {
  const std::vector<std::byte> before = Bytes(batch);
  try {
    call();
    ADD_FAILURE() << "accepted; expected a refusal naming " << words.front();
  } catch (const SceneError& error) {
    for (const std::string& word : words) EXPECT_THAT(error.what(), HasSubstr(word));
  }
  EXPECT_TRUE(Bytes(batch) == before) << "a refused call wrote into the batch";
}

void StepHealthy(Batch& batch, int steps) {
  for (int i = 0; i < steps; ++i) batch.Step(StepSettings{});
  EXPECT_EQ(batch.UnhealthyWorldCount(), 0u);
}

// ---- infinite limits: "no bound on that side", exactly as FLT_MAX

TEST(InfiniteLimitsTest, SliderBoundsAtInfinityMeanNoBoundAndMatchFltMaxBitForBit) {
  for (const auto& [min, max] : {std::pair{-1.0f, kInf}, std::pair{-kInf, kInf},
                                std::pair{-kInf, 2.0f}, std::pair{-1.0f, 1e30f}}) {
    Batch infinite(SliderScene(min, max), kWorlds);
    Batch finite(SliderScene(std::isinf(min) ? -FLT_MAX : min,
                             max >= kMaxHealthyCoordinate ? FLT_MAX : max),
                 kWorlds);
    StepHealthy(infinite, 30);
    StepHealthy(finite, 30);
    EXPECT_TRUE(StateOf(infinite) == StateOf(finite)) << min << ", " << max;
  }
}

TEST(InfiniteLimitsTest, PerWorldInfiniteLimitsKeepTheWorldHealthy) {
  Batch batch(SliderScene(-1, 1), kWorlds);
  batch.SetLimits(3, 0, -kInf, kInf);
  batch.SetLimits(4, 0, -0.25f, kInf);
  StepHealthy(batch, 30);
}

TEST(InfiniteLimitsTest, SixDofTranslationAtInfinityIsFreeOrRefusedByName) {
  Batch free_x(SixDofScene(-kInf, kInf), kWorlds);
  Batch free_x_flt(SixDofScene(-FLT_MAX, FLT_MAX), kWorlds);
  StepHealthy(free_x, 30);
  StepHealthy(free_x_flt, 30);
  EXPECT_TRUE(StateOf(free_x) == StateOf(free_x_flt));
  // A lower bound of +inf (locked at infinity) has no meaning.
  EXPECT_THROW(
      {
        try {
          Batch batch(SixDofScene(kInf, kInf), kWorlds);
        } catch (const SceneError& e) {
          EXPECT_THAT(e.what(), HasSubstr("limit_min[0]"));
          throw;
        }
      },
      SceneError);
  EXPECT_THROW(Batch(SixDofScene(-kInf, -kInf), kWorlds), SceneError);
  EXPECT_THROW(Batch(SixDofScene(-1, kNaN), kWorlds), SceneError);
}

// ---- step settings

TEST(StepSettingsTest, ATinyStepIsRefusedAndTheNextNormalStepStaysHealthy) {
  Batch batch(SliderScene(-1, 1), kWorlds);
  batch.Step(StepSettings{});
  StepSettings tiny;
  tiny.delta_time = 1e-45f;
  ExpectRefusedUnchanged(batch, [&] { batch.Step(tiny); }, {"delta_time", "e-45"});
  StepHealthy(batch, 5);
}

TEST(StepSettingsTest, OutOfRangeSettingsAreRefusedByName) {
  Batch batch(SliderScene(-1, 1), 4);
  const auto refused = [&](const char* field, auto spoil) {
    StepSettings settings;
    spoil(settings);
    ExpectRefusedUnchanged(batch, [&] { batch.Step(settings); }, {field});
  };
  refused("delta_time", [](StepSettings& s) { s.delta_time = 2.0f; });
  refused("delta_time", [](StepSettings& s) { s.delta_time = kInf; });
  refused("delta_time", [](StepSettings& s) { s.substeps = 64, s.delta_time = 1e-5f; });
  refused("substeps", [](StepSettings& s) { s.substeps = kMaxSubsteps + 1; });
  refused("velocity_iterations", [](StepSettings& s) { s.velocity_iterations = 1 << 30; });
  refused("position_iterations", [](StepSettings& s) { s.position_iterations = -1; });
  refused("unhealthy_worlds",
          [](StepSettings& s) { s.unhealthy_worlds = static_cast<UnhealthyWorlds>(7); });
}

// ---- per-world setters: the scene's checks, refused before anything is written

TEST(PerWorldSetterTest, ValuesTheSceneRefusesAreRefusedForOneWorld) {
  Scene scene = SliderScene(-1, 1);
  std::get<SliderConstraintSettings>(scene.constraints()[0]).limits_spring = {
      SpringMode::kFrequencyAndDamping, 5.0f, 0.5f};
  Batch batch(scene, kWorlds);
  const auto refused = [&](std::function<void()> call, std::vector<std::string> words) {
    words.push_back("world 3");
    ExpectRefusedUnchanged(batch, call, words);
  };
  refused([&] { batch.SetMotorSpring(3, 0, kNaN, 1); }, {"rail", "motor.spring"});
  refused([&] { batch.SetMotorSpring(3, 0, -2, 1); }, {"motor.spring", "position motor"});
  refused([&] { batch.SetMotorSpring(3, 0, 2, -1); }, {"motor.spring"});
  refused([&] { batch.SetLimitsSpring(3, 0, 5, kNaN); }, {"limits_spring"});
  refused([&] { batch.SetLimitsSpring(3, 0, kInf, 1); }, {"limits_spring"});
  refused([&] { batch.SetLimits(3, 0, 1, 2); }, {"limits_min"});
  refused([&] { batch.SetLimits(3, 0, kInf, kInf); }, {"limits_min"});
  refused([&] { batch.SetLimits(3, 0, -1, kNaN); }, {"limits_max"});
  refused([&] { batch.SetMotorLimits(3, 0, 1, kNaN); }, {"min_force_limit"});
  refused([&] { batch.SetMassProperties(3, 1, -1, {1, 1, 1}); }, {"box", "mass"});
  refused([&] { batch.SetMassProperties(3, 1, 1, {1, kInf, 1}); }, {"inertia_diagonal[1]"});
  refused([&] { batch.SetDamping(3, 1, kNaN, 0); }, {"linear_damping"});
  refused([&] { batch.SetGravityFactor(3, 1, kInf); }, {"gravity_factor"});
  // What the scene accepts, a world accepts.
  batch.SetMotorSpring(3, 0, 3, 0.5f);
  batch.SetLimitsSpring(3, 0, 8, 0.2f);
  batch.SetLimits(3, 0, -0.5f, 0.5f);
  StepHealthy(batch, 10);
}

// A body that may only rotate has inverse mass 0 in the scene (Jolt); a
// per-world mass must give it the same bits as the same mass in the scene.
// Here a pivot that may only turn holds a bob on a point joint: with the
// pivot's inverse mass not 0, the joint's effective mass and the swing differ.
TEST(PerWorldSetterTest, PerWorldMassOfATranslationLockedBodyEqualsTheScenes) {
  const auto scene_with_mass = [](float mass) {
    Scene scene;
    BodySettings pivot;
    pivot.name = "pivot";
    pivot.allowed_dofs = AllowedDofs::kRotationX | AllowedDofs::kRotationY |
                         AllowedDofs::kRotationZ;
    pivot.mass = mass;
    pivot.inertia_diagonal = {mass, mass, mass};
    BodySettings bob;
    bob.name = "bob";
    bob.position = {1, 0, 0};
    const std::size_t p = scene.AddBody(pivot), b = scene.AddBody(bob);
    PointConstraintSettings joint;
    joint.body1 = p;
    joint.body2 = b;
    scene.AddConstraint(joint);
    return scene;
  };
  Batch given(scene_with_mass(3.0f), kWorlds);
  Batch set(scene_with_mass(1.0f), kWorlds);
  for (std::size_t w = 0; w < kWorlds; ++w) set.SetMassProperties(w, 0, 3.0f, {3, 3, 3});
  for (int i = 0; i < 20; ++i) {
    given.Step(StepSettings{});
    set.Step(StepSettings{});
  }
  EXPECT_TRUE(StateOf(given) == StateOf(set));
}

// ---- enum values outside their enumerators

TEST(EnumRangeTest, OutOfRangeEnumValuesAreRefusedNamingTheField) {
  const auto refused = [](const char* field, std::function<void(Scene&)> spoil) {
    Scene scene = SliderScene(-1, 1);
    spoil(scene);
    try {
      Batch batch(scene, 4);
      ADD_FAILURE() << field << " accepted";
    } catch (const SceneError& error) {
      EXPECT_THAT(error.what(), HasSubstr(field));
    }
  };
  const auto slider = [](Scene& scene) -> SliderConstraintSettings& {
    return std::get<SliderConstraintSettings>(scene.constraints()[0]);
  };
  refused("motor_state", [&](Scene& s) { slider(s).motor_state = static_cast<MotorState>(9); });
  refused("motor.spring.mode",
          [&](Scene& s) { slider(s).motor.spring.mode = static_cast<SpringMode>(7); });
  refused("limits_spring.mode",
          [&](Scene& s) { slider(s).limits_spring.mode = static_cast<SpringMode>(3); });
  refused("space", [&](Scene& s) { slider(s).space = static_cast<ConstraintSpace>(2); });
  refused("motion_type",
          [](Scene& s) { s.bodies()[1].motion_type = static_cast<MotionType>(3); });
  refused("swing_type", [](Scene& s) {
    SwingTwistConstraintSettings swing;
    swing.body1 = 0;
    swing.body2 = 1;
    swing.swing_type = static_cast<SwingType>(5);
    s.AddConstraint(swing);
  });
  Batch batch(SliderScene(-1, 1), 4);
  std::vector<float> out(4 * 2 * 3);
  EXPECT_THROW(batch.GetField(static_cast<StateField>(9), out), std::invalid_argument);
}

// ---- threads, moved-from batches, concurrent calls

TEST(ConcurrencyTest, AbsurdThreadCountsAreRefused) {
  for (const int threads : {-1, kMaxThreads + 1, 1 << 30}) {
    BatchOptions options;
    options.threads = threads;
    try {
      Batch batch(SliderScene(-1, 1), 4, options);
      ADD_FAILURE() << threads << " threads accepted";
    } catch (const SceneError& error) {
      EXPECT_THAT(error.what(), HasSubstr("threads"));
    }
  }
}

TEST(ConcurrencyTest, AMovedFromBatchThrowsInsteadOfCrashing) {
  Batch batch(SliderScene(-1, 1), 4);
  Batch taken = std::move(batch);
  EXPECT_THROW(batch.Step(StepSettings{}), std::logic_error);  // NOLINT(bugprone-use-after-move)
  EXPECT_THROW(batch.world_count(), std::logic_error);
  EXPECT_THROW(batch.SetForce(0, 1, {1, 0, 0}), std::logic_error);
  EXPECT_THROW(batch.Snapshot(), std::logic_error);
  batch = Batch(SliderScene(-1, 1), 4);  // assigning makes it usable again
  batch.Step(StepSettings{});
  taken.Step(StepSettings{});
}

// Two threads step one Batch as fast as they can. Calls that find the other
// thread inside throw; the steps that ran must equal as many sequential
// steps, bit for bit (nothing was corrupted).
TEST(ConcurrencyTest, ConcurrentStepsOfOneBatchThrowInsteadOfCorrupting) {
  const Scene scene = MakeScene("chain16");
  BatchOptions one_thread;
  one_thread.threads = 1;
  Batch shared(scene, 128, one_thread);
  std::atomic<int> stepped{0}, refused{0};
  // Until the threads have met at least once (on a loaded machine they may
  // take turns on one core for a while), at most 2000 attempts each.
  const auto hammer = [&] {
    for (int i = 0; i < 2000 && refused.load() < 3; ++i) {
      try {
        shared.Step(StepSettings{});
        ++stepped;
      } catch (const std::logic_error&) {
        ++refused;
      }
    }
  };
  std::thread other(hammer);
  hammer();
  other.join();
  EXPECT_GT(refused.load(), 0) << "the threads never overlapped: the test proved nothing";
  Batch sequential(scene, 128, one_thread);
  for (int i = 0; i < stepped.load(); ++i) sequential.Step(StepSettings{});
  EXPECT_TRUE(StateOf(shared) == StateOf(sequential));
}

// Forcing a target on one Batch used to change Highway's global target set
// for a moment, so a Batch built meanwhile on another thread could get the
// forced target's kernels.
TEST(ConcurrencyTest, AForcedTargetNeverLeaksIntoABatchBuiltOnAnotherThread) {
  const auto& supported = SupportedKernels<StepKernels>();
  if (supported.size() < 2) GTEST_SKIP() << "one SIMD target only";
  const std::string best = DispatchedKernels<StepKernels>().target.name;
  const Scene scene = SliderScene(-1, 1);
  std::atomic<bool> done{false};
  std::thread forcing([&] {
    BatchOptions options;
    options.target = supported.back()->target.bits;
    while (!done) Batch forced(scene, 4, options);
  });
  int wrong = 0;
  for (int i = 0; i < 2000; ++i) wrong += Batch(scene, 4).SimdTarget() != best;
  done = true;
  forcing.join();
  EXPECT_EQ(wrong, 0);
}

// ---- inputs and interruptions

TEST(InputHealthTest, ANonFiniteInputOverwrittenBeforeTheStepIsNotReported) {
  Batch batch(SliderScene(-1, 1), kWorlds);
  batch.SetTargetPosition(2, 0, kNaN);
  batch.SetTargetPosition(2, 0, 0.25f);
  batch.SetForce(5, 1, {kInf, 0, 0});
  batch.SetForce(5, 1, {1, 0, 0});
  batch.SetForce(7, 1, {kNaN, 0, 0});
  batch.SetTargetPosition(7, 0, kNaN);
  batch.SetForce(7, 1, {1, 0, 0});  // the target is still NaN
  batch.Step(StepSettings{});
  EXPECT_EQ(batch.WorldHealth()[2], 0);
  EXPECT_EQ(batch.WorldHealth()[5], 0);
  EXPECT_NE(batch.WorldHealth()[7] & kNonFiniteInput, 0);
}

TEST(InterruptTest, AStopBeforeTheStepLeavesEveryWorldUntouchedAndFlagged) {
  Batch batch(SliderScene(-1, 1), kWorlds);
  batch.Step(StepSettings{});
  const std::vector<float> before = StateOf(batch);
  std::stop_source stop;
  stop.request_stop();
  EXPECT_FALSE(batch.Step(StepSettings{}, stop.get_token()));
  EXPECT_TRUE(StateOf(batch) == before);
  for (const std::uint8_t bits : batch.WorldHealth()) EXPECT_EQ(bits, kNotStepped);
  EXPECT_TRUE(batch.Step(StepSettings{}, std::stop_source().get_token()));
  EXPECT_EQ(batch.UnhealthyWorldCount(), 0u);
}

// A stop requested from another thread during a long step: whatever block it
// catches, the worlds flagged kNotStepped are exactly as before and all the
// others moved on.
TEST(InterruptTest, AStopDuringTheStepSplitsWorldsIntoSteppedAndUntouched) {
  BatchOptions one_thread;
  one_thread.threads = 1;
  Batch batch(MakeScene("chain16"), 2048, one_thread);  // ~2 ms a step in Release
  batch.Step(StepSettings{});
  const std::vector<float> before = StateOf(batch);
  std::stop_source stop;
  std::thread stopper([&] {
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
    stop.request_stop();
  });
  const bool completed = batch.Step(StepSettings{}, stop.get_token());
  stopper.join();
  const std::vector<float> after = StateOf(batch);
  const std::size_t per_world = batch.body_count() * kStateFloatsPerBody;
  std::size_t untouched = 0;
  for (std::size_t w = 0; w < batch.world_count(); ++w) {
    const bool same =
        std::memcmp(&after[w * per_world], &before[w * per_world], per_world * sizeof(float)) == 0;
    const bool not_stepped = batch.WorldHealth()[w] == kNotStepped;
    EXPECT_EQ(same, not_stepped) << "world " << w;
    untouched += not_stepped;
  }
  EXPECT_EQ(completed, untouched == 0);
}

}  // namespace
}  // namespace manyworlds
