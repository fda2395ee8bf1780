// DualAxisConstraintPart across worlds: two linear rows that keep body 2's
// anchor on a line of body 1 (slider and path constraints). Spec 2.3.
//
//   u = p2 - p1, axes n1 _|_ n2 (unit, world), lever arms r1 + u = p2 - x1,
//   r2 = p2 - x2.
//   C_i = u . n_i                                    (i = 0, 1)
//   J_i = [ -n_i, -((r1 + u) x n_i), n_i, r2 x n_i ]  (Chappuis 2.1.1, eq. 55)
//   K_ij = [dyn1] (m1^-1 d_ij + ((r1+u) x n_i) . I1^-1 ((r1+u) x n_j))
//        + [dyn2] (m2^-1 d_ij + (r2 x n_i) . I2^-1 (r2 x n_j))
//   K is symmetric; K^-1 by the closed 2x2 formula, det == 0 => Deactivate.
//
// Velocity step:  s_i = n_i.(v1 - v2) + ((r1+u) x n_i).w1 - (r2 x n_i).w2
//                 dL = K^-1 s,  L += dL,  P = n1 dL_0 + n2 dL_1
//                 v1 -= m1^-1 P, w1 -= sum_i dL_i I1^-1((r1+u) x n_i), body 2 +.
// Position step:  C = (u.n1, u.n2); where C != 0: L = -beta K^-1 C, applied as
//                 position and rotation steps with the same vectors.
// Only dynamic bodies are written; static bodies read as zero velocity.

#if defined(MANYWORLDS_KERNELS_DUAL_AXIS_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef MANYWORLDS_KERNELS_DUAL_AXIS_INL_H_
#undef MANYWORLDS_KERNELS_DUAL_AXIS_INL_H_
#else
#define MANYWORLDS_KERNELS_DUAL_AXIS_INL_H_
#endif

#include <cstddef>

#include "kernels/body_access-inl.h"
#include "kernels/dual_axis.h"
#include "kernels/lane_math-inl.h"

