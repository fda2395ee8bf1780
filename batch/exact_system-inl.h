// The exact solve's system across worlds (batch/exact_solve-inl.h has the
// phases that use it): per-thread working storage, J of every row group at
// the current poses (batch/exact_rows-inl.h), the inverse inertias with the
// geometric stiffness, K, and its block LDL^T and solve.
//
// Unknowns: one impulse lambda_k (3 rows, padded) per group k. A group's
// rows on body b are J_kb = [L_kb, A_kb] (linear, angular), so
//
//   K_kl = sum over shared dynamic bodies b of  m^-1 L_kb L_lb^T + A_kb I_b^-1 A_lb^T
//
// (padded rows: zero J, K's diagonal 1). For a point group (ball joint) with
// lever arm r (world, COM to anchor) and side s = -1 (body 1) or +1 (body 2),
// J_kb = s [E, -[r]x]; with A = I_b^-1 [r]x (world inertia)
//
//   K_kk = sum over its dynamic bodies of  m^-1 E + [r]x I^-1 [r]x^T
//   K_kl = sum over shared dynamic bodies of  s_k s_l (m^-1 E - [r_k]x A_l),
//          column c of -[r_k]x A_l being (column c of A_l) x r_k,
//
// which the chains' point-only scenes assemble without forming J. For a body
// whose allowed DOFs lock axes, m^-1 E is diag(m^-1 along the free
// translation axes, 0 along the locked ones) and I^-1 has the locked
// rotation axes' rows and columns zeroed (LinearInverseMass,
// BodyInverseInertia): its steps drop those components.
//
// Block LDL^T, right-looking, in the plan's order p = 0, 1, ...:
//   D_p = K_pp (updated),  W_pi = D_p^-1 K_pi  for each later neighbour i,
//   K_ij -= K_pi^T W_pj    for each pair i <= j of p's later neighbours.
// Solve K lambda = b:  forward  b_i -= W_pi^T b_p  (p in order),
//                      back     lambda_p = D_p^-1 b_p - sum_i W_pi lambda_i
//                               (p in reverse order).
// K is symmetric positive definite when every group has a dynamic body and
// no two groups' rows are dependent; a singular pivot (D_p not invertible in
// a lane) gives that group zero impulse in that lane, as Jolt deactivates a
// part whose K cannot be inverted.
//

#if defined(MANYWORLDS_BATCH_EXACT_SYSTEM_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef MANYWORLDS_BATCH_EXACT_SYSTEM_INL_H_
#undef MANYWORLDS_BATCH_EXACT_SYSTEM_INL_H_
#else
#define MANYWORLDS_BATCH_EXACT_SYSTEM_INL_H_
#endif

#include <cstddef>
#include <vector>

#include "batch/constraint_block.h"
#include "batch/exact_plan.h"
#include "batch/exact_rows-inl.h"
#include "kernels/lane_math-inl.h"
#include "kernels/point-inl.h"

HWY_BEFORE_NAMESPACE();
namespace manyworlds {
namespace HWY_NAMESPACE {

// Working storage of one block's solve, kept per thread between blocks.
struct ExactScratch {
  // Per position, for groups other than point groups: J (GroupRows) and
  // I^-1 A^T per side (columns: the rows' angular steps).
  struct GroupJacobian {
    Mat33Lanes linear[2], angular[2], inv_i_angular[2];
  };
  std::vector<GroupJacobian> jacobians;
  std::vector<Sym33Lanes> diagonal;  // K_pp, then D_p^-1
  std::vector<Mat33Lanes> blocks;    // K_pi, then W_pi (plan's block order)
  std::vector<Mat33Lanes> w;         // W of the position being eliminated
  std::vector<Vec3Lanes> rhs;        // b, then lambda
  std::vector<Vec3Lanes> translation, rotation;  // per body: one Newton step
  std::vector<Sym33Lanes> inverse_inertia;        // per dynamic body, this solve's
  std::vector<Sym33Lanes> stiffness;              // per dynamic body: G (also CurvatureWeights')
  LaneArray moving;                  // position phase: 1 where still correcting
  // Position phase: the trust region's factor (CurvatureVelocity: times
  // w / dt).
  LaneArray step_scale;
  // The curvature correction (CurvatureVelocity): per world its weight,
  // and per group C at the step's start.
  LaneArray velocity_weight;
  std::vector<Vec3Lanes> start_error;

