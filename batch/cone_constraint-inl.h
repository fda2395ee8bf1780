// Cone constraint across worlds (spec 3, Cone): a point part, then one angle
// row that keeps body 2's twist axis within a cone around body 1's.
//
//   t1 = R1 t1_local, t2 = R2 t2_local, cos(theta) = t1 . t2
//   cos(theta) < cos(alpha):  axis a = (t2 x t1) / |t2 x t1| (the previous a
//                             when the cross product is zero; persistent),
//                             angle row on a, impulse in [0, inf)
//   otherwise:                angle row deactivated
// A positive impulse turns body 2 about a, which moves t2 towards t1.
// Velocity: point, then the angle row. Position: the point part recomputed
// and stepped, then the cone row recomputed at the new rotations (which may
// deactivate it) and stepped with C = cos(theta) - cos(alpha), a cosine
// difference fed to an angle row (Jolt's approximation, kept).

#if defined(MANYWORLDS_BATCH_CONE_CONSTRAINT_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef MANYWORLDS_BATCH_CONE_CONSTRAINT_INL_H_
#undef MANYWORLDS_BATCH_CONE_CONSTRAINT_INL_H_
#else
#define MANYWORLDS_BATCH_CONE_CONSTRAINT_INL_H_
#endif

#include "batch/constraint_block.h"
#include "kernels/angle-inl.h"
#include "kernels/point-inl.h"

HWY_BEFORE_NAMESPACE();
namespace manyworlds {
namespace HWY_NAMESPACE {

// cos(theta), the rotation axis and the cone row at the current rotations;
// outside the cone the row's error is cos(theta) - cos(alpha), inside it is
// deactivated (error 0, so the position phase takes no step there).
inline void ConeRotationProperties(const ConstraintBlock& c) {
  auto& s = c.Main<ConeConstraintLanes>();
  auto& t = c.Scratch<ConeConstraintScratch>();
  LaneFlags inside;
  ForEachChunk([&](std::size_t offset) {
    const Vec3 t1 = Rotate(LoadQuat(c.bodies.body1->rotation, offset),
                           LoadVec3(s.twist_axis1_local, offset));
    const Vec3 t2 = Rotate(LoadQuat(c.bodies.body2->rotation, offset),
                           LoadVec3(s.twist_axis2_local, offset));
    const LaneVec cos_theta = Dot(t1, t2);
    const LaneVec cos_alpha = Load(s.cos_half_cone_angle, offset);
    const LaneMask outside = hn::Lt(cos_theta, cos_alpha);
    const Vec3 cross = Cross(t2, t1);
    const LaneVec length = hn::Sqrt(LengthSquared(cross));
    // The axis only changes outside the cone, and keeps its last direction
    // where t2 x t1 is zero.
    const Vec3 previous = LoadVec3(s.geometry.axis, offset);
    StoreVec3(Select(outside, DirectionOrPrevious(cross, length, previous), previous),
              s.geometry.axis, offset);
    Store(hn::IfThenElseZero(outside, hn::Sub(cos_theta, cos_alpha)), s.geometry.error, offset);
    StoreFlags(hn::Not(outside), inside, offset);
  });
  AngleCalculateProperties(c.bodies, s.geometry, t.angle);
  AngleDeactivate(t.angle, inside);
}

inline void ConeConstraintSetup(const ConstraintBlock& c, const StepScalars&) {
  PointCalculateProperties(c.bodies, c.Main<ConeConstraintLanes>().anchors,
                           c.Scratch<ConeConstraintScratch>().point);
  ConeRotationProperties(c);
}

inline void ConeConstraintWarmStart(const ConstraintBlock& c, const StepScalars& step) {
  auto& t = c.Scratch<ConeConstraintScratch>();
  PointWarmStart(c.bodies, t.point, step.warm_start_ratio);
  AngleWarmStart(c.bodies, t.angle, step.warm_start_ratio);
}

inline bool ConeConstraintSolveVelocity(const ConstraintBlock& c) {
  auto& t = c.Scratch<ConeConstraintScratch>();
  const bool point = PointSolveVelocity(c.bodies, t.point);
  return AngleSolveVelocity(c.bodies, c.Main<ConeConstraintLanes>().geometry, t.angle) || point;
}

inline bool ConeConstraintSolvePosition(const ConstraintBlock& c, const StepScalars& step) {
  auto& s = c.Main<ConeConstraintLanes>();
  auto& t = c.Scratch<ConeConstraintScratch>();
  const bool point = PointRecomputeAndSolvePosition(c.bodies, s.anchors, t.point, step.baumgarte);
  ConeRotationProperties(c);
  return AngleSolvePosition(c.bodies, s.geometry, t.angle, step.baumgarte) || point;
}

}  // namespace HWY_NAMESPACE
}  // namespace manyworlds
HWY_AFTER_NAMESPACE();

#endif  // MANYWORLDS_BATCH_CONE_CONSTRAINT_INL_H_
