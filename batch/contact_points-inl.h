// Contact points of a plane pair and of a pair of spheres and capsules across
// worlds (docs/contacts.md, "Points of a plane pair" and "Points of a pair of
// spheres and capsules"), from the poses at a substep's start; boxes with other
// shapes are in box_contact_points-inl.h. Which worlds touch, and which points
// each keeps, are lane masks.
//
// Plane: outward normal n_p (the plane shape's +Y), a point o on it,
// phi(y) = n_p.(y - o). A point is kept where phi(shape point) < D + 1 mm,
// the manifold exists where its deepest candidate has phi < D (D the
// speculative contact distance); a kept point's partner on the plane is its
// projection y - phi(y) n_p.
//   sphere (c, r):   c - r n_p
//   capsule:         ends a = c - h a^, b = c + h a^; lying flat (|2h a^.n_p| <
//                    0.02, not parallel): a - r w^, b - r w^ with w^ the unit
//                    part of n_p across a^; else the lower end e - r n_p
//   box:             the 4 corners of the face whose axis is most along n_p,
//                    on the side facing the plane, in polygon order
// Spheres and capsules with each other: one point from the closest points of
// their cores (a sphere's is its centre, a capsule's its segment), pushed
// out along the line between them by each radius.

#if defined(MANYWORLDS_BATCH_CONTACT_POINTS_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef MANYWORLDS_BATCH_CONTACT_POINTS_INL_H_
#undef MANYWORLDS_BATCH_CONTACT_POINTS_INL_H_
#else
#define MANYWORLDS_BATCH_CONTACT_POINTS_INL_H_
#endif

#include <cstddef>

#include "batch/constraint_block.h"
#include "batch/contact_plan.h"
#include "kernels/contact-inl.h"

