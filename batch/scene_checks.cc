// The checks shared by scenes and per-world setters (see scene_checks.h).

#include "batch/scene_checks.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdio>

#include "batch/plan.h"  // DriveKind
#include "manyworlds/batch.h"  // kMaxHealthyCoordinate
#include "manyworlds/error.h"
#include "manyworlds/lanes.h"  // kPi

namespace manyworlds {

void Refuse(const std::string& what, const std::string& field, const std::string& problem) {
  throw SceneError(what + ": " + field + " " + problem);
}

std::string ValueText(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.9g", x);
  return text;
}

bool Finite(float x) { return std::isfinite(x); }
bool Finite(const Float3& v) { return Finite(v[0]) && Finite(v[1]) && Finite(v[2]); }
bool Finite(const Quaternion& q) {
  return Finite(q[0]) && Finite(q[1]) && Finite(q[2]) && Finite(q[3]);
}
double Length(const Float3& v) {
  return std::sqrt(double(v[0]) * v[0] + double(v[1]) * v[1] + double(v[2]) * v[2]);
}
double Length(const Quaternion& q) {
  return std::sqrt(double(q[0]) * q[0] + double(q[1]) * q[1] + double(q[2]) * q[2] +
                   double(q[3]) * q[3]);
}
Quaternion Normalized(const Quaternion& q) {
  const double length = Length(q);
  return {float(q[0] / length), float(q[1] / length), float(q[2] / length),
          float(q[3] / length)};
}

void CheckFinite(const std::string& what, const std::string& field, float x) {
  if (!Finite(x)) Refuse(what, field, "is not finite (" + ValueText(x) + ")");
}
void CheckFinite(const std::string& what, const std::string& field, const Float3& v) {
  if (!Finite(v)) Refuse(what, field, "has a non-finite component");
}

void CheckAxis(const std::string& what, const std::string& field, const Float3& axis) {
  CheckFinite(what, field, axis);
  if (Length(axis) < 1e-6) Refuse(what, field, "is zero (a direction is needed)");
}

void CheckFrameAxes(const std::string& what, const std::string& first, const Float3& a,
                    const std::string& second, const Float3& b) {
  CheckAxis(what, first, a);
  CheckAxis(what, second, b);
  const double dot = (double(a[0]) * b[0] + double(a[1]) * b[1] + double(a[2]) * b[2]) /
                     (Length(a) * Length(b));
  if (std::abs(dot) > 1e-3) {
    Refuse(what, first + " and " + second,
           "are not perpendicular (cosine " + ValueText(dot) + ")");
  }
}

void CheckOrientation(const std::string& what, const std::string& field, const Quaternion& q) {
  if (!Finite(q)) Refuse(what, field, "has a non-finite component");
  // Eigen normalises a zero quaternion to zero, which would silently give a
  // wrong (not rotated, or zero) frame or inertia.
  if (Length(q) < 1e-6) {
    Refuse(what, field, "is a zero quaternion");
  }
}

namespace {

// An enum value past its last enumerator, named with the accepted range.
template <class Enum>
void CheckEnum(const std::string& what, const std::string& field, Enum value, Enum last,
               const char* type_name) {
  if (static_cast<unsigned>(value) > static_cast<unsigned>(last)) {
    Refuse(what, field,
           "is not a " + std::string(type_name) + " (got " +
               std::to_string(static_cast<unsigned>(value)) + ", accepted 0 to " +
               std::to_string(static_cast<unsigned>(last)) + ")");
  }
}

}  // namespace

void CheckMotionType(const std::string& what, MotionType type) {
  CheckEnum(what, "motion_type", type, MotionType::kDynamic, "MotionType");
}
void CheckMotorState(const std::string& what, const std::string& field, MotorState state) {
  CheckEnum(what, field, state, MotorState::kPositionAndVelocity, "MotorState");
}
void CheckSwingType(const std::string& what, SwingType type) {
  CheckEnum(what, "swing_type", type, SwingType::kPyramid, "SwingType");
}
void CheckConstraintSpace(const std::string& what, ConstraintSpace space) {
  CheckEnum(what, "space", space, ConstraintSpace::kLocalToBodyCOM, "ConstraintSpace");
}

void CheckMassProperties(const std::string& what, float mass, const Float3& inertia_diagonal) {
  if (!Finite(mass) || mass <= 0.0f) {
    Refuse(what, "mass", "must be finite and positive for a dynamic body (got " +
                             ValueText(mass) + ")");
  }
  for (int i = 0; i < 3; ++i) {
    if (!Finite(inertia_diagonal[i]) || inertia_diagonal[i] <= 0.0f) {
      Refuse(what, "inertia_diagonal[" + std::to_string(i) + "]",
             "must be finite and positive for a dynamic body (got " +
                 ValueText(inertia_diagonal[i]) + ")");
    }
  }
}

void CheckDamping(const std::string& what, float linear, float angular) {
  const auto non_negative = [&](const char* field, float x) {
    if (!Finite(x) || x < 0.0f) {
      Refuse(what, field, "must be finite and >= 0 (got " + ValueText(x) + ")");
    }
  };
  non_negative("linear_damping", linear);
  non_negative("angular_damping", angular);
}

void CheckGravityFactor(const std::string& what, float factor) {
  CheckFinite(what, "gravity_factor", factor);
}

void CheckShape(const BodySettings& body, const std::string& what) {
  const ShapeSettings& shape = body.shape;
  CheckEnum(what, "shape.type", shape.type, ShapeType::kPlane, "ShapeType");
  if (shape.type == ShapeType::kNone) return;
  const auto size = [&](const char* field, float x) {
    if (!(Finite(x) && x > 0.0f && x <= kMaxShapeSize)) {
      Refuse(what, field, "must be finite, positive and at most " + ValueText(kMaxShapeSize) +
                              " m (got " + ValueText(x) + ")");
    }
  };
  switch (shape.type) {
    case ShapeType::kSphere: size("shape.radius", shape.radius); break;
    case ShapeType::kCapsule:
      size("shape.radius", shape.radius);
      size("shape.half_height", shape.half_height);
      break;
    case ShapeType::kBox:
      size("shape.half_extents[0]", shape.half_extents[0]);
      size("shape.half_extents[1]", shape.half_extents[1]);
      size("shape.half_extents[2]", shape.half_extents[2]);
      break;
    case ShapeType::kPlane:
      if (body.motion_type != MotionType::kStatic) {
        Refuse(what, "shape.type",
               "is a plane, which only a static body may have (the body is " +
                   std::string(MotionTypeName(body.motion_type)) + ")");
      }
      break;
    case ShapeType::kNone: break;
  }
  CheckFinite(what, "shape.position", shape.position);
  CheckOrientation(what, "shape.rotation", shape.rotation);
  if (!(Finite(shape.friction) && shape.friction >= 0.0f)) {
    Refuse(what, "shape.friction", "must be finite and >= 0 (got " + ValueText(shape.friction) + ")");
  }
  if (!(shape.restitution >= 0.0f && shape.restitution <= 1.0f)) {
    Refuse(what, "shape.restitution",
           "must lie in [0, 1] (got " + ValueText(shape.restitution) + ")");
  }
}

void CheckBody(const BodySettings& body, const std::string& what) {
  CheckMotionType(what, body.motion_type);
  CheckShape(body, what);
  CheckFinite(what, "position", body.position);
  CheckFinite(what, "linear_velocity", body.linear_velocity);
  CheckFinite(what, "angular_velocity", body.angular_velocity);
  CheckOrientation(what, "rotation", body.rotation);
  const unsigned dofs = static_cast<unsigned>(body.allowed_dofs);
  if ((dofs & ~static_cast<unsigned>(AllowedDofs::kAll)) != 0) {
    Refuse(what, "allowed_dofs", "has bits outside AllowedDofs::kAll (got " +
                                     std::to_string(dofs) + ")");
  }
  if (body.motion_type != MotionType::kDynamic) return;
  if (dofs == 0) {
    Refuse(what, "allowed_dofs",
           "must allow at least one degree of freedom for a dynamic body (got none; "
           "make the body static instead)");
  }
  CheckMassProperties(what, body.mass, body.inertia_diagonal);
  CheckOrientation(what, "inertia_rotation", body.inertia_rotation);
  CheckDamping(what, body.linear_damping, body.angular_damping);
  const auto positive = [&](const char* field, float x) {
    if (!(x > 0.0f)) Refuse(what, field, "must be positive");
  };
  positive("max_linear_velocity", body.max_linear_velocity);
  positive("max_angular_velocity", body.max_angular_velocity);
  CheckGravityFactor(what, body.gravity_factor);
}

void CheckSpring(const std::string& what, const std::string& field,
                 const SpringSettings& spring) {
  CheckEnum(what, field + ".mode", spring.mode, SpringMode::kMassNormalizedStiffnessAndDamping,
            "SpringMode");
  if (!Finite(spring.frequency_or_stiffness) || !Finite(spring.damping) ||
      spring.damping < 0.0f) {
    Refuse(what, field, "must have a finite frequency or stiffness and a finite damping >= 0");
  }
}

void CheckMotorSpring(const std::string& what, const std::string& field, DriveKind drive,
                      const SpringSettings& spring) {
  CheckSpring(what, field, spring);
  if (drive == DriveKind::kPosition && !spring.HasStiffness()) {
    Refuse(what, field, "needs a positive frequency or stiffness for a position motor");
  }
  if (drive == DriveKind::kPositionAndVelocity && !spring.HasStiffnessOrDamping()) {
    Refuse(what, field, "needs stiffness or damping for a position-and-velocity motor");
  }
}

void CheckMotorLimits(const std::string& what, const std::string& field, float min, float max) {
  if (std::isnan(min) || std::isnan(max) || min > max) {
    Refuse(what, field, "must be ordered, min <= max (got " + ValueText(min) + ", " +
                            ValueText(max) + ")");
  }
}

void CheckMaxFriction(const std::string& what, const std::string& field, float max_friction) {
  if (!Finite(max_friction) || max_friction < 0.0f) {
    Refuse(what, field, "must be finite and >= 0 (got " + ValueText(max_friction) + ")");
  }
}

void CheckMotor(const std::string& what, MotorState state, const MotorSettings& motor,
                float max_friction, const std::string& friction_field,
                const std::string& motor_field) {
  // "motor" -> "motor_state", six-DOF's "motor[3]" -> "motor_state[3]".
  std::string state_field = motor_field;
  state_field.insert(std::min(state_field.find('['), state_field.size()), "_state");
  CheckMotorState(what, state_field, state);
  CheckMaxFriction(what, friction_field, max_friction);
  CheckMotorLimits(what, motor_field + ".min_force_limit / max_force_limit",
                   motor.min_force_limit, motor.max_force_limit);
  CheckMotorSpring(what, motor_field + ".spring", DriveOf(state, max_friction), motor.spring);
}

LimitRange CheckHingeLimits(const std::string& what, float min, float max) {
  if (!(min >= -kPi && min <= 0.0f)) {
    Refuse(what, "limits_min", "must lie in [-pi, 0] (got " + ValueText(min) + ")");
  }
  if (!(max >= 0.0f && max <= kPi)) {
    Refuse(what, "limits_max", "must lie in [0, pi] (got " + ValueText(max) + ")");
  }
  return {min, max};
}

LimitRange CheckTranslationLimits(const std::string& what, const std::string& min_field,
                                  const std::string& max_field, float min, float max,
                                  bool contains_zero) {
  if (std::isnan(min)) Refuse(what, min_field, "is NaN");
  if (std::isnan(max)) Refuse(what, max_field, "is NaN");
  if (contains_zero && min > 0.0f) {
    Refuse(what, min_field, "must be <= 0 (got " + ValueText(min) + ")");
  }
  if (contains_zero && max < 0.0f) {
    Refuse(what, max_field, "must be >= 0 (got " + ValueText(max) + ")");
  }
  // Six-DOF's "fixed" (min > max, as MakeFixedAxis's FLT_MAX > -FLT_MAX)
  // holds the axis at 0, whatever the two values.
  if (min > max) return {min, max};
  const float far = kMaxHealthyCoordinate;
  const std::string accepted =
      " m: a bound must lie within +-2^24 m, or be -inf / -FLT_MAX (lower) or +inf / "
      "FLT_MAX (upper) for no bound";
  if (min >= far) Refuse(what, min_field, "is " + ValueText(min) + accepted);
  if (max <= -far) Refuse(what, max_field, "is " + ValueText(max) + accepted);
  return {min <= -far ? -FLT_MAX : min, max >= far ? FLT_MAX : max};
}

LimitRange CheckDistanceLimits(const std::string& what, float min, float max) {
  if (!Finite(min) || !Finite(max) || !(min >= 0.0f) || !(min <= max)) {
    Refuse(what, "min_distance / max_distance",
           "must be finite with 0 <= min <= max (got " + ValueText(min) + ", " +
               ValueText(max) + ")");
  }
  return {min, max};
}

}  // namespace manyworlds
