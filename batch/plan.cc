// Scene checks and block layout (see plan.h).

#include "batch/plan.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <type_traits>

#include "batch/constraint_block.h"
#include "batch/constraint_lanes.h"
#include "batch/constraint_state.h"
#include "batch/scene_checks.h"
#include "kernels/body_lanes.h"
#include "kernels/contact.h"
#include "manyworlds/error.h"
#include "manyworlds/lanes.h"

namespace manyworlds {
const char* SettingsTypeName(const ConstraintSettings& settings) {
  return std::visit(
      [](const auto& s) -> const char* {
        using S = std::decay_t<decltype(s)>;
        if constexpr (std::is_same_v<S, PointConstraintSettings>) return "point";
        if constexpr (std::is_same_v<S, FixedConstraintSettings>) return "fixed";
        if constexpr (std::is_same_v<S, HingeConstraintSettings>) return "hinge";
        if constexpr (std::is_same_v<S, SliderConstraintSettings>) return "slider";
        if constexpr (std::is_same_v<S, GearConstraintSettings>) return "gear";
        if constexpr (std::is_same_v<S, RackAndPinionConstraintSettings>)
          return "rack_and_pinion";
        if constexpr (std::is_same_v<S, DistanceConstraintSettings>) return "distance";
        if constexpr (std::is_same_v<S, PulleyConstraintSettings>) return "pulley";
        if constexpr (std::is_same_v<S, ConeConstraintSettings>) return "cone";
        if constexpr (std::is_same_v<S, SwingTwistConstraintSettings>) return "swing_twist";
        if constexpr (std::is_same_v<S, SixDofConstraintSettings>) return "six_dof";
        if constexpr (std::is_same_v<S, PathConstraintSettings>) return "path";
      },
      settings);
}

namespace {

// Bump allocator over one block and its scratch (StepPlan::block_bytes,
// scratch_bytes); every struct is a whole number of LaneArrays. Scratch
// offsets count from the scratch's start until the stored block's size is
// known (ScratchInWorkingBlock).
class BlockLayout {
 public:
  template <class T>
  std::size_t Add() {
    return Bump<T>(bytes_);
  }
  template <class T>
  std::size_t AddScratch() {
    return Bump<T>(scratch_bytes_);
  }
  // `count` rows side by side in the block (Stored) and, as the step uses
  // them, side by side in the scratch (Row).
  template <class Stored, class Row>
  void AddRows(std::size_t count, std::size_t& offset, std::size_t& scratch_offset) {
    offset = Add<Stored>();
    scratch_offset = AddScratch<Row>();
    for (std::size_t i = 1; i < count; ++i) {
      Add<Stored>();
      AddScratch<Row>();
    }
  }
  std::size_t bytes() const { return bytes_; }
  std::size_t scratch_bytes() const { return scratch_bytes_; }

