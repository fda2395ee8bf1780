#include "batch/contact_plan.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <utility>
#include <variant>

#include "batch/scene_checks.h"

namespace manyworlds {
namespace {

ContactShape ShapeOf(const ShapeSettings& s) {
  ContactShape shape;
  shape.type = s.type;
  shape.radius = s.radius;
  shape.half_height = s.half_height;
  shape.half_extents = s.half_extents;
  shape.position = s.position;
  shape.rotation = Normalized(s.rotation);
  return shape;
}

// The largest distance of the shape's points from the body's centre of mass.
float ReachOf(const ShapeSettings& s) {
  const double centre = Length(s.position);
  switch (s.type) {
    case ShapeType::kSphere: return float(centre + s.radius);
    case ShapeType::kCapsule: return float(centre + s.half_height + s.radius);
    case ShapeType::kBox:
      return float(centre + Length(s.half_extents));
    default: return 0.0f;
  }
}

// The pairs of bodies a constraint joins (lower index first).
std::set<std::pair<std::size_t, std::size_t>> JoinedBodies(const Scene& scene) {
  std::set<std::pair<std::size_t, std::size_t>> joined;
  for (const ConstraintSettings& constraint : scene.constraints()) {
    std::visit(
        [&](const auto& c) {
          joined.insert({std::min(c.body1, c.body2), std::max(c.body1, c.body2)});
        },
        constraint);
  }
  return joined;
}

}  // namespace

const char* ContactPairKindName(ContactPairKind kind) {
  switch (kind) {
    case ContactPairKind::kPlaneSphere: return "plane-sphere";
    case ContactPairKind::kPlaneCapsule: return "plane-capsule";
    case ContactPairKind::kPlaneBox: return "plane-box";
    case ContactPairKind::kSphereSphere: return "sphere-sphere";
    case ContactPairKind::kSphereCapsule: return "sphere-capsule";
    case ContactPairKind::kCapsuleCapsule: return "capsule-capsule";
    case ContactPairKind::kSphereBox: return "sphere-box";
    case ContactPairKind::kCapsuleBox: return "capsule-box";
    case ContactPairKind::kBoxBox: return "box-box";
  }
  return "?";
}

std::vector<ContactPlan> FindContactPairs(const Scene& scene) {
  std::vector<ContactPlan> contacts;
  const auto& bodies = scene.bodies();
  const auto joined = JoinedBodies(scene);
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    const ShapeSettings& a = bodies[i].shape;
    if (a.type == ShapeType::kNone) continue;
    for (std::size_t j = i + 1; j < bodies.size(); ++j) {
      const ShapeSettings& b = bodies[j].shape;
      if (b.type == ShapeType::kNone) continue;
      if ((a.collision_group & b.collision_mask) == 0 ||
          (b.collision_group & a.collision_mask) == 0) {
        continue;
      }
      if (bodies[i].motion_type != MotionType::kDynamic &&
          bodies[j].motion_type != MotionType::kDynamic) {
        continue;
      }
      if (joined.count({i, j}) != 0 && !a.collide_with_joined && !b.collide_with_joined) {
        continue;
      }
      ContactPlan c;
      c.label = "contact " + BodyLabel(scene, i) + " / " + BodyLabel(scene, j);
      c.body1 = i;
      c.body2 = j;
      c.motion1 = bodies[i].motion_type;
      c.motion2 = bodies[j].motion_type;
      c.shape1 = ShapeOf(a);
      c.shape2 = ShapeOf(b);
      c.reach1 = ReachOf(a);
      c.reach2 = ReachOf(b);
      const auto is = [&](ShapeType x, ShapeType y) {
        return (a.type == x && b.type == y) || (a.type == y && b.type == x);
      };
      if (is(ShapeType::kPlane, ShapeType::kSphere)) {
        c.kind = ContactPairKind::kPlaneSphere;
        c.point_count = 1;
      } else if (is(ShapeType::kPlane, ShapeType::kCapsule)) {
        c.kind = ContactPairKind::kPlaneCapsule;
        c.point_count = 2;
      } else if (is(ShapeType::kPlane, ShapeType::kBox)) {
        c.kind = ContactPairKind::kPlaneBox;
        c.point_count = 4;
      } else if (is(ShapeType::kSphere, ShapeType::kSphere)) {
        c.kind = ContactPairKind::kSphereSphere;
        c.point_count = 1;
      } else if (is(ShapeType::kSphere, ShapeType::kCapsule)) {
        c.kind = ContactPairKind::kSphereCapsule;
        c.point_count = 1;
      } else if (is(ShapeType::kCapsule, ShapeType::kCapsule)) {
        c.kind = ContactPairKind::kCapsuleCapsule;
        c.point_count = 1;
      } else if (is(ShapeType::kSphere, ShapeType::kBox)) {
        c.kind = ContactPairKind::kSphereBox;
        c.point_count = 1;
      } else if (is(ShapeType::kCapsule, ShapeType::kBox)) {
        c.kind = ContactPairKind::kCapsuleBox;
        c.point_count = 2;
      } else {
        // Two boxes: two planes never get here (both are static).
        c.kind = ContactPairKind::kBoxBox;
        c.point_count = 4;
      }
      c.friction = float(std::sqrt(double(a.friction) * double(b.friction)));
      c.restitution = std::max(a.restitution, b.restitution);
      contacts.push_back(std::move(c));
    }
  }
  return contacts;
}

}  // namespace manyworlds
