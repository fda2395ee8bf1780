// Contact points of a box with a sphere, capsule or box for the reference
// world (docs/contacts.md, "Points of a box with a sphere, capsule or box"),
// called by reference/contact_constraint.h. Scalar reference, written from
// the docs; nothing of batch/ or kernels/.
//
// Sharp boxes. All in box A's frame (the box; two boxes: body 1's), l = Rᵀ(y − c);
// results in world space with the box as A, n from A to B (the caller negates
// n and swaps the pairs when the box is body 2). sign(x) = +1 for x ≥ 0;
// "first" = lowest index on ties; D = speculative distance (a function of n),
// K = D + 1 mm.
//
// Sphere–box: q = clamp(l, −h, h). Outside: L = |l − q|, m = (l − q)/L. Inside:
//   g_k = h_k − |l_k|, k the first least, m = sign(l_k) e_k, L = −g_k, q = l
//   with q_k = sign(l_k) h_k. Pair (q, l − r m), separation L − r < D.
// Capsule–box (core a..b, radius r, axis â): 1. slab test of a→b against the
//   closed box; 2. not touching: the first least |P − Q| of (a, clamp a),
//   (b, clamp b) and the 12 edges (axis k, (u, v) signs (−,−), (+,−), (+,+),
//   (−,+), −h_k → +h_k) by ClosestPointsOfSegments, m = (P − Q)/L (L = 0:
//   touching); 3. touching: of the faces (0,+), (0,−), ..., (2,−) the first
//   least g = h_k − min(σa_k, σb_k): m = σe_k, L = −g, P the end with the
//   smaller σx_k (a on ties), Q = clamp P with Q_k = σh_k; 4. exists when
//   L − r < D, pair (Q, P − r m); 5. α = â·m, if |2h_c α| < 0.02 and |α| < 1:
//   face k = first largest |m_k|, σ = sign m_k, P(t) = a' + t(b' − a') with
//   a', b' = a, b − r ŵ, ŵ = normalize(m − α â), λ(t) = (P_k − σh_k)/m_k,
//   P' = P − λ m; t ∈ [0, 1] clipped by f0 + f1 t ≤ H for f = ±P'_u, ±P'_v;
//   pairs (P'(t), P(t)) at t_in, t_out with λ < K, else step 4's.
// Box–box (B's centre t, axes C_j in A's frame): 1. axes e_i, C_j, e_i × C_j
//   (skip |u|² < 1e-6), s(u) = (|t·u| − Σa_k|u_k| − Σb_j|C_j·u|)/|u|; the first
//   best face axis unless the first best edge axis is > 1 mm better; n =
//   ±u/|u| with n·t ≥ 0; 2. A's face k = first largest |n_k|, σ = sign n_k,
//   B's k' from (C_j·n), σ' = −sign; corners in polygon order; 3. 24
//   candidates: B's corners onto A's face plane along n, A's onto B's, edge
//   crossings (Cramer, |Δ| > 1e-6|e_A||e_B|, s, τ ∈ [−1e-4, 1 + 1e-4]);
//   insides closed and widened by 1e-4; δ = (on B − on A)·n; 4. s < D and a
//   valid candidate with δ < D: those with δ < K; 5. over four: Jolt's
//   pruning about body 1's centre of mass, in the order P1, P3, P2, P4.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <stdexcept>

#include "reference/contact_points.h"
#include "reference/math.h"

