// The state of a part that persists between steps (its accumulated impulse),
// per world: get and set (Jolt's GetTotalLambda / SetTotalLambda) and save and
// restore of whole blocks (Jolt's SaveState / RestoreState).
#pragma once

#include <array>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

#include "batch/world_blocks.h"
#include "kernels/dual_axis.h"
#include "kernels/rack_and_pinion.h"

namespace manyworlds {

// Copies what survives between steps; everything else a part holds is
// recomputed by CalculateProperties.
template <class PartLanes>
std::vector<typename PartLanes::Persistent> SavePartState(
    const PartBlocks<PartLanes>& parts) {
  std::vector<typename PartLanes::Persistent> saved(parts.block_count());
  for (std::size_t block = 0; block < parts.block_count(); ++block) {
    saved[block] = parts[block].persistent;
  }
  return saved;
}

template <class PartLanes>
void RestorePartState(PartBlocks<PartLanes>& parts,
                      const std::vector<typename PartLanes::Persistent>& saved) {
  if (saved.size() != parts.block_count()) {
    throw std::invalid_argument(
        "RestorePartState: saved state has " + std::to_string(saved.size()) +
        " blocks, the part has " + std::to_string(parts.block_count()));
  }
  for (std::size_t block = 0; block < parts.block_count(); ++block) {
    parts[block].persistent = saved[block];
  }
}

inline std::array<float, 2> GetTotalLambda(const PartBlocks<DualAxisLanes>& parts,
                                           std::size_t world) {
  const Vec2Lanes& lambda = parts[world / kLaneWidth].persistent.total_lambda;
  return {lambda.x[world % kLaneWidth], lambda.y[world % kLaneWidth]};
}
inline void SetTotalLambda(PartBlocks<DualAxisLanes>& parts, std::size_t world,
                           const std::array<float, 2>& value) {
  Vec2Lanes& lambda = parts[world / kLaneWidth].persistent.total_lambda;
  lambda.x[world % kLaneWidth] = value[0];
  lambda.y[world % kLaneWidth] = value[1];
}

inline float GetTotalLambda(const PartBlocks<RackAndPinionLanes>& parts,
                            std::size_t world) {
  return parts[world / kLaneWidth].persistent.total_lambda[world % kLaneWidth];
}
inline void SetTotalLambda(PartBlocks<RackAndPinionLanes>& parts, std::size_t world,
                           float value) {
  parts[world / kLaneWidth].persistent.total_lambda[world % kLaneWidth] = value;
}

}  // namespace manyworlds
