// Contact points of a box with a sphere, capsule or box, for every world of a
// chunk at once (docs/contacts.md, "Points of a box with a sphere, capsule or
// box"). Boxes are sharp. Everything is found in box A's coordinates (the box
// of a sphere or capsule pair; body 1's box of a box pair), normal from A to
// B, then turned into world space and body order.
//   sphere:  the centre's clamp into the box; inside, the face of least depth
//   capsule: the closest pair of core and box (ends' clamps, the 12 edges),
//            or the face of least push-out where the core touches the box;
//            lying along the box's face, the core clipped to that face (2
//            points, each kept within D + 1 mm)
//   box:     the separating axis of largest separation (15 axes, an edge
//            axis only 1 mm beyond the best face axis), then the faces of
//            both boxes towards each other clipped against each other in
//            projection along n: B's corners inside A's face, A's corners
//            inside B's face, the 16 crossings of their edges; more than
//            four kept points are pruned as Jolt prunes them
// Per-world choices (which face, which axis, inside or outside) are lane
// masks: every lane runs the same instructions.

#if defined(MANYWORLDS_BATCH_BOX_CONTACT_POINTS_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef MANYWORLDS_BATCH_BOX_CONTACT_POINTS_INL_H_
#undef MANYWORLDS_BATCH_BOX_CONTACT_POINTS_INL_H_
#else
#define MANYWORLDS_BATCH_BOX_CONTACT_POINTS_INL_H_
#endif

#include <cstddef>

#include "batch/contact_points-inl.h"