  void Fit(const StepPlan& step_plan) {
    const ExactSolvePlan& plan = step_plan.exact;
    translation.resize(step_plan.bodies.size());
    rotation.resize(step_plan.bodies.size());
    inverse_inertia.resize(step_plan.bodies.size());
    stiffness.resize(step_plan.bodies.size());
    diagonal.resize(plan.group_count());
    blocks.resize(plan.blocks.size());
    rhs.resize(plan.group_count());
    start_error.resize(plan.group_count());
    jacobians.resize(plan.only_points() ? 0 : plan.group_count());
    std::size_t widest = 0;
    for (const auto& later : plan.later) widest = later.size() > widest ? later.size() : widest;
    w.resize(widest);
  }
};

namespace exact {

HWY_INLINE ConstraintBlock GroupAt(const StepPlan& plan, std::byte* block, std::size_t position) {
  return ConstraintInBlock(plan, plan.exact.order[position].constraint, block);
}

HWY_INLINE bool IsPoint(const ExactSolvePlan& exact, std::size_t position) {
  return exact.order[position].rows == ExactRows::kPoint;
}

// a^T b.
HWY_INLINE Mat33 TransposeTimes(const Mat33& a, const Mat33& b) {
  Mat33 product;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      LaneVec sum = hn::Mul(a.m[0][i], b.m[0][j]);
      sum = hn::MulAdd(a.m[1][i], b.m[1][j], sum);
      product.m[i][j] = hn::MulAdd(a.m[2][i], b.m[2][j], sum);
    }
  }
  return product;
}

HWY_INLINE Vec3 TransposeTimes(const Mat33& a, const Vec3& v) {
  return {hn::MulAdd(a.m[2][0], v.z, hn::MulAdd(a.m[1][0], v.y, hn::Mul(a.m[0][0], v.x))),
          hn::MulAdd(a.m[2][1], v.z, hn::MulAdd(a.m[1][1], v.y, hn::Mul(a.m[0][1], v.x))),
          hn::MulAdd(a.m[2][2], v.z, hn::MulAdd(a.m[1][2], v.y, hn::Mul(a.m[0][2], v.x)))};
}

HWY_INLINE Mat33 Difference(const Mat33& a, const Mat33& b) {
  Mat33 d;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) d.m[i][j] = hn::Sub(a.m[i][j], b.m[i][j]);
  }
  return d;
}

// The upper triangle of a - b^T c (b^T c is symmetric here in exact arithmetic;
// only the upper triangle is formed, so the stored K stays symmetric).
HWY_INLINE Sym33 SubTransposeTimes(const Sym33& a, const Mat33& b, const Mat33& c) {
  const auto entry = [&](int i, int j) {
    LaneVec sum = hn::Mul(b.m[0][i], c.m[0][j]);
    sum = hn::MulAdd(b.m[1][i], c.m[1][j], sum);
    return hn::MulAdd(b.m[2][i], c.m[2][j], sum);
  };
  return {hn::Sub(a.xx, entry(0, 0)), hn::Sub(a.xy, entry(0, 1)), hn::Sub(a.xz, entry(0, 2)),
          hn::Sub(a.yy, entry(1, 1)), hn::Sub(a.yz, entry(1, 2)), hn::Sub(a.zz, entry(2, 2))};
}

// The lever arm and I^-1 [r]x of joint k on one of its sides, as the point
// part caches them (zero I^-1 [r]x for a body that is not dynamic).
HWY_INLINE void Side(const PointLanes& part, bool body2, std::size_t offset, Vec3& r, Mat33& a) {
  r = LoadVec3(body2 ? part.r2 : part.r1, offset);
  Assign(a, LoadMat33(body2 ? part.inv_i2_r2_cross : part.inv_i1_r1_cross, offset));
}

HWY_INLINE Sym33 UpperTriangle(const Mat33& m) {
  return {m.m[0][0], m.m[0][1], m.m[0][2], m.m[1][1], m.m[1][2], m.m[2][2]};
}

