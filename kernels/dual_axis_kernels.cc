// Compiles the dual-axis kernels once per Highway target into a
// DualAxisKernels table (see kernels/kernel_table.h).

#include "kernels/dual_axis.h"

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "kernels/dual_axis_kernels.cc"
#include "hwy/foreach_target.h"  // IWYU pragma: keep

#include "hwy/highway.h"
#include "kernels/dual_axis-inl.h"

HWY_BEFORE_NAMESPACE();
namespace manyworlds {
namespace HWY_NAMESPACE {

const DualAxisKernels* GetDualAxisKernels() {
  static const DualAxisKernels kTable = {
      MANYWORLDS_THIS_TARGET, &DualAxisCalculateProperties, &DualAxisWarmStart,
      &DualAxisSolveVelocity, &DualAxisSolvePosition,       &DualAxisRecomputeAndSolvePosition,
      &DualAxisDeactivate,    &DualAxisIsActive,
  };
  return &kTable;
}

}  // namespace HWY_NAMESPACE
}  // namespace manyworlds
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace manyworlds {
MANYWORLDS_EXPORT_KERNEL_TABLE(DualAxisKernels, GetDualAxisKernels)
}  // namespace manyworlds
#endif  // HWY_ONCE
