// Batch: actions (forces, torques, motor and drive targets), per world or
// for every world at once. One writer, WriteLane, serves every form:
// the per-world setters (WriteActionOfWorld), the every-world ones
// (SetForces(body), SetTargetVelocities, SetTargetOrientations, ...: each a
// StepAction checked once by CheckAction, then written block by block) and
// Step(settings, io), which writes each block's actions in the block's own
// task (batch_fused_io.cc). So every form gives the same bits.
//
// Actions are never refused for their values: a non-finite one is noted
// (NoteInput) and the world is flagged in WorldHealth after the next Step.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <span>
#include <string>
#include <type_traits>

#include "batch/batch_impl.h"
#include "batch/constraint_block.h"
#include "manyworlds/batch.h"
#include "manyworlds/error.h"

namespace manyworlds {

namespace {

const char* SettingName(ActionKind kind) {
  switch (kind) {
    case ActionKind::kForce: return "a force";
    case ActionKind::kTorque: return "a torque";
    case ActionKind::kTargetVelocity: return "a target velocity";
    case ActionKind::kTargetPosition: return "a target position";
    case ActionKind::kTargetOrientation: return "a target orientation";
    case ActionKind::kTargetAngularVelocity: return "a target angular velocity";
    case ActionKind::kTargetTranslation: return "a target translation";
    case ActionKind::kTargetLinearVelocity: return "a target linear velocity";
  }
  return "an action";
}

// Floats per world of an action.
std::size_t ValuesPerWorld(ActionKind kind) {
  switch (kind) {
    case ActionKind::kTargetVelocity:
    case ActionKind::kTargetPosition: return 1;
    case ActionKind::kTargetOrientation: return 4;
    default: return 3;
  }
}

// |q| in double, as the orientation is normalised.
double QuaternionLength(const float* q) {
  return std::sqrt(double(q[0]) * q[0] + double(q[1]) * q[1] + double(q[2]) * q[2] +
                   double(q[3]) * q[3]);
}

}  // namespace

// Where the action's lanes are, and whether the scene has what it drives:
// a dynamic body for forces and torques, a single motor for motor targets,
// rotation or translation drives for drive targets.
Batch::Impl::CheckedAction Batch::Impl::CheckTarget(ActionKind kind, std::size_t index,
                                                    const char* what) const {
  CheckedAction checked{kind, 0, nullptr, nullptr};
  const char* setting = SettingName(kind);
  switch (kind) {
    case ActionKind::kForce:
    case ActionKind::kTorque: {
      CheckBody(index);
      const BodyPlan& body = plan_.bodies[index];
      if (body.motion_offset == kAbsent) {
        throw SceneError(body.label + ": " + setting + " applies to dynamic bodies only");
      }
      checked.offset = body.motion_offset + (kind == ActionKind::kForce
                                                 ? offsetof(BodyMotionLanes, force)
                                                 : offsetof(BodyMotionLanes, torque));
      return checked;
    }
    case ActionKind::kTargetVelocity:
    case ActionKind::kTargetPosition: {
      const ConstraintPlan& c = SingleMotor(index, setting);
      const bool velocity = kind == ActionKind::kTargetVelocity;
      const bool hinge = c.type == ConstraintType::kHinge;
      checked.offset =
          c.motor_offset +
          (velocity ? (hinge ? offsetof(AngularMotorLanes, target_velocity)
                             : offsetof(LinearMotorLanes, target_velocity))
                    : (hinge ? offsetof(AngularMotorLanes, target_position)
                             : offsetof(LinearMotorLanes, target_position)));
      if (!velocity && c.has_limits()) checked.clamp_into_limits = &c;
      return checked;
    }
    case ActionKind::kTargetOrientation:
    case ActionKind::kTargetAngularVelocity:
      checked.offset = WithRotationDrives(index, setting).rotation_drive_offset;
      return checked;
    case ActionKind::kTargetTranslation:
    case ActionKind::kTargetLinearVelocity:
      checked.offset = WithTranslationDrives(index, setting).motor_offset;
      return checked;
  }
  throw std::invalid_argument(std::string(what) + ": kind " + std::to_string(unsigned(kind)) +
                              " is not an ActionKind (accepted 0 to 7)");
}

Batch::Impl::CheckedAction Batch::Impl::CheckAction(const StepAction& action,
                                                    const char* what) const {
  CheckedAction checked = CheckTarget(action.kind, action.index, what);
  CheckSize(action.per_world.size(), world_count_ * ValuesPerWorld(action.kind), what);
  if (action.kind == ActionKind::kTargetOrientation) {
    for (std::size_t w = 0; w < world_count_; ++w) {
      if (QuaternionLength(action.per_world.data() + w * 4) == 0.0) {
        throw SceneError(InWorld(Constraint(action.index).label, w) +
                         ": target orientation is a zero quaternion");
      }
    }
  }
  checked.per_world = action.per_world.data();
  return checked;
}

// Calls fn(std::integral_constant<ActionKind, kind>) for the action's kind,
// so that what depends on the kind is decided once per call, not per world.
template <class Fn>
void WithKind(ActionKind kind, Fn&& fn) {
  using K = ActionKind;
  switch (kind) {
    case K::kForce: return fn(std::integral_constant<K, K::kForce>{});
    case K::kTorque: return fn(std::integral_constant<K, K::kTorque>{});
    case K::kTargetVelocity: return fn(std::integral_constant<K, K::kTargetVelocity>{});
    case K::kTargetPosition: return fn(std::integral_constant<K, K::kTargetPosition>{});
    case K::kTargetOrientation: return fn(std::integral_constant<K, K::kTargetOrientation>{});
    case K::kTargetAngularVelocity:
      return fn(std::integral_constant<K, K::kTargetAngularVelocity>{});
    case K::kTargetTranslation: return fn(std::integral_constant<K, K::kTargetTranslation>{});
    case K::kTargetLinearVelocity:
      return fn(std::integral_constant<K, K::kTargetLinearVelocity>{});
  }
}

// One world's values of an action into its lanes, as every form writes
// them. Position targets are clamped into the world's limits and noted as
// stored (InputsFinite reads the lanes later: an infinite target clamped to
// a finite limit is a finite input); orientations are normalised in double
// and noted as given (a NaN anywhere flags the world).
template <ActionKind kKind>
void Batch::Impl::WriteLane(const CheckedAction& action, std::byte* block, std::size_t world,
                            const float* v) {
  using K = ActionKind;
  const std::size_t l = Lane(world);
  if constexpr (kKind == K::kForce || kKind == K::kTorque) {
    Vec3Lanes& target = At<Vec3Lanes>(block, action.offset);
    target.x[l] = v[0];
    target.y[l] = v[1];
    target.z[l] = v[2];
    NoteInput(world, v[0], v[1], v[2]);
  } else if constexpr (kKind == K::kTargetVelocity || kKind == K::kTargetPosition) {
    const float value = action.clamp_into_limits != nullptr
                            ? ClampedTarget(world, *action.clamp_into_limits, v[0])
                            : v[0];
    At<LaneArray>(block, action.offset)[l] = value;
    NoteInput(world, value);
  } else if constexpr (kKind == K::kTargetOrientation) {
    QuatLanes& target = At<RotationDriveLanes>(block, action.offset).target_orientation;
    const double length = QuaternionLength(v);
    target.x[l] = float(v[0] / length);
    target.y[l] = float(v[1] / length);
    target.z[l] = float(v[2] / length);
    target.w[l] = float(v[3] / length);
    NoteInput(world, v[0], v[1], v[2], v[3]);
  } else if constexpr (kKind == K::kTargetAngularVelocity) {
    RotationDriveLanes& drive = At<RotationDriveLanes>(block, action.offset);
    for (int i = 0; i < 3; ++i) drive.rows[i].target_velocity[l] = v[i];
    NoteInput(world, v[0], v[1], v[2]);
  } else {
    LinearMotorLanes* drives = &At<LinearMotorLanes>(block, action.offset);
    for (int i = 0; i < 3; ++i) {
      (kKind == K::kTargetTranslation ? drives[i].target_position
                                      : drives[i].target_velocity)[l] = v[i];
    }
    NoteInput(world, v[0], v[1], v[2]);
  }
}

// Every step for every world in an RL loop: the kind is dispatched once per
// block, the loop over its worlds is the lane writes alone.
void Batch::Impl::WriteActionOfBlock(std::size_t block, const CheckedAction& action) {
  const std::size_t width = ValuesPerWorld(action.kind);
  std::byte* bytes = Block(block);
  WithKind(action.kind, [&](auto kind) {
    for (auto [world, end] = WorldsOf(block); world < end; ++world) {
      WriteLane<kind.value>(action, bytes, world, action.per_world + world * width);
    }
  });
}

// The per-world setters: the same checks and writer, for one world.
void Batch::Impl::WriteActionOfWorld(ActionKind kind, std::size_t index, std::size_t world,
                                     const float* values) {
  CheckWorld(world);
  const CheckedAction action = CheckTarget(kind, index, SettingName(kind));
  if (kind == ActionKind::kTargetOrientation && QuaternionLength(values) == 0.0) {
    throw SceneError(Constraint(index).label + ": target orientation is a zero quaternion");
  }
  WithKind(kind, [&](auto k) {
    WriteLane<k.value>(action, Block(world / kLaneWidth), world, values);
  });
}

// SetForces / SetTorques of [world][body][3]: static bodies' entries skipped.
void Batch::Impl::WriteEveryBody(ActionKind kind, std::span<const float> values,
                                 const char* call) {
  const Exclusive exclusive(*this, call);
  const std::size_t bodies = plan_.bodies.size();
  CheckSize(values.size(), world_count_ * bodies * 3, call);
  for (std::size_t w = 0; w < world_count_; ++w) {
    for (std::size_t b = 0; b < bodies; ++b) {
      if (plan_.bodies[b].motion_offset == kAbsent) continue;
      WriteActionOfWorld(kind, b, w, values.data() + (w * bodies + b) * 3);
    }
  }
}

// The every-world setters: all checked, then written block by block.
void Batch::Impl::WriteEveryWorld(ActionKind kind, std::size_t index,
                                  std::span<const float> per_world, const char* call) {
  const Exclusive exclusive(*this, call);
  WriteAction(CheckAction({kind, index, per_world}, call));
}

const ConstraintPlan& Batch::Impl::SingleMotor(std::size_t constraint, const char* what) const {
  const ConstraintPlan& c = Constraint(constraint);
  RefuseMultiAxis(c, what);
  if (c.motor_offset == kAbsent) {
    throw SceneError(c.label + ": " + what +
                     " needs a motor or friction in the scene (motor_state / max friction)");
  }
  return c;
}

// Swing-twist and six-DOF drives have one motor per axis; the single-value
// setters of hinges and sliders would not say which.
void Batch::Impl::RefuseMultiAxis(const ConstraintPlan& c, const char* what) {
  if (c.type == ConstraintType::kSwingTwist || c.type == ConstraintType::kSixDof) {
    throw SceneError(c.label + ": " + what + " of a " + ConstraintTypeName(c.type) +
                     " constraint is set per axis (SetTargetOrientation, "
                     "SetTargetAngularVelocity, SetTargetTranslation, "
                     "SetTargetLinearVelocity; other settings in the scene)");
  }
}

const ConstraintPlan& Batch::Impl::WithRotationDrives(std::size_t constraint,
                                                      const char* what) const {
  const ConstraintPlan& c = Constraint(constraint);
  if (!c.has_rotation_drives()) {
    throw SceneError(c.label + ": " + what +
                     " needs rotation motors or friction (a swing-twist or six-DOF "
                     "constraint with a motor state or max friction)");
  }
  return c;
}

const ConstraintPlan& Batch::Impl::WithTranslationDrives(std::size_t constraint,
                                                         const char* what) const {
  const ConstraintPlan& c = Constraint(constraint);
  if (c.type != ConstraintType::kSixDof || !c.has_motor()) {
    throw SceneError(c.label + ": " + what +
                     " needs a six-DOF constraint with translation motors or friction");
  }
  return c;
}

float Batch::Impl::ClampedTarget(std::size_t world, const ConstraintPlan& c,
                                 float position) const {
  if (!c.has_limits()) return position;
  if (c.type == ConstraintType::kHinge) {
    const auto& limit = In<AngularLimitLanes>(world, c.limit_offset);
    return std::clamp(position, limit.min[Lane(world)], limit.max[Lane(world)]);
  }
  const auto& limit = In<LinearLimitLanes>(world, c.limit_offset);
  return std::clamp(position, limit.min[Lane(world)], limit.max[Lane(world)]);
}

// ---- the public API

void Batch::SetForce(std::size_t world, std::size_t body, Float3 force) {
  impl().WriteActionOfWorld(ActionKind::kForce, body, world, force.data());
}

void Batch::SetTorque(std::size_t world, std::size_t body, Float3 torque) {
  impl().WriteActionOfWorld(ActionKind::kTorque, body, world, torque.data());
}

void Batch::SetForces(std::span<const float> forces) {
  impl().WriteEveryBody(ActionKind::kForce, forces, "SetForces");
}

void Batch::SetTorques(std::span<const float> torques) {
  impl().WriteEveryBody(ActionKind::kTorque, torques, "SetTorques");
}

void Batch::SetForces(std::size_t body, std::span<const float> per_world) {
  impl().WriteEveryWorld(ActionKind::kForce, body, per_world, "SetForces(body)");
}

void Batch::SetTorques(std::size_t body, std::span<const float> per_world) {
  impl().WriteEveryWorld(ActionKind::kTorque, body, per_world, "SetTorques(body)");
}

void Batch::SetTargetVelocity(std::size_t world, std::size_t constraint, float velocity) {
  impl().WriteActionOfWorld(ActionKind::kTargetVelocity, constraint, world, &velocity);
}

void Batch::SetTargetPosition(std::size_t world, std::size_t constraint, float position) {
  impl().WriteActionOfWorld(ActionKind::kTargetPosition, constraint, world, &position);
}

void Batch::SetTargetOrientation(std::size_t world, std::size_t constraint,
                                 Quaternion orientation) {
  impl().WriteActionOfWorld(ActionKind::kTargetOrientation, constraint, world,
                            orientation.data());
}

void Batch::SetTargetAngularVelocity(std::size_t world, std::size_t constraint,
                                     Float3 angular_velocity) {
  impl().WriteActionOfWorld(ActionKind::kTargetAngularVelocity, constraint, world,
                            angular_velocity.data());
}

void Batch::SetTargetTranslation(std::size_t world, std::size_t constraint,
                                 Float3 translation) {
  impl().WriteActionOfWorld(ActionKind::kTargetTranslation, constraint, world,
                            translation.data());
}

void Batch::SetTargetLinearVelocity(std::size_t world, std::size_t constraint, Float3 velocity) {
  impl().WriteActionOfWorld(ActionKind::kTargetLinearVelocity, constraint, world,
                            velocity.data());
}

void Batch::SetTargetVelocities(std::size_t constraint, std::span<const float> per_world) {
  impl().WriteEveryWorld(ActionKind::kTargetVelocity, constraint, per_world,
                         "SetTargetVelocities");
}

void Batch::SetTargetPositions(std::size_t constraint, std::span<const float> per_world) {
  impl().WriteEveryWorld(ActionKind::kTargetPosition, constraint, per_world,
                         "SetTargetPositions");
}

void Batch::SetTargetOrientations(std::size_t constraint, std::span<const float> per_world) {
  impl().WriteEveryWorld(ActionKind::kTargetOrientation, constraint, per_world,
                         "SetTargetOrientations");
}

void Batch::SetTargetAngularVelocities(std::size_t constraint,
                                       std::span<const float> per_world) {
  impl().WriteEveryWorld(ActionKind::kTargetAngularVelocity, constraint, per_world,
                         "SetTargetAngularVelocities");
}

void Batch::SetTargetTranslations(std::size_t constraint, std::span<const float> per_world) {
  impl().WriteEveryWorld(ActionKind::kTargetTranslation, constraint, per_world,
                         "SetTargetTranslations");
}

void Batch::SetTargetLinearVelocities(std::size_t constraint, std::span<const float> per_world) {
  impl().WriteEveryWorld(ActionKind::kTargetLinearVelocity, constraint, per_world,
                         "SetTargetLinearVelocities");
}

}  // namespace manyworlds
