// HingeRotationConstraintPart across worlds: two angular rows that keep body
// 2's hinge axis a2 aligned with body 1's hinge axis a1, leaving the rotation
// about the hinge free (hinge and path constraints). Spec 2.5.
//
//   Axes repair (Jolt's, per lane): if a1.a2 <= 1e-3 (>= ~90 deg apart),
//     p  = a2 - (a1.a2) a1, or perp(a1) where |p|^2 < 1e-6 (anti-parallel),
//     a2 := normalize(0.99 normalize(p) + 0.01 a1),
//   which keeps the linearisation on the side of the C = 0 manifold where a2
//   turns towards a1 instead of away from it.
//   b2 = perp(a2) (|x| > |y| choice of Jolt's GetNormalizedPerpendicular),
//   c2 = a2 x b2.
//   C   = (a1.b2, a1.c2)                        zero when a1 is parallel to a2
//   J_i = [0, -(e_i x a1), 0, e_i x a1],  e_0 = b2, e_1 = c2  (Chappuis 2.4.1)
//   K_ij = (e_i x a1) . (I1^-1 + I2^-1) (e_j x a1), I^-1 = 0 unless dynamic;
//   K^-1 by the closed 2x2 formula, det == 0 => Deactivate.
//
// Velocity step:  s_i = (e_i x a1).(w1 - w2) = -J_i v
//                 dL = K^-1 s,  L += dL,  P = (b2 x a1) dL_0 + (c2 x a1) dL_1,
//                 w1 -= I1^-1 P,  w2 += I2^-1 P   (dynamic bodies only).
// Position step:  C from the cached a1, b2, c2; where C != 0: L = -beta K^-1 C,
//                 body 1 rotated by -I1^-1 P, body 2 by +I2^-1 P.
// I^-1 comes from each body's current rotation (matrix form, spec 1.4); the
// products I^-1 (e_i x a1) are cached, so P never needs the 3x3 matrix again.

#if defined(MANYWORLDS_KERNELS_HINGE_ROTATION_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef MANYWORLDS_KERNELS_HINGE_ROTATION_INL_H_
#undef MANYWORLDS_KERNELS_HINGE_ROTATION_INL_H_
#else
#define MANYWORLDS_KERNELS_HINGE_ROTATION_INL_H_
#endif

#include <cstddef>

#include "kernels/body_access-inl.h"
#include "kernels/hinge_rotation.h"
#include "kernels/lane_math-inl.h"

