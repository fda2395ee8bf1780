// SwingTwistConstraintPart across worlds: limits the rotation of body 2's
// constraint frame relative to body 1's by a swing cone or pyramid and a
// twist range, with three angle rows (swing Y, swing Z, twist). Spec 2.12;
// the ragdoll joint, swing-twist and six-DOF constraints.
//
//   q = (q1 c1)* (q2 c2) = swing twist   (swing_twist_clamp-inl.h)
//   F = (q1 c1) swing: the constraint frame after the UNCLAMPED swing, world
//
// Rows (each an angle part with bias 0, J = [0, -a, 0, a], spec 2.8):
//   swing Y or Z locked: swing Y row on F Y, swing Z row on F Z. A locked
//       axis is always on; the other one only where the 1-DOF clamp hit a
//       limit, its axis negated at the min side so the impulse range is
//       always (-inf, 0].
//   neither locked, not both free: where the 2-DOF clamp moved the swing, one
//       row (swing Y) on a = normalize(desired x current), current = F X,
//       desired = (q1 c1) swing_clamped X; a zero cross product switches it
//       off. Swing Z is off.
//   twist: locked => on, axis F X; limited => on where clamped, negated at
//       the min side; free => off.
// Velocity step, in the order swing Y, swing Z, twist: the angle part's
//   clamped solve with L in (-FLT_MAX, 0], or (-FLT_MAX, FLT_MAX) where that
//   axis' sin_min == sin_max (locked, or a one-value range).
// Position step: decompose and clamp again from the current rotations; where
//   any limit is hit, one full 3-DOF rotation-Euler Baumgarte step (inertia
//   at the current rotations, spec 2.6) towards the clamped orientation,
//   r0^-1 = c2 (c1 swing_clamped twist_clamped)*.
//
// The configuration (locked / limited / free per axis, cone or pyramid) is
// the same in every world: scalar control flow. Which limit a lane hits is a
// per-lane mask. A row the configuration can never switch on (twist free;
// swing Z in the 2-DOF case; both swing rows when both are free) is skipped
// by warm start and velocity solve: its impulse and effective mass are zero,
// so it would apply nothing.
// Off rows hold zero axis, I^-1 a, effective mass and impulse, so that every
// lane stays finite whatever the verb.

#if defined(MANYWORLDS_KERNELS_SWING_TWIST_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef MANYWORLDS_KERNELS_SWING_TWIST_INL_H_
#undef MANYWORLDS_KERNELS_SWING_TWIST_INL_H_
#else
#define MANYWORLDS_KERNELS_SWING_TWIST_INL_H_
#endif

#include <cfloat>
#include <cstddef>

#include "kernels/angle-inl.h"
#include "kernels/body_access-inl.h"
#include "kernels/lane_math-inl.h"
#include "kernels/rotation_euler-inl.h"
#include "kernels/swing_twist.h"
#include "kernels/swing_twist_clamp-inl.h"

