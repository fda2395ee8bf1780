// Batch: joint coordinates and motor forces per world (the read-outs are
// batch/joint_coordinates.h; here only the world loop and the size checks).

#include <algorithm>
#include <string>
#include <vector>

#include "batch/batch_impl.h"
#include "batch/joint_coordinates.h"
#include "manyworlds/batch.h"

namespace manyworlds {

std::size_t Batch::JointCoordinateCount(std::size_t constraint) const {
  return manyworlds::JointCoordinateCount(impl().Constraint(constraint));
}

std::vector<std::string> Batch::JointCoordinateNames(std::size_t constraint) const {
  return manyworlds::JointCoordinateNames(impl().Constraint(constraint));
}

void Batch::GetJointCoordinates(std::size_t constraint, std::span<float> out) const {
  const Impl& batch = impl();
  const std::size_t count = JointCoordinateCount(constraint);
  batch.CheckSize(out.size(), batch.world_count_ * count, "GetJointCoordinates");
  batch.ForEachBlock([&](std::size_t block) {
    for (auto [world, end] = batch.WorldsOf(block); world < end; ++world) {
      JointCoordinatesOfLane(batch.plan_, batch.Block(block), Impl::Lane(world), constraint,
                             out.data() + world * count);
    }
  });
}

std::size_t Batch::JointCoordinatesPerWorld() const {
  std::size_t total = 0;
  for (std::size_t c = 0; c < constraint_count(); ++c) total += JointCoordinateCount(c);
  return total;
}

std::vector<Batch::Impl::JointSlice> Batch::Impl::JointSlices() const {
  std::vector<JointSlice> slices;
  for (std::size_t c = 0, offset = 0; c < plan_.constraints.size(); ++c) {
    const std::size_t count = manyworlds::JointCoordinateCount(plan_.constraints[c]);
    if (count > 0) slices.push_back({c, offset});
    offset += count;
  }
  return slices;
}

void Batch::Impl::ReadJointCoordinatesOfBlock(std::size_t block,
                                              std::span<const JointSlice> slices,
                                              std::size_t per_world, float* out) const {
  for (auto [world, end] = WorldsOf(block); world < end; ++world) {
    for (const auto& [c, offset] : slices) {
      JointCoordinatesOfLane(plan_, Block(block), Lane(world), c, out + world * per_world + offset);
    }
  }
}

void Batch::GetJointCoordinates(std::span<float> out) const {
  const Impl& batch = impl();
  const std::size_t per_world = JointCoordinatesPerWorld();
  batch.CheckSize(out.size(), batch.world_count_ * per_world, "GetJointCoordinates");
  const std::vector<Impl::JointSlice> slices = batch.JointSlices();
  batch.ForEachBlock([&](std::size_t block) {
    batch.ReadJointCoordinatesOfBlock(block, slices, per_world, out.data());
  });
}

std::size_t Batch::MotorForceCount(std::size_t constraint) const {
  return manyworlds::MotorForceCount(impl().Constraint(constraint));
}

void Batch::GetMotorForces(std::size_t constraint, std::span<float> out) const {
  const Impl& batch = impl();
  const std::size_t count = MotorForceCount(constraint);
  batch.CheckSize(out.size(), batch.world_count_ * count, "GetMotorForces");
  batch.ForEachBlock([&](std::size_t block) {
    for (auto [world, end] = batch.WorldsOf(block); world < end; ++world) {
      MotorForcesOfLane(batch.plan_, batch.Block(block), Impl::Lane(world), constraint,
                        batch.previous_substep_dt_, out.data() + world * count);
    }
  });
}

}  // namespace manyworlds
