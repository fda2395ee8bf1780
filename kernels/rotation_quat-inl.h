// RotationQuatConstraintPart across worlds: three angular rows that keep the
// rotation of body 2 relative to body 1 at its rest value r0, with the exact
// quaternion Jacobian instead of the rotation-Euler part's small-angle one.
// No Jolt constraint uses it. Spec 2.7.
//
//   r0^-1 = inverse rest rotation (q2 = q1 r0 at rest), b = q2 r0^-1.
//   C  = xyz(q1* b)   (no w sign normalisation: the Jacobian uses the same
//                      sign, so the two stay consistent)
//   JP = upper-left 3x3 of ML(a) MR(b), a = q1* / 2, where ML(a) p = a p and
//        MR(b) p = p b (quaternions as (x, y, z, w) 4-vectors). In closed form,
//        with [v]x the cross-product matrix and [v]x[u]x = u v^T - (v.u) E:
//        JP = (aw bw + av.bv) E + [bw av - aw bv]x - (bv av^T + av bv^T)
//   J  = [ 0, -JP, 0, JP ]
//   K  = JP ([dyn1] I1^-1 + [dyn2] I2^-1) JP^T   (symmetric 3x3)
//   K^-1 = adjugate / det, det == 0 => Deactivate.
//
// Velocity step:  dL = (K^-1 JP)(w1 - w2),  L += dL,
//                 w1 -= (I1^-1 JP^T) dL,  w2 += (I2^-1 JP^T) dL.
// Position step:  where C != 0: L = -beta K^-1 C, rotate body 1 by
//                 -(I1^-1 JP^T) L and body 2 by +(I2^-1 JP^T) L.
// Only dynamic bodies are written; static bodies read as zero velocity.

#if defined(MANYWORLDS_KERNELS_ROTATION_QUAT_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef MANYWORLDS_KERNELS_ROTATION_QUAT_INL_H_
#undef MANYWORLDS_KERNELS_ROTATION_QUAT_INL_H_
#else
#define MANYWORLDS_KERNELS_ROTATION_QUAT_INL_H_
#endif

#include <cstddef>

#include "kernels/body_access-inl.h"
#include "kernels/lane_math-inl.h"
#include "kernels/rotation_quat.h"

HWY_BEFORE_NAMESPACE();
namespace manyworlds {
namespace HWY_NAMESPACE {

namespace rotation_quat {

// JP = 1/2 A ML(q1*) MR(q2 r0^-1) A^T in the closed form of the header.
HWY_INLINE Mat33 JacobianBlock(const Quat& q1, const Quat& q2_inv_r0) {
  const LaneVec half = Splat(0.5f);
  const Vec3 av{hn::Mul(q1.x, hn::Neg(half)), hn::Mul(q1.y, hn::Neg(half)),
                hn::Mul(q1.z, hn::Neg(half))};
  const LaneVec aw = hn::Mul(q1.w, half);
  const Vec3 bv{q2_inv_r0.x, q2_inv_r0.y, q2_inv_r0.z};
  const LaneVec bw = q2_inv_r0.w;
  const LaneVec s = hn::MulAdd(aw, bw, Dot(av, bv));
  const Vec3 c = NegMulAdd(bv, aw, Scale(av, bw));  // bw av - aw bv
  const LaneVec a[3] = {av.x, av.y, av.z};
  const LaneVec b[3] = {bv.x, bv.y, bv.z};
  Mat33 jp;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      // -(b_i a_j + a_i b_j)
      jp.m[i][j] = hn::Neg(hn::MulAdd(b[i], a[j], hn::Mul(a[i], b[j])));
    }
  }
  jp.m[0][0] = hn::Add(jp.m[0][0], s);
  jp.m[1][1] = hn::Add(jp.m[1][1], s);
  jp.m[2][2] = hn::Add(jp.m[2][2], s);
  jp.m[0][1] = hn::Sub(jp.m[0][1], c.z);
  jp.m[0][2] = hn::Add(jp.m[0][2], c.y);
  jp.m[1][0] = hn::Add(jp.m[1][0], c.z);
  jp.m[1][2] = hn::Sub(jp.m[1][2], c.x);
  jp.m[2][0] = hn::Sub(jp.m[2][0], c.y);
  jp.m[2][1] = hn::Add(jp.m[2][1], c.x);
  return jp;
}

// Applies the impulse `lambda` of the three rows: body 1 gets
// -(I1^-1 JP^T) lambda, body 2 +(I2^-1 JP^T) lambda. kVelocity = false makes
// it a rotation step.
template <bool kVelocity>
HWY_INLINE void ApplyImpulse(const BodyPair& bodies, const RotationQuatLanes& part,
                             const Vec3& lambda, std::size_t offset) {
  if (bodies.motion1 == MotionType::kDynamic) {
    const Vec3 angular =
        Neg(Multiply(LoadMat33(part.inv_i1_jp_transposed, offset), lambda));
    if (kVelocity) {
      AddAngularVelocityStep(*bodies.body1, angular, offset);
    } else {
      AddRotationStep(*bodies.body1, angular, offset);
    }
  }
  if (bodies.motion2 == MotionType::kDynamic) {
    const Vec3 angular = Multiply(LoadMat33(part.inv_i2_jp_transposed, offset), lambda);
    if (kVelocity) {
      AddAngularVelocityStep(*bodies.body2, angular, offset);
    } else {
      AddRotationStep(*bodies.body2, angular, offset);
    }
  }
}

// I^-1 JP^T: column j is I^-1 (row j of JP).
HWY_INLINE Mat33 InverseInertiaTimesJacobianTransposed(const Sym33& inv_inertia,
                                                       const Mat33& jp) {
  return Multiply(inv_inertia, Transpose(jp));
}

}  // namespace rotation_quat

