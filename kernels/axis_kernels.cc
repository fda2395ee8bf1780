// Compiles the axis kernels once per Highway target into an AxisKernels
// table (see kernels/kernel_table.h).

#include "kernels/axis.h"

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "kernels/axis_kernels.cc"
#include "hwy/foreach_target.h"  // IWYU pragma: keep

#include "hwy/highway.h"
#include "kernels/axis-inl.h"

HWY_BEFORE_NAMESPACE();
namespace manyworlds {
namespace HWY_NAMESPACE {

const AxisKernels* GetAxisKernels() {
  static const AxisKernels kTable = {
      MANYWORLDS_THIS_TARGET,
      &AxisCalculateProperties,
      &AxisCalculatePropertiesWithFrequencyAndDamping,
      &AxisCalculatePropertiesWithStiffnessAndDamping,
      &AxisCalculatePropertiesForLimit,
      &AxisCalculatePropertiesForMotor,
      &AxisWarmStart,
      &AxisSolveVelocity,
      &AxisSolvePosition,
      &AxisDeactivate,
      &AxisIsActive,
  };
  return &kTable;
}

}  // namespace HWY_NAMESPACE
}  // namespace manyworlds
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace manyworlds {
MANYWORLDS_EXPORT_KERNEL_TABLE(AxisKernels, GetAxisKernels)
}  // namespace manyworlds
#endif  // HWY_ONCE
