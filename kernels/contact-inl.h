// A contact manifold across worlds: Jolt's contact constraint (spec:
// jolt-contacts.md sections 3-6, the friction model of its main text; our
// choices in docs/contacts.md). The caller (batch/contact_constraint-inl.h)
// finds the points; this part turns them into rows and solves them.
//
// Per kept point i, with p1_i on body 1, p2_i on body 2, n from 1 to 2:
//   p_i = (p1_i + p2_i)/2, r1 = p_i - x1, r2 = p_i - x2, s_i = (p2_i - p1_i).n
//   normal row: an axis row along n (kernels/axis-inl.h) with impulse >= 0 and
//   bias b = max(0, s/dt)                                     (speculative)
//        b = e (v_n - dv_f)   if e > 0, v_n < -v_min and v_n < -max(0, s/dt)
//   with v_n = (v2 + w2 x r2 - v1 - w1 x r1).n at setup and
//   dv_f = min(0, dt a_rel.n) (the velocity the substep's forces added: a
//   bounce starts from the approach speed before them).
// Friction (mu > 0): anchor c = mean of the kept p_i; t1 = perp(n), t2 = n x t1;
//   two axis rows at c, solved from the same velocities and clamped together
//   to the circle |L_t| <= mu sum_i L_n,i; with >= 2 points an angular row
//   about n, K = n.I1^-1 n + n.I2^-1 n, clamped to +-mu sum_i d_i L_n,i with
//   d_i = |(p_i - c) x n| (distance from the anchor across n).
// Warm start: t1, t2, angular, then normals in point order, L <- ratio L.
//   A new point takes the normal impulse of the first of last step's points
//   within 1 cm on both bodies (body frames); friction impulses carry over
//   where the manifold existed last step.
// Velocity pass: linear friction, angular friction, then each normal row.
// Position pass, point by point with the setup's n and body points, from the
//   poses at the start of the manifold's pass: C = max(s + slop, -max_pen);
//   where C < 0 one Baumgarte step -beta C / K at the current poses.
// Rows of points not kept, and friction rows without friction, have zero
// effective mass and impulse, so they change no bit of the velocities.

#if defined(MANYWORLDS_KERNELS_CONTACT_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef MANYWORLDS_KERNELS_CONTACT_INL_H_
#undef MANYWORLDS_KERNELS_CONTACT_INL_H_
#else
#define MANYWORLDS_KERNELS_CONTACT_INL_H_
#endif

#include <cstddef>

#include "kernels/axis-inl.h"
#include "kernels/body_access-inl.h"
#include "kernels/contact.h"
#include "kernels/lane_math-inl.h"

