// A path for the path constraint (spec 3, Path): a cubic Hermite spline
// through control points, the same in every world. The lane maths (closest
// point, point on path) is in hermite_path-inl.h; this table exports it per
// target for tests.
#pragma once

#include <cstddef>

#include "kernels/kernel_table.h"
#include "manyworlds/lanes.h"

namespace manyworlds {

struct HermitePathPoint {
  float position[3];
  float tangent[3];  // d position / d fraction
  float normal[3];
};

// A view of a path's points (at least 2). The fraction runs from 0 to
// max_fraction(): segment i is [i, i + 1]; a looping path has a last segment
// from the last point back to the first.
struct HermitePath {
  const HermitePathPoint* points = nullptr;
  std::size_t count = 0;
  bool looping = false;

  std::size_t segments() const { return looping ? count : count - 1; }
  float max_fraction() const { return float(segments()); }
};

struct HermitePathKernels {
  TargetInfo target;
  // Jolt's GetClosestPoint: the fraction of the point on the path closest to
  // `position` (path space), per lane.
  void (*closest_point)(const HermitePath& path, const Vec3Lanes& position, LaneArray& fraction);
  // Jolt's GetPointOnPath: position, unit tangent, normal and binormal at a
  // fraction (clamped to the ends, or wrapped for a looping path).
  void (*point_on_path)(const HermitePath& path, const LaneArray& fraction, Vec3Lanes& position,
                        Vec3Lanes& tangent, Vec3Lanes& normal, Vec3Lanes& binormal);
};

MANYWORLDS_DECLARE_KERNEL_TABLE(HermitePathKernels)

}  // namespace manyworlds
