// Contact points of two boxes for every world of a chunk at once
// (docs/contacts.md, "Box–box"). In box A's coordinates (body 1's box), with
// B's centre t and axes C_j:
//   separation along an axis u: s(u) = (|t.u| - sum a_k |u_k| - sum b_j |C_j.u|) / |u|
//   over A's axes, B's axes and the 9 crosses e_i x C_j (nearly parallel
//   edges skipped); the best face axis, or the best edge axis when it beats
//   it by more than 1 mm; n = u/|u| from A to B.
//   The faces of A and B most along +n and -n, clipped in projection along n:
//   24 candidates (B's corners inside A's face, A's corners inside B's face,
//   the 16 crossings of their edges), each a pair (on A, on B) with
//   separation delta along n. The manifold exists where s < D and a valid
//   candidate has delta < D; candidates with delta < D + 1 mm are kept; more
//   than four are pruned as Jolt prunes them (farthest from body 1's centre
//   of mass weighted by |on B - on A|^2, the farthest from it, then the
//   extremes on either side of that line).

#if defined(MANYWORLDS_BATCH_BOX_BOX_CONTACT_POINTS_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef MANYWORLDS_BATCH_BOX_BOX_CONTACT_POINTS_INL_H_
#undef MANYWORLDS_BATCH_BOX_BOX_CONTACT_POINTS_INL_H_
#else
#define MANYWORLDS_BATCH_BOX_BOX_CONTACT_POINTS_INL_H_
#endif

#include <cstddef>

#include "batch/box_contact_points-inl.h"