HWY_INLINE Mat33 Full(const Sym33& s) {
  Mat33 m;
  m.m[0][0] = s.xx, m.m[0][1] = s.xy, m.m[0][2] = s.xz;
  m.m[1][0] = s.xy, m.m[1][1] = s.yy, m.m[1][2] = s.yz;
  m.m[2][0] = s.xz, m.m[2][1] = s.yz, m.m[2][2] = s.zz;
  return m;
}

// Adds w (E - r r^T / |r|^2) to g: the geometric stiffness of a pull w along
// r (zero where |r| = 0, where w is zero too).
HWY_INLINE void AddTransverseStiffness(LaneVec w, const Vec3& r, Sym33& g) {
  LaneMask nonzero;
  const LaneVec scale = hn::Mul(w, ReciprocalOrZero(LengthSquared(r), nonzero));
  g.xx = hn::Add(g.xx, hn::NegMulAdd(hn::Mul(r.x, r.x), scale, w));
  g.yy = hn::Add(g.yy, hn::NegMulAdd(hn::Mul(r.y, r.y), scale, w));
  g.zz = hn::Add(g.zz, hn::NegMulAdd(hn::Mul(r.z, r.z), scale, w));
  g.xy = hn::NegMulAdd(hn::Mul(r.x, r.y), scale, g.xy);
  g.xz = hn::NegMulAdd(hn::Mul(r.x, r.z), scale, g.xz);
  g.yz = hn::NegMulAdd(hn::Mul(r.y, r.z), scale, g.yz);
}

// The lever arms r1, r2 of every point group at the current rotations,
// cached in its point part.
inline void LeverArms(const StepPlan& plan, std::byte* block) {
  const ExactSolvePlan& exact = plan.exact;
  for (std::size_t p = 0; p < exact.group_count(); ++p) {
    if (!IsPoint(exact, p)) continue;
    const ConstraintBlock c = GroupAt(plan, block, p);
    const PointGeometry& anchors = PointAnchors(c);
    PointLanes& part = PointPart(c);
    ForEachChunk([&](std::size_t offset) {
      StoreVec3(Rotate(LoadQuat(c.bodies.body1->rotation, offset),
                       LoadVec3(anchors.r1_local, offset)),
                part.r1, offset);
      StoreVec3(Rotate(LoadQuat(c.bodies.body2->rotation, offset),
                       LoadVec3(anchors.r2_local, offset)),
                part.r2, offset);
    });
  }
}

HWY_INLINE void StoreRows(const GroupRows& rows, ExactScratch::GroupJacobian& jacobian,
                          std::size_t offset) {
  for (int side = 0; side < 2; ++side) {
    StoreMat33(rows.linear[side], jacobian.linear[side], offset);
    StoreMat33(rows.angular[side], jacobian.angular[side], offset);
  }
}

// The rows of every group other than the point groups at the current poses
// (velocity phase: no C needed).
inline void GroupJacobians(const StepPlan& plan, std::byte* block, ExactScratch& scratch) {
  const ExactSolvePlan& exact = plan.exact;
  for (std::size_t p = 0; p < exact.group_count(); ++p) {
    if (IsPoint(exact, p)) continue;
    const ConstraintBlock c = GroupAt(plan, block, p);
    ForEachChunk([&](std::size_t offset) {
      StoreRows(RowsOfChunk(plan, c, exact.order[p].rows, false, offset), scratch.jacobians[p],
                offset);
    });
  }
}

