// Batch: the blocks of worlds, the TBB loop over them and the per-world API.

#include "manyworlds/batch.h"

#include <tbb/blocked_range.h>
#include <tbb/info.h>
#include <tbb/parallel_for.h>
#include <tbb/partitioner.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include "batch/constraint_block.h"
#include "batch/constraint_error.h"
#include "batch/plan.h"
#include "batch/scene_setup.h"
#include "batch/step_kernels.h"
#include "hwy/targets.h"
#include "manyworlds/error.h"
#include "manyworlds/lanes.h"

namespace manyworlds {

std::size_t StateFieldOffset(StateField field) {
  switch (field) {
    case StateField::kPosition: return 0;
    case StateField::kRotation: return 3;
    case StateField::kLinearVelocity: return 7;
    case StateField::kAngularVelocity: return 10;
  }
  return 0;
}

std::size_t StateFieldSize(StateField field) {
  return field == StateField::kRotation ? 4 : 3;
}

namespace {

const StepKernels* StepKernelsFor(std::int64_t target) {
  if (target == 0) return &DispatchedKernels<StepKernels>();
  const StepKernels* kernels = KernelsForTarget<StepKernels>(target);
  if (kernels == nullptr) {
    throw SceneError("batch options: target " + std::string(hwy::TargetName(target)) +
                     " is not compiled in or not supported by this CPU");
  }
  return kernels;
}

}  // namespace

class Batch::Impl {
 public:
  Impl(const Scene& scene, std::size_t world_count, BatchOptions options)
      : scene_(scene),
        plan_(CompilePlan(scene)),
        world_count_(world_count),
        block_count_(BlockCount(world_count)),
        arrays_per_block_(plan_.block_bytes / sizeof(LaneArray)),
        initial_(arrays_per_block_),
        storage_(arrays_per_block_ * block_count_),
        kernels_(StepKernelsFor(options.target)),
        threads_(options.threads > 0 ? options.threads : tbb::info::default_concurrency()),
        arena_(threads_),
        blocks_per_task_(options.blocks_per_task) {
    if (world_count == 0) throw SceneError("batch: world_count must be at least 1");
    if (options.threads < 0) throw SceneError("batch options: threads must be >= 0");
    WriteInitialBlock(scene_, plan_, Bytes(initial_.data()));
    for (std::size_t block = 0; block < block_count_; ++block) {
      std::copy(initial_.begin(), initial_.end(), storage_.begin() + block * arrays_per_block_);
    }
  }

  static constexpr std::size_t BlockCount(std::size_t worlds) {
    return (worlds + kLaneWidth - 1) / kLaneWidth;
  }
  static std::byte* Bytes(LaneArray* arrays) { return reinterpret_cast<std::byte*>(arrays); }

  std::byte* Block(std::size_t block) {
    return Bytes(storage_.data() + block * arrays_per_block_);
  }
  const std::byte* Block(std::size_t block) const {
    return reinterpret_cast<const std::byte*>(storage_.data() + block * arrays_per_block_);
  }

  void Step(const StepSettings& settings) {
    CheckStepSettings(settings);
    const float substep_dt = settings.delta_time / static_cast<float>(settings.substeps);
    StepParams params{};
    params.substep_delta_time = substep_dt;
    params.substeps = settings.substeps;
    params.first_warm_start_ratio =
        settings.warm_start && previous_substep_dt_ > 0.0f ? substep_dt / previous_substep_dt_
                                                           : 0.0f;
    params.velocity_iterations = settings.velocity_iterations;
    params.position_iterations = settings.position_iterations;
    params.baumgarte = settings.baumgarte;
    params.gravity = settings.gravity;
    params.gyroscopic = settings.gyroscopic;
    previous_substep_dt_ = substep_dt;

    const std::size_t grain =
        blocks_per_task_ > 0
            ? blocks_per_task_
            : std::max<std::size_t>(1, block_count_ / (static_cast<std::size_t>(threads_) * 4));
    const bool reset_unhealthy = settings.unhealthy_worlds == UnhealthyWorlds::kReset;
    auto step_blocks = [&](const tbb::blocked_range<std::size_t>& range) {
      for (std::size_t block = range.begin(); block != range.end(); ++block) {
        const bool unhealthy = kernels_->step_block(plan_, Block(block), params);
        RecordHealth(block, unhealthy, reset_unhealthy);
      }
    };
    if (threads_ == 1 || block_count_ == 1) {
      step_blocks(tbb::blocked_range<std::size_t>(0, block_count_));
      return;
    }
    arena_.execute([&] {
      tbb::parallel_for(tbb::blocked_range<std::size_t>(0, block_count_, grain), step_blocks,
                        tbb::simple_partitioner());
    });
  }

