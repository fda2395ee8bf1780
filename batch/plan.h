// The plan of a scene: what one step of a block runs and where each piece of
// data lives in the block.
//
// Compiling a scene checks it (SceneError naming the body or constraint and
// the field), converts world-space settings to body space, and decides per
// constraint which parts and features run (limits, motor, friction, springs),
// from the body kinds (static, kinematic, dynamic). Storage is laid out only
// for what is present. The step kernels follow the plan with scene-uniform
// control flow; only per-world decisions are lane masks.
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "batch/contact_plan.h"
#include "batch/exact_plan.h"
#include "kernels/hermite_path.h"  // HermitePathPoint
#include "kernels/swing_twist.h"  // SwingTwistConfig
#include "manyworlds/batch.h"
#include "manyworlds/motion_type.h"
#include "manyworlds/scene.h"
#include "manyworlds/spring_settings.h"

namespace manyworlds {

inline constexpr std::size_t kAbsent = static_cast<std::size_t>(-1);

enum class ConstraintType : std::uint8_t {
  kPoint,
  kFixed,
  kHinge,
  kSlider,
  kGear,
  kRackAndPinion,
  kDistance,
  kPulley,
  kCone,
  kSwingTwist,
  kSixDof,
  kPath,
};
const char* ConstraintTypeName(ConstraintType type);
// The same names from a scene's settings ("hinge", "swing_twist", ...).
const char* SettingsTypeName(const ConstraintSettings& settings);

// How a hinge or slider drives its free axis (from motor state and friction).
enum class DriveKind : std::uint8_t {
  kNone,                 // no motor row at all
  kFriction,             // motor off, max friction > 0: zero-velocity row, clamped
  kVelocity,             // bias -target velocity, clamped to the force limits
  kPosition,             // motor spring towards the target position
  kPositionAndVelocity,  // both
};
const char* DriveKindName(DriveKind kind);
// The drive a motor state gives a row (friction when off with max friction > 0).
DriveKind DriveOf(MotorState state, float max_friction);

// How a six-DOF constraint is built (spec 3, SixDOF): a scene setting, the
// same in every world.
struct SixDofConfig {
  // Per translation axis: kLocked = fixed, kLimited, kFree.
  std::array<AxisLimitKind, 3> translation{};
  bool translation_point = false;  // every translation fixed, no springs: point part
  bool translation_rows = false;   // limit rows at the limit offset (some constrained)
  std::array<bool, 3> translation_soft{};  // limit springs (no position steps)
  std::array<SpringMode, 3> translation_spring_modes{};
  std::array<DriveKind, 3> translation_drives{};  // motors at the motor offset
  std::array<SpringMode, 3> translation_drive_spring_modes{};
  bool rotation_euler = false;   // every rotation fixed: rotation-Euler part
  bool rotation_limits = false;  // some rotation constrained: swing-twist part

  bool has_translation_drives() const {
    for (DriveKind d : translation_drives) {
      if (d != DriveKind::kNone) return true;
    }
    return false;
  }
};

struct ConstraintPlan {
  ConstraintType type;
  std::string label;  // for messages and the printed plan
  std::size_t body1, body2;
  MotionType motion1, motion2;
  std::size_t offset = kAbsent;        // the type's main storage in the block
  // The type's ...Scratch struct (constraint_lanes.h), if it has one: an
  // offset into the working block, past the stored bytes (StepPlan).
  std::size_t scratch_offset = kAbsent;
  std::size_t limit_offset = kAbsent;  // hinge / slider limit row, if limited
  std::size_t motor_offset = kAbsent;  // hinge / slider motor or friction row
  // The same rows as a step uses them, in the working block's scratch
  // (constraint_lanes.h: ...Row beside the stored ...Lanes).
  std::size_t limit_scratch_offset = kAbsent, motor_scratch_offset = kAbsent;
  DriveKind drive = DriveKind::kNone;
  SpringMode motor_spring_mode = SpringMode::kFrequencyAndDamping;
  bool soft_limits = false;  // limit springs (no position-phase limit steps)
  // Distance: a rigid rod (DistanceConstraintSettings::rigid), and whether
  // the exact solve factors its row (a rod between two bodies that another
  // constraint with row groups already joins is solved whole instead: their
  // rows could be dependent; ExactSolvePlan::SolvedWhole).
  bool rod = false;
  bool rod_group = false;
  SpringMode limit_spring_mode = SpringMode::kFrequencyAndDamping;
  // Gear: the hinges of body 1 and 2; rack-and-pinion: hinge and slider.
  // Position correction runs only when both are given.
  std::size_t helper1 = kNoConstraint, helper2 = kNoConstraint;
  // Swing-twist and six-DOF: which rotation axes are locked, limited or
  // free; cone or pyramid.
  SwingTwistConfig swing_twist{};
  // Swing-twist and six-DOF rotation drives about body 2's frame axes X, Y, Z
  // (RotationDriveLanes at rotation_drive_offset when any is not kNone).
  std::size_t rotation_drive_offset = kAbsent;
  std::size_t rotation_drive_scratch_offset = kAbsent;  // RotationDriveRows
  std::array<DriveKind, 3> rotation_drives{};
  std::array<SpringMode, 3> rotation_drive_spring_modes{};
  // Axes whose position error counts (six-DOF projects the orientation error
  // onto its position-driven axes; swing-twist keeps all three).
  unsigned rotation_position_axes = 0b111;
  SixDofConfig six_dof{};
  // Path: the spline's points (path space), whether it loops, and how body
  // 2's rotation is held.
  std::vector<HermitePathPoint> path_points;
  bool path_looping = false;
  PathRotation path_rotation = PathRotation::kFree;
  HermitePath Path() const { return {path_points.data(), path_points.size(), path_looping}; }

