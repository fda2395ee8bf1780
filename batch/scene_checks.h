// The checks of every setting a scene or a world can be given, shared by the
// scene's plan (CompilePlan) and the Batch's per-world setters: a value the
// scene refuses is refused for one world too, with the same words, before
// anything is written. Each check raises SceneError "<what>: <field> <problem>",
// where `what` names the body or constraint (and the world, for a setter).
#pragma once

#include <cstddef>
#include <string>

#include "manyworlds/scene.h"
#include "manyworlds/spring_settings.h"

namespace manyworlds {

enum class DriveKind : std::uint8_t;  // batch/plan.h

[[noreturn]] void Refuse(const std::string& what, const std::string& field,
                         const std::string& problem);
// A value as a refusal shows it: every digit a float has ("1e-45", "inf"),
// where std::to_string would print 0.000000.
std::string ValueText(double x);

bool Finite(float x);
bool Finite(const Float3& v);
bool Finite(const Quaternion& q);
double Length(const Float3& v);
double Length(const Quaternion& q);
// q / |q| in double, rounded to float: how every rotation of a scene is used.
Quaternion Normalized(const Quaternion& q);

void CheckFinite(const std::string& what, const std::string& field, float x);
void CheckFinite(const std::string& what, const std::string& field, const Float3& v);
// A direction: finite and not zero (it is normalised when the batch is built).
void CheckAxis(const std::string& what, const std::string& field, const Float3& axis);
// Two axes of one frame: each a direction, and perpendicular (Jolt asserts it).
void CheckFrameAxes(const std::string& what, const std::string& first, const Float3& a,
                    const std::string& second, const Float3& b);
// Finite and not zero (normalised where it is used).
void CheckOrientation(const std::string& what, const std::string& field, const Quaternion& q);

// Enum values outside their enumerators (a cast from a bad integer) would
// otherwise fall through every switch and silently do nothing.
void CheckMotionType(const std::string& what, MotionType type);
void CheckMotorState(const std::string& what, const std::string& field, MotorState state);
void CheckSwingType(const std::string& what, SwingType type);
void CheckConstraintSpace(const std::string& what, ConstraintSpace space);

// ---- bodies
// Shapes are at most this large (m): a plane is unbounded, the others must fit
// well inside the healthy coordinate range.
inline constexpr float kMaxShapeSize = 1.0e4f;
// The contact step settings (distances in m, a speed in m/s) are at most this.
inline constexpr float kMaxContactSetting = 1.0e4f;
void CheckShape(const BodySettings& body, const std::string& what);
void CheckBody(const BodySettings& body, const std::string& what);
void CheckMassProperties(const std::string& what, float mass, const Float3& inertia_diagonal);
void CheckDamping(const std::string& what, float linear, float angular);
void CheckGravityFactor(const std::string& what, float factor);

// ---- springs, motors and friction
// A finite frequency or stiffness, a finite damping >= 0 and a known mode.
void CheckSpring(const std::string& what, const std::string& field, const SpringSettings& spring);
// What a drive needs of its motor spring: a position motor a positive
// frequency or stiffness, a position-and-velocity motor stiffness or damping
// (Jolt would silently switch the drive off without them).
void CheckMotorSpring(const std::string& what, const std::string& field, DriveKind drive,
                      const SpringSettings& spring);
// Ordered force (torque) limits, min <= max, neither NaN.
void CheckMotorLimits(const std::string& what, const std::string& field, float min, float max);
void CheckMaxFriction(const std::string& what, const std::string& field, float max_friction);
void CheckMotor(const std::string& what, MotorState state, const MotorSettings& motor,
                float max_friction, const std::string& friction_field,
                const std::string& motor_field = "motor");

// ---- limits
struct LimitRange {
  float min, max;
};
// A hinge's range: min in [-pi, 0], max in [0, pi].
LimitRange CheckHingeLimits(const std::string& what, float min, float max);
// A translation range (slider, six-DOF translation axes), metres. A bound at
// or beyond kMaxHealthyCoordinate (2^24 m) on its own side, infinity
// included, means "no bound on that side" and is returned as -FLT_MAX or
// FLT_MAX (Jolt's convention), so no kernel ever computes with an infinite
// bound (inf - inf or 0 * inf would turn the world NaN). A bound beyond it on
// the other side (a lower bound of +inf) is refused, as is NaN. min > max
// (six-DOF's "fixed at 0") is returned as given.
// `contains_zero`: the slider's rule that min <= 0 <= max.
LimitRange CheckTranslationLimits(const std::string& what, const std::string& min_field,
                                  const std::string& max_field, float min, float max,
                                  bool contains_zero);
// A distance constraint's range: finite, 0 <= min <= max (one world's values;
// the scene's negative "from the initial distance" is resolved before).
LimitRange CheckDistanceLimits(const std::string& what, float min, float max);

}  // namespace manyworlds