HWY_BEFORE_NAMESPACE();
namespace manyworlds {
namespace HWY_NAMESPACE {

namespace hinge_rotation {

// Jolt's thresholds for the axes repair (spec 2.5).
constexpr float kRepairBelowDot = 1.0e-3f;     // a1.a2 at or below: >= ~90 deg
constexpr float kAntiParallelBelow = 1.0e-6f;  // |a2 - (a1.a2) a1|^2 below
constexpr float kBlendPerpendicular = 0.99f;   // the new a2 is 99% in the plane
constexpr float kBlendTowardsA1 = 0.01f;       // and 1% along a1

// a2, or where a1.a2 <= 1e-3 the replacement a2 just inside 90 deg of a1.
HWY_INLINE Vec3 RepairedHingeAxis2(const Vec3& a1, const Vec3& a2) {
  const LaneVec dot = Dot(a1, a2);
  const LaneMask repair = hn::Le(dot, Splat(kRepairBelowDot));
  // The repair is rare (a hinge bent by 90 degrees or more) and costs three
  // square roots and divisions: a chunk where no lane needs it skips them.
  // Each lane still takes a2 or its own repair, so no world's bits depend
  // on its neighbours.
  if (!AnyLane(repair)) return a2;
  // Component of a2 perpendicular to a1; where it vanishes (a2 = -a1) any
  // perpendicular of a1 will do. Replacing it in every such lane, repaired or
  // not, keeps the normalisation below finite in all lanes.
  const Vec3 in_plane = NegMulAdd(a1, dot, a2);
  const LaneMask anti_parallel =
      hn::Lt(LengthSquared(in_plane), Splat(kAntiParallelBelow));
  const Vec3 perpendicular =
      Select(anti_parallel, NormalizedPerpendicular(a1), in_plane);
  const Vec3 blended =
      Normalize(MulAdd(Normalize(perpendicular), Splat(kBlendPerpendicular),
                       Scale(a1, Splat(kBlendTowardsA1))));
  return Select(repair, blended, a2);
}

// The lanes where C = (a1.b2, a1.c2) is exactly zero: the axes aligned, the
// position step a no-op (a NaN lane is not aligned).
HWY_INLINE LaneMask Aligned(const Vec3& a1, const Vec3& b2, const Vec3& c2) {
  return hn::And(hn::Eq(Dot(a1, b2), Zero()), hn::Eq(Dot(a1, c2), Zero()));
}

// Angular impulse of the two rows: P = (b2 x a1) lambda0 + (c2 x a1) lambda1,
// already multiplied by a body's inverse inertia through the cached vectors.
HWY_INLINE Vec3 InverseInertiaTimesImpulse(const Vec3Lanes& inv_i_b2_x_a1,
                                           const Vec3Lanes& inv_i_c2_x_a1,
                                           LaneVec lambda0, LaneVec lambda1,
                                           std::size_t offset) {
  return MulAdd(LoadVec3(inv_i_b2_x_a1, offset), lambda0,
                Scale(LoadVec3(inv_i_c2_x_a1, offset), lambda1));
}

// Applies (lambda0, lambda1): body 1 gets -J^T, body 2 +J^T, dynamic bodies
// only. kVelocity = false makes it a rotation step (position phase).
// `where` (velocity steps only): the lanes that take the step; the others
// keep every bit.
template <bool kVelocity, class Where = std::nullptr_t>
HWY_INLINE void ApplyImpulse(const BodyPair& bodies, const HingeRotationLanes& part,
                             LaneVec lambda0, LaneVec lambda1, std::size_t offset,
                             Where where = nullptr) {
  if (bodies.motion1 == MotionType::kDynamic) {
    const Vec3 step = Neg(InverseInertiaTimesImpulse(
        part.inv_i1_b2_x_a1, part.inv_i1_c2_x_a1, lambda0, lambda1, offset));
    if (kVelocity) {
      AddAngularVelocityStep(*bodies.body1, step, offset, where);
    } else {
      AddRotationStep(*bodies.body1, step, offset);
    }
  }
  if (bodies.motion2 == MotionType::kDynamic) {
    const Vec3 step = InverseInertiaTimesImpulse(
        part.inv_i2_b2_x_a1, part.inv_i2_c2_x_a1, lambda0, lambda1, offset);
    if (kVelocity) {
      AddAngularVelocityStep(*bodies.body2, step, offset, where);
    } else {
      AddRotationStep(*bodies.body2, step, offset);
    }
  }
}

}  // namespace hinge_rotation

// The first half of CalculateProperties: the axes a1, b2, c2 and the rows'
// directions b2 x a1, c2 x a1 from the geometry's world axes. Returns true
// if C = (a1.b2, a1.c2) is exactly zero in every lane: the position phase
// then has nothing to do (HingeRotationSolvePosition would rotate no body).
inline bool HingeRotationAxes(const HingeRotationGeometry& geometry, HingeRotationLanes& part) {
  bool aligned = true;
  ForEachChunk([&](std::size_t offset) {
    const Vec3 a1 = LoadVec3(geometry.hinge_axis1, offset);
    const Vec3 a2 = hinge_rotation::RepairedHingeAxis2(
        a1, LoadVec3(geometry.hinge_axis2, offset));
    const Vec3 b2 = NormalizedPerpendicular(a2);
    const Vec3 c2 = Cross(a2, b2);
    StoreVec3(a1, part.a1, offset);
    StoreVec3(b2, part.b2, offset);
    StoreVec3(c2, part.c2, offset);
    StoreVec3(Cross(b2, a1), part.b2_x_a1, offset);
    StoreVec3(Cross(c2, a1), part.c2_x_a1, offset);
    aligned &= hn::AllTrue(LaneTag(), hinge_rotation::Aligned(a1, b2, c2));
  });
  return aligned;
}

// The second half: the inverse inertias times the rows' directions at the
// bodies' current rotations and K^-1 (HingeRotationAxes first). Lanes where K
// is singular are deactivated (K^-1 = 0, impulse cleared); with
// `position_phase`, only those whose C is not zero: a lane with C = 0 takes
// no position step and is left exactly as it is, so that it comes out the
// same whether its block skipped the position step (aligned in every lane)
// or not.
inline void HingeRotationEffectiveMass(const BodyPair& bodies, HingeRotationLanes& part,
                                       bool position_phase = false) {
  ForEachChunk([&](std::size_t offset) {
    const Vec3 b2_x_a1 = LoadVec3(part.b2_x_a1, offset);
    const Vec3 c2_x_a1 = LoadVec3(part.c2_x_a1, offset);
    // Non-dynamic bodies have I^-1 = 0: their cached vectors stay zero so that
    // 0 * cache is 0 in every later verb.
    Vec3 inv_i1_b = ZeroVec3(), inv_i1_c = ZeroVec3();
    Vec3 inv_i2_b = ZeroVec3(), inv_i2_c = ZeroVec3();
    if (bodies.motion1 == MotionType::kDynamic) {
      const Sym33 inv_inertia = BodyInverseInertia(*bodies.body1, offset);
      inv_i1_b = Multiply(inv_inertia, b2_x_a1);
      inv_i1_c = Multiply(inv_inertia, c2_x_a1);
    }
    if (bodies.motion2 == MotionType::kDynamic) {
      const Sym33 inv_inertia = BodyInverseInertia(*bodies.body2, offset);
      inv_i2_b = Multiply(inv_inertia, b2_x_a1);
      inv_i2_c = Multiply(inv_inertia, c2_x_a1);
    }
    StoreVec3(inv_i1_b, part.inv_i1_b2_x_a1, offset);
    StoreVec3(inv_i1_c, part.inv_i1_c2_x_a1, offset);
    StoreVec3(inv_i2_b, part.inv_i2_b2_x_a1, offset);
    StoreVec3(inv_i2_c, part.inv_i2_c2_x_a1, offset);

    // K = J M^-1 J^T with (I1^-1 + I2^-1) applied through the cached vectors.
    const Vec3 sum_inv_i_b = Add(inv_i1_b, inv_i2_b);
    const Vec3 sum_inv_i_c = Add(inv_i1_c, inv_i2_c);
    const Sym22 k{Dot(b2_x_a1, sum_inv_i_b), Dot(b2_x_a1, sum_inv_i_c),
                  Dot(c2_x_a1, sum_inv_i_c)};
    LaneMask active;
    StoreSym22(InverseSym22(k, active), part.effective_mass, offset);
    if (position_phase) {
      active = hn::Or(active, hinge_rotation::Aligned(LoadVec3(part.a1, offset),
                                                      LoadVec3(part.b2, offset),
                                                      LoadVec3(part.c2, offset)));
    }
    // Singular lanes are deactivated, which also clears their impulse.
    Vec2Lanes& lambda = part.persistent.total_lambda;
    Store(hn::IfThenElseZero(active, Load(lambda.x, offset)), lambda.x, offset);
    Store(hn::IfThenElseZero(active, Load(lambda.y, offset)), lambda.y, offset);
  });
}

inline void HingeRotationCalculateProperties(const BodyPair& bodies,
                                             const HingeRotationGeometry& geometry,
                                             HingeRotationLanes& part) {
  HingeRotationAxes(geometry, part);
  HingeRotationEffectiveMass(bodies, part);
}

inline void HingeRotationWarmStart(const BodyPair& bodies, HingeRotationLanes& part,
                                   float warm_start_ratio) {
  const LaneVec ratio = Splat(warm_start_ratio);
  ForEachChunk([&](std::size_t offset) {
    Vec2Lanes& lambda = part.persistent.total_lambda;
    const LaneVec lambda0 = hn::Mul(Load(lambda.x, offset), ratio);
    const LaneVec lambda1 = hn::Mul(Load(lambda.y, offset), ratio);
    Store(lambda0, lambda.x, offset);
    Store(lambda1, lambda.y, offset);
    hinge_rotation::ApplyImpulse<true>(bodies, part, lambda0, lambda1, offset);
  });
}

// Returns true if any lane applied a non-zero impulse.
inline bool HingeRotationSolveVelocity(const BodyPair& bodies,
                                       HingeRotationLanes& part) {
  bool applied = false;
  ForEachChunk([&](std::size_t offset) {
    const Vec3 relative_angular =
        Sub(AngularVelocity(*bodies.body1, bodies.motion1, offset),
            AngularVelocity(*bodies.body2, bodies.motion2, offset));
    // s = -J v
    const LaneVec s0 = Dot(LoadVec3(part.b2_x_a1, offset), relative_angular);
    const LaneVec s1 = Dot(LoadVec3(part.c2_x_a1, offset), relative_angular);
    // A lane whose axes turn together exactly (s = 0: every planar hinge)
    // takes no step (SteppingLanes).
    const SteppingLanes turning = LanesThatStep(AnyComponentNonZero(s0, s1));
    if (turning.none) return;
    LaneVec delta0, delta1;
    Multiply(LoadSym22(part.effective_mass, offset), s0, s1, delta0, delta1);

    Vec2Lanes& lambda = part.persistent.total_lambda;
    const LaneVec lambda0 = Load(lambda.x, offset), lambda1 = Load(lambda.y, offset);
    Store(hn::IfThenElse(turning.mask, hn::Add(lambda0, delta0), lambda0), lambda.x, offset);
    Store(hn::IfThenElse(turning.mask, hn::Add(lambda1, delta1), lambda1), lambda.y, offset);
    hinge_rotation::ApplyImpulse<true>(bodies, part, delta0, delta1, offset, &turning.mask);
    applied |= AnyLane(hn::And(turning.mask, AnyComponentNonZero(delta0, delta1)));
  });
  return applied;
}

// Baumgarte step towards C = 0 using the axes and K^-1 of the last
// CalculateProperties (callers recompute them from the current rotations
// first). Returns true if any lane had a non-zero error.
inline bool HingeRotationSolvePosition(const BodyPair& bodies,
                                       const HingeRotationLanes& part,
                                       float baumgarte) {
  const LaneVec minus_beta = Splat(-baumgarte);
  bool applied = false;
  ForEachChunk([&](std::size_t offset) {
    const Vec3 a1 = LoadVec3(part.a1, offset);
    const LaneVec c0 = Dot(a1, LoadVec3(part.b2, offset));
    const LaneVec c1 = Dot(a1, LoadVec3(part.c2, offset));
    // Jolt skips the step when C == 0; the select keeps those lanes exact.
    const LaneMask has_error = AnyComponentNonZero(c0, c1);
    LaneVec k_inv_c0, k_inv_c1;
    Multiply(LoadSym22(part.effective_mass, offset), c0, c1, k_inv_c0, k_inv_c1);
    const LaneVec lambda0 = hn::IfThenElseZero(has_error, hn::Mul(minus_beta, k_inv_c0));
    const LaneVec lambda1 = hn::IfThenElseZero(has_error, hn::Mul(minus_beta, k_inv_c1));
    hinge_rotation::ApplyImpulse<false>(bodies, part, lambda0, lambda1, offset);
    applied |= AnyLane(has_error);
  });
  return applied;
}

// Jolt's Deactivate of the flagged lanes: K^-1 = 0 and accumulated impulse = 0.
inline void HingeRotationDeactivate(HingeRotationLanes& part, const LaneFlags& lanes) {
  DeactivateFlaggedLanes(part, lanes);
}

// flag = 1 where K^-1 != 0 (Jolt's IsActive), else 0.
inline void HingeRotationIsActive(const HingeRotationLanes& part, LaneFlags& active) {
  StoreActiveLanes(part, active);
}

}  // namespace HWY_NAMESPACE
}  // namespace manyworlds
HWY_AFTER_NAMESPACE();

#endif  // MANYWORLDS_KERNELS_HINGE_ROTATION_INL_H_