HWY_BEFORE_NAMESPACE();
namespace manyworlds {
namespace HWY_NAMESPACE {

// A box's face towards the other box, in A's coordinates: the box's centre,
// the face's centre and outward normal, its two other axes (u, v in
// increasing index; unit) and half extents along them, and the corners in
// polygon order (-,-), (+,-), (+,+), (-,+).
struct BoxFace {
  Vec3 box_centre, centre, normal, unit_u, unit_v;
  LaneVec half_u, half_v;
  Vec3 corners[4];
};

// The face of a box (axes[j] its unit axes, half its half extents) along
// `direction` (in the same coordinates as the axes; side +1) or against it
// (side -1), centred on `centre`.
inline BoxFace FaceAlong(const Vec3& centre, const Vec3 axes[3], const Vec3& half,
                         const Vec3& direction, float side) {
  const LaneVec d[3] = {Dot(axes[0], direction), Dot(axes[1], direction),
                        Dot(axes[2], direction)};
  const AxisPick k = FirstLargest(hn::Abs(d[0]), hn::Abs(d[1]), hn::Abs(d[2]));
  const LaneVec d_k = hn::IfThenElse(k.x, d[0], hn::IfThenElse(k.y, d[1], d[2]));
  const LaneVec sign = hn::Mul(Splat(side), SignOf(d_k));
  const Vec3 axis_k = Select(k.x, axes[0], Select(k.y, axes[1], axes[2]));
  BoxFace face;
  face.box_centre = centre;
  face.normal = Scale(axis_k, sign);
  face.centre = MulAdd(face.normal, AlongK(k, half), centre);
  face.unit_u = Select(k.x, axes[1], axes[0]);
  face.unit_v = Select(k.z, axes[1], axes[2]);
  face.half_u = AlongU(k, half);
  face.half_v = AlongV(k, half);
  const Vec3 u = Scale(face.unit_u, face.half_u), v = Scale(face.unit_v, face.half_v);
  static constexpr float kCornerSigns[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
  for (int i = 0; i < 4; ++i) {
    face.corners[i] =
        MulAdd(u, Splat(kCornerSigns[i][0]), MulAdd(v, Splat(kCornerSigns[i][1]), face.centre));
  }
  return face;
}

// Whether the projection along n of p onto a face's plane lies inside the
// face (closed), and that projection and its height above the plane along n.
inline LaneMask ProjectOntoFace(const BoxFace& face, const Vec3& p, const Vec3& n,
                                Vec3& projected, LaneVec& height) {
  height = hn::Div(Dot(Sub(p, face.centre), face.normal), Dot(n, face.normal));
  projected = NegMulAdd(n, height, p);
  const Vec3 r = Sub(projected, face.box_centre);
  const LaneVec grace = Splat(kEdgeGrace);
  return hn::And(hn::Le(hn::Abs(Dot(r, face.unit_u)), hn::Mul(grace, face.half_u)),
                 hn::Le(hn::Abs(Dot(r, face.unit_v)), hn::Mul(grace, face.half_v)));
}

inline constexpr int kBoxBoxCandidates = 24;

struct BoxBoxCandidate {
  Vec3 on_a, on_b;
  LaneVec separation;
  LaneMask valid;
};

// Jolt's pruning of more than four kept points to P1, P3, P2, P4 (holes where
// P3 or P4 does not exist), the distances measured from body 1's centre of
// mass `com` across n.
inline void PruneToFour(const BoxBoxCandidate* candidates, const LaneMask* keep,
                        const Vec3& n, const Vec3& com, BoxLocalPoints& out) {
  Vec3 q[kBoxBoxCandidates];
  LaneVec weight[kBoxBoxCandidates];
  const LaneVec tiny = Splat(1.0e-6f);
  for (int i = 0; i < kBoxBoxCandidates; ++i) {
    const Vec3 a = Sub(candidates[i].on_a, com);
    q[i] = NegMulAdd(n, Dot(a, n), a);
    weight[i] = hn::Max(tiny, LengthSquared(Sub(candidates[i].on_b, candidates[i].on_a)));
  }
  struct Choice {
    LaneVec score, index;
    LaneMask found;
    Vec3 q, on_a, on_b;
  };
  const auto pick = [&](Choice& choice, int i, LaneMask better, LaneVec score) {
    choice.score = hn::IfThenElse(better, score, choice.score);
    choice.index = hn::IfThenElse(better, Splat(float(i)), choice.index);
    choice.found = hn::Or(choice.found, better);
    choice.q = Select(better, q[i], choice.q);
    choice.on_a = Select(better, candidates[i].on_a, choice.on_a);
    choice.on_b = Select(better, candidates[i].on_b, choice.on_b);
  };
  const Choice empty{Splat(-1.0f), Splat(-1.0f), NoLanes(), ZeroVec3(), ZeroVec3(), ZeroVec3()};
  Choice p1 = empty, p2 = empty;
  for (int i = 0; i < kBoxBoxCandidates; ++i) {
    const LaneVec score = hn::Mul(hn::Max(tiny, LengthSquared(q[i])), weight[i]);
    pick(p1, i, hn::And(keep[i], hn::Gt(score, p1.score)), score);
  }
  for (int i = 0; i < kBoxBoxCandidates; ++i) {
    const LaneVec score = hn::Mul(hn::Max(tiny, LengthSquared(Sub(q[i], p1.q))), weight[i]);
    const LaneMask other = hn::And(keep[i], hn::Ne(p1.index, Splat(float(i))));
    pick(p2, i, hn::And(other, hn::Gt(score, p2.score)), score);
  }
  Choice p3 = empty, p4 = empty;
  p3.score = Zero();
  p4.score = Zero();
  const Vec3 across = Cross(Sub(p2.q, p1.q), n);
  for (int i = 0; i < kBoxBoxCandidates; ++i) {
    const LaneMask other = hn::And(keep[i], hn::And(hn::Ne(p1.index, Splat(float(i))),
                                                    hn::Ne(p2.index, Splat(float(i)))));
    const LaneVec side = Dot(across, Sub(q[i], p1.q));
    pick(p3, i, hn::And(other, hn::Lt(side, p3.score)), side);
    pick(p4, i, hn::And(other, hn::Gt(side, p4.score)), side);
  }
  const Choice* order[4] = {&p1, &p3, &p2, &p4};
  for (int j = 0; j < 4; ++j) {
    out.on_a[j] = order[j]->on_a;
    out.on_b[j] = order[j]->on_b;
    out.keep[j] = order[j]->found;
  }
}

inline ContactCandidates BoxBoxCandidates(const ContactBlock& c,
                                          const ContactStepScalars& scalars,
                                          std::size_t offset) {
  const BoxFrame a = WorldBox(*c.bodies.body1, c.plan.shape1, offset);
  const BoxFrame b = WorldBox(*c.bodies.body2, c.plan.shape2, offset);
  const Vec3 t = a.Local(b.centre);
  const Vec3 axes_b[3] = {a.LocalVector(Column(b.rotation, 0)),
                          a.LocalVector(Column(b.rotation, 1)),
                          a.LocalVector(Column(b.rotation, 2))};
  const LaneVec one = Splat(1.0f);
  const Vec3 axes_a[3] = {{one, Zero(), Zero()}, {Zero(), one, Zero()}, {Zero(), Zero(), one}};
  const LaneVec half_b[3] = {b.half.x, b.half.y, b.half.z};

  // Separating axes: the best face axis, then an edge axis beating it by 1 mm.
  const auto separation = [&](const Vec3& u) {
    LaneVec reach = Dot(AbsVec(u), a.half);
    for (int j = 0; j < 3; ++j) reach = hn::MulAdd(half_b[j], hn::Abs(Dot(axes_b[j], u)), reach);
    return hn::Div(hn::Sub(hn::Abs(Dot(t, u)), reach), hn::Sqrt(LengthSquared(u)));
  };
  const LaneVec lowest = Splat(-3.402823466e38f);
  LaneVec face_best = lowest, edge_best = lowest;
  Vec3 face_axis = axes_a[0], edge_axis = axes_a[0];
  for (int i = 0; i < 6; ++i) {
    const Vec3& u = i < 3 ? axes_a[i] : axes_b[i - 3];
    const LaneVec s = separation(u);
    const LaneMask better = hn::Gt(s, face_best);
    face_best = hn::IfThenElse(better, s, face_best);
    face_axis = Select(better, u, face_axis);
  }
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      const Vec3 u = Cross(axes_a[i], axes_b[j]);
      const LaneMask usable = hn::Ge(LengthSquared(u), Splat(1.0e-6f));
      const LaneVec s = hn::IfThenElse(usable, separation(u), lowest);
      const LaneMask better = hn::Gt(s, edge_best);
      edge_best = hn::IfThenElse(better, s, edge_best);
      edge_axis = Select(better, u, edge_axis);
    }
  }
  const LaneMask use_edge = hn::Gt(edge_best, hn::Add(face_best, Splat(0.001f)));
  const Vec3 u = Select(use_edge, edge_axis, face_axis);
  const LaneVec separation_of_boxes = hn::IfThenElse(use_edge, edge_best, face_best);
  const Vec3 unit = Scale(u, hn::Div(one, hn::Sqrt(LengthSquared(u))));
  const Vec3 n = Select(hn::Lt(Dot(t, u), Zero()), Neg(unit), unit);
  const LaneVec speculative = SpeculativeDistance(c, scalars, a.WorldVector(n), offset);
  BoxLocalPoints local;
  local.normal = n;
  for (int j = 0; j < 4; ++j) {
    local.on_a[j] = ZeroVec3();
    local.on_b[j] = ZeroVec3();
    local.keep[j] = NoLanes();
  }
  // Apart in every world of the chunk: no points to find (the same result as
  // finding them, since none would be kept).
  const LaneMask near = hn::Lt(separation_of_boxes, speculative);
  if (!AnyLane(near)) return ToBodyOrder(a, local, 4, false);

