// Batch::Impl: the blocks of worlds, the TBB loop over them and the lane
// access the per-world API is built on. Private to batch/ (batch.cc: the
// step, state and actions; batch_parameters.cc: per-world parameters;
// batch_snapshot.cc: snapshots).
#pragma once

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <span>
#include <stdexcept>
#include <stop_token>
#include <string>
#include <thread>
#include <vector>

#include "batch/constraint_block.h"  // At
#include "batch/constraint_lanes.h"
#include "batch/joint_coordinates.h"
#include "batch/plan.h"
#include "batch/step_kernels.h"
#include "manyworlds/batch.h"
#include "manyworlds/error.h"
#include "manyworlds/lanes.h"

namespace manyworlds {

class Batch::Impl {
 public:
  Impl(const Scene& scene, std::size_t world_count, BatchOptions options);

  static constexpr std::size_t BlockCount(std::size_t worlds) {
    return (worlds + kLaneWidth - 1) / kLaneWidth;
  }
  static std::byte* Bytes(LaneArray* arrays) { return reinterpret_cast<std::byte*>(arrays); }
  static std::size_t Lane(std::size_t world) { return world % kLaneWidth; }
  // The real worlds of a block, [first, end): the last block may hold
  // padding lanes. (A plain pair: clang 14 cannot use libstdc++ 12's
  // std::views::iota.)
  struct WorldRange {
    std::size_t first, end;
  };
  WorldRange WorldsOf(std::size_t block) const {
    return {block * kLaneWidth, std::min((block + 1) * kLaneWidth, world_count_)};
  }

  std::byte* Block(std::size_t block) {
    return Bytes(storage_.data() + block * arrays_per_block_);
  }
  const std::byte* Block(std::size_t block) const {
    return reinterpret_cast<const std::byte*>(storage_.data() + block * arrays_per_block_);
  }

  // fn(block) for every block, over the batch's threads when there are
  // enough blocks to share (read-outs that write disjoint per-world slices).
  template <class Fn>
  void ForEachBlock(Fn&& fn) const {
    constexpr std::size_t kBlocksPerTask = 16;
    if (threads_ == 1 || block_count_ < 2 * kBlocksPerTask) {
      for (std::size_t block = 0; block < block_count_; ++block) fn(block);
      return;
    }
    arena_.execute([&] {
      tbb::parallel_for(tbb::blocked_range<std::size_t>(0, block_count_, kBlocksPerTask),
                        [&](const tbb::blocked_range<std::size_t>& range) {
                          for (std::size_t b = range.begin(); b != range.end(); ++b) fn(b);
                        });
    });
  }

  // ---- actions written block by block (batch_actions.cc), by the separate
  // calls (SetForces(body), SetTargetVelocities, ...) over every block and
  // by Step(settings, io) in each block's task: one writer, so the two give
  // the same bits. A StepAction checked once per call: where its LaneArray
  // starts in a block, and the constraint whose limits clamp a position.
  struct CheckedAction {
    ActionKind kind;
    // Bytes, in a block: the Vec3Lanes of a force or torque, the LaneArray
    // of a motor target, the RotationDriveLanes or the first of the three
    // LinearMotorLanes of a drive target.
    std::size_t offset;
    const ConstraintPlan* clamp_into_limits = nullptr;
    const float* per_world;
  };
  // Refuses (SceneError, std::out_of_range or std::invalid_argument naming
  // `what`) an action the separate call would refuse; writes nothing.
  // CheckTarget checks the scene side only (body or constraint, kind).
  CheckedAction CheckTarget(ActionKind kind, std::size_t index, const char* what) const;
  CheckedAction CheckAction(const StepAction& action, const char* what) const;
  // One world's values into its lanes: the writer every form shares
  // (batch_actions.cc), one instance per kind.
  template <ActionKind kKind>
  void WriteLane(const CheckedAction& action, std::byte* block, std::size_t world,
                 const float* values);
  void WriteActionOfBlock(std::size_t block, const CheckedAction& action);
  void WriteAction(const CheckedAction& action) {
    for (std::size_t block = 0; block < block_count_; ++block) WriteActionOfBlock(block, action);
  }
  void WriteActionOfWorld(ActionKind kind, std::size_t index, std::size_t world,
                          const float* values);
  void WriteEveryWorld(ActionKind kind, std::size_t index, std::span<const float> per_world,
                       const char* call);
  void WriteEveryBody(ActionKind kind, std::span<const float> values, const char* call);
  // The constraint's plan if it has a single motor (hinge, slider, path),
  // else SceneError naming it and `what`.
  const ConstraintPlan& SingleMotor(std::size_t constraint, const char* what) const;

