// Swing-twist decomposition and limit clamping across worlds (spec 2.12,
// Jolt's Quat::GetSwingTwist and SwingTwistConstraintPart::ClampSwingTwist).
// The verbs that use them are in swing_twist-inl.h.
//
// Constraint space: X = twist axis, Y and Z = swing axes; q = rotation of
// body 2's constraint frame relative to body 1's.
//
//   q = swing twist,  s = sqrt(w^2 + x^2)
//   twist = (x/s, 0, 0, w/s),  swing = (0, (w y - x z)/s, (w z + x y)/s, s)
//   s == 0 (a half turn about an axis in the YZ plane): twist = 1, swing = q
//
// Limits live in sin(angle/2) space (quaternion components). Clamp, after
// making w >= 0 on both (signs restored at the end):
//   twist locked   clamped where x != 0, result identity
//   twist limited  out of range where sin_min - x > 0 or x - sin_max > 0; set
//                  to the nearer limit, distance |d| folded by d > 1 => 2 - d
//                  (sin = -1 and +1 are the same rotation)
//   swing Y and Z locked: identity; one locked: 1-DOF clamp of the other with
//                  the same rule, and if only the locked component was off,
//                  swing = (0, 0, z, sqrt(1 - z^2)) (resp. y)
//   neither locked, cone: (y, z) outside the ellipse with semi-axes
//                  (sin_y_max, sin_z_max) moves to the closest ellipse point,
//                  w = sqrt(max(0, 1 - y^2 - z^2))
//   neither locked, pyramid: half angles (atan2(y, w), atan2(z, w)) clamped per
//                  axis; if either changed, rebuild
//                  normalize(0, sy cz, cy sz, cy cz) (x dropped: no twist)
//
// Closest ellipse point (Jolt's Ellipse, after van den Bergen, "Rotation Joint
// Limits in Quaternion Space", Game Engine Gems 3): c = (a^2 px/(t + a^2),
// b^2 py/(t + b^2)) with t the root of
//   g(t) = (a px/(t + a^2))^2 + (b py/(t + b^2))^2 - 1,
// found by Newton from t = 0 until |g| < 1e-6. g is convex and decreasing for
// t > -min(a^2, b^2) and g(0) > 0 outside the ellipse, so the iterates rise
// monotonically to the root without overshooting. Jolt's loop has no cap; here
// every lane runs at most kEllipseMaxIterations steps, a lane that has
// converged keeps its t (so it returns exactly Jolt's iterate), and the loop
// ends as soon as every lane has converged.

#if defined(MANYWORLDS_KERNELS_SWING_TWIST_CLAMP_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef MANYWORLDS_KERNELS_SWING_TWIST_CLAMP_INL_H_
#undef MANYWORLDS_KERNELS_SWING_TWIST_CLAMP_INL_H_
#else
#define MANYWORLDS_KERNELS_SWING_TWIST_CLAMP_INL_H_
#endif

#include <cstddef>

#include "kernels/lane_math-inl.h"
#include "kernels/swing_twist.h"