HWY_BEFORE_NAMESPACE();
namespace manyworlds {
namespace HWY_NAMESPACE {

// Points found in one chunk by a pair's collision routine: up to
// kMaxContactPoints pairs (p1 on body 1, p2 on body 2) and whether each is
// kept, with the normal from body 1 to body 2. Kept points are a subset of
// the lanes where the manifold exists.
struct ContactCandidates {
  Vec3 normal;
  Vec3 point1[kMaxContactPoints];
  Vec3 point2[kMaxContactPoints];
  LaneMask keep[kMaxContactPoints];
};

// Uniform numbers of a contact's setup and position steps.
struct ContactScalars {
  LaneVec delta_time;
  LaneVec min_velocity_for_restitution;
  LaneVec penetration_slop;
  LaneVec max_penetration_distance;
  LaneVec baumgarte;
};

// (v2 + w2 x r2 - v1 - w1 x r1).n at the bodies' current velocities.
HWY_INLINE LaneVec ContactRelativeNormalVelocity(const BodyPair& bodies, const Vec3& r1,
                                                 const Vec3& r2, const Vec3& n,
                                                 std::size_t offset) {
  const Vec3 v1 = Add(LinearVelocity(*bodies.body1, bodies.motion1, offset),
                      Cross(AngularVelocity(*bodies.body1, bodies.motion1, offset), r1));
  const Vec3 v2 = Add(LinearVelocity(*bodies.body2, bodies.motion2, offset),
                      Cross(AngularVelocity(*bodies.body2, bodies.motion2, offset), r2));
  return Dot(Sub(v2, v1), n);
}

// A world point relative to a body's centre of mass, in its body frame.
HWY_INLINE Vec3 ContactLocalPoint(const BodyLanes& body, const Vec3& world,
                                  std::size_t offset) {
  return InverseRotate(LoadQuat(body.rotation, offset),
                       Sub(world, LoadVec3(body.position, offset)));
}

// The normal impulse a new point inherits: that of the first of last step's
// points (in order) present and within 1 cm of it on both bodies, else 0.
HWY_INLINE LaneVec ContactMatchedImpulse(const Vec3& local1, const Vec3& local2,
                                         const Vec3* old_local1, const Vec3* old_local2,
                                         const LaneMask* old_present,
                                         const LaneVec* old_lambda, std::size_t count) {
  const LaneVec max_distance_squared = Splat(1.0e-4f);
  LaneVec lambda = Zero();
  LaneMask found = hn::Lt(Zero(), Zero());  // all false
  for (std::size_t j = 0; j < count; ++j) {
    const LaneMask near =
        hn::And(hn::Le(LengthSquared(Sub(local1, old_local1[j])), max_distance_squared),
                hn::Le(LengthSquared(Sub(local2, old_local2[j])), max_distance_squared));
    const LaneMask take = hn::AndNot(found, hn::And(old_present[j], near));
    lambda = hn::IfThenElse(take, old_lambda[j], lambda);
    found = hn::Or(found, take);
  }
  return lambda;
}

// The rows of one chunk from this substep's points (positions at the
// substep's start, velocities after its forces). relative_acceleration is
// a_rel = g (gamma2 - gamma1) + F2/m2 - F1/m1 (dynamic bodies only).
HWY_INLINE void ContactSetupChunk(const BodyPair& bodies, const ContactCandidates& found,
                                  const Vec3& relative_acceleration,
                                  const ContactScalars& scalars, ContactLanes& manifold,
                                  ContactPointLanes* points, std::size_t point_count,
                                  std::size_t offset) {
  const Vec3 n = found.normal;
  const Vec3 x1 = LoadVec3(bodies.body1->position, offset);
  const Vec3 x2 = LoadVec3(bodies.body2->position, offset);

  // Last step's points, read before this step's overwrite them.
  Vec3 old_local1[kMaxContactPoints], old_local2[kMaxContactPoints];
  LaneMask old_present[kMaxContactPoints];
  LaneVec old_lambda[kMaxContactPoints];
  for (std::size_t i = 0; i < point_count; ++i) {
    old_local1[i] = LoadVec3(points[i].local_point1, offset);
    old_local2[i] = LoadVec3(points[i].local_point2, offset);
    old_present[i] = LoadFlags(points[i].present, offset);
    old_lambda[i] = Load(points[i].normal_lambda, offset);
  }

  const LaneVec dt = scalars.delta_time;
  const LaneVec restitution = Load(manifold.restitution, offset);
  const LaneVec force_velocity =
      hn::Min(Zero(), hn::Mul(dt, Dot(relative_acceleration, n)));
  LaneVec kept_count = Zero();
  Vec3 anchor = ZeroVec3();
  Vec3 midpoint[kMaxContactPoints];
  for (std::size_t i = 0; i < point_count; ++i) {
    ContactPointLanes& point = points[i];
    const LaneMask keep = found.keep[i];
    const Vec3 p1 = found.point1[i];
    const Vec3 p2 = found.point2[i];
    const Vec3 local1 = ContactLocalPoint(*bodies.body1, p1, offset);
    const Vec3 local2 = ContactLocalPoint(*bodies.body2, p2, offset);
    const LaneVec inherited = ContactMatchedImpulse(local1, local2, old_local1, old_local2,
                                                    old_present, old_lambda, point_count);
    StoreVec3(local1, point.local_point1, offset);
    StoreVec3(local2, point.local_point2, offset);
    StoreFlags(keep, point.present, offset);
    Store(hn::IfThenElseZero(keep, inherited), point.normal_lambda, offset);

    midpoint[i] = Scale(Add(p1, p2), Splat(0.5f));
    const Vec3 r1 = Sub(midpoint[i], x1);
    const Vec3 r2 = Sub(midpoint[i], x2);
    const LaneVec separation = Dot(Sub(p2, p1), n);
    const LaneVec speculative = hn::Max(Zero(), hn::Div(separation, dt));
    const LaneVec normal_velocity = ContactRelativeNormalVelocity(bodies, r1, r2, n, offset);
    const LaneMask bounces =
        hn::And(hn::And(hn::Gt(restitution, Zero()),
                        hn::Lt(normal_velocity, hn::Neg(scalars.min_velocity_for_restitution))),
                hn::Lt(normal_velocity, hn::Neg(speculative)));
    const LaneVec bias = hn::IfThenElse(
        bounces, hn::Mul(restitution, hn::Sub(normal_velocity, force_velocity)), speculative);
    AxisCalculatePropertiesChunk(bodies, r1, r2, n, bias, point.normal_row, point.normal_lambda,
                                 offset);
    AxisDeactivateChunk(hn::Not(keep), point.normal_row, point.normal_lambda, offset);

    kept_count = hn::Add(kept_count, hn::IfThenElseZero(keep, Splat(1.0f)));
    anchor = Add(anchor, Select(keep, midpoint[i], ZeroVec3()));
  }

  const LaneMask exists = hn::Gt(kept_count, Zero());
  const LaneMask had = LoadFlags(manifold.present, offset);
  StoreFlags(exists, manifold.present, offset);
  anchor = Scale(anchor, hn::Div(Splat(1.0f), hn::Max(kept_count, Splat(1.0f))));
  for (std::size_t i = 0; i < point_count; ++i) {
    const Vec3 from_anchor = Sub(midpoint[i], anchor);
    const Vec3 across = Sub(from_anchor, Scale(n, Dot(from_anchor, n)));
    Store(hn::IfThenElseZero(found.keep[i], hn::Sqrt(LengthSquared(across))),
          points[i].anchor_distance, offset);
  }

  // Friction: the impulses carry over where the manifold existed last step.
  const LaneMask rubs = hn::And(exists, hn::Gt(Load(manifold.friction, offset), Zero()));
  const LaneMask carries = hn::And(rubs, had);
  const Vec3 t1 = NormalizedPerpendicular(n);
  const Vec3 t2 = Cross(n, t1);
  StoreVec3(n, manifold.normal, offset);
  StoreVec3(t1, manifold.tangent1, offset);
  StoreVec3(t2, manifold.tangent2, offset);
  const Vec3 r1 = Sub(anchor, x1);
  const Vec3 r2 = Sub(anchor, x2);
  const auto tangent_row = [&](const Vec3& t, AxisProperties& row, LaneArray& lambda) {
    Store(hn::IfThenElseZero(carries, Load(lambda, offset)), lambda, offset);
    AxisCalculatePropertiesChunk(bodies, r1, r2, t, Zero(), row, lambda, offset);
    AxisDeactivateChunk(hn::Not(rubs), row, lambda, offset);
  };
  tangent_row(t1, manifold.tangent1_row, manifold.tangent1_lambda);
  tangent_row(t2, manifold.tangent2_row, manifold.tangent2_lambda);

  Vec3 inv_i1_n = ZeroVec3(), inv_i2_n = ZeroVec3();
  LaneVec k = Zero();
  if (bodies.motion1 == MotionType::kDynamic) {
    inv_i1_n = BodyInverseInertiaTimes(*bodies.body1, n, offset);
    k = Dot(n, inv_i1_n);
  }
  if (bodies.motion2 == MotionType::kDynamic) {
    inv_i2_n = BodyInverseInertiaTimes(*bodies.body2, n, offset);
    k = hn::Add(k, Dot(n, inv_i2_n));
  }
  LaneMask invertible;
  const LaneVec angular_mass = ReciprocalOrZero(k, invertible);
  const LaneMask twists = hn::And(hn::And(rubs, hn::Ge(kept_count, Splat(2.0f))), invertible);
  StoreVec3(inv_i1_n, manifold.inv_i1_normal, offset);
  StoreVec3(inv_i2_n, manifold.inv_i2_normal, offset);
  Store(hn::IfThenElseZero(twists, angular_mass), manifold.angular_effective_mass, offset);
  Store(hn::IfThenElseZero(hn::And(twists, had), Load(manifold.angular_lambda, offset)),
        manifold.angular_lambda, offset);
}

// Both bodies' velocities while a manifold is warm started or solved: read
// once (a static body's as zero), every row applied to them in registers,
// written back once with the locked translation axes zeroed (spec 5.2; only
// dynamic bodies are written).
struct ContactVelocities {
  Vec3 v1, w1, v2, w2;

