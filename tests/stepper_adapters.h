// One small interface over the two steppers, so that a behaviour test is
// written once and runs on the scalar reference (float and double) and on the
// SIMD batch on every Highway target this CPU runs (tests/jolt_behaviour_test.cc).
//
// Everything is read and written in double (Eigen); each stepper converts to
// its own precision. The batch runs kBatchWorlds identical copies of the scene
// (one full block of 16 and one partial block) with identical inputs; after
// every Step and state write it checks that every world holds exactly the bits
// of world 0 (a cheap determinism check on top of the behaviour), and the
// accessors read world 0.
//
// The batch has no hinge-angle or slider-position read-out; HingeAngle and
// SliderPosition apply the reference's own measurement (reference::World<double>
// built from the same scene, so with the same r0^-1, anchors and axes) to world
// 0's state.
#pragma once

#include <gtest/gtest.h>

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <functional>
#include <memory>
#include <ostream>
#include <string>
#include <vector>

#include "batch/step_kernels.h"
#include "hwy/targets.h"
#include "manyworlds/batch.h"
#include "manyworlds/scene.h"
#include "reference/world.h"

namespace manyworlds::stepper_test {

using Vec3d = reference::Vec3<double>;
using Quatd = reference::Quat<double>;

class Stepper {
 public:
  virtual ~Stepper() = default;

  virtual void Step(const StepSettings& settings) = 0;

  // ---- state of one body (world 0 of a batch)
  virtual Vec3d Position(std::size_t body) const = 0;
  virtual Quatd Rotation(std::size_t body) const = 0;
  virtual Vec3d LinearVelocity(std::size_t body) const = 0;
  virtual Vec3d AngularVelocity(std::size_t body) const = 0;
  // Overwrite a body's state (every world of a batch); the scene's
  // constraint frames stay those of the scene's initial poses.
  virtual void SetPosition(std::size_t body, const Vec3d& position) = 0;
  virtual void SetRotation(std::size_t body, const Quatd& rotation) = 0;
  virtual void SetVelocities(std::size_t body, const Vec3d& linear, const Vec3d& angular) = 0;

  // ---- actions for the next Step (every world of a batch)
  virtual void SetForce(std::size_t body, const Vec3d& force) = 0;
  virtual void SetTorque(std::size_t body, const Vec3d& torque) = 0;
  virtual void SetTargetVelocity(std::size_t constraint, double velocity) = 0;
  virtual void SetTargetPosition(std::size_t constraint, double position) = 0;
  // Swing-twist and six-DOF drives (body 2's frame in body 1's; rad/s about
  // body 2's frame axes) and six-DOF translation drives (body 1's frame).
  virtual void SetTargetOrientation(std::size_t constraint, const Quatd& orientation) = 0;
  virtual void SetTargetAngularVelocity(std::size_t constraint, const Vec3d& velocity) = 0;
  virtual void SetTargetTranslation(std::size_t constraint, const Vec3d& translation) = 0;
  virtual void SetTargetLinearVelocity(std::size_t constraint, const Vec3d& velocity) = 0;

  // ---- the reference's measurements of a hinge or slider
  virtual double HingeAngle(std::size_t constraint) const = 0;
  virtual double SliderPosition(std::size_t constraint) const = 0;
};

// ----------------------------------------------------------- reference

template <class T>
class ReferenceStepper final : public Stepper {
 public:
  explicit ReferenceStepper(const Scene& scene) : world_(scene) {}

  void Step(const StepSettings& settings) override { world_.Step(settings); }

  Vec3d Position(std::size_t body) const override {
    return world_.body(body).position.template cast<double>();
  }
  Quatd Rotation(std::size_t body) const override {
    return world_.body(body).rotation.template cast<double>();
  }
  Vec3d LinearVelocity(std::size_t body) const override {
    return world_.body(body).linear_velocity.template cast<double>();
  }
  Vec3d AngularVelocity(std::size_t body) const override {
    return world_.body(body).angular_velocity.template cast<double>();
  }
  void SetPosition(std::size_t body, const Vec3d& position) override {
    world_.body(body).position = position.cast<T>();
  }
  void SetRotation(std::size_t body, const Quatd& rotation) override {
    world_.body(body).rotation = rotation.cast<T>();
  }
  void SetVelocities(std::size_t body, const Vec3d& linear, const Vec3d& angular) override {
    world_.body(body).linear_velocity = linear.cast<T>();
    world_.body(body).angular_velocity = angular.cast<T>();
  }