  // Limit and motor structs at limit_offset / motor_offset: one per
  // translation axis for six-DOF, else one.
  std::size_t limit_and_motor_rows() const { return type == ConstraintType::kSixDof ? 3 : 1; }
  bool has_limits() const { return limit_offset != kAbsent; }
  bool has_motor() const { return motor_offset != kAbsent; }
  bool has_rotation_drives() const { return rotation_drive_offset != kAbsent; }
  // The parts in solve order, e.g. "angle(motor) point hinge_rotation".
  std::string PartsInOrder() const;

 private:
  std::string RotationDrivesInOrder() const;
  std::string SwingTypeText() const;
};

// A six-DOF constraint's limits after Jolt's rules (spec 3, SixDOF): a
// translation with min > max becomes 0 / 0; rotation limits are clamped into
// [-pi, pi], inverted ones become 0 / 0; a cone's swing limits become the
// symmetric +-max(0, limit_max). Axis order as SixDofAxis.
struct SixDofLimits {
  std::array<float, kSixDofAxes> min, max;
};
SixDofLimits NormalizedSixDofLimits(const SixDofConstraintSettings& settings);
// Fixed (kLocked) when min >= max, free when the range covers +-FLT_MAX
// (translation) or +-pi (rotation), else limited.
AxisLimitKind SixDofAxisKind(const SixDofLimits& limits, std::size_t axis);

struct BodyPlan {
  std::string label;
  MotionType motion;
  std::size_t offset;                    // BodyLanes in the block
  std::size_t motion_offset = kAbsent;   // BodyMotionLanes, dynamic bodies only
  // Some axis locked (allowed DOFs, spec 4.3; never for a static body, which
  // never moves): its BodyLockLanes follow its BodyLanes.
  bool dof_restricted = false;
};

// An accumulated impulse homed in the stored block and used, during a step,
// from a part in the scratch (constraint_lanes.h, CarryState): both are
// offsets in the working block.
struct CarriedState {
  std::size_t home, scratch, bytes;
};

struct StepPlan {
  std::vector<BodyPlan> bodies;
  std::vector<ConstraintPlan> constraints;
  std::vector<ContactPlan> contacts;  // solved after every constraint
  std::size_t health_offset = 0;  // WorldHealthLanes in the block
  // One block of kLaneWidth worlds as stored: bodies, parameters and what
  // survives a step. A block steps in a working block of block_bytes +
  // scratch_bytes, one per thread: a copy of the stored block followed by
  // what setup recomputes at every substep (the ...Scratch structs), so the
  // latter never travels to memory nor takes space per world. Without
  // scratch (scratch_bytes == 0) a block steps where it is stored.
  std::size_t block_bytes = 0;
  std::size_t scratch_bytes = 0;
  std::vector<CarriedState> carried;
  bool any_dynamic = false;
  ExactSolvePlan exact;  // JointSolver::kExact
  // Every array a velocity pass writes (Gauss-Seidel's, or the exact
  // solve's around its joints), as block offsets of LaneArrays: first the
  // dynamic bodies' linear and angular velocities
  // (body_velocity_arrays of them), then each constraint's solver state
  // (batch/constraint_state.h) and each contact's impulses. What a world
  // that has converged keeps (StepSettings::velocity_tolerance).
  std::vector<std::size_t> velocity_pass_arrays;
  std::size_t body_velocity_arrays = 0;

  std::size_t working_bytes() const { return block_bytes + scratch_bytes; }
};

// Checks the scene and lays it out; throws SceneError.
StepPlan CompilePlan(const Scene& scene);

// Checks step settings for the plan's scene; throws SceneError naming the
// field (JointSolver::kExact on a scene it cannot solve: why, by name).
void CheckStepSettings(const StepSettings& settings, const StepPlan& plan);

// Human-readable plan: phases, constraints with their parts and features,
// storage per block and per world.
std::string DescribePlan(const StepPlan& plan, const StepSettings& settings);

}  // namespace manyworlds