namespace manyworlds::reference {

// A box in world space: centre, rotation (box frame to world), half extents.
template <class T>
struct BoxFrame {
  Vec3<T> centre = Vec3<T>::Zero();
  Quat<T> rotation = Quat<T>::Identity();
  Vec3<T> half = Vec3<T>::Zero();
  Vec3<T> ToLocal(const Vec3<T>& y) const { return rotation.conjugate() * (y - centre); }
  Vec3<T> ToWorld(const Vec3<T>& l) const { return centre + rotation * l; }
};

// A manifold with the box as A: world points on A and on B, the world normal
// from A to B, `count` points (0: no manifold), compacted in order.
template <class T>
struct BoxPairPoints {
  int count = 0;
  Vec3<T> normal = Vec3<T>::Zero();
  std::array<Vec3<T>, kMaxContactPoints> on_a;
  std::array<Vec3<T>, kMaxContactPoints> on_b;
  BoxPairPoints() {
    on_a.fill(Vec3<T>::Zero());
    on_b.fill(Vec3<T>::Zero());
  }
  // Appends the pair (local points of `box`).
  void Add(const BoxFrame<T>& box, const Vec3<T>& a, const Vec3<T>& b) {
    on_a[count] = box.ToWorld(a);
    on_b[count] = box.ToWorld(b);
    ++count;
  }
};

namespace box_contact {

// A face's boundary is widened by 1e-4 of its half extent for the inside
// tests, and an edge's parameter range by 1e-4 at each end, so that points
// exactly on a face's edge line (a capsule lying along a box's edge, equal
// boxes stacked flush) are kept whatever the rounding (docs/contacts.md).
template <class T>
inline constexpr T kEdgeGrace = T(1.0001);
template <class T>
inline constexpr T kEdgeSlack = T(1.0e-4);

template <class T>
T Sign(T x) {
  return x >= T(0) ? T(1) : T(-1);
}

// The first index of the largest |v_k|.
template <class T>
int FirstLargestAbs(const Vec3<T>& v) {
  int k = 0;
  for (int i = 1; i < 3; ++i) {
    if (std::abs(v[i]) > std::abs(v[k])) k = i;
  }
  return k;
}

// The two axes other than k, in increasing index.
inline int OtherU(int k) { return k == 0 ? 1 : 0; }
inline int OtherV(int k) { return k == 2 ? 1 : 2; }

// Polygon order of a face's corners, (s_u, s_v): (−,−), (+,−), (+,+), (−,+).
inline constexpr int kSignU[4] = {-1, 1, 1, -1};
inline constexpr int kSignV[4] = {-1, -1, 1, 1};

// Corner j of the face of axis k on side σ of a box of half extents h.
template <class T>
Vec3<T> FaceCorner(const Vec3<T>& h, int k, T sigma, int j) {
  Vec3<T> x;
  x[k] = sigma * h[k];
  x[OtherU(k)] = T(kSignU[j]) * h[OtherU(k)];
  x[OtherV(k)] = T(kSignV[j]) * h[OtherV(k)];
  return x;
}

template <class T>
Vec3<T> ClampToBox(const Vec3<T>& l, const Vec3<T>& h) {
  return l.cwiseMax(-h).cwiseMin(h);
}

}  // namespace box_contact

// ---- sphere–box (one point). `speculative(n)` is D for the world normal n
// from the box to the sphere.
template <class T, class Speculative>
BoxPairPoints<T> SphereBoxPoints(const BoxFrame<T>& box, const Vec3<T>& sphere_centre, T radius,
                                 Speculative&& speculative) {
  using namespace box_contact;  // NOLINT(google-build-using-namespace)
  const Vec3<T>& h = box.half;
  const Vec3<T> l = box.ToLocal(sphere_centre);
  Vec3<T> q = ClampToBox(l, h);
  Vec3<T> m;
  T distance;
  if ((l - q).squaredNorm() > T(0)) {
    distance = (l - q).norm();
    m = (l - q) / distance;
  } else {
    // Inside: out through the nearest face.
    const Vec3<T> g = h - l.cwiseAbs();
    int k = 0;
    for (int i = 1; i < 3; ++i) {
      if (g[i] < g[k]) k = i;
    }
    m = Vec3<T>::Zero();
    m[k] = Sign(l[k]);
    distance = -g[k];
    q = l;
    q[k] = Sign(l[k]) * h[k];
  }
  BoxPairPoints<T> out;
  const Vec3<T> normal = box.rotation * m;
  if (!(distance - radius < speculative(normal))) return out;
  out.normal = normal;
  out.Add(box, q, Vec3<T>(l - radius * m));
  return out;
}

// ---- capsule–box (up to two points): the capsule's shape, world centre and
// world rotation (its +Y the axis â).
template <class T, class Speculative>
BoxPairPoints<T> CapsuleBoxPoints(const BoxFrame<T>& box, const ContactShape<T>& capsule,
                                  const Vec3<T>& centre, const Quat<T>& rotation,
                                  Speculative&& speculative) {
  using namespace box_contact;  // NOLINT(google-build-using-namespace)
  const Vec3<T>& h = box.half;
  const T r = capsule.radius, h_c = capsule.half_height;
  const Vec3<T> axis = box.rotation.conjugate() * (rotation * Vec3<T>::UnitY());  // â, local
  const Vec3<T> c = box.ToLocal(centre);
  const Vec3<T> a = c - h_c * axis;
  const Vec3<T> b = c + h_c * axis;

  // 1. Does the core touch the closed box? (slab test)
  bool touches = true;
  T t_in = T(0), t_out = T(1);
  for (int k = 0; k < 3; ++k) {
    const T d = b[k] - a[k];
    if (d == T(0)) {
      if (std::abs(a[k]) > h[k]) touches = false;
    } else {
      const T t1 = (-h[k] - a[k]) / d, t2 = (h[k] - a[k]) / d;
      t_in = std::max(t_in, std::min(t1, t2));
      t_out = std::min(t_out, std::max(t1, t2));
    }
  }
  touches = touches && t_in <= t_out;

  Vec3<T> p = Vec3<T>::Zero(), q = Vec3<T>::Zero(), m = Vec3<T>::Zero();
  T distance = T(0);
  if (!touches) {
    // 2. The first of the 14 candidates with the least |P − Q|.
    const auto consider = [&](const Vec3<T>& on_core, const Vec3<T>& on_box, bool first) {
      const T l = (on_core - on_box).norm();
      if (first || l < distance) {
        distance = l;
        p = on_core;
        q = on_box;
      }
    };
    consider(a, ClampToBox(a, h), true);
    consider(b, ClampToBox(b, h), false);
    for (int k = 0; k < 3; ++k) {
      for (int j = 0; j < 4; ++j) {
        const Vec3<T> end = FaceCorner(h, k, T(1), j);  // the edge's +h_k end
        Vec3<T> start = end;
        start[k] = -h[k];
        const auto [on_core, on_edge] = ClosestPointsOfSegments(a, b, start, end);
        consider(on_core, on_edge, false);
      }
    }
    if (distance > T(0)) {
      m = (p - q) / distance;
    } else {
      touches = true;  // rounding: the touching rule
    }
  }
  if (touches) {
    // 3. Out through the face that needs the least push.
    int face_k = 0;
    T face_sigma = T(1), least = T(0);
    for (int face = 0; face < 6; ++face) {
      const int k = face / 2;
      const T sigma = face % 2 == 0 ? T(1) : T(-1);
      const T g = h[k] - std::min(sigma * a[k], sigma * b[k]);
      if (face == 0 || g < least) {
        least = g;
        face_k = k;
        face_sigma = sigma;
      }
    }
    m = Vec3<T>::Zero();
    m[face_k] = face_sigma;
    distance = -least;
    p = face_sigma * b[face_k] < face_sigma * a[face_k] ? b : a;
    q = ClampToBox(p, h);
    q[face_k] = face_sigma * h[face_k];
  }

  // 4. The manifold.
  BoxPairPoints<T> out;
  const Vec3<T> normal = box.rotation * m;
  const T spec = speculative(normal);
  if (!(distance - r < spec)) return out;
  out.normal = normal;

  // 5. Two points when the capsule lies along the box's face (within 2 cm).
  const T alpha = axis.dot(m);
  if (std::abs(T(2) * h_c * alpha) < T(0.02) && std::abs(alpha) < T(1)) {
    const int k = FirstLargestAbs(m), u = OtherU(k), v = OtherV(k);
    const T sigma = Sign(m[k]);
    const Vec3<T> across = m - alpha * axis;
    const T across_length = across.norm();
    // |α| < 1 leaves `across` non-zero but for rounding: then m (as for a plane).
    const Vec3<T> w = across_length > T(0) ? Vec3<T>(across / across_length) : m;
    const Vec3<T> a1 = a - r * w, b1 = b - r * w;
    const auto point = [&](T t) { return Vec3<T>(a1 + t * (b1 - a1)); };
    const auto height = [&](const Vec3<T>& x) { return (x[k] - sigma * h[k]) / m[k]; };
    const auto project = [&](const Vec3<T>& x) { return Vec3<T>(x - height(x) * m); };
    const Vec3<T> at0 = project(point(T(0))), at1 = project(point(T(1)));
    T lo = T(0), hi = T(1);
    bool empty = false;
    for (int c_i = 0; c_i < 4; ++c_i) {  // +u, −u, +v, −v
      const int axis_i = c_i < 2 ? u : v;
      const T s = c_i % 2 == 0 ? T(1) : T(-1);
      const T f0 = s * at0[axis_i], f1 = s * at1[axis_i] - f0, bound = kEdgeGrace<T> * h[axis_i];
      if (f1 > T(0)) {
        hi = std::min(hi, (bound - f0) / f1);
      } else if (f1 < T(0)) {
        lo = std::max(lo, (bound - f0) / f1);
      } else if (f0 > bound) {
        empty = true;
      }
    }
    if (!empty && lo <= hi) {
      const T keep = spec + T(0.001);
      for (const T t : {lo, hi}) {
        const Vec3<T> on_capsule = point(t);
        const T lambda = height(on_capsule);
        if (lambda < keep) out.Add(box, Vec3<T>(on_capsule - lambda * m), on_capsule);
      }
      if (out.count > 0) return out;
    }
  }
  out.Add(box, q, Vec3<T>(p - r * m));
  return out;
}

// ---- box–box (up to four points): box A is body 1's, box B body 2's;
// `body1_com` is body 1's centre of mass (world), the pruning's origin.
template <class T, class Speculative>
BoxPairPoints<T> BoxBoxPoints(const BoxFrame<T>& box_a, const BoxFrame<T>& box_b,
                              const Vec3<T>& body1_com, Speculative&& speculative) {
  using namespace box_contact;  // NOLINT(google-build-using-namespace)
  const Vec3<T>& ha = box_a.half;
  const Vec3<T>& hb = box_b.half;
  const Vec3<T> t = box_a.ToLocal(box_b.centre);
  const Mat33<T> axes_b = (box_a.rotation.conjugate() * box_b.rotation).toRotationMatrix();
  const auto axis_b = [&](int j) { return Vec3<T>(axes_b.col(j)); };  // C_j

  // 1. Separating axes: the first best face axis (0-5), the first best edge
  // axis (6-14), the edge axis only when more than 1 mm better.
  const auto separation = [&](const Vec3<T>& u) {
    T s = std::abs(t.dot(u));
    for (int k = 0; k < 3; ++k) s -= ha[k] * std::abs(u[k]);
    for (int j = 0; j < 3; ++j) s -= hb[j] * std::abs(axis_b(j).dot(u));
    return s / u.norm();
  };
  // Axis i: e_i (0-2), C_j (3-5), e_i × C_j (6 + 3i + j).
  const auto axis = [&](int i) {
    if (i < 3) return Vec3<T>(Vec3<T>::Unit(i));
    if (i < 6) return axis_b(i - 3);
    return Vec3<T>(Vec3<T>(Vec3<T>::Unit((i - 6) / 3)).cross(axis_b((i - 6) % 3)));
  };
  std::array<T, 15> s{};
  int face = 0, edge = -1;
  for (int i = 0; i < 15; ++i) {
    const Vec3<T> u = axis(i);
    if (i >= 6 && u.squaredNorm() < T(1e-6)) continue;  // nearly parallel edges
    s[i] = separation(u);
    if (i < 6 && s[i] > s[face]) face = i;
    if (i >= 6 && (edge < 0 || s[i] > s[edge])) edge = i;
  }
  const int chosen = edge >= 0 && s[edge] > s[face] + T(0.001) ? edge : face;
  const Vec3<T> u = axis(chosen);
  const T chosen_s = s[chosen];
  Vec3<T> n = u / u.norm();
  if (t.dot(u) < T(0)) n = -n;

  BoxPairPoints<T> out;
  const Vec3<T> normal = box_a.rotation * n;
  const T spec = speculative(normal);
  if (!(chosen_s < spec)) return out;

  // 2. Supporting faces: A's towards B, B's towards A (B's corners in A's frame).
  const int k = FirstLargestAbs(n), ua = OtherU(k), va = OtherV(k);
  const T sigma = Sign(n[k]);
  const Vec3<T> n_b(axis_b(0).dot(n), axis_b(1).dot(n), axis_b(2).dot(n));
  const int kb = FirstLargestAbs(n_b), ub = OtherU(kb), vb = OtherV(kb);
  const T sigma_b = -Sign(n_b[kb]);
  std::array<Vec3<T>, 4> p, q;
  for (int j = 0; j < 4; ++j) {
    p[j] = FaceCorner(ha, k, sigma, j);
    q[j] = t + axes_b * FaceCorner(hb, kb, sigma_b, j);
  }
  const Vec3<T> normal_b = sigma_b * axis_b(kb);                  // N_B
  const Vec3<T> centre_b = t + (sigma_b * hb[kb]) * axis_b(kb);  // f_B

  // 3. The 24 candidates, in order.
  struct Candidate {
    bool valid = false;
    Vec3<T> on_a = Vec3<T>::Zero(), on_b = Vec3<T>::Zero();
    T delta = T(0);
  };
  std::array<Candidate, 24> cand{};
  for (int j = 0; j < 4; ++j) {  // B's corners onto A's face
    const T lambda = (q[j][k] - sigma * ha[k]) / n[k];
    const Vec3<T> projected = q[j] - lambda * n;
    cand[j] = {std::abs(projected[ua]) <= kEdgeGrace<T> * ha[ua] &&
                   std::abs(projected[va]) <= kEdgeGrace<T> * ha[va], projected,
               q[j], lambda};
  }
  for (int i = 0; i < 4; ++i) {  // A's corners onto B's face
    const T mu = (centre_b - p[i]).dot(normal_b) / n.dot(normal_b);
    const Vec3<T> projected = p[i] + mu * n;
    const Vec3<T> rel = projected - t;
    cand[4 + i] = {std::abs(rel.dot(axis_b(ub))) <= kEdgeGrace<T> * hb[ub] &&
                       std::abs(rel.dot(axis_b(vb))) <= kEdgeGrace<T> * hb[vb],
                   p[i], projected, mu};
  }
  for (int i = 0; i < 4; ++i) {  // edge crossings
    for (int j = 0; j < 4; ++j) {
      const Vec3<T> e_a = p[(i + 1) % 4] - p[i], e_b = q[(j + 1) % 4] - q[j], w = q[j] - p[i];
      const T det = e_a.cross(e_b).dot(n);
      Candidate& c = cand[8 + 4 * i + j];
      if (!(std::abs(det) > T(1e-6) * e_a.norm() * e_b.norm())) continue;
      const T s = w.cross(e_b).dot(n) / det;
      const T tau = w.cross(e_a).dot(n) / det;
      const T alpha = e_a.cross(e_b).dot(w) / det;
      c = {s >= -kEdgeSlack<T> && s <= T(1) + kEdgeSlack<T> && tau >= -kEdgeSlack<T> &&
               tau <= T(1) + kEdgeSlack<T>, p[i] + s * e_a, q[j] + tau * e_b,
           alpha};
    }
  }

  // 4. The manifold exists when a valid candidate has δ < D; kept: the
  // valid ones with δ < K.
  const T keep = spec + T(0.001);
  std::array<int, 24> kept{};
  int kept_count = 0;
  bool within = false;
  for (int i = 0; i < 24; ++i) {
    if (!cand[i].valid) continue;
    if (cand[i].delta < keep) kept[kept_count++] = i;
    within = within || cand[i].delta < spec;
  }
  if (!within) return out;
  out.normal = normal;
  if (kept_count <= 4) {
    for (int i = 0; i < kept_count; ++i) out.Add(box_a, cand[kept[i]].on_a, cand[kept[i]].on_b);
    return out;
  }

  // 5. Jolt's pruning, about body 1's centre of mass (in A's frame).
  const Vec3<T> com = box_a.ToLocal(body1_com);
  std::array<Vec3<T>, 24> proj;
  std::array<T, 24> weight{};
  for (int i = 0; i < kept_count; ++i) {
    const Candidate& c = cand[kept[i]];
    const Vec3<T> arm = c.on_a - com;
    proj[i] = arm - arm.dot(n) * n;
    weight[i] = std::max(T(1e-6), (c.on_b - c.on_a).squaredNorm());
  }
  // The first kept index but `skip` with the largest score(i).
  const auto first_best = [&](auto score, int skip) {
    int best = -1;
    for (int i = 0; i < kept_count; ++i) {
      if (i != skip && (best < 0 || score(i) > score(best))) best = i;
    }
    return best;
  };
  const int p1 = first_best(
      [&](int i) { return std::max(T(1e-6), proj[i].squaredNorm()) * weight[i]; }, -1);
  const int p2 = first_best(
      [&](int i) { return std::max(T(1e-6), (proj[i] - proj[p1]).squaredNorm()) * weight[i]; },
      p1);
  // Either side of P1→P2: the most negative (P3) and most positive (P4) σ_i.
  const Vec3<T> across = (proj[p2] - proj[p1]).cross(n);
  const auto side = [&](int i) { return across.dot(proj[i] - proj[p1]); };
  int p3 = -1, p4 = -1;
  for (int i = 0; i < kept_count; ++i) {
    if (i == p1 || i == p2) continue;
    if (side(i) < (p3 < 0 ? T(0) : side(p3))) p3 = i;
    if (side(i) > (p4 < 0 ? T(0) : side(p4))) p4 = i;
  }
  for (const int i : {p1, p3, p2, p4}) {
    if (i >= 0) out.Add(box_a, cand[kept[i]].on_a, cand[kept[i]].on_b);
  }
  return out;
}

// ---- dispatch: the box (A) with `other` (B: a sphere, capsule or box) at
// world centre `centre`, rotation `rotation`; two boxes: A is body 1's, and
// `body1_com` body 1's centre of mass (the pruning's origin).
template <class T, class Speculative>
BoxPairPoints<T> BoxContactPoints(const BoxFrame<T>& box, const ContactShape<T>& other,
                                  const Vec3<T>& centre, const Quat<T>& rotation,
                                  const Vec3<T>& body1_com, Speculative&& speculative) {
  switch (other.type) {
    case ShapeType::kSphere: return SphereBoxPoints(box, centre, other.radius, speculative);
    case ShapeType::kCapsule: return CapsuleBoxPoints(box, other, centre, rotation, speculative);
    case ShapeType::kBox:
      return BoxBoxPoints(box, BoxFrame<T>{centre, rotation, other.half_extents}, body1_com,
                          speculative);
    default: throw std::invalid_argument("reference::BoxContactPoints: unsupported shape");
  }
}

}  // namespace manyworlds::reference
