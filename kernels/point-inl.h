// PointConstraintPart across worlds: three linear rows that make the anchor
// points of two bodies coincide (ball joint; also inside fixed, hinge, cone,
// swing-twist and six-DOF constraints). Spec 2.4.
//
//   r1 = R1 r1_local, r2 = R2 r2_local (current rotations),
//   p1 = x1 + r1, p2 = x2 + r2.
//   C   = p2 - p1
//   J v = v2 + w2 x r2 - v1 - w1 x r1,  J = [ -E, [r1]x, E, -[r2]x ]
//   K   = J M^-1 J^T = [dyn1] (m1^-1 E + [r1]x I1^-1 [r1]x^T)
//                    + [dyn2] (m2^-1 E + [r2]x I2^-1 [r2]x^T)
//   K is symmetric; K^-1 = adjugate / det, det == 0 => Deactivate.
//   With A = I^-1 [r]x (cached): [r]x I^-1 [r]x^T = -[r]x A, whose column j
//   is (column j of A) x r.
//
// Velocity step:  s = -J v = v1 - r1 x w1 - v2 + r2 x w2
//                 dL = K^-1 s,  L += dL
//                 v1 -= m1^-1 dL, w1 -= A1 dL (= I1^-1 (r1 x dL)), body 2 +.
// Position step:  C from the current centres of mass and the cached r's;
//                 where C != 0: L = -beta K^-1 C, applied as position and
//                 rotation steps with the same vectors.
// Only dynamic bodies are written; static bodies read as zero velocity.

#if defined(MANYWORLDS_KERNELS_POINT_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef MANYWORLDS_KERNELS_POINT_INL_H_
#undef MANYWORLDS_KERNELS_POINT_INL_H_
#else
#define MANYWORLDS_KERNELS_POINT_INL_H_
#endif

#include <cstddef>

#include "kernels/body_access-inl.h"
#include "kernels/lane_math-inl.h"
#include "kernels/point.h"

