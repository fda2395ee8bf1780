// Block layout of a batch of worlds: body k of kLaneWidth worlds side by side.
//
// Storage is [block][body][field][lane] (AoSoA): one block holds every body of
// kLaneWidth worlds contiguously, so a task that steps one block works inside
// L1/L2. World counts that are not a multiple of kLaneWidth are padded with
// inert worlds (at rest, zero inverse mass and inertia) that go through the
// same SIMD path as real ones and never affect them.
#pragma once

#include <cstddef>
#include <vector>

#include "kernels/body_lanes.h"
#include "manyworlds/body_state.h"
#include "manyworlds/lanes.h"
#include "manyworlds/motion_type.h"

namespace manyworlds {

inline constexpr std::size_t BlockCount(std::size_t world_count) {
  return (world_count + kLaneWidth - 1) / kLaneWidth;
}

// A padding world's body: at rest at the origin, immovable.
BodyState InertBody();

class BodyBlocks {
 public:
  // One motion type per body (the same in every world); all worlds start with
  // InertBody() in every body.
  BodyBlocks(std::vector<MotionType> motion_types, std::size_t world_count);

  std::size_t world_count() const { return world_count_; }
  std::size_t block_count() const { return block_count_; }
  std::size_t body_count() const { return motion_types_.size(); }
  MotionType motion_type(std::size_t body) const { return motion_types_.at(body); }

  BodyLanes& lanes(std::size_t block, std::size_t body) {
    return storage_[block * body_count() + body];
  }
  const BodyLanes& lanes(std::size_t block, std::size_t body) const {
    return storage_[block * body_count() + body];
  }

  // One body of one real world; throws std::out_of_range naming the index.
  BodyState Get(std::size_t world, std::size_t body) const;
  void Set(std::size_t world, std::size_t body, const BodyState& state);

 private:
  void CheckIndices(std::size_t world, std::size_t body) const;

  std::vector<MotionType> motion_types_;
  std::size_t world_count_;
  std::size_t block_count_;
  std::vector<BodyLanes> storage_;  // 64-byte aligned through aligned new
};

// Reads / writes lane `lane` of a block-layout body as plain numbers (no bounds
// checks; padding lanes included).
BodyState ReadLane(const BodyLanes& lanes, std::size_t lane);
void WriteLane(BodyLanes& lanes, std::size_t lane, const BodyState& state);

// Per-block storage of one part (or any lane struct), zero-initialised.
template <class LaneStruct>
class PartBlocks {
 public:
  explicit PartBlocks(std::size_t block_count) : blocks_(block_count) {}
  std::size_t block_count() const { return blocks_.size(); }
  LaneStruct& operator[](std::size_t block) { return blocks_[block]; }
  const LaneStruct& operator[](std::size_t block) const { return blocks_[block]; }

 private:
  std::vector<LaneStruct> blocks_;  // value-initialised: all lanes zero
};

}  // namespace manyworlds
