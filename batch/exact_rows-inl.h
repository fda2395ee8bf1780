// The rows of the exact solve's groups (ExactRows, batch/exact_plan.h) at
// the current poses: J for each side and the position error C, with
// dC/dt = J v (v = (v1, w1, v2, w2)), so that the velocity solve and the
// Newton steps of the position phase use one Jacobian. Rows past a group's
// count are zero (padding). Per kind, with r1, r2 the lever arms (COM to
// anchor, world), u = p2 - p1 the anchors' separation:
//
//   point (ball, hinge, fixed, swing-twist, cone, six-DOF)  C = u
//     J_i = [-e_i, -(r1 x e_i), e_i, r2 x e_i]
//     (a six-DOF's anchor on body 1 is moved by c1 min, its fixed offset,
//     in both phases: Gauss-Seidel moves it in the position phase only, as
//     Jolt does, which leaves its velocity rows off the constrained point)
//   hinge rotation  a1 = R1 a1_local, a2 = R2 a2_local (Jolt's repair near
//     90 degrees, kernels/hinge_rotation-inl.h), b2 = perp(a2), c2 = a2 x b2
//     C = (a1 . b2, a1 . c2)      J_i = [0, -(e_i x a1), 0, e_i x a1], e = b2, c2
//   rotation (fixed, slider, six-DOF)  C = 2 xyz(q2 r0^-1 q1*), w >= 0
//     (a six-DOF's r0^-1 = c2 (c1 euler(min))*, its fixed rotation)
//     J = [0, -E, 0, E]           (dC/dt = w2 - w1 to first order in C)
//   slider axes  n_i = R1 (normal, binormal)_local
//     C_i = u . n_i               J_i = [-n_i, -((r1 + u) x n_i), n_i, r2 x n_i]
//   gear  a = R1 a1_local, b = R2 a2_local, ratio r
//     C = theta1 + r theta2       J = [0, a, 0, r b]
//   rack and pinion  a = R1 hinge_local, b = R2 slider_local
//     C = theta1 - r d2           J = [0, a, -r b, 0]
//   distance (a rod of length l)  n = u / |u|, the stored normal where u = 0
//     C = |u| - l                 J = [-n, -((r1 + u) x n), n, r2 x n]
//     ((r1 + u) x n and r1 x n have the same component along n: the
//     Gauss-Seidel row's lever arms; the stored normal is the last
//     Gauss-Seidel setup's, initially +Y, as the exact solve keeps it)
//
// theta are the helper hinges' unwrapped angles and d2 the helper slider's
// position, as the Gauss-Seidel position steps read them; without helpers
// C = 0 (Gauss-Seidel then corrects no position either). The rotation rows
// are Jolt's RotationEulerConstraintPart's, whose J is exact only at C = 0:
// the Newton steps on them converge linearly, at a rate of the order of the
// remaining angle.

#if defined(MANYWORLDS_BATCH_EXACT_ROWS_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef MANYWORLDS_BATCH_EXACT_ROWS_INL_H_
#undef MANYWORLDS_BATCH_EXACT_ROWS_INL_H_
#else
#define MANYWORLDS_BATCH_EXACT_ROWS_INL_H_
#endif

#include <cstddef>

#include "batch/constraint_block.h"
#include "batch/drive_and_limit_rows-inl.h"
#include "batch/exact_plan.h"
#include "batch/gear_constraint-inl.h"
#include "batch/hinge_constraint-inl.h"
#include "batch/slider_constraint-inl.h"
#include "kernels/hinge_rotation-inl.h"
#include "kernels/lane_math-inl.h"
#include "kernels/rotation_euler-inl.h"

