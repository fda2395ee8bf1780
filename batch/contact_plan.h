// Which shapes of a scene may touch (docs/contacts.md, "Which pairs make
// contacts"): one contact slot per pair, in the order of the bodies' indices,
// solved after every joint. The shapes are the same in every world, so their
// sizes and frames are plan constants.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "manyworlds/motion_type.h"
#include "manyworlds/scene.h"

namespace manyworlds {

// The shape pairs the step can collide (body order aside).
enum class ContactPairKind : std::uint8_t {
  kPlaneSphere,
  kPlaneCapsule,
  kPlaneBox,
  kSphereSphere,
  kSphereCapsule,
  kCapsuleCapsule,
  kSphereBox,
  kCapsuleBox,
  kBoxBox,
};
const char* ContactPairKindName(ContactPairKind kind);
// A plane with a sphere, capsule or box (else two of sphere, capsule, box).
inline bool IsPlanePair(ContactPairKind kind) {
  return kind == ContactPairKind::kPlaneSphere || kind == ContactPairKind::kPlaneCapsule ||
         kind == ContactPairKind::kPlaneBox;
}

// A shape as the collision routines read it: its frame in its body's
// centre-of-mass frame (rotation normalised) and its sizes.
struct ContactShape {
  ShapeType type = ShapeType::kNone;
  float radius = 0.0f, half_height = 0.0f;
  Float3 half_extents{0, 0, 0};
  Float3 position{0, 0, 0};
  Quaternion rotation{0, 0, 0, 1};
};

struct ContactPlan {
  std::string label;          // "contact <body> / <body>", for messages and the plan
  std::size_t body1, body2;   // body1 < body2: the normal points from 1 to 2
  MotionType motion1, motion2;
  ContactPairKind kind;
  ContactShape shape1, shape2;  // body 1's and body 2's
  // How far each shape reaches from its body's centre of mass (m; a plane:
  // 0, only static bodies have one): bounds a point's speed by |w| reach.
  float reach1 = 0.0f, reach2 = 0.0f;
  float friction, restitution;  // combined: sqrt(mu1 mu2), max(e1, e2)
  std::size_t point_count;  // points reserved: on a plane sphere 1, capsule 2, box 4;
                            // sphere and capsule pairs 1; a box with a sphere 1,
                            // a capsule 2, a box 4
  std::size_t offset = 0;         // ContactLanes in the block
  std::size_t points_offset = 0;  // point_count ContactPointLanes, one after another
  std::size_t motion_offset1 = static_cast<std::size_t>(-1);  // dynamic bodies' forces
  std::size_t motion_offset2 = static_cast<std::size_t>(-1);
};

// The contact slots of a checked scene (bodies and constraints valid), in
// solve order, without their block offsets.
std::vector<ContactPlan> FindContactPairs(const Scene& scene);

}  // namespace manyworlds
