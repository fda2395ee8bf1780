// Batch::Step(settings, io): the actions, resets and observation reads of
// an RL loop done inside the step's own pass over each block (batch.h,
// StepIo).
//
// Why: as separate calls, SetForces, Reset and GetState each pass over
// every block again, before or after Step. At 4096 cartpoles that was a fifth of a step on one
// thread and, with two threads, nearly half (docs/python.md, "Overhead of a
// Python step loop"), because each call's blocks are split between the two
// cores differently from the step's and come from the other core's cache.
// Here each block is reset and read in the task that just stepped it.
//
// Actions written from the calling thread also slowed the step itself: on
// two threads, set_body_forces before each step made it 22 us slower at
// 4096 cartpoles (docs/python.md), half of the blocks it dirtied being
// stepped by the other core.
//
// Bit-identity with the separate calls holds by construction: the same
// functions (WriteActionOfBlock, ResetWorldsOfBlock, ReadStateOfBlock,
// ReadJointCoordinatesOfBlock) run on the same block in the same order, and
// a world's result never depends on other worlds or on the thread.

#include <cstddef>
#include <cstdint>
#include <span>
#include <stdexcept>
#include <stop_token>
#include <string>

#include "batch/batch_impl.h"
#include "manyworlds/batch.h"

namespace manyworlds {

Batch::Impl::BlockIo Batch::Impl::CheckedBlockIo(const StepIo& io) const {
  const std::size_t state_floats = world_count_ * plan_.bodies.size() * kStateFloatsPerBody;
  BlockIo checked;
  for (std::size_t i = 0; i < io.actions.size(); ++i) {
    const std::string what = "Step actions[" + std::to_string(i) + "]";
    checked.actions.push_back(CheckAction(io.actions[i], what.c_str()));
  }
  if (!io.joints_out.empty()) checked.joints = JointCoordinateLayout();
  if (!io.reset_mask.empty()) CheckSize(io.reset_mask.size(), world_count_, "Step reset_mask");
  if (!io.reset_states.empty()) {
    if (io.reset_mask.empty()) {
      throw std::invalid_argument(
          "Step reset_states: given without a reset_mask (which worlds to reset)");
    }
    CheckSize(io.reset_states.size(), state_floats, "Step reset_states");
    CheckStates(io.reset_states, io.reset_mask);  // a zero rotation, before anything
  }
  if (!io.state_out.empty()) CheckSize(io.state_out.size(), state_floats, "Step state_out");
  if (!io.joints_out.empty()) {
    CheckSize(io.joints_out.size(), world_count_ * checked.joints.per_world, "Step joints_out");
  }
  checked.any = !io.actions.empty() || !io.reset_mask.empty() || !io.state_out.empty() ||
                !io.joints_out.empty();
  checked.reset_mask = io.reset_mask;
  checked.reset_states = io.reset_states;
  checked.state_out = io.state_out.empty() ? nullptr : io.state_out.data();
  checked.joints_out = io.joints_out.empty() ? nullptr : io.joints_out.data();
  return checked;
}

// Runs in the task that steps the block, before it does (or skips it for a
// stop request: the actions are then there for its next step, as when
// written by the separate calls).
void Batch::Impl::StartBlock(std::size_t block, const BlockIo& io) {
  for (const CheckedAction& action : io.actions) WriteActionOfBlock(block, action);
}

// Runs in the task that stepped the block (or skipped it for a stop
// request: then the block is left as it was, resets included, and only read).
void Batch::Impl::FinishBlock(std::size_t block, const BlockIo& io, bool stepped) {
  if (stepped && !io.reset_mask.empty()) ResetWorldsOfBlock(block, io.reset_mask, io.reset_states);
  if (io.state_out != nullptr) ReadStateOfBlock(block, io.state_out);
  if (io.joints_out != nullptr) ReadJointCoordinatesOfBlock(block, io.joints, io.joints_out);
}

void Batch::CheckStep(const StepSettings& settings, const StepIo& io) const {
  // In Step's order: io first (CheckedBlockIo), then the settings (Impl::Step).
  impl().CheckedBlockIo(io);
  CheckStepSettings(settings, impl().plan_);
}

bool Batch::Step(const StepSettings& settings, const StepIo& io, std::stop_token stop) {
  Impl& batch = impl();
  const Impl::Exclusive exclusive(batch, "Step");
  const Impl::BlockIo checked = batch.CheckedBlockIo(io);  // before any world changes
  // (An empty StepIo, Python's plain step(), runs exactly the plain Step.)
  batch.Step(settings, stop, checked.any ? &checked : nullptr);  // checks the settings first
  batch.last_settings_ = settings;
  return batch.EveryWorldStepped(stop);
}

}  // namespace manyworlds
