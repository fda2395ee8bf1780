// Joint coordinates of a block's worlds, SIMD per Highway target, one world
// per lane, in float: the observations RL loops read every step
// (joint_coordinates.h lists every type's coordinates and their meaning).
//
// The maths, per constraint (b1, b2 its bodies; x, q, v, w a body's centre
// of mass, normalised rotation, linear and angular velocity; R(q) v the
// rotation of v; static bodies read as zero velocity):
//   hinge        diff = q2 r0^-1 q1*, a1 = R(q1) hinge_axis1,
//                theta = 2 atan((xyz(diff) . a1) / w(diff)) (pi where w = 0),
//                unwrapped = reference + 2 pi turns + fold(theta - reference),
//                rate = (w2 - w1) . a1
//   slider       r_i = R(q_i) anchor_i, u = (x2 + r2) - (x1 + r1),
//                s = R(q1) slider_axis1: position u . s, velocity
//                (v2 + w2 x r2 - v1 - w1 x r1) . s + u . (w1 x s)
//   distance     |u|, and u_rate . u / |u| (0 where |u| = 0)
//   pulley       |x1 + r1 - f1| + ratio |x2 + r2 - f2|
//   cone         t_i = R(q_i) twist_axis_i: atan2(|t1 x t2|, t1 . t2)
//   swing-twist  c_i = q_i constraint_to_body_i, q = normalise(c1* c2) with
//                w >= 0, s = sqrt(w^2 + x^2): twist 2 atan2(x, w), swing
//                (w y - x z) / s and (w z + x y) / s about Y and Z as
//                2 atan2(swing, s) (s = 0: swing y, z as they are, 2 atan2
//                against w); rates R(c1)^-1 (w2 - w1)
//   six-DOF      translations R(c1)^-1 u, their rates R(c1)^-1 (u_rate +
//                u x w1) (u . (w1 x a) = a . (u x w1) for each axis a),
//                and the swing-twist rotations and rates above
//   path         the closest point's path fraction: a search over the
//                path's segments, per lane in double (JointCoordinatesOfLane)
//
// The same formulas as the double per-lane read-out (joint_coordinates.cc),
// which stays as the reference the tests compare every target with
// (tests/joint_coordinate_kernels_test.cc). Why SIMD: per world in double, the
// cartpole's two constraints cost about as much as a step of the world
// (docs/python.md, "Overhead of a Python step loop").

#include "batch/joint_coordinates.h"

#include <algorithm>
#include <cstddef>

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "batch/joint_coordinate_kernels.cc"
#include "hwy/foreach_target.h"  // IWYU pragma: keep

#include "batch/constraint_lanes.h"
#include "hwy/highway.h"
#include "kernels/body_access-inl.h"
#include "kernels/lane_math-inl.h"

HWY_BEFORE_NAMESPACE();
namespace manyworlds {
namespace HWY_NAMESPACE {
namespace {

// One chunk of lanes of one body: pose and motion.
struct BodyChunk {
  Vec3 x, v, w;
  Quat q;
};

// A constraint's two bodies in one chunk, with typed access to its lanes.
struct Chunk {
  const StepPlan& plan;
  const std::byte* block;
  const ConstraintPlan& c;
  std::size_t offset;  // first lane of the chunk