 private:
  template <class T>
  static std::size_t Bump(std::size_t& bytes) {
    static_assert(sizeof(T) % sizeof(LaneArray) == 0, "block structs are LaneArrays");
    static_assert(alignof(T) == alignof(LaneArray), "block structs are LaneArrays");
    const std::size_t offset = bytes;
    bytes += sizeof(T);
    return offset;
  }
  std::size_t bytes_ = 0;
  std::size_t scratch_bytes_ = 0;
};

// "name[i]", built by appending (GCC 12 warns falsely on "[" + string).
std::string IndexedField(const char* name, std::size_t i) {
  std::string field(name);
  field += '[';
  field += std::to_string(i);
  field += ']';
  return field;
}

// Checks a path constraint and lays it out (spec 3, Path).
void PlanPath(const std::string& what, const PathConstraintSettings& s, ConstraintPlan& c,
              BlockLayout& layout) {
  CheckFinite(what, "path_position", s.path_position);
  CheckOrientation(what, "path_rotation", s.path_rotation);
  if (s.path.size() < 2) {
    Refuse(what, "path", "needs at least 2 points (got " + std::to_string(s.path.size()) + ")");
  }
  for (std::size_t i = 0; i < s.path.size(); ++i) {
    const PathPoint& p = s.path[i];
    const std::string point = IndexedField("path", i);
    CheckFinite(what, point + ".position", p.position);
    // A zero tangent or a normal along it leaves the path frame undefined there.
    CheckAxis(what, point + ".tangent", p.tangent);
    CheckAxis(what, point + ".normal", p.normal);
    const double cx = double(p.normal[1]) * p.tangent[2] - double(p.normal[2]) * p.tangent[1];
    const double cy = double(p.normal[2]) * p.tangent[0] - double(p.normal[0]) * p.tangent[2];
    const double cz = double(p.normal[0]) * p.tangent[1] - double(p.normal[1]) * p.tangent[0];
    if (cx * cx + cy * cy + cz * cz < 1e-12) {
      Refuse(what, point + ".normal", "is parallel to the tangent");
    }
  }
  if (s.looping && s.path.front().position == s.path.back().position) {
    Refuse(what, "path", "of a looping path repeats its first point at the end (the loop closes by itself)");
  }
  CheckFinite(what, "path_fraction", s.path_fraction);
  if (std::size_t(s.rotation) > std::size_t(PathRotation::kFullyConstrained)) {
    Refuse(what, "rotation", "is not a PathRotation");
  }
  CheckMotor(what, s.motor_state, s.motor, s.max_friction_force, "max_friction_force");
  CheckFinite(what, "target_velocity", s.target_velocity);
  CheckFinite(what, "target_path_fraction", s.target_path_fraction);
  c.type = ConstraintType::kPath;
  c.offset = layout.Add<PathConstraintLanes>();
  c.drive = DriveOf(s.motor_state, s.max_friction_force);
  c.motor_spring_mode = s.motor.spring.mode;
  if (c.drive != DriveKind::kNone) {
    layout.AddRows<LinearMotorLanes, LinearMotorRow>(1, c.motor_offset, c.motor_scratch_offset);
  }
  for (const PathPoint& p : s.path) {
    c.path_points.push_back({{p.position[0], p.position[1], p.position[2]},
                             {p.tangent[0], p.tangent[1], p.tangent[2]},
                             {p.normal[0], p.normal[1], p.normal[2]}});
  }
  c.path_looping = s.looping;
  c.path_rotation = s.rotation;
}

// Checks a six-DOF constraint and decides its parts (spec 3, SixDOF).
void PlanSixDof(const std::string& what, const SixDofConstraintSettings& s,
                       ConstraintPlan& c, BlockLayout& layout) {
  CheckFinite(what, "position1", s.position1);
  CheckFinite(what, "position2", s.position2);
  CheckFrameAxes(what, "axis_x1", s.axis_x1, "axis_y1", s.axis_y1);
  CheckFrameAxes(what, "axis_x2", s.axis_x2, "axis_y2", s.axis_y2);
  const auto indexed = IndexedField;
  for (std::size_t i = 0; i < kSixDofAxes; ++i) {
    if (i < 3) {
      CheckTranslationLimits(what, indexed("limit_min", i), indexed("limit_max", i),
                             s.limit_min[i], s.limit_max[i], false);
    } else {
      if (std::isnan(s.limit_min[i])) Refuse(what, indexed("limit_min", i), "is NaN");
      if (std::isnan(s.limit_max[i])) Refuse(what, indexed("limit_max", i), "is NaN");
    }
    CheckMotor(what, s.motor_state[i], s.motor[i], s.max_friction[i],
               indexed("max_friction", i), indexed("motor", i));
  }
  for (std::size_t i = 0; i < 3; ++i) {
    CheckSpring(what, indexed("limits_spring", i), s.limits_spring[i]);
  }
  CheckFinite(what, "target_velocity", s.target_velocity);
  CheckFinite(what, "target_angular_velocity", s.target_angular_velocity);
  CheckFinite(what, "target_position", s.target_position);
  CheckOrientation(what, "target_orientation", s.target_orientation);

  c.type = ConstraintType::kSixDof;
  c.offset = layout.Add<SixDofConstraintLanes>();
  c.scratch_offset = layout.AddScratch<SixDofConstraintScratch>();
  const SixDofLimits limits = NormalizedSixDofLimits(s);
  SixDofConfig& config = c.six_dof;
  bool all_fixed = true, any_constrained = false, any_spring = false;
  for (std::size_t i = 0; i < 3; ++i) {
    config.translation[i] = SixDofAxisKind(limits, i);
    config.translation_soft[i] = s.limits_spring[i].HasStiffness();
    config.translation_spring_modes[i] = s.limits_spring[i].mode;
    all_fixed &= config.translation[i] == AxisLimitKind::kLocked;
    any_constrained |= config.translation[i] != AxisLimitKind::kFree;
    any_spring |= config.translation_soft[i];
  }
  config.translation_point = all_fixed && !any_spring;
  config.translation_rows = !config.translation_point && any_constrained;
  if (config.translation_rows) {
    layout.AddRows<LinearLimitLanes, LinearLimitRow>(3, c.limit_offset, c.limit_scratch_offset);
  }
  if (!config.translation_point) {
    for (std::size_t i = 0; i < 3; ++i) {
      config.translation_drives[i] = DriveOf(s.motor_state[i], s.max_friction[i]);
      config.translation_drive_spring_modes[i] = s.motor[i].spring.mode;
    }
  }
  if (config.has_translation_drives()) {
    layout.AddRows<LinearMotorLanes, LinearMotorRow>(3, c.motor_offset, c.motor_scratch_offset);
  }

  bool rotation_all_fixed = true, rotation_constrained = false;
  for (std::size_t i = 3; i < 6; ++i) {
    const AxisLimitKind kind = SixDofAxisKind(limits, i);
    rotation_all_fixed &= kind == AxisLimitKind::kLocked;
    rotation_constrained |= kind != AxisLimitKind::kFree;
  }
  config.rotation_euler = rotation_all_fixed;
  config.rotation_limits = !rotation_all_fixed && rotation_constrained;
  c.swing_twist.swing_type = s.swing_type;
  c.swing_twist.twist = ClassifyAxisLimit(limits.min[3], limits.max[3]);
  c.swing_twist.swing_y = ClassifyAxisLimit(limits.min[4], limits.max[4]);
  c.swing_twist.swing_z = ClassifyAxisLimit(limits.min[5], limits.max[5]);
  if (!rotation_all_fixed) {
    c.rotation_position_axes = 0;
    bool any_drive = false;
    for (std::size_t i = 0; i < 3; ++i) {
      c.rotation_drives[i] = DriveOf(s.motor_state[3 + i], s.max_friction[3 + i]);
      c.rotation_drive_spring_modes[i] = s.motor[3 + i].spring.mode;
      any_drive |= c.rotation_drives[i] != DriveKind::kNone;
      if (c.rotation_drives[i] == DriveKind::kPosition ||
          c.rotation_drives[i] == DriveKind::kPositionAndVelocity) {
        c.rotation_position_axes |= 1u << i;
      }
    }
    if (any_drive) {
      layout.AddRows<RotationDriveLanes, RotationDriveRows>(1, c.rotation_drive_offset,
                                                            c.rotation_drive_scratch_offset);
    }
  }
}

}  // namespace

const char* ConstraintTypeName(ConstraintType type) {
  switch (type) {
    case ConstraintType::kPoint: return "point";
    case ConstraintType::kFixed: return "fixed";
    case ConstraintType::kHinge: return "hinge";
    case ConstraintType::kSlider: return "slider";
    case ConstraintType::kGear: return "gear";
    case ConstraintType::kRackAndPinion: return "rack_and_pinion";
    case ConstraintType::kDistance: return "distance";
    case ConstraintType::kPulley: return "pulley";
    case ConstraintType::kCone: return "cone";
    case ConstraintType::kSwingTwist: return "swing_twist";
    case ConstraintType::kSixDof: return "six_dof";
    case ConstraintType::kPath: return "path";
  }
  return "unknown";
}

DriveKind DriveOf(MotorState state, float max_friction) {
  switch (state) {
    case MotorState::kOff:
      return max_friction > 0.0f ? DriveKind::kFriction : DriveKind::kNone;
    case MotorState::kVelocity: return DriveKind::kVelocity;
    case MotorState::kPosition: return DriveKind::kPosition;
    case MotorState::kPositionAndVelocity: return DriveKind::kPositionAndVelocity;
  }
  return DriveKind::kNone;
}

const char* DriveKindName(DriveKind kind) {
  switch (kind) {
    case DriveKind::kNone: return "none";
    case DriveKind::kFriction: return "friction";
    case DriveKind::kVelocity: return "velocity motor";
    case DriveKind::kPosition: return "position motor";
    case DriveKind::kPositionAndVelocity: return "position-and-velocity motor";
  }
  return "unknown";
}

std::string BodyLabel(const Scene& scene, std::size_t index) {
  std::string label = "body #" + std::to_string(index);
  if (index < scene.bodies().size() && !scene.bodies()[index].name.empty()) {
    label += " '" + scene.bodies()[index].name + "'";
  }
  return label;
}

std::string ConstraintLabel(const Scene& scene, std::size_t index) {
  if (index >= scene.constraints().size()) return "constraint #" + std::to_string(index);
  const ConstraintSettings& settings = scene.constraints()[index];
  std::string label = std::string(SettingsTypeName(settings)) + " constraint #" +
                      std::to_string(index);
  const std::string& name = std::visit([](const auto& s) -> const std::string& { return s.name; },
                                       settings);
  if (!name.empty()) label += " '" + name + "'";
  return label;
}

std::string ConstraintPlan::PartsInOrder() const {
  const std::string drive_row = has_motor() ? std::string(DriveKindName(drive)) : "";
  const std::string limit_row = soft_limits ? "soft limits" : "limits";
  switch (type) {
    case ConstraintType::kPoint: return "point";
    case ConstraintType::kFixed: return "rotation_euler point";
    case ConstraintType::kHinge:
      return (has_motor() ? "angle(" + drive_row + ") " : std::string()) +
             "point hinge_rotation" + (has_limits() ? " angle(" + limit_row + ")" : "");
    case ConstraintType::kSlider:
      return (has_motor() ? "axis(" + drive_row + ") " : std::string()) +
             "dual_axis rotation_euler" + (has_limits() ? " axis(" + limit_row + ")" : "");
    case ConstraintType::kGear:
      return helper1 != kNoConstraint ? "gear (position correction through the hinges)"
                                      : "gear (velocity only)";
    case ConstraintType::kRackAndPinion:
      return helper1 != kNoConstraint
                 ? "rack_and_pinion (position correction through hinge and slider)"
                 : "rack_and_pinion (velocity only)";
    case ConstraintType::kDistance: return "axis(" + limit_row + ")";
    case ConstraintType::kPulley: return "independent_axis(limits)";
    case ConstraintType::kCone: return "point angle(cone limit)";
    case ConstraintType::kSwingTwist:
      return RotationDrivesInOrder() + "swing_twist(" + SwingTypeText() + ") point";
    case ConstraintType::kPath: {
      static const char* const kRotationPart[] = {
          "",
          " hinge_rotation(about the tangent)",
          " hinge_rotation(about the normal)",
          " hinge_rotation(about the binormal)",
          " rotation_euler(to the path)",
          " rotation_euler(fixed)"};
      return (has_motor() ? "axis(" + drive_row + ") " : std::string()) +
             "dual_axis(normal, binormal)" + (path_looping ? "" : " axis(end limits)") +
             kRotationPart[std::size_t(path_rotation)];
    }
    case ConstraintType::kSixDof: {
      std::string parts;
      for (int i = 0; i < 3; ++i) {
        const DriveKind d = six_dof.translation_drives[i];
        if (d != DriveKind::kNone) {
          parts += std::string("axis(") + "XYZ"[i] + " " + DriveKindName(d) + ") ";
        }
      }
      parts += RotationDrivesInOrder();
      if (six_dof.rotation_euler) parts += "rotation_euler ";
      if (six_dof.rotation_limits) parts += "swing_twist(" + SwingTypeText() + ") ";
      if (six_dof.translation_point) parts += "point";
      for (int i = 0; i < 3 && six_dof.translation_rows; ++i) {
        const AxisLimitKind k = six_dof.translation[i];
        if (k == AxisLimitKind::kFree) continue;
        parts += std::string("axis(") + "XYZ"[i] + " " +
                 (k == AxisLimitKind::kLocked ? "fixed" : "limits") +
                 (six_dof.translation_soft[i] ? ", soft" : "") + ") ";
      }
      while (!parts.empty() && parts.back() == ' ') parts.pop_back();
      return parts;
    }
  }
  return "";
}

std::string ConstraintPlan::RotationDrivesInOrder() const {
  std::string parts;
  for (int i = 0; i < 3; ++i) {
    if (rotation_drives[i] == DriveKind::kNone) continue;
    parts += std::string("angle(") + "XYZ"[i] + " " + DriveKindName(rotation_drives[i]) + ") ";
  }
  return parts;
}

std::string ConstraintPlan::SwingTypeText() const {
  return swing_twist.swing_type == SwingType::kCone ? "cone" : "pyramid";
}

SixDofLimits NormalizedSixDofLimits(const SixDofConstraintSettings& s) {
  SixDofLimits limits{s.limit_min, s.limit_max};
  for (std::size_t i = 0; i < 3; ++i) {
    if (limits.min[i] > limits.max[i]) limits.min[i] = limits.max[i] = 0.0f;
    // No bound on that side (CheckTranslationLimits refused the other side's).
    if (limits.min[i] <= -kMaxHealthyCoordinate) limits.min[i] = -FLT_MAX;
    if (limits.max[i] >= kMaxHealthyCoordinate) limits.max[i] = FLT_MAX;
  }
  if (s.swing_type == SwingType::kCone) {
    for (std::size_t i = 4; i < 6; ++i) {
      limits.max[i] = std::max(0.0f, limits.max[i]);
      limits.min[i] = -limits.max[i];
    }
  }
  for (std::size_t i = 3; i < 6; ++i) {
    limits.min[i] = std::clamp(limits.min[i], -kPi, kPi);
    limits.max[i] = std::clamp(limits.max[i], -kPi, kPi);
    if (limits.min[i] > limits.max[i]) limits.min[i] = limits.max[i] = 0.0f;
  }
  return limits;
}

AxisLimitKind SixDofAxisKind(const SixDofLimits& limits, std::size_t axis) {
  const float bound = axis < 3 ? FLT_MAX : kPi;
  if (limits.min[axis] >= limits.max[axis]) return AxisLimitKind::kLocked;
  if (limits.min[axis] <= -bound && limits.max[axis] >= bound) return AxisLimitKind::kFree;
  return AxisLimitKind::kLimited;
}

void CheckStepSettings(const StepSettings& s, const StepPlan& plan) {
  const std::string what = "step settings";
  if (!(s.substeps >= 1 && s.substeps <= kMaxSubsteps)) {
    Refuse(what, "substeps", "must lie in [1, " + std::to_string(kMaxSubsteps) + "] (got " +
                                 std::to_string(s.substeps) + ")");
  }
  // Checked per substep: that is what 1/dt and the warm-start ratio see.
  const float substep = s.delta_time / static_cast<float>(s.substeps);
  if (!(substep >= kMinSubstepDeltaTime && substep <= kMaxSubstepDeltaTime)) {
    Refuse(what, "delta_time",
           "/ substeps must lie in [1e-6, 1] s (got " + ValueText(s.delta_time) + " / " +
               std::to_string(s.substeps) + ")");
  }
  const auto iterations = [&](const char* field, int n) {
    if (!(n >= 0 && n <= kMaxIterations)) {
      Refuse(what, field, "must lie in [0, " + std::to_string(kMaxIterations) + "] (got " +
                              std::to_string(n) + ")");
    }
  };
  iterations("velocity_iterations", s.velocity_iterations);
  iterations("position_iterations", s.position_iterations);
  if (!std::isfinite(s.baumgarte) || s.baumgarte < 0.0f) {
    Refuse(what, "baumgarte", "must be finite and >= 0");
  }
  if (static_cast<unsigned>(s.unhealthy_worlds) > static_cast<unsigned>(UnhealthyWorlds::kReset)) {
    Refuse(what, "unhealthy_worlds", "is not an UnhealthyWorlds (got " +
                                         std::to_string(unsigned(s.unhealthy_worlds)) + ")");
  }
  CheckFinite("step settings", "gravity", s.gravity);
  if (s.solver != JointSolver::kGaussSeidel && s.solver != JointSolver::kExact) {
    Refuse(what, "solver", "is not a JointSolver (got " + std::to_string(unsigned(s.solver)) + ")");
  }
  if (!(s.exact_tolerance > 0.0f && std::isfinite(s.exact_tolerance))) {
    Refuse(what, "exact_tolerance", "must be finite and > 0 (got " + ValueText(s.exact_tolerance) + ")");
  }
  if (!(s.exact_geometric_stiffness >= 0.0f && std::isfinite(s.exact_geometric_stiffness))) {
    Refuse(what, "exact_geometric_stiffness",
           "must be finite and >= 0 (got " + ValueText(s.exact_geometric_stiffness) + ")");
  }
  const auto contact_setting = [&](const char* field, float x) {
    if (!(x >= 0.0f && x <= kMaxContactSetting)) {
      Refuse(what, field, "must be finite, >= 0 and at most " + ValueText(kMaxContactSetting) +
                              " (got " + ValueText(x) + ")");
    }
  };
  contact_setting("speculative_contact_distance", s.speculative_contact_distance);
  contact_setting("penetration_slop", s.penetration_slop);
  contact_setting("max_penetration_distance", s.max_penetration_distance);
  contact_setting("min_velocity_for_restitution", s.min_velocity_for_restitution);
  if (!(s.velocity_tolerance >= 0.0f && std::isfinite(s.velocity_tolerance))) {
    Refuse(what, "velocity_tolerance",
           "must be finite and >= 0 (got " + ValueText(s.velocity_tolerance) + ")");
  }
  if (s.solver == JointSolver::kExact && !plan.exact.available()) {
    Refuse(what, "solver", std::string("is exact, but ") + plan.exact.unavailable);
  }
}

namespace {

// The stored block's size known, the scratch structs move past it, into the
// working block (StepPlan::block_bytes).
void ScratchInWorkingBlock(StepPlan& plan, const BlockLayout& layout) {
  plan.block_bytes = layout.bytes();
  plan.scratch_bytes = layout.scratch_bytes();
  for (ConstraintPlan& c : plan.constraints) {
    for (std::size_t* offset : {&c.scratch_offset, &c.limit_scratch_offset,
                                &c.motor_scratch_offset, &c.rotation_drive_scratch_offset}) {
      if (*offset != kAbsent) *offset += plan.block_bytes;
    }
  }
}

// A zeroed working block of the plan's size: the views only compute
// addresses, so it stands in for a real one.
std::vector<LaneArray> AddressOnlyBlock(const StepPlan& plan) {
  return std::vector<LaneArray>(plan.working_bytes() / sizeof(LaneArray) + 1);
}

// StepPlan::carried, from each type's CarryState.
void ListCarriedState(StepPlan& plan) {
  std::vector<LaneArray> block = AddressOnlyBlock(plan);
  std::byte* base = reinterpret_cast<std::byte*>(block.data());
  const auto at = [&](const void* p) {
    return static_cast<std::size_t>(static_cast<const std::byte*>(p) - base);
  };
  for (std::size_t k = 0; k < plan.constraints.size(); ++k) {
    VisitCarriedState(ConstraintInBlock(plan, k, base), [&](auto& home, auto& scratch) {
      static_assert(sizeof(home) == sizeof(scratch));
      const CarriedState next{at(&home), at(&scratch), sizeof(home)};
      CarriedState* last = plan.carried.empty() ? nullptr : &plan.carried.back();
      if (last != nullptr && last->home + last->bytes == next.home &&
          last->scratch + last->bytes == next.scratch) {
        last->bytes += next.bytes;  // one copy for neighbours in both places
      } else {
        plan.carried.push_back(next);
      }
    });
  }
}

// StepPlan::velocity_pass_arrays: inside a step, so the carried impulses'
// places in the scratch rather than their homes.
void ListVelocityPassArrays(StepPlan& plan) {
  std::vector<LaneArray> block = AddressOnlyBlock(plan);
  std::byte* base = reinterpret_cast<std::byte*>(block.data());
  std::vector<std::size_t>& arrays = plan.velocity_pass_arrays;
  const auto add = [&](const LaneArray& array) {
    std::size_t offset =
        static_cast<std::size_t>(reinterpret_cast<const std::byte*>(&array) - base);
    for (const CarriedState& carried : plan.carried) {
      if (offset >= carried.home && offset < carried.home + carried.bytes) {
        offset += carried.scratch - carried.home;
        break;
      }
    }
    arrays.push_back(offset);
  };
  const auto add3 = [&](const Vec3Lanes& v) {
    add(v.x);
    add(v.y);
    add(v.z);
  };
  for (const BodyPlan& body : plan.bodies) {
    if (body.motion != MotionType::kDynamic) continue;
    const BodyLanes& lanes = At<BodyLanes>(base, body.offset);
    add3(lanes.linear_velocity);
    add3(lanes.angular_velocity);
  }
  plan.body_velocity_arrays = arrays.size();
  for (std::size_t k = 0; k < plan.constraints.size(); ++k) {
    VisitConstraintState(ConstraintInBlock(plan, k, base), [&](LaneArray* array, const char*) {
      if (array != nullptr) add(*array);
    });
  }
  for (const ContactPlan& c : plan.contacts) {
    const ContactLanes& manifold = At<ContactLanes>(base, c.offset);
    add(manifold.tangent1_lambda);
    add(manifold.tangent2_lambda);
    add(manifold.angular_lambda);
    const ContactPointLanes* points = &At<ContactPointLanes>(base, c.points_offset);
    for (std::size_t i = 0; i < c.point_count; ++i) add(points[i].normal_lambda);
  }
}

}  // namespace

StepPlan CompilePlan(const Scene& scene) {
  StepPlan plan;
  BlockLayout layout;
  const std::size_t body_count = scene.bodies().size();
  if (body_count == 0) Refuse("scene", "bodies", "is empty");

  for (std::size_t i = 0; i < body_count; ++i) {
    const BodySettings& body = scene.bodies()[i];
    CheckBody(body, BodyLabel(scene, i));
    BodyPlan& planned = plan.bodies.emplace_back(
        BodyPlan{BodyLabel(scene, i), body.motion_type, layout.Add<BodyLanes>()});
    planned.dof_restricted =
        body.motion_type != MotionType::kStatic && body.allowed_dofs != AllowedDofs::kAll;
    if (planned.dof_restricted) layout.Add<BodyLockLanes>();
  }
  plan.health_offset = layout.Add<WorldHealthLanes>();
  for (BodyPlan& body : plan.bodies) {
    if (body.motion == MotionType::kDynamic) {
      body.motion_offset = layout.Add<BodyMotionLanes>();
      plan.any_dynamic = true;
    }
  }

  for (std::size_t index = 0; index < scene.constraints().size(); ++index) {
    const ConstraintSettings& settings = scene.constraints()[index];
    const std::string what = ConstraintLabel(scene, index);
    ConstraintPlan c;
    c.label = what;
    std::visit(
        [&](const auto& s) {
          c.body1 = s.body1;
          c.body2 = s.body2;
          if constexpr (requires { s.space; }) CheckConstraintSpace(what, s.space);
          if constexpr (requires { s.swing_type; }) CheckSwingType(what, s.swing_type);
        },
        settings);
    if (c.body1 >= body_count) {
      Refuse(what, "body1", "is " + std::to_string(c.body1) + ", but the scene has " +
                                std::to_string(body_count) + " bodies");
    }
    if (c.body2 >= body_count) {
      Refuse(what, "body2", "is " + std::to_string(c.body2) + ", but the scene has " +
                                std::to_string(body_count) + " bodies");
    }
    if (c.body1 == c.body2) Refuse(what, "body2", "is the same body as body1");
    c.motion1 = scene.bodies()[c.body1].motion_type;
    c.motion2 = scene.bodies()[c.body2].motion_type;
    if (c.motion1 != MotionType::kDynamic && c.motion2 != MotionType::kDynamic) {
      Refuse(what, "body1 / body2",
             "are both non-dynamic (" + BodyLabel(scene, c.body1) + " is " +
                 MotionTypeName(c.motion1) + ", " + BodyLabel(scene, c.body2) + " is " +
                 MotionTypeName(c.motion2) + "): nothing could move");
    }

    std::visit(
        [&](const auto& s) {
          using S = std::decay_t<decltype(s)>;
          if constexpr (std::is_same_v<S, PointConstraintSettings>) {
            CheckFinite(what, "point1", s.point1);
            CheckFinite(what, "point2", s.point2);
            c.type = ConstraintType::kPoint;
            c.offset = layout.Add<PointConstraintLanes>();
            c.scratch_offset = layout.AddScratch<PointConstraintScratch>();
          } else if constexpr (std::is_same_v<S, FixedConstraintSettings>) {
            CheckFinite(what, "point1", s.point1);
            CheckFinite(what, "point2", s.point2);
            CheckFrameAxes(what, "axis_x1", s.axis_x1, "axis_y1", s.axis_y1);
            CheckFrameAxes(what, "axis_x2", s.axis_x2, "axis_y2", s.axis_y2);
            if (s.auto_detect_point && s.space != ConstraintSpace::kWorldSpace) {
              Refuse(what, "auto_detect_point", "needs space = kWorldSpace");
            }
            c.type = ConstraintType::kFixed;
            c.offset = layout.Add<FixedConstraintLanes>();
            c.scratch_offset = layout.AddScratch<FixedConstraintScratch>();
          } else if constexpr (std::is_same_v<S, HingeConstraintSettings>) {
            CheckFinite(what, "point1", s.point1);
            CheckFinite(what, "point2", s.point2);
            CheckFrameAxes(what, "hinge_axis1", s.hinge_axis1, "normal_axis1", s.normal_axis1);
            CheckFrameAxes(what, "hinge_axis2", s.hinge_axis2, "normal_axis2", s.normal_axis2);
            CheckHingeLimits(what, s.limits_min, s.limits_max);
            CheckMotor(what, s.motor_state, s.motor, s.max_friction_torque,
                       "max_friction_torque");
            CheckSpring(what, "limits_spring", s.limits_spring);
            CheckFinite(what, "target_angular_velocity", s.target_angular_velocity);
            CheckFinite(what, "target_angle", s.target_angle);
            c.type = ConstraintType::kHinge;
            c.offset = layout.Add<HingeConstraintLanes>();
            c.scratch_offset = layout.AddScratch<HingeConstraintScratch>();
            if (!(s.limits_min == -kPi && s.limits_max == kPi)) {
              layout.AddRows<AngularLimitLanes, AngularLimitRow>(1, c.limit_offset,
                                                                 c.limit_scratch_offset);
              c.soft_limits = s.limits_spring.HasStiffness();
              c.limit_spring_mode = s.limits_spring.mode;
            }
            c.drive = DriveOf(s.motor_state, s.max_friction_torque);
            c.motor_spring_mode = s.motor.spring.mode;
            if (c.drive != DriveKind::kNone) {
              layout.AddRows<AngularMotorLanes, AngularMotorRow>(1, c.motor_offset,
                                                                 c.motor_scratch_offset);
            }
          } else if constexpr (std::is_same_v<S, SliderConstraintSettings>) {
            CheckFinite(what, "point1", s.point1);
            CheckFinite(what, "point2", s.point2);
            CheckFrameAxes(what, "slider_axis1", s.slider_axis1, "normal_axis1", s.normal_axis1);
            CheckFrameAxes(what, "slider_axis2", s.slider_axis2, "normal_axis2", s.normal_axis2);
            const LimitRange limits = CheckTranslationLimits(
                what, "limits_min", "limits_max", s.limits_min, s.limits_max, true);
            if (s.auto_detect_point && s.space != ConstraintSpace::kWorldSpace) {
              Refuse(what, "auto_detect_point", "needs space = kWorldSpace");
            }
            CheckMotor(what, s.motor_state, s.motor, s.max_friction_force,
                       "max_friction_force");
            CheckSpring(what, "limits_spring", s.limits_spring);
            CheckFinite(what, "target_velocity", s.target_velocity);
            CheckFinite(what, "target_position", s.target_position);
            c.type = ConstraintType::kSlider;
            c.offset = layout.Add<SliderConstraintLanes>();
            c.scratch_offset = layout.AddScratch<SliderConstraintScratch>();
            if (limits.min != -FLT_MAX || limits.max != FLT_MAX) {
              layout.AddRows<LinearLimitLanes, LinearLimitRow>(1, c.limit_offset,
                                                               c.limit_scratch_offset);
              c.soft_limits = s.limits_spring.HasStiffness();
              c.limit_spring_mode = s.limits_spring.mode;
            }
            c.drive = DriveOf(s.motor_state, s.max_friction_force);
            c.motor_spring_mode = s.motor.spring.mode;
            if (c.drive != DriveKind::kNone) {
              layout.AddRows<LinearMotorLanes, LinearMotorRow>(1, c.motor_offset,
                                                               c.motor_scratch_offset);
            }
          } else if constexpr (std::is_same_v<S, DistanceConstraintSettings>) {
            CheckFinite(what, "point1", s.point1);
            CheckFinite(what, "point2", s.point2);
            CheckFinite(what, "min_distance", s.min_distance);
            CheckFinite(what, "max_distance", s.max_distance);
            // Negative bounds are resolved from the initial distance, which
            // keeps min <= max; two given bounds must be ordered.
            if (s.min_distance >= 0.0f && s.max_distance >= 0.0f &&
                s.min_distance > s.max_distance) {
              Refuse(what, "min_distance / max_distance",
                     "must be ordered, min <= max (got " + std::to_string(s.min_distance) +
                         " > " + std::to_string(s.max_distance) + ")");
            }
            CheckSpring(what, "limits_spring", s.limits_spring);
            c.type = ConstraintType::kDistance;
            c.offset = layout.Add<DistanceConstraintLanes>();
            layout.AddRows<LinearLimitLanes, LinearLimitRow>(1, c.limit_offset,
                                                             c.limit_scratch_offset);
            c.soft_limits = s.limits_spring.HasStiffness();
            c.limit_spring_mode = s.limits_spring.mode;
            c.rod = s.rigid();
          } else if constexpr (std::is_same_v<S, SwingTwistConstraintSettings>) {
            CheckFinite(what, "point1", s.point1);
            CheckFinite(what, "point2", s.point2);
            CheckFrameAxes(what, "twist_axis1", s.twist_axis1, "plane_axis1", s.plane_axis1);
            CheckFrameAxes(what, "twist_axis2", s.twist_axis2, "plane_axis2", s.plane_axis2);
            const auto in_range = [&](const char* field, float x, float low) {
              if (!(x >= low && x <= kPi)) {
                Refuse(what, field, "must lie in [" + std::string(low < 0.0f ? "-pi" : "0") +
                                        ", pi] (got " + std::to_string(x) + ")");
              }
            };
            in_range("normal_half_cone_angle", s.normal_half_cone_angle, 0.0f);
            in_range("plane_half_cone_angle", s.plane_half_cone_angle, 0.0f);
            in_range("twist_min_angle", s.twist_min_angle, -kPi);
            in_range("twist_max_angle", s.twist_max_angle, -kPi);
            if (s.twist_min_angle > s.twist_max_angle) {
              Refuse(what, "twist_min_angle / twist_max_angle", "must be ordered, min <= max");
            }
            c.type = ConstraintType::kSwingTwist;
            c.offset = layout.Add<SwingTwistConstraintLanes>();
            c.scratch_offset = layout.AddScratch<SwingTwistConstraintScratch>();
            c.swing_twist.swing_type = s.swing_type;
            c.swing_twist.twist = ClassifyAxisLimit(s.twist_min_angle, s.twist_max_angle);
            c.swing_twist.swing_y =
                ClassifyAxisLimit(-s.plane_half_cone_angle, s.plane_half_cone_angle);
            c.swing_twist.swing_z =
                ClassifyAxisLimit(-s.normal_half_cone_angle, s.normal_half_cone_angle);
            CheckMotor(what, s.twist_motor_state, s.twist_motor, s.max_friction_torque,
                       "max_friction_torque", "twist_motor");
            CheckMotor(what, s.swing_motor_state, s.swing_motor, s.max_friction_torque,
                       "max_friction_torque", "swing_motor");
            CheckFinite(what, "target_angular_velocity", s.target_angular_velocity);
            CheckOrientation(what, "target_orientation", s.target_orientation);
            c.rotation_drives = {DriveOf(s.twist_motor_state, s.max_friction_torque),
                                 DriveOf(s.swing_motor_state, s.max_friction_torque),
                                 DriveOf(s.swing_motor_state, s.max_friction_torque)};
            c.rotation_drive_spring_modes = {s.twist_motor.spring.mode,
                                             s.swing_motor.spring.mode,
                                             s.swing_motor.spring.mode};
            if (c.rotation_drives[0] != DriveKind::kNone ||
                c.rotation_drives[1] != DriveKind::kNone) {
              layout.AddRows<RotationDriveLanes, RotationDriveRows>(
                  1, c.rotation_drive_offset, c.rotation_drive_scratch_offset);
            }
          } else if constexpr (std::is_same_v<S, SixDofConstraintSettings>) {
            PlanSixDof(what, s, c, layout);
          } else if constexpr (std::is_same_v<S, PathConstraintSettings>) {
            PlanPath(what, s, c, layout);
          } else if constexpr (std::is_same_v<S, ConeConstraintSettings>) {
            CheckFinite(what, "point1", s.point1);
            CheckFinite(what, "point2", s.point2);
            CheckAxis(what, "twist_axis1", s.twist_axis1);
            CheckAxis(what, "twist_axis2", s.twist_axis2);
            if (!(s.half_cone_angle >= 0.0f && s.half_cone_angle <= kPi)) {
              Refuse(what, "half_cone_angle", "must lie in [0, pi] (got " +
                                                  std::to_string(s.half_cone_angle) + ")");
            }
            c.type = ConstraintType::kCone;
            c.offset = layout.Add<ConeConstraintLanes>();
            c.scratch_offset = layout.AddScratch<ConeConstraintScratch>();
          } else if constexpr (std::is_same_v<S, PulleyConstraintSettings>) {
            CheckFinite(what, "body_point1", s.body_point1);
            CheckFinite(what, "fixed_point1", s.fixed_point1);
            CheckFinite(what, "body_point2", s.body_point2);
            CheckFinite(what, "fixed_point2", s.fixed_point2);
            CheckFinite(what, "ratio", s.ratio);
            if (!(s.ratio > 0.0f)) {
              Refuse(what, "ratio", "must be positive (got " + std::to_string(s.ratio) + ")");
            }
            CheckFinite(what, "min_length", s.min_length);
            CheckFinite(what, "max_length", s.max_length);
            if (s.min_length >= 0.0f && s.max_length >= 0.0f && s.min_length > s.max_length) {
              Refuse(what, "min_length / max_length",
                     "must be ordered, min <= max (got " + std::to_string(s.min_length) +
                         " > " + std::to_string(s.max_length) + ")");
            }
            c.type = ConstraintType::kPulley;
            c.offset = layout.Add<PulleyConstraintLanes>();
          } else {
            // Gear and rack-and-pinion: both bodies must be able to turn / move
            // (spec 1.5: the parts read motion properties of both bodies).
            for (int which = 1; which <= 2; ++which) {
              const std::size_t body = which == 1 ? s.body1 : s.body2;
              if (scene.bodies()[body].motion_type == MotionType::kStatic) {
                Refuse(what, "body" + std::to_string(which),
                       "is static (" + BodyLabel(scene, body) +
                           "); a gear or rack-and-pinion needs two non-static bodies");
              }
            }
            CheckFinite(what, "ratio", s.ratio);
            if constexpr (std::is_same_v<S, GearConstraintSettings>) {
              CheckAxis(what, "hinge_axis1", s.hinge_axis1);
              CheckAxis(what, "hinge_axis2", s.hinge_axis2);
              c.type = ConstraintType::kGear;
              c.offset = layout.Add<GearConstraintLanes>();
              c.scratch_offset = layout.AddScratch<GearConstraintScratch>();
              c.helper1 = s.hinge1;
              c.helper2 = s.hinge2;
            } else {
              CheckAxis(what, "hinge_axis1", s.hinge_axis1);
              CheckAxis(what, "slider_axis2", s.slider_axis2);
              c.type = ConstraintType::kRackAndPinion;
              c.offset = layout.Add<RackAndPinionConstraintLanes>();
              c.scratch_offset = layout.AddScratch<RackAndPinionConstraintScratch>();
              c.helper1 = s.hinge;
              c.helper2 = s.slider;
            }
          }
        },
        settings);
    plan.constraints.push_back(std::move(c));
  }

  // Gear / rack helpers: both or neither, of the right type and bodies.
  for (std::size_t index = 0; index < plan.constraints.size(); ++index) {
    ConstraintPlan& c = plan.constraints[index];
    if (c.type != ConstraintType::kGear && c.type != ConstraintType::kRackAndPinion) continue;
    const bool gear = c.type == ConstraintType::kGear;
    const char* field1 = gear ? "hinge1" : "hinge";
    const char* field2 = gear ? "hinge2" : "slider";
    if ((c.helper1 == kNoConstraint) != (c.helper2 == kNoConstraint)) {
      Refuse(c.label, std::string(field1) + " / " + field2,
             "must be given together (position correction needs both) or not at all");
    }
    if (c.helper1 == kNoConstraint) continue;
    const auto check_helper = [&](std::size_t helper, const char* field,
                                  ConstraintType type, std::size_t body) {
      if (helper >= plan.constraints.size()) {
        Refuse(c.label, field, "is " + std::to_string(helper) + ", but the scene has " +
                                   std::to_string(plan.constraints.size()) +
                                   " constraints");
      }
      const ConstraintPlan& h = plan.constraints[helper];
      if (h.type != type) {
        Refuse(c.label, field, "must name a " + std::string(ConstraintTypeName(type)) +
                                   " constraint, but " + h.label + " is a " +
                                   ConstraintTypeName(h.type));
      }
      if (h.body2 != body && h.body1 != body) {
        Refuse(c.label, field, h.label + " does not act on " + BodyLabel(scene, body));
      }
    };
    check_helper(c.helper1, field1, ConstraintType::kHinge, c.body1);
    check_helper(c.helper2, field2, gear ? ConstraintType::kHinge : ConstraintType::kSlider,
                 c.body2);
  }

  plan.contacts = FindContactPairs(scene);
  for (ContactPlan& c : plan.contacts) {
    c.offset = layout.Add<ContactLanes>();
    c.points_offset = layout.Add<ContactPointLanes>();
    for (std::size_t i = 1; i < c.point_count; ++i) layout.Add<ContactPointLanes>();
    c.motion_offset1 = plan.bodies[c.body1].motion_offset;
    c.motion_offset2 = plan.bodies[c.body2].motion_offset;
  }

  ScratchInWorkingBlock(plan, layout);
  ListCarriedState(plan);
  ListVelocityPassArrays(plan);
  ChooseRodGroups(scene, plan);
  plan.exact = PlanExactSolve(scene, plan);
  return plan;
}

std::string DescribePlan(const StepPlan& plan, const StepSettings& settings) {
  std::ostringstream out;
  std::size_t dynamic = 0;
  for (const BodyPlan& body : plan.bodies) dynamic += body.motion == MotionType::kDynamic;
  out << "bodies: " << plan.bodies.size() << " (" << dynamic << " dynamic)\n";
  for (const BodyPlan& body : plan.bodies) {
    out << "  " << body.label << ": " << MotionTypeName(body.motion)
        << (body.motion_offset != kAbsent ? ", forces, damping and velocity clamps" : "")
        << "\n";
  }
  out << "constraints in solve order: " << plan.constraints.size() << "\n";
  for (const ConstraintPlan& c : plan.constraints) {
    out << "  " << c.label << " (" << plan.bodies[c.body1].label << " "
        << MotionTypeName(c.motion1) << ", " << plan.bodies[c.body2].label << " "
        << MotionTypeName(c.motion2) << "): " << c.PartsInOrder() << "\n";
  }
  out << "contacts in solve order (after the constraints): " << plan.contacts.size() << "\n";
  for (const ContactPlan& c : plan.contacts) {
    out << "  " << c.label << " (" << MotionTypeName(c.motion1) << ", "
        << MotionTypeName(c.motion2) << "): " << ContactPairKindName(c.kind) << ", up to "
        << c.point_count << " point(s), friction " << c.friction << ", restitution "
        << c.restitution << "\n";
  }
  const bool constraints = !plan.constraints.empty() || !plan.contacts.empty();
  const int substeps = settings.substeps;
  out << "step: " << substeps << " substep(s) of " << settings.delta_time / substeps
      << " s, each:\n";
  out << "  1. forces, gravity, damping, velocity clamps"
      << (plan.any_dynamic ? "" : " (skipped: no dynamic body)") << "\n";
  if (constraints) {
    out << "  2. setup of every constraint\n";
    out << "  3. warm start (" << (settings.warm_start ? "ratio dt/dt_prev" : "off: impulses zeroed")
        << ")\n";
    out << "  4. up to " << settings.velocity_iterations
        << " velocity iterations (stop when no world applied an impulse)\n";
  } else {
    out << "  2-4. constraint setup and velocity iterations (skipped: no constraint)\n";
  }
  out << "  5. integration (exact axis-angle rotation, then position)\n";
  if (constraints && settings.position_iterations > 0) {
    out << "  6. up to " << settings.position_iterations
        << " position iterations, Baumgarte " << settings.baumgarte << "\n";
  } else {
    out << "  6. position iterations (skipped)\n";
  }
  out << "storage: " << plan.block_bytes << " bytes per block of " << kLaneWidth
      << " worlds, " << plan.block_bytes / kLaneWidth << " bytes per world\n";
  out << "scratch: " << plan.scratch_bytes
      << " bytes per thread (recomputed at every substep's setup)\n";
  return out.str();
}

}  // namespace manyworlds
