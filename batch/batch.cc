// Batch: the blocks of worlds, the TBB loop over them, state and resets
// (actions: batch_actions.cc; per-world parameters: batch_parameters.cc;
// snapshots: batch_snapshot.cc;
// state read-outs: batch_state_read.cc; the fused step's resets and
// outputs: batch_fused_io.cc).

#include "manyworlds/batch.h"

#include <tbb/blocked_range.h>
#include <tbb/info.h>
#include <tbb/parallel_for.h>
#include <tbb/partitioner.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include "batch/batch_impl.h"
#include "batch/constraint_block.h"
#include "batch/constraint_error.h"
#include "batch/scene_setup.h"
#include "batch/working_block.h"
#include "hwy/targets.h"
#include "manyworlds/error.h"

namespace manyworlds {

std::size_t StateFieldOffset(StateField field) {
  switch (field) {
    case StateField::kPosition: return 0;
    case StateField::kRotation: return 3;
    case StateField::kLinearVelocity: return 7;
    case StateField::kAngularVelocity: return 10;
  }
  throw std::invalid_argument("StateField " + std::to_string(unsigned(field)) +
                              " is not a StateField (accepted 0 to 3)");
}

std::size_t StateFieldSize(StateField field) {
  StateFieldOffset(field);  // refuses a value outside the enum
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

// Checked before the arena is made: TBB crashes on absurd thread counts.
int ThreadsOf(const BatchOptions& options) {
  if (options.threads < 0 || options.threads > kMaxThreads) {
    throw SceneError("batch options: threads must lie in [0, " + std::to_string(kMaxThreads) +
                     "] (0: every core; got " + std::to_string(options.threads) + ")");
  }
  return options.threads > 0 ? options.threads : tbb::info::default_concurrency();
}

std::size_t CheckedWorldCount(std::size_t world_count) {
  if (world_count == 0) throw SceneError("batch: world_count must be at least 1");
  return world_count;
}

// The LaneArrays of a block that hold actions: forces and torques of
// dynamic bodies, motor targets, drive orientations and velocities.
std::vector<std::size_t> InputArrays(const StepPlan& plan) {
  std::vector<std::size_t> arrays;
  const auto add = [&](std::size_t offset, std::size_t count) {
    for (std::size_t i = 0; i < count; ++i) arrays.push_back(offset + i * sizeof(LaneArray));
  };
  for (const BodyPlan& body : plan.bodies) {
    if (body.motion_offset == kAbsent) continue;
    add(body.motion_offset + offsetof(BodyMotionLanes, force), 3);
    add(body.motion_offset + offsetof(BodyMotionLanes, torque), 3);
  }
  static_assert(offsetof(AngularMotorLanes, target_velocity) ==
                offsetof(LinearMotorLanes, target_velocity));
  static_assert(offsetof(AngularMotorLanes, target_position) ==
                offsetof(LinearMotorLanes, target_position));
  for (const ConstraintPlan& c : plan.constraints) {
    if (c.motor_offset != kAbsent) {
      const std::size_t motors = c.type == ConstraintType::kSixDof ? 3 : 1;
      for (std::size_t m = 0; m < motors; ++m) {
        const std::size_t motor = c.motor_offset + m * sizeof(LinearMotorLanes);
        add(motor + offsetof(LinearMotorLanes, target_velocity), 1);
        add(motor + offsetof(LinearMotorLanes, target_position), 1);
      }
    }
    if (c.rotation_drive_offset != kAbsent) {
      add(c.rotation_drive_offset + offsetof(RotationDriveLanes, target_orientation), 4);
      for (std::size_t row = 0; row < 3; ++row) {
        add(c.rotation_drive_offset + offsetof(RotationDriveLanes, rows) +
                row * sizeof(AngularDriveRowLanes) +
                offsetof(AngularDriveRowLanes, target_velocity),
            1);
      }
    }
  }
  return arrays;
}

}  // namespace

Batch::Impl::Impl(const Scene& scene, std::size_t world_count, BatchOptions options)
    : scene_(scene),
      plan_(CompilePlan(scene)),
      world_count_(CheckedWorldCount(world_count)),
      block_count_(BlockCount(world_count)),
      arrays_per_block_(plan_.block_bytes / sizeof(LaneArray)),
      initial_(arrays_per_block_),
      storage_(arrays_per_block_ * block_count_),
      input_arrays_(InputArrays(plan_)),
      kernels_(StepKernelsFor(options.target)),
      joint_kernels_(KernelsForTarget<JointCoordinateKernels>(kernels_->target.bits)),
      threads_(ThreadsOf(options)),
      arena_(threads_),
      blocks_per_task_(options.blocks_per_task),
      profile_phases_(options.profile_phases),
      prefetch_next_block_(storage_.size() * sizeof(LaneArray) /
                               static_cast<std::size_t>(threads_) >
                           kPrefetchAboveBytesPerThread) {
  // Both tables are built for the same Highway targets; a missing one would
  // be a build error, not a user's.
  if (joint_kernels_ == nullptr) {
    throw std::logic_error(std::string("manyworlds: no joint-coordinate kernels for target ") +
                           kernels_->target.name);
  }
  WriteInitialBlock(scene_, plan_, Bytes(initial_.data()));
  for (std::size_t block = 0; block < block_count_; ++block) {
    std::copy(initial_.begin(), initial_.end(), storage_.begin() + block * arrays_per_block_);
  }
}

void Batch::Impl::Step(const StepSettings& settings, std::stop_token stop, const BlockIo* io) {
  CheckStepSettings(settings, plan_);
  const float substep_dt = settings.delta_time / static_cast<float>(settings.substeps);
  StepParams params{};
  params.substep_delta_time = substep_dt;
  params.substeps = settings.substeps;
  params.first_warm_start_ratio =
      settings.warm_start && previous_substep_dt_ > 0.0f ? substep_dt / previous_substep_dt_
                                                         : 0.0f;
  params.velocity_iterations = settings.velocity_iterations;
  params.velocity_tolerance = settings.velocity_tolerance;
  params.position_iterations = settings.position_iterations;
  params.baumgarte = settings.baumgarte;
  params.gravity = settings.gravity;
  params.gyroscopic = settings.gyroscopic;
  params.solver = settings.solver;
  params.exact_tolerance = settings.exact_tolerance;
  params.exact_curvature_velocity = settings.exact_curvature_velocity;
  params.exact_stiffness = settings.exact_geometric_stiffness * substep_dt;
  params.exact_first_stiffness =
      previous_substep_dt_ > 0.0f ? params.exact_stiffness * (substep_dt / previous_substep_dt_)
                                  : params.exact_stiffness;
  params.speculative_contact_distance = settings.speculative_contact_distance;
  params.penetration_slop = settings.penetration_slop;
  params.max_penetration_distance = settings.max_penetration_distance;
  params.min_velocity_for_restitution = settings.min_velocity_for_restitution;
  params.speculative_contacts_from_velocity = settings.speculative_contacts_from_velocity;
  previous_substep_dt_ = substep_dt;

  const std::size_t grain =
      blocks_per_task_ > 0
          ? blocks_per_task_
          : std::max<std::size_t>(1, block_count_ / (static_cast<std::size_t>(threads_) * 4));
  const bool reset_unhealthy = settings.unhealthy_worlds == UnhealthyWorlds::kReset;
  const bool stoppable = stop.stop_possible();
  auto step_blocks = [&](const tbb::blocked_range<std::size_t>& range) {
    for (std::size_t block = range.begin(); block != range.end(); ++block) {
      if (io != nullptr) StartBlock(block, *io);
      if (stoppable && stop.stop_requested()) {
        for (auto [world, end] = WorldsOf(block); world < end; ++world) {
          health_[world] = kNotStepped;
        }
        if (io != nullptr) FinishBlock(block, *io, false);
        continue;
      }
      const bool prefetch = prefetch_next_block_ && block + 1 != range.end();
      const bool unhealthy = StepBlock(block, prefetch ? Block(block + 1) : nullptr, params);
      RecordHealth(block, unhealthy, reset_unhealthy);
      if (io != nullptr) FinishBlock(block, *io, true);
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

bool Batch::Impl::StepBlock(std::size_t block, const std::byte* next_block,
                            const StepParams& params) {
  const WorkingBlock working(plan_, Block(block));
  if (!profile_phases_) return kernels_->step_block(plan_, working.bytes(), next_block, params);
  std::uint64_t phase_ns[kStepPhaseCount] = {};
  const bool unhealthy =
      kernels_->step_block_profiled(plan_, working.bytes(), next_block, params, phase_ns);
  for (std::size_t p = 0; p < kStepPhaseCount; ++p) {
    phase_ns_[p].fetch_add(phase_ns[p], std::memory_order_relaxed);
  }
  const auto [first, end] = WorldsOf(block);
  profiled_blocks_.fetch_add(1, std::memory_order_relaxed);
  profiled_worlds_.fetch_add(end - first, std::memory_order_relaxed);
  return unhealthy;
}

// Copies the block's health lanes of its real worlds, with the non-finite
// inputs noted since the last Step, into health_ and, if asked, resets the
// unhealthy worlds; runs in the block's task, while the block is in cache,
// and touches only this block's worlds.
void Batch::Impl::RecordHealth(std::size_t block, bool unhealthy, bool reset_unhealthy) {
  const auto& lanes = At<WorldHealthLanes>(Block(block), plan_.health_offset);
  for (auto [world, end] = WorldsOf(block); world < end; ++world) {
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

Batch::Impl::Exclusive::Exclusive(const Impl& impl, const char* call) : impl_(impl) {
  const std::thread::id me = std::this_thread::get_id();
  owns_ = !(impl.busy_.load(std::memory_order_acquire) &&
            impl.busy_thread_.load(std::memory_order_relaxed) == me);
  if (!owns_) return;
  if (impl.busy_.exchange(true, std::memory_order_acquire)) {
    throw std::logic_error(std::string("manyworlds::Batch::") + call +
                           " called while another thread is inside a call on the same "
                           "Batch (a Batch is not thread-safe: one thread at a time)");
  }
  impl.busy_thread_.store(me, std::memory_order_relaxed);
}

Batch::Impl::Exclusive::~Exclusive() {
  if (!owns_) return;
  impl_.busy_thread_.store(std::thread::id(), std::memory_order_relaxed);
  impl_.busy_.store(false, std::memory_order_release);
}

void Batch::Impl::CheckNotBusy(const char* call) const {
  if (busy_.load(std::memory_order_relaxed) &&
      busy_thread_.load(std::memory_order_relaxed) != std::this_thread::get_id()) {
    throw std::logic_error(std::string("manyworlds::Batch: ") + call +
                           " while another thread is inside Step or another call that "
                           "writes many worlds of the same Batch (one thread at a time)");
  }
}

bool Batch::Impl::InputsFinite(std::size_t world) const {
  const std::byte* block = Block(world / kLaneWidth);
  const std::size_t l = Lane(world);
  return std::all_of(input_arrays_.begin(), input_arrays_.end(), [&](std::size_t offset) {
    return std::isfinite(reinterpret_cast<const LaneArray*>(block + offset)->lanes[l]);
  });
}

void Batch::Impl::CheckWorld(std::size_t world) const {
  if (world >= world_count_) {
    throw std::out_of_range("world " + std::to_string(world) + " out of range (batch has " +
                            std::to_string(world_count_) + " worlds)");
  }
}

void Batch::Impl::CheckBody(std::size_t body) const {
  if (body >= plan_.bodies.size()) {
    throw std::out_of_range("body " + std::to_string(body) + " out of range (scene has " +
                            std::to_string(plan_.bodies.size()) + " bodies)");
  }
}

const ConstraintPlan& Batch::Impl::Constraint(std::size_t index) const {
  if (index >= plan_.constraints.size()) {
    throw std::out_of_range("constraint " + std::to_string(index) + " out of range (scene has " +
                            std::to_string(plan_.constraints.size()) + " constraints)");
  }
  return plan_.constraints[index];
}

BodyMotionLanes& Batch::Impl::Motion(std::size_t world, std::size_t body, const char* setting) {
  Body(world, body);  // range checks
  if (plan_.bodies[body].motion_offset == kAbsent) {
    throw SceneError(plan_.bodies[body].label + ": " + setting +
                     " applies to dynamic bodies only");
  }
  return In<BodyMotionLanes>(world, plan_.bodies[body].motion_offset);
}

void Batch::Impl::ReadState(std::size_t world, std::size_t body, float* out) const {
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

namespace {

double RotationNorm(const float* state) {
  double norm = 0.0;
  for (int i = 3; i < 7; ++i) norm += double(state[i]) * state[i];
  return std::sqrt(norm);
}

}  // namespace

void Batch::Impl::CheckStates(std::span<const float> in,
                              std::span<const std::uint8_t> mask) const {
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

void Batch::Impl::WriteState(std::size_t world, std::size_t body, const float* in) {
  BodyLanes& b = In<BodyLanes>(world, plan_.bodies[body].offset);
  const std::size_t l = Lane(world);
  b.position.x[l] = in[0];
  b.position.y[l] = in[1];
  b.position.z[l] = in[2];
  // A rotation the step itself left (unit to a few float roundings) is kept
  // bit for bit, so that a state read and written back changes nothing;
  // others are normalised. Non-finite ones are written as given: the next
  // Step flags the world.
  const double norm = RotationNorm(in);
  const bool unit = std::abs(norm - 1.0) <= 8.0 * FLT_EPSILON;
  const double scale = std::isfinite(norm) && !unit ? 1.0 / norm : 1.0;
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

void Batch::Impl::WriteStates(std::span<const float> in, std::span<const std::uint8_t> mask) {
  const std::size_t bodies = plan_.bodies.size();
  CheckSize(in.size(), world_count_ * bodies * kStateFloatsPerBody, "SetState");
  if (!mask.empty()) CheckSize(mask.size(), world_count_, "SetState mask");
  CheckStates(in, mask);
  for (std::size_t w = 0; w < world_count_; ++w) {
    if (!Selected(mask, w)) continue;
    for (std::size_t b = 0; b < bodies; ++b) {
      WriteState(w, b, in.data() + (w * bodies + b) * kStateFloatsPerBody);
    }
  }
}

void Batch::Impl::CheckSize(std::size_t got, std::size_t want, const char* what) const {
  if (got != want) {
    throw std::invalid_argument(std::string(what) + ": expected " + std::to_string(want) +
                                " floats, got " + std::to_string(got));
  }
}

// Every LaneArray of the world's block, lane `world % 16`, from the initial block.
void Batch::Impl::ResetWorld(std::size_t world) {
  const std::size_t lane = Lane(world);
  ResetLanes(world / kLaneWidth, &lane, 1);
}

// Every array of the block takes the initial block's lanes of the resetting
// worlds, a vector select per array on the step's target (a float at a time
// before: the same time for one reset world per block, more for several).
void Batch::Impl::ResetLanes(std::size_t block, const std::size_t* lanes, std::size_t count) {
  LaneArray take{};
  for (std::size_t k = 0; k < count; ++k) take[lanes[k]] = 1.0f;
  kernels_->reset_lanes(Block(block), Bytes(initial_.data()), arrays_per_block_, take);
}

// Over the batch's threads, block by block (a world's lanes, health and
// pending input are its block's alone): an RL loop resets done worlds every
// step, each rewriting its lane of every array of its block, and with two
// threads half of those blocks sit in the other core's cache after Step.
void Batch::Impl::ResetWorlds(std::span<const std::uint8_t> mask,
                              std::span<const float> states) {
  ForEachBlock([&](std::size_t block) { ResetWorldsOfBlock(block, mask, states); });
}

void Batch::Impl::ResetWorldsOfBlock(std::size_t block, std::span<const std::uint8_t> mask,
                                     std::span<const float> states) {
  const auto [first, end] = WorldsOf(block);
  std::size_t lanes[kLaneWidth], count = 0;
  for (std::size_t w = first; w < end; ++w) {
    if (mask[w] != 0) lanes[count++] = Lane(w);
  }
  if (count == 0) return;
  ResetLanes(block, lanes, count);
  const std::size_t bodies = plan_.bodies.size();
  for (std::size_t k = 0; k < count; ++k) {
    const std::size_t w = first + lanes[k];
    for (std::size_t b = 0; b < bodies && !states.empty(); ++b) {
      WriteState(w, b, states.data() + (w * bodies + b) * kStateFloatsPerBody);
    }
    health_[w] = 0;
    pending_input_[w] = 0;
  }
}

// ---- the public API

Batch::Batch(const Scene& scene, std::size_t world_count, BatchOptions options)
    : impl_(std::make_unique<Impl>(scene, world_count, options)) {}
Batch::~Batch() = default;
Batch::Batch(Batch&&) noexcept = default;
Batch& Batch::operator=(Batch&&) noexcept = default;

Batch::Impl& Batch::impl() {
  return const_cast<Impl&>(static_cast<const Batch*>(this)->impl());
}
const Batch::Impl& Batch::impl() const {
  if (!impl_) throw std::logic_error("manyworlds::Batch used after it was moved from");
  impl_->CheckNotBusy("a Batch call");
  return *impl_;
}

std::size_t Batch::world_count() const { return impl().world_count_; }
std::size_t Batch::body_count() const { return impl().plan_.bodies.size(); }
std::size_t Batch::constraint_count() const { return impl().plan_.constraints.size(); }
const Scene& Batch::scene() const { return impl().scene_; }
int Batch::threads() const { return impl().threads_; }

void Batch::Step(const StepSettings& settings) { Step(settings, std::stop_token()); }

bool Batch::Step(const StepSettings& settings, std::stop_token stop) {
  Impl& batch = impl();
  const Impl::Exclusive exclusive(batch, "Step");
  batch.Step(settings, stop);
  batch.last_settings_ = settings;
  return batch.EveryWorldStepped(stop);
}

bool Batch::Impl::EveryWorldStepped(std::stop_token stop) const {
  return !stop.stop_requested() ||
         std::none_of(health_.begin(), health_.end(),
                      [](std::uint8_t bits) { return (bits & kNotStepped) != 0; });
}

std::span<const std::uint8_t> Batch::WorldHealth() const { return impl().health_; }
std::size_t Batch::UnhealthyWorldCount() const {
  return static_cast<std::size_t>(std::count_if(impl().health_.begin(), impl().health_.end(),
                                                [](std::uint8_t bits) { return bits != 0; }));
}

void Batch::SetState(std::span<const float> in, std::span<const std::uint8_t> world_mask) {
  Impl& batch = impl();
  const Impl::Exclusive exclusive(batch, "SetState");
  batch.WriteStates(in, world_mask);
}

void Batch::SetField(StateField field, std::span<const float> in) {
  const Impl::Exclusive exclusive(impl(), "SetField");
  const std::size_t bodies = body_count(), size = StateFieldSize(field);
  impl().CheckSize(in.size(), world_count() * bodies * size, "SetField");
  if (field == StateField::kRotation) {
    for (std::size_t i = 0; i < world_count() * bodies; ++i) {
      const float* q = in.data() + i * size;
      if (q[0] == 0.0f && q[1] == 0.0f && q[2] == 0.0f && q[3] == 0.0f) {
        throw SceneError(impl().plan_.bodies[i % bodies].label + " in world " +
                         std::to_string(i / bodies) + ": rotation is zero (nothing was written)");
      }
    }
  }
  float state[kStateFloatsPerBody];
  for (std::size_t w = 0; w < world_count(); ++w) {
    for (std::size_t b = 0; b < bodies; ++b) {
      impl().ReadState(w, b, state);
      std::copy_n(in.data() + (w * bodies + b) * size, size, state + StateFieldOffset(field));
      impl().WriteState(w, b, state);
    }
  }
}

void Batch::Reset(std::span<const std::uint8_t> world_mask) {
  Impl& batch = impl();
  const Impl::Exclusive exclusive(batch, "Reset");
  batch.CheckSize(world_mask.size(), world_count(), "Reset mask");
  batch.ResetWorlds(world_mask);
}

void Batch::ResetTo(std::span<const std::uint8_t> world_mask, std::span<const float> state) {
  Impl& batch = impl();
  const Impl::Exclusive exclusive(batch, "ResetTo");
  // Every check before the reset, so that a refused call changes nothing.
  batch.CheckSize(world_mask.size(), world_count(), "ResetTo mask");
  batch.CheckSize(state.size(), world_count() * body_count() * kStateFloatsPerBody, "ResetTo");
  batch.CheckStates(state, world_mask);
  batch.ResetWorlds(world_mask, state);
}

std::string Batch::Plan() const { return Plan(impl().last_settings_); }

std::string Batch::Plan(const StepSettings& settings) const {
  return DescribePlan(impl().plan_, settings) + "kernels: " +
         impl().kernels_->target.name + ", " +
         std::to_string(impl().kernels_->target.vector_lanes) + " float lanes per vector\n";
}

const char* JointSolverName(JointSolver solver) {
  switch (solver) {
    case JointSolver::kGaussSeidel: return "gauss_seidel";
    case JointSolver::kExact: return "exact";
  }
  throw std::invalid_argument("JointSolver " + std::to_string(unsigned(solver)) +
                              " is not a JointSolver (accepted 0 and 1)");
}

const char* StepPhaseName(StepPhase phase) {
  static constexpr const char* kNames[kStepPhaseCount] = {
      "forces", "setup", "warm_start", "velocity", "integration", "position", "finish"};
  const auto index = static_cast<std::size_t>(phase);
  if (index >= kStepPhaseCount) {
    throw std::invalid_argument("StepPhase " + std::to_string(index) +
                                " is not a StepPhase (accepted 0 to 6)");
  }
  return kNames[index];
}

PhaseProfile Batch::GetPhaseProfile() const {
  const Impl& batch = impl();
  PhaseProfile profile;
  for (std::size_t p = 0; p < kStepPhaseCount; ++p) {
    profile.seconds[p] = 1e-9 * double(batch.phase_ns_[p].load(std::memory_order_relaxed));
  }
  profile.block_steps = batch.profiled_blocks_.load(std::memory_order_relaxed);
  profile.world_steps = batch.profiled_worlds_.load(std::memory_order_relaxed);
  return profile;
}

void Batch::ResetPhaseProfile() {
  Impl& batch = impl();
  const Impl::Exclusive exclusive(batch, "ResetPhaseProfile");
  for (auto& ns : batch.phase_ns_) ns.store(0, std::memory_order_relaxed);
  batch.profiled_blocks_.store(0, std::memory_order_relaxed);
  batch.profiled_worlds_.store(0, std::memory_order_relaxed);
}

std::size_t Batch::BytesPerWorld() const { return impl().plan_.block_bytes / kLaneWidth; }
const char* Batch::SimdTarget() const { return impl().kernels_->target.name; }
std::size_t Batch::SimdLanes() const { return impl().kernels_->target.vector_lanes; }

float Batch::MaxConstraintError(std::size_t world) const {
  impl().CheckWorld(world);
  return MaxConstraintErrorOfLane(impl().plan_, impl().Block(world / kLaneWidth),
                                  Impl::Lane(world));
}

ConstraintErrorSplit Batch::MaxConstraintErrorSplit(std::size_t world) const {
  impl().CheckWorld(world);
  return MaxConstraintErrorSplitOfLane(impl().plan_, impl().Block(world / kLaneWidth),
                                       Impl::Lane(world));
}

double Batch::ConstraintError(std::size_t world, std::size_t constraint) const {
  impl().CheckWorld(world);
  impl().Constraint(constraint);  // throws for an index out of range
  return ConstraintErrorOfLane(impl().plan_, impl().Block(world / kLaneWidth), Impl::Lane(world),
                               constraint);
}

double Batch::ConstraintVelocityError(std::size_t world, std::size_t constraint) const {
  impl().CheckWorld(world);
  impl().Constraint(constraint);  // throws for an index out of range
  return ConstraintVelocityErrorOfLane(impl().plan_, impl().Block(world / kLaneWidth),
                                       Impl::Lane(world), constraint);
}

}  // namespace manyworlds