// Calls f(body index, body, r, pull, offset) for each dynamic body of each
// point group, chunk by chunk: r its lever arm (cached in the point part),
// pull = s lambda . r with lambda the group's last velocity impulse and
// s = -1 on body 1 (positive when the joint pulls the body's anchor
// outward, along r).
template <class F>
void ForEachPull(const StepPlan& plan, std::byte* block, F&& f) {
  const ExactSolvePlan& exact = plan.exact;
  for (std::size_t p = 0; p < exact.group_count(); ++p) {
    if (!IsPoint(exact, p)) continue;
    const ConstraintBlock c = GroupAt(plan, block, p);
    const PointLanes& part = PointPart(c);
    ForEachChunk([&](std::size_t offset) {
      const Vec3 lambda = LoadVec3(part.persistent.total_lambda, offset);
      if (c.bodies.motion1 == MotionType::kDynamic) {
        const Vec3 r = LoadVec3(part.r1, offset);
        f(c.plan.body1, *c.bodies.body1, r, hn::Neg(Dot(lambda, r)), offset);
      }
      if (c.bodies.motion2 == MotionType::kDynamic) {
        const Vec3 r = LoadVec3(part.r2, offset);
        f(c.plan.body2, *c.bodies.body2, r, Dot(lambda, r), offset);
      }
    });
  }
}

// The largest step's trust-region factor per world (kExactMaxNewtonTurn):
// max_turn / (the largest |rotation step| over dynamic bodies, from
// scratch.rotation) where that is larger than max_turn, else 1. A world
// whose step is NaN keeps 1 (the comparison is false).
HWY_INLINE LaneVec TrustRegionScale(const StepPlan& plan, const ExactScratch& scratch,
                                    std::size_t offset) {
  const LaneVec max_turn = Splat(kExactMaxNewtonTurn);
  LaneVec largest_squared = Zero();
  for (std::size_t b = 0; b < plan.bodies.size(); ++b) {
    if (plan.bodies[b].motion != MotionType::kDynamic) continue;
    largest_squared =
        hn::Max(largest_squared, LengthSquared(LoadVec3(scratch.rotation[b], offset)));
  }
  const LaneMask too_far = hn::Gt(largest_squared, hn::Mul(max_turn, max_turn));
  return hn::IfThenElse(too_far, hn::Div(max_turn, hn::Sqrt(largest_squared)), Splat(1.0f));
}

// Into scratch.stiffness, per dynamic body: G = factor * sum over its point
// groups of max(0, s lambda . r) (E - r^ r^T), lambda the group's last
// velocity impulse and r its lever arm (ForEachPull; LeverArms first).
inline void SumGeometricStiffness(const StepPlan& plan, std::byte* block, ExactScratch& scratch,
                                  float factor) {
  for (std::size_t b = 0; b < plan.bodies.size(); ++b) {
    if (plan.bodies[b].motion != MotionType::kDynamic) continue;
    ForEachChunk(
        [&](std::size_t offset) { StoreSym33(ZeroSym33(), scratch.stiffness[b], offset); });
  }
  const LaneVec factor_lanes = Splat(factor);
  ForEachPull(plan, block, [&](std::size_t b, const BodyLanes&, const Vec3& r, LaneVec pull,
                               std::size_t offset) {
    Sym33 g = LoadSym33(scratch.stiffness[b], offset);
    AddTransverseStiffness(hn::Mul(factor_lanes, hn::Max(pull, Zero())), r, g);
    StoreSym33(g, scratch.stiffness[b], offset);
  });
}

// Each dynamic body's inverse inertia for this solve (LeverArms first): I^-1 at its current
// rotation, or with `stiffness` > 0 (velocity phase) (I + G)^-1, where G
// (SumGeometricStiffness) sums over the body's point groups
// stiffness * max(0, s lambda . r) (E - r^ r^T)
// with lambda the group's impulse of the last velocity solve and s = -1 on
// body 1: the geometric stiffness of the joints' pulls (Tournier et al.,
// "Stable Constrained Dynamics", 2015), taken implicitly. A slender link
// pulled hard along its length by a heavy body swings transversally faster
// than one step can follow explicitly (chain16-r100 comes apart without it
// at 1 substep); stiffness = dt is the backward-Euler amount of it; only
// pulls count, pushes would make I + G indefinite. Computed as
// I^-1 (E + G I^-1)^-1, which needs no inverse of I (a zero inverse inertia
// stays zero). The other groups' rows (a slider's, a hinge's rotation rows)
// add no stiffness.
inline void Inertia(const StepPlan& plan, std::byte* block, ExactScratch& scratch,
                    float stiffness) {
  for (std::size_t b = 0; b < plan.bodies.size(); ++b) {
    if (plan.bodies[b].motion != MotionType::kDynamic) continue;
    const BodyLanes& body = BodyAt(plan, block, b);
    ForEachChunk([&](std::size_t offset) {
      StoreSym33(BodyInverseInertia(body, offset), scratch.inverse_inertia[b], offset);
    });
  }
  if (stiffness <= 0.0f) return;
  SumGeometricStiffness(plan, block, scratch, stiffness);
  for (std::size_t b = 0; b < plan.bodies.size(); ++b) {
    if (plan.bodies[b].motion != MotionType::kDynamic) continue;
    ForEachChunk([&](std::size_t offset) {
      const Sym33 inverse = LoadSym33(scratch.inverse_inertia[b], offset);
      Mat33 m = Multiply(LoadSym33(scratch.stiffness[b], offset), Full(inverse));
      for (int i = 0; i < 3; ++i) m.m[i][i] = hn::Add(m.m[i][i], Splat(1.0f));
      LaneMask invertible;
      StoreSym33(UpperTriangle(Multiply(inverse, Inverse33(m, invertible))),
                 scratch.inverse_inertia[b], offset);
    });
  }
}