HWY_BEFORE_NAMESPACE();
namespace manyworlds {
namespace HWY_NAMESPACE {
namespace swing_twist {

// Newton steps per lane for the closest ellipse point. Jolt stops at
// |g| < 1e-6 with no cap; in float, over 20 million random points on the unit
// disc and semi-axes log-uniform in [sin(0.25 deg), 1] (a limit below 0.5 deg
// is locked), the most steps needed were 20 (median 12; 5 to 8 for limits of
// 20 to 60 deg). 32 leaves a margin; a lane that reaches it keeps its last
// iterate, which lies just outside the ellipse (the iterates approach the root
// from below).
inline constexpr int kEllipseMaxIterations = 32;

struct SwingTwistPair {
  Quat swing;  // x = 0
  Quat twist;  // y = z = 0
};

// Which limits a clamp hit, per lane.
struct ClampedAxes {
  LaneMask twist_min, twist_max;
  LaneMask swing_y_min, swing_y_max;
  LaneMask swing_z_min, swing_z_max;
};

HWY_INLINE LaneMask AnyClamped(const ClampedAxes& c) {
  return hn::Or(hn::Or(hn::Or(c.twist_min, c.twist_max), hn::Or(c.swing_y_min, c.swing_y_max)),
                hn::Or(c.swing_z_min, c.swing_z_max));
}

HWY_INLINE Quat NegateQuat(const Quat& q) {
  return {hn::Neg(q.x), hn::Neg(q.y), hn::Neg(q.z), hn::Neg(q.w)};
}

// One axis' limits of one chunk.
struct AxisLimit {
  LaneVec half_min, half_max;
  LaneVec sin_min, sin_max;
  LaneVec cos_min, cos_max;
};

HWY_INLINE AxisLimit LoadAxisLimit(const AxisLimitLanes& limit, std::size_t offset) {
  return {Load(limit.half_min, offset),     Load(limit.half_max, offset),
          Load(limit.sin_half_min, offset), Load(limit.sin_half_max, offset),
          Load(limit.cos_half_min, offset), Load(limit.cos_half_max, offset)};
}

// Jolt's GetSwingTwist (see the top of this file).
HWY_INLINE SwingTwistPair Decompose(const Quat& q) {
  const LaneVec s = hn::Sqrt(hn::MulAdd(q.w, q.w, hn::Mul(q.x, q.x)));
  const LaneMask regular = hn::Ne(s, Zero());
  const LaneVec inv_s = hn::Div(Splat(1.0f), hn::IfThenElse(regular, s, Splat(1.0f)));
  const Quat twist{hn::Mul(q.x, inv_s), Zero(), Zero(), hn::Mul(q.w, inv_s)};
  const Quat swing{Zero(), hn::Mul(hn::MulSub(q.w, q.y, hn::Mul(q.x, q.z)), inv_s),
                   hn::Mul(hn::MulAdd(q.w, q.z, hn::Mul(q.x, q.y)), inv_s), s};
  return {Select(regular, swing, q), Select(regular, twist, IdentityQuat())};
}

// |d|, folded by "d > 1 => 2 - d": the distance in sin(angle/2) space with
// -1 and +1 (the same rotation) identified.
HWY_INLINE LaneVec FoldedDistance(LaneVec d) {
  const LaneVec abs_d = hn::Abs(d);
  return hn::IfThenElse(hn::Gt(abs_d, Splat(1.0f)), hn::Sub(Splat(2.0f), abs_d), abs_d);
}

// 1-DOF clamp of the sin(angle/2) `value`: lanes out of range go to the
// nearer limit (to_min or to_max; both false where in range).
HWY_INLINE void ClampOneAxis(LaneVec value, const AxisLimit& limit, LaneMask& to_min,
                             LaneMask& to_max) {
  const LaneVec delta_min = hn::Sub(limit.sin_min, value);
  const LaneVec delta_max = hn::Sub(value, limit.sin_max);
  const LaneMask outside = hn::Or(hn::Gt(delta_min, Zero()), hn::Gt(delta_max, Zero()));
  const LaneMask min_nearer = hn::Lt(FoldedDistance(delta_min), FoldedDistance(delta_max));
  to_min = hn::And(outside, min_nearer);
  to_max = hn::AndNot(min_nearer, outside);
}

// Closest point on the ellipse (x/a)^2 + (y/b)^2 = 1 to (px, py) in the lanes
// of `solve` (the others return junk that callers do not select); see the top
// of this file. `iterations` counts the Newton steps per lane.
HWY_INLINE void EllipseClosestPoint(LaneVec a, LaneVec b, LaneVec px, LaneVec py,
                                    LaneMask solve, LaneVec& closest_x, LaneVec& closest_y,
                                    LaneVec& iterations) {
  const LaneVec a_sq = hn::Mul(a, a), b_sq = hn::Mul(b, b);
  const LaneVec a_px = hn::Mul(a, px), b_py = hn::Mul(b, py);
  const LaneVec a_sq_px = hn::Mul(a_sq, px), b_sq_py = hn::Mul(b_sq, py);
  const LaneVec a_sq_px_sq = hn::Mul(a_sq_px, px), b_sq_py_sq = hn::Mul(b_sq_py, py);
  LaneVec t = Zero();
  LaneMask done = hn::Not(solve);
  iterations = Zero();
  for (int step = 0; step <= kEllipseMaxIterations; ++step) {
    const LaneVec t_plus_a_sq = hn::Add(t, a_sq), t_plus_b_sq = hn::Add(t, b_sq);
    const LaneVec gx = hn::Div(a_px, t_plus_a_sq), gy = hn::Div(b_py, t_plus_b_sq);
    const LaneVec g = hn::Sub(hn::MulAdd(gx, gx, hn::Mul(gy, gy)), Splat(1.0f));
    done = hn::Or(done, hn::Lt(hn::Abs(g), Splat(1.0e-6f)));
    if (step == kEllipseMaxIterations || hn::AllTrue(LaneTag(), done)) break;
    // g'(t) = -2 (a^2 px^2/(t + a^2)^3 + b^2 py^2/(t + b^2)^3)
    const LaneVec cube_a = hn::Mul(hn::Mul(t_plus_a_sq, t_plus_a_sq), t_plus_a_sq);
    const LaneVec cube_b = hn::Mul(hn::Mul(t_plus_b_sq, t_plus_b_sq), t_plus_b_sq);
    const LaneVec slope = hn::Mul(
        Splat(-2.0f), hn::Add(hn::Div(a_sq_px_sq, cube_a), hn::Div(b_sq_py_sq, cube_b)));
    t = hn::IfThenElse(done, t, hn::Sub(t, hn::Div(g, slope)));
    iterations = hn::Add(iterations, hn::IfThenZeroElse(done, Splat(1.0f)));
  }
  closest_x = hn::Div(a_sq_px, hn::Add(t, a_sq));
  closest_y = hn::Div(b_sq_py, hn::Add(t, b_sq));
}

// Two-DOF cone clamp: swing (w >= 0) outside the ellipse moves onto it.
HWY_INLINE Quat ClampCone(const Quat& swing, const AxisLimit& y_limit, const AxisLimit& z_limit,
                          LaneMask& clamped, LaneVec& iterations) {
  const LaneVec a = y_limit.sin_max, b = z_limit.sin_max;
  const LaneVec y_over_a = hn::Div(swing.y, a), z_over_b = hn::Div(swing.z, b);
  clamped = hn::Gt(hn::MulAdd(y_over_a, y_over_a, hn::Mul(z_over_b, z_over_b)), Splat(1.0f));
  if (hn::AllFalse(LaneTag(), clamped)) {
    iterations = Zero();
    return swing;
  }
  LaneVec y, z;
  EllipseClosestPoint(a, b, swing.y, swing.z, clamped, y, z, iterations);
  const LaneVec w_sq = hn::NegMulAdd(y, y, hn::NegMulAdd(z, z, Splat(1.0f)));
  const Quat projected{Zero(), y, z, hn::Sqrt(hn::Max(w_sq, Zero()))};
  return Select(clamped, projected, swing);
}

// Two-DOF pyramid clamp on the half angles atan2(y, w), atan2(z, w).
HWY_INLINE Quat ClampPyramid(const Quat& swing, const AxisLimit& y_limit,
                             const AxisLimit& z_limit, LaneMask& clamped) {
  const LaneVec half_y = Atan2(swing.y, swing.w);
  const LaneVec half_z = Atan2(swing.z, swing.w);
  const LaneVec clamped_y = hn::Min(hn::Max(half_y, y_limit.half_min), y_limit.half_max);
  const LaneVec clamped_z = hn::Min(hn::Max(half_z, z_limit.half_min), z_limit.half_max);
  clamped = hn::Or(hn::Ne(half_y, clamped_y), hn::Ne(half_z, clamped_z));
  if (hn::AllFalse(LaneTag(), clamped)) return swing;
  LaneVec sin_y, cos_y, sin_z, cos_z;
  SinCos(clamped_y, sin_y, cos_y);
  SinCos(clamped_z, sin_z, cos_z);
  // Rotation about Y then Z is (-sy sz, sy cz, cy sz, cy cz); x is left out so
  // that the clamp introduces no twist, hence the normalisation.
  const Quat rebuilt = Normalize(
      Quat{Zero(), hn::Mul(sin_y, cos_z), hn::Mul(cos_y, sin_z), hn::Mul(cos_y, cos_z)});
  return Select(clamped, rebuilt, swing);
}

// 1-DOF swing: the other component (`free_component`, y or z) is clamped to
// its limit; `locked_off` are the lanes whose locked component was non-zero.
// `make(component, w)` builds the swing quaternion about the free axis.
template <class MakeSwing>
HWY_INLINE Quat ClampSwingOneAxis(const Quat& swing, LaneVec free_component,
                                  const AxisLimit& free_limit, LaneMask locked_off,
                                  LaneMask& to_min, LaneMask& to_max, MakeSwing make) {
  ClampOneAxis(free_component, free_limit, to_min, to_max);
  // In range but the locked component was off: keep the free one, drop the
  // locked one and renormalise through w (max(0, .) only guards rounding).
  const LaneVec w_sq = hn::NegMulAdd(free_component, free_component, Splat(1.0f));
  Quat result = Select(locked_off, make(free_component, hn::Sqrt(hn::Max(w_sq, Zero()))), swing);
  result = Select(to_min, make(free_limit.sin_min, free_limit.cos_min), result);
  return Select(to_max, make(free_limit.sin_max, free_limit.cos_max), result);
}

// Jolt's ClampSwingTwist (see the top of this file). `ellipse_iterations`
// is zero except for cone lanes that were projected.
HWY_INLINE SwingTwistPair Clamp(const SwingTwistConfig& config, const AxisLimit& twist_limit,
                                const AxisLimit& y_limit, const AxisLimit& z_limit,
                                SwingTwistPair in, ClampedAxes& clamped,
                                LaneVec& ellipse_iterations) {
  const LaneMask none = NoLanes();
  clamped = {none, none, none, none, none, none};
  ellipse_iterations = Zero();
  const LaneMask negate_swing = hn::Lt(in.swing.w, Zero());
  const LaneMask negate_twist = hn::Lt(in.twist.w, Zero());
  Quat swing = Select(negate_swing, NegateQuat(in.swing), in.swing);
  Quat twist = Select(negate_twist, NegateQuat(in.twist), in.twist);

  if (config.twist == AxisLimitKind::kLocked) {
    clamped.twist_min = clamped.twist_max = hn::Ne(twist.x, Zero());
    twist = IdentityQuat();
  } else if (config.twist == AxisLimitKind::kLimited) {
    ClampOneAxis(twist.x, twist_limit, clamped.twist_min, clamped.twist_max);
    twist = Select(clamped.twist_min,
                   Quat{twist_limit.sin_min, Zero(), Zero(), twist_limit.cos_min}, twist);
    twist = Select(clamped.twist_max,
                   Quat{twist_limit.sin_max, Zero(), Zero(), twist_limit.cos_max}, twist);
  }

  const bool y_locked = config.swing_y == AxisLimitKind::kLocked;
  const bool z_locked = config.swing_z == AxisLimitKind::kLocked;
  if (y_locked && z_locked) {
    clamped.swing_y_min = clamped.swing_y_max = hn::Ne(swing.y, Zero());
    clamped.swing_z_min = clamped.swing_z_max = hn::Ne(swing.z, Zero());
    swing = IdentityQuat();
  } else if (y_locked) {
    clamped.swing_y_min = clamped.swing_y_max = hn::Ne(swing.y, Zero());
    swing = ClampSwingOneAxis(swing, swing.z, z_limit, clamped.swing_y_min,
                              clamped.swing_z_min, clamped.swing_z_max,
                              [](LaneVec z, LaneVec w) { return Quat{Zero(), Zero(), z, w}; });
  } else if (z_locked) {
    clamped.swing_z_min = clamped.swing_z_max = hn::Ne(swing.z, Zero());
    swing = ClampSwingOneAxis(swing, swing.y, y_limit, clamped.swing_z_min,
                              clamped.swing_y_min, clamped.swing_y_max,
                              [](LaneVec y, LaneVec w) { return Quat{Zero(), y, Zero(), w}; });
  } else {
    // Two degrees of freedom (also when both are free, as in Jolt). Which
    // side was hit is not used, so all four flags are set together.
    LaneMask two_dof_clamped;
    if (config.swing_type == SwingType::kCone) {
      swing = ClampCone(swing, y_limit, z_limit, two_dof_clamped, ellipse_iterations);
    } else {
      swing = ClampPyramid(swing, y_limit, z_limit, two_dof_clamped);
    }
    clamped.swing_y_min = clamped.swing_y_max = two_dof_clamped;
    clamped.swing_z_min = clamped.swing_z_max = two_dof_clamped;
  }

  return {Select(negate_swing, NegateQuat(swing), swing),
          Select(negate_twist, NegateQuat(twist), twist)};
}

// Jolt's SetLimits for one axis of one chunk: half angles always; sine and
// cosine of them for limited axes, the fixed values for locked and free ones.
HWY_INLINE void SetAxisLimit(AxisLimitKind kind, LaneVec min_angle, LaneVec max_angle,
                             AxisLimitLanes& out, std::size_t offset) {
  const LaneVec half_min = hn::Mul(min_angle, Splat(0.5f));
  const LaneVec half_max = hn::Mul(max_angle, Splat(0.5f));
  Store(half_min, out.half_min, offset);
  Store(half_max, out.half_max, offset);
  // Locked unless limited or free.
  LaneVec sin_min = Zero(), sin_max = Zero();
  LaneVec cos_min = Splat(1.0f), cos_max = Splat(1.0f);
  if (kind == AxisLimitKind::kFree) {
    sin_min = Splat(-1.0f);
    sin_max = Splat(1.0f);
    cos_min = cos_max = Zero();
  } else if (kind == AxisLimitKind::kLimited) {
    SinCos(half_min, sin_min, cos_min);
    SinCos(half_max, sin_max, cos_max);
  }
  Store(sin_min, out.sin_half_min, offset);
  Store(sin_max, out.sin_half_max, offset);
  Store(cos_min, out.cos_half_min, offset);
  Store(cos_max, out.cos_half_max, offset);
}

}  // namespace swing_twist
}  // namespace HWY_NAMESPACE
}  // namespace manyworlds
HWY_AFTER_NAMESPACE();

#endif  // MANYWORLDS_KERNELS_SWING_TWIST_CLAMP_INL_H_