  template <class Lanes>
  const Lanes& at(std::size_t byte_offset) const {
    return *reinterpret_cast<const Lanes*>(block + byte_offset);
  }
  BodyChunk Body(std::size_t body) const {
    const BodyLanes& b = at<BodyLanes>(plan.bodies[body].offset);
    const MotionType motion = plan.bodies[body].motion;
    return {LoadVec3(b.position, offset), LinearVelocity(b, motion, offset),
            AngularVelocity(b, motion, offset), Normalize(LoadQuat(b.rotation, offset))};
  }
  Vec3 operator()(const Vec3Lanes& v) const { return LoadVec3(v, offset); }
  Quat operator()(const QuatLanes& q) const { return LoadQuat(q, offset); }
  LaneVec operator()(const LaneArray& a) const { return Load(a, offset); }
};

// u = anchor 2 - anchor 1 and its rate, the two anchors' velocity difference.
struct Separation {
  Vec3 u, rate;
};
Separation AnchorSeparation(const Chunk& k, const BodyChunk& b1, const BodyChunk& b2,
                            const PointGeometry& anchors) {
  const Vec3 r1 = Rotate(b1.q, k(anchors.r1_local)), r2 = Rotate(b2.q, k(anchors.r2_local));
  return {Sub(Add(b2.x, r2), Add(b1.x, r1)),
          Sub(Add(b2.v, Cross(b2.w, r2)), Add(b1.v, Cross(b1.w, r1)))};
}

LaneVec Length(const Vec3& v) { return hn::Sqrt(LengthSquared(v)); }

// Jolt's swing-twist angles of body 2's constraint frame in body 1's, and
// the relative angular velocity in body 1's frame: six values.
void RotationCoordinates(const Quat& frame1, const Quat& frame2, const BodyChunk& b1,
                         const BodyChunk& b2, LaneVec* out) {
  Quat q = Normalize(Mul(Conjugate(frame1), frame2));
  const LaneMask flip = hn::Lt(q.w, Zero());
  q = Select(flip, Quat{hn::Neg(q.x), hn::Neg(q.y), hn::Neg(q.z), hn::Neg(q.w)}, q);
  const LaneVec s = hn::Sqrt(hn::MulAdd(q.w, q.w, hn::Mul(q.x, q.x)));
  const LaneMask regular = hn::Ne(s, Zero());
  const LaneVec inv_s = hn::Div(Splat(1.0f), hn::IfThenElse(regular, s, Splat(1.0f)));
  const LaneVec swing_y = hn::IfThenElse(
      regular, hn::Mul(hn::MulSub(q.w, q.y, hn::Mul(q.x, q.z)), inv_s), q.y);
  const LaneVec swing_z = hn::IfThenElse(
      regular, hn::Mul(hn::MulAdd(q.w, q.z, hn::Mul(q.x, q.y)), inv_s), q.z);
  const LaneVec swing_w = hn::IfThenElse(regular, s, q.w);
  const LaneVec two = Splat(2.0f);
  out[0] = hn::IfThenElseZero(regular, hn::Mul(two, Atan2(q.x, q.w)));
  out[1] = hn::Mul(two, Atan2(swing_y, swing_w));
  out[2] = hn::Mul(two, Atan2(swing_z, swing_w));
  const Vec3 w = InverseRotate(frame1, Sub(b2.w, b1.w));
  out[3] = w.x;
  out[4] = w.y;
  out[5] = w.z;
}

// The coordinates of one chunk; returns how many were written to `values`.
std::size_t CoordinatesOfChunk(const Chunk& k, LaneVec* values) {
  const ConstraintPlan& c = k.c;
  const BodyChunk b1 = k.Body(c.body1), b2 = k.Body(c.body2);
  switch (c.type) {
    case ConstraintType::kHinge: {
      const auto& s = k.at<HingeConstraintLanes>(c.offset);
      const Quat diff = Mul(Mul(b2.q, k(s.inv_initial_orientation)), Conjugate(b1.q));
      const Vec3 a1 = Rotate(b1.q, k(s.hinge_axis1_local));
      const LaneVec along = Dot(Vec3{diff.x, diff.y, diff.z}, a1);
      const LaneVec theta =
          hn::IfThenElse(hn::Eq(diff.w, Zero()), Splat(kPiHigh),
                         hn::Mul(Splat(2.0f), Atan(hn::Div(along, diff.w))));
      values[0] = theta;
      values[1] = UnwrappedAngle(theta, k(s.turn_reference_angle), k(s.turns));
      values[2] = Dot(Sub(b2.w, b1.w), a1);
      return 3;
    }
    case ConstraintType::kSlider: {
      const auto& s = k.at<SliderConstraintLanes>(c.offset);
      const Separation sep = AnchorSeparation(k, b1, b2, s.anchors);
      const Vec3 axis = Rotate(b1.q, k(s.slider_axis1_local));
      values[0] = Dot(sep.u, axis);
      values[1] = hn::Add(Dot(sep.rate, axis), Dot(sep.u, Cross(b1.w, axis)));
      return 2;
    }
    case ConstraintType::kDistance: {
      const auto& s = k.at<DistanceConstraintLanes>(c.offset);
      const Separation sep = AnchorSeparation(k, b1, b2, s.anchors);
      const LaneVec length = Length(sep.u);
      const LaneMask apart = hn::Gt(length, Zero());
      values[0] = length;
      values[1] = hn::IfThenElseZero(
          apart, hn::Div(Dot(sep.rate, sep.u), hn::IfThenElse(apart, length, Splat(1.0f))));
      return 2;
    }
    case ConstraintType::kPulley: {
      const auto& s = k.at<PulleyConstraintLanes>(c.offset);
      const Vec3 p1 = Add(b1.x, Rotate(b1.q, k(s.anchors.r1_local)));
      const Vec3 p2 = Add(b2.x, Rotate(b2.q, k(s.anchors.r2_local)));
      values[0] = hn::MulAdd(k(s.geometry.ratio), Length(Sub(p2, k(s.fixed_point2))),
                             Length(Sub(p1, k(s.fixed_point1))));
      return 1;
    }
    case ConstraintType::kCone: {
      const auto& s = k.at<ConeConstraintLanes>(c.offset);
      const Vec3 t1 = Rotate(b1.q, k(s.twist_axis1_local));
      const Vec3 t2 = Rotate(b2.q, k(s.twist_axis2_local));
      values[0] = Atan2(Length(Cross(t1, t2)), Dot(t1, t2));
      return 1;
    }
    case ConstraintType::kSwingTwist: {
      const auto& s = k.at<SwingTwistConstraintLanes>(c.offset);
      RotationCoordinates(Mul(b1.q, k(s.frames.constraint_to_body1)),
                          Mul(b2.q, k(s.frames.constraint_to_body2)), b1, b2, values);
      return 6;
    }
    case ConstraintType::kSixDof: {
      const auto& s = k.at<SixDofConstraintLanes>(c.offset);
      const Quat frame1 = Mul(b1.q, k(s.frames.constraint_to_body1));
      const Separation sep = AnchorSeparation(k, b1, b2, s.anchors);
      LaneVec rotation[6];
      RotationCoordinates(frame1, Mul(b2.q, k(s.frames.constraint_to_body2)), b1, b2, rotation);
      const Vec3 translation = InverseRotate(frame1, sep.u);
      const Vec3 velocity = InverseRotate(frame1, Add(sep.rate, Cross(sep.u, b1.w)));
      // translations, angles, their rates, angular velocities
      values[0] = translation.x, values[1] = translation.y, values[2] = translation.z;
      values[6] = velocity.x, values[7] = velocity.y, values[8] = velocity.z;
      for (int i = 0; i < 3; ++i) {
        values[3 + i] = rotation[i];
        values[9 + i] = rotation[3 + i];
      }
      return 12;
    }
    case ConstraintType::kPath:  // per lane, by the caller
    case ConstraintType::kPoint:
    case ConstraintType::kFixed:
    case ConstraintType::kGear:
    case ConstraintType::kRackAndPinion: return 0;
  }
  return 0;
}

void ReadBlock(const StepPlan& plan, const std::byte* block, std::size_t constraint,
               std::size_t lanes, std::size_t row_stride, float* out) {
  const ConstraintPlan& c = plan.constraints[constraint];
  if (c.type == ConstraintType::kPath) {
    for (std::size_t lane = 0; lane < lanes; ++lane) {
      JointCoordinatesOfLane(plan, block, lane, constraint, out + lane * row_stride);
    }
    return;
  }
  const LaneTag d;
  const std::size_t chunk_lanes = hn::Lanes(d);
  HWY_ALIGN float column[kLaneWidth];
  ForEachChunk([&](std::size_t offset) {
    if (offset >= lanes) return;  // padding worlds only
    LaneVec values[12];
    const std::size_t count = CoordinatesOfChunk(Chunk{plan, block, c, offset}, values);
    const std::size_t real = std::min(chunk_lanes, lanes - offset);
    for (std::size_t i = 0; i < count; ++i) {
      hn::Store(values[i], d, column);
      for (std::size_t l = 0; l < real; ++l) out[(offset + l) * row_stride + i] = column[l];
    }
  });
}

}  // namespace

const JointCoordinateKernels* GetJointCoordinateKernels() {
  static const JointCoordinateKernels kTable = {MANYWORLDS_THIS_TARGET, &ReadBlock};
  return &kTable;
}

}  // namespace HWY_NAMESPACE
}  // namespace manyworlds
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace manyworlds {
MANYWORLDS_EXPORT_KERNEL_TABLE(JointCoordinateKernels, GetJointCoordinateKernels)
}  // namespace manyworlds
#endif  // HWY_ONCE