HWY_BEFORE_NAMESPACE();
namespace manyworlds {
namespace HWY_NAMESPACE {

namespace dual_axis {

// Adds one body's contribution to K and caches I^-1 (lever x n_i).
HWY_INLINE void AddBodyToInverseEffectiveMass(const BodyLanes& body,
                                              const Vec3& lever_x_n1,
                                              const Vec3& lever_x_n2,
                                              Vec3& inv_i_lever_x_n1,
                                              Vec3& inv_i_lever_x_n2,
                                              Sym22& k, std::size_t offset) {
  const Sym33 inv_inertia = BodyInverseInertia(body, offset);
  inv_i_lever_x_n1 = Multiply(inv_inertia, lever_x_n1);
  inv_i_lever_x_n2 = Multiply(inv_inertia, lever_x_n2);
  const LaneVec inv_mass = Load(body.inv_mass, offset);
  k.xx = hn::Add(k.xx, hn::Add(inv_mass, Dot(lever_x_n1, inv_i_lever_x_n1)));
  k.xy = hn::Add(k.xy, Dot(lever_x_n1, inv_i_lever_x_n2));
  k.yy = hn::Add(k.yy, hn::Add(inv_mass, Dot(lever_x_n2, inv_i_lever_x_n2)));
}

// Applies the impulse (lambda0, lambda1) along (n1, n2): body 1 gets -J^T,
// body 2 +J^T. kVelocity = false makes it a position and rotation step.
// `where`: the lanes whose velocities or positions are stored
// (AddVelocityStep, AddPositionStep); a position step's caller also zeroes
// lambda in the other lanes, whose rotation step of zero then keeps q.
template <bool kVelocity, class Where = std::nullptr_t>
HWY_INLINE void ApplyImpulse(const BodyPair& bodies, const DualAxisGeometry& geometry,
                             const DualAxisLanes& part, LaneVec lambda0,
                             LaneVec lambda1, std::size_t offset,
                             Where where = nullptr) {
  const Vec3 impulse = MulAdd(LoadVec3(geometry.n1, offset), lambda0,
                              Scale(LoadVec3(geometry.n2, offset), lambda1));
  if (bodies.motion1 == MotionType::kDynamic) {
    const LaneVec inv_mass = Load(bodies.body1->inv_mass, offset);
    const Vec3 linear = Scale(impulse, hn::Neg(inv_mass));
    const Vec3 angular = Neg(MulAdd(
        LoadVec3(part.inv_i1_r1_plus_u_x_n1, offset), lambda0,
        Scale(LoadVec3(part.inv_i1_r1_plus_u_x_n2, offset), lambda1)));
    if (kVelocity) {
      AddVelocityStep(*bodies.body1, linear, angular, offset, where);
    } else {
      AddPositionStep(*bodies.body1, linear, offset, where);
      AddRotationStep(*bodies.body1, angular, offset);
    }
  }
  if (bodies.motion2 == MotionType::kDynamic) {
    const LaneVec inv_mass = Load(bodies.body2->inv_mass, offset);
    const Vec3 linear = Scale(impulse, inv_mass);
    const Vec3 angular =
        MulAdd(LoadVec3(part.inv_i2_r2_x_n1, offset), lambda0,
               Scale(LoadVec3(part.inv_i2_r2_x_n2, offset), lambda1));
    if (kVelocity) {
      AddVelocityStep(*bodies.body2, linear, angular, offset, where);
    } else {
      AddPositionStep(*bodies.body2, linear, offset, where);
      AddRotationStep(*bodies.body2, angular, offset);
    }
  }
}

// The cross products, I^-1 vectors and K^-1 at the current geometry
// (CalculateProperties of one chunk); returns the lanes where K is
// invertible (the others get K^-1 = 0: Jolt's Deactivate, whose clearing of
// the impulse is the caller's).
HWY_INLINE LaneMask StoreProperties(const BodyPair& bodies, const DualAxisGeometry& geometry,
                                    DualAxisLanes& part, std::size_t offset) {
  const Vec3 r1_plus_u = LoadVec3(geometry.r1_plus_u, offset);
  const Vec3 r2 = LoadVec3(geometry.r2, offset);
  const Vec3 n1 = LoadVec3(geometry.n1, offset);
  const Vec3 n2 = LoadVec3(geometry.n2, offset);
  const Vec3 r1_plus_u_x_n1 = Cross(r1_plus_u, n1);
  const Vec3 r1_plus_u_x_n2 = Cross(r1_plus_u, n2);
  const Vec3 r2_x_n1 = Cross(r2, n1);
  const Vec3 r2_x_n2 = Cross(r2, n2);
  StoreVec3(r1_plus_u_x_n1, part.r1_plus_u_x_n1, offset);
  StoreVec3(r1_plus_u_x_n2, part.r1_plus_u_x_n2, offset);
  StoreVec3(r2_x_n1, part.r2_x_n1, offset);
  StoreVec3(r2_x_n2, part.r2_x_n2, offset);

  // Non-dynamic bodies add nothing to K; their cached I^-1 vectors stay zero
  // so that 0 * cache is 0 in every later verb.
  Sym22 k{Zero(), Zero(), Zero()};
  Vec3 inv_i1_n1 = ZeroVec3(), inv_i1_n2 = ZeroVec3();
  Vec3 inv_i2_n1 = ZeroVec3(), inv_i2_n2 = ZeroVec3();
  if (bodies.motion1 == MotionType::kDynamic) {
    AddBodyToInverseEffectiveMass(*bodies.body1, r1_plus_u_x_n1, r1_plus_u_x_n2, inv_i1_n1,
                                  inv_i1_n2, k, offset);
  }
  if (bodies.motion2 == MotionType::kDynamic) {
    AddBodyToInverseEffectiveMass(*bodies.body2, r2_x_n1, r2_x_n2, inv_i2_n1, inv_i2_n2, k,
                                  offset);
  }
  StoreVec3(inv_i1_n1, part.inv_i1_r1_plus_u_x_n1, offset);
  StoreVec3(inv_i1_n2, part.inv_i1_r1_plus_u_x_n2, offset);
  StoreVec3(inv_i2_n1, part.inv_i2_r2_x_n1, offset);
  StoreVec3(inv_i2_n2, part.inv_i2_r2_x_n2, offset);

  LaneMask active;
  StoreSym22(InverseSym22(k, active), part.effective_mass, offset);
  return active;
}

// C = (u.n1, u.n2) with u = p2 - p1 now.
HWY_INLINE void Error(const DualAxisGeometry& geometry, const Vec3Lanes& separation,
                      std::size_t offset, LaneVec& c0, LaneVec& c1) {
  const Vec3 u = LoadVec3(separation, offset);
  c0 = Dot(u, LoadVec3(geometry.n1, offset));
  c1 = Dot(u, LoadVec3(geometry.n2, offset));
}

// Baumgarte step L = -beta K^-1 C in the lanes of `with_error` (C != 0).
// Jolt skips the others; here they take no step at all, not even a zero one
// (SteppingLanes), and the select keeps them exact even if K^-1 is huge
// (0 * inf would be NaN).
HWY_INLINE void PositionStep(const BodyPair& bodies, const DualAxisGeometry& geometry,
                             const DualAxisLanes& part, LaneVec c0, LaneVec c1,
                             const SteppingLanes& with_error, LaneVec minus_beta,
                             std::size_t offset) {
  LaneVec k_inv_c0, k_inv_c1;
  Multiply(LoadSym22(part.effective_mass, offset), c0, c1, k_inv_c0, k_inv_c1);
  const LaneVec lambda0 = hn::Mul(minus_beta, k_inv_c0);
  const LaneVec lambda1 = hn::Mul(minus_beta, k_inv_c1);
  if (with_error.every) {
    ApplyImpulse<false>(bodies, geometry, part, lambda0, lambda1, offset);
  } else {
    ApplyImpulse<false>(bodies, geometry, part, hn::IfThenElseZero(with_error.mask, lambda0),
                        hn::IfThenElseZero(with_error.mask, lambda1), offset,
                        &with_error.mask);
  }
}

}  // namespace dual_axis

inline void DualAxisCalculateProperties(const BodyPair& bodies,
                                        const DualAxisGeometry& geometry,
                                        DualAxisLanes& part) {
  ForEachChunk([&](std::size_t offset) {
    const LaneMask active = dual_axis::StoreProperties(bodies, geometry, part, offset);
    // Singular lanes are deactivated, which also clears their impulse.
    ClearWhere(hn::Not(active), part.persistent.total_lambda, offset);
  });
}

inline void DualAxisWarmStart(const BodyPair& bodies,
                                  const DualAxisGeometry& geometry,
                                  DualAxisLanes& part, float warm_start_ratio) {
  const LaneVec ratio = Splat(warm_start_ratio);
  ForEachChunk([&](std::size_t offset) {
    Vec2Lanes& lambda = part.persistent.total_lambda;
    const LaneVec lambda0 = hn::Mul(Load(lambda.x, offset), ratio);
    const LaneVec lambda1 = hn::Mul(Load(lambda.y, offset), ratio);
    Store(lambda0, lambda.x, offset);
    Store(lambda1, lambda.y, offset);
    dual_axis::ApplyImpulse<true>(bodies, geometry, part, lambda0, lambda1, offset);
  });
}

// Returns true if any lane applied a non-zero impulse.
inline bool DualAxisSolveVelocity(const BodyPair& bodies,
                                      const DualAxisGeometry& geometry,
                                      DualAxisLanes& part) {
  bool applied = false;
  ForEachChunk([&](std::size_t offset) {
    const Vec3 relative_linear =
        Sub(LinearVelocity(*bodies.body1, bodies.motion1, offset),
            LinearVelocity(*bodies.body2, bodies.motion2, offset));
    const Vec3 w1 = AngularVelocity(*bodies.body1, bodies.motion1, offset);
    const Vec3 w2 = AngularVelocity(*bodies.body2, bodies.motion2, offset);
    // s = -J v
    const LaneVec s0 =
        hn::Sub(hn::Add(Dot(LoadVec3(geometry.n1, offset), relative_linear),
                        Dot(LoadVec3(part.r1_plus_u_x_n1, offset), w1)),
                Dot(LoadVec3(part.r2_x_n1, offset), w2));
    const LaneVec s1 =
        hn::Sub(hn::Add(Dot(LoadVec3(geometry.n2, offset), relative_linear),
                        Dot(LoadVec3(part.r1_plus_u_x_n2, offset), w1)),
                Dot(LoadVec3(part.r2_x_n2, offset), w2));
    // A lane moving exactly along the axis (every rail of a planar
    // mechanism) takes no step (SteppingLanes).
    const SteppingLanes off_axis = LanesThatStep(AnyComponentNonZero(s0, s1));
    if (off_axis.none) return;
    LaneVec delta0, delta1;
    Multiply(LoadSym22(part.effective_mass, offset), s0, s1, delta0, delta1);

    Vec2Lanes& lambda = part.persistent.total_lambda;
    const LaneVec lambda0 = Load(lambda.x, offset), lambda1 = Load(lambda.y, offset);
    if (off_axis.every) {
      Store(hn::Add(lambda0, delta0), lambda.x, offset);
      Store(hn::Add(lambda1, delta1), lambda.y, offset);
      dual_axis::ApplyImpulse<true>(bodies, geometry, part, delta0, delta1, offset);
    } else {
      Store(hn::IfThenElse(off_axis.mask, hn::Add(lambda0, delta0), lambda0), lambda.x, offset);
      Store(hn::IfThenElse(off_axis.mask, hn::Add(lambda1, delta1), lambda1), lambda.y, offset);
      dual_axis::ApplyImpulse<true>(bodies, geometry, part, delta0, delta1, offset,
                                    &off_axis.mask);
    }
    applied |= AnyLane(hn::And(off_axis.mask, AnyComponentNonZero(delta0, delta1)));
  });
  return applied;
}

namespace dual_axis {

// One position pass from C = (u.n1, u.n2): the step in every chunk where
// some lane has an error, with kRecompute the properties recomputed there
// first and the impulses of singular lanes with an error cleared.
template <bool kRecompute, class Part>
HWY_INLINE bool PositionPass(const BodyPair& bodies, const DualAxisGeometry& geometry,
                             const Vec3Lanes& separation, Part& part, float baumgarte) {
  const LaneVec minus_beta = Splat(-baumgarte);
  bool applied = false;
  ForEachChunk([&](std::size_t offset) {
    LaneVec c0, c1;
    Error(geometry, separation, offset, c0, c1);
    const SteppingLanes with_error = LanesThatStep(AnyComponentNonZero(c0, c1));
    if (with_error.none) return;
    if constexpr (kRecompute) {
      const LaneMask active = StoreProperties(bodies, geometry, part, offset);
      ClearWhere(hn::AndNot(active, with_error.mask), part.persistent.total_lambda, offset);
    }
    PositionStep(bodies, geometry, part, c0, c1, with_error, minus_beta, offset);
    applied = true;
  });
  return applied;
}

}  // namespace dual_axis

// Baumgarte step towards C = 0 using the properties of the last
// CalculateProperties (callers recompute them first). `u` = p2 - p1 now.
// Returns true if any lane had a non-zero error.
inline bool DualAxisSolvePosition(const BodyPair& bodies, const DualAxisGeometry& geometry,
                                  const Vec3Lanes& separation, const DualAxisLanes& part,
                                  float baumgarte) {
  return dual_axis::PositionPass<false>(bodies, geometry, separation, part, baumgarte);
}

// The position phase's verb, after the caller has placed the geometry at the
// current poses: the properties, then one Baumgarte step. A lane whose C is
// exactly zero takes no step and is left exactly as it is (its impulse is
// not cleared even if K has become singular since the setup, where Jolt's
// recompute would clear it); where that holds in every lane of a chunk (a
// rack sliding exactly along its rail) the properties are not computed, and
// the part's cached properties keep their setup values, which nothing reads
// before the next setup. Returns true if any lane had a non-zero error.
inline bool DualAxisRecomputeAndSolvePosition(const BodyPair& bodies,
                                              const DualAxisGeometry& geometry,
                                              const Vec3Lanes& separation, DualAxisLanes& part,
                                              float baumgarte) {
  return dual_axis::PositionPass<true>(bodies, geometry, separation, part, baumgarte);
}

// Jolt's Deactivate of the flagged lanes: K^-1 = 0 and accumulated impulse = 0.
inline void DualAxisDeactivate(DualAxisLanes& part, const LaneFlags& lanes) {
  DeactivateFlaggedLanes(part, lanes);
}

// flag = 1 where K^-1 != 0 (Jolt's IsActive), else 0.
inline void DualAxisIsActive(const DualAxisLanes& part, LaneFlags& active) {
  StoreActiveLanes(part, active);
}

}  // namespace HWY_NAMESPACE
}  // namespace manyworlds
HWY_AFTER_NAMESPACE();

#endif  // MANYWORLDS_KERNELS_DUAL_AXIS_INL_H_
