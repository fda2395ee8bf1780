#include "batch/part_binding.h"

#include <utility>

#include "manyworlds/error.h"

namespace manyworlds {

const char* PartKindName(PartKind kind) {
  switch (kind) {
    case PartKind::kAxis: return "axis";
    case PartKind::kDualAxis: return "dual_axis";
    case PartKind::kPoint: return "point";
    case PartKind::kHingeRotation: return "hinge_rotation";
    case PartKind::kRotationEuler: return "rotation_euler";
    case PartKind::kRotationQuat: return "rotation_quat";
    case PartKind::kAngle: return "angle";
    case PartKind::kRackAndPinion: return "rack_and_pinion";
    case PartKind::kGear: return "gear";
    case PartKind::kIndependentAxis: return "independent_axis";
    case PartKind::kSwingTwist: return "swing_twist";
  }
  return "unknown";
}

namespace {

std::string Describe(const std::string& constraint_name, PartKind kind) {
  return "constraint '" + constraint_name + "' (" + PartKindName(kind) + " part)";
}

void CheckBodyExists(const BodyBlocks& bodies, const std::string& where,
                     const char* field, std::size_t body) {
  if (body >= bodies.body_count()) {
    throw SceneError(where + ": " + field + " = " + std::to_string(body) +
                     " does not exist (the scene has " +
                     std::to_string(bodies.body_count()) + " bodies)");
  }
}

}  // namespace

PartBinding BindPart(const BodyBlocks& bodies, std::string constraint_name,
                     PartKind kind, std::size_t body1, std::size_t body2) {
  const std::string where = Describe(constraint_name, kind);
  CheckBodyExists(bodies, where, "body1", body1);
  CheckBodyExists(bodies, where, "body2", body2);
  if (body1 == body2) {
    throw SceneError(where + ": body1 and body2 are both body " +
                     std::to_string(body1) + "; a part needs two bodies");
  }
  if (kind == PartKind::kRackAndPinion || kind == PartKind::kGear) {
    // Jolt reads both bodies' motion properties, which static bodies lack.
    const bool rack = kind == PartKind::kRackAndPinion;
    const char* roles[2] = {rack ? "body1 (pinion)" : "body1 (gear 1)",
                            rack ? "body2 (rack)" : "body2 (gear 2)"};
    const std::size_t indices[2] = {body1, body2};
    for (int i = 0; i < 2; ++i) {
      if (bodies.motion_type(indices[i]) == MotionType::kStatic) {
        throw SceneError(where + ": " + roles[i] + " = body " +
                         std::to_string(indices[i]) + " is static; both bodies of a " +
                         (rack ? "rack-and-pinion" : "gear") +
                         " must be kinematic or dynamic");
      }
    }
  }
  return PartBinding{std::move(constraint_name), kind, body1, body2};
}

BodyPair PairInBlock(BodyBlocks& bodies, const PartBinding& binding,
                     std::size_t block) {
  return BodyPair{&bodies.lanes(block, binding.body1),
                  bodies.motion_type(binding.body1),
                  &bodies.lanes(block, binding.body2),
                  bodies.motion_type(binding.body2)};
}

}  // namespace manyworlds