  // The faces towards each other, and the 24 candidates between them.
  const BoxFace face_a = FaceAlong(ZeroVec3(), axes_a, a.half, n, 1.0f);
  const BoxFace face_b = FaceAlong(t, axes_b, b.half, n, -1.0f);
  BoxBoxCandidate candidates[kBoxBoxCandidates];
  int next = 0;
  for (const Vec3& q : face_b.corners) {
    BoxBoxCandidate& candidate = candidates[next++];
    candidate.on_b = q;
    candidate.valid = ProjectOntoFace(face_a, q, n, candidate.on_a, candidate.separation);
  }
  for (const Vec3& p : face_a.corners) {
    BoxBoxCandidate& candidate = candidates[next++];
    candidate.on_a = p;
    LaneVec height;
    candidate.valid = ProjectOntoFace(face_b, p, n, candidate.on_b, height);
    candidate.separation = hn::Neg(height);  // p' = p + mu n with mu = -height
  }
  const auto in_unit_interval = [&](LaneVec x) {
    return hn::And(hn::Ge(x, Splat(-kEdgeSlack)), hn::Le(x, Splat(1.0f + kEdgeSlack)));
  };
  for (int i = 0; i < 4; ++i) {
    const Vec3& p = face_a.corners[i];
    const Vec3 edge_a = Sub(face_a.corners[(i + 1) % 4], p);
    for (int j = 0; j < 4; ++j) {
      const Vec3& q = face_b.corners[j];
      const Vec3 edge_b = Sub(face_b.corners[(j + 1) % 4], q);
      const Vec3 w = Sub(q, p);
      const Vec3 normal_of_edges = Cross(edge_a, edge_b);
      const LaneVec determinant = Dot(normal_of_edges, n);
      const LaneMask solvable = hn::Gt(
          hn::Abs(determinant),
          hn::Mul(Splat(1.0e-6f), hn::Sqrt(hn::Mul(LengthSquared(edge_a), LengthSquared(edge_b)))));
      const LaneVec s = DivWhere(solvable, Dot(Cross(w, edge_b), n), determinant);
      const LaneVec tau = DivWhere(solvable, Dot(Cross(w, edge_a), n), determinant);
      BoxBoxCandidate& candidate = candidates[next++];
      candidate.separation = DivWhere(solvable, Dot(normal_of_edges, w), determinant);
      candidate.on_a = MulAdd(edge_a, s, p);
      candidate.on_b = MulAdd(edge_b, tau, q);
      candidate.valid = hn::And(solvable, hn::And(in_unit_interval(s), in_unit_interval(tau)));
    }
  }

