// Binding a constraint part to two bodies of the scene, checked when the
// scene is built: a bad binding is refused with an error naming the
// constraint, the body and the rule it breaks, never discovered mid-step.
#pragma once

#include <cstddef>
#include <string>

#include "batch/world_blocks.h"
#include "kernels/body_lanes.h"

namespace manyworlds {

enum class PartKind {
  kAxis,
  kDualAxis,
  kPoint,
  kHingeRotation,
  kRotationEuler,
  kRotationQuat,
  kAngle,
  kRackAndPinion,
  kGear,
  kIndependentAxis,
  kSwingTwist,
};

const char* PartKindName(PartKind kind);

struct PartBinding {
  std::string constraint_name;
  PartKind kind;
  std::size_t body1;
  std::size_t body2;
};

// Throws SceneError if the bodies do not exist, are the same body, or have a
// motion type the part cannot work with (rack-and-pinion and gear: no static
// body, spec 1.5).
PartBinding BindPart(const BodyBlocks& bodies, std::string constraint_name,
                     PartKind kind, std::size_t body1, std::size_t body2);

// The two bodies of a binding in one block, ready for a kernel call.
BodyPair PairInBlock(BodyBlocks& bodies, const PartBinding& binding,
                     std::size_t block);

}  // namespace manyworlds
