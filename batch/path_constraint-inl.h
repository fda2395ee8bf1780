// Path constraint across worlds (spec 3, Path): body 2's attachment point
// slides along a Hermite path fixed to body 1 (kernels/hermite_path-inl.h),
// the same path in every world.
//
//   path space in world: rotation q1 qp1, origin x1 + q1 tp1
//   attachment (body 2): position a = x2 + q2 ta2, frame q2 qa2
//   fraction = closest point of the path to a (path space), and the path's
//   point p, tangent t, normal n, binormal b there (in world)
//   r1 = p - x1, r2 = a - x2, u = a - p
// Parts in solve order:
//   axis (motor on t): friction, velocity (bias -v), position (C = fraction -
//     target, wrapped into +-half the length for a looping path), both;
//   dual axis on (n, b) with lever arms r1 + u, r2;
//   axis (end limit on t) where an open path's fraction is <= 0 (impulse
//     >= 0) or >= its end (impulse <= 0), off (impulse wiped) elsewhere;
//   rotation: hinge rotation keeping t / n / b and body 2's X / Z / Y axes
//     parallel, or rotation Euler towards r0^-1 = qa2 (qp1 q_frame)* (to the
//     path) or q2* q1 of the start (fully constrained). Jolt's rotation rows
//     ignore the path's curvature; the position phase takes up the rest.
// Position: everything recomputed at the current poses (which may switch the
// end limit off), then one step each of the dual axis on u, the end limit on
// u . t, and the rotation part.

#if defined(MANYWORLDS_BATCH_PATH_CONSTRAINT_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef MANYWORLDS_BATCH_PATH_CONSTRAINT_INL_H_
#undef MANYWORLDS_BATCH_PATH_CONSTRAINT_INL_H_
#else
#define MANYWORLDS_BATCH_PATH_CONSTRAINT_INL_H_
#endif

#include <cfloat>

#include "batch/constraint_block.h"
#include "batch/drive_and_limit_rows-inl.h"
#include "kernels/axis-inl.h"
#include "kernels/dual_axis-inl.h"
#include "kernels/hermite_path-inl.h"
#include "kernels/hinge_rotation-inl.h"
#include "kernels/rotation_euler-inl.h"

