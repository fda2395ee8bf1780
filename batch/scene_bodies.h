// The bodies the built-in scenes (batch/scenes.cc, batch/stress_scenes.cc)
// are made of: Jolt's body defaults except damping, which every built-in scene
// sets to 0 so that energy is a meaningful check.
#pragma once

#include <string>
#include <utility>

#include "manyworlds/scene.h"

namespace manyworlds::scene_bodies {

inline BodySettings Dynamic(std::string name, float mass, Float3 inertia, Float3 position,
                            Quaternion rotation = {0, 0, 0, 1}) {
  BodySettings body;
  body.name = std::move(name);
  body.motion_type = MotionType::kDynamic;
  body.mass = mass;
  body.inertia_diagonal = inertia;
  body.position = position;
  body.rotation = rotation;
  body.linear_damping = 0.0f;
  body.angular_damping = 0.0f;
  return body;
}

// The static world body every scene anchors its joints to, at the origin.
inline BodySettings StaticWorld() {
  BodySettings body;
  body.name = "world";
  body.motion_type = MotionType::kStatic;
  body.linear_damping = 0.0f;
  body.angular_damping = 0.0f;
  return body;
}

}  // namespace manyworlds::scene_bodies
