// Compiles the rack-and-pinion kernels once per Highway target into a
// RackAndPinionKernels table (see kernels/kernel_table.h).

#include "kernels/rack_and_pinion.h"

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "kernels/rack_and_pinion_kernels.cc"
#include "hwy/foreach_target.h"  // IWYU pragma: keep

#include "hwy/highway.h"
#include "kernels/rack_and_pinion-inl.h"

HWY_BEFORE_NAMESPACE();
namespace manyworlds {
namespace HWY_NAMESPACE {

const RackAndPinionKernels* GetRackAndPinionKernels() {
  static const RackAndPinionKernels kTable = {
      MANYWORLDS_THIS_TARGET,  &RackAndPinionCalculateProperties, &RackAndPinionWarmStart,
      &RackAndPinionSolveVelocity,      &RackAndPinionSolvePosition,       &RackAndPinionDeactivate,
      &RackAndPinionIsActive,
  };
  return &kTable;
}

}  // namespace HWY_NAMESPACE
}  // namespace manyworlds
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace manyworlds {
MANYWORLDS_EXPORT_KERNEL_TABLE(RackAndPinionKernels, GetRackAndPinionKernels)
}  // namespace manyworlds
#endif  // HWY_ONCE
