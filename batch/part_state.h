// The state of a part that persists between steps (its accumulated impulse),
// per world: get and set (Jolt's GetTotalLambda / SetTotalLambda) and save and
// restore of whole blocks (Jolt's SaveState / RestoreState).
#pragma once

#include <array>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "batch/world_blocks.h"
#include "manyworlds/lanes.h"

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

// One lane of a lane struct as plain numbers, and back.
inline float ReadLaneValue(const LaneArray& field, std::size_t lane) {
  return field[lane];
}
inline std::array<float, 2> ReadLaneValue(const Vec2Lanes& field, std::size_t lane) {
  return {field.x[lane], field.y[lane]};
}
inline std::array<float, 3> ReadLaneValue(const Vec3Lanes& field, std::size_t lane) {
  return {field.x[lane], field.y[lane], field.z[lane]};
}
inline void WriteLaneValue(LaneArray& field, std::size_t lane, float value) {
  field[lane] = value;
}
inline void WriteLaneValue(Vec2Lanes& field, std::size_t lane,
                           const std::array<float, 2>& value) {
  field.x[lane] = value[0];
  field.y[lane] = value[1];
}
inline void WriteLaneValue(Vec3Lanes& field, std::size_t lane,
                           const std::array<float, 3>& value) {
  field.x[lane] = value[0];
  field.y[lane] = value[1];
  field.z[lane] = value[2];
}

// Accumulated impulse of one world (Jolt's GetTotalLambda): a float, or an
// array for parts with 2 or 3 rows. Parts with several independent impulses
// (swing-twist) name them in their own Persistent struct instead.
template <class PartLanes>
auto GetTotalLambda(const PartBlocks<PartLanes>& parts, std::size_t world) {
  return ReadLaneValue(parts[world / kLaneWidth].persistent.total_lambda,
                       world % kLaneWidth);
}

template <class PartLanes>
using TotalLambdaValue = decltype(ReadLaneValue(
    std::declval<const PartLanes&>().persistent.total_lambda, std::size_t{0}));

template <class PartLanes>
void SetTotalLambda(PartBlocks<PartLanes>& parts, std::size_t world,
                    const TotalLambdaValue<PartLanes>& value) {
  WriteLaneValue(parts[world / kLaneWidth].persistent.total_lambda,
                 world % kLaneWidth, value);
}

}  // namespace manyworlds
