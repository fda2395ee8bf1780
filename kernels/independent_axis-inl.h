// IndependentAxisConstraintPart across worlds: one linear row over two axes,
// one per body (the pulley: body 1 moves along n1, body 2 along n2, the rope
// length through both is limited). Spec 2.11.
//
//   C = (x1 + r1 - f1).n1 + r (x2 + r2 - f2).n2 - length   (dn/dt ~ 0 assumed)
//   J = [n1, r1 x n1, r n2, r (r2 x n2)]                   (both positive)
//   K = [!static1] (m1^-1 + (r1 x n1).I1^-1 (r1 x n1))
//     + [!static2] (r^2 m2^-1 + r (r2 x n2).I2^-1 r (r2 x n2));  K == 0 => Deactivate
//   Velocity: dL = -K^-1 J v; L_new = clamp(L + dL, min, max), dL = L_new - L,
//             L = L_new; v1 += dL m1^-1 n1, w1 += dL I1^-1 (r1 x n1),
//             v2 += dL r m2^-1 n2, w2 += dL I2^-1 r (r2 x n2) (dynamic only).
//   Position: where C != 0: L = -K^-1 beta C, positions and rotations moved
//             by the same vectors (dynamic only).
//
// Jolt's motion-type rule kept on purpose (spec 1.5): the Jacobian and the
// mass terms of K are those of every body that is not static, so a kinematic
// body's stored mass enters K (Jolt asserts against it in debug builds), while
// impulses only reach dynamic bodies. In such lanes one solve does not bring
// J v to zero.

#if defined(MANYWORLDS_KERNELS_INDEPENDENT_AXIS_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef MANYWORLDS_KERNELS_INDEPENDENT_AXIS_INL_H_
#undef MANYWORLDS_KERNELS_INDEPENDENT_AXIS_INL_H_
#else
#define MANYWORLDS_KERNELS_INDEPENDENT_AXIS_INL_H_
#endif

#include <cstddef>

#include "kernels/body_access-inl.h"
#include "kernels/independent_axis.h"
#include "kernels/lane_math-inl.h"

