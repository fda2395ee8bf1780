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
// `where` (velocity steps only): the lanes that take the step (AddVelocityStep).
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
      AddPositionStep(*bodies.body1, linear, offset);
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
      AddPositionStep(*bodies.body2, linear, offset);
      AddRotationStep(*bodies.body2, angular, offset);
    }
  }
}

HWY_INLINE Vec3 LoadLambda(const PointLanes& part, std::size_t offset) {
  return LoadVec3(part.persistent.total_lambda, offset);
}

}  // namespace point

inline void PointCalculateProperties(const BodyPair& bodies,
                                     const PointGeometry& geometry, PointLanes& part) {
  ForEachChunk([&](std::size_t offset) {
    const Vec3 r1 = Rotate(LoadQuat(bodies.body1->rotation, offset),
                           LoadVec3(geometry.r1_local, offset));
    const Vec3 r2 = Rotate(LoadQuat(bodies.body2->rotation, offset),
                           LoadVec3(geometry.r2_local, offset));
    StoreVec3(r1, part.r1, offset);
    StoreVec3(r2, part.r2, offset);

    // Non-dynamic bodies add nothing to K; their cached I^-1 [r]x stays zero
    // so that 0 * cache is 0 in every later verb.
    Sym33 k = ZeroSym33();
    Mat33 a1 = ZeroMat33(), a2 = ZeroMat33();
    if (bodies.motion1 == MotionType::kDynamic) {
      a1 = point::InverseInertiaTimesCross(BodyInverseInertia(*bodies.body1, offset), r1);
      point::AddBodyToInverseEffectiveMass(Load(bodies.body1->inv_mass, offset), a1, r1, k);
    }
    if (bodies.motion2 == MotionType::kDynamic) {
      a2 = point::InverseInertiaTimesCross(BodyInverseInertia(*bodies.body2, offset), r2);
      point::AddBodyToInverseEffectiveMass(Load(bodies.body2->inv_mass, offset), a2, r2, k);
    }
    StoreMat33(a1, part.inv_i1_r1_cross, offset);
    StoreMat33(a2, part.inv_i2_r2_cross, offset);

    LaneMask active;
    StoreSym33(InverseSym33(k, active), part.effective_mass, offset);
    // Singular lanes are deactivated, which also clears their impulse.
    Vec3Lanes& lambda = part.persistent.total_lambda;
    StoreVec3(Select(active, LoadVec3(lambda, offset), ZeroVec3()), lambda, offset);
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

// Baumgarte step towards p1 = p2 with the lever arms and K^-1 of the last
// CalculateProperties (callers recompute them first). Returns true if any
// lane had a non-zero error.
inline bool PointSolvePosition(const BodyPair& bodies, const PointLanes& part,
                               float baumgarte) {
  const LaneVec minus_beta = Splat(-baumgarte);
  bool applied = false;
  ForEachChunk([&](std::size_t offset) {
    const Vec3 x1 = LoadVec3(bodies.body1->position, offset);
    const Vec3 x2 = LoadVec3(bodies.body2->position, offset);
    const Vec3 c = Sub(Add(Sub(x2, x1), LoadVec3(part.r2, offset)),
                       LoadVec3(part.r1, offset));
    // Jolt skips the step when C == 0; the select keeps those lanes exact even
    // if K^-1 is huge (0 * inf would be NaN).
    const LaneMask has_error = AnyComponentNonZero(c);
    const Vec3 k_inv_c = Multiply(LoadSym33(part.effective_mass, offset), c);
    const Vec3 lambda = Select(has_error, Scale(k_inv_c, minus_beta), ZeroVec3());
    point::ApplyImpulse<false>(bodies, part, lambda, offset);
    applied |= AnyLane(has_error);
  });
  return applied;
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
