// The working block a block steps in (StepPlan::block_bytes, scratch_bytes):
// a copy of the stored block followed by the scratch its setup recomputes at
// every substep, one per thread and reused block after block, so that the
// scratch stays in L1 or L2 and takes no space per world.
#pragma once

#include <cstddef>
#include <cstring>
#include <vector>

#include "batch/plan.h"
#include "manyworlds/lanes.h"

namespace manyworlds {

class WorkingBlock {
 public:
  // Copies `stored` in, and what the plan carries (impulses, row
  // parameters) into the scratch; a plan without scratch steps the stored
  // block itself.
  WorkingBlock(const StepPlan& plan, std::byte* stored) : plan_(plan), stored_(stored) {
    if (plan.scratch_bytes == 0) {
      bytes_ = stored;
      return;
    }
    thread_local std::vector<LaneArray> buffer;
    const std::size_t arrays = plan.working_bytes() / sizeof(LaneArray);
    if (buffer.size() < arrays) buffer.resize(arrays);
    bytes_ = reinterpret_cast<std::byte*>(buffer.data());
    std::memcpy(bytes_, stored, plan.block_bytes);
#ifndef NDEBUG
    // Debug builds (CI's sanitizer stage among them) fill the scratch with
    // NaN first (all bits set: a quiet NaN; one memset, cheap at -O0 under
    // ASan): a value a step reads before its setup wrote it then turns its
    // world NaN and fails the tests, rather than quietly depending on what
    // another block or batch left there.
    std::memset(bytes_ + plan.block_bytes, 0xFF, plan.scratch_bytes);
#endif
    for (const CarriedState& c : plan.carried) {
      std::memcpy(bytes_ + c.scratch, bytes_ + c.home, c.bytes);
    }
  }
  // Copies what is carried home and the block back.
  ~WorkingBlock() {
    if (bytes_ == stored_) return;
    for (const CarriedState& c : plan_.carried) {
      std::memcpy(bytes_ + c.home, bytes_ + c.scratch, c.bytes);
    }
    std::memcpy(stored_, bytes_, plan_.block_bytes);
  }
  WorkingBlock(const WorkingBlock&) = delete;
  WorkingBlock& operator=(const WorkingBlock&) = delete;

  std::byte* bytes() const { return bytes_; }

 private:
  const StepPlan& plan_;
  std::byte* stored_;
  std::byte* bytes_;
};

}  // namespace manyworlds
