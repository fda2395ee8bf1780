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
  const double length = std::sqrt(double(s.rotation[0]) * s.rotation[0] +
                                  double(s.rotation[1]) * s.rotation[1] +
                                  double(s.rotation[2]) * s.rotation[2] +
                                  double(s.rotation[3]) * s.rotation[3]);
  for (int i = 0; i < 4; ++i) shape.rotation[i] = float(s.rotation[i] / length);
  return shape;
}

const char* ShapeTypeName(ShapeType type) {
  switch (type) {
    case ShapeType::kNone: return "none";
    case ShapeType::kSphere: return "sphere";
    case ShapeType::kCapsule: return "capsule";
    case ShapeType::kBox: return "box";
    case ShapeType::kPlane: return "plane";
  }
  return "?";
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
      const bool a_plane = a.type == ShapeType::kPlane;
      const bool b_plane = b.type == ShapeType::kPlane;
      if (a_plane == b_plane) {
        Refuse(c.label, "shape.type",
               std::string("pairs a ") + ShapeTypeName(a.type) + " with a " +
                   ShapeTypeName(b.type) +
                   ", which contacts do not collide yet (only a plane with a sphere, "
                   "capsule or box): put the two in collision groups that do not meet");
      }
      c.plane_is_body1 = a_plane;
      c.plane = ShapeOf(a_plane ? a : b);
      c.shape = ShapeOf(a_plane ? b : a);
      switch (c.shape.type) {
        case ShapeType::kSphere: c.kind = ContactPairKind::kPlaneSphere; c.point_count = 1; break;
        case ShapeType::kCapsule: c.kind = ContactPairKind::kPlaneCapsule; c.point_count = 2; break;
        default: c.kind = ContactPairKind::kPlaneBox; c.point_count = 4; break;
      }
      c.friction = float(std::sqrt(double(a.friction) * double(b.friction)));
      c.restitution = std::max(a.restitution, b.restitution);
      contacts.push_back(std::move(c));
    }
  }
  return contacts;
}

}  // namespace manyworlds