// The body's linear inverse mass per world axis: m^-1, and 0 along the axes
// its allowed DOFs lock (the velocity and position steps drop those
// components, LockTranslation, so K must not count them). The same bits as
// m^-1 for an unrestricted body.
HWY_INLINE Vec3 LinearInverseMass(const BodyLanes& body, std::size_t offset) {
  const LaneVec inv_mass = Load(body.inv_mass, offset);
  return LockTranslation(body, Vec3{inv_mass, inv_mass, inv_mass}, offset);
}

// A group's rows on one side as the exact scratch keeps them (GroupJacobians,
// and I^-1 A^T from AssembleK's diagonal pass), read entry by entry where
// used, as PointRows reads a point group's.
struct StoredRows {
  LaneVec Linear(int i, int c) const { return Load(jacobian.linear[side].m[i][c], offset); }
  LaneVec Angular(int i, int c) const { return Load(jacobian.angular[side].m[i][c], offset); }
  LaneVec InvIAngular(int c, int j) const {
    return Load(jacobian.inv_i_angular[side].m[c][j], offset);
  }
  bool HasLinear() const { return linear; }
  int Rows() const { return rows; }

  const ExactScratch::GroupJacobian& jacobian;
  int side;
  std::size_t offset;
  bool linear;  // HasLinearRows: false where the linear rows are all zero
  int rows;     // ExactRowCount: the rows below are padding, all zero
};

template <class Rows>
HWY_INLINE Vec3 LinearRow(const Rows& rows, int i) {
  return {rows.Linear(i, 0), rows.Linear(i, 1), rows.Linear(i, 2)};
}
template <class Rows>
HWY_INLINE Vec3 AngularRow(const Rows& rows, int i) {
  return {rows.Angular(i, 0), rows.Angular(i, 1), rows.Angular(i, 2)};
}
template <class Rows>
HWY_INLINE Vec3 InvIAngularColumn(const Rows& rows, int j) {
  return {rows.InvIAngular(0, j), rows.InvIAngular(1, j), rows.InvIAngular(2, j)};
}