  // Copies the block's health lanes of its real worlds, with the non-finite
  // inputs noted since the last Step, into health_ and, if asked, resets the
  // unhealthy worlds; runs in the block's task, while the block is in cache,
  // and touches only this block's worlds.
  void RecordHealth(std::size_t block, bool unhealthy, bool reset_unhealthy) {
    const std::size_t first = block * kLaneWidth;
    const std::size_t end = std::min(first + kLaneWidth, world_count_);
    const auto& lanes = At<WorldHealthLanes>(Block(block), plan_.health_offset);
    for (std::size_t world = first; world < end; ++world) {
      std::uint8_t bits = pending_input_[world];
      pending_input_[world] = 0;
      if (unhealthy) {
        const std::size_t l = Lane(world);
        bits |= (lanes.non_finite[l] != 0.0f ? kNonFiniteState : 0) |
                (lanes.velocity_overflow[l] != 0.0f ? kVelocityOverflow : 0) |
                (lanes.out_of_range[l] != 0.0f ? kPositionOutOfRange : 0);
      }
      health_[world] = bits;
      if (bits != 0 && reset_unhealthy) ResetWorld(world);
    }
  }

  // Actions are not refused (RL loops write them every step): a non-finite
  // one is noted and reported with the world's health after the next Step.
  template <class... Values>
  void NoteInput(std::size_t world, Values... values) {
    if (!(std::isfinite(values) && ...)) pending_input_[world] = kNonFiniteInput;
  }

  // ---- lane access
  void CheckWorld(std::size_t world) const {
    if (world >= world_count_) {
      throw std::out_of_range("world " + std::to_string(world) + " out of range (batch has " +
                              std::to_string(world_count_) + " worlds)");
    }
  }
  void CheckBody(std::size_t body) const {
    if (body >= plan_.bodies.size()) {
      throw std::out_of_range("body " + std::to_string(body) + " out of range (scene has " +
                              std::to_string(plan_.bodies.size()) + " bodies)");
    }
  }
  const ConstraintPlan& Constraint(std::size_t index) const {
    if (index >= plan_.constraints.size()) {
      throw std::out_of_range("constraint " + std::to_string(index) +
                              " out of range (scene has " +
                              std::to_string(plan_.constraints.size()) + " constraints)");
    }
    return plan_.constraints[index];
  }

  template <class Lanes>
  Lanes& In(std::size_t world, std::size_t offset) {
    return At<Lanes>(Block(world / kLaneWidth), offset);
  }
  template <class Lanes>
  const Lanes& In(std::size_t world, std::size_t offset) const {
    return *reinterpret_cast<const Lanes*>(Block(world / kLaneWidth) + offset);
  }
  static std::size_t Lane(std::size_t world) { return world % kLaneWidth; }

  BodyLanes& Body(std::size_t world, std::size_t body) {
    CheckWorld(world);
    CheckBody(body);
    return In<BodyLanes>(world, plan_.bodies[body].offset);
  }
  BodyMotionLanes& Motion(std::size_t world, std::size_t body, const char* setting) {
    BodyLanes& lanes = Body(world, body);
    (void)lanes;
    if (plan_.bodies[body].motion_offset == kAbsent) {
      throw SceneError(plan_.bodies[body].label + ": " + setting +
                       " applies to dynamic bodies only");
    }
    return In<BodyMotionLanes>(world, plan_.bodies[body].motion_offset);
  }

  void ReadState(std::size_t world, std::size_t body, float* out) const {
    const BodyLanes& b = In<BodyLanes>(world, plan_.bodies[body].offset);
    const std::size_t l = Lane(world);
    const float values[kStateFloatsPerBody] = {
        b.position.x[l],         b.position.y[l],         b.position.z[l],
        b.rotation.x[l],         b.rotation.y[l],         b.rotation.z[l],
        b.rotation.w[l],         b.linear_velocity.x[l],  b.linear_velocity.y[l],
        b.linear_velocity.z[l],  b.angular_velocity.x[l], b.angular_velocity.y[l],
        b.angular_velocity.z[l]};
    std::copy(std::begin(values), std::end(values), out);
  }