HWY_BEFORE_NAMESPACE();
namespace manyworlds {
namespace HWY_NAMESPACE {

// An axis row's lever arms and axis from the path geometry of this step.
HWY_INLINE void PathAxisRow(const PathConstraintLanes& s, AxisGeometry& row,
                            std::size_t offset) {
  StoreAxisRow(s.dual_geometry.r1_plus_u, s.dual_geometry.r2, s.tangent, row, offset);
}

// Jolt's PathConstraint::CalculateConstraintProperties: the closest point,
// the path frame, every part's properties, the end limit's activation and
// the motor row, at the current poses.
inline void PathConstraintProperties(const ConstraintBlock& c, const StepScalars& step) {
  auto& s = c.Main<PathConstraintLanes>();
  const HermitePath path = c.plan.Path();
  const PathRotation rotation = c.plan.path_rotation;
  const float max_fraction = path.max_fraction();
  LaneFlags limit_off;
  ForEachChunk([&](std::size_t offset) {
    const Quat q1 = LoadQuat(c.bodies.body1->rotation, offset);
    const Quat q2 = LoadQuat(c.bodies.body2->rotation, offset);
    const Vec3 x1 = LoadVec3(c.bodies.body1->position, offset);
    const Vec3 x2 = LoadVec3(c.bodies.body2->position, offset);
    const Quat path_to_world = Mul(q1, LoadQuat(s.path_to_body1_rotation, offset));
    const Vec3 path_origin = Add(x1, Rotate(q1, LoadVec3(s.path_to_body1_position, offset)));
    const Vec3 attachment = Add(x2, Rotate(q2, LoadVec3(s.attachment_to_body2_position, offset)));
    const LaneVec fraction = hermite::ClosestPoint(
        path, InverseRotate(path_to_world, Sub(attachment, path_origin)));
    const hermite::PathFrame frame = hermite::PointOnPath(path, fraction);
    const Vec3 path_point = Add(path_origin, Rotate(path_to_world, frame.position));
    const Vec3 tangent = Rotate(path_to_world, frame.tangent);
    const Vec3 normal = Rotate(path_to_world, frame.normal);
    const Vec3 binormal = Rotate(path_to_world, frame.binormal);
    Store(fraction, s.fraction, offset);
    StoreVec3(Sub(attachment, path_point), s.separation, offset);
    StoreVec3(tangent, s.tangent, offset);
    StoreVec3(Sub(attachment, x1), s.dual_geometry.r1_plus_u, offset);  // r1 + u
    StoreVec3(Sub(attachment, x2), s.dual_geometry.r2, offset);
    StoreVec3(normal, s.dual_geometry.n1, offset);
    StoreVec3(binormal, s.dual_geometry.n2, offset);

    // End limit: open paths only, at or beyond either end.
    const LaneMask at_start = hn::Le(fraction, Zero());
    const LaneMask at_end = hn::Ge(fraction, Splat(max_fraction));
    PathAxisRow(s, s.limit_geometry, offset);
    StoreLimitImpulseRange(at_start, NoLanes(), s.limit_geometry, offset);
    const LaneMask limit_on = path.looping ? NoLanes() : hn::Or(at_start, at_end);
    StoreFlags(hn::Not(limit_on), limit_off, offset);

    const Quat attachment_frame = Mul(q2, LoadQuat(s.attachment_to_body2_rotation, offset));
    switch (rotation) {
      case PathRotation::kFree:
      case PathRotation::kFullyConstrained: break;
      case PathRotation::kConstrainAroundTangent:
        StoreVec3(tangent, s.hinge_geometry.hinge_axis1, offset);
        StoreVec3(Rotate(attachment_frame, Vec3{Splat(1.0f), Zero(), Zero()}),
                  s.hinge_geometry.hinge_axis2, offset);
        break;
      case PathRotation::kConstrainAroundNormal:
        StoreVec3(normal, s.hinge_geometry.hinge_axis1, offset);
        StoreVec3(Rotate(attachment_frame, Vec3{Zero(), Zero(), Splat(1.0f)}),
                  s.hinge_geometry.hinge_axis2, offset);
        break;
      case PathRotation::kConstrainAroundBinormal:
        StoreVec3(binormal, s.hinge_geometry.hinge_axis1, offset);
        StoreVec3(Rotate(attachment_frame, Vec3{Zero(), Splat(1.0f), Zero()}),
                  s.hinge_geometry.hinge_axis2, offset);
        break;
      case PathRotation::kConstrainToPath: {
        // r0^-1 = qa2 (qp1 q_frame)*, q_frame = (t, b, n) in path space.
        Mat33 m;
        const Vec3 columns[3] = {frame.tangent, frame.binormal, frame.normal};
        for (int j = 0; j < 3; ++j) {
          m.m[0][j] = columns[j].x;
          m.m[1][j] = columns[j].y;
          m.m[2][j] = columns[j].z;
        }
        const Quat path_frame =
            Mul(LoadQuat(s.path_to_body1_rotation, offset), QuatFromRotationMatrix(m));
        StoreQuat(Mul(LoadQuat(s.attachment_to_body2_rotation, offset), Conjugate(path_frame)),
                  s.inv_initial_orientation, offset);
        break;
      }
    }
  });
  DualAxisCalculateProperties(c.bodies, s.dual_geometry, s.dual);
  AxisCalculateProperties(c.bodies, s.limit_geometry, s.limit);
  AxisDeactivate(s.limit, limit_off);
  switch (rotation) {
    case PathRotation::kFree: break;
    case PathRotation::kConstrainAroundTangent:
    case PathRotation::kConstrainAroundNormal:
    case PathRotation::kConstrainAroundBinormal:
      HingeRotationCalculateProperties(c.bodies, s.hinge_geometry, s.hinge);
      break;
    case PathRotation::kConstrainToPath:
    case PathRotation::kFullyConstrained:
      RotationEulerCalculateProperties(c.bodies, s.rotation);
      break;
  }

  if (!c.plan.has_motor()) return;
  auto& motor = c.Motor<LinearMotorRow>();
  const DriveKind drive = c.plan.drive;
  const LaneVec dt = Splat(step.delta_time);
  LaneFlags no_spring;
  ForEachChunk([&](std::size_t offset) {
    PathAxisRow(s, motor.geometry, offset);
    StoreDriveRow(drive, dt, motor, no_spring, offset);
    LaneVec error = hn::Sub(Load(s.fraction, offset), Load(motor.target_position, offset));
    if (path.looping) {
      // fmod into (-L, L), then the shorter way round: into [-L/2, L/2].
      const LaneVec length = Splat(max_fraction), half = Splat(0.5f * max_fraction);
      error = hn::Sub(error, hn::Mul(length, hn::Trunc(hn::Div(error, length))));
      error = hn::IfThenElse(hn::Gt(error, half), hn::Sub(error, length),
                             hn::IfThenElse(hn::Lt(error, hn::Neg(half)), hn::Add(error, length),
                                            error));
    }
    Store(error, motor.geometry.error, offset);
  });
  CalculateDriveRowProperties(c.bodies, drive, c.plan.motor_spring_mode, step.delta_time,
                              no_spring, motor.geometry, motor.part);
}

inline void PathConstraintSetup(const ConstraintBlock& c, const StepScalars& step) {
  PathConstraintProperties(c, step);
}

inline void PathConstraintWarmStart(const ConstraintBlock& c, const StepScalars& step) {
  auto& s = c.Main<PathConstraintLanes>();
  const float ratio = step.warm_start_ratio;
  if (c.plan.has_motor()) {
    auto& motor = c.Motor<LinearMotorRow>();
    AxisWarmStart(c.bodies, motor.geometry, motor.part, ratio);
  }
  DualAxisWarmStart(c.bodies, s.dual_geometry, s.dual, ratio);
  AxisWarmStart(c.bodies, s.limit_geometry, s.limit, ratio);
  switch (c.plan.path_rotation) {
    case PathRotation::kFree: break;
    case PathRotation::kConstrainAroundTangent:
    case PathRotation::kConstrainAroundNormal:
    case PathRotation::kConstrainAroundBinormal:
      HingeRotationWarmStart(c.bodies, s.hinge, ratio);
      break;
    case PathRotation::kConstrainToPath:
    case PathRotation::kFullyConstrained:
      RotationEulerWarmStart(c.bodies, s.rotation, ratio);
      break;
  }
}

inline bool PathConstraintSolveVelocity(const ConstraintBlock& c) {
  auto& s = c.Main<PathConstraintLanes>();
  bool applied = false;
  if (c.plan.has_motor()) {
    auto& motor = c.Motor<LinearMotorRow>();
    applied |= AxisSolveVelocity(c.bodies, motor.geometry, motor.part);
  }
  applied |= DualAxisSolveVelocity(c.bodies, s.dual_geometry, s.dual);
  if (!c.plan.path_looping) applied |= AxisSolveVelocity(c.bodies, s.limit_geometry, s.limit);
  switch (c.plan.path_rotation) {
    case PathRotation::kFree: break;
    case PathRotation::kConstrainAroundTangent:
    case PathRotation::kConstrainAroundNormal:
    case PathRotation::kConstrainAroundBinormal:
      applied |= HingeRotationSolveVelocity(c.bodies, s.hinge);
      break;
    case PathRotation::kConstrainToPath:
    case PathRotation::kFullyConstrained:
      applied |= RotationEulerSolveVelocity(c.bodies, s.rotation);
      break;
  }
  return applied;
}

inline bool PathConstraintSolvePosition(const ConstraintBlock& c, const StepScalars& step) {
  auto& s = c.Main<PathConstraintLanes>();
  PathConstraintProperties(c, step);
  bool applied =
      DualAxisSolvePosition(c.bodies, s.dual_geometry, s.separation, s.dual, step.baumgarte);
  if (!c.plan.path_looping) {
    // C = u . t where the end limit is on; zero (no step) where it is off.
    LaneFlags on;
    AxisIsActive(s.limit, on);
    ForEachChunk([&](std::size_t offset) {
      const LaneVec error = Dot(LoadVec3(s.separation, offset), LoadVec3(s.tangent, offset));
      Store(hn::IfThenElseZero(LoadFlags(on, offset), error), s.limit_geometry.error, offset);
    });
    applied |= AxisSolvePosition(c.bodies, s.limit_geometry, s.limit, step.baumgarte);
  }
  switch (c.plan.path_rotation) {
    case PathRotation::kFree: break;
    case PathRotation::kConstrainAroundTangent:
    case PathRotation::kConstrainAroundNormal:
    case PathRotation::kConstrainAroundBinormal:
      applied |= HingeRotationSolvePosition(c.bodies, s.hinge, step.baumgarte);
      break;
    case PathRotation::kConstrainToPath:
    case PathRotation::kFullyConstrained:
      applied |= RotationEulerSolvePosition(c.bodies, s.inv_initial_orientation, s.rotation,
                                            step.baumgarte);
      break;
  }
  return applied;
}

}  // namespace HWY_NAMESPACE
}  // namespace manyworlds
HWY_AFTER_NAMESPACE();

#endif  // MANYWORLDS_BATCH_PATH_CONSTRAINT_INL_H_