// m^-1 L_a L_b^T + A_a (I^-1 A_b^T): how the rows a and b (StoredRows or
// PointRows) couple through one body (m^-1 per axis for a body with locked
// translation axes). Row by row of a, each entry of b read where it is used,
// each entry of the product handed to add(i, j, entry) as it is formed, so
// no 3x3 is held whole. Where a or b has no linear rows (HasLinearRows) the
// first term is a zero and is not formed; entries of padding rows (Rows) are
// not formed at all. Either way the bits are the same: x + 0 = x for x != 0,
// and every entry is summed into K from +0, where a zero of either sign
// leaves +0.
template <class RowsA, class RowsB, class Add>
HWY_INLINE void AddCoupling(const BodyLanes& body, std::size_t offset, const RowsA& a,
                            const RowsB& b, Add&& add) {
  const int rows_a = a.Rows(), rows_b = b.Rows();
  if (!a.HasLinear() || !b.HasLinear()) {  // the plan's choice: the same in every chunk
    for (int i = 0; i < 3; ++i) {
      if (i >= rows_a) break;
      const Vec3 angular_a = AngularRow(a, i);
      for (int j = 0; j < 3; ++j) {
        if (j >= rows_b) break;
        add(i, j, Dot(angular_a, InvIAngularColumn(b, j)));
      }
    }
    return;
  }
  if (!DofRestricted(body)) {  // the scene's choice: the same branch in every chunk
    const LaneVec inv_mass = Load(body.inv_mass, offset);
    for (int i = 0; i < 3; ++i) {
      if (i >= rows_a) break;
      const Vec3 linear_a = LinearRow(a, i), angular_a = AngularRow(a, i);
      for (int j = 0; j < 3; ++j) {
        if (j >= rows_b) break;
        add(i, j, hn::MulAdd(inv_mass, Dot(linear_a, LinearRow(b, j)),
                             Dot(angular_a, InvIAngularColumn(b, j))));
      }
    }
    return;
  }
  const Vec3 free = LinearInverseMass(body, offset);
  for (int i = 0; i < 3; ++i) {
    if (i >= rows_a) break;
    const Vec3 linear_a = LinearRow(a, i), angular_a = AngularRow(a, i);
    const Vec3 weighted{hn::Mul(linear_a.x, free.x), hn::Mul(linear_a.y, free.y),
                        hn::Mul(linear_a.z, free.z)};
    for (int j = 0; j < 3; ++j) {
      if (j >= rows_b) break;
      add(i, j, hn::Add(Dot(weighted, LinearRow(b, j)), Dot(angular_a, InvIAngularColumn(b, j))));
    }
  }
}

// Calls f(rows) with rows(offset) giving the rows of the group at `position`
// on one side: PointRows for a point group (LeverArms first), StoredRows for
// the others (AssembleK's diagonal pass first).
template <class F>
HWY_INLINE void WithGroupRows(const StepPlan& plan, std::byte* block, const ExactScratch& scratch,
                              std::size_t position, bool body2, F&& f) {
  if (IsPoint(plan.exact, position)) {
    const PointLanes& part = PointPart(GroupAt(plan, block, position));
    f([&part, body2](std::size_t offset) { return PointRows(part, body2, offset); });
    return;
  }
  const ExactScratch::GroupJacobian& jacobian = scratch.jacobians[position];
  const int side = body2 ? 1 : 0;
  const ExactRows kind = plan.exact.order[position].rows;
  const bool linear = HasLinearRows(kind, side);
  const int rows = ExactRowCount(kind);
  f([&jacobian, side, linear, rows](std::size_t offset) {
    return StoredRows{jacobian, side, offset, linear, rows};
  });
}

