// A scene: the bodies and constraints of one world, which a Batch copies into
// N worlds. Settings are modelled on Jolt's BodyCreationSettings and
// constraint settings (spec 3 and 4.3), with Jolt's defaults.
//
// A scene is plain data; nothing is checked until a Batch is built from it,
// which refuses a bad scene with a SceneError naming the body or constraint
// and the field at fault.
#pragma once

#include <array>
#include <cfloat>
#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "manyworlds/motion_type.h"
#include "manyworlds/spring_settings.h"
#include "manyworlds/swing_type.h"

namespace manyworlds {

using Float3 = std::array<float, 3>;
using Quaternion = std::array<float, 4>;  // (x, y, z, w), w the real part

inline constexpr float kPi = 3.14159265358979323846f;

// Jolt's EAllowedDOFs (spec 4.3): which world-axis translations and rotations a
// body may make, as bit flags. A disallowed translation axis is zeroed in every
// linear velocity write and position step; a disallowed rotation axis in the
// rows and columns of the world inverse inertia (so no impulse, torque or
// position correction turns the body about it). No translation at all makes
// the inverse mass 0, no rotation the inverse inertia. A dynamic body must allow
// at least one DOF (Jolt asserts it; a Batch refuses it).
enum class AllowedDofs : std::uint8_t {
  kNone = 0,  // refused for a dynamic body
  kTranslationX = 1,
  kTranslationY = 2,
  kTranslationZ = 4,
  kRotationX = 8,
  kRotationY = 16,
  kRotationZ = 32,
  kAll = 63,
  kPlane2D = kTranslationX | kTranslationY | kRotationZ,  // moves in the XY plane only
};

constexpr AllowedDofs operator|(AllowedDofs a, AllowedDofs b) {
  return static_cast<AllowedDofs>(static_cast<std::uint8_t>(a) | static_cast<std::uint8_t>(b));
}
constexpr AllowedDofs operator&(AllowedDofs a, AllowedDofs b) {
  return static_cast<AllowedDofs>(static_cast<std::uint8_t>(a) & static_cast<std::uint8_t>(b));
}
// Whether any translation (any rotation) axis is allowed: without one the
// body's inverse mass (inverse inertia) is 0.
constexpr bool AllowsTranslation(AllowedDofs dofs) {
  return (dofs & (AllowedDofs::kTranslationX | AllowedDofs::kTranslationY |
                  AllowedDofs::kTranslationZ)) != AllowedDofs::kNone;
}
constexpr bool AllowsRotation(AllowedDofs dofs) {
  return (dofs & (AllowedDofs::kRotationX | AllowedDofs::kRotationY |
                  AllowedDofs::kRotationZ)) != AllowedDofs::kNone;
}

// The shape a body collides with (Jolt's primitive shapes), in the body
// frame: centred at `position` (relative to the centre of mass), turned by
// `rotation`. Contacts are made only between shapes (docs/contacts.md), and
// the same shapes are in every world.
enum class ShapeType : std::uint8_t {
  kNone,     // no collision
  kSphere,   // radius
  kCapsule,  // a segment along the shape's Y axis, +-half_height, swept by radius
  kBox,      // half_extents along the shape's axes, sharp corners
  kPlane,    // the half-space below the shape's XZ plane (outward normal: the
             // shape's +Y); static bodies only, a ground or a wall
};

struct ShapeSettings {
  ShapeType type = ShapeType::kNone;
  float radius = 0.5f;       // m: sphere, capsule
  float half_height = 0.5f;  // m: capsule, half the length of its core segment
  Float3 half_extents{0.5f, 0.5f, 0.5f};  // m: box
  Float3 position{0, 0, 0};               // body frame, relative to the centre of mass
  Quaternion rotation{0, 0, 0, 1};        // shape frame to body frame
  // Jolt's body defaults; a contact uses sqrt(friction1 friction2) and
  // max(restitution1, restitution2).
  float friction = 0.2f;
  float restitution = 0.0f;
  // Which shapes meet: two shapes make contacts when (group1 & mask2) and
  // (group2 & mask1) are non-zero, at least one body is dynamic, and no
  // constraint joins the two bodies (unless collide_with_joined).
  std::uint32_t collision_group = 1;
  std::uint32_t collision_mask = 0xffffffffu;
  bool collide_with_joined = false;
};

struct BodySettings {
  std::string name;  // used in error messages and the printed plan
  MotionType motion_type = MotionType::kDynamic;
  float mass = 1.0f;                  // kg; dynamic bodies only
  Float3 inertia_diagonal{1, 1, 1};   // principal moments (kg m^2), body frame
  Quaternion inertia_rotation{0, 0, 0, 1};  // principal axes in the body frame
  Float3 position{0, 0, 0};           // centre of mass, world
  Quaternion rotation{0, 0, 0, 1};
  Float3 linear_velocity{0, 0, 0};
  Float3 angular_velocity{0, 0, 0};
  float linear_damping = 0.05f;   // 1/s: v *= max(0, 1 - c dt) each step
  float angular_damping = 0.05f;
  float max_linear_velocity = 500.0f;                // m/s
  float max_angular_velocity = 0.25f * kPi * 60.0f;  // rad/s
  float gravity_factor = 1.0f;
  AllowedDofs allowed_dofs = AllowedDofs::kAll;  // world axes; see AllowedDofs
  ShapeSettings shape;  // none by default: the body collides with nothing
};

// How the points and axes of a constraint's settings are given.
enum class ConstraintSpace : std::uint8_t {
  kWorldSpace,      // in world space at the scene's initial poses (Jolt's default)
  kLocalToBodyCOM,  // relative to each body's centre of mass, in body space
};

// Ball joint: body 1's point1 and body 2's point2 coincide (spec 3, Point).
struct PointConstraintSettings {
  std::string name;
  std::size_t body1 = 0, body2 = 0;
  ConstraintSpace space = ConstraintSpace::kWorldSpace;
  Float3 point1{0, 0, 0};
  Float3 point2{0, 0, 0};
};

// Welds two bodies: relative rotation and the anchor fixed. auto_detect_point
// puts the anchor at the inverse-mass-weighted average of the two centres of
// mass (world space only).
struct FixedConstraintSettings {
  std::string name;
  std::size_t body1 = 0, body2 = 0;
  ConstraintSpace space = ConstraintSpace::kWorldSpace;
  bool auto_detect_point = false;
  Float3 point1{0, 0, 0};
  Float3 axis_x1{1, 0, 0};
  Float3 axis_y1{0, 1, 0};
  Float3 point2{0, 0, 0};
  Float3 axis_x2{1, 0, 0};
  Float3 axis_y2{0, 1, 0};
};

// One rotational degree of freedom about the hinge axis, angle measured from
// the normal axes. Limits within [-pi, 0] and [0, pi]; [-pi, pi] means none.
struct HingeConstraintSettings {
  std::string name;
  std::size_t body1 = 0, body2 = 0;
  ConstraintSpace space = ConstraintSpace::kWorldSpace;
  Float3 point1{0, 0, 0};
  Float3 hinge_axis1{0, 1, 0};
  Float3 normal_axis1{1, 0, 0};
  Float3 point2{0, 0, 0};
  Float3 hinge_axis2{0, 1, 0};
  Float3 normal_axis2{1, 0, 0};
  float limits_min = -kPi;
  float limits_max = kPi;
  SpringSettings limits_spring;      // frequency_or_stiffness <= 0: hard limits
  float max_friction_torque = 0.0f;  // N m, when the motor is off
  MotorSettings motor;               // force limits are torque limits here
  MotorState motor_state = MotorState::kOff;
  float target_angular_velocity = 0.0f;  // rad/s, body 2 relative to body 1
  float target_angle = 0.0f;             // rad, clamped into the limits
};

// One translational degree of freedom along the slider axis; rotation fixed.
struct SliderConstraintSettings {
  std::string name;
  std::size_t body1 = 0, body2 = 0;
  ConstraintSpace space = ConstraintSpace::kWorldSpace;
  bool auto_detect_point = false;
  Float3 point1{0, 0, 0};
  Float3 slider_axis1{1, 0, 0};
  Float3 normal_axis1{0, 1, 0};
  Float3 point2{0, 0, 0};
  Float3 slider_axis2{1, 0, 0};
  Float3 normal_axis2{0, 1, 0};
  float limits_min = -FLT_MAX;  // m, <= 0
  float limits_max = FLT_MAX;   // m, >= 0
  SpringSettings limits_spring;
  float max_friction_force = 0.0f;  // N, when the motor is off
  MotorSettings motor;
  MotorState motor_state = MotorState::kOff;
  float target_velocity = 0.0f;  // m/s
  float target_position = 0.0f;  // m, clamped into the limits
};

// Keeps the distance between body 1's point1 and body 2's point2 within
// [min_distance, max_distance]: a rod (min = max), a rope (min = 0) or, with
// a limits spring, a spring (spec 3, Distance). A negative bound means "the
// initial distance": both negative, a rod of the initial length; only min
// negative, min(initial, max); only max negative, max(initial, min).
struct DistanceConstraintSettings {
  std::string name;
  std::size_t body1 = 0, body2 = 0;
  ConstraintSpace space = ConstraintSpace::kWorldSpace;
  Float3 point1{0, 0, 0};
  Float3 point2{0, 0, 0};
  float min_distance = -1.0f;  // m
  float max_distance = -1.0f;  // m
  SpringSettings limits_spring;  // frequency_or_stiffness > 0: soft limits

