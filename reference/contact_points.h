// Contact points of the reference world (docs/contacts.md, "Points of a plane
// pair" and "Points of a pair of spheres and capsules"): for one slot's pair
// of shapes, the candidate points and the normal from body 1 to body 2, from
// the poses at the start of a substep. reference/contact_constraint.h keeps
// the points it wants and solves them. Scalar reference, written from the
// docs; nothing of batch/ or kernels/.
//
// ---- Points (every substep, from the poses at its start) ----
// Plane: outward unit normal n_p (the plane shape's +Y), centre o, signed
// distance φ(y) = n_p·(y − o). D = speculative distance, K_keep = D + 1 mm.
// The shape gives candidate points y_j in a fixed order (sphere: c − r n_p;
// capsule: both ends − r ŵ when it lies flat within 2 cm, else the lower end
// − r n_p; box: the 4 corners of the face towards the plane). The manifold
// exists when min_j φ(y_j) < D and keeps the candidates with φ < K_keep; each
// kept point is (y_j on the shape, y_j − φ(y_j) n_p on the plane).
// n points from body 1 to body 2: n_p when the plane is body 1, −n_p otherwise;
// p1 is the point on body 1, p2 the point on body 2, so s = (p2 − p1)·n = φ.
//
// Spheres and capsules (one point): each is a core segment swept by its
// radius, a = c − h â to b = c + h â (a sphere: a = b = c). With s1, s2 the
// closest points of body 1's and body 2's cores (sphere–sphere: the centres;
// sphere–capsule: the segment point nearest the centre; capsule–capsule: the
// segments' closest points, the middle of the overlap when parallel),
//   δ = s2 − s1, L = |δ|, n = δ/L (L = 0: n = normalize(d1 × d2) for two
//   capsules, as it comes; else, or d1 × d2 = 0, +Y),
//   p1 = s1 + r1 n, p2 = s2 − r2 n, s = L − r1 − r2;
// the point (and the manifold) exists when L − r1 − r2 < D.
//
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <tuple>
#include <utility>

#include "manyworlds/scene.h"
#include "reference/math.h"
#include "reference/world_setup.h"  // ToVec3, ToQuat

