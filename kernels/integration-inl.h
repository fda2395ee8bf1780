// Body integration across worlds: the first and the integration stage of
// Jolt's step (spec 4.1, steps 1 and 6).
//
// Forces (dynamic bodies, once per substep, before the constraints):
//   with StepSettings::gyroscopic only, w <- the implicit-midpoint gyroscopic
//   step (ApplyGyroscopicStep below, derived in reference/gyroscopic.h); then
//   v <- lockT(v + dt (gravity_factor g + m^-1 F))
//   w <- w + dt I^-1 tau                     (inertia at the current rotation,
//                                             locked rotation axes masked)
//   v <- v max(0, 1 - c_lin dt),  w <- w max(0, 1 - c_ang dt)
//   |v| <= v_max, |w| <= w_max               (uniform rescale when exceeded)
//   A lane whose |v|^2 or |w|^2 overflows float here (forces of ~1e30) is
//   marked in WorldHealthLanes::velocity_overflow: Jolt's clamp would turn
//   that velocity into 0 (v * max / inf) without a word.
// Integration (after the velocity iterations):
//   dynamic bodies clamp |v|, |w| again; then q <- AddRotationStep(w dt)
//   (exact axis-angle, normalised, skipped below 1e-6 rad) and
//   x <- x + lockT(v dt) (symplectic Euler: new velocity, rotation before
//   translation). Kinematic bodies integrate the same way without clamps;
//   static bodies never move. lockT zeroes the locked translation axes of a
//   body with allowed DOFs (spec 4.3); see body_access-inl.h.

#if defined(MANYWORLDS_KERNELS_INTEGRATION_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef MANYWORLDS_KERNELS_INTEGRATION_INL_H_
#undef MANYWORLDS_KERNELS_INTEGRATION_INL_H_
#else
#define MANYWORLDS_KERNELS_INTEGRATION_INL_H_
#endif

#include <cstddef>

#include "kernels/body_access-inl.h"
#include "kernels/body_lanes.h"
#include "kernels/lane_math-inl.h"

