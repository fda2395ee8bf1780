// Compiles the independent-axis kernels once per Highway target into a
// IndependentAxisKernels table (see kernels/kernel_table.h).

#include "kernels/independent_axis.h"

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "kernels/independent_axis_kernels.cc"
#include "hwy/foreach_target.h"  // IWYU pragma: keep

#include "hwy/highway.h"
#include "kernels/independent_axis-inl.h"

HWY_BEFORE_NAMESPACE();
namespace manyworlds {
namespace HWY_NAMESPACE {

const IndependentAxisKernels* GetIndependentAxisKernels() {
  static const IndependentAxisKernels kTable = {
      MANYWORLDS_THIS_TARGET,
      &IndependentAxisCalculateProperties,
      &IndependentAxisWarmStart,
      &IndependentAxisSolveVelocity,
      &IndependentAxisSolvePosition,
      &IndependentAxisDeactivate,
      &IndependentAxisIsActive,
  };
  return &kTable;
}

}  // namespace HWY_NAMESPACE
}  // namespace manyworlds
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace manyworlds {
MANYWORLDS_EXPORT_KERNEL_TABLE(IndependentAxisKernels, GetIndependentAxisKernels)
}  // namespace manyworlds
#endif  // HWY_ONCE
