// The scene's initial block (see scene_setup.h): settings converted once, in
// double, to what the kernels read.

#include "batch/scene_setup.h"

#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cfloat>
#include <cmath>
#include <utility>
#include <type_traits>

#include "batch/constraint_block.h"
#include "batch/constraint_lanes.h"
#include "batch/path_frame.h"
#include "kernels/contact.h"
#include "batch/scene_checks.h"

namespace manyworlds {
namespace {

using Vector = Eigen::Vector3d;
using Rotation = Eigen::Quaterniond;

Vector ToVector(const Float3& v) { return Vector(v[0], v[1], v[2]); }
Rotation ToRotation(const Quaternion& q) {
  return Rotation(q[3], q[0], q[1], q[2]).normalized();
}

// Writes one value into every lane: the initial block holds the scene in all
// 16 worlds (padding worlds too, so they stay ordinary, finite worlds).
void Fill(LaneArray& array, double value) {
  std::fill(std::begin(array.lanes), std::end(array.lanes), static_cast<float>(value));
}
void Fill(Vec3Lanes& lanes, const Vector& v) {
  Fill(lanes.x, v.x());
  Fill(lanes.y, v.y());
  Fill(lanes.z, v.z());
}
void Fill(QuatLanes& lanes, const Rotation& q) {
  Fill(lanes.x, q.x());
  Fill(lanes.y, q.y());
  Fill(lanes.z, q.z());
  Fill(lanes.w, q.w());
}
void Fill(SpringSettingsLanes& lanes, const SpringSettings& spring) {
  Fill(lanes.frequency_or_stiffness, spring.frequency_or_stiffness);
  Fill(lanes.damping, spring.damping);
}

// Jolt's allowed DOFs (spec 4.3) as 1/0 per world axis.
unsigned Dofs(const BodySettings& body) { return static_cast<unsigned>(body.allowed_dofs); }
Vector TranslationMask(const BodySettings& body) {
  const unsigned d = Dofs(body);
  return Vector((d & 1u) ? 1.0 : 0.0, (d & 2u) ? 1.0 : 0.0, (d & 4u) ? 1.0 : 0.0);
}
Vector RotationMask(const BodySettings& body) {
  const unsigned d = Dofs(body);
  return Vector((d & 8u) ? 1.0 : 0.0, (d & 16u) ? 1.0 : 0.0, (d & 32u) ? 1.0 : 0.0);
}
// v with the locked axes exactly +0.
Vector Locked(const Vector& v, const Vector& mask) {
  return Vector(mask.x() != 0.0 ? v.x() : 0.0, mask.y() != 0.0 ? v.y() : 0.0,
                mask.z() != 0.0 ? v.z() : 0.0);
}
bool CanRotate(const BodySettings& body) { return AllowsRotation(body.allowed_dofs); }

// Jolt's MotionProperties::SetMassProperties: m^-1 = 0 without any allowed
// translation (so auto-detected anchors and the parts see an immovable body).
double InverseMass(const BodySettings& body) {
  return InverseMassPropertiesOf(body, body.mass, body.inertia_diagonal).inv_mass;
}

struct Pose {
  Vector position;
  Rotation rotation;
  double inv_mass;
  bool can_move;  // not static
};

Pose PoseOf(const BodySettings& body) {
  return Pose{ToVector(body.position), ToRotation(body.rotation), InverseMass(body),
              body.motion_type != MotionType::kStatic};
}

// Converts a constraint's points and axes from its space to body-COM space.
class Frames {
 public:
  Frames(const Pose& body1, const Pose& body2, ConstraintSpace space)
      : body1_(body1), body2_(body2), world_(space == ConstraintSpace::kWorldSpace) {}

  Vector Point1(const Float3& p) const { return Local(body1_, ToVector(p)); }
  Vector Point2(const Float3& p) const { return Local(body2_, ToVector(p)); }
  Vector Axis1(const Float3& a) const { return LocalAxis(body1_, ToVector(a)); }
  Vector Axis2(const Float3& a) const { return LocalAxis(body2_, ToVector(a)); }

  // World position at the initial poses of a body-COM-space anchor.
  Vector World1(const Vector& local) const { return body1_.position + body1_.rotation * local; }
  Vector World2(const Vector& local) const { return body2_.position + body2_.rotation * local; }

