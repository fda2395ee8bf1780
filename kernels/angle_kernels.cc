// Compiles the angle kernels once per Highway target into an AngleKernels
// table (see kernels/kernel_table.h).

#include "kernels/angle.h"

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "kernels/angle_kernels.cc"
#include "hwy/foreach_target.h"  // IWYU pragma: keep

#include "hwy/highway.h"
#include "kernels/angle-inl.h"

HWY_BEFORE_NAMESPACE();
namespace manyworlds {
namespace HWY_NAMESPACE {

const AngleKernels* GetAngleKernels() {
  static const AngleKernels kTable = {
      MANYWORLDS_THIS_TARGET,
      &AngleCalculateProperties,
      &AngleCalculatePropertiesWithFrequencyAndDamping,
      &AngleCalculatePropertiesWithStiffnessAndDamping,
      &AngleCalculatePropertiesForLimit,
      &AngleCalculatePropertiesForMotor,
      &AngleWarmStart,
      &AngleSolveVelocity,
      &AngleSolvePosition,
      &AngleDeactivate,
      &AngleIsActive,
  };
  return &kTable;
}

}  // namespace HWY_NAMESPACE
}  // namespace manyworlds
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace manyworlds {
MANYWORLDS_EXPORT_KERNEL_TABLE(AngleKernels, GetAngleKernels)
}  // namespace manyworlds
#endif  // HWY_ONCE
