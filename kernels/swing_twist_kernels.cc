// Compiles the swing-twist kernels once per Highway target into a
// SwingTwistKernels table (see kernels/kernel_table.h), with the
// decomposition, clamp and limit set-up exported for tests.

#include "kernels/swing_twist.h"

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "kernels/swing_twist_kernels.cc"
#include "hwy/foreach_target.h"  // IWYU pragma: keep

#include "hwy/highway.h"
#include "kernels/swing_twist-inl.h"

HWY_BEFORE_NAMESPACE();
namespace manyworlds {
namespace HWY_NAMESPACE {
namespace {

void SwingTwistSetLimits(const SwingTwistConfig& config, const SwingTwistLimitAngles& angles,
                         SwingTwistLimitLanes& limits) {
  ForEachChunk([&](std::size_t offset) {
    swing_twist::SetAxisLimit(config.twist, Load(angles.twist_min, offset),
                              Load(angles.twist_max, offset), limits.twist, offset);
    swing_twist::SetAxisLimit(config.swing_y, Load(angles.swing_y_min, offset),
                              Load(angles.swing_y_max, offset), limits.swing_y, offset);
    swing_twist::SetAxisLimit(config.swing_z, Load(angles.swing_z_min, offset),
                              Load(angles.swing_z_max, offset), limits.swing_z, offset);
  });
}

void SwingTwistDecompose(const QuatLanes& q, QuatLanes& swing, QuatLanes& twist) {
  ForEachChunk([&](std::size_t offset) {
    const swing_twist::SwingTwistPair pair = swing_twist::Decompose(LoadQuat(q, offset));
    StoreQuat(pair.swing, swing, offset);
    StoreQuat(pair.twist, twist, offset);
  });
}

void SwingTwistClamp(const SwingTwistConfig& config, const SwingTwistLimitLanes& limits,
                     const QuatLanes& swing, const QuatLanes& twist,
                     SwingTwistClampLanes& out) {
  ForEachChunk([&](std::size_t offset) {
    swing_twist::ClampedAxes axes;
    LaneVec iterations;
    const swing_twist::SwingTwistPair clamped = swing_twist::Clamp(
        config, swing_twist::LoadAxisLimit(limits.twist, offset),
        swing_twist::LoadAxisLimit(limits.swing_y, offset),
        swing_twist::LoadAxisLimit(limits.swing_z, offset),
        {LoadQuat(swing, offset), LoadQuat(twist, offset)}, axes, iterations);
    StoreQuat(clamped.swing, out.swing, offset);
    StoreQuat(clamped.twist, out.twist, offset);
    StoreFlags(axes.twist_min, out.twist_min, offset);
    StoreFlags(axes.twist_max, out.twist_max, offset);
    StoreFlags(axes.swing_y_min, out.swing_y_min, offset);
    StoreFlags(axes.swing_y_max, out.swing_y_max, offset);
    StoreFlags(axes.swing_z_min, out.swing_z_min, offset);
    StoreFlags(axes.swing_z_max, out.swing_z_max, offset);
    Store(iterations, out.ellipse_iterations, offset);
  });
}

}  // namespace

const SwingTwistKernels* GetSwingTwistKernels() {
  static const SwingTwistKernels kTable = {
      MANYWORLDS_THIS_TARGET,
      &SwingTwistSetLimits,
      &SwingTwistDecompose,
      &SwingTwistClamp,
      &SwingTwistCalculateProperties,
      &SwingTwistWarmStart,
      &SwingTwistSolveVelocity,
      &SwingTwistSolvePosition,
      &SwingTwistDeactivate,
      &SwingTwistIsActive,
  };
  return &kTable;
}

}  // namespace HWY_NAMESPACE
}  // namespace manyworlds
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace manyworlds {
MANYWORLDS_EXPORT_KERNEL_TABLE(SwingTwistKernels, GetSwingTwistKernels)
}  // namespace manyworlds
#endif  // HWY_ONCE