HWY_BEFORE_NAMESPACE();
namespace manyworlds {
namespace HWY_NAMESPACE {

namespace point {

// I^-1 [r]x: column j is I^-1 (r x e_j), with r x e_x = (0, rz, -ry),
// r x e_y = (-rz, 0, rx), r x e_z = (ry, -rx, 0).
HWY_INLINE Mat33 InverseInertiaTimesCross(const Sym33& i, const Vec3& r) {
  Mat33 a;
  a.m[0][0] = DifferenceOfProducts(i.xy, r.z, i.xz, r.y);
  a.m[1][0] = DifferenceOfProducts(i.yy, r.z, i.yz, r.y);
  a.m[2][0] = DifferenceOfProducts(i.yz, r.z, i.zz, r.y);
  a.m[0][1] = DifferenceOfProducts(i.xz, r.x, i.xx, r.z);
  a.m[1][1] = DifferenceOfProducts(i.yz, r.x, i.xy, r.z);
  a.m[2][1] = DifferenceOfProducts(i.zz, r.x, i.xz, r.z);
  a.m[0][2] = DifferenceOfProducts(i.xx, r.y, i.xy, r.x);
  a.m[1][2] = DifferenceOfProducts(i.xy, r.y, i.yy, r.x);
  a.m[2][2] = DifferenceOfProducts(i.xz, r.y, i.yz, r.x);
  return a;
}

// Adds one dynamic body's terms to K: m^-1 E + [r]x I^-1 [r]x^T, the latter's
// column j being (column j of A) x r; only the upper triangle is kept.
HWY_INLINE void AddBodyToInverseEffectiveMass(LaneVec inv_mass, const Mat33& a,
                                              const Vec3& r, Sym33& k) {
  const Vec3 column0 = Cross(Column(a, 0), r);
  const Vec3 column1 = Cross(Column(a, 1), r);
  const Vec3 column2 = Cross(Column(a, 2), r);
  k.xx = hn::Add(k.xx, hn::Add(inv_mass, column0.x));
  k.xy = hn::Add(k.xy, column1.x);
  k.xz = hn::Add(k.xz, column2.x);
  k.yy = hn::Add(k.yy, hn::Add(inv_mass, column1.y));
  k.yz = hn::Add(k.yz, column2.y);
  k.zz = hn::Add(k.zz, hn::Add(inv_mass, column2.z));
}

// Applies the impulse `lambda` (world, linear): body 1 gets -J^T lambda,
// body 2 +J^T lambda. kVelocity = false makes it a position and rotation step.
// `where`: the lanes whose velocities or positions are stored
// (AddVelocityStep, AddPositionStep); a position step's caller also zeroes
// lambda in the other lanes, whose rotation step of zero then keeps q.
template <bool kVelocity, class Where = std::nullptr_t>
HWY_INLINE void ApplyImpulse(const BodyPair& bodies, const PointLanes& part,
                             const Vec3& lambda, std::size_t offset,
                             Where where = nullptr) {
  if (bodies.motion1 == MotionType::kDynamic) {
    const LaneVec inv_mass = Load(bodies.body1->inv_mass, offset);
    const Vec3 linear = Scale(lambda, hn::Neg(inv_mass));
    const Vec3 angular = Neg(Multiply(LoadMat33(part.inv_i1_r1_cross, offset), lambda));
    if (kVelocity) {
      AddVelocityStep(*bodies.body1, linear, angular, offset, where);
    } else {
      AddPositionStep(*bodies.body1, linear, offset, where);
      AddRotationStep(*bodies.body1, angular, offset);
    }
  }
  if (bodies.motion2 == MotionType::kDynamic) {
    const LaneVec inv_mass = Load(bodies.body2->inv_mass, offset);
    const Vec3 linear = Scale(lambda, inv_mass);
    const Vec3 angular = Multiply(LoadMat33(part.inv_i2_r2_cross, offset), lambda);
    if (kVelocity) {
      AddVelocityStep(*bodies.body2, linear, angular, offset, where);
    } else {
      AddPositionStep(*bodies.body2, linear, offset, where);
      AddRotationStep(*bodies.body2, angular, offset);
    }
  }
}

HWY_INLINE Vec3 LoadLambda(const PointLanes& part, std::size_t offset) {
  return LoadVec3(part.persistent.total_lambda, offset);
}

// The lever arms at the bodies' current rotations.
HWY_INLINE void LeverArms(const BodyPair& bodies, const PointGeometry& geometry,
                          std::size_t offset, Vec3& r1, Vec3& r2) {
  r1 = Rotate(LoadQuat(bodies.body1->rotation, offset), LoadVec3(geometry.r1_local, offset));
  r2 = Rotate(LoadQuat(bodies.body2->rotation, offset), LoadVec3(geometry.r2_local, offset));
}

// C = p2 - p1 from the current centres of mass and the lever arms r1, r2.
HWY_INLINE Vec3 Error(const BodyPair& bodies, const Vec3& r1, const Vec3& r2,
                      std::size_t offset) {
  const Vec3 x1 = LoadVec3(bodies.body1->position, offset);
  const Vec3 x2 = LoadVec3(bodies.body2->position, offset);
  return Sub(Add(Sub(x2, x1), r2), r1);
}

// Stores r1, r2, I^-1 [r]x and K^-1 (CalculateProperties of one chunk);
// returns the lanes where K is invertible (the others get K^-1 = 0: Jolt's
// Deactivate, whose clearing of the impulse is the caller's).
HWY_INLINE LaneMask StoreProperties(const BodyPair& bodies, const Vec3& r1, const Vec3& r2,
                                    PointLanes& part, std::size_t offset) {
  StoreVec3(r1, part.r1, offset);
  StoreVec3(r2, part.r2, offset);
  // Non-dynamic bodies add nothing to K; their cached I^-1 [r]x stays zero
  // so that 0 * cache is 0 in every later verb.
  Sym33 k = ZeroSym33();
  Mat33 a1 = ZeroMat33(), a2 = ZeroMat33();
  if (bodies.motion1 == MotionType::kDynamic) {
    a1 = InverseInertiaTimesCross(BodyInverseInertia(*bodies.body1, offset), r1);
    AddBodyToInverseEffectiveMass(Load(bodies.body1->inv_mass, offset), a1, r1, k);
  }
  if (bodies.motion2 == MotionType::kDynamic) {
    a2 = InverseInertiaTimesCross(BodyInverseInertia(*bodies.body2, offset), r2);
    AddBodyToInverseEffectiveMass(Load(bodies.body2->inv_mass, offset), a2, r2, k);
  }
  StoreMat33(a1, part.inv_i1_r1_cross, offset);
  StoreMat33(a2, part.inv_i2_r2_cross, offset);
  LaneMask active;
  StoreSym33(InverseSym33(k, active), part.effective_mass, offset);
  return active;
}

// Baumgarte step L = -beta K^-1 C in the lanes of `with_error` (C != 0).
// Jolt skips the others; here they take no step at all, not even a zero one
// (SteppingLanes), and the select keeps them exact even if K^-1 is huge
// (0 * inf would be NaN).
HWY_INLINE void PositionStep(const BodyPair& bodies, const PointLanes& part, const Vec3& c,
                             const SteppingLanes& with_error, LaneVec minus_beta,
                             std::size_t offset) {
  const Vec3 lambda = Scale(Multiply(LoadSym33(part.effective_mass, offset), c), minus_beta);
  if (with_error.every) {
    ApplyImpulse<false>(bodies, part, lambda, offset);
  } else {
    ApplyImpulse<false>(bodies, part, Select(with_error.mask, lambda, ZeroVec3()), offset,
                        &with_error.mask);
  }
}

}  // namespace point

inline void PointCalculateProperties(const BodyPair& bodies,
                                     const PointGeometry& geometry, PointLanes& part) {
  ForEachChunk([&](std::size_t offset) {
    Vec3 r1, r2;
    point::LeverArms(bodies, geometry, offset, r1, r2);
    const LaneMask active = point::StoreProperties(bodies, r1, r2, part, offset);
    // Singular lanes are deactivated, which also clears their impulse.
    ClearWhere(hn::Not(active), part.persistent.total_lambda, offset);
  });
}

inline void PointWarmStart(const BodyPair& bodies, PointLanes& part,
                           float warm_start_ratio) {
  const LaneVec ratio = Splat(warm_start_ratio);
  ForEachChunk([&](std::size_t offset) {
    const Vec3 lambda = Scale(point::LoadLambda(part, offset), ratio);
    StoreVec3(lambda, part.persistent.total_lambda, offset);
    point::ApplyImpulse<true>(bodies, part, lambda, offset);
  });
}

// Returns true if any lane applied a non-zero impulse.
inline bool PointSolveVelocity(const BodyPair& bodies, PointLanes& part) {
  bool applied = false;
  ForEachChunk([&](std::size_t offset) {
    // s = -J v = v1 - r1 x w1 - v2 + r2 x w2; a static body contributes nothing.
    Vec3 s = ZeroVec3();
    if (bodies.motion1 != MotionType::kStatic) {
      s = Sub(LoadVec3(bodies.body1->linear_velocity, offset),
              Cross(LoadVec3(part.r1, offset),
                    LoadVec3(bodies.body1->angular_velocity, offset)));
    }
    if (bodies.motion2 != MotionType::kStatic) {
      s = Add(Sub(s, LoadVec3(bodies.body2->linear_velocity, offset)),
              Cross(LoadVec3(part.r2, offset),
                    LoadVec3(bodies.body2->angular_velocity, offset)));
    }
    // A lane whose anchors move together exactly (bodies turning about
    // the joint's axis through their centres: gears, pinions) takes no step
    // (SteppingLanes).
    const SteppingLanes apart = LanesThatStep(AnyComponentNonZero(s));
    if (apart.none) return;
    const Vec3 delta = Multiply(LoadSym33(part.effective_mass, offset), s);
    const Vec3 lambda = point::LoadLambda(part, offset);
    if (apart.every) {
      StoreVec3(Add(lambda, delta), part.persistent.total_lambda, offset);
      point::ApplyImpulse<true>(bodies, part, delta, offset);
    } else {
      StoreVec3(Select(apart.mask, Add(lambda, delta), lambda), part.persistent.total_lambda,
                offset);
      point::ApplyImpulse<true>(bodies, part, delta, offset, &apart.mask);
    }
    applied |= AnyLane(hn::And(apart.mask, AnyComponentNonZero(delta)));
  });
  return applied;
}

namespace point {

// One position pass: C from the lever arms of the last CalculateProperties,
// or with kRecompute from those at the current rotations (`geometry`), and
// the step in every chunk where some lane has an error, with kRecompute the
// properties recomputed there first and the impulses of singular lanes with
// an error cleared.
template <bool kRecompute, class Part>
HWY_INLINE bool PositionPass(const BodyPair& bodies, const PointGeometry* geometry, Part& part,
                             float baumgarte) {
  const LaneVec minus_beta = Splat(-baumgarte);
  bool applied = false;
  ForEachChunk([&](std::size_t offset) {
    Vec3 r1, r2;
    if constexpr (kRecompute) {
      LeverArms(bodies, *geometry, offset, r1, r2);
    } else {
      r1 = LoadVec3(part.r1, offset);
      r2 = LoadVec3(part.r2, offset);
    }
    const Vec3 c = Error(bodies, r1, r2, offset);
    const SteppingLanes with_error = LanesThatStep(AnyComponentNonZero(c));
    if (with_error.none) return;
    if constexpr (kRecompute) {
      const LaneMask active = StoreProperties(bodies, r1, r2, part, offset);
      ClearWhere(hn::AndNot(active, with_error.mask), part.persistent.total_lambda, offset);
    }
    PositionStep(bodies, part, c, with_error, minus_beta, offset);
    applied = true;
  });
  return applied;
}

}  // namespace point

// Baumgarte step towards p1 = p2 with the lever arms and K^-1 of the last
// CalculateProperties (callers recompute them first). Returns true if any
// lane had a non-zero error.
inline bool PointSolvePosition(const BodyPair& bodies, const PointLanes& part,
                               float baumgarte) {
  return point::PositionPass<false>(bodies, nullptr, part, baumgarte);
}

// The position phase's verb: the properties at the current rotations, then
// one Baumgarte step. A lane whose C is exactly zero takes no step and is
// left exactly as it is (its impulse is not cleared even if K has become
// singular since the setup, where Jolt's recompute would clear it); where
// that holds in every lane of a chunk (anchors at the centres of bodies that
// turn about them: gears, pinions, wheels on axles) the properties are not
// computed, and the part's cached properties keep their setup values, which
// nothing reads before the next setup. Returns true if any lane had a
// non-zero error.
inline bool PointRecomputeAndSolvePosition(const BodyPair& bodies,
                                           const PointGeometry& geometry, PointLanes& part,
                                           float baumgarte) {
  return point::PositionPass<true>(bodies, &geometry, part, baumgarte);
}

// Jolt's Deactivate of the flagged lanes: K^-1 = 0 and accumulated impulse = 0.
inline void PointDeactivate(PointLanes& part, const LaneFlags& lanes) {
  DeactivateFlaggedLanes(part, lanes);
}

// flag = 1 where K^-1 != 0 (Jolt's IsActive), else 0.
inline void PointIsActive(const PointLanes& part, LaneFlags& active) {
  StoreActiveLanes(part, active);
}

}  // namespace HWY_NAMESPACE
}  // namespace manyworlds
HWY_AFTER_NAMESPACE();

#endif  // MANYWORLDS_KERNELS_POINT_INL_H_