  // A rigid rod: both bounds negative (the initial distance) or given equal,
  // and no limits spring. Its one row is an equality, which the exact joint
  // solve factors (docs/stepping.md); Batch::SetLimits may change a rod's
  // length per world but keeps it a rod.
  bool rigid() const {
    const bool both_initial = min_distance < 0.0f && max_distance < 0.0f;
    return !limits_spring.HasStiffness() &&
           (both_initial || (min_distance >= 0.0f && min_distance == max_distance));
  }
};

// A rope from body 1's point over fixed_point1 and fixed_point2 (world
// space, fixed) to body 2's point: L = |p1 - f1| + ratio |p2 - f2| stays in
// [min_length, max_length] (spec 3, Pulley). ratio > 1 is a block and tackle
// on body 2's side. A negative length means the initial length.
struct PulleyConstraintSettings {
  std::string name;
  std::size_t body1 = 0, body2 = 0;
  ConstraintSpace space = ConstraintSpace::kWorldSpace;  // of body_point1/2 only
  Float3 body_point1{0, 0, 0};
  Float3 fixed_point1{0, 0, 0};  // world space
  Float3 body_point2{0, 0, 0};
  Float3 fixed_point2{0, 0, 0};  // world space
  float ratio = 1.0f;
  float min_length = 0.0f;   // m
  float max_length = -1.0f;  // m; negative: the initial length
};

// A ball joint whose twist axes may part by at most half_cone_angle (spec 3,
// Cone): body 1's point1 and body 2's point2 coincide, and the angle between
// twist_axis1 (body 1) and twist_axis2 (body 2) stays within [0, half angle].
struct ConeConstraintSettings {
  std::string name;
  std::size_t body1 = 0, body2 = 0;
  ConstraintSpace space = ConstraintSpace::kWorldSpace;
  Float3 point1{0, 0, 0};
  Float3 twist_axis1{1, 0, 0};
  Float3 point2{0, 0, 0};
  Float3 twist_axis2{1, 0, 0};
  float half_cone_angle = 0.0f;  // rad, in [0, pi]
};

// A ragdoll joint (spec 3, SwingTwist): body 1's point1 and body 2's point2
// coincide, and body 2's frame may turn relative to body 1's within a swing
// cone (or pyramid) and a twist range. Frames: X = twist axis, Z = plane
// axis, Y = Z x X ("normal"); swing about Y is limited by
// plane_half_cone_angle, about Z by normal_half_cone_angle, twist about X by
// [twist_min_angle, twist_max_angle]. An axis is locked when its range is
// within +-0.5 deg and free beyond +-179.5 deg (Jolt's rule).
//
// Motors act about the axes of body 2's constraint frame: the twist motor
// about X, the swing motor about Y and Z together. A velocity motor drives
// the relative angular velocity (body 2 - body 1) about those axes to
// target_angular_velocity (components along X, Y, Z of body 2's frame); a
// position motor drives body 2's frame towards target_orientation (body 2's
// frame relative to body 1's), which is clamped into the limits first.
// With a motor off and max_friction_torque > 0 that axis has friction.
struct SwingTwistConstraintSettings {
  std::string name;
  std::size_t body1 = 0, body2 = 0;
  ConstraintSpace space = ConstraintSpace::kWorldSpace;
  Float3 point1{0, 0, 0};
  Float3 twist_axis1{1, 0, 0};
  Float3 plane_axis1{0, 1, 0};
  Float3 point2{0, 0, 0};
  Float3 twist_axis2{1, 0, 0};
  Float3 plane_axis2{0, 1, 0};
  SwingType swing_type = SwingType::kCone;
  float normal_half_cone_angle = 0.0f;  // rad, [0, pi]
  float plane_half_cone_angle = 0.0f;   // rad, [0, pi]
  float twist_min_angle = 0.0f;         // rad, [-pi, pi]
  float twist_max_angle = 0.0f;         // rad, [-pi, pi]
  float max_friction_torque = 0.0f;     // N m, on every axis whose motor is off
  MotorSettings swing_motor;            // force limits are torque limits here
  MotorSettings twist_motor;
  MotorState swing_motor_state = MotorState::kOff;
  MotorState twist_motor_state = MotorState::kOff;
  Float3 target_angular_velocity{0, 0, 0};   // rad/s, about body 2's frame X, Y, Z
  Quaternion target_orientation{0, 0, 0, 1};  // body 2's frame in body 1's
};

// The six degrees of freedom of a six-DOF constraint, in its constraint frame
// (X, Y from the settings' axes, Z = X x Y).
enum class SixDofAxis : std::uint8_t {
  kTranslationX,
  kTranslationY,
  kTranslationZ,
  kRotationX,  // twist
  kRotationY,  // swing
  kRotationZ,  // swing
};
inline constexpr std::size_t kSixDofAxes = 6;

// The most general joint (spec 3, SixDOF): per axis of the constraint frame
// (X = axis_x, Y = axis_y, Z = X x Y, body 1's for translation, body 2's for
// the rotation motors) the axis is
//   fixed    when limit_min >= limit_max (a translation with min > max, or an
//            inverted rotation range, becomes 0 / 0),
//   free     when limit_min <= -L and limit_max >= L (L = FLT_MAX for
//            translation, pi for rotation; rotation limits are clamped into
//            [-pi, pi]),
//   limited  otherwise: the translation d = (p2 - p1) . axis within
//            [min, max]; rotations as a swing-twist joint (X twist, Y and Z
//            swing; a cone uses the symmetric range +-max(0, limit_max)).
// Translation limits may be springs (limits_spring); each axis may have a
// motor (targets in the constraint frame) or friction (max_friction, when its
// motor is off). Jolt's shortcuts: all translations fixed without springs use
// a point part, all rotations fixed a rotation-Euler part (the motors of those
// axes are then not used).
struct SixDofConstraintSettings {
  std::string name;
  std::size_t body1 = 0, body2 = 0;
  ConstraintSpace space = ConstraintSpace::kWorldSpace;
  Float3 position1{0, 0, 0};
  Float3 axis_x1{1, 0, 0};
  Float3 axis_y1{0, 1, 0};
  Float3 position2{0, 0, 0};
  Float3 axis_x2{1, 0, 0};
  Float3 axis_y2{0, 1, 0};
  SwingType swing_type = SwingType::kCone;
  std::array<float, kSixDofAxes> limit_min{-FLT_MAX, -FLT_MAX, -FLT_MAX,
                                           -FLT_MAX, -FLT_MAX, -FLT_MAX};
  std::array<float, kSixDofAxes> limit_max{FLT_MAX, FLT_MAX, FLT_MAX,
                                           FLT_MAX, FLT_MAX, FLT_MAX};
  std::array<SpringSettings, 3> limits_spring{};         // translation axes only
  std::array<float, kSixDofAxes> max_friction{};          // N (translation), N m (rotation)
  std::array<MotorSettings, kSixDofAxes> motor{};
  std::array<MotorState, kSixDofAxes> motor_state{};
  Float3 target_velocity{0, 0, 0};           // m/s, body 1's frame
  Float3 target_angular_velocity{0, 0, 0};   // rad/s, body 2's frame
  Float3 target_position{0, 0, 0};           // m, body 1's frame
  Quaternion target_orientation{0, 0, 0, 1};  // body 2's frame in body 1's, clamped

