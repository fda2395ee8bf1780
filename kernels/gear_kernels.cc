// Compiles the gear kernels once per Highway target into a
// GearKernels table (see kernels/kernel_table.h).

#include "kernels/gear.h"

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "kernels/gear_kernels.cc"
#include "hwy/foreach_target.h"  // IWYU pragma: keep

#include "hwy/highway.h"
#include "kernels/gear-inl.h"

HWY_BEFORE_NAMESPACE();
namespace manyworlds {
namespace HWY_NAMESPACE {

const GearKernels* GetGearKernels() {
  static const GearKernels kTable = {
      MANYWORLDS_THIS_TARGET,
      &GearCalculateProperties,
      &GearWarmStart,
      &GearSolveVelocity,
      &GearSolvePosition,
      &GearDeactivate,
      &GearIsActive,
  };
  return &kTable;
}

}  // namespace HWY_NAMESPACE
}  // namespace manyworlds
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace manyworlds {
MANYWORLDS_EXPORT_KERNEL_TABLE(GearKernels, GetGearKernels)
}  // namespace manyworlds
#endif  // HWY_ONCE