inline void RotationQuatCalculateProperties(const BodyPair& bodies,
                                            const QuatLanes& inv_initial_orientation,
                                            RotationQuatLanes& part) {
  ForEachChunk([&](std::size_t offset) {
    const Quat q1 = LoadQuat(bodies.body1->rotation, offset);
    const Quat q2 = LoadQuat(bodies.body2->rotation, offset);
    const Mat33 jp = rotation_quat::JacobianBlock(
        q1, Mul(q2, LoadQuat(inv_initial_orientation, offset)));

    // Non-dynamic bodies add nothing to K; their cached I^-1 JP^T stays zero
    // so that 0 * cache is 0 in every later verb.
    Mat33 inv_i1_jpt = ZeroMat33(), inv_i2_jpt = ZeroMat33();
    if (bodies.motion1 == MotionType::kDynamic) {
      inv_i1_jpt = rotation_quat::InverseInertiaTimesJacobianTransposed(
          BodyInverseInertia(*bodies.body1, offset), jp);
    }
    if (bodies.motion2 == MotionType::kDynamic) {
      inv_i2_jpt = rotation_quat::InverseInertiaTimesJacobianTransposed(
          BodyInverseInertia(*bodies.body2, offset), jp);
    }
    StoreMat33(inv_i1_jpt, part.inv_i1_jp_transposed, offset);
    StoreMat33(inv_i2_jpt, part.inv_i2_jp_transposed, offset);

    // K_ij = (row i of JP) . (column j of (I1^-1 + I2^-1) JP^T), upper triangle.
    auto entry = [&](int i, int j) {
      const Vec3 jp_row{jp.m[i][0], jp.m[i][1], jp.m[i][2]};
      const Vec3 column{hn::Add(inv_i1_jpt.m[0][j], inv_i2_jpt.m[0][j]),
                        hn::Add(inv_i1_jpt.m[1][j], inv_i2_jpt.m[1][j]),
                        hn::Add(inv_i1_jpt.m[2][j], inv_i2_jpt.m[2][j])};
      return Dot(jp_row, column);
    };
    const Sym33 k{entry(0, 0), entry(0, 1), entry(0, 2),
                  entry(1, 1), entry(1, 2), entry(2, 2)};
    LaneMask active;
    const Sym33 k_inv = InverseSym33(k, active);
    StoreSym33(k_inv, part.effective_mass, offset);
    // Zero where singular, since K^-1 is.
    StoreMat33(Multiply(k_inv, jp), part.effective_mass_jp, offset);
    // Singular lanes are deactivated, which also clears their impulse.
    ClearWhere(hn::Not(active), part.persistent.total_lambda, offset);
  });
}

