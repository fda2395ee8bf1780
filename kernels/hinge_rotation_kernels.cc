// Compiles the hinge-rotation kernels once per Highway target into a
// HingeRotationKernels table (see kernels/kernel_table.h).

#include "kernels/hinge_rotation.h"

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "kernels/hinge_rotation_kernels.cc"
#include "hwy/foreach_target.h"  // IWYU pragma: keep

#include "hwy/highway.h"
#include "kernels/hinge_rotation-inl.h"

HWY_BEFORE_NAMESPACE();
namespace manyworlds {
namespace HWY_NAMESPACE {

const HingeRotationKernels* GetHingeRotationKernels() {
  static const HingeRotationKernels kTable = {
      MANYWORLDS_THIS_TARGET,
      &HingeRotationCalculateProperties,
      &HingeRotationWarmStart,
      &HingeRotationSolveVelocity,
      &HingeRotationSolvePosition,
      &HingeRotationDeactivate,
      &HingeRotationIsActive,
  };
  return &kTable;
}

}  // namespace HWY_NAMESPACE
}  // namespace manyworlds
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace manyworlds {
MANYWORLDS_EXPORT_KERNEL_TABLE(HingeRotationKernels, GetHingeRotationKernels)
}  // namespace manyworlds
#endif  // HWY_ONCE