  static ContactVelocities Read(const BodyPair& bodies, std::size_t offset) {
    return {LinearVelocity(*bodies.body1, bodies.motion1, offset),
            AngularVelocity(*bodies.body1, bodies.motion1, offset),
            LinearVelocity(*bodies.body2, bodies.motion2, offset),
            AngularVelocity(*bodies.body2, bodies.motion2, offset)};
  }
  // Only the lanes of `touched` (those with a manifold) are written: the
  // others' rows are all zero, and skipping them keeps every bit (v + 0
  // would turn a -0 into +0), so a chunk with no manifold can be skipped
  // whole and a world's bits never depend on its neighbours.
  void Write(const BodyPair& bodies, LaneMask touched, std::size_t offset) const {
    const auto write = [&](BodyLanes& body, const Vec3& v, const Vec3& w) {
      StoreVec3(Select(touched, LockTranslation(body, v, offset),
                       LoadVec3(body.linear_velocity, offset)),
                body.linear_velocity, offset);
      StoreVec3(Select(touched, w, LoadVec3(body.angular_velocity, offset)),
                body.angular_velocity, offset);
    };
    if (bodies.motion1 == MotionType::kDynamic) write(*bodies.body1, v1, w1);
    if (bodies.motion2 == MotionType::kDynamic) write(*bodies.body2, v2, w2);
  }

