// Lane maths of a Hermite path (kernels/hermite_path.h, spec 3 Path), the
// same path in every lane and a different query point or fraction per lane.
//
// Segment i between points P_i, P_j (j = i + 1, or 0 for the last segment of a
// looping path) with tangents M_i, M_j, for t in [0, 1]:
//   P(t) = h00 P_i + h10 M_i + h01 P_j + h11 M_j,
//   h00 = 2t^3 - 3t^2 + 1, h10 = t^3 - 2t^2 + t, h01 = -2t^3 + 3t^2, h11 = t^3 - t^2,
// and P'(t) from the derivatives of the h's.
//
// Closest point to q (Jolt's GetClosestPoint; per segment, with P relative to
// q so the target is the origin): the roots of f(t) = P(t) . P'(t).
//   1. A bracket by bisection, as Jolt: f(0) = P_i . M_i within 1e-6 of zero
//      gives t = 0, f(1) within 1e-6 gives t = 1; if f(0), f(1) have the same
//      sign the bracket stays [0, 1]; else 4 halvings (a zero within 1e-6 on
//      the way ends the search there). Newton on all of [0, 1] can settle on
//      a local minimum of |P|^2 of the quintic, e.g. for straight segments.
//   2. Newton from the middle of the bracket, at most 10 steps of
//      -f / f' (f' = P' . P' + P . P''), each clamped to +-(bracket width);
//      stop when f' = 0, when the step leaves the bracket further, or when
//      it is below 1e-4. The squared distance is that of the last point
//      evaluated (before the last step), as Jolt.
//   3. The candidates: every control point (the segment's first point and
//      the path's last point), the bisection's exact root, and Newton's t if
//      within [0, 1]; the nearest wins, the first on ties.
// Every decision is a lane mask; a lane's result never depends on another.
//
// Point on path (Jolt's GetPointOnPath): index = trunc(fraction), t =
// fraction - index; a looping path wraps the index into [0, count); an open
// one clamps to (0, 0) below and (count - 2, 1) above. Tangent = P'/|P'|;
// normal linearly interpolated, binormal = normalize(normal x tangent),
// normal = tangent x binormal.

#if defined(MANYWORLDS_KERNELS_HERMITE_PATH_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef MANYWORLDS_KERNELS_HERMITE_PATH_INL_H_
#undef MANYWORLDS_KERNELS_HERMITE_PATH_INL_H_
#else
#define MANYWORLDS_KERNELS_HERMITE_PATH_INL_H_
#endif

#include <cstddef>

#include "kernels/hermite_path.h"
#include "kernels/lane_math-inl.h"

