// Block storage of the constraint types: for 16 worlds, each type's per-world
// parameters (anchors, axes, limits, motor targets, springs, ratios) next to
// the parts it is built from (spec 3). Optional features (limits, motor or
// friction) have their own struct, allocated only when the scene uses them.
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
// block (StepPlan::scratch_bytes). Its parts' accumulated impulses are homed
// in the first struct and carried into the scratch around each block's step
// (CarryState, StepPlan::carried).
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

// Motor or friction row of a hinge (angle part) or slider (axis part).
// geometry.spring holds the per-world motor spring.
struct AngularMotorLanes {
  LaneArray target_velocity, target_position;  // rad/s, rad
  LaneArray min_force_limit, max_force_limit;  // N m
  LaneArray max_friction;                      // N m
  AngleGeometry geometry;
  AngleLanes part;
};
struct LinearMotorLanes {
  LaneArray target_velocity, target_position;  // m/s, m
  LaneArray min_force_limit, max_force_limit;  // N
  LaneArray max_friction;                      // N
  AxisGeometry geometry;
  AxisLanes part;
};

// Limit row; geometry.spring holds the per-world limit spring.
struct AngularLimitLanes {
  LaneArray min, max;  // rad
  AngleGeometry geometry;
  AngleLanes part;
};
struct LinearLimitLanes {
  LaneArray min, max;  // m
  AxisGeometry geometry;
  AxisLanes part;
};

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
struct GearConstraintLanes {
  Vec3Lanes hinge_axis1_local, hinge_axis2_local;
  GearGeometry geometry;  // world axes of this step and the ratio (parameter)
  GearLanes part;
  LaneArray error;        // position error of the current position iteration
};

// ---- Rack and pinion: one part; position correction through hinge + slider.
struct RackAndPinionConstraintLanes {
  Vec3Lanes hinge_axis1_local, slider_axis2_local;
  RackAndPinionGeometry geometry;
  RackAndPinionLanes part;
  LaneArray error;
};

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
  // (initially a perpendicular of body 1's twist axis).
  AngleGeometry geometry;
  LaneArray cos_theta;  // t1 . t2 of the last properties computation
  PointLanes point;
  AngleLanes angle;
};

// ---- Rotation drives of swing-twist and six-DOF: one motor or friction row
// about each axis of body 2's constraint frame (X = twist, Y and Z = swing);
// geometry.spring holds the per-world motor spring.
struct AngularDriveRowLanes {
  LaneArray target_velocity;                   // rad/s about this axis
  LaneArray min_force_limit, max_force_limit;  // N m
  LaneArray max_friction;                      // N m
  AngleGeometry geometry;
  AngleLanes part;
};
struct RotationDriveLanes {
  // Body 2's constraint frame relative to body 1's that position drives aim
  // at, unit, as given: it is clamped into the limits at every setup.
  QuatLanes target_orientation;
  AngularDriveRowLanes rows[3];
};

// ---- Swing-twist: [drives] -> the swing-twist part (limits) -> point.
struct SwingTwistConstraintLanes {
  PointGeometry anchors;
  SwingTwistGeometry frames;       // constraint frame to body 1 / body 2 (parameters)
  SwingTwistLimitLanes limits;     // per world (parameters)
  SwingTwistLanes swing_twist;
  PointLanes point;
};

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
  Vec3Lanes r1_plus_u, r2;            // lever arms of the translation rows this step
  Vec3Lanes translation_axis[3];      // columns of R(q1 c1) this step
  LaneArray displacement[3];          // (p2 - p1) . axis_i this step
  PointLanes point;
  RotationEulerLanes rotation;
  SwingTwistLanes swing_twist;
};

}  // namespace manyworlds
