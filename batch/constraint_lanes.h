// Block storage of the constraint types: for 16 worlds, each type's per-world
// parameters (anchors, axes, limits, motor targets, springs, ratios) and the
// parts it is built from (spec 3). Optional features (limits, motor or
// friction) have their own structs, allocated only when the scene uses them.
//
// Everything is made of LaneArrays (16 floats, 64-byte aligned), so a block is
// a plain sequence of LaneArrays: resetting, copying or hashing one world is
// the same loop over lane `i` of every array, whatever the constraint.
//
// A type whose lanes come in two structs keeps in the first (in the block)
// what survives a step: parameters, accumulated impulses, turn counts. The
// second, "...Scratch", holds what its setup recomputes at every substep
// (this step's axes and lever arms, the parts' Jacobians and effective
// masses) and lives in one scratch block per thread, reused block after
// block (StepPlan::scratch_bytes). Its parts' accumulated impulses (and a
// gear's or rack's ratio) are homed in the first struct and carried into the
// scratch and back around each block's step (CarryState, StepPlan::carried).
#pragma once

#include "kernels/angle.h"
#include "kernels/axis.h"
#include "kernels/dual_axis.h"
#include "kernels/gear.h"
#include "kernels/hermite_path.h"
#include "kernels/hinge_rotation.h"
#include "kernels/independent_axis.h"
#include "kernels/point.h"
#include "kernels/rack_and_pinion.h"
#include "kernels/rotation_euler.h"
#include "kernels/swing_twist.h"
#include "manyworlds/lanes.h"

