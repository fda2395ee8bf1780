// What the constraints with motor / friction and limit rows share (spec 3:
// hinge, slider, six-DOF, path, the swing-twist and six-DOF rotation drives):
// the impulse ranges and velocity bias of a drive, and the impulse range of a
// limit, for angle and axis parts alike (the motor structs have the same
// fields); and the lever arms of an axis row from two anchors.
//
//   friction:              bias 0,            impulse in dt [-f, f]
//   velocity motor:        bias -target_v,    impulse in dt [min, max]
//   position motor:        bias 0, C through the motor spring, dt [min, max]
//   position and velocity: bias -target_v, C through the spring, dt [min, max]
//   limit:                 both ways if min == max, [0, inf) when the min
//                          limit is the one engaged (nearer), else (-inf, 0]

#if defined(MANYWORLDS_BATCH_DRIVE_AND_LIMIT_ROWS_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef MANYWORLDS_BATCH_DRIVE_AND_LIMIT_ROWS_INL_H_
#undef MANYWORLDS_BATCH_DRIVE_AND_LIMIT_ROWS_INL_H_
#else
#define MANYWORLDS_BATCH_DRIVE_AND_LIMIT_ROWS_INL_H_
#endif

#include <cfloat>
#include <cstddef>

#include "batch/plan.h"
#include "kernels/angle-inl.h"
#include "kernels/axis-inl.h"
#include "kernels/lane_math-inl.h"
#include "kernels/point.h"  // PointGeometry

HWY_BEFORE_NAMESPACE();
namespace manyworlds {
namespace HWY_NAMESPACE {

// Writes the drive's impulse range and velocity bias into motor.geometry and
// flags the lanes whose motor spring has no stiffness (a position drive is
// off there, as Jolt deactivates it; the scene's own setting has stiffness).
template <class MotorLanes>
HWY_INLINE void StoreDriveRow(DriveKind drive, LaneVec dt, MotorLanes& motor,
                              LaneFlags& no_spring, std::size_t offset) {
  LaneVec min_lambda, max_lambda;
  if (drive == DriveKind::kFriction) {
    max_lambda = hn::Mul(dt, Load(motor.max_friction, offset));
    min_lambda = hn::Neg(max_lambda);
  } else {
    min_lambda = hn::Mul(dt, Load(motor.min_force_limit, offset));
    max_lambda = hn::Mul(dt, Load(motor.max_force_limit, offset));
  }
  Store(min_lambda, motor.geometry.min_lambda, offset);
  Store(max_lambda, motor.geometry.max_lambda, offset);
  const bool velocity_bias =
      drive == DriveKind::kVelocity || drive == DriveKind::kPositionAndVelocity;
  Store(velocity_bias ? hn::Neg(Load(motor.target_velocity, offset)) : Zero(),
        motor.geometry.bias, offset);
  StoreFlags(hn::Le(Load(motor.geometry.spring.frequency_or_stiffness, offset), Zero()),
             no_spring, offset);
}

// Friction and velocity drives are hard rows; position drives go through the
// motor spring (CalculatePropertiesForMotor).
inline bool DriveUsesSpring(DriveKind drive) {
  return drive == DriveKind::kPosition || drive == DriveKind::kPositionAndVelocity;
}

// A drive row's properties once StoreDriveRow has written its range and bias
// and the caller its axis and error: hard for friction and velocity drives,
// through the motor spring for position drives, and off in the worlds where
// a position drive's spring has no stiffness. For axis (linear) and angle
// (angular) rows alike.
HWY_INLINE void CalculateDriveRowProperties(const BodyPair& bodies, DriveKind drive,
                                            SpringMode mode, float delta_time,
                                            const LaneFlags& no_spring,
                                            const AxisGeometry& geometry, AxisLanes& part) {
  if (!DriveUsesSpring(drive)) return AxisCalculateProperties(bodies, geometry, part);
  AxisCalculatePropertiesForMotor(bodies, geometry, part, delta_time, mode);
  if (drive == DriveKind::kPosition) AxisDeactivate(part, no_spring);
}
HWY_INLINE void CalculateDriveRowProperties(const BodyPair& bodies, DriveKind drive,
                                            SpringMode mode, float delta_time,
                                            const LaneFlags& no_spring,
                                            const AngleGeometry& geometry, AngleLanes& part) {
  if (!DriveUsesSpring(drive)) return AngleCalculateProperties(bodies, geometry, part);
  AngleCalculatePropertiesForMotor(bodies, geometry, part, delta_time, mode);
  if (drive == DriveKind::kPosition) AngleDeactivate(part, no_spring);
}

// The lever arms of a row between body 1's anchor and body 2's at the
// current poses: r1 = R1 r1_local, r2 = R2 r2_local, r1 + u = x2 + r2 - x1
// (body 1's arm reaching body 2's anchor) and u = p2 - p1.
struct AnchorLeverArms {
  Vec3 r1, r2, r1_plus_u, separation;
};
HWY_INLINE AnchorLeverArms AnchorLeverArmsOfChunk(const BodyPair& bodies,
                                                  const PointGeometry& anchors,
                                                  std::size_t offset) {
  AnchorLeverArms arms;
  arms.r1 = Rotate(LoadQuat(bodies.body1->rotation, offset), LoadVec3(anchors.r1_local, offset));
  arms.r2 = Rotate(LoadQuat(bodies.body2->rotation, offset), LoadVec3(anchors.r2_local, offset));
  arms.r1_plus_u = Sub(Add(LoadVec3(bodies.body2->position, offset), arms.r2),
                       LoadVec3(bodies.body1->position, offset));
  arms.separation = Sub(arms.r1_plus_u, arms.r1);
  return arms;
}

// An axis row's lever arms and axis, copied from where its constraint keeps
// them for this step.
HWY_INLINE void StoreAxisRow(const Vec3Lanes& r1_plus_u, const Vec3Lanes& r2,
                             const Vec3Lanes& axis, AxisGeometry& row, std::size_t offset) {
  StoreVec3(LoadVec3(r1_plus_u, offset), row.r1_plus_u, offset);
  StoreVec3(LoadVec3(r2, offset), row.r2, offset);
  StoreVec3(LoadVec3(axis, offset), row.axis, offset);
}

// Writes a limit row's impulse range: `min_engaged` where the min limit is
// the one that applies, both ways where min == max; and a row's zero
// velocity bias (a limit has none; the row is scratch, rewritten at every
// setup).
template <class Geometry>
HWY_INLINE void StoreLimitImpulseRange(LaneMask min_engaged, LaneMask both_ways,
                                       Geometry& geometry, std::size_t offset) {
  if constexpr (requires { geometry.bias; }) Store(Zero(), geometry.bias, offset);
  const LaneVec unbounded = Splat(FLT_MAX);
  Store(hn::IfThenElse(hn::Or(both_ways, hn::Not(min_engaged)), hn::Neg(unbounded), Zero()),
        geometry.min_lambda, offset);
  Store(hn::IfThenElse(hn::Or(both_ways, min_engaged), unbounded, Zero()), geometry.max_lambda,
        offset);
}

}  // namespace HWY_NAMESPACE
}  // namespace manyworlds
HWY_AFTER_NAMESPACE();

#endif  // MANYWORLDS_BATCH_DRIVE_AND_LIMIT_ROWS_INL_H_