  void SetForce(std::size_t body, const Vec3d& force) override {
    world_.SetForce(body, force.cast<T>());
  }
  void SetTorque(std::size_t body, const Vec3d& torque) override {
    world_.SetTorque(body, torque.cast<T>());
  }
  void SetTargetVelocity(std::size_t constraint, double velocity) override {
    world_.SetTargetVelocity(constraint, T(velocity));
  }
  void SetTargetPosition(std::size_t constraint, double position) override {
    world_.SetTargetPosition(constraint, T(position));
  }
  void SetTargetOrientation(std::size_t constraint, const Quatd& orientation) override {
    world_.SetTargetOrientation(constraint, orientation.cast<T>());
  }
  void SetTargetAngularVelocity(std::size_t constraint, const Vec3d& velocity) override {
    world_.SetTargetAngularVelocity(constraint, velocity.cast<T>());
  }
  void SetTargetTranslation(std::size_t constraint, const Vec3d& translation) override {
    world_.SetTargetTranslation(constraint, translation.cast<T>());
  }
  void SetTargetLinearVelocity(std::size_t constraint, const Vec3d& velocity) override {
    world_.SetTargetLinearVelocity(constraint, velocity.cast<T>());
  }

  double HingeAngle(std::size_t constraint) const override {
    return double(world_.HingeAngle(constraint));
  }
  double SliderPosition(std::size_t constraint) const override {
    return double(world_.SliderPosition(constraint));
  }

 private:
  reference::World<T> world_;
};

// --------------------------------------------------------------- batch

inline constexpr std::size_t kBatchWorlds = 20;  // one full block of 16, one partial

class BatchStepper final : public Stepper {
 public:
  BatchStepper(const Scene& scene, std::int64_t target, std::size_t worlds = kBatchWorlds)
      : batch_(scene, worlds, BatchOptions{1, 0, target}),
        measure_(scene),
        per_world_(batch_.body_count() * kStateFloatsPerBody),
        state_(worlds * per_world_) {
    Refresh("construction");
  }

  void Step(const StepSettings& settings) override {
    batch_.Step(settings);
    ++steps_;
    Refresh("step");
  }

  Vec3d Position(std::size_t body) const override { return Read(body, 0); }
  Quatd Rotation(std::size_t body) const override {
    const float* s = Slot(body);
    return Quatd(s[6], s[3], s[4], s[5]);  // (w, x, y, z)
  }
  Vec3d LinearVelocity(std::size_t body) const override { return Read(body, 7); }
  Vec3d AngularVelocity(std::size_t body) const override { return Read(body, 10); }

  void SetPosition(std::size_t body, const Vec3d& position) override {
    Write(body, 0, {float(position.x()), float(position.y()), float(position.z())});
  }
  void SetRotation(std::size_t body, const Quatd& rotation) override {
    Write(body, 3, {float(rotation.x()), float(rotation.y()), float(rotation.z()),
                    float(rotation.w())});
  }
  void SetVelocities(std::size_t body, const Vec3d& linear, const Vec3d& angular) override {
    Write(body, 7, {float(linear.x()), float(linear.y()), float(linear.z()),
                    float(angular.x()), float(angular.y()), float(angular.z())});
  }

  void SetForce(std::size_t body, const Vec3d& force) override {
    for (std::size_t w = 0; w < batch_.world_count(); ++w) batch_.SetForce(w, body, ToFloat3(force));
  }
  void SetTorque(std::size_t body, const Vec3d& torque) override {
    for (std::size_t w = 0; w < batch_.world_count(); ++w) {
      batch_.SetTorque(w, body, ToFloat3(torque));
    }
  }
  void SetTargetVelocity(std::size_t constraint, double velocity) override {
    for (std::size_t w = 0; w < batch_.world_count(); ++w) {
      batch_.SetTargetVelocity(w, constraint, float(velocity));
    }
  }
  void SetTargetPosition(std::size_t constraint, double position) override {
    for (std::size_t w = 0; w < batch_.world_count(); ++w) {
      batch_.SetTargetPosition(w, constraint, float(position));
    }
  }
  void SetTargetOrientation(std::size_t constraint, const Quatd& q) override {
    const Quaternion target{float(q.x()), float(q.y()), float(q.z()), float(q.w())};
    for (std::size_t w = 0; w < batch_.world_count(); ++w) {
      batch_.SetTargetOrientation(w, constraint, target);
    }
  }
  void SetTargetAngularVelocity(std::size_t constraint, const Vec3d& velocity) override {
    for (std::size_t w = 0; w < batch_.world_count(); ++w) {
      batch_.SetTargetAngularVelocity(w, constraint, ToFloat3(velocity));
    }
  }
  void SetTargetTranslation(std::size_t constraint, const Vec3d& translation) override {
    for (std::size_t w = 0; w < batch_.world_count(); ++w) {
      batch_.SetTargetTranslation(w, constraint, ToFloat3(translation));
    }
  }
  void SetTargetLinearVelocity(std::size_t constraint, const Vec3d& velocity) override {
    for (std::size_t w = 0; w < batch_.world_count(); ++w) {
      batch_.SetTargetLinearVelocity(w, constraint, ToFloat3(velocity));
    }
  }

