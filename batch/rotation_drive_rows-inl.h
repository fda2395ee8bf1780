// The rotation drives of swing-twist and six-DOF (spec 3): one motor or
// friction row (an angle part) about each axis of body 2's constraint frame,
// X = twist, Y and Z = swing, with the impulse ranges and biases of the hinge
// and slider drives (drive_and_limit_rows-inl.h).
//
//   axes a_i = columns of R(q2 c2)
//   q = (q1 c1)* (q2 c2)           body 2's frame relative to body 1's
//   target = clamp(target)         into the swing-twist limits (Jolt's
//                                  SetTargetOrientationCS clamps when the
//                                  target is set; clamping here at every setup
//                                  gives the same quaternion and keeps it right
//                                  when a world's limits change)
//   target' = target if q . target > 0 else -target   (shortest way round)
//   diff = q* target'              the rotation still to go, in body 2's frame
//   diff projected onto the axes with position drives (six-DOF): the twist
//     about that axis for one axis, diff (twist about the third axis)* for
//     two, diff for three; swing-twist uses diff
//   C_i = -2 diff.xyz_i            small-angle error (for large errors only
//                                  the sign is right, which is enough to move
//                                  the right way)
// Row i: friction bias 0, impulse dt [-f, f]; velocity bias -w_target_i,
// dt [min, max]; position C_i through the motor spring; both together.
// A position drive whose spring lost its stiffness (a per-world setting) is
// off in that world, as Jolt deactivates it. Drives take no position steps.

#if defined(MANYWORLDS_BATCH_ROTATION_DRIVE_ROWS_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef MANYWORLDS_BATCH_ROTATION_DRIVE_ROWS_INL_H_
#undef MANYWORLDS_BATCH_ROTATION_DRIVE_ROWS_INL_H_
#else
#define MANYWORLDS_BATCH_ROTATION_DRIVE_ROWS_INL_H_
#endif

#include "batch/constraint_block.h"
#include "batch/drive_and_limit_rows-inl.h"
#include "kernels/angle-inl.h"
#include "kernels/swing_twist_clamp-inl.h"

HWY_BEFORE_NAMESPACE();
namespace manyworlds {
namespace HWY_NAMESPACE {

// The part of `diff` about the axes in `axes` (bit i = axis i), spec 3 SixDOF.
HWY_INLINE Quat ProjectOntoAxes(const Quat& diff, unsigned axes) {
  switch (axes) {
    case 0b001: return TwistAboutAxis(diff, 0);
    case 0b010: return TwistAboutAxis(diff, 1);
    case 0b100: return TwistAboutAxis(diff, 2);
    // diff = swing * twist about the third axis => swing = diff twist*.
    case 0b011: return Mul(diff, Conjugate(TwistAboutAxis(diff, 2)));
    case 0b101: return Mul(diff, Conjugate(TwistAboutAxis(diff, 1)));
    case 0b110: return Mul(diff, Conjugate(TwistAboutAxis(diff, 0)));
    default: return diff;
  }
}

// The target orientation clamped into the limits: swing twist where a limit
// was hit, the target itself elsewhere.
HWY_INLINE Quat ClampedTargetOrientation(const SwingTwistConfig& config,
                                         const SwingTwistLimitLanes& limits,
                                         const Quat& target, std::size_t offset) {
  swing_twist::ClampedAxes axes;
  LaneVec ellipse_iterations;
  const swing_twist::SwingTwistPair clamped = swing_twist::Clamp(
      config, swing_twist::LoadAxisLimit(limits.twist, offset),
      swing_twist::LoadAxisLimit(limits.swing_y, offset),
      swing_twist::LoadAxisLimit(limits.swing_z, offset), swing_twist::Decompose(target), axes,
      ellipse_iterations);
  return Select(swing_twist::AnyClamped(axes), Mul(clamped.swing, clamped.twist), target);
}

// Setup of the drive rows from the bodies' current rotations.
inline void RotationDriveProperties(const ConstraintBlock& c, const SwingTwistGeometry& frames,
                                    const SwingTwistLimitLanes& limits,
                                    const StepScalars& step) {
  auto& drive = At<RotationDriveRows>(c.block, c.plan.rotation_drive_scratch_offset);
  const auto& kinds = c.plan.rotation_drives;
  bool any_position = false;
  for (DriveKind kind : kinds) any_position |= DriveUsesSpring(kind);
  const LaneVec dt = Splat(step.delta_time);
  LaneFlags no_spring[3];
  ForEachChunk([&](std::size_t offset) {
    const Quat frame1 = Mul(LoadQuat(c.bodies.body1->rotation, offset),
                            LoadQuat(frames.constraint_to_body1, offset));
    const Quat frame2 = Mul(LoadQuat(c.bodies.body2->rotation, offset),
                            LoadQuat(frames.constraint_to_body2, offset));
    const Mat33 axes = RotationMatrix(frame2);
    Vec3 error = ZeroVec3();
    if (any_position) {
      const Quat q = Mul(Conjugate(frame1), frame2);
      const Quat target = ClampedTargetOrientation(
          c.plan.swing_twist, limits, LoadQuat(drive.target_orientation, offset), offset);
      const Quat shortest =
          Select(hn::Gt(QuatDot(q, target), Zero()), target, swing_twist::NegateQuat(target));
      const Quat diff = ProjectOntoAxes(Mul(Conjugate(q), shortest),
                                        c.plan.rotation_position_axes);
      error = Scale(Vec3{diff.x, diff.y, diff.z}, Splat(-2.0f));
    }
    const LaneVec errors[3] = {error.x, error.y, error.z};
    for (int i = 0; i < 3; ++i) {
      if (kinds[i] == DriveKind::kNone) continue;
      AngularDriveRow& row = drive.rows[i];
      StoreVec3(Column(axes, i), row.geometry.axis, offset);
      StoreDriveRow(kinds[i], dt, row, no_spring[i], offset);
      Store(errors[i], row.geometry.error, offset);
    }
  });
  for (int i = 0; i < 3; ++i) {
    AngularDriveRow& row = drive.rows[i];
    if (kinds[i] == DriveKind::kNone) continue;
    CalculateDriveRowProperties(c.bodies, kinds[i], c.plan.rotation_drive_spring_modes[i],
                                step.delta_time, no_spring[i], row.geometry, row.part);
  }
}

inline void RotationDriveWarmStart(const ConstraintBlock& c, float warm_start_ratio) {
  auto& drive = At<RotationDriveRows>(c.block, c.plan.rotation_drive_scratch_offset);
  for (int i = 0; i < 3; ++i) {
    if (c.plan.rotation_drives[i] == DriveKind::kNone) continue;
    AngleWarmStart(c.bodies, drive.rows[i].part, warm_start_ratio);
  }
}

inline bool RotationDriveSolveVelocity(const ConstraintBlock& c) {
  auto& drive = At<RotationDriveRows>(c.block, c.plan.rotation_drive_scratch_offset);
  bool applied = false;
  for (int i = 0; i < 3; ++i) {
    if (c.plan.rotation_drives[i] == DriveKind::kNone) continue;
    applied |= AngleSolveVelocity(c.bodies, drive.rows[i].geometry, drive.rows[i].part);
  }
  return applied;
}

}  // namespace HWY_NAMESPACE
}  // namespace manyworlds
HWY_AFTER_NAMESPACE();

#endif  // MANYWORLDS_BATCH_ROTATION_DRIVE_ROWS_INL_H_