  // -J v of an axis row: n.(v1 - v2) + a1.w1 - a2.w2 (a static body's a is 0).
  LaneVec MinusJv(const Vec3& axis, const AxisProperties& row, std::size_t offset) const {
    return hn::Add(Dot(axis, Sub(v1, v2)),
                   hn::Sub(Dot(LoadVec3(row.r1_plus_u_x_axis, offset), w1),
                           Dot(LoadVec3(row.r2_x_axis, offset), w2)));
  }
  // The impulse lambda along an axis row: body 1 gets -J^T lambda, body 2 +.
  void ApplyAxis(const BodyPair& bodies, const Vec3& axis, const AxisProperties& row,
                 LaneVec lambda, std::size_t offset) {
    if (bodies.motion1 == MotionType::kDynamic) {
      v1 = NegMulAdd(axis, hn::Mul(lambda, Load(bodies.body1->inv_mass, offset)), v1);
      w1 = NegMulAdd(LoadVec3(row.inv_i1_r1_plus_u_x_axis, offset), lambda, w1);
    }
    if (bodies.motion2 == MotionType::kDynamic) {
      v2 = MulAdd(axis, hn::Mul(lambda, Load(bodies.body2->inv_mass, offset)), v2);
      w2 = MulAdd(LoadVec3(row.inv_i2_r2_x_axis, offset), lambda, w2);
    }
  }
  // The angular friction impulse lambda about n: w1 -= lambda I1^-1 n, w2 +=.
  void ApplyAngular(const BodyPair& bodies, const ContactLanes& manifold, LaneVec lambda,
                    std::size_t offset) {
    if (bodies.motion1 == MotionType::kDynamic) {
      w1 = NegMulAdd(LoadVec3(manifold.inv_i1_normal, offset), lambda, w1);
    }
    if (bodies.motion2 == MotionType::kDynamic) {
      w2 = MulAdd(LoadVec3(manifold.inv_i2_normal, offset), lambda, w2);
    }
  }
};

HWY_INLINE void ContactWarmStartChunk(const BodyPair& bodies, ContactLanes& manifold,
                                      ContactPointLanes* points, std::size_t point_count,
                                      LaneVec ratio, std::size_t offset) {
  ContactVelocities velocities = ContactVelocities::Read(bodies, offset);
  const auto warm_start = [&](const Vec3& axis, const AxisProperties& row, LaneArray& lambda) {
    const LaneVec scaled = hn::Mul(Load(lambda, offset), ratio);
    Store(scaled, lambda, offset);
    velocities.ApplyAxis(bodies, axis, row, scaled, offset);
  };
  warm_start(LoadVec3(manifold.tangent1, offset), manifold.tangent1_row, manifold.tangent1_lambda);
  warm_start(LoadVec3(manifold.tangent2, offset), manifold.tangent2_row, manifold.tangent2_lambda);
  const LaneVec angular = hn::Mul(Load(manifold.angular_lambda, offset), ratio);
  Store(angular, manifold.angular_lambda, offset);
  velocities.ApplyAngular(bodies, manifold, angular, offset);
  const Vec3 n = LoadVec3(manifold.normal, offset);
  for (std::size_t i = 0; i < point_count; ++i) {
    warm_start(n, points[i].normal_row, points[i].normal_lambda);
  }
  velocities.Write(bodies, LoadFlags(manifold.present, offset), offset);
}

// One velocity pass of the manifold; returns the lanes that applied an impulse.
HWY_INLINE LaneMask ContactSolveVelocityChunk(const BodyPair& bodies, ContactLanes& manifold,
                                              ContactPointLanes* points,
                                              std::size_t point_count, std::size_t offset) {
  ContactVelocities velocities = ContactVelocities::Read(bodies, offset);
  // Friction limits from the normal impulses so far.
  const LaneVec mu = Load(manifold.friction, offset);
  LaneVec normal_sum = Zero(), moment_sum = Zero();
  for (std::size_t i = 0; i < point_count; ++i) {
    const LaneVec lambda = Load(points[i].normal_lambda, offset);
    normal_sum = hn::Add(normal_sum, lambda);
    moment_sum = hn::MulAdd(Load(points[i].anchor_distance, offset), lambda, moment_sum);
  }
  const LaneVec max_linear = hn::Mul(mu, normal_sum);
  const LaneVec max_angular = hn::Mul(mu, moment_sum);

  // Linear friction: both rows from the same velocities, then the circle.
  const Vec3 t1 = LoadVec3(manifold.tangent1, offset);
  const Vec3 t2 = LoadVec3(manifold.tangent2, offset);
  const LaneVec old1 = Load(manifold.tangent1_lambda, offset);
  const LaneVec old2 = Load(manifold.tangent2_lambda, offset);
  LaneVec new1 = hn::MulAdd(Load(manifold.tangent1_row.effective_mass, offset),
                            velocities.MinusJv(t1, manifold.tangent1_row, offset), old1);
  LaneVec new2 = hn::MulAdd(Load(manifold.tangent2_row.effective_mass, offset),
                            velocities.MinusJv(t2, manifold.tangent2_row, offset), old2);
  const LaneVec length_squared = hn::MulAdd(new1, new1, hn::Mul(new2, new2));
  const LaneMask outside = hn::Gt(length_squared, hn::Mul(max_linear, max_linear));
  // Only a chunk with a lane sliding pays the square root and division.
  if (AnyLane(outside)) {
    const LaneVec shrink = hn::Div(
        max_linear, hn::Sqrt(hn::IfThenElse(outside, length_squared, Splat(1.0f))));
    new1 = hn::IfThenElse(outside, hn::Mul(new1, shrink), new1);
    new2 = hn::IfThenElse(outside, hn::Mul(new2, shrink), new2);
  }
  Store(new1, manifold.tangent1_lambda, offset);
  Store(new2, manifold.tangent2_lambda, offset);
  const LaneVec delta1 = hn::Sub(new1, old1);
  const LaneVec delta2 = hn::Sub(new2, old2);
  velocities.ApplyAxis(bodies, t1, manifold.tangent1_row, delta1, offset);
  velocities.ApplyAxis(bodies, t2, manifold.tangent2_row, delta2, offset);
  LaneMask applied = AnyComponentNonZero(delta1, delta2);

  // Angular friction about n: -J w = (w1 - w2).n.
  const Vec3 n = LoadVec3(manifold.normal, offset);
  const LaneVec old_angular = Load(manifold.angular_lambda, offset);
  const LaneVec new_angular = hn::Min(
      hn::Max(hn::MulAdd(Load(manifold.angular_effective_mass, offset),
                         Dot(n, Sub(velocities.w1, velocities.w2)), old_angular),
              hn::Neg(max_angular)),
      max_angular);
  Store(new_angular, manifold.angular_lambda, offset);
  const LaneVec delta_angular = hn::Sub(new_angular, old_angular);
  velocities.ApplyAngular(bodies, manifold, delta_angular, offset);
  applied = hn::Or(applied, hn::Ne(delta_angular, Zero()));

  // Normal rows, point by point: impulse >= 0, towards the bias.
  for (std::size_t i = 0; i < point_count; ++i) {
    const AxisProperties& row = points[i].normal_row;
    const LaneVec old = Load(points[i].normal_lambda, offset);
    const LaneVec updated = hn::Max(
        Zero(), hn::MulAdd(Load(row.effective_mass, offset),
                           hn::Sub(velocities.MinusJv(n, row, offset), Load(row.spring.bias, offset)),
                           old));
    Store(updated, points[i].normal_lambda, offset);
    const LaneVec delta = hn::Sub(updated, old);
    velocities.ApplyAxis(bodies, n, row, delta, offset);
    applied = hn::Or(applied, hn::Ne(delta, Zero()));
  }
  velocities.Write(bodies, LoadFlags(manifold.present, offset), offset);
  return applied;
}

// One position pass of the manifold; returns the lanes that moved.
HWY_INLINE LaneMask ContactSolvePositionChunk(const BodyPair& bodies,
                                              const ContactLanes& manifold,
                                              ContactPointLanes* points,
                                              std::size_t point_count,
                                              const ContactScalars& scalars,
                                              std::size_t offset) {
  const Vec3 n = LoadVec3(manifold.normal, offset);
  // The poses at the start of the manifold's pass place the points.
  const Vec3 x1 = LoadVec3(bodies.body1->position, offset);
  const Vec3 x2 = LoadVec3(bodies.body2->position, offset);
  const Quat q1 = LoadQuat(bodies.body1->rotation, offset);
  const Quat q2 = LoadQuat(bodies.body2->rotation, offset);
  LaneMask moved = hn::Lt(Zero(), Zero());
  for (std::size_t i = 0; i < point_count; ++i) {
    ContactPointLanes& point = points[i];
    const Vec3 p1 = Add(x1, Rotate(q1, LoadVec3(point.local_point1, offset)));
    const Vec3 p2 = Add(x2, Rotate(q2, LoadVec3(point.local_point2, offset)));
    const LaneVec error = hn::Max(hn::Add(Dot(Sub(p2, p1), n), scalars.penetration_slop),
                                  hn::Neg(scalars.max_penetration_distance));
    const LaneMask corrects = hn::And(LoadFlags(point.present, offset), hn::Lt(error, Zero()));
    if (!AnyLane(corrects)) continue;
    // Lever arms and K at the current poses (earlier points may have moved
    // the bodies); a scratch impulse, as the velocity phase's stays put.
    const Vec3 midpoint = Scale(Add(p1, p2), Splat(0.5f));
    LaneArray scratch_lambda{};
    AxisCalculatePropertiesChunk(bodies, Sub(midpoint, LoadVec3(bodies.body1->position, offset)),
                                 Sub(midpoint, LoadVec3(bodies.body2->position, offset)), n,
                                 Zero(), point.normal_row, scratch_lambda, offset);
    // lambda = -beta C / K; only the lanes that correct are written (see
    // ContactVelocities::Write).
    const LaneVec lambda = hn::IfThenElseZero(
        corrects, hn::Mul(hn::Neg(hn::Mul(Load(point.normal_row.effective_mass, offset),
                                          scalars.baumgarte)),
                          error));
    // A zero lambda turns no rotation (AddRotationStep keeps q below 1e-6 rad).
    const auto step = [&](BodyLanes& body, const Vec3& inv_i_a, LaneVec signed_lambda) {
      const Vec3 x = LoadVec3(body.position, offset);
      const Vec3 moved_x = Add(
          x, LockTranslation(body, Scale(n, hn::Mul(signed_lambda, Load(body.inv_mass, offset))),
                             offset));
      StoreVec3(Select(corrects, moved_x, x), body.position, offset);
      AddRotationStep(body, Scale(inv_i_a, signed_lambda), offset);
    };
    if (bodies.motion1 == MotionType::kDynamic) {
      step(*bodies.body1, LoadVec3(point.normal_row.inv_i1_r1_plus_u_x_axis, offset),
           hn::Neg(lambda));
    }
    if (bodies.motion2 == MotionType::kDynamic) {
      step(*bodies.body2, LoadVec3(point.normal_row.inv_i2_r2_x_axis, offset), lambda);
    }
    moved = hn::Or(moved, hn::And(corrects, hn::Ne(Load(point.normal_row.effective_mass, offset),
                                                   Zero())));
  }
  return moved;
}

}  // namespace HWY_NAMESPACE
}  // namespace manyworlds
HWY_AFTER_NAMESPACE();

#endif  // MANYWORLDS_KERNELS_CONTACT_INL_H_
