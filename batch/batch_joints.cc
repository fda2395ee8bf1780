// Batch: joint coordinates and motor forces per world (the read-outs are
// batch/joint_coordinates.h; here only the world loop and the size checks).

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
  for (std::size_t world = 0; world < batch.world_count_; ++world) {
    JointCoordinatesOfLane(batch.plan_, batch.Block(world / kLaneWidth), Impl::Lane(world),
                           constraint, out.data() + world * count);
  }
}

std::size_t Batch::JointCoordinatesPerWorld() const {
  std::size_t total = 0;
  for (std::size_t c = 0; c < constraint_count(); ++c) total += JointCoordinateCount(c);
  return total;
}

void Batch::GetJointCoordinates(std::span<float> out) const {
  const Impl& batch = impl();
  const std::size_t per_world = JointCoordinatesPerWorld();
  batch.CheckSize(out.size(), batch.world_count_ * per_world, "GetJointCoordinates");
  for (std::size_t world = 0; world < batch.world_count_; ++world) {
    float* world_out = out.data() + world * per_world;
    for (std::size_t c = 0; c < batch.plan_.constraints.size(); ++c) {
      JointCoordinatesOfLane(batch.plan_, batch.Block(world / kLaneWidth), Impl::Lane(world), c,
                             world_out);
      world_out += manyworlds::JointCoordinateCount(batch.plan_.constraints[c]);
    }
  }
}

std::size_t Batch::MotorForceCount(std::size_t constraint) const {
  return manyworlds::MotorForceCount(impl().Constraint(constraint));
}

void Batch::GetMotorForces(std::size_t constraint, std::span<float> out) const {
  const Impl& batch = impl();
  const std::size_t count = MotorForceCount(constraint);
  batch.CheckSize(out.size(), batch.world_count_ * count, "GetMotorForces");
  for (std::size_t world = 0; world < batch.world_count_; ++world) {
    MotorForcesOfLane(batch.plan_, batch.Block(world / kLaneWidth), Impl::Lane(world),
                      constraint, batch.previous_substep_dt_, out.data() + world * count);
  }
}

}  // namespace manyworlds