HWY_BEFORE_NAMESPACE();
namespace manyworlds {
namespace HWY_NAMESPACE {
namespace swing_twist {

// Which rows the configuration can switch on at all.
struct RowsInUse {
  bool swing_y, swing_z, twist;
};

HWY_INLINE RowsInUse RowsInUseOf(const SwingTwistConfig& config) {
  const bool y_locked = config.swing_y == AxisLimitKind::kLocked;
  const bool z_locked = config.swing_z == AxisLimitKind::kLocked;
  const bool both_free =
      config.swing_y == AxisLimitKind::kFree && config.swing_z == AxisLimitKind::kFree;
  return {!both_free, y_locked || z_locked, config.twist != AxisLimitKind::kFree};
}

// q1 c1 (constraint space to world) and q = (q1 c1)* (q2 c2), from the
// bodies' current rotations.
HWY_INLINE void ConstraintRotation(const BodyPair& bodies, const SwingTwistGeometry& geometry,
                                   std::size_t offset, Quat& constraint_to_world,
                                   Quat& rotation) {
  constraint_to_world = Mul(LoadQuat(bodies.body1->rotation, offset),
                            LoadQuat(geometry.constraint_to_body1, offset));
  const Quat body2_frame = Mul(LoadQuat(bodies.body2->rotation, offset),
                               LoadQuat(geometry.constraint_to_body2, offset));
  rotation = Mul(Conjugate(constraint_to_world), body2_frame);
}

// X axis of the unit quaternion's frame: the first column of its matrix.
HWY_INLINE Vec3 RotatedAxisX(const Quat& q) {
  const LaneVec two = Splat(2.0f);
  return {hn::NegMulAdd(two, hn::MulAdd(q.y, q.y, hn::Mul(q.z, q.z)), Splat(1.0f)),
          hn::Mul(two, hn::MulAdd(q.x, q.y, hn::Mul(q.w, q.z))),
          hn::Mul(two, hn::MulSub(q.x, q.z, hn::Mul(q.w, q.y)))};
}

// Upper impulse bound of an axis: FLT_MAX where sin_min == sin_max, else 0.
HWY_INLINE LaneVec MaxLambda(const AxisLimit& limit) {
  return hn::IfThenElseZero(hn::Eq(limit.sin_min, limit.sin_max), Splat(FLT_MAX));
}

// A row switched off in every lane of the chunk: every cached value zero
// (a hard row's spring state too), as a row that is on writes them all.
HWY_INLINE void SwitchOffRow(SwingTwistRowLanes& row, LaneArray& total_lambda,
                             std::size_t offset) {
  StoreVec3(ZeroVec3(), row.axis, offset);
  Store(Zero(), row.max_lambda, offset);
  StoreVec3(ZeroVec3(), row.properties.inv_i1_axis, offset);
  StoreVec3(ZeroVec3(), row.properties.inv_i2_axis, offset);
  Store(Zero(), row.properties.effective_mass, offset);
  Store(Zero(), row.properties.spring.softness, offset);
  Store(Zero(), row.properties.spring.bias, offset);
  Store(Zero(), total_lambda, offset);
}

// A row on `axis` in the lanes of `on` (the angle part may still switch a
// lane off where K == 0); off lanes get the SwitchOffRow state.
HWY_INLINE void CalculateRow(const BodyPair& bodies, const Vec3& axis, LaneMask on,
                             LaneVec max_lambda, SwingTwistRowLanes& row,
                             LaneArray& total_lambda, std::size_t offset) {
  if (!AnyLane(on)) return SwitchOffRow(row, total_lambda, offset);
  const LaneMask off = hn::Not(on);
  StoreVec3(Select(on, axis, ZeroVec3()), row.axis, offset);
  Store(max_lambda, row.max_lambda, offset);
  AngleCalculatePropertiesChunk(bodies, axis, Zero(), row.properties, total_lambda, offset);
  AngleDeactivateChunk(off, row.properties, total_lambda, offset);
  ClearWhere(off, row.properties.inv_i1_axis, offset);
  ClearWhere(off, row.properties.inv_i2_axis, offset);
}

// The limits of one chunk, clamped decomposition of the current rotation.
struct ClampedRotation {
  Quat constraint_to_world;
  SwingTwistPair decomposed;
  SwingTwistPair clamped;
  ClampedAxes axes;
};

HWY_INLINE ClampedRotation DecomposeAndClamp(const BodyPair& bodies,
                                             const SwingTwistConfig& config,
                                             const SwingTwistGeometry& geometry,
                                             const SwingTwistLimitLanes& limits,
                                             std::size_t offset) {
  ClampedRotation result;
  Quat rotation;
  ConstraintRotation(bodies, geometry, offset, result.constraint_to_world, rotation);
  result.decomposed = Decompose(rotation);
  LaneVec ellipse_iterations;
  result.clamped = Clamp(config, LoadAxisLimit(limits.twist, offset),
                         LoadAxisLimit(limits.swing_y, offset),
                         LoadAxisLimit(limits.swing_z, offset), result.decomposed, result.axes,
                         ellipse_iterations);
  return result;
}

// Swing Y and Z rows of one chunk when one or both swing axes are locked.
HWY_INLINE void CalculateOneDofSwingRows(const BodyPair& bodies, const SwingTwistConfig& config,
                                         const Mat33& frame, const ClampedAxes& clamped,
                                         const AxisLimit& y_limit, const AxisLimit& z_limit,
                                         SwingTwistLanes& part, std::size_t offset) {
  const bool y_locked = config.swing_y == AxisLimitKind::kLocked;
  const bool z_locked = config.swing_z == AxisLimitKind::kLocked;
  Vec3 y_axis = Column(frame, 1), z_axis = Column(frame, 2);
  LaneMask y_on = AllLanes(), z_on = AllLanes();
  if (!y_locked) {
    y_on = hn::Or(clamped.swing_y_min, clamped.swing_y_max);
    y_axis = Select(clamped.swing_y_min, Neg(y_axis), y_axis);
  }
  if (!z_locked) {
    z_on = hn::Or(clamped.swing_z_min, clamped.swing_z_max);
    z_axis = Select(clamped.swing_z_min, Neg(z_axis), z_axis);
  }
  CalculateRow(bodies, y_axis, y_on, MaxLambda(y_limit), part.swing_y,
               part.persistent.swing_y_lambda, offset);
  CalculateRow(bodies, z_axis, z_on, MaxLambda(z_limit), part.swing_z,
               part.persistent.swing_z_lambda, offset);
}

// The single 2-DOF swing row (on the swing Y row) of one chunk.
HWY_INLINE void CalculateTwoDofSwingRow(const BodyPair& bodies, const ClampedRotation& r,
                                        const Vec3& current, const AxisLimit& y_limit,
                                        SwingTwistLanes& part, std::size_t offset) {
  const Vec3 desired = RotatedAxisX(Mul(r.constraint_to_world, r.clamped.swing));
  const Vec3 cross = Cross(desired, current);
  const LaneVec length = hn::Sqrt(LengthSquared(cross));
  const LaneMask on = hn::And(r.axes.swing_y_min, hn::Ne(length, Zero()));
  const LaneVec inv_length = hn::Div(Splat(1.0f), hn::IfThenElse(on, length, Splat(1.0f)));
  CalculateRow(bodies, Scale(cross, inv_length), on, MaxLambda(y_limit), part.swing_y,
               part.persistent.swing_y_lambda, offset);
  SwitchOffRow(part.swing_z, part.persistent.swing_z_lambda, offset);
}

}  // namespace swing_twist

inline void SwingTwistCalculateProperties(const BodyPair& bodies, const SwingTwistConfig& config,
                                          const SwingTwistGeometry& geometry,
                                          const SwingTwistLimitLanes& limits,
                                          SwingTwistLanes& part) {
  namespace st = swing_twist;
  const bool y_locked = config.swing_y == AxisLimitKind::kLocked;
  const bool z_locked = config.swing_z == AxisLimitKind::kLocked;
  const st::RowsInUse rows = st::RowsInUseOf(config);
  ForEachChunk([&](std::size_t offset) {
    const st::ClampedRotation r = st::DecomposeAndClamp(bodies, config, geometry, limits, offset);
    const st::AxisLimit y_limit = st::LoadAxisLimit(limits.swing_y, offset);
    const st::AxisLimit z_limit = st::LoadAxisLimit(limits.swing_z, offset);
    const st::AxisLimit twist_limit = st::LoadAxisLimit(limits.twist, offset);
    // World axes of the constraint frame after the unclamped swing.
    const Mat33 frame = RotationMatrix(Mul(r.constraint_to_world, r.decomposed.swing));
    const Vec3 frame_x = Column(frame, 0);

    if (y_locked || z_locked) {
      st::CalculateOneDofSwingRows(bodies, config, frame, r.axes, y_limit, z_limit, part, offset);
    } else if (rows.swing_y) {
      st::CalculateTwoDofSwingRow(bodies, r, frame_x, y_limit, part, offset);
    } else {
      st::SwitchOffRow(part.swing_y, part.persistent.swing_y_lambda, offset);
      st::SwitchOffRow(part.swing_z, part.persistent.swing_z_lambda, offset);
    }

    switch (config.twist) {
      case AxisLimitKind::kLocked:
        st::CalculateRow(bodies, frame_x, AllLanes(), st::MaxLambda(twist_limit), part.twist,
                         part.persistent.twist_lambda, offset);
        break;
      case AxisLimitKind::kLimited:
        st::CalculateRow(bodies, Select(r.axes.twist_min, Neg(frame_x), frame_x),
                         hn::Or(r.axes.twist_min, r.axes.twist_max), st::MaxLambda(twist_limit),
                         part.twist, part.persistent.twist_lambda, offset);
        break;
      case AxisLimitKind::kFree:
        st::SwitchOffRow(part.twist, part.persistent.twist_lambda, offset);
        break;
    }
  });
}

inline void SwingTwistWarmStart(const BodyPair& bodies, const SwingTwistConfig& config,
                                SwingTwistLanes& part, float warm_start_ratio) {
  const swing_twist::RowsInUse rows = swing_twist::RowsInUseOf(config);
  const LaneVec ratio = Splat(warm_start_ratio);
  ForEachChunk([&](std::size_t offset) {
    if (rows.swing_y) {
      AngleWarmStartChunk(bodies, ratio, part.swing_y.properties, part.persistent.swing_y_lambda,
                          offset);
    }
    if (rows.swing_z) {
      AngleWarmStartChunk(bodies, ratio, part.swing_z.properties, part.persistent.swing_z_lambda,
                          offset);
    }
    if (rows.twist) {
      AngleWarmStartChunk(bodies, ratio, part.twist.properties, part.persistent.twist_lambda,
                          offset);
    }
  });
}

// Returns true if any lane applied a non-zero impulse.
inline bool SwingTwistSolveVelocity(const BodyPair& bodies, const SwingTwistConfig& config,
                                    SwingTwistLanes& part) {
  const swing_twist::RowsInUse rows = swing_twist::RowsInUseOf(config);
  const LaneVec min_lambda = Splat(-FLT_MAX);
  bool applied = false;
  ForEachChunk([&](std::size_t offset) {
    auto solve_row = [&](const SwingTwistRowLanes& row, LaneArray& total_lambda) {
      return AngleSolveVelocityChunk(bodies, LoadVec3(row.axis, offset), min_lambda,
                                     Load(row.max_lambda, offset), row.properties, total_lambda,
                                     offset);
    };
    LaneMask any = NoLanes();
    if (rows.swing_y) any = hn::Or(any, solve_row(part.swing_y, part.persistent.swing_y_lambda));
    if (rows.swing_z) any = hn::Or(any, solve_row(part.swing_z, part.persistent.swing_z_lambda));
    if (rows.twist) any = hn::Or(any, solve_row(part.twist, part.persistent.twist_lambda));
    applied |= AnyLane(any);
  });
  return applied;
}

// Returns true if any lane was outside its limits (and so took a step).
inline bool SwingTwistSolvePosition(const BodyPair& bodies, const SwingTwistConfig& config,
                                    const SwingTwistGeometry& geometry,
                                    const SwingTwistLimitLanes& limits, float baumgarte) {
  namespace st = swing_twist;
  bool applied = false;
  ForEachChunk([&](std::size_t offset) {
    const st::ClampedRotation r = st::DecomposeAndClamp(bodies, config, geometry, limits, offset);
    const LaneMask violated = st::AnyClamped(r.axes);
    if (!AnyLane(violated)) return;
    const Quat clamped_in_body1 = Mul(Mul(LoadQuat(geometry.constraint_to_body1, offset),
                                          r.clamped.swing),
                                      r.clamped.twist);
    const Quat inv_initial_orientation =
        Mul(LoadQuat(geometry.constraint_to_body2, offset), Conjugate(clamped_in_body1));
    LaneMask invertible;  // singular lanes have K^-1 = 0 and take a zero step
    const RotationEulerChunk euler = RotationEulerPropertiesOfChunk(bodies, offset, invertible);
    applied |= AnyLane(RotationEulerPositionStepOfChunk(bodies, euler, inv_initial_orientation,
                                                        baumgarte, violated, offset));
  });
  return applied;
}

// Deactivate lanes whose flag is set: all three rows' effective mass and
// impulse zero.
inline void SwingTwistDeactivate(SwingTwistLanes& part, const LaneFlags& lanes) {
  ForEachChunk([&](std::size_t offset) {
    const LaneMask off = LoadFlags(lanes, offset);
    AngleDeactivateChunk(off, part.swing_y.properties, part.persistent.swing_y_lambda, offset);
    AngleDeactivateChunk(off, part.swing_z.properties, part.persistent.swing_z_lambda, offset);
    AngleDeactivateChunk(off, part.twist.properties, part.persistent.twist_lambda, offset);
  });
}

// flag = 1 where any row is active (Jolt's IsActive), else 0.
inline void SwingTwistIsActive(const SwingTwistLanes& part, LaneFlags& active) {
  ForEachChunk([&](std::size_t offset) {
    StoreFlags(hn::Or(hn::Or(AngleIsActiveChunk(part.swing_y.properties, offset),
                             AngleIsActiveChunk(part.swing_z.properties, offset)),
                      AngleIsActiveChunk(part.twist.properties, offset)),
               active, offset);
  });
}

}  // namespace HWY_NAMESPACE
}  // namespace manyworlds
HWY_AFTER_NAMESPACE();

#endif  // MANYWORLDS_KERNELS_SWING_TWIST_INL_H_