HWY_BEFORE_NAMESPACE();
namespace manyworlds {
namespace HWY_NAMESPACE {
namespace hermite {

struct Segment {
  Vec3 p1, m1, p2, m2;
};

HWY_INLINE Vec3 SplatVec3(const float v[3]) { return {Splat(v[0]), Splat(v[1]), Splat(v[2])}; }

// Segment i's control points, positions relative to q.
HWY_INLINE Segment SegmentRelativeTo(const HermitePath& path, std::size_t i, const Vec3& q) {
  const HermitePathPoint& a = path.points[i];
  const HermitePathPoint& b = path.points[(i + 1) % path.count];
  return {Sub(SplatVec3(a.position), q), SplatVec3(a.tangent), Sub(SplatVec3(b.position), q),
          SplatVec3(b.tangent)};
}

HWY_INLINE void PositionAndTangent(const Segment& s, LaneVec t, Vec3& position, Vec3& tangent) {
  const LaneVec t2 = hn::Mul(t, t), t3 = hn::Mul(t, t2);
  const LaneVec two = Splat(2.0f), three = Splat(3.0f), one = Splat(1.0f);
  const LaneVec h00 = hn::Add(hn::Sub(hn::Mul(two, t3), hn::Mul(three, t2)), one);
  const LaneVec h10 = hn::Add(hn::Sub(t3, hn::Mul(two, t2)), t);
  const LaneVec h01 = hn::Sub(hn::Mul(three, t2), hn::Mul(two, t3));
  const LaneVec h11 = hn::Sub(t3, t2);
  const LaneVec d00 = hn::Mul(Splat(6.0f), hn::Sub(t2, t));
  const LaneVec d10 = hn::Add(hn::Sub(hn::Mul(three, t2), hn::Mul(Splat(4.0f), t)), one);
  const LaneVec d01 = hn::Neg(d00);
  const LaneVec d11 = hn::Sub(hn::Mul(three, t2), hn::Mul(two, t));
  position = Add(Add(Scale(s.p1, h00), Scale(s.m1, h10)), Add(Scale(s.p2, h01), Scale(s.m2, h11)));
  tangent = Add(Add(Scale(s.p1, d00), Scale(s.m1, d10)), Add(Scale(s.p2, d01), Scale(s.m2, d11)));
}

HWY_INLINE Vec3 SecondDerivative(const Segment& s, LaneVec t) {
  const LaneVec d00 = hn::Sub(hn::Mul(Splat(12.0f), t), Splat(6.0f));
  const LaneVec d10 = hn::Sub(hn::Mul(Splat(6.0f), t), Splat(4.0f));
  const LaneVec d11 = hn::Sub(hn::Mul(Splat(6.0f), t), Splat(2.0f));
  return Add(Add(Scale(s.p1, d00), Scale(s.m1, d10)),
             Add(Scale(s.p2, hn::Neg(d00)), Scale(s.m2, d11)));
}

HWY_INLINE LaneMask NearZero(LaneVec x) { return hn::Lt(hn::Abs(x), Splat(1.0e-6f)); }

// Step 1: the bracket [t_min, t_max] (equal where a root was found).
HWY_INLINE void Bracket(const Segment& s, LaneVec& t_min, LaneVec& t_max) {
  const LaneVec f_min = Dot(s.p1, s.m1), f_max = Dot(s.p2, s.m2);
  const LaneMask root_at_0 = NearZero(f_min);
  const LaneMask root_at_1 = hn::AndNot(root_at_0, NearZero(f_max));
  const LaneMask min_negative = hn::Lt(f_min, Zero());
  const LaneMask signs_differ = hn::Xor(min_negative, hn::Lt(f_max, Zero()));
  t_min = hn::IfThenElse(root_at_1, Splat(1.0f), Zero());
  t_max = hn::IfThenElse(root_at_0, Zero(), Splat(1.0f));
  LaneMask searching = hn::AndNot(hn::Or(root_at_0, root_at_1), signs_differ);
  for (int iteration = 0; iteration < 4 && AnyLane(searching); ++iteration) {
    const LaneVec t_mid = hn::Mul(Splat(0.5f), hn::Add(t_min, t_max));
    Vec3 position, tangent;
    PositionAndTangent(s, t_mid, position, tangent);
    const LaneVec f_mid = Dot(position, tangent);
    const LaneMask root = hn::And(searching, NearZero(f_mid));
    t_min = hn::IfThenElse(root, t_mid, t_min);
    t_max = hn::IfThenElse(root, t_mid, t_max);
    searching = hn::AndNot(root, searching);
    const LaneMask same_as_min = hn::Not(hn::Xor(hn::Lt(f_mid, Zero()), min_negative));
    t_min = hn::IfThenElse(hn::And(searching, same_as_min), t_mid, t_min);
    t_max = hn::IfThenElse(hn::AndNot(same_as_min, searching), t_mid, t_max);
  }
}

// Step 2: Newton in the lanes of `active` (t_min != t_max); returns t and the
// squared distance of the last point evaluated.
HWY_INLINE LaneVec Newton(const Segment& s, LaneVec t_min, LaneVec t_max, LaneMask active,
                          LaneVec& distance_squared) {
  const LaneVec interval = hn::Sub(t_max, t_min);
  LaneVec t = hn::Mul(Splat(0.5f), hn::Add(t_min, t_max));
  Vec3 closest = ZeroVec3();
  for (int iteration = 0; iteration < 10 && AnyLane(active); ++iteration) {
    Vec3 position, tangent;
    PositionAndTangent(s, t, position, tangent);
    closest = Select(active, position, closest);
    const LaneVec f = Dot(position, tangent);
    const LaneVec f_prime = hn::Add(Dot(tangent, tangent), Dot(position, SecondDerivative(s, t)));
    active = hn::AndNot(hn::Eq(f_prime, Zero()), active);
    const LaneVec safe_f_prime = hn::IfThenElse(active, f_prime, Splat(1.0f));
    const LaneVec delta =
        hn::Min(hn::Max(hn::Neg(hn::Div(f, safe_f_prime)), hn::Neg(interval)), interval);
    const LaneMask leaving = hn::Or(hn::And(hn::Gt(t, t_max), hn::Gt(delta, Zero())),
                                    hn::And(hn::Lt(t, t_min), hn::Lt(delta, Zero())));
    active = hn::AndNot(leaving, active);
    t = hn::IfThenElse(active, hn::Add(t, delta), t);
    active = hn::AndNot(hn::Lt(hn::Abs(delta), Splat(1.0e-4f)), active);
  }
  distance_squared = LengthSquared(closest);
  return t;
}

// Jolt's GetClosestPoint for one chunk of query points (path space).
HWY_INLINE LaneVec ClosestPoint(const HermitePath& path, const Vec3& q) {
  const HermitePathPoint& last = path.points[path.count - 1];
  LaneVec best_distance = LengthSquared(Sub(SplatVec3(last.position), q));
  LaneVec best_fraction = Splat(float(path.count - 1));
  for (std::size_t i = 0; i < path.segments(); ++i) {
    const Segment s = SegmentRelativeTo(path, i, q);
    const LaneVec segment_start = Splat(float(i));
    const auto take = [&](LaneMask better, LaneVec fraction, LaneVec distance) {
      best_fraction = hn::IfThenElse(better, fraction, best_fraction);
      best_distance = hn::IfThenElse(better, distance, best_distance);
    };
    const LaneVec to_start = LengthSquared(s.p1);
    take(hn::Lt(to_start, best_distance), segment_start, to_start);

    LaneVec t_min, t_max;
    Bracket(s, t_min, t_max);
    const LaneMask found = hn::Eq(t_min, t_max);
    Vec3 position, tangent;
    PositionAndTangent(s, t_min, position, tangent);
    const LaneVec at_root = LengthSquared(position);
    take(hn::And(found, hn::Lt(at_root, best_distance)), hn::Add(segment_start, t_min), at_root);

    LaneVec newton_distance;
    const LaneVec t = Newton(s, t_min, t_max, hn::Not(found), newton_distance);
    const LaneMask in_segment = hn::And(hn::Ge(t, Zero()), hn::Le(t, Splat(1.0f)));
    take(hn::AndNot(found, hn::And(in_segment, hn::Lt(newton_distance, best_distance))),
         hn::Add(segment_start, t), newton_distance);
  }
  return best_fraction;
}

struct PathFrame {
  Vec3 position, tangent, normal, binormal;
};

// Jolt's GetPointOnPath for one chunk of fractions.
HWY_INLINE PathFrame PointOnPath(const HermitePath& path, LaneVec fraction) {
  LaneVec index = hn::Trunc(fraction);
  LaneVec t = hn::Sub(fraction, index);
  const LaneVec count = Splat(float(path.count));
  if (path.looping) {
    // The non-negative remainder: Jolt adds multiples of count, then takes %.
    index = hn::Sub(index, hn::Mul(count, hn::Floor(hn::Div(index, count))));
  } else {
    const LaneMask below = hn::Lt(index, Zero());
    const LaneMask above = hn::Ge(index, Splat(float(path.count - 1)));
    index = hn::IfThenElse(below, Zero(), hn::IfThenElse(above, Splat(float(path.count - 2)), index));
    t = hn::IfThenElse(below, Zero(), hn::IfThenElse(above, Splat(1.0f), t));
  }
  // The segment's points, chosen per lane.
  Segment s = SegmentRelativeTo(path, 0, ZeroVec3());
  Vec3 n1 = SplatVec3(path.points[0].normal), n2 = SplatVec3(path.points[1 % path.count].normal);
  for (std::size_t i = 1; i < path.segments(); ++i) {
    const LaneMask here = hn::Eq(index, Splat(float(i)));
    if (!AnyLane(here)) continue;
    const Segment si = SegmentRelativeTo(path, i, ZeroVec3());
    s = {Select(here, si.p1, s.p1), Select(here, si.m1, s.m1), Select(here, si.p2, s.p2),
         Select(here, si.m2, s.m2)};
    n1 = Select(here, SplatVec3(path.points[i].normal), n1);
    n2 = Select(here, SplatVec3(path.points[(i + 1) % path.count].normal), n2);
  }
  PathFrame frame;
  Vec3 tangent;
  PositionAndTangent(s, t, frame.position, tangent);
  frame.tangent = Normalize(tangent);
  const Vec3 normal = Add(Scale(n1, hn::Sub(Splat(1.0f), t)), Scale(n2, t));
  frame.binormal = Normalize(Cross(normal, frame.tangent));
  frame.normal = Cross(frame.tangent, frame.binormal);
  return frame;
}

}  // namespace hermite
}  // namespace HWY_NAMESPACE
}  // namespace manyworlds
HWY_AFTER_NAMESPACE();

#endif  // MANYWORLDS_KERNELS_HERMITE_PATH_INL_H_