// K from the lever arms, the other groups' rows (GroupJacobians) and the
// inverse inertias of Inertia: every point group's I^-1 [r]x (cached in its
// point part) and every other group's I^-1 A^T, the diagonal blocks and the
// couplings through shared bodies.
inline void AssembleK(const StepPlan& plan, std::byte* block, ExactScratch& scratch) {
  const ExactSolvePlan& exact = plan.exact;
  for (std::size_t p = 0; p < exact.group_count(); ++p) {
    const ConstraintBlock c = GroupAt(plan, block, p);
    if (!IsPoint(exact, p)) {
      const int rows = ExactRowCount(exact.order[p].rows);
      const bool linear[2] = {HasLinearRows(exact.order[p].rows, 0),
                              HasLinearRows(exact.order[p].rows, 1)};
      ExactScratch::GroupJacobian& jacobian = scratch.jacobians[p];
      ForEachChunk([&](std::size_t offset) {
        Mat33 k = ZeroMat33();
        for (int side = 0; side < 2; ++side) {
          const std::size_t body = side == 1 ? c.plan.body2 : c.plan.body1;
          Mat33Lanes& inv_i_angular = jacobian.inv_i_angular[side];
          if ((side == 1 ? c.bodies.motion2 : c.bodies.motion1) != MotionType::kDynamic) {
            StoreMat33(ZeroMat33(), inv_i_angular, offset);
            continue;
          }
          const StoredRows group_rows{jacobian, side, offset, linear[side], rows};
          const Sym33 inverse_inertia = LoadSym33(scratch.inverse_inertia[body], offset);
          for (int r = 0; r < 3; ++r) {
            const Vec3 step = Multiply(inverse_inertia, AngularRow(group_rows, r));
            Store(step.x, inv_i_angular.m[0][r], offset);
            Store(step.y, inv_i_angular.m[1][r], offset);
            Store(step.z, inv_i_angular.m[2][r], offset);
          }
          AddCoupling(BodyAt(plan, block, body), offset, group_rows, group_rows,
                      [&](int i, int j, LaneVec term) { k.m[i][j] = hn::Add(k.m[i][j], term); });
        }
        for (int r = rows; r < 3; ++r) k.m[r][r] = Splat(1.0f);  // padding
        StoreSym33(UpperTriangle(k), scratch.diagonal[p], offset);
      });
      continue;
    }
    PointLanes& part = PointPart(c);
    ForEachChunk([&](std::size_t offset) {
      Sym33 k = ZeroSym33();
      const auto side = [&](std::size_t body, MotionType motion, const Vec3Lanes& lever,
                            Mat33Lanes& cache) {
        Mat33 a = ZeroMat33();
        if (motion == MotionType::kDynamic) {
          const BodyLanes& lanes = BodyAt(plan, block, body);
          const Vec3 r = LoadVec3(lever, offset);
          a = point::InverseInertiaTimesCross(LoadSym33(scratch.inverse_inertia[body], offset), r);
          if (!DofRestricted(lanes)) {
            point::AddBodyToInverseEffectiveMass(Load(lanes.inv_mass, offset), a, r, k);
          } else {  // m^-1 only along the free axes
            point::AddBodyToInverseEffectiveMass(Zero(), a, r, k);
            const Vec3 free = LinearInverseMass(lanes, offset);
            k.xx = hn::Add(k.xx, free.x);
            k.yy = hn::Add(k.yy, free.y);
            k.zz = hn::Add(k.zz, free.z);
          }
        }
        StoreMat33(a, cache, offset);
      };
      side(c.plan.body1, c.bodies.motion1, part.r1, part.inv_i1_r1_cross);
      side(c.plan.body2, c.bodies.motion2, part.r2, part.inv_i2_r2_cross);
      StoreSym33(k, scratch.diagonal[p], offset);
    });
  }
  for (Mat33Lanes& b : scratch.blocks) {
    ForEachChunk([&](std::size_t offset) { StoreMat33(ZeroMat33(), b, offset); });
  }
  for (const ExactSolvePlan::SharedBody& shared : exact.shared_bodies) {
    const BodyLanes& body = BodyAt(plan, block, shared.body);
    Mat33Lanes& out = scratch.blocks[shared.block];
    if (!IsPoint(exact, shared.first) || !IsPoint(exact, shared.second)) {
      const auto add_coupling = [&](auto first, auto second) {
        ForEachChunk([&](std::size_t offset) {
          AddCoupling(body, offset, first(offset), second(offset),
                      [&](int i, int j, LaneVec term) {
                        Store(hn::Add(Load(out.m[i][j], offset), term), out.m[i][j], offset);
                      });
        });
      };
      WithGroupRows(plan, block, scratch, shared.first, shared.first_is_body2, [&](auto first) {
        WithGroupRows(plan, block, scratch, shared.second, shared.second_is_body2,
                      [&](auto second) { add_coupling(first, second); });
      });
      continue;
    }
    const PointLanes& first = PointPart(GroupAt(plan, block, shared.first));
    const PointLanes& second = PointPart(GroupAt(plan, block, shared.second));
    const bool same_sign = shared.first_is_body2 == shared.second_is_body2;
    ForEachChunk([&](std::size_t offset) {
      Vec3 r_first, r_second;
      Mat33 a_first, a_second;
      Side(first, shared.first_is_body2, offset, r_first, a_first);
      Side(second, shared.second_is_body2, offset, r_second, a_second);
      const Vec3 inv_mass = LinearInverseMass(body, offset);
      Mat33 coupling = LoadMat33(out, offset);
      for (int column = 0; column < 3; ++column) {
        Vec3 term = Cross(Column(a_second, column), r_first);
        if (column == 0) term.x = hn::Add(term.x, inv_mass.x);
        if (column == 1) term.y = hn::Add(term.y, inv_mass.y);
        if (column == 2) term.z = hn::Add(term.z, inv_mass.z);
        if (!same_sign) term = Neg(term);
        coupling.m[0][column] = hn::Add(coupling.m[0][column], term.x);
        coupling.m[1][column] = hn::Add(coupling.m[1][column], term.y);
        coupling.m[2][column] = hn::Add(coupling.m[2][column], term.z);
      }
      StoreMat33(coupling, out, offset);
    });
  }
}