  // ---- what a Step(settings, io) does per block besides stepping
  // (batch_fused_io.cc): the caller's StepIo, checked, with the joint
  // coordinates' layout worked out once per call.
  // The constraints that have joint coordinates and their offsets in a
  // world's row of per_world floats.
  struct JointLayout {
    std::vector<std::size_t> constraints, offsets;
    std::size_t per_world = 0;
  };
  struct BlockIo {
    std::vector<CheckedAction> actions;
    std::span<const std::uint8_t> reset_mask;
    std::span<const float> reset_states;
    float* state_out = nullptr;
    float* joints_out = nullptr;
    JointLayout joints;
    bool any = false;  // anything to do besides stepping
  };
  // Refuses (std::invalid_argument, by name) what Step(settings, io) must
  // not start with; writes nothing.
  BlockIo CheckedBlockIo(const StepIo& io) const;
  // Before the block's step (or its skipping by a stop request): the actions.
  void StartBlock(std::size_t block, const BlockIo& io);
  // After the block's step (stepped) or its skipping by a stop request.
  void FinishBlock(std::size_t block, const BlockIo& io, bool stepped);

  // Steps every block whose task starts before `stop` is requested; with
  // `io`, each block's resets and outputs follow its step in the same task.
  void Step(const StepSettings& settings, std::stop_token stop, const BlockIo* io = nullptr);
  // One block's step, timed per phase when profiling; true if unhealthy.
  // next_block (the thread's next, or nullptr) is brought into L2 meanwhile.
  bool StepBlock(std::size_t block, const std::byte* next_block, const StepParams& params);
  void RecordHealth(std::size_t block, bool unhealthy, bool reset_unhealthy);
  // Step's result: false when `stop` left some block unstepped.
  bool EveryWorldStepped(std::stop_token stop) const;

  // ---- one caller at a time. A Batch is not thread-safe; calls that write
  // many worlds (or step them) hold `busy_` and throw if another thread
  // already does, rather than corrupting worlds; single-world calls only
  // look at it (cheap enough for RL loops that call them per world).
  class Exclusive {
   public:
    Exclusive(const Impl& impl, const char* call);
    ~Exclusive();
    Exclusive(const Exclusive&) = delete;
    Exclusive& operator=(const Exclusive&) = delete;

   private:
    const Impl& impl_;
    bool owns_;  // false when nested in this thread's own Exclusive call
  };
  void CheckNotBusy(const char* call) const;

  // ---- actions: never refused (RL loops write them every step); a
  // non-finite one is noted and reported with the world's health after the
  // next Step. A finite one overwriting it clears the note once none of the
  // world's inputs is non-finite any more.
  template <class... Values>
  void NoteInput(std::size_t world, Values... values) {
    if (!(std::isfinite(values) && ...)) {
      pending_input_[world] = kNonFiniteInput;
    } else if (pending_input_[world] != 0) {
      pending_input_[world] = InputsFinite(world) ? 0 : kNonFiniteInput;
    }
  }
  bool InputsFinite(std::size_t world) const;

  // ---- lane access
  void CheckWorld(std::size_t world) const;
  void CheckBody(std::size_t body) const;
  const ConstraintPlan& Constraint(std::size_t index) const;
  // "<body or constraint label> in world <w>", for per-world refusals.
  std::string InWorld(const std::string& label, std::size_t world) const {
    return label + " in world " + std::to_string(world);
  }

  template <class Lanes>
  Lanes& In(std::size_t world, std::size_t offset) {
    return At<Lanes>(Block(world / kLaneWidth), offset);
  }
  template <class Lanes>
  const Lanes& In(std::size_t world, std::size_t offset) const {
    return *reinterpret_cast<const Lanes*>(Block(world / kLaneWidth) + offset);
  }

  BodyLanes& Body(std::size_t world, std::size_t body) {
    CheckWorld(world);
    CheckBody(body);
    return In<BodyLanes>(world, plan_.bodies[body].offset);
  }
  BodyMotionLanes& Motion(std::size_t world, std::size_t body, const char* setting);

