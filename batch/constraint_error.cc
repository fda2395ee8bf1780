// Constraint errors of one world (see constraint_error.h).

#include "batch/constraint_error.h"

#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "batch/constraint_lanes.h"
#include "kernels/body_lanes.h"

namespace manyworlds {
namespace {

using Vector = Eigen::Vector3d;
using Rotation = Eigen::Quaterniond;
constexpr double kTwoPi = 6.283185307179586;

// Read-only view of one lane of a block.
struct LaneReader {
  const std::byte* block;
  std::size_t lane;

  template <class Lanes>
  const Lanes& at(std::size_t offset) const {
    return *reinterpret_cast<const Lanes*>(block + offset);
  }
  double operator()(const LaneArray& a) const { return a[lane]; }
  Vector operator()(const Vec3Lanes& v) const { return Vector(v.x[lane], v.y[lane], v.z[lane]); }
  Rotation operator()(const QuatLanes& q) const {
    return Rotation(q.w[lane], q.x[lane], q.y[lane], q.z[lane]);
  }
};

struct Pose {
  Vector x;
  Rotation q;
};

Pose BodyPose(const StepPlan& plan, const LaneReader& read, std::size_t body) {
  const BodyLanes& b = read.at<BodyLanes>(plan.bodies[body].offset);
  return Pose{read(b.position), read(b.rotation).normalized()};
}

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

double LimitViolation(double value, double min, double max) {
  return std::max({0.0, min - value, value - max});
}

double Fold(double angle) {
  double x = std::fmod(angle, kTwoPi);
  if (x > M_PI) x -= kTwoPi;
  if (x < -M_PI) x += kTwoPi;
  return x;
}

double HingeAngle(const Pose& b1, const Pose& b2, const LaneReader& read,
                  const HingeConstraintLanes& s) {
  const Rotation diff = b2.q * read(s.inv_initial_orientation) * b1.q.conjugate();
  const Vector a1 = b1.q * read(s.hinge_axis1_local);
  if (diff.w() == 0.0) return M_PI;
  return 2.0 * std::atan(diff.vec().dot(a1) / diff.w());
}

double SliderPosition(const Pose& b1, const Pose& b2, const LaneReader& read,
                      const SliderConstraintLanes& s, Vector* separation = nullptr,
                      Vector* axis = nullptr) {
  const Vector u = (b2.x + b2.q * read(s.anchors.r2_local)) - (b1.x + b1.q * read(s.anchors.r1_local));
  const Vector slider = b1.q * read(s.slider_axis1_local);
  if (separation != nullptr) *separation = u;
  if (axis != nullptr) *axis = slider;
  return u.dot(slider);
}

}  // namespace

double ConstraintErrorOfLane(const StepPlan& plan, const std::byte* block, std::size_t lane,
                             std::size_t index) {
  const LaneReader read{block, lane};
  const ConstraintPlan& c = plan.constraints[index];
  const Pose b1 = BodyPose(plan, read, c.body1);
  const Pose b2 = BodyPose(plan, read, c.body2);
  switch (c.type) {
    case ConstraintType::kPoint:
      return AnchorError(b1, b2, read, read.at<PointConstraintLanes>(c.offset).anchors);
    case ConstraintType::kFixed: {
      const auto& s = read.at<FixedConstraintLanes>(c.offset);
      return std::max(AnchorError(b1, b2, read, s.anchors),
                      RestRotationError(b1, b2, read(s.inv_initial_orientation)));
    }
    case ConstraintType::kHinge: {
      const auto& s = read.at<HingeConstraintLanes>(c.offset);
      const Vector a1 = b1.q * read(s.hinge_axis1_local);
      const Vector a2 = b2.q * read(s.hinge_axis2_local);
      double error = std::max(AnchorError(b1, b2, read, s.anchors),
                              std::atan2(a1.cross(a2).norm(), a1.dot(a2)));
      if (c.has_limits()) {
        const auto& limit = read.at<AngularLimitLanes>(c.limit_offset);
        error = std::max(error, LimitViolation(HingeAngle(b1, b2, read, s), read(limit.min),
                                               read(limit.max)));
      }
      return error;
    }
    case ConstraintType::kSlider: {
      const auto& s = read.at<SliderConstraintLanes>(c.offset);
      Vector u, axis;
      const double d = SliderPosition(b1, b2, read, s, &u, &axis);
      double error = std::max((u - d * axis).norm(),
                              RestRotationError(b1, b2, read(s.inv_initial_orientation)));
      if (c.has_limits()) {
        const auto& limit = read.at<LinearLimitLanes>(c.limit_offset);
        error = std::max(error, LimitViolation(d, read(limit.min), read(limit.max)));
      }
      return error;
    }
    case ConstraintType::kGear: {
      if (c.helper1 == kNoConstraint) return 0.0;
      const auto& s = read.at<GearConstraintLanes>(c.offset);
      const ConstraintPlan& h1 = plan.constraints[c.helper1];
      const ConstraintPlan& h2 = plan.constraints[c.helper2];
      const double theta1 = (h1.body2 == c.body1 ? 1.0 : -1.0) *
                            HingeAngle(BodyPose(plan, read, h1.body1), BodyPose(plan, read, h1.body2),
                                       read, read.at<HingeConstraintLanes>(h1.offset));
      const double theta2 = (h2.body2 == c.body2 ? 1.0 : -1.0) *
                            HingeAngle(BodyPose(plan, read, h2.body1), BodyPose(plan, read, h2.body2),
                                       read, read.at<HingeConstraintLanes>(h2.offset));
      return std::abs(Fold(theta1 + read(s.geometry.ratio) * theta2));
    }
    case ConstraintType::kRackAndPinion: {
      if (c.helper1 == kNoConstraint) return 0.0;
      const auto& s = read.at<RackAndPinionConstraintLanes>(c.offset);
      const ConstraintPlan& h = plan.constraints[c.helper1];
      const ConstraintPlan& sl = plan.constraints[c.helper2];
      const double theta = (h.body2 == c.body1 ? 1.0 : -1.0) *
                           HingeAngle(BodyPose(plan, read, h.body1), BodyPose(plan, read, h.body2),
                                      read, read.at<HingeConstraintLanes>(h.offset));
      const double d = (sl.body2 == c.body2 ? 1.0 : -1.0) *
                       SliderPosition(BodyPose(plan, read, sl.body1), BodyPose(plan, read, sl.body2),
                                      read, read.at<SliderConstraintLanes>(sl.offset));
      return std::abs(Fold(theta - read(s.geometry.ratio) * d));
    }
    case ConstraintType::kDistance: {
      const auto& s = read.at<DistanceConstraintLanes>(c.offset);
      const auto& limit = read.at<LinearLimitLanes>(c.limit_offset);
      const double length = ((b2.x + b2.q * read(s.anchors.r2_local)) -
                             (b1.x + b1.q * read(s.anchors.r1_local))).norm();
      return LimitViolation(length, read(limit.min), read(limit.max));
    }
    case ConstraintType::kCone: {
      const auto& s = read.at<ConeConstraintLanes>(c.offset);
      const Vector t1 = b1.q * read(s.twist_axis1_local);
      const Vector t2 = b2.q * read(s.twist_axis2_local);
      const double angle = std::atan2(t1.cross(t2).norm(), t1.dot(t2));
      const double half_cone = std::acos(std::clamp(read(s.cos_half_cone_angle), -1.0, 1.0));
      return std::max(AnchorError(b1, b2, read, s.anchors), std::max(0.0, angle - half_cone));
    }
    case ConstraintType::kPulley: {
      const auto& s = read.at<PulleyConstraintLanes>(c.offset);
      const double length =
          (b1.x + b1.q * read(s.anchors.r1_local) - read(s.fixed_point1)).norm() +
          read(s.geometry.ratio) *
              (b2.x + b2.q * read(s.anchors.r2_local) - read(s.fixed_point2)).norm();
      return LimitViolation(length, read(s.min_length), read(s.max_length));
    }
  }
  return 0.0;
}

float MaxConstraintErrorOfLane(const StepPlan& plan, const std::byte* block, std::size_t lane) {
  double error = 0.0;
  for (std::size_t i = 0; i < plan.constraints.size(); ++i) {
    error = std::max(error, ConstraintErrorOfLane(plan, block, lane, i));
  }
  return static_cast<float>(error);
}

}  // namespace manyworlds