// LDL^T in place: diagonal -> D^-1, blocks -> W. visit() once per group.
template <class Visit>
void Factor(const ExactSolvePlan& exact, ExactScratch& scratch, Visit&& visit) {
  for (std::size_t p = 0; p < exact.group_count(); ++p) {
    visit();
    const auto& later = exact.later[p];
    ForEachChunk([&](std::size_t offset) {
      LaneMask invertible;
      const Sym33 d_inv = InverseSym33(LoadSym33(scratch.diagonal[p], offset), invertible);
      StoreSym33(d_inv, scratch.diagonal[p], offset);
      for (std::size_t n = 0; n < later.size(); ++n) {
        StoreMat33(Multiply(d_inv, LoadMat33(scratch.blocks[later[n].block], offset)),
                   scratch.w[n], offset);
      }
      for (const ExactSolvePlan::Update& update : exact.updates[p]) {
        const Mat33 k_pi = LoadMat33(scratch.blocks[later[update.left].block], offset);
        const Mat33 w_pj = LoadMat33(scratch.w[update.right], offset);
        if (update.target == ExactSolvePlan::kDiagonal) {
          Sym33Lanes& k_ii = scratch.diagonal[later[update.left].position];
          StoreSym33(SubTransposeTimes(LoadSym33(k_ii, offset), k_pi, w_pj), k_ii, offset);
        } else {
          Mat33Lanes& k_ij = scratch.blocks[update.target];
          StoreMat33(Difference(LoadMat33(k_ij, offset), TransposeTimes(k_pi, w_pj)), k_ij, offset);
        }
      }
      for (std::size_t n = 0; n < later.size(); ++n) {
        StoreMat33(LoadMat33(scratch.w[n], offset), scratch.blocks[later[n].block], offset);
      }
    });
  }
}

// rhs -> K^-1 rhs with the factors of Factor.
inline void Solve(const ExactSolvePlan& exact, ExactScratch& scratch) {
  const std::size_t groups = exact.group_count();
  for (std::size_t p = 0; p < groups; ++p) {
    ForEachChunk([&](std::size_t offset) {
      const Vec3 b_p = LoadVec3(scratch.rhs[p], offset);
      for (const ExactSolvePlan::Neighbour& n : exact.later[p]) {
        Vec3Lanes& b_i = scratch.rhs[n.position];
        StoreVec3(Sub(LoadVec3(b_i, offset),
                             TransposeTimes(LoadMat33(scratch.blocks[n.block], offset), b_p)),
                  b_i, offset);
      }
    });
  }
  for (std::size_t p = groups; p-- > 0;) {
    ForEachChunk([&](std::size_t offset) {
      Vec3 lambda = Multiply(LoadSym33(scratch.diagonal[p], offset), LoadVec3(scratch.rhs[p], offset));
      for (const ExactSolvePlan::Neighbour& n : exact.later[p]) {
        lambda = Sub(lambda, Multiply(LoadMat33(scratch.blocks[n.block], offset),
                                             LoadVec3(scratch.rhs[n.position], offset)));
      }
      StoreVec3(lambda, scratch.rhs[p], offset);
    });
  }
}

}  // namespace exact
}  // namespace HWY_NAMESPACE
}  // namespace manyworlds
HWY_AFTER_NAMESPACE();

#endif  // MANYWORLDS_BATCH_EXACT_SYSTEM_INL_H_
