// Constraint errors of one world (see constraint_error.h).

#include "batch/constraint_error.h"

#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "batch/constraint_lanes.h"
#include "batch/lane_readout.h"
#include "kernels/body_lanes.h"
#include "batch/path_frame.h"

namespace manyworlds {
namespace {

using namespace readout;

// Angle of the rotation q (in [0, pi]).
double RotationAngle(const Rotation& q) {
  return 2.0 * std::atan2(q.vec().norm(), std::abs(q.w()));
}

double AnchorError(const Pose& b1, const Pose& b2, const LaneReader& read,
                   const PointGeometry& anchors) {
  return ((b2.x + b2.q * read(anchors.r2_local)) - (b1.x + b1.q * read(anchors.r1_local))).norm();
}

double RestRotationError(const Pose& b1, const Pose& b2, const Rotation& inv_initial) {
  return RotationAngle(b2.q * inv_initial * b1.q.conjugate());
}

// A helper hinge's unwrapped angle (gear, rack-and-pinion) in this lane.
double UnwrappedAngleOf(const StepPlan& plan, const LaneReader& read, const ConstraintPlan& hinge) {
  const auto& s = read.at<HingeConstraintLanes>(hinge.offset);
  return UnwrappedHingeAngle(
      HingeAngle(BodyPose(plan, read, hinge.body1), BodyPose(plan, read, hinge.body2), read, s),
      read, s);
}

double LimitViolation(double value, double min, double max) {
  return std::max({0.0, min - value, value - max});
}

// How far the relative rotation q of a swing-twist joint (body 2's frame in
// body 1's) lies outside its limits, in rad: twist about X, and swing per axis
// (pyramid, or a locked or free axis) or radially beyond the ellipse (cone).
double SwingTwistViolation(const Rotation& q, const SwingTwistConfig& config,
                           const LaneReader& read,
                           const SwingTwistLimitLanes& limits) {
  const SwingTwist decomposed = DecomposeSwingTwist(q);
  const double twist = decomposed.twist, swing_y = decomposed.swing_y;
  const double swing_z = decomposed.swing_z, swing_w = decomposed.swing_w;
  const auto axis_violation = [&](AxisLimitKind kind, double angle, const AxisLimitLanes& l) {
    if (kind == AxisLimitKind::kFree) return 0.0;
    if (kind == AxisLimitKind::kLocked) return std::abs(angle);
    return LimitViolation(angle, 2.0 * read(l.half_min), 2.0 * read(l.half_max));
  };
  double error = axis_violation(config.twist, Fold(twist), limits.twist);
  const bool cone = config.swing_type == SwingType::kCone &&
                    config.swing_y == AxisLimitKind::kLimited &&
                    config.swing_z == AxisLimitKind::kLimited;
  if (!cone) {
    error = std::max(error, axis_violation(config.swing_y, 2.0 * std::atan2(swing_y, swing_w),
                                           limits.swing_y));
    return std::max(error, axis_violation(config.swing_z, 2.0 * std::atan2(swing_z, swing_w),
                                          limits.swing_z));
  }
  // Cone: the ellipse (y/a)^2 + (z/b)^2 <= 1 with a, b the sines of the half
  // cone angles; outside, the swing angle beyond the ellipse's along (y, z).
  const double a = read(limits.swing_y.sin_half_max), b = read(limits.swing_z.sin_half_max);
  const double radius = std::hypot(swing_y, swing_z);
  if (radius == 0.0 || (swing_y / a) * (swing_y / a) + (swing_z / b) * (swing_z / b) <= 1.0) {
    return error;
  }
  const double cos_phi = swing_y / radius, sin_phi = swing_z / radius;
  const double allowed = 1.0 / std::hypot(cos_phi / a, sin_phi / b);
  return std::max(error, 2.0 * (std::asin(std::min(1.0, radius)) -
                                std::asin(std::min(1.0, allowed))));
}


// |v_p2 - v_p1| at the anchors of a point part.
double AnchorVelocityError(const Pose& b1, const Motion& m1, const Pose& b2, const Motion& m2,
                           const LaneReader& read, const PointGeometry& anchors) {
  return (PointVelocity(m2, b2.q * read(anchors.r2_local)) -
          PointVelocity(m1, b1.q * read(anchors.r1_local)))
      .norm();
}

}  // namespace

ConstraintErrorSplit ConstraintErrorSplitOfLane(const StepPlan& plan, const std::byte* block,
                                               std::size_t lane, std::size_t index) {
  const LaneReader read{block, lane};
  const ConstraintPlan& c = plan.constraints[index];
  const Pose b1 = BodyPose(plan, read, c.body1);
  const Pose b2 = BodyPose(plan, read, c.body2);
  switch (c.type) {
    case ConstraintType::kPoint:
      return {AnchorError(b1, b2, read, read.at<PointConstraintLanes>(c.offset).anchors), 0.0};
    case ConstraintType::kFixed: {
      const auto& s = read.at<FixedConstraintLanes>(c.offset);
      return {AnchorError(b1, b2, read, s.anchors),
              RestRotationError(b1, b2, read(s.inv_initial_orientation))};
    }
    case ConstraintType::kHinge: {
      const auto& s = read.at<HingeConstraintLanes>(c.offset);
      const Vector a1 = b1.q * read(s.hinge_axis1_local);
      const Vector a2 = b2.q * read(s.hinge_axis2_local);
      ConstraintErrorSplit error{AnchorError(b1, b2, read, s.anchors),
                                 std::atan2(a1.cross(a2).norm(), a1.dot(a2))};
      if (c.has_limits()) {
        const auto& limit = read.at<AngularLimitLanes>(c.limit_offset);
        error.angular = std::max(error.angular, LimitViolation(HingeAngle(b1, b2, read, s),
                                                               read(limit.min), read(limit.max)));
      }
      return error;
    }
    case ConstraintType::kSlider: {
      const auto& s = read.at<SliderConstraintLanes>(c.offset);
      Vector u, axis;
      const double d = SliderPosition(b1, b2, read, s, &u, &axis);
      ConstraintErrorSplit error{(u - d * axis).norm(),
                                 RestRotationError(b1, b2, read(s.inv_initial_orientation))};
      if (c.has_limits()) {
        const auto& limit = read.at<LinearLimitLanes>(c.limit_offset);
        error.linear = std::max(error.linear, LimitViolation(d, read(limit.min), read(limit.max)));
      }
      return error;
    }
    case ConstraintType::kGear: {
      if (c.helper1 == kNoConstraint) return {};
      const auto& s = read.at<GearConstraintLanes>(c.offset);
      const ConstraintPlan& h1 = plan.constraints[c.helper1];
      const ConstraintPlan& h2 = plan.constraints[c.helper2];
      // The coupling error of the gears' unwrapped angles, as the position
      // step measures it (docs/constraint-parts.md, "Unwrapped angles").
      const double theta1 = (h1.body2 == c.body1 ? 1.0 : -1.0) * UnwrappedAngleOf(plan, read, h1);
      const double theta2 = (h2.body2 == c.body2 ? 1.0 : -1.0) * UnwrappedAngleOf(plan, read, h2);
      return {0.0, std::abs(theta1 + read(s.geometry.ratio) * theta2)};
    }
    case ConstraintType::kRackAndPinion: {
      if (c.helper1 == kNoConstraint) return {};
      const auto& s = read.at<RackAndPinionConstraintLanes>(c.offset);
      const ConstraintPlan& h = plan.constraints[c.helper1];
      const ConstraintPlan& sl = plan.constraints[c.helper2];
      const double theta = (h.body2 == c.body1 ? 1.0 : -1.0) * UnwrappedAngleOf(plan, read, h);
      const double d = (sl.body2 == c.body2 ? 1.0 : -1.0) *
                       SliderPosition(BodyPose(plan, read, sl.body1), BodyPose(plan, read, sl.body2),
                                      read, read.at<SliderConstraintLanes>(sl.offset));
      // theta - r d: the ratio (rad/m) turns the rack's metres into radians.
      return {0.0, std::abs(theta - read(s.geometry.ratio) * d)};
    }
    case ConstraintType::kDistance: {
      const auto& s = read.at<DistanceConstraintLanes>(c.offset);
      const auto& limit = read.at<LinearLimitLanes>(c.limit_offset);
      const double length = ((b2.x + b2.q * read(s.anchors.r2_local)) -
                             (b1.x + b1.q * read(s.anchors.r1_local))).norm();
      return {LimitViolation(length, read(limit.min), read(limit.max)), 0.0};
    }
    case ConstraintType::kCone: {
      const auto& s = read.at<ConeConstraintLanes>(c.offset);
      const Vector t1 = b1.q * read(s.twist_axis1_local);
      const Vector t2 = b2.q * read(s.twist_axis2_local);
      const double angle = std::atan2(t1.cross(t2).norm(), t1.dot(t2));
      const double half_cone = std::acos(std::clamp(read(s.cos_half_cone_angle), -1.0, 1.0));
      return {AnchorError(b1, b2, read, s.anchors), std::max(0.0, angle - half_cone)};
    }
    case ConstraintType::kSwingTwist: {
      const auto& s = read.at<SwingTwistConstraintLanes>(c.offset);
      const Rotation frame1 = b1.q * read(s.frames.constraint_to_body1);
      const Rotation frame2 = b2.q * read(s.frames.constraint_to_body2);
      return {AnchorError(b1, b2, read, s.anchors),
              SwingTwistViolation((frame1.conjugate() * frame2).normalized(), c.swing_twist,
                                  read, s.limits)};
    }
    case ConstraintType::kSixDof: {
      const auto& s = read.at<SixDofConstraintLanes>(c.offset);
      const Rotation frame1 = b1.q * read(s.frames.constraint_to_body1);
      const Rotation frame2 = b2.q * read(s.frames.constraint_to_body2);
      ConstraintErrorSplit error;
      if (c.six_dof.rotation_euler) {
        error.angular = RestRotationError(b1, b2, read(s.inv_initial_orientation));
      } else if (c.six_dof.rotation_limits) {
        error.angular = SwingTwistViolation((frame1.conjugate() * frame2).normalized(),
                                            c.swing_twist, read, s.rotation_limits);
      }
      if (c.six_dof.translation_point) {
        error.linear = AnchorError(b1, b2, read, s.fixed_anchors);
        return error;
      }
      if (!c.six_dof.translation_rows) return error;
      const Vector u = (b2.x + b2.q * read(s.anchors.r2_local)) -
                       (b1.x + b1.q * read(s.anchors.r1_local));
      const auto* limits = &read.at<LinearLimitLanes>(c.limit_offset);
      for (int i = 0; i < 3; ++i) {
        if (c.six_dof.translation[i] == AxisLimitKind::kFree) continue;
        const double d = u.dot(frame1 * Vector::Unit(i));
        error.linear =
            std::max(error.linear, LimitViolation(d, read(limits[i].min), read(limits[i].max)));
      }
      return error;
    }
    case ConstraintType::kPath: {
      const auto& s = read.at<PathConstraintLanes>(c.offset);
      const Rotation path_to_world = b1.q * read(s.path_to_body1_rotation);
      const Vector origin = b1.x + b1.q * read(s.path_to_body1_position);
      const Vector attachment = b2.x + b2.q * read(s.attachment_to_body2_position);
      const PathPointFrame on_path = ClosestPathFrame(
          c.Path(), Vector(path_to_world.conjugate() * (attachment - origin)));
      // Off the curve: the separation across the tangent, and along it
      // beyond an end of an open path.
      const Vector u = attachment - (origin + path_to_world * on_path.position);
      const Vector t = path_to_world * on_path.tangent;
      const bool at_end = !c.path_looping && (on_path.fraction <= 0.0 ||
                                              on_path.fraction >= c.Path().max_fraction());
      ConstraintErrorSplit error{(u - u.dot(t) * t).norm(), 0.0};
      if (at_end) error.linear = std::max(error.linear, std::abs(u.dot(t)));
      const Rotation frame2 = b2.q * read(s.attachment_to_body2_rotation);
      const Rotation path_frame = path_to_world * on_path.frame;
      switch (c.path_rotation) {
        case PathRotation::kFree: break;
        case PathRotation::kConstrainAroundTangent:
        case PathRotation::kConstrainAroundNormal:
        case PathRotation::kConstrainAroundBinormal: {
          // The kept axis (X tangent, Z normal, Y binormal) of both frames.
          const int axis = c.path_rotation == PathRotation::kConstrainAroundTangent ? 0
                           : c.path_rotation == PathRotation::kConstrainAroundNormal ? 2
                                                                                      : 1;
          const Vector a = path_frame * Vector::Unit(axis), b = frame2 * Vector::Unit(axis);
          error.angular = std::atan2(a.cross(b).norm(), a.dot(b));
          break;
        }
        case PathRotation::kConstrainToPath:
          error.angular = RotationAngle(path_frame.conjugate() * frame2);
          break;
        case PathRotation::kFullyConstrained:
          error.angular = RestRotationError(b1, b2, read(s.inv_initial_orientation));
          break;
      }
      return error;
    }
    case ConstraintType::kPulley: {
      const auto& s = read.at<PulleyConstraintLanes>(c.offset);
      const double length =
          (b1.x + b1.q * read(s.anchors.r1_local) - read(s.fixed_point1)).norm() +
          read(s.geometry.ratio) *
              (b2.x + b2.q * read(s.anchors.r2_local) - read(s.fixed_point2)).norm();
      return {LimitViolation(length, read(s.min_length), read(s.max_length)), 0.0};
    }
  }
  return {};
}

double ConstraintErrorOfLane(const StepPlan& plan, const std::byte* block, std::size_t lane,
                             std::size_t index) {
  const ConstraintErrorSplit error = ConstraintErrorSplitOfLane(plan, block, lane, index);
  return std::max(error.linear, error.angular);
}

double ConstraintVelocityErrorOfLane(const StepPlan& plan, const std::byte* block,
                                     std::size_t lane, std::size_t index) {
  const LaneReader read{block, lane};
  const ConstraintPlan& c = plan.constraints[index];
  const Pose b1 = BodyPose(plan, read, c.body1);
  const Pose b2 = BodyPose(plan, read, c.body2);
  const Motion m1 = BodyMotion(plan, read, c.body1);
  const Motion m2 = BodyMotion(plan, read, c.body2);
  switch (c.type) {
    case ConstraintType::kPoint:
      return AnchorVelocityError(b1, m1, b2, m2, read,
                                 read.at<PointConstraintLanes>(c.offset).anchors);
    case ConstraintType::kFixed:
      return std::max(AnchorVelocityError(b1, m1, b2, m2, read,
                                          read.at<FixedConstraintLanes>(c.offset).anchors),
                      (m2.w - m1.w).norm());
    case ConstraintType::kHinge: {
      const auto& s = read.at<HingeConstraintLanes>(c.offset);
      const Vector a1 = b1.q * read(s.hinge_axis1_local);
      return std::max(AnchorVelocityError(b1, m1, b2, m2, read, s.anchors),
                      (m2.w - m1.w).cross(a1).norm());
    }
    case ConstraintType::kSlider: {
      const auto& s = read.at<SliderConstraintLanes>(c.offset);
      const Vector r1 = b1.q * read(s.anchors.r1_local);
      const Vector r2 = b2.q * read(s.anchors.r2_local);
      const Vector u = (b2.x + r2) - (b1.x + r1);
      const Vector axis = b1.q * read(s.slider_axis1_local);
      // d/dt of u . n for a normal n turning with body 1 (Jolt's dual axis rows).
      const Vector rate = PointVelocity(m2, r2) - PointVelocity(m1, r1 + u);
      return std::max((rate - rate.dot(axis) * axis).norm(), (m2.w - m1.w).norm());
    }
    case ConstraintType::kGear: {
      const auto& s = read.at<GearConstraintLanes>(c.offset);
      const Vector a1 = b1.q * read(s.hinge_axis1_local);
      const Vector a2 = b2.q * read(s.hinge_axis2_local);
      return std::abs(a1.dot(m1.w) + read(s.geometry.ratio) * a2.dot(m2.w));
    }
    case ConstraintType::kRackAndPinion: {
      const auto& s = read.at<RackAndPinionConstraintLanes>(c.offset);
      const Vector a = b1.q * read(s.hinge_axis1_local);
      const Vector b = b2.q * read(s.slider_axis2_local);
      return std::abs(a.dot(m1.w) - read(s.geometry.ratio) * b.dot(m2.v));
    }
    case ConstraintType::kDistance: {
      const auto& s = read.at<DistanceConstraintLanes>(c.offset);
      const auto& limit = read.at<LinearLimitLanes>(c.limit_offset);
      if (read(limit.min) != read(limit.max)) return 0.0;
      const Vector r1 = b1.q * read(s.anchors.r1_local);
      const Vector r2 = b2.q * read(s.anchors.r2_local);
      const Vector separation = (b2.x + r2) - (b1.x + r1);
      const double length = separation.norm();
      if (length == 0.0) return 0.0;  // no direction to measure along
      return std::abs(separation.dot(PointVelocity(m2, r2) - PointVelocity(m1, r1)) / length);
    }
    case ConstraintType::kPulley: {
      const auto& s = read.at<PulleyConstraintLanes>(c.offset);
      if (read(s.min_length) != read(s.max_length)) return 0.0;
      const auto segment_rate = [](const Vector& point, const Vector& fixed,
                                   const Vector& velocity) {
        const Vector segment = point - fixed;
        const double length = segment.norm();
        return length == 0.0 ? 0.0 : segment.dot(velocity) / length;
      };
      const Vector r1 = b1.q * read(s.anchors.r1_local);
      const Vector r2 = b2.q * read(s.anchors.r2_local);
      return std::abs(
          segment_rate(b1.x + r1, read(s.fixed_point1), PointVelocity(m1, r1)) +
          read(s.geometry.ratio) *
              segment_rate(b2.x + r2, read(s.fixed_point2), PointVelocity(m2, r2)));
    }
    case ConstraintType::kCone:
      return AnchorVelocityError(b1, m1, b2, m2, read,
                                 read.at<ConeConstraintLanes>(c.offset).anchors);
    case ConstraintType::kSwingTwist:
      return AnchorVelocityError(b1, m1, b2, m2, read,
                                 read.at<SwingTwistConstraintLanes>(c.offset).anchors);
    case ConstraintType::kSixDof: {
      const auto& s = read.at<SixDofConstraintLanes>(c.offset);
      const double rotation = c.six_dof.rotation_euler ? (m2.w - m1.w).norm() : 0.0;
      if (c.six_dof.translation_point) {
        // The constrained points: body 1's anchor moved by c1 limit_min.
        return std::max(rotation, AnchorVelocityError(b1, m1, b2, m2, read, s.fixed_anchors));
      }
      const Vector r1 = b1.q * read(s.anchors.r1_local);
      const Vector r2 = b2.q * read(s.anchors.r2_local);
      const Vector u = (b2.x + r2) - (b1.x + r1);
      // d/dt of u . a_i for the frame axes a_i turning with body 1 (the
      // slider's rows), over the hard fixed axes only.
      const Vector rate = PointVelocity(m2, r2) - PointVelocity(m1, r1 + u);
      const Rotation frame1 = b1.q * read(s.frames.constraint_to_body1);
      double squared = 0.0;
      for (int i = 0; i < 3; ++i) {
        if (c.six_dof.translation[i] != AxisLimitKind::kLocked || c.six_dof.translation_soft[i]) {
          continue;
        }
        const double along = rate.dot(frame1 * Vector::Unit(i));
        squared += along * along;
      }
      return std::max(rotation, std::sqrt(squared));
    }
    case ConstraintType::kPath: {
      // The rows across the path (Jolt's dual axis, with the path's normal and
      // binormal turning with body 1) and the rotation rows, which ignore the
      // path's curvature as Jolt's do; the motor and end limits are not
      // equalities.
      const auto& s = read.at<PathConstraintLanes>(c.offset);
      const Rotation path_to_world = b1.q * read(s.path_to_body1_rotation);
      const Vector origin = b1.x + b1.q * read(s.path_to_body1_position);
      const Vector r2 = b2.q * read(s.attachment_to_body2_position);
      const PathPointFrame on_path =
          ClosestPathFrame(c.Path(), Vector(path_to_world.conjugate() * (b2.x + r2 - origin)));
      const Vector t = path_to_world * on_path.tangent;
      const Vector rate = PointVelocity(m2, r2) - PointVelocity(m1, b2.x + r2 - b1.x);
      double error = (rate - rate.dot(t) * t).norm();
      const Vector w = m2.w - m1.w;
      const Rotation path_frame = path_to_world * on_path.frame;
      switch (c.path_rotation) {
        case PathRotation::kFree: break;
        case PathRotation::kConstrainAroundTangent:
          error = std::max(error, w.cross(path_frame * Vector::UnitX()).norm());
          break;
        case PathRotation::kConstrainAroundNormal:
          error = std::max(error, w.cross(path_frame * Vector::UnitZ()).norm());
          break;
        case PathRotation::kConstrainAroundBinormal:
          error = std::max(error, w.cross(path_frame * Vector::UnitY()).norm());
          break;
        case PathRotation::kConstrainToPath:
        case PathRotation::kFullyConstrained: error = std::max(error, w.norm()); break;
      }
      return error;
    }
  }
  return 0.0;
}

ConstraintErrorSplit MaxConstraintErrorSplitOfLane(const StepPlan& plan, const std::byte* block,
                                                  std::size_t lane) {
  ConstraintErrorSplit worst;
  for (std::size_t i = 0; i < plan.constraints.size(); ++i) {
    const ConstraintErrorSplit error = ConstraintErrorSplitOfLane(plan, block, lane, i);
    worst.linear = std::max(worst.linear, error.linear);
    worst.angular = std::max(worst.angular, error.angular);
  }
  return worst;
}

float MaxConstraintErrorOfLane(const StepPlan& plan, const std::byte* block, std::size_t lane) {
  const ConstraintErrorSplit worst = MaxConstraintErrorSplitOfLane(plan, block, lane);
  return static_cast<float>(std::max(worst.linear, worst.angular));
}

}  // namespace manyworlds