  // Jolt's mAutoDetectPoint: the inverse-mass-weighted average of the centres
  // of mass, or the centre of mass of the body that can move.
  Vector AutoDetectedPoint() const {
    if (!body1_.can_move) return body2_.position;
    if (!body2_.can_move) return body1_.position;
    const double total = body1_.inv_mass + body2_.inv_mass;
    if (total == 0.0) return body1_.position;
    return (body1_.inv_mass * body1_.position + body2_.inv_mass * body2_.position) / total;
  }
  const Pose& body1() const { return body1_; }
  const Pose& body2() const { return body2_; }
  bool world_space() const { return world_; }

  Vector AutoPoint1() const { return body1_.rotation.conjugate() * (AutoDetectedPoint() - body1_.position); }
  Vector AutoPoint2() const { return body2_.rotation.conjugate() * (AutoDetectedPoint() - body2_.position); }

 private:
  Vector Local(const Pose& body, const Vector& p) const {
    return world_ ? Vector(body.rotation.conjugate() * (p - body.position)) : p;
  }
  Vector LocalAxis(const Pose& body, const Vector& a) const {
    return (world_ ? Vector(body.rotation.conjugate() * a) : a).normalized();
  }

  Pose body1_, body2_;
  bool world_;
};

// quat of the frame with columns (x, y, x cross y), all in body space.
Rotation FrameRotation(const Vector& x, const Vector& y) {
  Eigen::Matrix3d frame;
  frame.col(0) = x;
  frame.col(1) = y;
  frame.col(2) = x.cross(y);
  return Rotation(frame).normalized();
}

// r0^-1 = quat(C2) quat(C1)* (spec 2.6), with q2 = q1 r0 at rest.
Rotation InverseInitialOrientation(const Rotation& frame1, const Rotation& frame2) {
  return (frame2 * frame1.conjugate()).normalized();
}

void WriteBodies(const Scene& scene, const StepPlan& plan, std::byte* block) {
  for (std::size_t i = 0; i < plan.bodies.size(); ++i) {
    const BodySettings& body = scene.bodies()[i];
    const bool dynamic = body.motion_type == MotionType::kDynamic;
    const bool is_static = body.motion_type == MotionType::kStatic;
    BodyLanes& lanes = At<BodyLanes>(block, plan.bodies[i].offset);
    // Allowed DOFs (spec 4.3): static bodies never move, so never restricted.
    // The initial velocities are locked as Jolt's SetLinear/AngularVelocity do.
    const Vector translation_mask = TranslationMask(body);
    const Vector rotation_mask = RotationMask(body);
    const bool restricted = plan.bodies[i].dof_restricted;
    Fill(lanes.dof_restricted, restricted ? 1.0 : 0.0);
    if (restricted) {
      Fill(Locks(lanes).translation_locked, Vector(Vector::Ones() - translation_mask));
      Fill(Locks(lanes).rotation_locked, Vector(Vector::Ones() - rotation_mask));
    }
    Fill(lanes.position, ToVector(body.position));
    Fill(lanes.rotation, ToRotation(body.rotation));
    Fill(lanes.linear_velocity, is_static ? Vector::Zero()
                                          : Locked(ToVector(body.linear_velocity),
                                                   translation_mask));
    Fill(lanes.angular_velocity, is_static ? Vector::Zero()
                                           : Locked(ToVector(body.angular_velocity),
                                                    rotation_mask));
    const InverseMassProperties inverse =
        InverseMassPropertiesOf(body, body.mass, body.inertia_diagonal);
    Fill(lanes.inv_mass, inverse.inv_mass);
    // D = 0 and an identity inertia rotation without any allowed rotation (Jolt).
    const bool rotates = dynamic && CanRotate(body);
    Fill(lanes.inv_inertia_diagonal, ToVector(inverse.inv_inertia_diagonal));
    Fill(lanes.inertia_rotation,
         dynamic && !rotates ? Rotation::Identity() : ToRotation(body.inertia_rotation));
    if (plan.bodies[i].motion_offset == kAbsent) continue;
    BodyMotionLanes& motion = At<BodyMotionLanes>(block, plan.bodies[i].motion_offset);
    Fill(motion.force, Vector::Zero());
    Fill(motion.torque, Vector::Zero());
    Fill(motion.linear_damping, body.linear_damping);
    Fill(motion.angular_damping, body.angular_damping);
    Fill(motion.max_linear_velocity, body.max_linear_velocity);
    Fill(motion.max_angular_velocity, body.max_angular_velocity);
    Fill(motion.gravity_factor, body.gravity_factor);
  }
}

template <class Motor>
void WriteMotor(Motor& motor, const MotorSettings& settings, float target_velocity,
                float target_position, float max_friction) {
  Fill(motor.target_velocity, target_velocity);
  Fill(motor.target_position, target_position);
  Fill(motor.min_force_limit, settings.min_force_limit);
  Fill(motor.max_force_limit, settings.max_force_limit);
  Fill(motor.max_friction, max_friction);
  Fill(motor.geometry.spring, settings.spring);
}

template <class Limit>
void WriteLimit(Limit& limit, float min, float max, const SpringSettings& spring) {
  Fill(limit.min, min);
  Fill(limit.max, max);
  Fill(limit.geometry.spring, spring);
}

// Jolt's SwingTwistConstraintPart::SetLimits for one axis: the half angles
// always; sine and cosine of them where limited, (0, 1) locked, (-1/1, 0) free.
void WriteAxisLimit(AxisLimitLanes& lanes, AxisLimitKind kind, double min, double max) {
  Fill(lanes.half_min, 0.5 * min);
  Fill(lanes.half_max, 0.5 * max);
  const bool limited = kind == AxisLimitKind::kLimited, free = kind == AxisLimitKind::kFree;
  Fill(lanes.sin_half_min, limited ? std::sin(0.5 * min) : free ? -1.0 : 0.0);
  Fill(lanes.sin_half_max, limited ? std::sin(0.5 * max) : free ? 1.0 : 0.0);
  Fill(lanes.cos_half_min, limited ? std::cos(0.5 * min) : free ? 0.0 : 1.0);
  Fill(lanes.cos_half_max, limited ? std::cos(0.5 * max) : free ? 0.0 : 1.0);
}

// The rotation drives of a swing-twist or six-DOF constraint: per axis of
// body 2's frame (X, Y, Z) its motor settings, friction and target velocity,
// and the shared target orientation (normalised; clamped by the kernels).
void WriteRotationDrives(const ConstraintPlan& c, std::byte* block,
                         const std::array<const MotorSettings*, 3>& motors,
                         const std::array<float, 3>& max_friction,
                         const Float3& target_angular_velocity, const Quaternion& target) {
  if (!c.has_rotation_drives()) return;
  auto& drive = At<RotationDriveLanes>(block, c.rotation_drive_offset);
  Fill(drive.target_orientation, ToRotation(target).normalized());
  for (std::size_t i = 0; i < 3; ++i) {
    AngularDriveRowLanes& row = drive.rows[i];
    Fill(row.target_velocity, target_angular_velocity[i]);
    Fill(row.min_force_limit, motors[i]->min_force_limit);
    Fill(row.max_force_limit, motors[i]->max_force_limit);
    Fill(row.max_friction, max_friction[i]);
    Fill(row.geometry.spring, motors[i]->spring);
  }
}

// Jolt's Quat::sEulerAngles: rotation about Z, then Y, then X (q = Rz Ry Rx).
Rotation EulerRotation(double x, double y, double z) {
  return Rotation(Eigen::AngleAxisd(z, Vector::UnitZ()) * Eigen::AngleAxisd(y, Vector::UnitY()) *
                  Eigen::AngleAxisd(x, Vector::UnitX()));
}

void WriteSixDof(const ConstraintPlan& c, const SixDofConstraintSettings& s, const Frames& frames,
                 std::byte* block) {
  auto& lanes = At<SixDofConstraintLanes>(block, c.offset);
  const Vector r1 = frames.Point1(s.position1), r2 = frames.Point2(s.position2);
  Fill(lanes.anchors.r1_local, r1);
  Fill(lanes.anchors.r2_local, r2);
  const Rotation c1 = FrameRotation(frames.Axis1(s.axis_x1), frames.Axis1(s.axis_y1));
  const Rotation c2 = FrameRotation(frames.Axis2(s.axis_x2), frames.Axis2(s.axis_y2));
  Fill(lanes.frames.constraint_to_body1, c1);
  Fill(lanes.frames.constraint_to_body2, c2);
  const SixDofLimits limits = NormalizedSixDofLimits(s);
  const Vector min_translation(limits.min[0], limits.min[1], limits.min[2]);
  Fill(lanes.fixed_anchors.r1_local, Vector(r1 + c1 * min_translation));
  Fill(lanes.fixed_anchors.r2_local, r2);
  Fill(lanes.inv_initial_orientation,
       InverseInitialOrientation(c1 * EulerRotation(limits.min[3], limits.min[4], limits.min[5]),
                                 c2));
  WriteAxisLimit(lanes.rotation_limits.twist, c.swing_twist.twist, limits.min[3],
                 limits.max[3]);
  WriteAxisLimit(lanes.rotation_limits.swing_y, c.swing_twist.swing_y, limits.min[4],
                 limits.max[4]);
  WriteAxisLimit(lanes.rotation_limits.swing_z, c.swing_twist.swing_z, limits.min[5],
                 limits.max[5]);
  for (std::size_t i = 0; i < 3; ++i) {
    if (c.six_dof.translation_rows) {
      WriteLimit((&At<LinearLimitLanes>(block, c.limit_offset))[i], limits.min[i], limits.max[i],
                 s.limits_spring[i]);
    }
    if (c.has_motor()) {
      WriteMotor((&At<LinearMotorLanes>(block, c.motor_offset))[i], s.motor[i],
                 s.target_velocity[i], s.target_position[i], s.max_friction[i]);
    }
  }
  WriteRotationDrives(c, block, {&s.motor[3], &s.motor[4], &s.motor[5]},
                      {s.max_friction[3], s.max_friction[4], s.max_friction[5]},
                      s.target_angular_velocity, s.target_orientation);
}

// The path constraint: path space in body 1's COM space, and the attachment
// frame (X = tangent, Y = binormal, Z = normal at the starting fraction,
// evaluated by the batch's own path kernels, in float as Jolt) in body 2's.
void WritePath(const ConstraintPlan& c, const PathConstraintSettings& s, const Frames& frames,
               std::byte* block) {
  auto& lanes = At<PathConstraintLanes>(block, c.offset);
  const Pose& b1 = frames.body1();
  const Pose& b2 = frames.body2();
  Rotation path_rotation = ToRotation(s.path_rotation).normalized();
  Vector path_position = ToVector(s.path_position);
  if (frames.world_space()) {
    path_rotation = (b1.rotation.conjugate() * path_rotation).normalized();
    path_position = b1.rotation.conjugate() * (path_position - b1.position);
  }
  Fill(lanes.path_to_body1_rotation, path_rotation);
  Fill(lanes.path_to_body1_position, path_position);

  const PathPointFrame start = PathFrameAt(c.Path(), s.path_fraction);
  const Rotation attachment_world = (b1.rotation * path_rotation * start.frame).normalized();
  const Vector attachment_position =
      b1.position + b1.rotation * (path_position + path_rotation * start.position);
  Fill(lanes.attachment_to_body2_rotation, (b2.rotation.conjugate() * attachment_world).normalized());
  Fill(lanes.attachment_to_body2_position,
       Vector(b2.rotation.conjugate() * (attachment_position - b2.position)));
  // Jolt's sGetInvInitialOrientation: q2* q1 at creation (fully constrained).
  Fill(lanes.inv_initial_orientation, (b2.rotation.conjugate() * b1.rotation).normalized());
  if (c.has_motor()) {
    WriteMotor(At<LinearMotorLanes>(block, c.motor_offset), s.motor, s.target_velocity,
               s.target_path_fraction, s.max_friction_force);
  }
}

// Jolt's Vec3::GetNormalizedPerpendicular: (z, 0, -x) / |.| if |x| > |y|,
// else (0, z, -y) / |.|.
Vector NormalizedPerpendicular(const Vector& v) {
  if (std::abs(v.x()) > std::abs(v.y())) {
    return Vector(v.z(), 0.0, -v.x()) / std::sqrt(v.x() * v.x() + v.z() * v.z());
  }
  return Vector(0.0, v.z(), -v.y()) / std::sqrt(v.y() * v.y() + v.z() * v.z());
}

// Jolt's DistanceConstraint: a negative bound means the initial distance
// (both: a rod of that length; min only: min(initial, max); max only:
// max(initial, min)).
std::pair<float, float> ResolveDistanceLimits(const DistanceConstraintSettings& s,
                                              float initial) {
  if (s.min_distance < 0.0f && s.max_distance < 0.0f) return {initial, initial};
  if (s.min_distance < 0.0f) return {std::min(initial, s.max_distance), s.max_distance};
  if (s.max_distance < 0.0f) return {s.min_distance, std::max(initial, s.min_distance)};
  return {s.min_distance, s.max_distance};
}

void WriteConstraint(const ConstraintPlan& c, const ConstraintSettings& settings,
                     const Frames& frames, std::byte* block) {
  std::visit(
      [&](const auto& s) {
        using S = std::decay_t<decltype(s)>;
        if constexpr (std::is_same_v<S, PointConstraintSettings>) {
          auto& lanes = At<PointConstraintLanes>(block, c.offset);
          Fill(lanes.anchors.r1_local, frames.Point1(s.point1));
          Fill(lanes.anchors.r2_local, frames.Point2(s.point2));
        } else if constexpr (std::is_same_v<S, FixedConstraintSettings>) {
          auto& lanes = At<FixedConstraintLanes>(block, c.offset);
          Fill(lanes.anchors.r1_local,
               s.auto_detect_point ? frames.AutoPoint1() : frames.Point1(s.point1));
          Fill(lanes.anchors.r2_local,
               s.auto_detect_point ? frames.AutoPoint2() : frames.Point2(s.point2));
          Fill(lanes.inv_initial_orientation,
               InverseInitialOrientation(
                   FrameRotation(frames.Axis1(s.axis_x1), frames.Axis1(s.axis_y1)),
                   FrameRotation(frames.Axis2(s.axis_x2), frames.Axis2(s.axis_y2))));
        } else if constexpr (std::is_same_v<S, HingeConstraintSettings>) {
          auto& lanes = At<HingeConstraintLanes>(block, c.offset);
          Fill(lanes.anchors.r1_local, frames.Point1(s.point1));
          Fill(lanes.anchors.r2_local, frames.Point2(s.point2));
          const Vector hinge1 = frames.Axis1(s.hinge_axis1);
          const Vector hinge2 = frames.Axis2(s.hinge_axis2);
          Fill(lanes.hinge_axis1_local, hinge1);
          Fill(lanes.hinge_axis2_local, hinge2);
          // Frames (X = normal, Z = hinge): Y = Z x X.
          const Vector normal1 = frames.Axis1(s.normal_axis1);
          const Vector normal2 = frames.Axis2(s.normal_axis2);
          Fill(lanes.inv_initial_orientation,
               InverseInitialOrientation(FrameRotation(normal1, hinge1.cross(normal1)),
                                         FrameRotation(normal2, hinge2.cross(normal2))));
          if (c.has_limits()) {
            WriteLimit(At<AngularLimitLanes>(block, c.limit_offset), s.limits_min,
                       s.limits_max, s.limits_spring);
          }
          if (c.has_motor()) {
            const float target = c.has_limits()
                                     ? std::clamp(s.target_angle, s.limits_min, s.limits_max)
                                     : s.target_angle;
            WriteMotor(At<AngularMotorLanes>(block, c.motor_offset), s.motor,
                       s.target_angular_velocity, target, s.max_friction_torque);
          }
        } else if constexpr (std::is_same_v<S, SliderConstraintSettings>) {
          auto& lanes = At<SliderConstraintLanes>(block, c.offset);
          Fill(lanes.anchors.r1_local,
               s.auto_detect_point ? frames.AutoPoint1() : frames.Point1(s.point1));
          Fill(lanes.anchors.r2_local,
               s.auto_detect_point ? frames.AutoPoint2() : frames.Point2(s.point2));
          const Vector slider1 = frames.Axis1(s.slider_axis1);
          const Vector normal1 = frames.Axis1(s.normal_axis1);
          Fill(lanes.slider_axis1_local, slider1);
          Fill(lanes.normal_axis1_local, normal1);
          Fill(lanes.binormal_axis1_local, slider1.cross(normal1));
          Fill(lanes.inv_initial_orientation,
               InverseInitialOrientation(
                   FrameRotation(slider1, normal1),
                   FrameRotation(frames.Axis2(s.slider_axis2), frames.Axis2(s.normal_axis2))));
          // Bounds at or beyond 2^24 m are "none", FLT_MAX (CheckTranslationLimits).
          const LimitRange limits = CheckTranslationLimits(
              c.label, "limits_min", "limits_max", s.limits_min, s.limits_max, true);
          if (c.has_limits()) {
            WriteLimit(At<LinearLimitLanes>(block, c.limit_offset), limits.min, limits.max,
                       s.limits_spring);
          }
          if (c.has_motor()) {
            const float target = c.has_limits()
                                     ? std::clamp(s.target_position, limits.min, limits.max)
                                     : s.target_position;
            WriteMotor(At<LinearMotorLanes>(block, c.motor_offset), s.motor, s.target_velocity,
                       target, s.max_friction_force);
          }
        } else if constexpr (std::is_same_v<S, DistanceConstraintSettings>) {
          auto& lanes = At<DistanceConstraintLanes>(block, c.offset);
          const Vector r1 = frames.Point1(s.point1), r2 = frames.Point2(s.point2);
          Fill(lanes.anchors.r1_local, r1);
          Fill(lanes.anchors.r2_local, r2);
          Fill(lanes.normal, Vector(0, 1, 0));  // Jolt's initial normal
          const auto [min, max] = ResolveDistanceLimits(
              s, float((frames.World2(r2) - frames.World1(r1)).norm()));
          WriteLimit(At<LinearLimitLanes>(block, c.limit_offset), min, max, s.limits_spring);
        } else if constexpr (std::is_same_v<S, SwingTwistConstraintSettings>) {
          auto& lanes = At<SwingTwistConstraintLanes>(block, c.offset);
          Fill(lanes.anchors.r1_local, frames.Point1(s.point1));
          Fill(lanes.anchors.r2_local, frames.Point2(s.point2));
          // Constraint frame: X = twist, Y = plane x twist, Z = plane.
          const Vector twist1 = frames.Axis1(s.twist_axis1), plane1 = frames.Axis1(s.plane_axis1);
          const Vector twist2 = frames.Axis2(s.twist_axis2), plane2 = frames.Axis2(s.plane_axis2);
          Fill(lanes.frames.constraint_to_body1, FrameRotation(twist1, plane1.cross(twist1)));
          Fill(lanes.frames.constraint_to_body2, FrameRotation(twist2, plane2.cross(twist2)));
          WriteAxisLimit(lanes.limits.twist, c.swing_twist.twist, s.twist_min_angle,
                         s.twist_max_angle);
          WriteAxisLimit(lanes.limits.swing_y, c.swing_twist.swing_y, -s.plane_half_cone_angle,
                         s.plane_half_cone_angle);
          WriteAxisLimit(lanes.limits.swing_z, c.swing_twist.swing_z, -s.normal_half_cone_angle,
                         s.normal_half_cone_angle);
          WriteRotationDrives(c, block, {&s.twist_motor, &s.swing_motor, &s.swing_motor},
                              {s.max_friction_torque, s.max_friction_torque,
                               s.max_friction_torque},
                              s.target_angular_velocity, s.target_orientation);
        } else if constexpr (std::is_same_v<S, SixDofConstraintSettings>) {
          WriteSixDof(c, s, frames, block);
        } else if constexpr (std::is_same_v<S, PathConstraintSettings>) {
          WritePath(c, s, frames, block);
        } else if constexpr (std::is_same_v<S, ConeConstraintSettings>) {
          auto& lanes = At<ConeConstraintLanes>(block, c.offset);
          Fill(lanes.anchors.r1_local, frames.Point1(s.point1));
          Fill(lanes.anchors.r2_local, frames.Point2(s.point2));
          const Vector twist1 = frames.Axis1(s.twist_axis1);
          Fill(lanes.twist_axis1_local, twist1);
          Fill(lanes.twist_axis2_local, frames.Axis2(s.twist_axis2));
          Fill(lanes.cos_half_cone_angle, std::cos(double(s.half_cone_angle)));
          Fill(lanes.geometry.axis, NormalizedPerpendicular(twist1));  // Jolt's initial axis
          Fill(lanes.geometry.min_lambda, 0.0);  // the row only pushes back into the cone
          Fill(lanes.geometry.max_lambda, double(FLT_MAX));
        } else if constexpr (std::is_same_v<S, PulleyConstraintSettings>) {
          auto& lanes = At<PulleyConstraintLanes>(block, c.offset);
          const Vector r1 = frames.Point1(s.body_point1), r2 = frames.Point2(s.body_point2);
          const Vector f1 = ToVector(s.fixed_point1), f2 = ToVector(s.fixed_point2);
          Fill(lanes.anchors.r1_local, r1);
          Fill(lanes.anchors.r2_local, r2);
          Fill(lanes.fixed_point1, f1);
          Fill(lanes.fixed_point2, f2);
          Fill(lanes.geometry.ratio, s.ratio);
          Fill(lanes.geometry.n1, Vector(0, -1, 0));  // Jolt's initial normals
          Fill(lanes.geometry.n2, Vector(0, -1, 0));
          // Jolt: a negative bound takes the initial length.
          const double initial =
              (frames.World1(r1) - f1).norm() + double(s.ratio) * (frames.World2(r2) - f2).norm();
          Fill(lanes.min_length, s.min_length < 0.0f ? float(initial) : s.min_length);
          Fill(lanes.max_length, s.max_length < 0.0f ? float(initial) : s.max_length);
        } else if constexpr (std::is_same_v<S, GearConstraintSettings>) {
          auto& lanes = At<GearConstraintLanes>(block, c.offset);
          Fill(lanes.hinge_axis1_local, frames.Axis1(s.hinge_axis1));
          Fill(lanes.hinge_axis2_local, frames.Axis2(s.hinge_axis2));
          Fill(lanes.geometry.ratio, s.ratio);
        } else {
          auto& lanes = At<RackAndPinionConstraintLanes>(block, c.offset);
          Fill(lanes.hinge_axis1_local, frames.Axis1(s.hinge_axis1));
          Fill(lanes.slider_axis2_local, frames.Axis2(s.slider_axis2));
          Fill(lanes.geometry.ratio, s.ratio);
        }
      },
      settings);
}

}  // namespace

InverseMassProperties InverseMassPropertiesOf(const BodySettings& body, float mass,
                                              const Float3& inertia_diagonal) {
  const bool dynamic = body.motion_type == MotionType::kDynamic;
  const bool translates = dynamic && AllowsTranslation(body.allowed_dofs);
  const bool rotates = dynamic && AllowsRotation(body.allowed_dofs);
  // Divided in double, then rounded once, as the scene always has been.
  const auto inverse = [](bool allowed, float x) {
    return allowed ? static_cast<float>(1.0 / double(x)) : 0.0f;
  };
  return {inverse(translates, mass),
          {inverse(rotates, inertia_diagonal[0]), inverse(rotates, inertia_diagonal[1]),
           inverse(rotates, inertia_diagonal[2])}};
}

void WriteInitialBlock(const Scene& scene, const StepPlan& plan, std::byte* block) {
  WriteBodies(scene, plan, block);
  for (std::size_t i = 0; i < plan.constraints.size(); ++i) {
    const ConstraintPlan& c = plan.constraints[i];
    const Frames frames(PoseOf(scene.bodies()[c.body1]), PoseOf(scene.bodies()[c.body2]),
                        std::visit([](const auto& s) { return s.space; }, scene.constraints()[i]));
    WriteConstraint(c, scene.constraints()[i], frames, block);
  }
  // Contacts start with no manifold and no impulse (zero bytes) and the
  // pair's combined friction and restitution in every world.
  for (const ContactPlan& c : plan.contacts) {
    ContactLanes& lanes = At<ContactLanes>(block, c.offset);
    Fill(lanes.friction, c.friction);
    Fill(lanes.restitution, c.restitution);
  }
}

}  // namespace manyworlds