HWY_BEFORE_NAMESPACE();
namespace manyworlds {
namespace HWY_NAMESPACE {

// One of the three axes per lane (exactly one mask set).
struct AxisPick {
  LaneMask x, y, z;
};

// The first index of the largest of three values.
inline AxisPick FirstLargest(LaneVec ax, LaneVec ay, LaneVec az) {
  const LaneMask x = hn::And(hn::Ge(ax, ay), hn::Ge(ax, az));
  const LaneMask y = hn::AndNot(x, hn::Ge(ay, az));
  return {x, y, hn::Not(hn::Or(x, y))};
}

// The first index of the smallest of three values.
inline AxisPick FirstSmallest(LaneVec ax, LaneVec ay, LaneVec az) {
  return FirstLargest(hn::Neg(ax), hn::Neg(ay), hn::Neg(az));
}

// v's component along the picked axis k, and along the other two (u, v in
// increasing index).
inline LaneVec AlongK(const AxisPick& k, const Vec3& v) {
  return hn::IfThenElse(k.x, v.x, hn::IfThenElse(k.y, v.y, v.z));
}
inline LaneVec AlongU(const AxisPick& k, const Vec3& v) { return hn::IfThenElse(k.x, v.y, v.x); }
inline LaneVec AlongV(const AxisPick& k, const Vec3& v) { return hn::IfThenElse(k.z, v.y, v.z); }

// The vector with `length` along the picked axis.
inline Vec3 OnAxis(const AxisPick& k, LaneVec length) {
  return {hn::IfThenElseZero(k.x, length), hn::IfThenElseZero(k.y, length),
          hn::IfThenElseZero(k.z, length)};
}

// v with its picked component replaced by `value`.
inline Vec3 WithK(const AxisPick& k, const Vec3& v, LaneVec value) {
  return {hn::IfThenElse(k.x, value, v.x), hn::IfThenElse(k.y, value, v.y),
          hn::IfThenElse(k.z, value, v.z)};
}

// A face's boundary is widened by 1e-4 of its half extent for the inside
// tests, and an edge's parameter range by 1e-4 at each end, so that points
// exactly on a face's edge line (a capsule lying along a box's edge, equal
// boxes stacked flush) are kept whatever the rounding (docs/contacts.md).
inline constexpr float kEdgeGrace = 1.0001f;
inline constexpr float kEdgeSlack = 1.0e-4f;

// +1 where x >= 0, else -1.
inline LaneVec SignOf(LaneVec x) {
  return hn::IfThenElse(hn::Ge(x, Zero()), Splat(1.0f), Splat(-1.0f));
}

inline Vec3 AbsVec(const Vec3& v) { return {hn::Abs(v.x), hn::Abs(v.y), hn::Abs(v.z)}; }

inline Vec3 ClampToBox(const Vec3& p, const Vec3& half) {
  return {hn::Min(hn::Max(p.x, hn::Neg(half.x)), half.x),
          hn::Min(hn::Max(p.y, hn::Neg(half.y)), half.y),
          hn::Min(hn::Max(p.z, hn::Neg(half.z)), half.z)};
}

// x / y where `use`, else a value never read (no division by zero).
inline LaneVec DivWhere(LaneMask use, LaneVec x, LaneVec y) {
  return hn::Div(x, hn::IfThenElse(use, y, Splat(1.0f)));
}

// A box in one chunk: centre, rotation (columns: its axes in world space) and
// half extents.
struct BoxFrame {
  Vec3 centre;
  Mat33 rotation;
  Vec3 half;
  Vec3 Local(const Vec3& y) const { return Multiply(Transpose(rotation), Sub(y, centre)); }
  Vec3 LocalVector(const Vec3& v) const { return Multiply(Transpose(rotation), v); }
  Vec3 World(const Vec3& l) const { return Add(centre, Multiply(rotation, l)); }
  Vec3 WorldVector(const Vec3& m) const { return Multiply(rotation, m); }
};

inline BoxFrame WorldBox(const BodyLanes& body, const ContactShape& shape, std::size_t offset) {
  const ShapeFrame frame = WorldShapeFrame(body, shape, offset);
  return {frame.centre, RotationMatrix(frame.rotation),
          Vec3{Splat(shape.half_extents[0]), Splat(shape.half_extents[1]),
               Splat(shape.half_extents[2])}};
}

// Points found in box A's coordinates, normal m from A to B, before they are
// turned into world space and body order.
struct BoxLocalPoints {
  Vec3 normal;
  Vec3 on_a[kMaxContactPoints], on_b[kMaxContactPoints];
  LaneMask keep[kMaxContactPoints];
};

// World points and normal in body order: A is body 1 unless `a_is_body2`.
inline ContactCandidates ToBodyOrder(const BoxFrame& a, const BoxLocalPoints& local,
                                     std::size_t point_count, bool a_is_body2) {
  ContactCandidates found;
  const Vec3 normal = a.WorldVector(local.normal);
  found.normal = a_is_body2 ? Neg(normal) : normal;
  for (std::size_t i = 0; i < point_count; ++i) {
    const Vec3 on_a = a.World(local.on_a[i]), on_b = a.World(local.on_b[i]);
    found.point1[i] = a_is_body2 ? on_b : on_a;
    found.point2[i] = a_is_body2 ? on_a : on_b;
    found.keep[i] = local.keep[i];
  }
  return found;
}

// The slot's speculative distance for a normal m in A's coordinates.
inline LaneVec BoxSpeculative(const ContactBlock& c, const ContactStepScalars& scalars,
                              const BoxFrame& a, const Vec3& m, bool a_is_body2,
                              std::size_t offset) {
  const Vec3 normal = a.WorldVector(m);
  return SpeculativeDistance(c, scalars, a_is_body2 ? Neg(normal) : normal, offset);
}

// A slot's box (A) and its other shape (B, a sphere or capsule) in one chunk.
struct BoxAndOther {
  bool box_is_body2;
  BoxFrame box;
  const ContactShape& other;
  ShapeFrame other_frame;
};

inline BoxAndOther SplitBoxPair(const ContactBlock& c, std::size_t offset) {
  const bool box_is_body2 = c.plan.shape2.type == ShapeType::kBox;
  const ContactShape& other = box_is_body2 ? c.plan.shape1 : c.plan.shape2;
  return {box_is_body2,
          box_is_body2 ? WorldBox(*c.bodies.body2, c.plan.shape2, offset)
                       : WorldBox(*c.bodies.body1, c.plan.shape1, offset),
          other,
          WorldShapeFrame(box_is_body2 ? *c.bodies.body1 : *c.bodies.body2, other, offset)};
}

// ---- Sphere and box: one point ----
inline ContactCandidates SphereBoxCandidates(const ContactBlock& c,
                                             const ContactStepScalars& scalars,
                                             std::size_t offset) {
  const BoxAndOther pair = SplitBoxPair(c, offset);
  const bool box_is_body2 = pair.box_is_body2;
  const BoxFrame& box = pair.box;
  const ContactShape& sphere_shape = pair.other;
  const ShapeFrame& sphere = pair.other_frame;
  const Vec3 l = box.Local(sphere.centre);
  const Vec3 clamped = ClampToBox(l, box.half);
  const Vec3 out = Sub(l, clamped);
  const LaneVec out_squared = LengthSquared(out);
  const LaneMask outside = hn::Gt(out_squared, Zero());
  const LaneVec out_length = hn::Sqrt(out_squared);
  // Inside: the face of least depth g_k = h_k - |l_k|.
  const Vec3 depth = Sub(box.half, AbsVec(l));
  const AxisPick k = FirstSmallest(depth.x, depth.y, depth.z);
  const LaneVec side = SignOf(AlongK(k, l));
  BoxLocalPoints local;
  local.normal = Select(outside, Scale(out, DivWhere(outside, Splat(1.0f), out_length)),
                        OnAxis(k, side));
  const LaneVec distance = hn::IfThenElse(outside, out_length, hn::Neg(AlongK(k, depth)));
  local.on_a[0] = Select(outside, clamped, WithK(k, l, hn::Mul(side, AlongK(k, box.half))));
  const LaneVec radius = Splat(sphere_shape.radius);
  local.on_b[0] = NegMulAdd(local.normal, radius, l);
  local.keep[0] = hn::Lt(hn::Sub(distance, radius),
                         BoxSpeculative(c, scalars, box, local.normal, box_is_body2, offset));
  return ToBodyOrder(box, local, 1, box_is_body2);
}

// ---- Capsule and box: up to two points ----

// Whether the segment a -> b meets the closed box (slab test).
inline LaneMask SegmentMeetsBox(const Vec3& a, const Vec3& b, const Vec3& half) {
  LaneVec t_in = Zero(), t_out = Splat(1.0f);
  LaneMask missed = NoLanes();
  const LaneVec as[3] = {a.x, a.y, a.z}, bs[3] = {b.x, b.y, b.z}, hs[3] = {half.x, half.y, half.z};
  for (int k = 0; k < 3; ++k) {
    const LaneVec d = hn::Sub(bs[k], as[k]);
    const LaneMask moving = hn::Ne(d, Zero());
    missed = hn::Or(missed, hn::AndNot(moving, hn::Gt(hn::Abs(as[k]), hs[k])));
    const LaneVec t1 = DivWhere(moving, hn::Sub(hn::Neg(hs[k]), as[k]), d);
    const LaneVec t2 = DivWhere(moving, hn::Sub(hs[k], as[k]), d);
    t_in = hn::IfThenElse(moving, hn::Max(t_in, hn::Min(t1, t2)), t_in);
    t_out = hn::IfThenElse(moving, hn::Min(t_out, hn::Max(t1, t2)), t_out);
  }
  return hn::AndNot(missed, hn::Le(t_in, t_out));
}

// The closest pair of segment a -> b and the box (the segment not meeting
// it): the ends' clamps, then the 12 edges, the first of the least distance.
inline void ClosestOfSegmentAndBox(const CoreSegment& core, const Vec3& half, Vec3& on_core,
                                   Vec3& on_box, LaneVec& distance_squared) {
  on_core = core.a;
  on_box = ClampToBox(core.a, half);
  distance_squared = LengthSquared(Sub(on_core, on_box));
  const auto consider = [&](const Vec3& p, const Vec3& q) {
    const LaneVec d = LengthSquared(Sub(p, q));
    const LaneMask better = hn::Lt(d, distance_squared);
    on_core = Select(better, p, on_core);
    on_box = Select(better, q, on_box);
    distance_squared = hn::Min(d, distance_squared);
  };
  consider(core.b, ClampToBox(core.b, half));
  // The edges along axis k at (s_u h_u, s_v h_v) across it, from -h_k to +h_k.
  static constexpr float kEdgeSigns[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
  const LaneVec h[3] = {half.x, half.y, half.z};
  const auto on_axes = [](int k, LaneVec along, LaneVec u, LaneVec v) {
    return k == 0 ? Vec3{along, u, v} : k == 1 ? Vec3{u, along, v} : Vec3{u, v, along};
  };
  for (int k = 0; k < 3; ++k) {
    const LaneVec h_u = h[k == 0 ? 1 : 0], h_v = h[k == 2 ? 1 : 2];
    for (const auto& signs : kEdgeSigns) {
      const LaneVec u = hn::Mul(Splat(signs[0]), h_u), v = hn::Mul(Splat(signs[1]), h_v);
      const Vec3 start = on_axes(k, hn::Neg(h[k]), u, v);
      Vec3 p, q;
      ClosestOnSegments(core, CoreSegment{start, on_axes(k, h[k], u, v), start}, p, q);
      consider(p, q);
    }
  }
}

inline ContactCandidates CapsuleBoxCandidates(const ContactBlock& c,
                                              const ContactStepScalars& scalars,
                                              std::size_t offset) {
  const BoxAndOther pair = SplitBoxPair(c, offset);
  const bool box_is_body2 = pair.box_is_body2;
  const BoxFrame& box = pair.box;
  const ContactShape& capsule_shape = pair.other;
  const ShapeFrame& capsule = pair.other_frame;
  // The capsule's axis (its +Y) and core a -> b in box coordinates.
  const Vec3 axis_unit =
      box.LocalVector(Rotate(capsule.rotation, Vec3{Zero(), Splat(1.0f), Zero()}));
  const Vec3 centre = box.Local(capsule.centre);
  const Vec3 half_core = Scale(axis_unit, Splat(capsule_shape.half_height));
  const CoreSegment core{Sub(centre, half_core), Add(centre, half_core), centre};
  const Vec3& half = box.half;
  const LaneVec radius = Splat(capsule_shape.radius);

  // The closest pair, or where the core meets the box the face of least
  // push-out g = h_k - min(s a_k, s b_k) over (k, s) = (0, +), (0, -), ...
  Vec3 on_core, on_box;
  LaneVec distance_squared;
  ClosestOfSegmentAndBox(core, half, on_core, on_box, distance_squared);
  const LaneVec distance = hn::Sqrt(distance_squared);
  const LaneMask touching =
      hn::Or(SegmentMeetsBox(core.a, core.b, half), hn::Eq(distance, Zero()));
  LaneVec least = Splat(3.402823466e38f), least_side = Zero();
  AxisPick least_axis{NoLanes(), NoLanes(), NoLanes()};
  LaneMask* const axis_masks[3] = {&least_axis.x, &least_axis.y, &least_axis.z};
  const LaneVec as[3] = {core.a.x, core.a.y, core.a.z}, bs[3] = {core.b.x, core.b.y, core.b.z},
                hs[3] = {half.x, half.y, half.z};
  for (int k = 0; k < 3; ++k) {
    for (const float side : {1.0f, -1.0f}) {
      const LaneVec s = Splat(side);
      const LaneVec g = hn::Sub(hs[k], hn::Min(hn::Mul(s, as[k]), hn::Mul(s, bs[k])));
      const LaneMask better = hn::Lt(g, least);
      least = hn::IfThenElse(better, g, least);
      least_side = hn::IfThenElse(better, s, least_side);
      for (int j = 0; j < 3; ++j) *axis_masks[j] = hn::AndNot(better, *axis_masks[j]);
      *axis_masks[k] = hn::Or(*axis_masks[k], better);
    }
  }
  const LaneMask a_lower = hn::Le(hn::Mul(least_side, AlongK(least_axis, core.a)),
                                  hn::Mul(least_side, AlongK(least_axis, core.b)));
  const Vec3 pushed_end = Select(a_lower, core.a, core.b);
  const Vec3 pushed_on_box = WithK(least_axis, ClampToBox(pushed_end, half),
                                   hn::Mul(least_side, AlongK(least_axis, half)));
  const Vec3 apart = Scale(Sub(on_core, on_box), DivWhere(hn::Not(touching), Splat(1.0f), distance));
  const Vec3 m = Select(touching, OnAxis(least_axis, least_side), apart);
  const LaneVec separation_of_core = hn::IfThenElse(touching, hn::Neg(least), distance);
  on_core = Select(touching, pushed_end, on_core);
  on_box = Select(touching, pushed_on_box, on_box);

  const LaneVec speculative = BoxSpeculative(c, scalars, box, m, box_is_body2, offset);
  const LaneMask exists = hn::Lt(hn::Sub(separation_of_core, radius), speculative);

  // Lying along the face towards the capsule: the capsule's face a' -> b'
  // clipped to the box's face in projection along m (+u, -u, +v, -v).
  const Vec3 axis = Sub(core.b, core.a);
  const LaneVec along = Dot(axis_unit, m);
  const LaneMask flat = hn::And(
      hn::Lt(hn::Abs(hn::Mul(Splat(2.0f * capsule_shape.half_height), along)),
             Splat(kCapsuleProjectionSlop)),
      hn::Lt(hn::Abs(along), Splat(1.0f)));
  const AxisPick k = FirstLargest(hn::Abs(m.x), hn::Abs(m.y), hn::Abs(m.z));
  const LaneVec face = hn::Mul(SignOf(AlongK(k, m)), AlongK(k, half));
  const LaneVec m_k = AlongK(k, m);
  // (|alpha| < 1 leaves it non-zero but for rounding: then m, as the
  // reference and the plane rule.)
  const Vec3 across_axis = Sub(m, Scale(axis_unit, along));
  const Vec3 across = DirectionOrPrevious(across_axis, hn::Sqrt(LengthSquared(across_axis)), m);
  const Vec3 start = NegMulAdd(across, radius, core.a);
  const Vec3 direction = axis;  // b' - a' = b - a
  const auto height = [&](const Vec3& p) { return hn::Div(hn::Sub(AlongK(k, p), face), m_k); };
  const auto project = [&](const Vec3& p) { return NegMulAdd(m, height(p), p); };
  const Vec3 start_projected = project(start);
  const Vec3 end_projected = project(Add(start, direction));
  LaneVec t_in = Zero(), t_out = Splat(1.0f);
  LaneMask empty = hn::Not(flat);
  const LaneVec h_u = hn::Mul(Splat(kEdgeGrace), AlongU(k, half));
  const LaneVec h_v = hn::Mul(Splat(kEdgeGrace), AlongV(k, half));
  const LaneVec f_u0 = AlongU(k, start_projected), f_v0 = AlongV(k, start_projected);
  const LaneVec f_u1 = hn::Sub(AlongU(k, end_projected), f_u0);
  const LaneVec f_v1 = hn::Sub(AlongV(k, end_projected), f_v0);
  const struct {
    LaneVec f0, f1, bound;
  } conditions[4] = {{f_u0, f_u1, h_u}, {hn::Neg(f_u0), hn::Neg(f_u1), h_u},
                     {f_v0, f_v1, h_v}, {hn::Neg(f_v0), hn::Neg(f_v1), h_v}};
  for (const auto& f : conditions) {
    const LaneMask rising = hn::Gt(f.f1, Zero()), falling = hn::Lt(f.f1, Zero());
    const LaneVec t = DivWhere(hn::Or(rising, falling), hn::Sub(f.bound, f.f0), f.f1);
    t_out = hn::IfThenElse(rising, hn::Min(t_out, t), t_out);
    t_in = hn::IfThenElse(falling, hn::Max(t_in, t), t_in);
    empty = hn::Or(empty, hn::AndNot(hn::Or(rising, falling), hn::Gt(f.f0, f.bound)));
  }
  const LaneMask clipped = hn::And(exists, hn::AndNot(empty, hn::Le(t_in, t_out)));
  const LaneVec keep_below = hn::Add(speculative, Splat(kContactManifoldTolerance));
  BoxLocalPoints local;
  local.normal = m;
  LaneMask clip_keep[2];
  Vec3 clip_on_capsule[2], clip_on_box[2];
  const LaneVec ts[2] = {t_in, t_out};
  for (int i = 0; i < 2; ++i) {
    clip_on_capsule[i] = MulAdd(direction, ts[i], start);
    const LaneVec lambda = height(clip_on_capsule[i]);
    clip_on_box[i] = NegMulAdd(m, lambda, clip_on_capsule[i]);
    clip_keep[i] = hn::And(clipped, hn::Lt(lambda, keep_below));
  }
  const LaneMask use_clip = hn::Or(clip_keep[0], clip_keep[1]);
  local.on_b[0] = Select(use_clip, clip_on_capsule[0], NegMulAdd(m, radius, on_core));
  local.on_a[0] = Select(use_clip, clip_on_box[0], on_box);
  local.keep[0] = hn::Or(clip_keep[0], hn::AndNot(use_clip, exists));
  local.on_b[1] = clip_on_capsule[1];
  local.on_a[1] = clip_on_box[1];
  local.keep[1] = clip_keep[1];
  return ToBodyOrder(box, local, 2, box_is_body2);
}

}  // namespace HWY_NAMESPACE
}  // namespace manyworlds
HWY_AFTER_NAMESPACE();

#endif  // MANYWORLDS_BATCH_BOX_CONTACT_POINTS_INL_H_