namespace manyworlds {

// ---- Point: one point part.
struct PointConstraintLanes {
  PointGeometry anchors;  // body-space anchors (parameters)
  PointLanes::Persistent point_state;
};
struct PointConstraintScratch {
  PointLanes point;
};
template <class Carry>
void CarryState(PointConstraintLanes& s, PointConstraintScratch& t, Carry&& carry) {
  carry(s.point_state, t.point.persistent);
}

// ---- Fixed: rotation Euler, then point.
struct FixedConstraintLanes {
  PointGeometry anchors;
  QuatLanes inv_initial_orientation;  // r0^-1 (parameter)
  RotationEulerLanes::Persistent rotation_state;
  PointLanes::Persistent point_state;
};
struct FixedConstraintScratch {
  RotationEulerLanes rotation;
  PointLanes point;
};
template <class Carry>
void CarryState(FixedConstraintLanes& s, FixedConstraintScratch& t, Carry&& carry) {
  carry(s.rotation_state, t.rotation.persistent);
  carry(s.point_state, t.point.persistent);
}

// ---- Hinge: [motor angle] -> point -> hinge rotation -> [limit angle].
struct HingeConstraintLanes {
  PointGeometry anchors;
  Vec3Lanes hinge_axis1_local, hinge_axis2_local;  // unit, body space
  QuatLanes inv_initial_orientation;  // r0^-1 from the normal/hinge frames
  PointLanes::Persistent point_state;
  HingeRotationLanes::Persistent rotation_state;
  // Turn counting for the unwrapped angle theta + 2 pi turns (joint
  // coordinates; the gear and rack-and-pinion position steps): theta at the
  // last setup, and the whole turns made since the scene's pose (a float
  // holds them exactly up to 2^24 turns). A wrap from near +pi to near -pi
  // between two setups is a turn up; a hinge that turns more than pi within
  // one substep is miscounted.
  LaneArray turn_reference_angle;
  LaneArray turns;
};
struct HingeConstraintScratch {
  HingeRotationGeometry rotation_geometry;  // world hinge axes of this step
  PointLanes point;
  HingeRotationLanes rotation;
  LaneArray angle;  // theta at setup (rad, (-pi, pi])
};
template <class Carry>
void CarryState(HingeConstraintLanes& s, HingeConstraintScratch& t, Carry&& carry) {
  carry(s.point_state, t.point.persistent);
  carry(s.rotation_state, t.rotation.persistent);
}

// Motor, friction and limit rows, and the rotation drives below, come in
// two structs with the same field paths: the row as a step uses it
// (...Row: this step's geometry and part, in the scratch) and what of it is
// stored in the block (...Lanes, the same template with StoredSpringGeometry
// and StoredPart: the per-world targets, force limits, friction and spring,
// and the accumulated impulse), which CarryRow copies
// into the row around each block's step and back. Readers and writers of
// the stored block (actions, parameters, scene setup, joint forces) name the
// fields as the step does.
struct StoredSpringGeometry {
  SpringSettingsLanes spring;  // the per-world motor or limit spring
};
template <class Part>
struct StoredPart {
  typename Part::Persistent persistent;  // the accumulated impulse
};

// Motor or friction row of a hinge (angle part) or slider (axis part).
// geometry.spring holds the per-world motor spring.
template <class Geometry, class Part>
struct MotorRow {
  LaneArray target_velocity, target_position;  // rad/s, rad or m/s, m
  LaneArray min_force_limit, max_force_limit;  // N m or N
  LaneArray max_friction;                      // N m or N
  Geometry geometry;
  Part part;
};
using AngularMotorRow = MotorRow<AngleGeometry, AngleLanes>;
using LinearMotorRow = MotorRow<AxisGeometry, AxisLanes>;
using AngularMotorLanes = MotorRow<StoredSpringGeometry, StoredPart<AngleLanes>>;
using LinearMotorLanes = MotorRow<StoredSpringGeometry, StoredPart<AxisLanes>>;

// Limit row; geometry.spring holds the per-world limit spring.
template <class Geometry, class Part>
struct LimitRow {
  LaneArray min, max;  // rad or m
  Geometry geometry;
  Part part;
};
using AngularLimitRow = LimitRow<AngleGeometry, AngleLanes>;
using LinearLimitRow = LimitRow<AxisGeometry, AxisLanes>;
using AngularLimitLanes = LimitRow<StoredSpringGeometry, StoredPart<AngleLanes>>;
using LinearLimitLanes = LimitRow<StoredSpringGeometry, StoredPart<AxisLanes>>;

// ---- Slider: [motor axis] -> dual axis -> rotation Euler -> [limit axis].
struct SliderConstraintLanes {
  PointGeometry anchors;
  Vec3Lanes slider_axis1_local, normal_axis1_local, binormal_axis1_local;  // body 1 space
  QuatLanes inv_initial_orientation;
  DualAxisLanes::Persistent dual_state;
  RotationEulerLanes::Persistent rotation_state;
};
struct SliderConstraintScratch {
  DualAxisGeometry dual_geometry;  // lever arms and normals of this step
  Vec3Lanes separation;            // u = p2 - p1 of this step
  Vec3Lanes slider_axis;           // world slider axis of this step
  DualAxisLanes dual;
  RotationEulerLanes rotation;
  LaneArray position;  // d = u . slider axis at setup (m)
};
template <class Carry>
void CarryState(SliderConstraintLanes& s, SliderConstraintScratch& t, Carry&& carry) {
  carry(s.dual_state, t.dual.persistent);
  carry(s.rotation_state, t.rotation.persistent);
}

// ---- Gear: one gear part; position correction through the two hinges.
// The ratio is a parameter in the part's geometry: stored under the same
// field path and carried into the scratch's geometry around each step.
struct StoredRatioGeometry {
  LaneArray ratio;  // r (gear, rack and pinion)
};
struct GearConstraintLanes {
  Vec3Lanes hinge_axis1_local, hinge_axis2_local;
  StoredRatioGeometry geometry;
  StoredPart<GearLanes> part;
};
struct GearConstraintScratch {
  GearGeometry geometry;  // world axes of this step and the ratio
  GearLanes part;
  LaneArray error;        // position error of the current position iteration
};
template <class Carry>
void CarryState(GearConstraintLanes& s, GearConstraintScratch& t, Carry&& carry) {
  carry(s.geometry.ratio, t.geometry.ratio);
  carry(s.part.persistent, t.part.persistent);
}

// ---- Rack and pinion: one part; position correction through hinge + slider.
struct RackAndPinionConstraintLanes {
  Vec3Lanes hinge_axis1_local, slider_axis2_local;
  StoredRatioGeometry geometry;
  StoredPart<RackAndPinionLanes> part;
};
struct RackAndPinionConstraintScratch {
  RackAndPinionGeometry geometry;
  RackAndPinionLanes part;
  LaneArray error;
};
template <class Carry>
void CarryState(RackAndPinionConstraintLanes& s, RackAndPinionConstraintScratch& t,
                Carry&& carry) {
  carry(s.geometry.ratio, t.geometry.ratio);
  carry(s.part.persistent, t.part.persistent);
}

// ---- Distance: one axis row along the anchor separation; its min/max,
// spring, geometry and part are the LinearLimitLanes at the limit offset.
struct DistanceConstraintLanes {
  PointGeometry anchors;
  Vec3Lanes normal;  // persistent: n of the last non-zero separation (initially +Y)
  // World anchors at the last CalculateProperties: the position phase measures
  // its error from these (Jolt's quirk, spec 3 Distance).
  Vec3Lanes world_point1, world_point2;
};

// ---- Pulley: one independent-axis row over the two rope segments.
struct PulleyConstraintLanes {
  PointGeometry anchors;                 // body points, body space
  Vec3Lanes fixed_point1, fixed_point2;  // world space (parameters)
  LaneArray min_length, max_length;      // m (parameters)
  // n1, n2 persist: the last non-zero segment directions (initially -Y).
  IndependentAxisGeometry geometry;
  IndependentAxisLanes part;
  LaneArray error;  // C of the current position iteration
};

// ---- Cone: point, then one angle row keeping the twist axes within the cone.
struct ConeConstraintLanes {
  PointGeometry anchors;
  Vec3Lanes twist_axis1_local, twist_axis2_local;  // unit, body space
  LaneArray cos_half_cone_angle;                   // parameter
  // geometry.axis persists: the last non-degenerate rotation axis t2 x t1
  // (initially a perpendicular of body 1's twist axis); its bias and impulse
  // range are the scene's, its error this step's.
  AngleGeometry geometry;
  PointLanes::Persistent point_state;
  AngleLanes::Persistent angle_state;
};
struct ConeConstraintScratch {
  PointLanes point;
  AngleLanes angle;
};
template <class Carry>
void CarryState(ConeConstraintLanes& s, ConeConstraintScratch& t, Carry&& carry) {
  carry(s.point_state, t.point.persistent);
  carry(s.angle_state, t.angle.persistent);
}

// ---- Rotation drives of swing-twist and six-DOF: one motor or friction row
// about each axis of body 2's constraint frame (X = twist, Y and Z = swing);
// geometry.spring holds the per-world motor spring. Row (scratch) and
// stored (block) structs as the motor rows above.
template <class Geometry, class Part>
struct DriveRow {
  LaneArray target_velocity;                   // rad/s about this axis
  LaneArray min_force_limit, max_force_limit;  // N m
  LaneArray max_friction;                      // N m
  Geometry geometry;
  Part part;
};
using AngularDriveRow = DriveRow<AngleGeometry, AngleLanes>;
using AngularDriveRowLanes = DriveRow<StoredSpringGeometry, StoredPart<AngleLanes>>;
template <class Row>
struct RotationDrives {
  // Body 2's constraint frame relative to body 1's that position drives aim
  // at, unit, as given: it is clamped into the limits at every setup.
  QuatLanes target_orientation;
  Row rows[3];
};
using RotationDriveRows = RotationDrives<AngularDriveRow>;
using RotationDriveLanes = RotationDrives<AngularDriveRowLanes>;

// Calls carry(stored, row) for what a stored row holds (VisitCarriedState).
template <class Part, class Geometry, class Carry>
void CarryRow(MotorRow<StoredSpringGeometry, StoredPart<Part>>& s, MotorRow<Geometry, Part>& t,
              Carry&& carry) {
  carry(s.target_velocity, t.target_velocity);
  carry(s.target_position, t.target_position);
  carry(s.min_force_limit, t.min_force_limit);
  carry(s.max_force_limit, t.max_force_limit);
  carry(s.max_friction, t.max_friction);
  carry(s.geometry.spring, t.geometry.spring);
  carry(s.part.persistent, t.part.persistent);
}
template <class Part, class Geometry, class Carry>
void CarryRow(LimitRow<StoredSpringGeometry, StoredPart<Part>>& s, LimitRow<Geometry, Part>& t,
              Carry&& carry) {
  carry(s.min, t.min);
  carry(s.max, t.max);
  carry(s.geometry.spring, t.geometry.spring);
  carry(s.part.persistent, t.part.persistent);
}
template <class Carry>
void CarryRow(AngularDriveRowLanes& s, AngularDriveRow& t, Carry&& carry) {
  carry(s.target_velocity, t.target_velocity);
  carry(s.min_force_limit, t.min_force_limit);
  carry(s.max_force_limit, t.max_force_limit);
  carry(s.max_friction, t.max_friction);
  carry(s.geometry.spring, t.geometry.spring);
  carry(s.part.persistent, t.part.persistent);
}
template <class Carry>
void CarryRow(RotationDriveLanes& s, RotationDriveRows& t, Carry&& carry) {
  carry(s.target_orientation, t.target_orientation);
  for (int i = 0; i < 3; ++i) CarryRow(s.rows[i], t.rows[i], carry);
}

// ---- Swing-twist: [drives] -> the swing-twist part (limits) -> point.
struct SwingTwistConstraintLanes {
  PointGeometry anchors;
  SwingTwistGeometry frames;       // constraint frame to body 1 / body 2 (parameters)
  SwingTwistLimitLanes limits;     // per world (parameters)
  SwingTwistLanes::Persistent swing_twist_state;
  PointLanes::Persistent point_state;
};
struct SwingTwistConstraintScratch {
  SwingTwistLanes swing_twist;
  PointLanes point;
};
template <class Carry>
void CarryState(SwingTwistConstraintLanes& s, SwingTwistConstraintScratch& t, Carry&& carry) {
  carry(s.swing_twist_state, t.swing_twist.persistent);
  carry(s.point_state, t.point.persistent);
}

// ---- Path: [motor axis] -> dual axis (normal, binormal) -> [end limit
// axis] -> hinge rotation or rotation Euler (by the rotation mode). The
// path's points are scene data in the plan; the motor is a LinearMotorLanes
// at the motor offset (target_position = target path fraction).
struct PathConstraintLanes {
  // Path space in body 1's and the attachment frame (X = tangent, Y =
  // binormal, Z = normal at the starting fraction) in body 2's COM space.
  QuatLanes path_to_body1_rotation, attachment_to_body2_rotation;
  Vec3Lanes path_to_body1_position, attachment_to_body2_position;
  // r0^-1: fixed for kFullyConstrained, this step's for kConstrainToPath.
  QuatLanes inv_initial_orientation;
  LaneArray fraction;  // the closest fraction of this step
  Vec3Lanes separation;  // u = attachment - path point, this step
  Vec3Lanes tangent;     // world path tangent, this step
  DualAxisGeometry dual_geometry;
  DualAxisLanes dual;
  AxisGeometry limit_geometry;  // end limit on the tangent (open paths)
  AxisLanes limit;
  HingeRotationGeometry hinge_geometry;
  HingeRotationLanes hinge;
  RotationEulerLanes rotation;
};

// ---- Six-DOF: [translation drives] -> [rotation drives] -> rotation Euler
// (all rotations fixed) or swing-twist (some constrained) -> point (all
// translations fixed, no springs) or up to three translation limit rows.
// The translation limit rows are three LinearLimitLanes at the limit
// offset, the translation drives three LinearMotorLanes at the motor offset,
// the rotation drives a RotationDriveLanes.
struct SixDofConstraintLanes {
  PointGeometry anchors;
  // The point part's anchors in the position phase when every translation is
  // fixed: body 1's moved by c1 limit_min (Jolt keeps the velocity rows on
  // the plain anchors).
  PointGeometry fixed_anchors;
  SwingTwistGeometry frames;          // c1, c2 (parameters)
  SwingTwistLimitLanes rotation_limits;
  // c2 (c1 euler(limit_min))*: the rotation-Euler position target when every
  // rotation is fixed.
  QuatLanes inv_initial_orientation;
  PointLanes::Persistent point_state;
  RotationEulerLanes::Persistent rotation_state;
  SwingTwistLanes::Persistent swing_twist_state;
};
struct SixDofConstraintScratch {
  Vec3Lanes r1_plus_u, r2;            // lever arms of the translation rows this step
  Vec3Lanes translation_axis[3];      // columns of R(q1 c1) this step
  LaneArray displacement[3];          // (p2 - p1) . axis_i this step
  PointLanes point;
  RotationEulerLanes rotation;
  SwingTwistLanes swing_twist;
};
template <class Carry>
void CarryState(SixDofConstraintLanes& s, SixDofConstraintScratch& t, Carry&& carry) {
  carry(s.point_state, t.point.persistent);
  carry(s.rotation_state, t.rotation.persistent);
  carry(s.swing_twist_state, t.swing_twist.persistent);
}

}  // namespace manyworlds