  static double RotationNorm(const float* state) {
    double norm = 0.0;
    for (int i = 3; i < 7; ++i) norm += double(state[i]) * state[i];
    return std::sqrt(norm);
  }
  // Refuses, before anything is written, a state array with a zero rotation
  // in a selected world ([world][body][13]).
  void CheckStates(std::span<const float> in, std::span<const std::uint8_t> mask) const {
    const std::size_t bodies = plan_.bodies.size();
    for (std::size_t world = 0; world < world_count_; ++world) {
      if (!Selected(mask, world)) continue;
      for (std::size_t body = 0; body < bodies; ++body) {
        if (RotationNorm(in.data() + (world * bodies + body) * kStateFloatsPerBody) == 0.0) {
          throw SceneError(plan_.bodies[body].label + " in world " + std::to_string(world) +
                           ": rotation is zero (nothing was written)");
        }
      }
    }
  }

  void WriteState(std::size_t world, std::size_t body, const float* in) {
    BodyLanes& b = In<BodyLanes>(world, plan_.bodies[body].offset);
    const std::size_t l = Lane(world);
    b.position.x[l] = in[0];
    b.position.y[l] = in[1];
    b.position.z[l] = in[2];
    // Non-finite rotations are written as given: the next Step flags the world.
    const double norm = RotationNorm(in);
    const double scale = std::isfinite(norm) ? 1.0 / norm : 1.0;
    b.rotation.x[l] = static_cast<float>(in[3] * scale);
    b.rotation.y[l] = static_cast<float>(in[4] * scale);
    b.rotation.z[l] = static_cast<float>(in[5] * scale);
    b.rotation.w[l] = static_cast<float>(in[6] * scale);
    const bool moves = plan_.bodies[body].motion != MotionType::kStatic;
    b.linear_velocity.x[l] = moves ? in[7] : 0.0f;
    b.linear_velocity.y[l] = moves ? in[8] : 0.0f;
    b.linear_velocity.z[l] = moves ? in[9] : 0.0f;
    b.angular_velocity.x[l] = moves ? in[10] : 0.0f;
    b.angular_velocity.y[l] = moves ? in[11] : 0.0f;
    b.angular_velocity.z[l] = moves ? in[12] : 0.0f;
  }

  void CheckSize(std::size_t got, std::size_t want, const char* what) const {
    if (got != want) {
      throw std::invalid_argument(std::string(what) + ": expected " + std::to_string(want) +
                                  " floats, got " + std::to_string(got));
    }
  }
  bool Selected(std::span<const std::uint8_t> mask, std::size_t world) const {
    return mask.empty() || mask[world] != 0;
  }

  // A Vec3Lanes at `offset` of every block from [world][3] values.
  void WriteLanes(std::size_t offset, std::span<const float> per_world) {
    for (std::size_t world = 0; world < world_count_; ++world) {
      Vec3Lanes& v = In<Vec3Lanes>(world, offset);
      const std::size_t l = Lane(world);
      v.x[l] = per_world[world * 3 + 0];
      v.y[l] = per_world[world * 3 + 1];
      v.z[l] = per_world[world * 3 + 2];
      NoteInput(world, v.x[l], v.y[l], v.z[l]);
    }
  }

  // Every LaneArray of the world's block, lane `world % 16`, from the initial block.
  void ResetWorld(std::size_t world) {
    LaneArray* block = storage_.data() + (world / kLaneWidth) * arrays_per_block_;
    const std::size_t l = Lane(world);
    for (std::size_t i = 0; i < arrays_per_block_; ++i) block[i][l] = initial_[i][l];
  }

  // ---- per-constraint parameters
  // Swing-twist and six-DOF drives have one motor per axis; the single-value
  // setters of hinges and sliders would not say which.
  static void RefuseMultiAxis(const ConstraintPlan& c, const char* what) {
    if (c.type == ConstraintType::kSwingTwist || c.type == ConstraintType::kSixDof) {
      throw SceneError(c.label + ": " + what + " of a " + ConstraintTypeName(c.type) +
                       " constraint is set per axis (SetTargetOrientation, "
                       "SetTargetAngularVelocity, SetTargetTranslation, "
                       "SetTargetLinearVelocity; other settings in the scene)");
    }
  }

  // The rotation drives of a swing-twist or six-DOF constraint.
  RotationDriveLanes& RotationDrive(std::size_t world, std::size_t constraint, const char* what) {
    CheckWorld(world);
    const ConstraintPlan& c = Constraint(constraint);
    if (!c.has_rotation_drives()) {
      throw SceneError(c.label + ": " + what +
                       " needs rotation motors or friction (a swing-twist or six-DOF "
                       "constraint with a motor state or max friction)");
    }
    return In<RotationDriveLanes>(world, c.rotation_drive_offset);
  }