HWY_BEFORE_NAMESPACE();
namespace manyworlds {
namespace HWY_NAMESPACE {

namespace independent_axis {

// Applies lambda along J^T to the dynamic bodies: kVelocity = true adds to
// the velocities, false moves positions and rotations (position phase).
template <bool kVelocity>
HWY_INLINE void ApplyImpulse(const BodyPair& bodies,
                             const IndependentAxisGeometry& geometry,
                             const IndependentAxisLanes& part, LaneVec lambda,
                             std::size_t offset) {
  if (bodies.motion1 == MotionType::kDynamic) {
    const Vec3 linear = Scale(LoadVec3(geometry.n1, offset),
                              hn::Mul(Load(bodies.body1->inv_mass, offset), lambda));
    const Vec3 angular = Scale(LoadVec3(part.inv_i1_r1_x_n1, offset), lambda);
    if (kVelocity) {
      AddVelocityStep(*bodies.body1, linear, angular, offset);
    } else {
      AddPositionStep(*bodies.body1, linear, offset);
      AddRotationStep(*bodies.body1, angular, offset);
    }
  }
  if (bodies.motion2 == MotionType::kDynamic) {
    const LaneVec ratio_inv_mass =
        hn::Mul(Load(geometry.ratio, offset), Load(bodies.body2->inv_mass, offset));
    const Vec3 linear =
        Scale(LoadVec3(geometry.n2, offset), hn::Mul(ratio_inv_mass, lambda));
    const Vec3 angular = Scale(LoadVec3(part.inv_i2_ratio_r2_x_n2, offset), lambda);
    if (kVelocity) {
      AddVelocityStep(*bodies.body2, linear, angular, offset);
    } else {
      AddPositionStep(*bodies.body2, linear, offset);
      AddRotationStep(*bodies.body2, angular, offset);
    }
  }
}

}  // namespace independent_axis

inline void IndependentAxisCalculateProperties(const BodyPair& bodies,
                                               const IndependentAxisGeometry& geometry,
                                               IndependentAxisLanes& part) {
  ForEachChunk([&](std::size_t offset) {
    // Static bodies contribute nothing: zero Jacobian terms, no mass.
    Vec3 r1_x_n1 = ZeroVec3(), inv_i1_r1_x_n1 = ZeroVec3();
    Vec3 ratio_r2_x_n2 = ZeroVec3(), inv_i2_ratio_r2_x_n2 = ZeroVec3();
    LaneVec k = Zero();
    if (bodies.motion1 != MotionType::kStatic) {
      r1_x_n1 = Cross(LoadVec3(geometry.r1, offset), LoadVec3(geometry.n1, offset));
      inv_i1_r1_x_n1 = BodyInverseInertiaTimes(*bodies.body1, r1_x_n1, offset);
      k = hn::Add(Load(bodies.body1->inv_mass, offset), Dot(inv_i1_r1_x_n1, r1_x_n1));
    }
    if (bodies.motion2 != MotionType::kStatic) {
      const LaneVec ratio = Load(geometry.ratio, offset);
      ratio_r2_x_n2 = Scale(
          Cross(LoadVec3(geometry.r2, offset), LoadVec3(geometry.n2, offset)), ratio);
      inv_i2_ratio_r2_x_n2 = BodyInverseInertiaTimes(*bodies.body2, ratio_r2_x_n2, offset);
      const LaneVec body2_term =
          hn::MulAdd(hn::Mul(ratio, ratio), Load(bodies.body2->inv_mass, offset),
                     Dot(inv_i2_ratio_r2_x_n2, ratio_r2_x_n2));
      k = hn::Add(k, body2_term);
    }
    LaneMask active;
    const LaneVec effective_mass = ReciprocalOrZero(k, active);
    StoreVec3(r1_x_n1, part.r1_x_n1, offset);
    StoreVec3(inv_i1_r1_x_n1, part.inv_i1_r1_x_n1, offset);
    StoreVec3(ratio_r2_x_n2, part.ratio_r2_x_n2, offset);
    StoreVec3(inv_i2_ratio_r2_x_n2, part.inv_i2_ratio_r2_x_n2, offset);
    Store(effective_mass, part.effective_mass, offset);
    LaneArray& lambda = part.persistent.total_lambda;
    Store(hn::IfThenElseZero(active, Load(lambda, offset)), lambda, offset);
  });
}

// Scales the impulse of the previous step by dt/dt_prev and applies it, with
// no clamp (Jolt's WarmStart).
inline void IndependentAxisWarmStart(const BodyPair& bodies,
                                     const IndependentAxisGeometry& geometry,
                                     IndependentAxisLanes& part,
                                     float warm_start_ratio) {
  const LaneVec ratio = Splat(warm_start_ratio);
  ForEachChunk([&](std::size_t offset) {
    LaneArray& total = part.persistent.total_lambda;
    const LaneVec lambda = hn::Mul(Load(total, offset), ratio);
    Store(lambda, total, offset);
    independent_axis::ApplyImpulse<true>(bodies, geometry, part, lambda, offset);
  });
}

// Returns true if any lane applied a non-zero impulse.
inline bool IndependentAxisSolveVelocity(const BodyPair& bodies,
                                         const IndependentAxisGeometry& geometry,
                                         IndependentAxisLanes& part) {
  bool applied = false;
  ForEachChunk([&](std::size_t offset) {
    const Vec3 v1 = LinearVelocity(*bodies.body1, bodies.motion1, offset);
    const Vec3 w1 = AngularVelocity(*bodies.body1, bodies.motion1, offset);
    const Vec3 v2 = LinearVelocity(*bodies.body2, bodies.motion2, offset);
    const Vec3 w2 = AngularVelocity(*bodies.body2, bodies.motion2, offset);
    // J v = n1.v1 + (r1 x n1).w1 + r n2.v2 + r (r2 x n2).w2
    const LaneVec body1_rate =
        hn::Add(Dot(LoadVec3(geometry.n1, offset), v1),
                Dot(LoadVec3(part.r1_x_n1, offset), w1));
    const LaneVec body2_rate =
        hn::MulAdd(Load(geometry.ratio, offset), Dot(LoadVec3(geometry.n2, offset), v2),
                   Dot(LoadVec3(part.ratio_r2_x_n2, offset), w2));
    const LaneVec unclamped_delta = hn::Neg(
        hn::Mul(Load(part.effective_mass, offset), hn::Add(body1_rate, body2_rate)));
    // Clamp the accumulated impulse, not the increment (spec 1.1).
    LaneArray& total = part.persistent.total_lambda;
    const LaneVec old_total = Load(total, offset);
    const LaneVec new_total =
        hn::Min(hn::Max(hn::Add(old_total, unclamped_delta),
                        Load(geometry.min_lambda, offset)),
                Load(geometry.max_lambda, offset));
    const LaneVec delta = hn::Sub(new_total, old_total);
    Store(new_total, total, offset);
    independent_axis::ApplyImpulse<true>(bodies, geometry, part, delta, offset);
    applied |= AnyLane(hn::Ne(delta, Zero()));
  });
  return applied;
}

// Baumgarte step for the caller's position error C. Returns true if any lane
// had a non-zero error.
inline bool IndependentAxisSolvePosition(const BodyPair& bodies,
                                         const IndependentAxisGeometry& geometry,
                                         const LaneArray& error,
                                         const IndependentAxisLanes& part,
                                         float baumgarte) {
  const LaneVec minus_beta = Splat(-baumgarte);
  bool applied = false;
  ForEachChunk([&](std::size_t offset) {
    const LaneVec c = Load(error, offset);
    const LaneMask has_error = hn::Ne(c, Zero());
    const LaneVec lambda = hn::IfThenElseZero(
        has_error, hn::Mul(hn::Mul(minus_beta, Load(part.effective_mass, offset)), c));
    independent_axis::ApplyImpulse<false>(bodies, geometry, part, lambda, offset);
    applied |= AnyLane(has_error);
  });
  return applied;
}

// Jolt's Deactivate of the flagged lanes: K^-1 = 0 and accumulated impulse = 0.
inline void IndependentAxisDeactivate(IndependentAxisLanes& part, const LaneFlags& lanes) {
  DeactivateFlaggedLanes(part, lanes);
}

// flag = 1 where K^-1 != 0 (Jolt's IsActive), else 0.
inline void IndependentAxisIsActive(const IndependentAxisLanes& part, LaneFlags& active) {
  StoreActiveLanes(part, active);
}

}  // namespace HWY_NAMESPACE
}  // namespace manyworlds
HWY_AFTER_NAMESPACE();

#endif  // MANYWORLDS_KERNELS_INDEPENDENT_AXIS_INL_H_