HWY_BEFORE_NAMESPACE();
namespace manyworlds {
namespace HWY_NAMESPACE {

// Jolt's ClampLinear/AngularVelocity: v *= max / |v| where |v|^2 > max^2.
HWY_INLINE Vec3 ClampLength(const Vec3& v, LaneVec max_length) {
  const LaneVec length_squared = LengthSquared(v);
  const LaneMask too_fast = hn::Gt(length_squared, hn::Mul(max_length, max_length));
  // The clamp is rare: a chunk where no lane is too fast keeps v without the
  // square root and division.
  if (hn::AllFalse(LaneTag(), too_fast)) return v;
  const LaneVec scale = hn::Div(max_length, hn::Sqrt(length_squared));
  return Select(too_fast, Scale(v, scale), v);
}

// The opt-in gyroscopic step (StepSettings::gyroscopic) for one dynamic body
// of a block, before its forces in every substep: the implicit-midpoint
// solution of Euler's torque-free equations in the principal frame, two
// Newton steps, a lane whose Jacobian determinant is not positive keeping its
// w, and the result rescaled to the energy of w. The derivation, and why
// this stays stable for any step, is at the top of reference/gyroscopic.h,
// which this follows operation for operation. Lanes whose rotation DOFs are
// restricted keep w.
HWY_INLINE void ApplyGyroscopicStep(BodyLanes& body, LaneVec h) {
  const LaneVec half = Splat(0.5f);
  const LaneVec half_h = hn::Mul(half, h);
  ForEachChunk([&](std::size_t offset) {
    const Quat to_world =
        Mul(LoadQuat(body.rotation, offset), LoadQuat(body.inertia_rotation, offset));
    const Vec3 w_world = LoadVec3(body.angular_velocity, offset);
    const Vec3 w0 = InverseRotate(to_world, w_world);
    const Vec3 d = LoadVec3(body.inv_inertia_diagonal, offset);
    const Vec3 inertia{hn::Div(Splat(1.0f), d.x), hn::Div(Splat(1.0f), d.y),
                       hn::Div(Splat(1.0f), d.z)};
    const auto times_inertia = [&](const Vec3& v) {
      return Vec3{hn::Mul(inertia.x, v.x), hn::Mul(inertia.y, v.y), hn::Mul(inertia.z, v.z)};
    };
    LaneMask solved = AllLanes();
    if (DofRestricted(body)) {
      const Vec3 locked = LoadVec3(Locks(body).rotation_locked, offset);
      solved = hn::Not(AnyComponentNonZero(locked));
    }
    Vec3 w1 = w0;
    for (int newton = 0; newton < 2; ++newton) {
      const Vec3 wm = Scale(Add(w0, w1), half);
      const Vec3 iwm = times_inertia(wm);
      const Vec3 g = MulAdd(Cross(wm, iwm), h, times_inertia(Sub(w1, w0)));
      // J = I + h/2 (S(wm) I - S(I wm)): off the diagonal, row r and column c
      // hold h/2 (S(wm)[r][c] I[c] - S(I wm)[r][c]); S's diagonal is zero.
      const auto off = [&](LaneVec s_w, LaneVec inertia_c, LaneVec s_iw) {
        return hn::Mul(half_h, hn::MulSub(s_w, inertia_c, s_iw));
      };
      const Vec3 r0{inertia.x, off(hn::Neg(wm.z), inertia.y, hn::Neg(iwm.z)),
                    off(wm.y, inertia.z, iwm.y)};
      const Vec3 r1{off(wm.z, inertia.x, iwm.z), inertia.y,
                    off(hn::Neg(wm.x), inertia.z, hn::Neg(iwm.x))};
      const Vec3 r2{off(hn::Neg(wm.y), inertia.x, hn::Neg(iwm.y)), off(wm.x, inertia.y, iwm.x),
                    inertia.z};
      const Vec3 c0 = Cross(r1, r2), c1 = Cross(r2, r0), c2 = Cross(r0, r1);
      const LaneVec det = Dot(r0, c0);
      solved = hn::And(solved, hn::Gt(det, Zero()));
      const Vec3 step = MulAdd(c0, g.x, MulAdd(c1, g.y, Scale(c2, g.z)));
      // Lanes already given up divide by 1, not by a zero determinant.
      w1 = Sub(w1, Scale(step, hn::Div(Splat(1.0f), hn::IfThenElse(solved, det, Splat(1.0f)))));
    }
    const LaneVec energy0 = Dot(w0, times_inertia(w0));
    const LaneVec energy1 = Dot(w1, times_inertia(w1));
    solved = hn::And(solved, hn::And(hn::Gt(energy1, Zero()), hn::IsFinite(energy1)));
    const LaneVec safe_energy1 = hn::IfThenElse(solved, energy1, Splat(1.0f));
    w1 = Scale(w1, hn::Sqrt(hn::Div(energy0, safe_energy1)));
    StoreVec3(Select(solved, Rotate(to_world, w1), w_world), body.angular_velocity, offset);
  });
}

// Step 1 for one dynamic body of a block; clears the force and torque after
// use only at the end of the whole step (the caller), as they act in every
// substep.
HWY_INLINE void ApplyForcesAndDamping(BodyLanes& body, const BodyMotionLanes& motion,
                                      const Vec3& gravity, LaneVec delta_time,
                                      WorldHealthLanes& health) {
  ForEachChunk([&](std::size_t offset) {
    const LaneVec inv_mass = Load(body.inv_mass, offset);
    const LaneVec gravity_factor = Load(motion.gravity_factor, offset);
    const Vec3 acceleration =
        MulAdd(LoadVec3(motion.force, offset), inv_mass, Scale(gravity, gravity_factor));
    Vec3 linear = LockTranslation(
        body, MulAdd(acceleration, delta_time, LoadVec3(body.linear_velocity, offset)), offset);
    Vec3 angular =
        MulAdd(BodyInverseInertiaTimes(body, LoadVec3(motion.torque, offset), offset),
               delta_time, LoadVec3(body.angular_velocity, offset));
    const LaneVec one = Splat(1.0f);
    const LaneVec linear_keep =
        hn::Max(Zero(), hn::NegMulAdd(Load(motion.linear_damping, offset), delta_time, one));
    const LaneVec angular_keep =
        hn::Max(Zero(), hn::NegMulAdd(Load(motion.angular_damping, offset), delta_time, one));
    linear = Scale(linear, linear_keep);
    angular = Scale(angular, angular_keep);
    const LaneMask overflow =
        hn::Or(hn::IsInf(LengthSquared(linear)), hn::IsInf(LengthSquared(angular)));
    Store(hn::Max(Load(health.velocity_overflow, offset),
                  hn::IfThenElseZero(overflow, Splat(1.0f))),
          health.velocity_overflow, offset);
    linear = ClampLength(linear, Load(motion.max_linear_velocity, offset));
    angular = ClampLength(angular, Load(motion.max_angular_velocity, offset));
    StoreVec3(linear, body.linear_velocity, offset);
    StoreVec3(angular, body.angular_velocity, offset);
  });
}

// Step 6 for one body of a block. `motion` is null for kinematic bodies (no
// clamps); static bodies are not integrated at all.
HWY_INLINE void IntegrateBody(BodyLanes& body, const BodyMotionLanes* motion,
                              LaneVec delta_time) {
  ForEachChunk([&](std::size_t offset) {
    Vec3 linear = LoadVec3(body.linear_velocity, offset);
    Vec3 angular = LoadVec3(body.angular_velocity, offset);
    if (motion != nullptr) {
      linear = ClampLength(linear, Load(motion->max_linear_velocity, offset));
      angular = ClampLength(angular, Load(motion->max_angular_velocity, offset));
      StoreVec3(linear, body.linear_velocity, offset);
      StoreVec3(angular, body.angular_velocity, offset);
    }
    AddRotationStep(body, Scale(angular, delta_time), offset);
    AddPositionStep(body, Scale(linear, delta_time), offset);
  });
}

// After a Step: marks the lanes where the body's position, rotation or
// velocities are not finite, or a coordinate lies beyond max_coordinate.
HWY_INLINE void CheckBodyHealth(const BodyLanes& body, LaneVec max_coordinate,
                                WorldHealthLanes& health) {
  ForEachChunk([&](std::size_t offset) {
    const Vec3 position = LoadVec3(body.position, offset);
    const Quat rotation = LoadQuat(body.rotation, offset);
    const Vec3 linear = LoadVec3(body.linear_velocity, offset);
    const Vec3 angular = LoadVec3(body.angular_velocity, offset);
    LaneMask finite = hn::IsFinite(rotation.w);
    for (const Vec3* v : {&position, &linear, &angular}) {
      finite = hn::And(finite, hn::And(hn::IsFinite(v->x),
                                       hn::And(hn::IsFinite(v->y), hn::IsFinite(v->z))));
    }
    finite = hn::And(finite, hn::And(hn::IsFinite(rotation.x),
                                     hn::And(hn::IsFinite(rotation.y), hn::IsFinite(rotation.z))));
    const LaneMask non_finite = hn::Not(finite);
    const LaneVec farthest =
        hn::Max(hn::Max(hn::Abs(position.x), hn::Abs(position.y)), hn::Abs(position.z));
    // Only finite lanes: Max of a NaN differs between targets.
    const LaneMask out_of_range = hn::And(finite, hn::Gt(farthest, max_coordinate));
    const LaneVec one = Splat(1.0f);
    Store(hn::Max(Load(health.non_finite, offset), hn::IfThenElseZero(non_finite, one)),
          health.non_finite, offset);
    Store(hn::Max(Load(health.out_of_range, offset), hn::IfThenElseZero(out_of_range, one)),
          health.out_of_range, offset);
  });
}

}  // namespace HWY_NAMESPACE
}  // namespace manyworlds
HWY_AFTER_NAMESPACE();

#endif  // MANYWORLDS_KERNELS_INTEGRATION_INL_H_