  // The three translation drives of a six-DOF constraint.
  LinearMotorLanes* TranslationDrives(std::size_t world, std::size_t constraint,
                                      const char* what) {
    CheckWorld(world);
    const ConstraintPlan& c = Constraint(constraint);
    if (c.type != ConstraintType::kSixDof || !c.has_motor()) {
      throw SceneError(c.label + ": " + what +
                       " needs a six-DOF constraint with translation motors or friction");
    }
    return &In<LinearMotorLanes>(world, c.motor_offset);
  }

  template <class Fn>
  void WithMotor(std::size_t world, std::size_t constraint, const char* what, Fn&& fn) {
    CheckWorld(world);
    const ConstraintPlan& c = Constraint(constraint);
    RefuseMultiAxis(c, what);
    if (c.motor_offset == kAbsent) {
      throw SceneError(c.label + ": " + what +
                       " needs a motor or friction in the scene (motor_state / max friction)");
    }
    if (c.type == ConstraintType::kHinge) {
      fn(In<AngularMotorLanes>(world, c.motor_offset), c);
    } else {
      fn(In<LinearMotorLanes>(world, c.motor_offset), c);
    }
  }
  template <class Fn>
  void WithLimits(std::size_t world, std::size_t constraint, const char* what, Fn&& fn) {
    CheckWorld(world);
    const ConstraintPlan& c = Constraint(constraint);
    RefuseMultiAxis(c, what);
    if (c.limit_offset == kAbsent) {
      throw SceneError(c.label + ": " + what + " needs limits in the scene");
    }
    if (c.type == ConstraintType::kHinge) {
      fn(In<AngularLimitLanes>(world, c.limit_offset), c);
    } else {
      fn(In<LinearLimitLanes>(world, c.limit_offset), c);
    }
  }

  float ClampedTarget(std::size_t world, const ConstraintPlan& c, float position) {
    if (!c.has_limits()) return position;
    float result = position;
    if (c.type == ConstraintType::kHinge) {
      const auto& limit = In<AngularLimitLanes>(world, c.limit_offset);
      result = std::clamp(position, limit.min[Lane(world)], limit.max[Lane(world)]);
    } else {
      const auto& limit = In<LinearLimitLanes>(world, c.limit_offset);
      result = std::clamp(position, limit.min[Lane(world)], limit.max[Lane(world)]);
    }
    return result;
  }

