// Compiles the rotation-Euler kernels once per Highway target into a
// RotationEulerKernels table (see kernels/kernel_table.h).

#include "kernels/rotation_euler.h"

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "kernels/rotation_euler_kernels.cc"
#include "hwy/foreach_target.h"  // IWYU pragma: keep

#include "hwy/highway.h"
#include "kernels/rotation_euler-inl.h"

HWY_BEFORE_NAMESPACE();
namespace manyworlds {
namespace HWY_NAMESPACE {

const RotationEulerKernels* GetRotationEulerKernels() {
  static const RotationEulerKernels kTable = {
      MANYWORLDS_THIS_TARGET,
      &RotationEulerCalculateProperties,
      &RotationEulerWarmStart,
      &RotationEulerSolveVelocity,
      &RotationEulerSolvePosition,
      &RotationEulerDeactivate,
      &RotationEulerIsActive,
      &RotationEulerInverseInitialOrientationFromBodies,
      &RotationEulerInverseInitialOrientationFromFramesXY,
      &RotationEulerInverseInitialOrientationFromFramesXZ,
      &RotationEulerInverseInitialOrientationWorldToLocal,
  };
  return &kTable;
}

}  // namespace HWY_NAMESPACE
}  // namespace manyworlds
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace manyworlds {
MANYWORLDS_EXPORT_KERNEL_TABLE(RotationEulerKernels, GetRotationEulerKernels)
}  // namespace manyworlds
#endif  // HWY_ONCE
