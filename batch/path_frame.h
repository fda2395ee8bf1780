// One point of a path evaluated by the batch's own path kernels (in float, as
// the step computes it) and read back in double, for the code outside the
// step that needs it: the scene setup (the attachment frame at the starting
// fraction) and the constraint error (the closest point now).
#pragma once

#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <cstddef>

#include "kernels/hermite_path.h"
#include "manyworlds/lanes.h"

namespace manyworlds {

struct PathPointFrame {
  double fraction;
  Eigen::Vector3d position, tangent;
  Eigen::Quaterniond frame;  // X = tangent, Y = binormal, Z = normal
};

// The point, tangent and frame at `fraction` (every lane the same; lane 0 read).
inline PathPointFrame PathFrameOfLane0(const HermitePath& path, const LaneArray& fraction) {
  Vec3Lanes position, tangent, normal, binormal;
  DispatchedKernels<HermitePathKernels>().point_on_path(path, fraction, position, tangent,
                                                          normal, binormal);
  const auto lane0 = [](const Vec3Lanes& v) { return Eigen::Vector3d(v.x[0], v.y[0], v.z[0]); };
  Eigen::Matrix3d frame;
  frame << lane0(tangent), lane0(binormal), lane0(normal);
  return {fraction[0], lane0(position), lane0(tangent),
          Eigen::Quaterniond(frame).normalized()};
}

inline PathPointFrame PathFrameAt(const HermitePath& path, float fraction) {
  LaneArray fractions;
  for (float& f : fractions.lanes) f = fraction;
  return PathFrameOfLane0(path, fractions);
}

// The closest point of the path to q (path space).
inline PathPointFrame ClosestPathFrame(const HermitePath& path, const Eigen::Vector3d& q) {
  Vec3Lanes query;
  for (std::size_t lane = 0; lane < kLaneWidth; ++lane) {
    query.x[lane] = float(q.x());
    query.y[lane] = float(q.y());
    query.z[lane] = float(q.z());
  }
  LaneArray fraction;
  DispatchedKernels<HermitePathKernels>().closest_point(path, query, fraction);
  return PathFrameOfLane0(path, fraction);
}

}  // namespace manyworlds
