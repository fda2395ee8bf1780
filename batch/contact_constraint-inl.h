// Contact slots across worlds: each substep finds the points of a slot's
// shape pair in every world of the block from the poses at the substep's
// start (batch/contact_points-inl.h, batch/box_contact_points-inl.h,
// batch/box_box_contact_points-inl.h), then the contact part
// (kernels/contact-inl.h) makes and solves its rows. Which worlds touch, and
// which points each keeps, are lane masks.

#if defined(MANYWORLDS_BATCH_CONTACT_CONSTRAINT_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef MANYWORLDS_BATCH_CONTACT_CONSTRAINT_INL_H_
#undef MANYWORLDS_BATCH_CONTACT_CONSTRAINT_INL_H_
#else
#define MANYWORLDS_BATCH_CONTACT_CONSTRAINT_INL_H_
#endif

#include <cstddef>

#include "batch/box_box_contact_points-inl.h"
#include "batch/box_contact_points-inl.h"
#include "batch/contact_points-inl.h"

HWY_BEFORE_NAMESPACE();
namespace manyworlds {
namespace HWY_NAMESPACE {

// a_rel = g (gamma2 - gamma1) + F2/m2 - F1/m1 over the dynamic bodies.
inline Vec3 RelativeForceAcceleration(const ContactBlock& c, const Vec3& gravity,
                                      std::size_t offset) {
  Vec3 acceleration = ZeroVec3();
  const auto add = [&](const BodyLanes& body, const BodyMotionLanes* motion, float sign) {
    if (motion == nullptr) return;
    const Vec3 a = MulAdd(gravity, Load(motion->gravity_factor, offset),
                          Scale(LoadVec3(motion->force, offset), Load(body.inv_mass, offset)));
    acceleration = Add(acceleration, Scale(a, Splat(sign)));
  };
  add(*c.bodies.body1, c.motion1, -1.0f);
  add(*c.bodies.body2, c.motion2, 1.0f);
  return acceleration;
}

// The candidate points of a slot in one chunk (the pair kind is the same in
// every world, so this switch is not per lane).
inline ContactCandidates SlotCandidates(const ContactBlock& c, const ContactStepScalars& scalars,
                                        std::size_t offset) {
  switch (c.plan.kind) {
    case ContactPairKind::kPlaneSphere:
    case ContactPairKind::kPlaneCapsule:
    case ContactPairKind::kPlaneBox: return PlanePairCandidates(c, scalars, offset);
    case ContactPairKind::kSphereBox: return SphereBoxCandidates(c, scalars, offset);
    case ContactPairKind::kCapsuleBox: return CapsuleBoxCandidates(c, scalars, offset);
    case ContactPairKind::kBoxBox: return BoxBoxCandidates(c, scalars, offset);
    default: return CorePairCandidates(c, scalars, offset);
  }
}

// The broad phase, per chunk: whether the two shapes may come within the
// speculative distance in any world, from the bounding spheres about the
// bodies' centres of mass (radius: the shape's reach), or for a plane the
// height of the other body's centre of mass above it, the distance grown as
// SpeculativeDistance grows it (|v2 - v1| bounds the approach along any n).
// The bound is loosened by 1e-3 of the reach and 1 mm against rounding, so a
// lane it rules out has no manifold by any rounding of the points.
inline LaneMask MayTouch(const ContactBlock& c, const ContactStepScalars& scalars,
                         std::size_t offset) {
  const BodyPair& b = c.bodies;
  LaneVec reach = hn::Add(Splat(c.plan.reach1 + c.plan.reach2), scalars.speculative_distance);
  if (scalars.speculative_from_velocity) {
    const Vec3 relative = Sub(LinearVelocity(*b.body2, b.motion2, offset),
                              LinearVelocity(*b.body1, b.motion1, offset));
    const LaneVec approach = hn::Add(
        hn::Sqrt(LengthSquared(relative)),
        hn::MulAdd(hn::Sqrt(LengthSquared(AngularVelocity(*b.body1, b.motion1, offset))),
                   Splat(c.plan.reach1),
                   hn::Mul(hn::Sqrt(LengthSquared(AngularVelocity(*b.body2, b.motion2, offset))),
                           Splat(c.plan.reach2))));
    reach = hn::MulAdd(approach, scalars.part.delta_time, reach);
  }
  reach = hn::MulAdd(reach, Splat(1.001f), Splat(1.0e-3f));
  if (IsPlanePair(c.plan.kind)) {
    const bool plane_is_body1 = c.plan.shape1.type == ShapeType::kPlane;
    const ShapeFrame plane = plane_is_body1 ? WorldShapeFrame(*b.body1, c.plan.shape1, offset)
                                            : WorldShapeFrame(*b.body2, c.plan.shape2, offset);
    const Vec3 normal = Rotate(plane.rotation, Vec3{Zero(), Splat(1.0f), Zero()});
    const Vec3 centre = LoadVec3(plane_is_body1 ? b.body2->position : b.body1->position, offset);
    return hn::Le(Dot(normal, Sub(centre, plane.centre)), reach);
  }
  const Vec3 between = Sub(LoadVec3(b.body2->position, offset), LoadVec3(b.body1->position, offset));
  return hn::Le(LengthSquared(between), hn::Mul(reach, reach));
}

// A chunk whose shapes are apart in every world: what the setup leaves for a
// slot without a manifold (no points, no impulses to carry over); the rows
// are never read, since no pass touches a chunk without a manifold.
inline void ClearContactChunk(const ContactBlock& c, std::size_t offset) {
  StoreFlags(NoLanes(), c.manifold.present, offset);
  for (LaneArray* lambda : {&c.manifold.tangent1_lambda, &c.manifold.tangent2_lambda,
                            &c.manifold.angular_lambda}) {
    Store(Zero(), *lambda, offset);
  }
  for (std::size_t i = 0; i < c.plan.point_count; ++i) {
    StoreFlags(NoLanes(), c.points[i].present, offset);
    Store(Zero(), c.points[i].normal_lambda, offset);
  }
}

inline void ContactSetup(const ContactBlock& c, const ContactStepScalars& scalars) {
  ForEachChunk([&](std::size_t offset) {
    if (!AnyLane(MayTouch(c, scalars, offset))) {
      ClearContactChunk(c, offset);
      return;
    }
    const ContactCandidates found = SlotCandidates(c, scalars, offset);
    ContactSetupChunk(c.bodies, found, RelativeForceAcceleration(c, scalars.gravity, offset),
                      scalars.part, c.manifold, c.points, c.plan.point_count, offset);
  });
}

// A chunk in which no world has this slot's manifold is skipped: its rows
// are all zero and the part writes only the lanes with a manifold, so this
// changes no bit (most slots of a heap of shapes are empty most of the time).
inline bool AnyManifold(const ContactBlock& c, std::size_t offset) {
  return AnyLane(LoadFlags(c.manifold.present, offset));
}

inline void ContactWarmStart(const ContactBlock& c, float warm_start_ratio) {
  const LaneVec ratio = Splat(warm_start_ratio);
  ForEachChunk([&](std::size_t offset) {
    if (!AnyManifold(c, offset)) return;
    ContactWarmStartChunk(c.bodies, c.manifold, c.points, c.plan.point_count, ratio, offset);
  });
}

inline bool ContactSolveVelocity(const ContactBlock& c) {
  bool applied = false;
  ForEachChunk([&](std::size_t offset) {
    if (!AnyManifold(c, offset)) return;
    applied |= AnyLane(
        ContactSolveVelocityChunk(c.bodies, c.manifold, c.points, c.plan.point_count, offset));
  });
  return applied;
}

inline bool ContactSolvePosition(const ContactBlock& c, const ContactStepScalars& scalars) {
  bool moved = false;
  ForEachChunk([&](std::size_t offset) {
    if (!AnyManifold(c, offset)) return;
    moved |= AnyLane(ContactSolvePositionChunk(c.bodies, c.manifold, c.points,
                                               c.plan.point_count, scalars.part, offset));
  });
  return moved;
}

}  // namespace HWY_NAMESPACE
}  // namespace manyworlds
HWY_AFTER_NAMESPACE();

#endif  // MANYWORLDS_BATCH_CONTACT_CONSTRAINT_INL_H_
