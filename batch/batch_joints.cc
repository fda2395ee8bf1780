// Batch: joint coordinates and motor forces per world (the read-outs are
// batch/joint_coordinates.h; here only the block loop and the size checks).
// Joint coordinates are read a block at a time by the SIMD kernels of the
// step's Highway target, also for one world (its block's read-out, one row
// kept), so every form gives the same bits.

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
  if (count == 0) return;
  batch.ForEachBlock([&](std::size_t block) {
    const auto [first, end] = batch.WorldsOf(block);
    batch.joint_kernels_->read_block(batch.plan_, batch.Block(block), constraint, end - first,
                                     count, out.data() + first * count);
  });
}

std::size_t Batch::JointCoordinatesPerWorld() const {
  std::size_t total = 0;
  for (std::size_t c = 0; c < constraint_count(); ++c) total += JointCoordinateCount(c);
  return total;
}

Batch::Impl::JointLayout Batch::Impl::JointCoordinateLayout() const {
  JointLayout layout;
  for (std::size_t c = 0; c < plan_.constraints.size(); ++c) {
    const std::size_t count = manyworlds::JointCoordinateCount(plan_.constraints[c]);
    if (count == 0) continue;
    layout.constraints.push_back(c);
    layout.offsets.push_back(layout.per_world);
    layout.per_world += count;
  }
  return layout;
}

// The block's lanes up to the world's, one row kept.
void Batch::Impl::ReadJointCoordinatesOfWorld(std::size_t world, const JointLayout& layout,
                                              float* row) const {
  const std::size_t lanes = Lane(world) + 1;
  std::vector<float> rows(lanes * layout.per_world);
  for (std::size_t i = 0; i < layout.constraints.size(); ++i) {
    joint_kernels_->read_block(plan_, Block(world / kLaneWidth), layout.constraints[i], lanes,
                               layout.per_world, rows.data() + layout.offsets[i]);
  }
  std::copy_n(rows.data() + Lane(world) * layout.per_world, layout.per_world, row);
}

void Batch::Impl::ReadJointCoordinatesOfBlock(std::size_t block, const JointLayout& layout,
                                              float* out) const {
  const auto [first, end] = WorldsOf(block);
  for (std::size_t i = 0; i < layout.constraints.size(); ++i) {
    joint_kernels_->read_block(plan_, Block(block), layout.constraints[i], end - first,
                               layout.per_world, out + first * layout.per_world + layout.offsets[i]);
  }
}

void Batch::GetJointCoordinates(std::span<float> out) const {
  const Impl& batch = impl();
  const Impl::JointLayout layout = batch.JointCoordinateLayout();
  batch.CheckSize(out.size(), batch.world_count_ * layout.per_world, "GetJointCoordinates");
  batch.ForEachBlock(
      [&](std::size_t block) { batch.ReadJointCoordinatesOfBlock(block, layout, out.data()); });
}

void Batch::GetWorldJointCoordinates(std::size_t world, std::span<float> out) const {
  const Impl& batch = impl();
  batch.CheckWorld(world);
  const Impl::JointLayout layout = batch.JointCoordinateLayout();
  batch.CheckSize(out.size(), layout.per_world, "GetWorldJointCoordinates");
  batch.ReadJointCoordinatesOfWorld(world, layout, out.data());
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