  // The manifold exists where a valid candidate is within D (a point of
  // the two faces that close: the separating axis alone may be within D
  // where the boxes are farther apart); it keeps those within D + 1 mm.
  const LaneVec keep_below = hn::Add(speculative, Splat(kContactManifoldTolerance));
  LaneMask exists = NoLanes();
  LaneMask keep[kBoxBoxCandidates];
  for (int i = 0; i < kBoxBoxCandidates; ++i) {
    const BoxBoxCandidate& candidate = candidates[i];
    exists = hn::Or(exists, hn::And(candidate.valid, hn::Lt(candidate.separation, speculative)));
    keep[i] = hn::And(candidate.valid, hn::Lt(candidate.separation, keep_below));
  }
  exists = hn::And(exists, near);
  LaneVec count = Zero();
  for (int i = 0; i < kBoxBoxCandidates; ++i) {
    keep[i] = hn::And(exists, keep[i]);
    count = hn::Add(count, hn::IfThenElseZero(keep[i], one));
  }

  // Up to four: in candidate order; more: pruned.
  LaneVec rank = Zero();
  for (int i = 0; i < kBoxBoxCandidates; ++i) {
    for (int j = 0; j < 4; ++j) {
      const LaneMask take = hn::And(keep[i], hn::Eq(rank, Splat(float(j))));
      local.on_a[j] = Select(take, candidates[i].on_a, local.on_a[j]);
      local.on_b[j] = Select(take, candidates[i].on_b, local.on_b[j]);
      local.keep[j] = hn::Or(local.keep[j], take);
    }
    rank = hn::Add(rank, hn::IfThenElseZero(keep[i], one));
  }
  const LaneMask prune = hn::Gt(count, Splat(4.0f));
  if (AnyLane(prune)) {
    BoxLocalPoints pruned;
    PruneToFour(candidates, keep, n, a.Local(LoadVec3(c.bodies.body1->position, offset)), pruned);
    for (int j = 0; j < 4; ++j) {
      local.on_a[j] = Select(prune, pruned.on_a[j], local.on_a[j]);
      local.on_b[j] = Select(prune, pruned.on_b[j], local.on_b[j]);
      local.keep[j] = hn::Or(hn::And(prune, pruned.keep[j]), hn::AndNot(prune, local.keep[j]));
    }
  }
  return ToBodyOrder(a, local, 4, false);
}

}  // namespace HWY_NAMESPACE
}  // namespace manyworlds
HWY_AFTER_NAMESPACE();

#endif  // MANYWORLDS_BATCH_BOX_BOX_CONTACT_POINTS_INL_H_
