// Host-side read-outs of one world (lane) of a block, in double: body poses
// and velocities, hinge angles, slider positions and the swing-twist
// decomposition, as the kernels define them. Shared by the accuracy metrics
// (constraint_error.cc) and the joint coordinates (joint_coordinates.cc); not
// on the step's path.
#pragma once

#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <cmath>
#include <cstddef>

#include "batch/constraint_lanes.h"
#include "batch/plan.h"
#include "kernels/body_lanes.h"

namespace manyworlds::readout {

using Vector = Eigen::Vector3d;
using Rotation = Eigen::Quaterniond;
inline constexpr double kTwoPi = 6.283185307179586;

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

inline Pose BodyPose(const StepPlan& plan, const LaneReader& read, std::size_t body) {
  const BodyLanes& b = read.at<BodyLanes>(plan.bodies[body].offset);
  return Pose{read(b.position), read(b.rotation).normalized()};
}

// A body's linear and angular velocity; a static body has none, whatever its
// lanes hold.
struct Motion {
  Vector v, w;
};

inline Motion BodyMotion(const StepPlan& plan, const LaneReader& read, std::size_t body) {
  if (plan.bodies[body].motion == MotionType::kStatic) {
    return Motion{Vector::Zero(), Vector::Zero()};
  }
  const BodyLanes& b = read.at<BodyLanes>(plan.bodies[body].offset);
  return Motion{read(b.linear_velocity), read(b.angular_velocity)};
}

// Velocity of a body's point at world lever arm r (from the centre of mass).
inline Vector PointVelocity(const Motion& m, const Vector& r) { return m.v + m.w.cross(r); }

// An angle folded into (-pi, pi].
inline double Fold(double angle) {
  double x = std::fmod(angle, kTwoPi);
  if (x > M_PI) x -= kTwoPi;
  if (x < -M_PI) x += kTwoPi;
  return x;
}

// Jolt's hinge angle: diff = q2 r0^-1 q1*, theta = 2 atan((xyz(diff) . a1) / w(diff)).
// `axis`, if given, receives a1 (body 1's hinge axis in world space).
inline double HingeAngle(const Pose& b1, const Pose& b2, const LaneReader& read,
                         const HingeConstraintLanes& s, Vector* axis = nullptr) {
  const Rotation diff = b2.q * read(s.inv_initial_orientation) * b1.q.conjugate();
  const Vector a1 = b1.q * read(s.hinge_axis1_local);
  if (axis != nullptr) *axis = a1;
  if (diff.w() == 0.0) return M_PI;
  return 2.0 * std::atan(diff.vec().dot(a1) / diff.w());
}

// The hinge's unwrapped angle for its current angle theta: continued from the
// angle and whole turns counted at its last setup (the step's
// UnwrappedAngle in double; both angles lie in (-pi, pi], so one fold).
inline double UnwrappedHingeAngle(double theta, const LaneReader& read,
                                  const HingeConstraintLanes& s) {
  const double reference = read(s.turn_reference_angle);
  double since_setup = theta - reference;
  if (since_setup > M_PI) since_setup -= kTwoPi;
  if (since_setup < -M_PI) since_setup += kTwoPi;
  return reference + kTwoPi * read(s.turns) + since_setup;
}

// The slider's d = u . s, with u the anchor separation and s body 1's slider axis.
inline double SliderPosition(const Pose& b1, const Pose& b2, const LaneReader& read,
                             const SliderConstraintLanes& s, Vector* separation = nullptr,
                             Vector* axis = nullptr) {
  const Vector u =
      (b2.x + b2.q * read(s.anchors.r2_local)) - (b1.x + b1.q * read(s.anchors.r1_local));
  const Vector slider = b1.q * read(s.slider_axis1_local);
  if (separation != nullptr) *separation = u;
  if (axis != nullptr) *axis = slider;
  return u.dot(slider);
}

// Jolt's swing-twist decomposition of a relative rotation q (body 2's
// constraint frame in body 1's): q = swing * twist, twist about X, the swing
// quaternion (swing_w, 0, swing_y, swing_z); angles in rad.
struct SwingTwist {
  double twist, swing_y, swing_z, swing_w;
  double TwistAngle() const { return twist; }
  double SwingYAngle() const { return 2.0 * std::atan2(swing_y, swing_w); }
  double SwingZAngle() const { return 2.0 * std::atan2(swing_z, swing_w); }
};

inline SwingTwist DecomposeSwingTwist(Rotation q) {
  if (q.w() < 0.0) q.coeffs() = -q.coeffs();
  const double s = std::sqrt(q.w() * q.w() + q.x() * q.x());
  if (s == 0.0) return {0.0, q.y(), q.z(), q.w()};
  return {2.0 * std::atan2(q.x(), q.w()), (q.w() * q.y() - q.x() * q.z()) / s,
          (q.w() * q.z() + q.x() * q.y()) / s, s};
}

}  // namespace manyworlds::readout