  // ---- state
  void ReadState(std::size_t world, std::size_t body, float* out) const;
  void CheckStates(std::span<const float> in, std::span<const std::uint8_t> mask) const;
  void WriteState(std::size_t world, std::size_t body, const float* in);
  void WriteStates(std::span<const float> in, std::span<const std::uint8_t> mask);
  void CheckSize(std::size_t got, std::size_t want, const char* what) const;
  static bool Selected(std::span<const std::uint8_t> mask, std::size_t world) {
    return mask.empty() || mask[world] != 0;
  }
  void ResetWorld(std::size_t world);
  void ResetLanes(std::size_t block, const std::size_t* lanes, std::size_t count);
  // Reset (and with `states`, ResetTo) of the masked worlds, over the
  // batch's threads, or of one block's.
  void ResetWorlds(std::span<const std::uint8_t> mask, std::span<const float> states = {});
  void ResetWorldsOfBlock(std::size_t block, std::span<const std::uint8_t> mask,
                          std::span<const float> states);

  // ---- observations of one block's real worlds: every body's state into
  // out[world][body][13] (batch.cc), the joint coordinates into
  // out[world][layout.per_world] (batch_joints.cc).
  void ReadStateOfBlock(std::size_t block, float* out) const;
  JointLayout JointCoordinateLayout() const;
  void ReadJointCoordinatesOfWorld(std::size_t world, const JointLayout& layout,
                                   float* row) const;
  void ReadJointCoordinatesOfBlock(std::size_t block, const JointLayout& layout,
                                   float* out) const;

  // ---- per-constraint parameters
  static void RefuseMultiAxis(const ConstraintPlan& c, const char* what);
  // The constraint's plan if it has rotation (translation) drives, else
  // SceneError naming it and `what`.
  const ConstraintPlan& WithRotationDrives(std::size_t constraint, const char* what) const;
  const ConstraintPlan& WithTranslationDrives(std::size_t constraint, const char* what) const;

  template <class Fn>
  void WithMotor(std::size_t world, std::size_t constraint, const char* what, Fn&& fn) {
    CheckWorld(world);
    const ConstraintPlan& c = SingleMotor(constraint, what);
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
  float ClampedTarget(std::size_t world, const ConstraintPlan& c, float position) const;

  Scene scene_;
  StepPlan plan_;
  std::size_t world_count_;
  std::size_t block_count_;
  std::size_t arrays_per_block_;
  std::vector<LaneArray> initial_;  // one block with the scene in every lane
  std::vector<LaneArray> storage_;  // block_count_ blocks
  // Byte offsets in a block of the LaneArrays that hold actions (forces,
  // torques, motor and drive targets), for InputsFinite.
  std::vector<std::size_t> input_arrays_;
  const StepKernels* kernels_;
  // The joint-coordinate read-out of the same Highway target as the step.
  const JointCoordinateKernels* joint_kernels_;
  int threads_;
  mutable tbb::task_arena arena_;  // const read-outs run in it too
  std::size_t blocks_per_task_;
  // BatchOptions::profile_phases: nanoseconds per StepPhase, blocks and
  // real worlds stepped, summed by every block's task.
  bool profile_phases_;
  // Whether each block's step brings the thread's next block into L2 (see
  // NextBlockPrefetch in step_kernels.cc): only when a thread's share of the
  // batch is larger than an L2 cache can hold, as otherwise the blocks are
  // there already and the requests would only cost instructions (chain16 at
  // 256 worlds on two threads: 3-5 % slower with them).
  static constexpr std::size_t kPrefetchAboveBytesPerThread = std::size_t{1} << 20;
  bool prefetch_next_block_;
  std::array<std::atomic<std::uint64_t>, kStepPhaseCount> phase_ns_{};
  std::atomic<std::uint64_t> profiled_blocks_{0}, profiled_worlds_{0};
  float previous_substep_dt_ = 0.0f;  // Jolt's mPreviousStepDeltaTime (0: cold start)
  std::vector<std::uint8_t> health_ = std::vector<std::uint8_t>(world_count_, 0);
  std::vector<std::uint8_t> pending_input_ = std::vector<std::uint8_t>(world_count_, 0);
  StepSettings last_settings_{};
  mutable std::atomic<bool> busy_{false};
  mutable std::atomic<std::thread::id> busy_thread_{};
};

}  // namespace manyworlds