HWY_BEFORE_NAMESPACE();
namespace manyworlds {
namespace HWY_NAMESPACE {
namespace exact {

// A group's rows on both sides (index 0 body 1, 1 body 2): row i of J is
// (linear[0].m[i], angular[0].m[i], linear[1].m[i], angular[1].m[i]).
struct GroupRows {
  Mat33 linear[2], angular[2];
  Vec3 error;
};

HWY_INLINE void SetRow(Mat33& m, int row, const Vec3& v) {
  m.m[row][0] = v.x, m.m[row][1] = v.y, m.m[row][2] = v.z;
}

HWY_INLINE Mat33 Identity33() {
  Mat33 m = ZeroMat33();
  m.m[0][0] = m.m[1][1] = m.m[2][2] = Splat(1.0f);
  return m;
}

// Entry (i, c) of [r]x, the matrix of r x.
HWY_INLINE LaneVec CrossEntry(const Vec3& r, int i, int c) {
  switch (3 * i + c) {
    case 1: return hn::Neg(r.z);
    case 2: return r.y;
    case 3: return r.z;
    case 5: return hn::Neg(r.x);
    case 6: return hn::Neg(r.y);
    case 7: return r.x;
    default: return Zero();  // the diagonal
  }
}

HWY_INLINE Mat33 Negated(const Mat33& a) {
  Mat33 m;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) m.m[i][j] = hn::Neg(a.m[i][j]);
  }
  return m;
}

// The anchors and point part of a constraint with a point group.
HWY_INLINE const PointGeometry& PointAnchors(const ConstraintBlock& c) {
  switch (c.plan.type) {
    case ConstraintType::kSixDof: return c.Main<SixDofConstraintLanes>().fixed_anchors;
    case ConstraintType::kHinge: return c.Main<HingeConstraintLanes>().anchors;
    case ConstraintType::kFixed: return c.Main<FixedConstraintLanes>().anchors;
    case ConstraintType::kSwingTwist: return c.Main<SwingTwistConstraintLanes>().anchors;
    case ConstraintType::kCone: return c.Main<ConeConstraintLanes>().anchors;
    default: return c.Main<PointConstraintLanes>().anchors;
  }
}
HWY_INLINE PointLanes& PointPart(const ConstraintBlock& c) {
  switch (c.plan.type) {
    case ConstraintType::kSixDof: return c.Scratch<SixDofConstraintScratch>().point;
    case ConstraintType::kHinge: return c.Scratch<HingeConstraintScratch>().point;
    case ConstraintType::kFixed: return c.Scratch<FixedConstraintScratch>().point;
    case ConstraintType::kSwingTwist: return c.Scratch<SwingTwistConstraintScratch>().point;
    case ConstraintType::kCone: return c.Scratch<ConeConstraintScratch>().point;
    default: return c.Scratch<PointConstraintScratch>().point;
  }
}

// r0^-1 of a constraint with a rotation group.
HWY_INLINE const QuatLanes& RestOrientationInverse(const ConstraintBlock& c) {
  switch (c.plan.type) {
    case ConstraintType::kFixed: return c.Main<FixedConstraintLanes>().inv_initial_orientation;
    case ConstraintType::kSixDof: return c.Main<SixDofConstraintLanes>().inv_initial_orientation;
    default: return c.Main<SliderConstraintLanes>().inv_initial_orientation;
  }
}

// A point group's rows on one side as general rows, entry by entry, from the
// lever arm r and I^-1 [r]x its part caches: linear s E, angular -s [r]x,
// I^-1 (angular)^T = s I^-1 [r]x (s = -1 on body 1; the sign flips the sign
// bit, as Negated does). Read where a coupling uses them (AddCoupling), so no
// 3x3 of them is held in registers (AVX2 has 16: held whole, they spilled).
struct PointRows {
  PointRows(const PointLanes& part, bool body2, std::size_t offset)
      : r(LoadVec3(body2 ? part.r2 : part.r1, offset)),
        inv_i_r_cross(body2 ? part.inv_i2_r2_cross : part.inv_i1_r1_cross),
        flip(body2 ? Zero() : Splat(-0.0f)),
        offset(offset) {}
  LaneVec Linear(int i, int c) const { return hn::Xor(i == c ? Splat(1.0f) : Zero(), flip); }
  LaneVec Angular(int i, int c) const { return hn::Xor(hn::Neg(CrossEntry(r, i, c)), flip); }
  LaneVec InvIAngular(int c, int j) const {
    return hn::Xor(Load(inv_i_r_cross.m[c][j], offset), flip);
  }
  bool HasLinear() const { return true; }
  int Rows() const { return 3; }

