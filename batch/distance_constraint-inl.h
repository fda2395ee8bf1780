// Distance constraint across worlds (spec 3, Distance): one axis row along
// the line between the two anchors, active only outside [min, max].
//
//   p1 = x1 + R1 r1_local, p2 = x2 + R2 r2_local, L = |p2 - p1|
//   n = (p2 - p1) / L, or the previous n when L = 0 (initially +Y; persistent)
//   lever arms r1 + u = p2 - x1, r2 = p2 - x2
//   min == max:  C = L - min, impulse both ways          (a rod, or a spring)
//   L <= min:    C = L - min, impulse in [0, inf)        (pushes apart)
//   L >= max:    C = L - max, impulse in (-inf, 0]       (pulls together)
//   otherwise:   row deactivated (effective mass and impulse zero)
// The row's spring is the limits spring (soft where it has stiffness).
//
// Position phase (hard limits only), Jolt's quirk reproduced exactly: the
// error is measured from the world anchors and normal stored by the last
// CalculateProperties (in the first iteration those of the setup, before
// integration), d = (p2_stored - p1_stored) . n_stored, error d - min below
// min, d - max above max (strict), else 0. Only where the error is non-zero
// is everything recomputed from the current poses (which may deactivate the
// row and zero its impulse) and one Baumgarte step taken on that error; the
// other worlds keep their stored anchors, normal and row untouched.

#if defined(MANYWORLDS_BATCH_DISTANCE_CONSTRAINT_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef MANYWORLDS_BATCH_DISTANCE_CONSTRAINT_INL_H_
#undef MANYWORLDS_BATCH_DISTANCE_CONSTRAINT_INL_H_
#else
#define MANYWORLDS_BATCH_DISTANCE_CONSTRAINT_INL_H_
#endif

#include "batch/constraint_block.h"
#include "batch/drive_and_limit_rows-inl.h"
#include "kernels/axis-inl.h"

HWY_BEFORE_NAMESPACE();
namespace manyworlds {
namespace HWY_NAMESPACE {

// Anchors, normal, lever arms and the limit row at the current poses.
inline void DistanceProperties(const ConstraintBlock& c, const StepScalars& step) {
  auto& s = c.Main<DistanceConstraintLanes>();
  auto& limit = c.Limit<LinearLimitRow>();
  LaneFlags inside;
  ForEachChunk([&](std::size_t offset) {
    const Vec3 x1 = LoadVec3(c.bodies.body1->position, offset);
    const Vec3 x2 = LoadVec3(c.bodies.body2->position, offset);
    const Vec3 p1 = Add(x1, Rotate(LoadQuat(c.bodies.body1->rotation, offset),
                                   LoadVec3(s.anchors.r1_local, offset)));
    const Vec3 p2 = Add(x2, Rotate(LoadQuat(c.bodies.body2->rotation, offset),
                                   LoadVec3(s.anchors.r2_local, offset)));
    const Vec3 separation = Sub(p2, p1);
    const LaneVec length = hn::Sqrt(LengthSquared(separation));
    const Vec3 normal = DirectionOrPrevious(separation, length, LoadVec3(s.normal, offset));
    StoreVec3(normal, s.normal, offset);
    StoreVec3(p1, s.world_point1, offset);
    StoreVec3(p2, s.world_point2, offset);
    StoreVec3(Sub(p2, x1), limit.geometry.r1_plus_u, offset);
    StoreVec3(Sub(p2, x2), limit.geometry.r2, offset);
    StoreVec3(normal, limit.geometry.axis, offset);
    const LaneVec min = Load(limit.min, offset);
    const LaneVec max = Load(limit.max, offset);
    const LaneMask rod = hn::Eq(min, max);
    const LaneMask below = hn::Or(rod, hn::Le(length, min));
    Store(hn::Sub(length, hn::IfThenElse(below, min, max)), limit.geometry.error, offset);
    StoreLimitImpulseRange(below, rod, limit.geometry, offset);
    StoreFlags(hn::Not(hn::Or(below, hn::Ge(length, max))), inside, offset);
  });
  AxisCalculatePropertiesForLimit(c.bodies, limit.geometry, limit.part, step.delta_time,
                                  c.plan.limit_spring_mode);
  AxisDeactivate(limit.part, inside);
}

inline void DistanceConstraintSetup(const ConstraintBlock& c, const StepScalars& step) {
  DistanceProperties(c, step);
}

inline void DistanceConstraintWarmStart(const ConstraintBlock& c, const StepScalars& step) {
  auto& limit = c.Limit<LinearLimitRow>();
  AxisWarmStart(c.bodies, limit.geometry, limit.part, step.warm_start_ratio);
}

inline bool DistanceConstraintSolveVelocity(const ConstraintBlock& c) {
  auto& limit = c.Limit<LinearLimitRow>();
  return AxisSolveVelocity(c.bodies, limit.geometry, limit.part);
}

inline bool DistanceConstraintSolvePosition(const ConstraintBlock& c, const StepScalars& step) {
  if (c.plan.soft_limits) return false;  // a spring corrects through its bias
  auto& s = c.Main<DistanceConstraintLanes>();
  auto& limit = c.Limit<LinearLimitRow>();
  LaneArray error;
  LaneFlags has_error;
  bool any_error = false;
  ForEachChunk([&](std::size_t offset) {
    const LaneVec distance = Dot(
        Sub(LoadVec3(s.world_point2, offset), LoadVec3(s.world_point1, offset)),
        LoadVec3(s.normal, offset));
    const LaneVec min = Load(limit.min, offset);
    const LaneVec max = Load(limit.max, offset);
    const LaneVec e = hn::IfThenElse(
        hn::Lt(distance, min), hn::Sub(distance, min),
        hn::IfThenElseZero(hn::Gt(distance, max), hn::Sub(distance, max)));
    Store(e, error, offset);
    const LaneMask nonzero = hn::Ne(e, Zero());
    StoreFlags(nonzero, has_error, offset);
    any_error |= AnyLane(nonzero);
  });
  if (!any_error) return false;
  const DistanceConstraintLanes stored = s;
  const LinearLimitRow stored_limit = limit;
  DistanceProperties(c, step);
  KeepChangedLanes(has_error, s, stored);
  KeepChangedLanes(has_error, limit, stored_limit);
  limit.geometry.error = error;  // C from the stored anchors (0 where nothing changed)
  return AxisSolvePosition(c.bodies, limit.geometry, limit.part, step.baumgarte);
}

}  // namespace HWY_NAMESPACE
}  // namespace manyworlds
HWY_AFTER_NAMESPACE();

#endif  // MANYWORLDS_BATCH_DISTANCE_CONSTRAINT_INL_H_
