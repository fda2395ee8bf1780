// Compiles the rotation-quaternion kernels once per Highway target into a
// RotationQuatKernels table (see kernels/kernel_table.h).

#include "kernels/rotation_quat.h"

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "kernels/rotation_quat_kernels.cc"
#include "hwy/foreach_target.h"  // IWYU pragma: keep

#include "hwy/highway.h"
#include "kernels/rotation_quat-inl.h"

HWY_BEFORE_NAMESPACE();
namespace manyworlds {
namespace HWY_NAMESPACE {

const RotationQuatKernels* GetRotationQuatKernels() {
  static const RotationQuatKernels kTable = {
      MANYWORLDS_THIS_TARGET, &RotationQuatCalculateProperties, &RotationQuatWarmStart,
      &RotationQuatSolveVelocity, &RotationQuatSolvePosition, &RotationQuatDeactivate,
      &RotationQuatIsActive,
  };
  return &kTable;
}

}  // namespace HWY_NAMESPACE
}  // namespace manyworlds
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace manyworlds {
MANYWORLDS_EXPORT_KERNEL_TABLE(RotationQuatKernels, GetRotationQuatKernels)
}  // namespace manyworlds
#endif  // HWY_ONCE
