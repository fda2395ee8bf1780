// Batch: actions (forces, torques, motor and drive targets), per world or
// for every world at once. The every-world forms (SetForces(body),
// SetTorques(body), SetTargetVelocities, SetTargetPositions and the drive
// targets' SetTargetOrientations ... SetTargetLinearVelocities) are
// StepActions: checked once (CheckAction), then
// written block by block (WriteActionOfBlock), here over every block and
// by Step(settings, io) in each block's own task (batch_fused_io.cc), so
// the two write the same bits.
//
// Actions are never refused for their values: a non-finite one is noted
// (NoteInput) and the world is flagged in WorldHealth after the next Step.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <span>
#include <string>

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

// Floats per world of a drive target.
std::size_t DriveTargetWidth(ActionKind kind) {
  return kind == ActionKind::kTargetOrientation ? 4 : 3;
}

bool IsZeroQuaternion(const float* q) {
  return std::sqrt(double(q[0]) * q[0] + double(q[1]) * q[1] + double(q[2]) * q[2] +
                   double(q[3]) * q[3]) == 0.0;
}

}  // namespace

Batch::Impl::CheckedAction Batch::Impl::CheckAction(const StepAction& action,
                                                    const char* what) const {
  CheckedAction checked{action.kind, 0, nullptr, action.per_world.data()};
  const char* setting = SettingName(action.kind);
  switch (action.kind) {
    case ActionKind::kForce:
    case ActionKind::kTorque: {
      CheckBody(action.index);
      const BodyPlan& body = plan_.bodies[action.index];
      if (body.motion_offset == kAbsent) {
        throw SceneError(body.label + ": " + setting + " applies to dynamic bodies only");
      }
      CheckSize(action.per_world.size(), world_count_ * 3, what);
      checked.offset = body.motion_offset + (action.kind == ActionKind::kForce
                                                 ? offsetof(BodyMotionLanes, force)
                                                 : offsetof(BodyMotionLanes, torque));
      return checked;
    }
    case ActionKind::kTargetVelocity:
    case ActionKind::kTargetPosition: {
      const ConstraintPlan& c = SingleMotor(action.index, setting);
      CheckSize(action.per_world.size(), world_count_, what);
      const bool velocity = action.kind == ActionKind::kTargetVelocity;
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
    case ActionKind::kTargetAngularVelocity: {
      const ConstraintPlan& c = WithRotationDrives(action.index, setting);
      CheckSize(action.per_world.size(), world_count_ * DriveTargetWidth(action.kind), what);
      if (action.kind == ActionKind::kTargetOrientation) {
        for (std::size_t w = 0; w < world_count_; ++w) {
          if (IsZeroQuaternion(action.per_world.data() + w * 4)) {
            throw SceneError(InWorld(c.label, w) + ": target orientation is a zero quaternion");
          }
        }
      }
      checked.offset = c.rotation_drive_offset;
      return checked;
    }
    case ActionKind::kTargetTranslation:
    case ActionKind::kTargetLinearVelocity: {
      const ConstraintPlan& c = WithTranslationDrives(action.index, setting);
      CheckSize(action.per_world.size(), world_count_ * 3, what);
      checked.offset = c.motor_offset;
      return checked;
    }
  }
  throw std::invalid_argument(std::string(what) + ": kind " +
                              std::to_string(unsigned(action.kind)) +
                              " is not an ActionKind (accepted 0 to 7)");
}

// Orientations normalised in double, as given otherwise; the values given
// are noted (a NaN anywhere flags the world).
void Batch::Impl::WriteDriveTarget(ActionKind kind, std::byte* block, std::size_t offset,
                                   std::size_t world, const float* v) {
  const std::size_t l = Lane(world);
  switch (kind) {
    case ActionKind::kTargetOrientation: {
      QuatLanes& target = At<RotationDriveLanes>(block, offset).target_orientation;
      const double length = std::sqrt(double(v[0]) * v[0] + double(v[1]) * v[1] +
                                      double(v[2]) * v[2] + double(v[3]) * v[3]);
      target.x[l] = float(v[0] / length);
      target.y[l] = float(v[1] / length);
      target.z[l] = float(v[2] / length);
      target.w[l] = float(v[3] / length);
      NoteInput(world, v[0], v[1], v[2], v[3]);
      return;
    }
    case ActionKind::kTargetAngularVelocity: {
      RotationDriveLanes& drive = At<RotationDriveLanes>(block, offset);
      for (int i = 0; i < 3; ++i) drive.rows[i].target_velocity[l] = v[i];
      break;
    }
    case ActionKind::kTargetTranslation:
    case ActionKind::kTargetLinearVelocity: {
      LinearMotorLanes* drives = &At<LinearMotorLanes>(block, offset);
      for (int i = 0; i < 3; ++i) {
        (kind == ActionKind::kTargetTranslation ? drives[i].target_position
                                                : drives[i].target_velocity)[l] = v[i];
      }
      break;
    }
    default: return;
  }
  NoteInput(world, v[0], v[1], v[2]);
}

// The block's lane arrays located once (RL loops write their actions every
// step: at 4096 worlds this is part of the loop's cost over Step).
void Batch::Impl::WriteActionOfBlock(std::size_t block, const CheckedAction& action) {
  const float* per_world = action.per_world;
  if (action.kind == ActionKind::kForce || action.kind == ActionKind::kTorque) {
    Vec3Lanes& v = At<Vec3Lanes>(Block(block), action.offset);
    for (auto [world, end] = WorldsOf(block); world < end; ++world) {
      const std::size_t l = Lane(world);
      const float* value = per_world + world * 3;
      v.x[l] = value[0];
      v.y[l] = value[1];
      v.z[l] = value[2];
      NoteInput(world, value[0], value[1], value[2]);
    }
    return;
  }
  if (action.kind != ActionKind::kTargetVelocity && action.kind != ActionKind::kTargetPosition) {
    const std::size_t width = DriveTargetWidth(action.kind);
    for (auto [world, end] = WorldsOf(block); world < end; ++world) {
      WriteDriveTarget(action.kind, Block(block), action.offset, world, per_world + world * width);
    }
    return;
  }
  // The value stored is noted, as InputsFinite reads it later: an infinite
  // position target clamped into finite limits is a finite input.
  LaneArray& target = At<LaneArray>(Block(block), action.offset);
  for (auto [world, end] = WorldsOf(block); world < end; ++world) {
    const float value = action.clamp_into_limits != nullptr
                            ? ClampedTarget(world, *action.clamp_into_limits, per_world[world])
                            : per_world[world];
    target[Lane(world)] = value;
    NoteInput(world, value);
  }
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

RotationDriveLanes& Batch::Impl::RotationDrive(std::size_t world, std::size_t constraint,
                                               const char* what) {
  CheckWorld(world);
  return In<RotationDriveLanes>(world, WithRotationDrives(constraint, what).rotation_drive_offset);
}

LinearMotorLanes* Batch::Impl::TranslationDrives(std::size_t world, std::size_t constraint,
                                                 const char* what) {
  CheckWorld(world);
  return &In<LinearMotorLanes>(world, WithTranslationDrives(constraint, what).motor_offset);
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
  BodyMotionLanes& m = impl().Motion(world, body, "a force");
  const std::size_t l = Impl::Lane(world);
  m.force.x[l] = force[0];
  m.force.y[l] = force[1];
  m.force.z[l] = force[2];
  impl().NoteInput(world, force[0], force[1], force[2]);
}

void Batch::SetTorque(std::size_t world, std::size_t body, Float3 torque) {
  BodyMotionLanes& m = impl().Motion(world, body, "a torque");
  const std::size_t l = Impl::Lane(world);
  m.torque.x[l] = torque[0];
  m.torque.y[l] = torque[1];
  m.torque.z[l] = torque[2];
  impl().NoteInput(world, torque[0], torque[1], torque[2]);
}

void Batch::SetForces(std::span<const float> forces) {
  const Impl::Exclusive exclusive(impl(), "SetForces");
  const std::size_t bodies = body_count();
  impl().CheckSize(forces.size(), world_count() * bodies * 3, "SetForces");
  for (std::size_t w = 0; w < world_count(); ++w) {
    for (std::size_t b = 0; b < bodies; ++b) {
      if (impl().plan_.bodies[b].motion_offset == kAbsent) continue;
      const float* f = forces.data() + (w * bodies + b) * 3;
      SetForce(w, b, {f[0], f[1], f[2]});
    }
  }
}

void Batch::SetTorques(std::span<const float> torques) {
  const Impl::Exclusive exclusive(impl(), "SetTorques");
  const std::size_t bodies = body_count();
  impl().CheckSize(torques.size(), world_count() * bodies * 3, "SetTorques");
  for (std::size_t w = 0; w < world_count(); ++w) {
    for (std::size_t b = 0; b < bodies; ++b) {
      if (impl().plan_.bodies[b].motion_offset == kAbsent) continue;
      const float* t = torques.data() + (w * bodies + b) * 3;
      SetTorque(w, b, {t[0], t[1], t[2]});
    }
  }
}

void Batch::SetForces(std::size_t body, std::span<const float> per_world) {
  const Impl::Exclusive exclusive(impl(), "SetForces");
  impl().WriteAction(
      impl().CheckAction({ActionKind::kForce, body, per_world}, "SetForces(body)"));
}

void Batch::SetTorques(std::size_t body, std::span<const float> per_world) {
  const Impl::Exclusive exclusive(impl(), "SetTorques");
  impl().WriteAction(
      impl().CheckAction({ActionKind::kTorque, body, per_world}, "SetTorques(body)"));
}

void Batch::SetTargetVelocity(std::size_t world, std::size_t constraint, float velocity) {
  impl().WithMotor(world, constraint, "a target velocity",
                   [&](auto& motor, const ConstraintPlan&) {
                     motor.target_velocity[Impl::Lane(world)] = velocity;
                   });
  impl().NoteInput(world, velocity);
}

void Batch::SetTargetPosition(std::size_t world, std::size_t constraint, float position) {
  float stored = position;  // clamped into the limits; NaN stays NaN
  impl().WithMotor(world, constraint, "a target position",
                   [&](auto& motor, const ConstraintPlan& c) {
                     stored = impl().ClampedTarget(world, c, position);
                     motor.target_position[Impl::Lane(world)] = stored;
                   });
  impl().NoteInput(world, stored);
}

// The per-world drive setters: checks, then the writer every form shares.
void Batch::SetTargetOrientation(std::size_t world, std::size_t constraint,
                                 Quaternion orientation) {
  Impl& batch = impl();
  batch.RotationDrive(world, constraint, "a target orientation");  // checks
  if (IsZeroQuaternion(orientation.data())) {
    throw SceneError(batch.Constraint(constraint).label +
                     ": target orientation is a zero quaternion");
  }
  batch.WriteDriveTarget(ActionKind::kTargetOrientation, batch.Block(world / kLaneWidth),
                         batch.Constraint(constraint).rotation_drive_offset, world,
                         orientation.data());
}

void Batch::SetTargetAngularVelocity(std::size_t world, std::size_t constraint,
                                     Float3 angular_velocity) {
  Impl& batch = impl();
  batch.RotationDrive(world, constraint, "a target angular velocity");
  batch.WriteDriveTarget(ActionKind::kTargetAngularVelocity, batch.Block(world / kLaneWidth),
                         batch.Constraint(constraint).rotation_drive_offset, world,
                         angular_velocity.data());
}

void Batch::SetTargetTranslation(std::size_t world, std::size_t constraint,
                                 Float3 translation) {
  Impl& batch = impl();
  batch.TranslationDrives(world, constraint, "a target translation");
  batch.WriteDriveTarget(ActionKind::kTargetTranslation, batch.Block(world / kLaneWidth),
                         batch.Constraint(constraint).motor_offset, world, translation.data());
}

void Batch::SetTargetLinearVelocity(std::size_t world, std::size_t constraint, Float3 velocity) {
  Impl& batch = impl();
  batch.TranslationDrives(world, constraint, "a target linear velocity");
  batch.WriteDriveTarget(ActionKind::kTargetLinearVelocity, batch.Block(world / kLaneWidth),
                         batch.Constraint(constraint).motor_offset, world, velocity.data());
}

void Batch::SetTargetOrientations(std::size_t constraint, std::span<const float> per_world) {
  const Impl::Exclusive exclusive(impl(), "SetTargetOrientations");
  impl().WriteAction(impl().CheckAction(
      {ActionKind::kTargetOrientation, constraint, per_world}, "SetTargetOrientations"));
}

void Batch::SetTargetAngularVelocities(std::size_t constraint,
                                       std::span<const float> per_world) {
  const Impl::Exclusive exclusive(impl(), "SetTargetAngularVelocities");
  impl().WriteAction(impl().CheckAction(
      {ActionKind::kTargetAngularVelocity, constraint, per_world}, "SetTargetAngularVelocities"));
}

void Batch::SetTargetTranslations(std::size_t constraint, std::span<const float> per_world) {
  const Impl::Exclusive exclusive(impl(), "SetTargetTranslations");
  impl().WriteAction(impl().CheckAction(
      {ActionKind::kTargetTranslation, constraint, per_world}, "SetTargetTranslations"));
}

void Batch::SetTargetLinearVelocities(std::size_t constraint, std::span<const float> per_world) {
  const Impl::Exclusive exclusive(impl(), "SetTargetLinearVelocities");
  impl().WriteAction(impl().CheckAction(
      {ActionKind::kTargetLinearVelocity, constraint, per_world}, "SetTargetLinearVelocities"));
}

void Batch::SetTargetVelocities(std::size_t constraint, std::span<const float> per_world) {
  const Impl::Exclusive exclusive(impl(), "SetTargetVelocities");
  impl().WriteAction(impl().CheckAction({ActionKind::kTargetVelocity, constraint, per_world},
                                        "SetTargetVelocities"));
}

void Batch::SetTargetPositions(std::size_t constraint, std::span<const float> per_world) {
  const Impl::Exclusive exclusive(impl(), "SetTargetPositions");
  impl().WriteAction(impl().CheckAction({ActionKind::kTargetPosition, constraint, per_world},
                                        "SetTargetPositions"));
}

}  // namespace manyworlds