namespace manyworlds::reference {

// The most points a slot holds (a box face's four corners).
inline constexpr int kMaxContactPoints = 4;

// A body's shape in T: where it sits in the body's COM frame and its sizes.
template <class T>
struct ContactShape {
  ShapeType type = ShapeType::kNone;
  T radius = T(0);
  T half_height = T(0);
  Vec3<T> half_extents = Vec3<T>::Zero();
  Vec3<T> position = Vec3<T>::Zero();     // body COM frame
  Quat<T> rotation = Quat<T>::Identity();  // shape frame to body frame
};

template <class T>
ContactShape<T> MakeContactShape(const ShapeSettings& settings) {
  ContactShape<T> shape;
  shape.type = settings.type;
  shape.radius = T(settings.radius);
  shape.half_height = T(settings.half_height);
  shape.half_extents = ToVec3<T>(settings.half_extents);
  shape.position = ToVec3<T>(settings.position);
  shape.rotation = ToQuat<T>(settings.rotation);
  return shape;
}

// The candidate points of a plane against another shape, in the order of
// docs/contacts.md; the manifold and the kept points are chosen by the caller.
template <class T>
struct PlaneCandidates {
  int count = 0;
  std::array<Vec3<T>, kMaxContactPoints> on_shape;  // world points on the shape
};

// Candidates of `shape` (world centre `centre`, world rotation `rotation`)
// against the plane with outward unit normal n_p.
template <class T>
PlaneCandidates<T> PlaneContactCandidates(const Vec3<T>& n_p, const ContactShape<T>& shape,
                                          const Vec3<T>& centre, const Quat<T>& rotation) {
  PlaneCandidates<T> out;
  out.on_shape.fill(Vec3<T>::Zero());
  switch (shape.type) {
    case ShapeType::kSphere:
      out.count = 1;
      out.on_shape[0] = centre - shape.radius * n_p;
      break;
    case ShapeType::kCapsule: {
      const Vec3<T> axis = rotation * Vec3<T>::UnitY();
      const Vec3<T> a = centre - shape.half_height * axis;
      const Vec3<T> b = centre + shape.half_height * axis;
      const T axis_dot_n = axis.dot(n_p);
      // κ: how much higher one end is than the other. Below Jolt's capsule
      // projection slop (2 cm) the capsule lies along the plane and both ends
      // touch; the points go down from the ends along ŵ, the part of n_p across
      // the capsule axis (not along n_p: that is where the surface line lies).
      const T kappa = std::abs(T(2) * shape.half_height * axis_dot_n);
      if (kappa < T(0.02) && std::abs(axis_dot_n) < T(1)) {
        const Vec3<T> across = n_p - axis_dot_n * axis;
        const T length = across.norm();
        // A zero `across` needs n_p along the axis, which |â·n_p| < 1 excludes
        // but for rounding; fall back to n_p rather than divide by zero.
        const Vec3<T> w = length > T(0) ? Vec3<T>(across / length) : n_p;
        out.count = 2;
        out.on_shape[0] = a - shape.radius * w;
        out.on_shape[1] = b - shape.radius * w;
      } else {
        // Standing or tilted: the lower end only (equal heights: a).
        const Vec3<T> e = n_p.dot(b) < n_p.dot(a) ? b : a;
        out.count = 1;
        out.on_shape[0] = e - shape.radius * n_p;
      }
      break;
    }
    case ShapeType::kBox: {
      // The face towards the plane: its axis k has the largest |m_k| of the
      // plane normal in box coordinates (first index on ties), and it lies on
      // the side −sign(m_k).
      const Vec3<T> m = rotation.conjugate() * n_p;
      int k = 0;
      for (int i = 1; i < 3; ++i) {
        if (std::abs(m[i]) > std::abs(m[k])) k = i;
      }
      const int u = k == 0 ? 1 : 0;
      const int v = k == 2 ? 1 : 2;
      const T face_side = m[k] > T(0) ? T(-1) : T(1);
      // Polygon order (−,−), (+,−), (+,+), (−,+) in (u, v).
      const T signs_u[4] = {T(-1), T(1), T(1), T(-1)};
      const T signs_v[4] = {T(-1), T(-1), T(1), T(1)};
      out.count = 4;
      for (int j = 0; j < 4; ++j) {
        Vec3<T> local;
        local[k] = face_side * shape.half_extents[k];
        local[u] = signs_u[j] * shape.half_extents[u];
        local[v] = signs_v[j] * shape.half_extents[v];
        out.on_shape[j] = centre + rotation * local;
      }
      break;
    }
    case ShapeType::kNone:
    case ShapeType::kPlane:
      throw std::invalid_argument("reference::PlaneContactCandidates: unsupported shape");
  }
  return out;
}

// ---- spheres and capsules (docs/contacts.md, "Points of a pair of spheres
// and capsules")

// The core of a sphere or capsule in world space: the segment a..b (a = b = c
// for a sphere), its centre c and its radius.
template <class T>
struct RoundCore {
  bool is_capsule = false;
  Vec3<T> centre = Vec3<T>::Zero();
  Vec3<T> a = Vec3<T>::Zero();  // centre − h â
  Vec3<T> b = Vec3<T>::Zero();  // centre + h â
  T radius = T(0);
};

// `shape` (a sphere or capsule) with world centre `centre` and world rotation
// `rotation`; â is the shape's +Y.
template <class T>
RoundCore<T> MakeRoundCore(const ContactShape<T>& shape, const Vec3<T>& centre,
                           const Quat<T>& rotation) {
  RoundCore<T> core;
  core.is_capsule = shape.type == ShapeType::kCapsule;
  core.centre = centre;
  core.radius = shape.radius;
  core.a = centre;
  core.b = centre;
  if (core.is_capsule) {
    const Vec3<T> axis = rotation * Vec3<T>::UnitY();
    core.a = centre - shape.half_height * axis;
    core.b = centre + shape.half_height * axis;
  }
  return core;
}

template <class T>
T Clamp01(T x) {
  return std::min(std::max(x, T(0)), T(1));
}

// The point of segment a..b nearest to `point`:
//   t = clamp((p − a)·(b − a) / |b − a|², 0, 1),  s = a + t (b − a).
// (A segment of zero length, a capsule of half height 0, is its point a.)
template <class T>
Vec3<T> NearestOnSegment(const Vec3<T>& point, const Vec3<T>& a, const Vec3<T>& b) {
  const Vec3<T> d = b - a;
  const T length_squared = d.dot(d);
  if (!(length_squared > T(0))) return a;
  const T t = Clamp01((point - a).dot(d) / length_squared);
  return a + t * d;
}

// The closest points s1 = a1 + t1 d1, s2 = a2 + t2 d2 of segments a1..b1 and
// a2..b2. With d1 = b1 − a1, d2 = b2 − a2, e = a1 − a2 and
//   A = d1·d1, E = d2·d2, B = d1·d2, C = d1·e, F = d2·e, Δ = A E − B²
// (|s2 − s1|² as a function of (t1, t2) has its minimum at
//   A t1 − B t2 = −C,  B t1 − E t2 = −F):
// - not parallel (Δ > 1e-6 A E): t1 = clamp((B F − C E)/Δ), the unconstrained
//   minimum clamped; then t2 = clamp((B t1 + F)/E), the point of segment 2
//   nearest s1; then t1 = clamp((B t2 − C)/A), the point of segment 1 nearest s2.
// - parallel: no unique pair; the middle of the overlap of segment 2 projected
//   on segment 1: u_a = clamp(−C/A), u_b = clamp((B − C)/A) (a2 and b2 as
//   parameters of segment 1), t1 = (u_a + u_b)/2, t2 = clamp((B t1 + F)/E).
// A segment of zero length (not a case of the doc; only a capsule of half
// height 0 makes one) is its point a: t = 0, the other segment's parameter
// the nearest to it.
template <class T>
std::pair<Vec3<T>, Vec3<T>> ClosestPointsOfSegments(const Vec3<T>& a1, const Vec3<T>& b1,
                                                    const Vec3<T>& a2, const Vec3<T>& b2) {
  const Vec3<T> d1 = b1 - a1;
  const Vec3<T> d2 = b2 - a2;
  const Vec3<T> e = a1 - a2;
  const T A = d1.dot(d1), E = d2.dot(d2), B = d1.dot(d2), C = d1.dot(e), F = d2.dot(e);
  T t1 = T(0), t2 = T(0);
  if (!(A > T(0)) || !(E > T(0))) {
    if (A > T(0)) t1 = Clamp01(-C / A);  // a2 against segment 1
    if (E > T(0)) t2 = Clamp01(F / E);   // a1 against segment 2
  } else {
    const T delta = A * E - B * B;
    if (delta > T(1e-6) * A * E) {
      t1 = Clamp01((B * F - C * E) / delta);
      t2 = Clamp01((B * t1 + F) / E);
      t1 = Clamp01((B * t2 - C) / A);
    } else {
      const T u_a = Clamp01(-C / A);
      const T u_b = Clamp01((B - C) / A);
      t1 = (u_a + u_b) / T(2);
      t2 = Clamp01((B * t1 + F) / E);
    }
  }
  return {a1 + t1 * d1, a2 + t2 * d2};
}

// The one candidate point of two round shapes, body 1's core first.
template <class T>
struct RoundCandidate {
  Vec3<T> s1 = Vec3<T>::Zero();      // on body 1's core
  Vec3<T> s2 = Vec3<T>::Zero();      // on body 2's core
  Vec3<T> normal = Vec3<T>::UnitY();  // body 1 to body 2
  T distance = T(0);                  // L = |s2 − s1|
};

template <class T>
RoundCandidate<T> RoundContactCandidate(const RoundCore<T>& core1, const RoundCore<T>& core2) {
  RoundCandidate<T> out;
  if (!core1.is_capsule && !core2.is_capsule) {
    out.s1 = core1.centre;
    out.s2 = core2.centre;
  } else if (!core1.is_capsule) {
    out.s1 = core1.centre;
    out.s2 = NearestOnSegment(core1.centre, core2.a, core2.b);
  } else if (!core2.is_capsule) {
    out.s1 = NearestOnSegment(core2.centre, core1.a, core1.b);
    out.s2 = core2.centre;
  } else {
    std::tie(out.s1, out.s2) = ClosestPointsOfSegments(core1.a, core1.b, core2.a, core2.b);
  }
  const Vec3<T> delta = out.s2 - out.s1;
  out.distance = delta.norm();
  if (out.distance > T(0)) {
    out.normal = delta / out.distance;
    return out;
  }
  // L = 0: the centres or the cores meet and δ gives no direction (Jolt's EPA
  // picks one; any fixed rule will do). Crossing capsules: across both
  // segments, d1 × d2 as it comes (two segments through one point have no
  // side towards the other: their centres are level along d1 × d2); else, or
  // when d1 × d2 = 0, +Y.
  out.normal = Vec3<T>::UnitY();
  if (core1.is_capsule && core2.is_capsule) {
    const Vec3<T> across = (core1.b - core1.a).cross(core2.b - core2.a);
    const T length = across.norm();
    if (length > T(0)) out.normal = across / length;
  }
  return out;
}

}  // namespace manyworlds::reference