HWY_BEFORE_NAMESPACE();
namespace manyworlds {
namespace HWY_NAMESPACE {

// Jolt's manifold tolerance: points up to this beyond the speculative
// distance are kept once the manifold exists.
inline constexpr float kContactManifoldTolerance = 1.0e-3f;
// Jolt's capsule projection slop: a capsule lies flat on a plane (two
// points) when its ends' heights differ by less than this.
inline constexpr float kCapsuleProjectionSlop = 0.02f;

// A contact slot inside one block.
struct ContactBlock {
  const ContactPlan& plan;
  BodyPair bodies;
  const BodyMotionLanes* motion1;  // null unless dynamic
  const BodyMotionLanes* motion2;
  ContactLanes& manifold;
  ContactPointLanes* points;
};

inline ContactBlock ContactInBlock(const StepPlan& plan, std::size_t contact,
                                   std::byte* block) {
  const ContactPlan& c = plan.contacts[contact];
  const auto motion = [&](std::size_t offset) {
    return offset == kAbsent ? nullptr : &At<BodyMotionLanes>(block, offset);
  };
  return ContactBlock{c,
                      BodyPair{&BodyAt(plan, block, c.body1), c.motion1,
                               &BodyAt(plan, block, c.body2), c.motion2},
                      motion(c.motion_offset1),
                      motion(c.motion_offset2),
                      At<ContactLanes>(block, c.offset),
                      &At<ContactPointLanes>(block, c.points_offset)};
}

// Uniform contact numbers of one substep.
struct ContactStepScalars {
  ContactScalars part;
  LaneVec speculative_distance;
  Vec3 gravity;
  bool speculative_from_velocity;  // StepSettings::speculative_contacts_from_velocity
};

// A slot's speculative distance in each world: the setting, and with
// speculative_contacts_from_velocity also how far its shapes may approach in
// this substep along n (body 1 to body 2): dt max(0, -(v2 - v1).n + |w1| R1 +
// |w2| R2), R a shape's reach from its body's centre of mass. Jolt's
// discrete contacts catch a body only once it is within the fixed distance,
// so a fast one lands inside the other by up to one substep's travel.
inline LaneVec SpeculativeDistance(const ContactBlock& c, const ContactStepScalars& scalars,
                                   const Vec3& n, std::size_t offset) {
  if (!scalars.speculative_from_velocity) return scalars.speculative_distance;
  const BodyPair& b = c.bodies;
  const Vec3 relative = Sub(LinearVelocity(*b.body2, b.motion2, offset),
                            LinearVelocity(*b.body1, b.motion1, offset));
  const LaneVec spin = hn::MulAdd(
      hn::Sqrt(LengthSquared(AngularVelocity(*b.body1, b.motion1, offset))),
      Splat(c.plan.reach1),
      hn::Mul(hn::Sqrt(LengthSquared(AngularVelocity(*b.body2, b.motion2, offset))),
              Splat(c.plan.reach2)));
  const LaneVec approach = hn::Max(Zero(), hn::Sub(spin, Dot(relative, n)));
  return hn::MulAdd(approach, scalars.part.delta_time, scalars.speculative_distance);
}

// A shape's frame in world space in one chunk: its centre and rotation.
struct ShapeFrame {
  Vec3 centre;
  Quat rotation;
};

inline ShapeFrame WorldShapeFrame(const BodyLanes& body, const ContactShape& shape,
                                  std::size_t offset) {
  const Quat body_rotation = LoadQuat(body.rotation, offset);
  const Vec3 local{Splat(shape.position[0]), Splat(shape.position[1]), Splat(shape.position[2])};
  const Quat local_rotation{Splat(shape.rotation[0]), Splat(shape.rotation[1]),
                            Splat(shape.rotation[2]), Splat(shape.rotation[3])};
  return {Add(LoadVec3(body.position, offset), Rotate(body_rotation, local)),
          Mul(body_rotation, local_rotation)};
}

// The plane of a chunk: outward normal and a point on it.
struct PlaneLanes {
  Vec3 normal;
  Vec3 origin;
  LaneVec Distance(const Vec3& y) const { return Dot(normal, Sub(y, origin)); }
  Vec3 Project(const Vec3& y) const { return Sub(y, Scale(normal, Distance(y))); }
};

// Up to kMaxContactPoints shape points (in slot order) and which are kept,
// each paired with its projection on the plane.
struct PlanePoints {
  Vec3 on_shape[kMaxContactPoints];
  LaneMask keep[kMaxContactPoints];
};

inline PlanePoints SpherePoints(const PlaneLanes& plane, const ShapeFrame& sphere,
                                const ContactShape& shape, LaneVec speculative) {
  PlanePoints out;
  out.on_shape[0] = Sub(sphere.centre, Scale(plane.normal, Splat(shape.radius)));
  out.keep[0] = hn::Lt(plane.Distance(out.on_shape[0]), speculative);
  return out;
}

inline PlanePoints CapsulePoints(const PlaneLanes& plane, const ShapeFrame& capsule,
                                 const ContactShape& shape, LaneVec speculative,
                                 LaneVec tolerance) {
  const Vec3 axis = Rotate(capsule.rotation, Vec3{Zero(), Splat(1.0f), Zero()});
  const Vec3 half = Scale(axis, Splat(shape.half_height));
  const Vec3 end_a = Sub(capsule.centre, half);
  const Vec3 end_b = Add(capsule.centre, half);
  const LaneVec radius = Splat(shape.radius);
  const LaneVec along = Dot(axis, plane.normal);
  const LaneMask flat = hn::And(
      hn::Lt(hn::Abs(hn::Mul(Splat(2.0f * shape.half_height), along)),
             Splat(kCapsuleProjectionSlop)),
      hn::Lt(hn::Abs(along), Splat(1.0f)));
  // Lying flat: both ends, pushed across the axis towards the plane.
  const Vec3 across = Normalize(Sub(plane.normal, Scale(axis, along)));
  const Vec3 flat_a = Sub(end_a, Scale(across, radius));
  const Vec3 flat_b = Sub(end_b, Scale(across, radius));
  const LaneVec phi_a = plane.Distance(flat_a);
  const LaneVec phi_b = plane.Distance(flat_b);
  const LaneMask flat_exists = hn::Lt(hn::Min(phi_a, phi_b), speculative);
  // Otherwise the lower end (a on a tie), straight towards the plane.
  const Vec3 lower = Select(hn::Le(plane.Distance(end_a), plane.Distance(end_b)), end_a, end_b);
  const Vec3 tip = Sub(lower, Scale(plane.normal, radius));
  const LaneMask tip_exists = hn::Lt(plane.Distance(tip), speculative);

  PlanePoints out;
  out.on_shape[0] = Select(flat, flat_a, tip);
  out.keep[0] = hn::Or(hn::And(flat, hn::And(flat_exists, hn::Lt(phi_a, tolerance))),
                       hn::AndNot(flat, tip_exists));
  out.on_shape[1] = flat_b;
  out.keep[1] = hn::And(flat, hn::And(flat_exists, hn::Lt(phi_b, tolerance)));
  return out;
}

inline PlanePoints BoxPoints(const PlaneLanes& plane, const ShapeFrame& box,
                             const ContactShape& shape, LaneVec speculative,
                             LaneVec tolerance) {
  // The box's axes (scaled by the half extents) in world space.
  const Vec3 axes[3] = {
      Rotate(box.rotation, Vec3{Splat(shape.half_extents[0]), Zero(), Zero()}),
      Rotate(box.rotation, Vec3{Zero(), Splat(shape.half_extents[1]), Zero()}),
      Rotate(box.rotation, Vec3{Zero(), Zero(), Splat(shape.half_extents[2])})};
  const Vec3 m = InverseRotate(box.rotation, plane.normal);
  const LaneVec ax = hn::Abs(m.x), ay = hn::Abs(m.y), az = hn::Abs(m.z);
  const LaneMask face_x = hn::And(hn::Ge(ax, ay), hn::Ge(ax, az));
  const LaneMask face_y = hn::AndNot(face_x, hn::Ge(ay, az));
  const LaneMask face_z = hn::Not(hn::Or(face_x, face_y));
  // The face facing the plane sits at -sign(m_k) along axis k; its other two
  // axes (u, v) in increasing index.
  const LaneVec m_k = hn::IfThenElse(face_x, m.x, hn::IfThenElse(face_y, m.y, m.z));
  const LaneVec face_side = hn::IfThenElse(hn::Gt(m_k, Zero()), Splat(-1.0f), Splat(1.0f));
  const Vec3 face_axis = Select(face_x, axes[0], Select(face_y, axes[1], axes[2]));
  const Vec3 u_axis = Select(face_x, axes[1], axes[0]);
  const Vec3 v_axis = Select(face_z, axes[1], axes[2]);
  const Vec3 face_centre = Add(box.centre, Scale(face_axis, face_side));
  static constexpr float kCornerSigns[kMaxContactPoints][2] = {
      {-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
  PlanePoints out;
  LaneVec deepest = Splat(3.402823466e38f);
  LaneVec phi[kMaxContactPoints];
  for (std::size_t j = 0; j < kMaxContactPoints; ++j) {
    out.on_shape[j] = Add(face_centre, Add(Scale(u_axis, Splat(kCornerSigns[j][0])),
                                           Scale(v_axis, Splat(kCornerSigns[j][1]))));
    phi[j] = plane.Distance(out.on_shape[j]);
    deepest = hn::Min(deepest, phi[j]);
  }
  const LaneMask exists = hn::Lt(deepest, speculative);
  for (std::size_t j = 0; j < kMaxContactPoints; ++j) {
    out.keep[j] = hn::And(exists, hn::Lt(phi[j], tolerance));
  }
  return out;
}

// The candidates of a plane pair in one chunk, in body order.
inline ContactCandidates PlanePairCandidates(const ContactBlock& c,
                                             const ContactStepScalars& scalars,
                                             std::size_t offset) {
  const ContactPlan& plan = c.plan;
  const bool plane_is_body1 = plan.shape1.type == ShapeType::kPlane;
  const BodyLanes& plane_body = plane_is_body1 ? *c.bodies.body1 : *c.bodies.body2;
  const BodyLanes& shape_body = plane_is_body1 ? *c.bodies.body2 : *c.bodies.body1;
  const ContactShape& shape_of_plane = plane_is_body1 ? plan.shape1 : plan.shape2;
  const ContactShape& other = plane_is_body1 ? plan.shape2 : plan.shape1;
  const ShapeFrame plane_frame = WorldShapeFrame(plane_body, shape_of_plane, offset);
  const PlaneLanes plane{Rotate(plane_frame.rotation, Vec3{Zero(), Splat(1.0f), Zero()}),
                         plane_frame.centre};
  const ShapeFrame shape = WorldShapeFrame(shape_body, other, offset);
  const Vec3 normal = plane_is_body1 ? plane.normal : Neg(plane.normal);
  const LaneVec speculative = SpeculativeDistance(c, scalars, normal, offset);
  const LaneVec tolerance = hn::Add(speculative, Splat(kContactManifoldTolerance));
  // Returned straight into `points`: assigned in a switch, the aggregate was
  // copied whole (rep movsq on AVX2, Assign in kernels/lane_math-inl.h).
  const PlanePoints points = [&] {
    switch (plan.kind) {
      case ContactPairKind::kPlaneSphere:
        return SpherePoints(plane, shape, other, speculative);
      case ContactPairKind::kPlaneCapsule:
        return CapsulePoints(plane, shape, other, speculative, tolerance);
      default:
        return BoxPoints(plane, shape, other, speculative, tolerance);
    }
  }();
  ContactCandidates found;
  found.normal = normal;
  for (std::size_t i = 0; i < plan.point_count; ++i) {
    const Vec3 on_plane = plane.Project(points.on_shape[i]);
    found.point1[i] = plane_is_body1 ? on_plane : points.on_shape[i];
    found.point2[i] = plane_is_body1 ? points.on_shape[i] : on_plane;
    found.keep[i] = points.keep[i];
  }
  return found;
}

// A sphere's or capsule's core in world space: the segment a -> b (a = b for
// a sphere) swept by radius.
struct CoreSegment {
  Vec3 a, b, centre;
};

inline CoreSegment WorldCore(const BodyLanes& body, const ContactShape& shape,
                             std::size_t offset) {
  const ShapeFrame frame = WorldShapeFrame(body, shape, offset);
  if (shape.type == ShapeType::kSphere) return {frame.centre, frame.centre, frame.centre};
  const Vec3 half = Rotate(frame.rotation, Vec3{Zero(), Splat(shape.half_height), Zero()});
  return {Sub(frame.centre, half), Add(frame.centre, half), frame.centre};
}

// The point of segment a -> b nearest to p.
inline Vec3 NearestOnSegment(const CoreSegment& segment, const Vec3& p) {
  const Vec3 d = Sub(segment.b, segment.a);
  const LaneVec t = hn::Min(
      hn::Max(hn::Div(Dot(Sub(p, segment.a), d), LengthSquared(d)), Zero()), Splat(1.0f));
  return MulAdd(d, t, segment.a);
}

// The closest points of two segments (docs/contacts.md): the lines' closest
// parameters clamped, then each side's nearest point to the other's, in turn;
// parallel segments take the middle of their overlap on segment 1.
inline void ClosestOnSegments(const CoreSegment& s1, const CoreSegment& s2, Vec3& on1,
                              Vec3& on2) {
  const Vec3 d1 = Sub(s1.b, s1.a), d2 = Sub(s2.b, s2.a), e = Sub(s1.a, s2.a);
  const LaneVec a = LengthSquared(d1), ee = LengthSquared(d2), b = Dot(d1, d2);
  const LaneVec c = Dot(d1, e), f = Dot(d2, e);
  const LaneVec determinant = hn::Sub(hn::Mul(a, ee), hn::Mul(b, b));
  const LaneMask parallel = hn::Le(determinant, hn::Mul(Splat(1.0e-6f), hn::Mul(a, ee)));
  const auto clamp01 = [](LaneVec x) { return hn::Min(hn::Max(x, Zero()), Splat(1.0f)); };
  const LaneVec safe_determinant = hn::IfThenElse(parallel, Splat(1.0f), determinant);
  const LaneVec skew_t1 = clamp01(
      hn::Div(hn::Sub(hn::Mul(b, f), hn::Mul(c, ee)), safe_determinant));
  const LaneVec start = clamp01(hn::Div(hn::Neg(c), a));
  const LaneVec end = clamp01(hn::Div(hn::Sub(b, c), a));
  const LaneVec overlap_t1 = hn::Mul(hn::Add(start, end), Splat(0.5f));
  LaneVec t1 = hn::IfThenElse(parallel, overlap_t1, skew_t1);
  const LaneVec t2 = clamp01(hn::Div(hn::MulAdd(b, t1, f), ee));
  t1 = hn::IfThenElse(parallel, t1, clamp01(hn::Div(hn::Sub(hn::Mul(b, t2), c), a)));
  on1 = MulAdd(d1, t1, s1.a);
  on2 = MulAdd(d2, t2, s2.a);
}

// The one point of a sphere or capsule pair in one chunk (docs/contacts.md):
// the closest points of the two cores, pushed out by the radii.
inline ContactCandidates CorePairCandidates(const ContactBlock& c,
                                            const ContactStepScalars& scalars,
                                            std::size_t offset) {
  const ContactPlan& plan = c.plan;
  const CoreSegment core1 = WorldCore(*c.bodies.body1, plan.shape1, offset);
  const CoreSegment core2 = WorldCore(*c.bodies.body2, plan.shape2, offset);
  Vec3 on1, on2;
  switch (plan.kind) {
    case ContactPairKind::kSphereSphere:
      on1 = core1.centre;
      on2 = core2.centre;
      break;
    case ContactPairKind::kSphereCapsule:
      if (plan.shape1.type == ShapeType::kSphere) {
        on1 = core1.centre;
        on2 = NearestOnSegment(core2, on1);
      } else {
        on2 = core2.centre;
        on1 = NearestOnSegment(core1, on2);
      }
      break;
    default:
      ClosestOnSegments(core1, core2, on1, on2);
      break;
  }
  const Vec3 between = Sub(on2, on1);
  const LaneVec distance = hn::Sqrt(LengthSquared(between));
  // Cores that meet (distance 0): crossing capsules push apart along d1 x d2
  // as it comes (crossing cores have no side towards the other), anything
  // else along +Y.
  Vec3 fallback{Zero(), Splat(1.0f), Zero()};
  if (plan.kind == ContactPairKind::kCapsuleCapsule) {
    const Vec3 cross = Cross(Sub(core1.b, core1.a), Sub(core2.b, core2.a));
    fallback = DirectionOrPrevious(cross, hn::Sqrt(LengthSquared(cross)), fallback);
  }
  ContactCandidates found;
  found.normal = DirectionOrPrevious(between, distance, fallback);
  const LaneVec radius1 = Splat(plan.shape1.radius), radius2 = Splat(plan.shape2.radius);
  found.point1[0] = MulAdd(found.normal, radius1, on1);
  found.point2[0] = NegMulAdd(found.normal, radius2, on2);
  found.keep[0] = hn::Lt(hn::Sub(distance, hn::Add(radius1, radius2)),
                        SpeculativeDistance(c, scalars, found.normal, offset));
  return found;
}

}  // namespace HWY_NAMESPACE
}  // namespace manyworlds
HWY_AFTER_NAMESPACE();

#endif  // MANYWORLDS_BATCH_CONTACT_POINTS_INL_H_
