// Compiles the Hermite path maths once per Highway target into a
// HermitePathKernels table, for tests (the path constraint's step kernels
// include hermite_path-inl.h directly).

#include "kernels/hermite_path.h"

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "kernels/hermite_path_kernels.cc"
#include "hwy/foreach_target.h"  // IWYU pragma: keep

#include "hwy/highway.h"
#include "kernels/hermite_path-inl.h"

HWY_BEFORE_NAMESPACE();
namespace manyworlds {
namespace HWY_NAMESPACE {
namespace {

void PathClosestPoint(const HermitePath& path, const Vec3Lanes& position, LaneArray& fraction) {
  ForEachChunk([&](std::size_t offset) {
    Store(hermite::ClosestPoint(path, LoadVec3(position, offset)), fraction, offset);
  });
}

void PathPointOnPath(const HermitePath& path, const LaneArray& fraction, Vec3Lanes& position,
                     Vec3Lanes& tangent, Vec3Lanes& normal, Vec3Lanes& binormal) {
  ForEachChunk([&](std::size_t offset) {
    const hermite::PathFrame frame = hermite::PointOnPath(path, Load(fraction, offset));
    StoreVec3(frame.position, position, offset);
    StoreVec3(frame.tangent, tangent, offset);
    StoreVec3(frame.normal, normal, offset);
    StoreVec3(frame.binormal, binormal, offset);
  });
}

}  // namespace

const HermitePathKernels* GetHermitePathKernels() {
  static const HermitePathKernels kTable = {MANYWORLDS_THIS_TARGET, &PathClosestPoint,
                                            &PathPointOnPath};
  return &kTable;
}

}  // namespace HWY_NAMESPACE
}  // namespace manyworlds
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace manyworlds {
MANYWORLDS_EXPORT_KERNEL_TABLE(HermitePathKernels, GetHermitePathKernels)
}  // namespace manyworlds
#endif  // HWY_ONCE
