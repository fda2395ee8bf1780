// Compiles the point kernels once per Highway target into a PointKernels
// table (see kernels/kernel_table.h).

#include "kernels/point.h"

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "kernels/point_kernels.cc"
#include "hwy/foreach_target.h"  // IWYU pragma: keep

#include "hwy/highway.h"
#include "kernels/point-inl.h"

HWY_BEFORE_NAMESPACE();
namespace manyworlds {
namespace HWY_NAMESPACE {

const PointKernels* GetPointKernels() {
  static const PointKernels kTable = {
      MANYWORLDS_THIS_TARGET, &PointCalculateProperties,       &PointWarmStart,
      &PointSolveVelocity,    &PointSolvePosition,             &PointRecomputeAndSolvePosition,
      &PointDeactivate,       &PointIsActive,
  };
  return &kTable;
}

}  // namespace HWY_NAMESPACE
}  // namespace manyworlds
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace manyworlds {
MANYWORLDS_EXPORT_KERNEL_TABLE(PointKernels, GetPointKernels)
}  // namespace manyworlds
#endif  // HWY_ONCE