inline void RotationQuatWarmStart(const BodyPair& bodies, RotationQuatLanes& part,
                                  float warm_start_ratio) {
  const LaneVec ratio = Splat(warm_start_ratio);
  ForEachChunk([&](std::size_t offset) {
    const Vec3 lambda = Scale(LoadVec3(part.persistent.total_lambda, offset), ratio);
    StoreVec3(lambda, part.persistent.total_lambda, offset);
    rotation_quat::ApplyImpulse<true>(bodies, part, lambda, offset);
  });
}

// Returns true if any lane applied a non-zero impulse.
inline bool RotationQuatSolveVelocity(const BodyPair& bodies, RotationQuatLanes& part) {
  bool applied = false;
  ForEachChunk([&](std::size_t offset) {
    // -J v = JP (w1 - w2)
    const Vec3 relative = Sub(AngularVelocity(*bodies.body1, bodies.motion1, offset),
                              AngularVelocity(*bodies.body2, bodies.motion2, offset));
    const Vec3 delta = Multiply(LoadMat33(part.effective_mass_jp, offset), relative);
    StoreVec3(Add(LoadVec3(part.persistent.total_lambda, offset), delta),
              part.persistent.total_lambda, offset);
    rotation_quat::ApplyImpulse<true>(bodies, part, delta, offset);
    applied |= AnyLane(AnyComponentNonZero(delta));
  });
  return applied;
}

// Baumgarte step towards q2 = q1 r0 with the properties of the last
// CalculateProperties (callers recompute them first). Returns true if any
// lane had a non-zero error.
inline bool RotationQuatSolvePosition(const BodyPair& bodies,
                                      const QuatLanes& inv_initial_orientation,
                                      const RotationQuatLanes& part, float baumgarte) {
  const LaneVec minus_beta = Splat(-baumgarte);
  bool applied = false;
  ForEachChunk([&](std::size_t offset) {
    const Quat q1 = LoadQuat(bodies.body1->rotation, offset);
    const Quat q2 = LoadQuat(bodies.body2->rotation, offset);
    const Quat error = Mul(Mul(Conjugate(q1), q2), LoadQuat(inv_initial_orientation, offset));
    const Vec3 c{error.x, error.y, error.z};
    // Jolt skips the step when C == 0; the select keeps those lanes exact even
    // if K^-1 is huge (0 * inf would be NaN).
    const LaneMask has_error = AnyComponentNonZero(c);
    const Vec3 k_inv_c = Multiply(LoadSym33(part.effective_mass, offset), c);
    const Vec3 lambda = Select(has_error, Scale(k_inv_c, minus_beta), ZeroVec3());
    rotation_quat::ApplyImpulse<false>(bodies, part, lambda, offset);
    applied |= AnyLane(has_error);
  });
  return applied;
}

// Deactivate lanes whose flag is set: zero K^-1, K^-1 JP and the accumulated
// impulse.
inline void RotationQuatDeactivate(RotationQuatLanes& part, const LaneFlags& lanes) {
  ForEachChunk([&](std::size_t offset) {
    const LaneMask off = LoadFlags(lanes, offset);
    ClearWhere(off, part.effective_mass, offset);
    ClearWhere(off, part.effective_mass_jp, offset);  // else K^-1 JP still applies
    ClearWhere(off, part.persistent.total_lambda, offset);
  });
}

// flag = 1 where K^-1 != 0 (Jolt's IsActive), else 0.
inline void RotationQuatIsActive(const RotationQuatLanes& part, LaneFlags& active) {
  StoreActiveLanes(part, active);
}

}  // namespace HWY_NAMESPACE
}  // namespace manyworlds
HWY_AFTER_NAMESPACE();

#endif  // MANYWORLDS_KERNELS_ROTATION_QUAT_INL_H_
