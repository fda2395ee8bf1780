// Pulley constraint across worlds (spec 3, Pulley): one independent-axis row
// (kernels/independent_axis-inl.h) over the two rope segments.
//
//   p_i = x_i + R_i r_i_local, r_i = p_i - x_i, f_i fixed in world space
//   n_i = (p_i - f_i) / |p_i - f_i|, the previous n_i when that is zero
//         (initially -Y; persistent)
//   L = |p1 - f1| + ratio |p2 - f2|
//   min == max:  impulse both ways                 (a rope of fixed length)
//   L <= min:    impulse in [0, inf)                (pushes the bodies out)
//   L >= max:    impulse in (-inf, 0]               (pulls them in)
//   otherwise:   row deactivated
// Position phase: C = L - min if L < min, L - max if L > max (strict), from
// the current poses; only where C != 0 is the row recomputed (the normals
// change there only) and one Baumgarte step taken.

#if defined(MANYWORLDS_BATCH_PULLEY_CONSTRAINT_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef MANYWORLDS_BATCH_PULLEY_CONSTRAINT_INL_H_
#undef MANYWORLDS_BATCH_PULLEY_CONSTRAINT_INL_H_
#else
#define MANYWORLDS_BATCH_PULLEY_CONSTRAINT_INL_H_
#endif

#include "batch/constraint_block.h"
#include "batch/drive_and_limit_rows-inl.h"
#include "kernels/independent_axis-inl.h"

HWY_BEFORE_NAMESPACE();
namespace manyworlds {
namespace HWY_NAMESPACE {

struct PulleySegments {
  Vec3 r1, r2;              // lever arms to the attachments
  Vec3 offset1, offset2;    // p_i - f_i
  LaneVec length1, length2; // |p_i - f_i|
  LaneVec length;           // L = length1 + ratio length2
};

HWY_INLINE PulleySegments PulleySegmentsOfChunk(const ConstraintBlock& c,
                                                const PulleyConstraintLanes& s,
                                                std::size_t offset) {
  PulleySegments seg;
  seg.r1 = Rotate(LoadQuat(c.bodies.body1->rotation, offset), LoadVec3(s.anchors.r1_local, offset));
  seg.r2 = Rotate(LoadQuat(c.bodies.body2->rotation, offset), LoadVec3(s.anchors.r2_local, offset));
  seg.offset1 = Sub(Add(LoadVec3(c.bodies.body1->position, offset), seg.r1),
                    LoadVec3(s.fixed_point1, offset));
  seg.offset2 = Sub(Add(LoadVec3(c.bodies.body2->position, offset), seg.r2),
                    LoadVec3(s.fixed_point2, offset));
  seg.length1 = hn::Sqrt(LengthSquared(seg.offset1));
  seg.length2 = hn::Sqrt(LengthSquared(seg.offset2));
  seg.length = hn::MulAdd(Load(s.geometry.ratio, offset), seg.length2, seg.length1);
  return seg;
}

// Lever arms, normals, impulse range and the row at the current poses.
inline void PulleyProperties(const ConstraintBlock& c) {
  auto& s = c.Main<PulleyConstraintLanes>();
  LaneFlags inside;
  ForEachChunk([&](std::size_t offset) {
    const PulleySegments seg = PulleySegmentsOfChunk(c, s, offset);
    StoreVec3(seg.r1, s.geometry.r1, offset);
    StoreVec3(seg.r2, s.geometry.r2, offset);
    StoreVec3(DirectionOrPrevious(seg.offset1, seg.length1, LoadVec3(s.geometry.n1, offset)),
              s.geometry.n1, offset);
    StoreVec3(DirectionOrPrevious(seg.offset2, seg.length2, LoadVec3(s.geometry.n2, offset)),
              s.geometry.n2, offset);
    const LaneVec min = Load(s.min_length, offset);
    const LaneVec max = Load(s.max_length, offset);
    const LaneMask fixed = hn::Eq(min, max);
    const LaneMask at_min = hn::Le(seg.length, min);
    const LaneMask at_max = hn::Ge(seg.length, max);
    // [0, inf) at the minimum, (-inf, 0] at the maximum, both when fixed.
    StoreLimitImpulseRange(at_min, fixed, s.geometry, offset);
    StoreFlags(hn::Not(hn::Or(fixed, hn::Or(at_min, at_max))), inside, offset);
  });
  IndependentAxisCalculateProperties(c.bodies, s.geometry, s.part);
  IndependentAxisDeactivate(s.part, inside);
}

inline void PulleyConstraintSetup(const ConstraintBlock& c, const StepScalars&) {
  PulleyProperties(c);
}

inline void PulleyConstraintWarmStart(const ConstraintBlock& c, const StepScalars& step) {
  auto& s = c.Main<PulleyConstraintLanes>();
  IndependentAxisWarmStart(c.bodies, s.geometry, s.part, step.warm_start_ratio);
}

inline bool PulleyConstraintSolveVelocity(const ConstraintBlock& c) {
  auto& s = c.Main<PulleyConstraintLanes>();
  return IndependentAxisSolveVelocity(c.bodies, s.geometry, s.part);
}

inline bool PulleyConstraintSolvePosition(const ConstraintBlock& c, const StepScalars& step) {
  auto& s = c.Main<PulleyConstraintLanes>();
  LaneFlags has_error;
  bool any_error = false;
  ForEachChunk([&](std::size_t offset) {
    const LaneVec length = PulleySegmentsOfChunk(c, s, offset).length;
    const LaneVec min = Load(s.min_length, offset);
    const LaneVec max = Load(s.max_length, offset);
    const LaneVec e = hn::IfThenElse(
        hn::Lt(length, min), hn::Sub(length, min),
        hn::IfThenElseZero(hn::Gt(length, max), hn::Sub(length, max)));
    Store(e, s.error, offset);
    const LaneMask nonzero = hn::Ne(e, Zero());
    StoreFlags(nonzero, has_error, offset);
    any_error |= AnyLane(nonzero);
  });
  if (!any_error) return false;
  const PulleyConstraintLanes stored = s;
  PulleyProperties(c);
  KeepChangedLanes(has_error, s, stored);
  return IndependentAxisSolvePosition(c.bodies, s.geometry, s.error, s.part, step.baumgarte);
}

}  // namespace HWY_NAMESPACE
}  // namespace manyworlds
HWY_AFTER_NAMESPACE();

#endif  // MANYWORLDS_BATCH_PULLEY_CONSTRAINT_INL_H_
