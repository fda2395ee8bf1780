// Joint coordinates and motor forces of one world (see joint_coordinates.h).

#include "batch/joint_coordinates.h"

#include <algorithm>
#include <cmath>

#include "batch/constraint_lanes.h"
#include "batch/lane_readout.h"
#include "batch/path_frame.h"

namespace manyworlds {
namespace {

using namespace readout;

// u = anchor 2 - anchor 1 and its rate d/dt u = v_p2 - v_p1.
struct Separation {
  Vector u, rate;
};

Separation AnchorSeparation(const Pose& b1, const Motion& m1, const Pose& b2, const Motion& m2,
                            const LaneReader& read, const PointGeometry& anchors) {
  const Vector r1 = b1.q * read(anchors.r1_local), r2 = b2.q * read(anchors.r2_local);
  return {(b2.x + r2) - (b1.x + r1), PointVelocity(m2, r2) - PointVelocity(m1, r1)};
}

// Swing-twist angles of body 2's constraint frame in body 1's, and the
// relative angular velocity in body 1's constraint frame: six values.
void RotationCoordinates(const Rotation& frame1, const Rotation& frame2, const Motion& m1,
                         const Motion& m2, double* out) {
  const SwingTwist st = DecomposeSwingTwist((frame1.conjugate() * frame2).normalized());
  out[0] = st.TwistAngle();
  out[1] = st.SwingYAngle();
  out[2] = st.SwingZAngle();
  const Vector w = frame1.conjugate() * (m2.w - m1.w);
  for (int i = 0; i < 3; ++i) out[3 + i] = w[i];
}

}  // namespace

std::size_t JointCoordinateCount(const ConstraintPlan& c) {
  switch (c.type) {
    case ConstraintType::kHinge: return 3;
    case ConstraintType::kSlider:
    case ConstraintType::kDistance: return 2;
    case ConstraintType::kPulley:
    case ConstraintType::kCone:
    case ConstraintType::kPath: return 1;
    case ConstraintType::kSwingTwist: return 6;
    case ConstraintType::kSixDof: return 12;
    case ConstraintType::kPoint:
    case ConstraintType::kFixed:
    case ConstraintType::kGear:
    case ConstraintType::kRackAndPinion: return 0;
  }
  return 0;
}

std::vector<std::string> JointCoordinateNames(const ConstraintPlan& c) {
  switch (c.type) {
    case ConstraintType::kHinge: return {"angle", "unwrapped_angle", "angular_velocity"};
    case ConstraintType::kSlider: return {"position", "velocity"};
    case ConstraintType::kDistance: return {"distance", "velocity"};
    case ConstraintType::kPulley: return {"length"};
    case ConstraintType::kCone: return {"cone_angle"};
    case ConstraintType::kSwingTwist:
      return {"twist", "swing_y", "swing_z",
              "angular_velocity_x", "angular_velocity_y", "angular_velocity_z"};
    case ConstraintType::kSixDof:
      return {"translation_x", "translation_y", "translation_z", "twist", "swing_y",
              "swing_z", "velocity_x", "velocity_y", "velocity_z", "angular_velocity_x",
              "angular_velocity_y", "angular_velocity_z"};
    case ConstraintType::kPath: return {"fraction"};
    case ConstraintType::kPoint:
    case ConstraintType::kFixed:
    case ConstraintType::kGear:
    case ConstraintType::kRackAndPinion: return {};
  }
  return {};
}

namespace {

// The coordinates of constraint c from its bodies' poses and motions.
void CoordinatesOf(const ConstraintPlan& c, const LaneReader& read, const Pose& b1,
                   const Pose& b2, const Motion& m1, const Motion& m2, float* out) {
  const std::size_t count = JointCoordinateCount(c);
  double values[12] = {};
  switch (c.type) {
    case ConstraintType::kHinge: {
      const auto& s = read.at<HingeConstraintLanes>(c.offset);
      Vector a1;
      const double theta = HingeAngle(b1, b2, read, s, &a1);
      values[0] = theta;
      values[1] = UnwrappedHingeAngle(theta, read, s);
      values[2] = (m2.w - m1.w).dot(a1);
      break;
    }
    case ConstraintType::kSlider: {
      const auto& s = read.at<SliderConstraintLanes>(c.offset);
      const Separation sep = AnchorSeparation(b1, m1, b2, m2, read, s.anchors);
      const Vector axis = b1.q * read(s.slider_axis1_local);
      values[0] = sep.u.dot(axis);
      values[1] = sep.rate.dot(axis) + sep.u.dot(m1.w.cross(axis));  // the axis turns with body 1
      break;
    }
    case ConstraintType::kDistance: {
      const auto& s = read.at<DistanceConstraintLanes>(c.offset);
      const Separation sep = AnchorSeparation(b1, m1, b2, m2, read, s.anchors);
      values[0] = sep.u.norm();
      values[1] = values[0] > 0.0 ? sep.rate.dot(sep.u) / values[0] : 0.0;
      break;
    }
    case ConstraintType::kPulley: {
      const auto& s = read.at<PulleyConstraintLanes>(c.offset);
      values[0] = (b1.x + b1.q * read(s.anchors.r1_local) - read(s.fixed_point1)).norm() +
                  read(s.geometry.ratio) *
                      (b2.x + b2.q * read(s.anchors.r2_local) - read(s.fixed_point2)).norm();
      break;
    }
    case ConstraintType::kCone: {
      const auto& s = read.at<ConeConstraintLanes>(c.offset);
      const Vector t1 = b1.q * read(s.twist_axis1_local), t2 = b2.q * read(s.twist_axis2_local);
      values[0] = std::atan2(t1.cross(t2).norm(), t1.dot(t2));
      break;
    }
    case ConstraintType::kSwingTwist: {
      const auto& s = read.at<SwingTwistConstraintLanes>(c.offset);
      RotationCoordinates(b1.q * read(s.frames.constraint_to_body1),
                          b2.q * read(s.frames.constraint_to_body2), m1, m2, values);
      break;
    }
    case ConstraintType::kSixDof: {
      const auto& s = read.at<SixDofConstraintLanes>(c.offset);
      const Rotation frame1 = b1.q * read(s.frames.constraint_to_body1);
      const Separation sep = AnchorSeparation(b1, m1, b2, m2, read, s.anchors);
      double rotation[6];
      RotationCoordinates(frame1, b2.q * read(s.frames.constraint_to_body2), m1, m2, rotation);
      for (int i = 0; i < 3; ++i) {
        const Vector axis = frame1 * Vector::Unit(i);
        values[i] = sep.u.dot(axis);
        values[3 + i] = rotation[i];
        values[6 + i] = sep.rate.dot(axis) + sep.u.dot(m1.w.cross(axis));
        values[9 + i] = rotation[3 + i];
      }
      break;
    }
    case ConstraintType::kPath: {
      const auto& s = read.at<PathConstraintLanes>(c.offset);
      const Rotation path_to_world = b1.q * read(s.path_to_body1_rotation);
      const Vector origin = b1.x + b1.q * read(s.path_to_body1_position);
      const Vector attachment = b2.x + b2.q * read(s.attachment_to_body2_position);
      values[0] = ClosestPathFrame(c.Path(), Vector(path_to_world.conjugate() *
                                                    (attachment - origin)))
                      .fraction;
      break;
    }
    case ConstraintType::kPoint:
    case ConstraintType::kFixed:
    case ConstraintType::kGear:
    case ConstraintType::kRackAndPinion: break;
  }
  for (std::size_t i = 0; i < count; ++i) out[i] = static_cast<float>(values[i]);
}

}  // namespace

void JointCoordinatesOfLane(const StepPlan& plan, const std::byte* block, std::size_t lane,
                            std::size_t constraint, float* out) {
  const LaneReader read{block, lane};
  const ConstraintPlan& c = plan.constraints[constraint];
  if (JointCoordinateCount(c) == 0) return;
  CoordinatesOf(c, read, BodyPose(plan, read, c.body1), BodyPose(plan, read, c.body2),
                BodyMotion(plan, read, c.body1), BodyMotion(plan, read, c.body2), out);
}

std::size_t MotorForceCount(const ConstraintPlan& c) {
  switch (c.type) {
    case ConstraintType::kHinge:
    case ConstraintType::kSlider:
    case ConstraintType::kPath: return c.has_motor() ? 1 : 0;
    case ConstraintType::kSwingTwist: return c.has_rotation_drives() ? 3 : 0;
    case ConstraintType::kSixDof:
      return c.has_motor() || c.has_rotation_drives() ? 6 : 0;
    default: return 0;
  }
}

void MotorForcesOfLane(const StepPlan& plan, const std::byte* block, std::size_t lane,
                       std::size_t constraint, float substep_dt, float* out) {
  const LaneReader read{block, lane};
  const ConstraintPlan& c = plan.constraints[constraint];
  const std::size_t count = MotorForceCount(c);
  std::fill(out, out + count, 0.0f);
  if (count == 0 || !(substep_dt > 0.0f)) return;
  const auto force = [&](const LaneArray& total_lambda) {
    return static_cast<float>(read(total_lambda) / substep_dt);
  };
  // The hinge's motor is an angle row, the slider's and path's axis rows:
  // both keep the accumulated impulse in part.persistent.total_lambda.
  if (c.type == ConstraintType::kHinge) {
    out[0] = force(read.at<AngularMotorLanes>(c.motor_offset).part.persistent.total_lambda);
    return;
  }
  if (c.type == ConstraintType::kSlider || c.type == ConstraintType::kPath) {
    out[0] = force(read.at<LinearMotorLanes>(c.motor_offset).part.persistent.total_lambda);
    return;
  }
  std::size_t first_rotation = 0;
  if (c.type == ConstraintType::kSixDof) {
    first_rotation = 3;
    if (c.has_motor()) {
      const auto* drives = &read.at<LinearMotorLanes>(c.motor_offset);
      for (std::size_t i = 0; i < 3; ++i) {
        if (c.six_dof.translation_drives[i] != DriveKind::kNone) {
          out[i] = force(drives[i].part.persistent.total_lambda);
        }
      }
    }
  }
  if (c.has_rotation_drives()) {
    const auto& drives = read.at<RotationDriveLanes>(c.rotation_drive_offset);
    for (std::size_t i = 0; i < 3; ++i) {
      if (c.rotation_drives[i] != DriveKind::kNone) {
        out[first_rotation + i] = force(drives.rows[i].part.persistent.total_lambda);
      }
    }
  }
}

}  // namespace manyworlds