  Vec3 r;
  const Mat33Lanes& inv_i_r_cross;
  LaneVec flip;  // -0 on body 1: x ^ -0 = -x
  std::size_t offset;
};

// The helper hinge's unwrapped angle of `body`'s turn (AsSeenBy).
HWY_INLINE LaneVec HelperAngle(const StepPlan& plan, const ConstraintBlock& c,
                               std::size_t helper, std::size_t body, std::size_t offset) {
  const ConstraintBlock hinge = ConstraintInBlock(plan, helper, c.block);
  return AsSeenBy(hinge, body,
                  HingeUnwrappedAngleOfChunk(hinge.bodies, hinge.Main<HingeConstraintLanes>(),
                                             offset));
}

// The rows of a group that is not a point group (those use their part's
// cached lever arms directly); C only `with_error`.
HWY_INLINE GroupRows RowsOfChunk(const StepPlan& plan, const ConstraintBlock& c, ExactRows kind,
                                 bool with_error, std::size_t offset) {
  GroupRows rows;
  for (int side = 0; side < 2; ++side) {
    Assign(rows.linear[side], ZeroMat33());
    Assign(rows.angular[side], ZeroMat33());
  }
  rows.error = ZeroVec3();
  const Quat q1 = LoadQuat(c.bodies.body1->rotation, offset);
  const Quat q2 = LoadQuat(c.bodies.body2->rotation, offset);
  switch (kind) {
    case ExactRows::kPoint: break;  // not used
    case ExactRows::kHingeRotation: {
      const auto& s = c.Main<HingeConstraintLanes>();
      const Vec3 a1 = Rotate(q1, LoadVec3(s.hinge_axis1_local, offset));
      const Vec3 a2 =
          hinge_rotation::RepairedHingeAxis2(a1, Rotate(q2, LoadVec3(s.hinge_axis2_local, offset)));
      const Vec3 b2 = NormalizedPerpendicular(a2);
      const Vec3 e[2] = {b2, Cross(a2, b2)};
      for (int i = 0; i < 2; ++i) {
        const Vec3 axis = Cross(e[i], a1);
        SetRow(rows.angular[0], i, Neg(axis));
        SetRow(rows.angular[1], i, axis);
      }
      rows.error = {Dot(a1, e[0]), Dot(a1, e[1]), Zero()};
      break;
    }
    case ExactRows::kRotation: {
      Assign(rows.angular[0], Negated(Identity33()));
      Assign(rows.angular[1], Identity33());
      if (with_error) {
        rows.error = RotationEulerError(c.bodies, LoadQuat(RestOrientationInverse(c), offset),
                                        offset);
      }
      break;
    }
    case ExactRows::kSliderAxes: {
      const auto& s = c.Main<SliderConstraintLanes>();
      const AnchorLeverArms arms = AnchorLeverArmsOfChunk(c.bodies, s.anchors, offset);
      const Vec3 n[2] = {Rotate(q1, LoadVec3(s.normal_axis1_local, offset)),
                         Rotate(q1, LoadVec3(s.binormal_axis1_local, offset))};
      for (int i = 0; i < 2; ++i) {
        SetRow(rows.linear[0], i, Neg(n[i]));
        SetRow(rows.angular[0], i, Neg(Cross(arms.r1_plus_u, n[i])));
        SetRow(rows.linear[1], i, n[i]);
        SetRow(rows.angular[1], i, Cross(arms.r2, n[i]));
      }
      rows.error = {Dot(arms.separation, n[0]), Dot(arms.separation, n[1]), Zero()};
      break;
    }
    case ExactRows::kGear: {
      const auto& s = c.Main<GearConstraintLanes>();
      const LaneVec ratio = Load(s.geometry.ratio, offset);
      SetRow(rows.angular[0], 0, Rotate(q1, LoadVec3(s.hinge_axis1_local, offset)));
      SetRow(rows.angular[1], 0, Scale(Rotate(q2, LoadVec3(s.hinge_axis2_local, offset)), ratio));
      if (with_error && c.plan.helper1 != kNoConstraint && c.plan.helper2 != kNoConstraint) {
        rows.error.x = hn::MulAdd(ratio, HelperAngle(plan, c, c.plan.helper2, c.plan.body2, offset),
                                  HelperAngle(plan, c, c.plan.helper1, c.plan.body1, offset));
      }
      break;
    }
    case ExactRows::kDistance: {
      const auto& s = c.Main<DistanceConstraintLanes>();
      const AnchorLeverArms arms = AnchorLeverArmsOfChunk(c.bodies, s.anchors, offset);
      const LaneVec length = hn::Sqrt(LengthSquared(arms.separation));
      const Vec3 n = DirectionOrPrevious(arms.separation, length, LoadVec3(s.normal, offset));
      SetRow(rows.linear[0], 0, Neg(n));
      SetRow(rows.angular[0], 0, Neg(Cross(arms.r1_plus_u, n)));
      SetRow(rows.linear[1], 0, n);
      SetRow(rows.angular[1], 0, Cross(arms.r2, n));
      rows.error.x = hn::Sub(length, Load(c.Limit<LinearLimitRow>().min, offset));
      break;
    }
    case ExactRows::kRackAndPinion: {
      const auto& s = c.Main<RackAndPinionConstraintLanes>();
      const LaneVec ratio = Load(s.geometry.ratio, offset);
      SetRow(rows.angular[0], 0, Rotate(q1, LoadVec3(s.hinge_axis1_local, offset)));
      SetRow(rows.linear[1], 0,
             Scale(Rotate(q2, LoadVec3(s.slider_axis2_local, offset)), hn::Neg(ratio)));
      if (with_error && c.plan.helper1 != kNoConstraint && c.plan.helper2 != kNoConstraint) {
        const ConstraintBlock slider = ConstraintInBlock(plan, c.plan.helper2, c.block);
        const LaneVec d2 = AsSeenBy(
            slider, c.plan.body2,
            SliderCurrentPositionOfChunk(slider.bodies, slider.Main<SliderConstraintLanes>(),
                                         offset));
        rows.error.x =
            hn::NegMulAdd(ratio, d2, HelperAngle(plan, c, c.plan.helper1, c.plan.body1, offset));
      }
      break;
    }
  }
  return rows;
}

// What a hinge's setup does besides its rows, done by the exact solve in its
// place once per substep: the angle and its turn count (joint coordinates,
// the gear and rack-and-pinion errors read them).
inline void HingeTurns(const StepPlan& plan, std::byte* block) {
  for (std::size_t i = 0; i < plan.constraints.size(); ++i) {
    if (plan.constraints[i].type != ConstraintType::kHinge) continue;
    const ConstraintBlock c = ConstraintInBlock(plan, i, block);
    HingeAxesAndAngle(c, true);
    HingeCountTurns(c.Main<HingeConstraintLanes>(), c.Scratch<HingeConstraintScratch>());
  }
}

}  // namespace exact
}  // namespace HWY_NAMESPACE
}  // namespace manyworlds
HWY_AFTER_NAMESPACE();

#endif  // MANYWORLDS_BATCH_EXACT_ROWS_INL_H_