  double HingeAngle(std::size_t constraint) const override {
    SyncMeasure();
    return measure_.HingeAngle(constraint);
  }
  double SliderPosition(std::size_t constraint) const override {
    SyncMeasure();
    return measure_.SliderPosition(constraint);
  }

  const Batch& batch() const { return batch_; }

 private:
  static Float3 ToFloat3(const Vec3d& v) { return {float(v.x()), float(v.y()), float(v.z())}; }

  const float* Slot(std::size_t body, std::size_t world = 0) const {
    return state_.data() + world * per_world_ + body * kStateFloatsPerBody;
  }
  Vec3d Read(std::size_t body, std::size_t offset) const {
    const float* s = Slot(body) + offset;
    return Vec3d(s[0], s[1], s[2]);
  }

  // Writes `values` at `offset` of the body's state in every world.
  void Write(std::size_t body, std::size_t offset, const std::vector<float>& values) {
    for (std::size_t w = 0; w < batch_.world_count(); ++w) {
      float* s = state_.data() + w * per_world_ + body * kStateFloatsPerBody + offset;
      std::memcpy(s, values.data(), values.size() * sizeof(float));
    }
    batch_.SetState(state_);
    Refresh("state write");  // SetState normalises rotations
  }

  // Reads every world and checks them bitwise against world 0; reports the
  // first differing float once per test (the test fails).
  void Refresh(const char* after) {
    batch_.GetState(state_);
    if (reported_) return;
    for (std::size_t w = 1; w < batch_.world_count(); ++w) {
      if (std::memcmp(Slot(0, w), Slot(0, 0), per_world_ * sizeof(float)) == 0) continue;
      for (std::size_t i = 0; i < per_world_; ++i) {
        const float a = Slot(0, 0)[i], b = Slot(0, w)[i];
        if (std::memcmp(&a, &b, sizeof(float)) == 0) continue;
        ADD_FAILURE() << "batch on " << batch_.SimdTarget() << ": world " << w
                      << " differs from world 0 after " << after << " " << steps_
                      << " at body " << i / kStateFloatsPerBody << " float "
                      << i % kStateFloatsPerBody << ": " << b << " vs " << a;
        reported_ = true;
        return;
      }
    }
  }

  void SyncMeasure() const {
    for (std::size_t b = 0; b < batch_.body_count(); ++b) {
      const float* s = Slot(b);
      reference::Body<double>& body = measure_.body(b);
      body.position = Vec3d(s[0], s[1], s[2]);
      body.rotation = Quatd(s[6], s[3], s[4], s[5]);
      body.linear_velocity = Vec3d(s[7], s[8], s[9]);
      body.angular_velocity = Vec3d(s[10], s[11], s[12]);
    }
  }

  Batch batch_;
  mutable reference::World<double> measure_;  // measurements only, never stepped
  std::size_t per_world_;
  std::vector<float> state_;  // [world][body][13] after the last Step or write
  int steps_ = 0;
  bool reported_ = false;
};

// ------------------------------------------------ parameters of the tests

// One stepper to run a test on: its name (for the test name) and a factory.
struct StepperKind {
  std::string name;
  std::function<std::unique_ptr<Stepper>(const Scene&)> make;
  bool is_batch = false;
  // Whether the stepper computes in double (the reference in double); the
  // batch and the float reference compute in float. For tolerances that are
  // rounding bounds of the precision.
  bool is_double = false;
};

// gtest prints a failing test's parameter with this.
inline void PrintTo(const StepperKind& kind, std::ostream* os) { *os << kind.name; }

inline std::vector<StepperKind> AllStepperKinds() {
  std::vector<StepperKind> kinds;
  kinds.push_back({"reference_float",
                   [](const Scene& scene) -> std::unique_ptr<Stepper> {
                     return std::make_unique<ReferenceStepper<float>>(scene);
                   },
                   false, false});
  kinds.push_back({"reference_double",
                   [](const Scene& scene) -> std::unique_ptr<Stepper> {
                     return std::make_unique<ReferenceStepper<double>>(scene);
                   },
                   false, true});
  for (const StepKernels* kernels : SupportedKernels<StepKernels>()) {
    const std::int64_t target = kernels->target.bits;
    kinds.push_back({std::string("batch_") + hwy::TargetName(target),
                     [target](const Scene& scene) -> std::unique_ptr<Stepper> {
                       return std::make_unique<BatchStepper>(scene, target);
                     },
                     true, false});
  }
  return kinds;
}

}  // namespace manyworlds::stepper_test