  void MakeFixedAxis(SixDofAxis axis) {
    limit_min[std::size_t(axis)] = FLT_MAX;
    limit_max[std::size_t(axis)] = -FLT_MAX;
  }
  void MakeFreeAxis(SixDofAxis axis) {
    limit_min[std::size_t(axis)] = -FLT_MAX;
    limit_max[std::size_t(axis)] = FLT_MAX;
  }
  void SetLimitedAxis(SixDofAxis axis, float min, float max) {
    limit_min[std::size_t(axis)] = min;
    limit_max[std::size_t(axis)] = max;
  }
};

// One control point of a path (a cubic Hermite spline through the points, in
// path space): its position, the tangent (the derivative of position by
// fraction, so its length shapes the curve) and the normal, which is
// interpolated linearly between points and made perpendicular to the tangent.
struct PathPoint {
  Float3 position{0, 0, 0};
  Float3 tangent{1, 0, 0};
  Float3 normal{0, 1, 0};
};

// How a path constraint holds body 2's rotation (Jolt's
// EPathRotationConstraintType). Body 2's frame is the path frame at its
// starting fraction: X = tangent, Y = binormal, Z = normal.
enum class PathRotation : std::uint8_t {
  kFree,
  kConstrainAroundTangent,   // turns only about the path tangent (a hinge on it)
  kConstrainAroundNormal,    // only about the path normal
  kConstrainAroundBinormal,  // only about the path binormal
  kConstrainToPath,          // its frame follows the path frame
  kFullyConstrained,         // keeps its rotation relative to body 1
};

// Body 2 slides along a path fixed to body 1 (spec 3, Path): its attachment
// point stays on the curve (two rows across it), stops at the ends of a
// path that does not loop, and its rotation is held as `rotation` says. The
// path is the same in every world. A motor drives the path fraction (the
// segment index plus the spline parameter): velocity in m/s along the
// tangent, position as a fraction (wrapped for looping paths); with the
// motor off, max_friction_force resists sliding.
struct PathConstraintSettings {
  std::string name;
  std::size_t body1 = 0, body2 = 0;
  // Where path space sits: in world space at the scene's initial poses, or
  // relative to body 1's centre of mass in body space.
  ConstraintSpace space = ConstraintSpace::kWorldSpace;
  Float3 path_position{0, 0, 0};
  Quaternion path_rotation{0, 0, 0, 1};
  std::vector<PathPoint> path;  // at least 2 points
  bool looping = false;         // the last point joins the first
  float path_fraction = 0.0f;   // where body 2 is attached at the start
  PathRotation rotation = PathRotation::kFree;
  float max_friction_force = 0.0f;  // N, when the motor is off
  MotorSettings motor;
  MotorState motor_state = MotorState::kOff;
  float target_velocity = 0.0f;       // m/s along the path tangent
  float target_path_fraction = 0.0f;  // for position motors
};

// No constraint index: the gear / rack has no position correction.
inline constexpr std::size_t kNoConstraint = static_cast<std::size_t>(-1);

// Couples the rotations of two hinged bodies: theta1 + ratio theta2 = 0
// (ratio = teeth2 / teeth1). Position correction needs both hinges; it reads
// their unwrapped angles (whole turns counted at every step), so any ratio
// stays coupled over any number of turns, as long as no hinge turns more than
// pi in one substep (Jolt's wrapped angles slip with a non-integer ratio:
// docs/constraint-parts.md, "Unwrapped angles").
struct GearConstraintSettings {
  std::string name;
  std::size_t body1 = 0, body2 = 0;
  ConstraintSpace space = ConstraintSpace::kWorldSpace;
  Float3 hinge_axis1{1, 0, 0};
  Float3 hinge_axis2{1, 0, 0};
  float ratio = 1.0f;
  std::size_t hinge1 = kNoConstraint;  // the hinge constraints of body 1 and 2
  std::size_t hinge2 = kNoConstraint;
};

// Couples a pinion's rotation (body 1) to a rack's translation (body 2):
// theta - ratio d = 0, ratio in rad/m. Position correction needs both helpers
// (theta: the hinge's unwrapped angle, as for the gear).
struct RackAndPinionConstraintSettings {
  std::string name;
  std::size_t body1 = 0, body2 = 0;
  ConstraintSpace space = ConstraintSpace::kWorldSpace;
  Float3 hinge_axis1{1, 0, 0};
  Float3 slider_axis2{1, 0, 0};
  float ratio = 1.0f;
  std::size_t hinge = kNoConstraint;   // the pinion's hinge
  std::size_t slider = kNoConstraint;  // the rack's slider
};

using ConstraintSettings =
    std::variant<PointConstraintSettings, FixedConstraintSettings, HingeConstraintSettings,
                 SliderConstraintSettings, GearConstraintSettings,
                 RackAndPinionConstraintSettings, DistanceConstraintSettings,
                 PulleyConstraintSettings, ConeConstraintSettings,
                 SwingTwistConstraintSettings, SixDofConstraintSettings,
                 PathConstraintSettings>;

// The world every batch copies. Constraints are solved in the order they were
// added (Jolt's order for equal priorities).
class Scene {
 public:
  std::size_t AddBody(BodySettings body) {
    bodies_.push_back(std::move(body));
    return bodies_.size() - 1;
  }
  std::size_t AddConstraint(ConstraintSettings constraint) {
    constraints_.push_back(std::move(constraint));
    return constraints_.size() - 1;
  }

  const std::vector<BodySettings>& bodies() const { return bodies_; }
  const std::vector<ConstraintSettings>& constraints() const { return constraints_; }
  std::vector<BodySettings>& bodies() { return bodies_; }
  std::vector<ConstraintSettings>& constraints() { return constraints_; }

 private:
  std::vector<BodySettings> bodies_;
  std::vector<ConstraintSettings> constraints_;
};

// A name for messages: the constraint's name if given, else "<type> #index".
std::string ConstraintLabel(const Scene& scene, std::size_t index);
std::string BodyLabel(const Scene& scene, std::size_t index);

}  // namespace manyworlds
