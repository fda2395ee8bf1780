#include "batch/world_blocks.h"

#include <stdexcept>
#include <string>
#include <utility>

namespace manyworlds {

namespace {

void WriteVec3(Vec3Lanes& out, std::size_t lane, const std::array<float, 3>& v) {
  out.x[lane] = v[0];
  out.y[lane] = v[1];
  out.z[lane] = v[2];
}
std::array<float, 3> ReadVec3(const Vec3Lanes& in, std::size_t lane) {
  return {in.x[lane], in.y[lane], in.z[lane]};
}
void WriteQuat(QuatLanes& out, std::size_t lane, const std::array<float, 4>& q) {
  out.x[lane] = q[0];
  out.y[lane] = q[1];
  out.z[lane] = q[2];
  out.w[lane] = q[3];
}
std::array<float, 4> ReadQuat(const QuatLanes& in, std::size_t lane) {
  return {in.x[lane], in.y[lane], in.z[lane], in.w[lane]};
}

}  // namespace

BodyState InertBody() { return BodyState{}; }

BodyState ReadLane(const BodyLanes& lanes, std::size_t lane) {
  BodyState state;
  state.position = ReadVec3(lanes.position, lane);
  state.rotation = ReadQuat(lanes.rotation, lane);
  state.linear_velocity = ReadVec3(lanes.linear_velocity, lane);
  state.angular_velocity = ReadVec3(lanes.angular_velocity, lane);
  state.inv_mass = lanes.inv_mass[lane];
  state.inv_inertia_diagonal = ReadVec3(lanes.inv_inertia_diagonal, lane);
  state.inertia_rotation = ReadQuat(lanes.inertia_rotation, lane);
  return state;
}

void WriteLane(BodyLanes& lanes, std::size_t lane, const BodyState& state) {
  WriteVec3(lanes.position, lane, state.position);
  WriteQuat(lanes.rotation, lane, state.rotation);
  WriteVec3(lanes.linear_velocity, lane, state.linear_velocity);
  WriteVec3(lanes.angular_velocity, lane, state.angular_velocity);
  lanes.inv_mass[lane] = state.inv_mass;
  WriteVec3(lanes.inv_inertia_diagonal, lane, state.inv_inertia_diagonal);
  WriteQuat(lanes.inertia_rotation, lane, state.inertia_rotation);
}

BodyBlocks::BodyBlocks(std::vector<MotionType> motion_types,
                       std::size_t world_count)
    : motion_types_(std::move(motion_types)),
      world_count_(world_count),
      block_count_(BlockCount(world_count)),
      storage_(block_count_ * motion_types_.size()) {
  const BodyState inert = InertBody();
  for (BodyLanes& body : storage_) {
    for (std::size_t lane = 0; lane < kLaneWidth; ++lane) {
      WriteLane(body, lane, inert);
    }
  }
}

void BodyBlocks::CheckIndices(std::size_t world, std::size_t body) const {
  if (world >= world_count_) {
    throw std::out_of_range("world " + std::to_string(world) +
                            " is out of range: the batch has " +
                            std::to_string(world_count_) + " worlds");
  }
  if (body >= body_count()) {
    throw std::out_of_range("body " + std::to_string(body) +
                            " is out of range: the scene has " +
                            std::to_string(body_count()) + " bodies");
  }
}

BodyState BodyBlocks::Get(std::size_t world, std::size_t body) const {
  CheckIndices(world, body);
  return ReadLane(lanes(world / kLaneWidth, body), world % kLaneWidth);
}

void BodyBlocks::Set(std::size_t world, std::size_t body, const BodyState& state) {
  CheckIndices(world, body);
  WriteLane(lanes(world / kLaneWidth, body), world % kLaneWidth, state);
}

}  // namespace manyworlds