  Scene scene_;
  StepPlan plan_;
  std::size_t world_count_;
  std::size_t block_count_;
  std::size_t arrays_per_block_;
  std::vector<LaneArray> initial_;  // one block with the scene in every lane
  std::vector<LaneArray> storage_;  // block_count_ blocks
  const StepKernels* kernels_;
  int threads_;
  tbb::task_arena arena_;
  std::size_t blocks_per_task_;
  float previous_substep_dt_ = 0.0f;  // Jolt's mPreviousStepDeltaTime (0: cold start)
  std::vector<std::uint8_t> health_ = std::vector<std::uint8_t>(world_count_, 0);
  std::vector<std::uint8_t> pending_input_ = std::vector<std::uint8_t>(world_count_, 0);
  StepSettings last_settings_{};
};

Batch::Batch(const Scene& scene, std::size_t world_count, BatchOptions options)
    : impl_(std::make_unique<Impl>(scene, world_count, options)) {}
Batch::~Batch() = default;
Batch::Batch(Batch&&) noexcept = default;
Batch& Batch::operator=(Batch&&) noexcept = default;

std::size_t Batch::world_count() const { return impl_->world_count_; }
std::size_t Batch::body_count() const { return impl_->plan_.bodies.size(); }
std::size_t Batch::constraint_count() const { return impl_->plan_.constraints.size(); }
const Scene& Batch::scene() const { return impl_->scene_; }
int Batch::threads() const { return impl_->threads_; }

void Batch::Step(const StepSettings& settings) {
  impl_->Step(settings);
  impl_->last_settings_ = settings;
}

std::span<const std::uint8_t> Batch::WorldHealth() const { return impl_->health_; }
std::size_t Batch::UnhealthyWorldCount() const {
  return static_cast<std::size_t>(std::count_if(impl_->health_.begin(), impl_->health_.end(),
                                                [](std::uint8_t bits) { return bits != 0; }));
}

void Batch::GetState(std::span<float> out) const {
  const std::size_t bodies = body_count();
  impl_->CheckSize(out.size(), world_count() * bodies * kStateFloatsPerBody, "GetState");
  for (std::size_t w = 0; w < world_count(); ++w) {
    for (std::size_t b = 0; b < bodies; ++b) {
      impl_->ReadState(w, b, out.data() + (w * bodies + b) * kStateFloatsPerBody);
    }
  }
}

void Batch::SetState(std::span<const float> in, std::span<const std::uint8_t> world_mask) {
  const std::size_t bodies = body_count();
  impl_->CheckSize(in.size(), world_count() * bodies * kStateFloatsPerBody, "SetState");
  if (!world_mask.empty()) impl_->CheckSize(world_mask.size(), world_count(), "SetState mask");
  impl_->CheckStates(in, world_mask);
  for (std::size_t w = 0; w < world_count(); ++w) {
    if (!impl_->Selected(world_mask, w)) continue;
    for (std::size_t b = 0; b < bodies; ++b) {
      impl_->WriteState(w, b, in.data() + (w * bodies + b) * kStateFloatsPerBody);
    }
  }
}

void Batch::GetField(StateField field, std::span<float> out) const {
  const std::size_t bodies = body_count(), size = StateFieldSize(field);
  impl_->CheckSize(out.size(), world_count() * bodies * size, "GetField");
  float state[kStateFloatsPerBody];
  for (std::size_t w = 0; w < world_count(); ++w) {
    for (std::size_t b = 0; b < bodies; ++b) {
      impl_->ReadState(w, b, state);
      std::copy_n(state + StateFieldOffset(field), size, out.data() + (w * bodies + b) * size);
    }
  }
}

void Batch::SetField(StateField field, std::span<const float> in) {
  const std::size_t bodies = body_count(), size = StateFieldSize(field);
  impl_->CheckSize(in.size(), world_count() * bodies * size, "SetField");
  if (field == StateField::kRotation) {
    for (std::size_t i = 0; i < world_count() * bodies; ++i) {
      const float* q = in.data() + i * size;
      if (q[0] == 0.0f && q[1] == 0.0f && q[2] == 0.0f && q[3] == 0.0f) {
        throw SceneError(impl_->plan_.bodies[i % bodies].label + " in world " +
                         std::to_string(i / bodies) + ": rotation is zero (nothing was written)");
      }
    }
  }
  float state[kStateFloatsPerBody];
  for (std::size_t w = 0; w < world_count(); ++w) {
    for (std::size_t b = 0; b < bodies; ++b) {
      impl_->ReadState(w, b, state);
      std::copy_n(in.data() + (w * bodies + b) * size, size, state + StateFieldOffset(field));
      impl_->WriteState(w, b, state);
    }
  }
}

void Batch::Reset(std::span<const std::uint8_t> world_mask) {
  impl_->CheckSize(world_mask.size(), world_count(), "Reset mask");
  for (std::size_t w = 0; w < world_count(); ++w) {
    if (world_mask[w] == 0) continue;
    impl_->ResetWorld(w);
    impl_->health_[w] = 0;
    impl_->pending_input_[w] = 0;
  }
}

void Batch::ResetTo(std::span<const std::uint8_t> world_mask, std::span<const float> state) {
  // Every check before the reset, so that a refused call changes nothing.
  impl_->CheckSize(world_mask.size(), world_count(), "ResetTo mask");
  impl_->CheckSize(state.size(), world_count() * body_count() * kStateFloatsPerBody, "ResetTo");
  impl_->CheckStates(state, world_mask);
  Reset(world_mask);
  SetState(state, world_mask);
}

void Batch::SetForce(std::size_t world, std::size_t body, Float3 force) {
  BodyMotionLanes& m = impl_->Motion(world, body, "a force");
  const std::size_t l = Impl::Lane(world);
  m.force.x[l] = force[0];
  m.force.y[l] = force[1];
  m.force.z[l] = force[2];
  impl_->NoteInput(world, force[0], force[1], force[2]);
}

void Batch::SetTorque(std::size_t world, std::size_t body, Float3 torque) {
  BodyMotionLanes& m = impl_->Motion(world, body, "a torque");
  const std::size_t l = Impl::Lane(world);
  m.torque.x[l] = torque[0];
  m.torque.y[l] = torque[1];
  m.torque.z[l] = torque[2];
  impl_->NoteInput(world, torque[0], torque[1], torque[2]);
}

void Batch::SetForces(std::span<const float> forces) {
  const std::size_t bodies = body_count();
  impl_->CheckSize(forces.size(), world_count() * bodies * 3, "SetForces");
  for (std::size_t w = 0; w < world_count(); ++w) {
    for (std::size_t b = 0; b < bodies; ++b) {
      if (impl_->plan_.bodies[b].motion_offset == kAbsent) continue;
      const float* f = forces.data() + (w * bodies + b) * 3;
      SetForce(w, b, {f[0], f[1], f[2]});
    }
  }
}

void Batch::SetTorques(std::span<const float> torques) {
  const std::size_t bodies = body_count();
  impl_->CheckSize(torques.size(), world_count() * bodies * 3, "SetTorques");
  for (std::size_t w = 0; w < world_count(); ++w) {
    for (std::size_t b = 0; b < bodies; ++b) {
      if (impl_->plan_.bodies[b].motion_offset == kAbsent) continue;
      const float* t = torques.data() + (w * bodies + b) * 3;
      SetTorque(w, b, {t[0], t[1], t[2]});
    }
  }
}

void Batch::SetForces(std::size_t body, std::span<const float> per_world) {
  impl_->Motion(0, body, "a force");
  impl_->CheckSize(per_world.size(), world_count() * 3, "SetForces(body)");
  impl_->WriteLanes(impl_->plan_.bodies[body].motion_offset + offsetof(BodyMotionLanes, force),
                    per_world);
}

void Batch::SetTorques(std::size_t body, std::span<const float> per_world) {
  impl_->Motion(0, body, "a torque");
  impl_->CheckSize(per_world.size(), world_count() * 3, "SetTorques(body)");
  impl_->WriteLanes(impl_->plan_.bodies[body].motion_offset + offsetof(BodyMotionLanes, torque),
                    per_world);
}

void Batch::SetTargetVelocity(std::size_t world, std::size_t constraint, float velocity) {
  impl_->WithMotor(world, constraint, "a target velocity",
                         [&](auto& motor, const ConstraintPlan&) {
                           motor.target_velocity[Impl::Lane(world)] = velocity;
                         });
  impl_->NoteInput(world, velocity);
}

void Batch::SetTargetPosition(std::size_t world, std::size_t constraint, float position) {
  impl_->WithMotor(world, constraint, "a target position",
                         [&](auto& motor, const ConstraintPlan& c) {
                           motor.target_position[Impl::Lane(world)] =
                               impl_->ClampedTarget(world, c, position);
                         });
  impl_->NoteInput(world, position);
}

void Batch::SetTargetOrientation(std::size_t world, std::size_t constraint,
                                 Quaternion orientation) {
  RotationDriveLanes& drive = impl_->RotationDrive(world, constraint, "a target orientation");
  const double length = std::sqrt(double(orientation[0]) * orientation[0] +
                                  double(orientation[1]) * orientation[1] +
                                  double(orientation[2]) * orientation[2] +
                                  double(orientation[3]) * orientation[3]);
  if (length == 0.0) {
    throw SceneError(impl_->Constraint(constraint).label +
                     ": target orientation is a zero quaternion");
  }
  const std::size_t l = Impl::Lane(world);
  drive.target_orientation.x[l] = float(orientation[0] / length);
  drive.target_orientation.y[l] = float(orientation[1] / length);
  drive.target_orientation.z[l] = float(orientation[2] / length);
  drive.target_orientation.w[l] = float(orientation[3] / length);
  impl_->NoteInput(world, orientation[0], orientation[1], orientation[2], orientation[3]);
}

void Batch::SetTargetAngularVelocity(std::size_t world, std::size_t constraint,
                                     Float3 angular_velocity) {
  RotationDriveLanes& drive =
      impl_->RotationDrive(world, constraint, "a target angular velocity");
  for (int i = 0; i < 3; ++i) {
    drive.rows[i].target_velocity[Impl::Lane(world)] = angular_velocity[i];
  }
  impl_->NoteInput(world, angular_velocity[0], angular_velocity[1], angular_velocity[2]);
}

void Batch::SetTargetTranslation(std::size_t world, std::size_t constraint,
                                 Float3 translation) {
  LinearMotorLanes* drives = impl_->TranslationDrives(world, constraint, "a target translation");
  for (int i = 0; i < 3; ++i) drives[i].target_position[Impl::Lane(world)] = translation[i];
  impl_->NoteInput(world, translation[0], translation[1], translation[2]);
}

void Batch::SetTargetLinearVelocity(std::size_t world, std::size_t constraint, Float3 velocity) {
  LinearMotorLanes* drives =
      impl_->TranslationDrives(world, constraint, "a target linear velocity");
  for (int i = 0; i < 3; ++i) drives[i].target_velocity[Impl::Lane(world)] = velocity[i];
  impl_->NoteInput(world, velocity[0], velocity[1], velocity[2]);
}

void Batch::SetTargetVelocities(std::size_t constraint, std::span<const float> per_world) {
  impl_->CheckSize(per_world.size(), world_count(), "SetTargetVelocities");
  for (std::size_t w = 0; w < world_count(); ++w) SetTargetVelocity(w, constraint, per_world[w]);
}

void Batch::SetTargetPositions(std::size_t constraint, std::span<const float> per_world) {
  impl_->CheckSize(per_world.size(), world_count(), "SetTargetPositions");
  for (std::size_t w = 0; w < world_count(); ++w) SetTargetPosition(w, constraint, per_world[w]);
}

void Batch::SetMassProperties(std::size_t world, std::size_t body, float mass,
                              Float3 inertia_diagonal) {
  impl_->Motion(world, body, "mass properties");
  const std::string& label = impl_->plan_.bodies[body].label;
  if (!std::isfinite(mass) || mass <= 0.0f) {
    throw SceneError(label + " in world " + std::to_string(world) +
                     ": mass must be finite and positive");
  }
  for (int i = 0; i < 3; ++i) {
    if (!std::isfinite(inertia_diagonal[i]) || inertia_diagonal[i] <= 0.0f) {
      throw SceneError(label + " in world " + std::to_string(world) + ": inertia_diagonal[" +
                       std::to_string(i) + "] must be finite and positive");
    }
  }
  BodyLanes& b = impl_->Body(world, body);
  const std::size_t l = Impl::Lane(world);
  b.inv_mass[l] = 1.0f / mass;
  b.inv_inertia_diagonal.x[l] = 1.0f / inertia_diagonal[0];
  b.inv_inertia_diagonal.y[l] = 1.0f / inertia_diagonal[1];
  b.inv_inertia_diagonal.z[l] = 1.0f / inertia_diagonal[2];
}

void Batch::SetDamping(std::size_t world, std::size_t body, float linear, float angular) {
  BodyMotionLanes& m = impl_->Motion(world, body, "damping");
  if (!(linear >= 0.0f) || !(angular >= 0.0f) || !std::isfinite(linear) ||
      !std::isfinite(angular)) {
    throw SceneError(impl_->plan_.bodies[body].label + ": damping must be finite and >= 0");
  }
  m.linear_damping[Impl::Lane(world)] = linear;
  m.angular_damping[Impl::Lane(world)] = angular;
}

void Batch::SetGravityFactor(std::size_t world, std::size_t body, float factor) {
  BodyMotionLanes& m = impl_->Motion(world, body, "a gravity factor");
  if (!std::isfinite(factor)) {
    throw SceneError(impl_->plan_.bodies[body].label + ": gravity_factor must be finite");
  }
  m.gravity_factor[Impl::Lane(world)] = factor;
}

void Batch::SetLimits(std::size_t world, std::size_t constraint, float min, float max) {
  impl_->WithLimits(world, constraint, "limits", [&](auto& limit, const ConstraintPlan& c) {
    const bool hinge = c.type == ConstraintType::kHinge;
    const bool distance = c.type == ConstraintType::kDistance;
    const bool ok = hinge      ? (min >= -kPi && min <= 0.0f && max >= 0.0f && max <= kPi)
                    : distance ? (min >= 0.0f && min <= max && std::isfinite(max))
                               : (min <= 0.0f && max >= 0.0f);
    if (!ok) {
      throw SceneError(c.label + ": limits_min / limits_max " +
                       (hinge      ? "must lie in [-pi, 0] and [0, pi]"
                        : distance ? "must be finite with 0 <= min <= max"
                                   : "must be <= 0 and >= 0"));
    }
    limit.min[Impl::Lane(world)] = min;
    limit.max[Impl::Lane(world)] = max;
  });
}

void Batch::SetLimitsSpring(std::size_t world, std::size_t constraint,
                            float frequency_or_stiffness, float damping) {
  impl_->WithLimits(world, constraint, "a limits spring",
                    [&](auto& limit, const ConstraintPlan& c) {
                      // The plan skips position-phase limit steps for soft limits, so
                      // a world may tune its spring but not switch hard <-> soft.
                      if ((frequency_or_stiffness > 0.0f) != c.soft_limits) {
                        throw SceneError(c.label + ": limits_spring " +
                                         (c.soft_limits
                                              ? "must keep a positive frequency (soft in the scene)"
                                              : "must stay <= 0 (hard limits in the scene)"));
                      }
                      limit.geometry.spring.frequency_or_stiffness[Impl::Lane(world)] =
                          frequency_or_stiffness;
                      limit.geometry.spring.damping[Impl::Lane(world)] = damping;
                    });
}

void Batch::SetMotorSpring(std::size_t world, std::size_t constraint,
                           float frequency_or_stiffness, float damping) {
  impl_->WithMotor(world, constraint, "a motor spring",
                         [&](auto& motor, const ConstraintPlan&) {
                           motor.geometry.spring.frequency_or_stiffness[Impl::Lane(world)] =
                               frequency_or_stiffness;
                           motor.geometry.spring.damping[Impl::Lane(world)] = damping;
                         });
}

void Batch::SetMotorLimits(std::size_t world, std::size_t constraint, float min, float max) {
  impl_->WithMotor(world, constraint, "motor limits",
                         [&](auto& motor, const ConstraintPlan& c) {
                           if (!(min <= max)) {
                             throw SceneError(c.label + ": motor min_force_limit must be <= max");
                           }
                           motor.min_force_limit[Impl::Lane(world)] = min;
                           motor.max_force_limit[Impl::Lane(world)] = max;
                         });
}

void Batch::SetMaxFriction(std::size_t world, std::size_t constraint, float max_friction) {
  impl_->WithMotor(world, constraint, "a max friction",
                         [&](auto& motor, const ConstraintPlan& c) {
                           if (!(max_friction >= 0.0f) || !std::isfinite(max_friction)) {
                             throw SceneError(c.label + ": max friction must be finite and >= 0");
                           }
                           motor.max_friction[Impl::Lane(world)] = max_friction;
                         });
}

void Batch::SetRatio(std::size_t world, std::size_t constraint, float ratio) {
  impl_->CheckWorld(world);
  const ConstraintPlan& c = impl_->Constraint(constraint);
  if (!std::isfinite(ratio)) throw SceneError(c.label + ": ratio must be finite");
  const std::size_t l = Impl::Lane(world);
  if (c.type == ConstraintType::kGear) {
    impl_->In<GearConstraintLanes>(world, c.offset).geometry.ratio[l] = ratio;
  } else if (c.type == ConstraintType::kRackAndPinion) {
    impl_->In<RackAndPinionConstraintLanes>(world, c.offset).geometry.ratio[l] = ratio;
  } else if (c.type == ConstraintType::kPulley) {
    if (!(ratio > 0.0f)) throw SceneError(c.label + ": ratio must be positive for a pulley");
    impl_->In<PulleyConstraintLanes>(world, c.offset).geometry.ratio[l] = ratio;
  } else {
    throw SceneError(c.label +
                     ": ratio applies to gear, rack-and-pinion and pulley constraints only");
  }
}

std::string Batch::Plan() const { return Plan(impl_->last_settings_); }

std::string Batch::Plan(const StepSettings& settings) const {
  return DescribePlan(impl_->plan_, settings) + "kernels: " +
         impl_->kernels_->target.name + ", " +
         std::to_string(impl_->kernels_->target.vector_lanes) + " float lanes per vector\n";
}

std::size_t Batch::BytesPerWorld() const { return impl_->plan_.block_bytes / kLaneWidth; }
const char* Batch::SimdTarget() const { return impl_->kernels_->target.name; }
std::size_t Batch::SimdLanes() const { return impl_->kernels_->target.vector_lanes; }

float Batch::MaxConstraintError(std::size_t world) const {
  impl_->CheckWorld(world);
  return MaxConstraintErrorOfLane(impl_->plan_, impl_->Block(world / kLaneWidth),
                                  Impl::Lane(world));
}

double Batch::ConstraintError(std::size_t world, std::size_t constraint) const {
  impl_->CheckWorld(world);
  impl_->Constraint(constraint);  // throws for an index out of range
  return ConstraintErrorOfLane(impl_->plan_, impl_->Block(world / kLaneWidth), Impl::Lane(world),
                               constraint);
}

double Batch::ConstraintVelocityError(std::size_t world, std::size_t constraint) const {
  impl_->CheckWorld(world);
  impl_->Constraint(constraint);  // throws for an index out of range
  return ConstraintVelocityErrorOfLane(impl_->plan_, impl_->Block(world / kLaneWidth),
                                       Impl::Lane(world), constraint);
}

}  // namespace manyworlds
