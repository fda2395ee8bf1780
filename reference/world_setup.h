// Scene conversion for the scalar reference world (reference/world.h): turns the
// float settings of a manyworlds::Scene into reference bodies, per-body motion
// settings and the body-space geometry every constraint type needs.
//
// What is converted, and how (spec 3 intro, 4.3):
//
//   Body:   inverse mass m⁻¹ = 1/mass and inverse inertia diagonal D = 1/I for
//           dynamic bodies; static and kinematic bodies get m⁻¹ = 0 and D = 0
//           (every part ignores their mass, spec 1.5 and 7). A static body has no
//           velocity, whatever the settings say. Rotations are normalised.
//           Allowed DOFs (spec 4.3): per-axis masks on the body; m⁻¹ = 0 without
//           any allowed translation, D = 0 without any allowed rotation; the
//           initial velocities are locked.
//
//   Points and axes given in world space are converted ONCE, with the bodies'
//   poses at scene creation, into body-COM space:
//
//           local point = Rᵀ (p − x),   local axis = normalize(Rᵀ a)
//
//   (Rᵀ = rotation by q*). Points given in LocalToBodyCOM space are taken as they
//   are, axes are normalised as Jolt does.
//
//   Auto-detected anchor (Fixed, Slider; world space only): the inverse-mass-
//   weighted average of the two centres of mass. If one body is static, the
//   other's COM; if neither has an inverse mass (e.g. two kinematic bodies),
//   body 1's COM. With m⁻¹ = 0 for kinematic bodies a kinematic–dynamic pair
//   anchors at the dynamic body's COM.
//
//   r0⁻¹ from constraint frames (spec 2.6): from the frames of the settings, and,
//   when those are world-space frames, r0⁻¹ ← q20*·r0⁻¹·q10 with the creation
//   rotations (InvInitialOrientationFromWorldSpace).
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

#include "manyworlds/scene.h"
#include "manyworlds/spring_settings.h"
#include "reference/body.h"
#include "reference/math.h"
#include "reference/rotation_euler_part.h"
#include "reference/spring_part.h"

namespace manyworlds::reference {

// ---- plain conversions from the scene's float arrays ----

template <class T>
Vec3<T> ToVec3(const Float3& v) {
  return Vec3<T>(T(v[0]), T(v[1]), T(v[2]));
}

// Scene quaternions are (x, y, z, w); Eigen's constructor takes w first.
template <class T>
Quat<T> ToQuat(const Quaternion& q) {
  // Normalised, as the batch does: a scene's quaternion may be off unit by rounding.
  return Quat<T>(T(q[3]), T(q[0]), T(q[1]), T(q[2])).normalized();
}

template <class T>
SpringSettings<T> ToReferenceSpring(const manyworlds::SpringSettings& spring) {
  SpringSettings<T> out;
  switch (spring.mode) {
    case manyworlds::SpringMode::kFrequencyAndDamping:
      out.mode = SpringMode::kFrequencyAndDamping;
      break;
    case manyworlds::SpringMode::kStiffnessAndDamping:
      out.mode = SpringMode::kStiffnessAndDamping;
      break;
    case manyworlds::SpringMode::kMassNormalizedStiffnessAndDamping:
      out.mode = SpringMode::kMassNormalizedStiffnessAndDamping;
      break;
  }
  out.frequency_or_stiffness = T(spring.frequency_or_stiffness);
  out.damping = T(spring.damping);
  return out;
}

// ---- bodies ----

// What the integrator needs of a body besides its state (spec 4.1 step 1, 4.3),
// plus the force and torque the user set for the next step.
template <class T>
struct BodyMotionSettings {
  T linear_damping = T(0);
  T angular_damping = T(0);
  T max_linear_velocity = T(0);
  T max_angular_velocity = T(0);
  T gravity_factor = T(0);
  Vec3<T> force = Vec3<T>::Zero();   // world space, through the COM; cleared after a step
  Vec3<T> torque = Vec3<T>::Zero();
};

// 1/x, or 0 for x == 0. A dynamic body with a zero principal moment is refused by
// the batch; here it simply cannot rotate about that axis (D = 0 there).
template <class T>
T InverseOrZero(float x) {
  return x > 0.0f ? T(1) / T(x) : T(0);
}

template <class T>
Body<T> MakeBody(const BodySettings& settings) {
  Body<T> body;
  body.motion_type = settings.motion_type;
  body.position = ToVec3<T>(settings.position);
  // Normalised: a unit quaternion rounded to float is not exactly unit, and every
  // rotation formula here assumes |q| = 1 (Jolt asserts it).
  body.rotation = ToQuat<T>(settings.rotation).normalized();
  body.inertia_rotation = ToQuat<T>(settings.inertia_rotation).normalized();
  // Allowed DOFs (spec 4.3): bits 0-2 translation X/Y/Z, bits 3-5 rotation X/Y/Z.
  // A static body never moves, so it keeps the all-allowed masks.
  const unsigned dofs = static_cast<unsigned>(settings.allowed_dofs);
  const bool can_translate = AllowsTranslation(settings.allowed_dofs);
  const bool can_rotate = AllowsRotation(settings.allowed_dofs);
  if (settings.motion_type != MotionType::kStatic) {
    for (int axis = 0; axis < 3; ++axis) {
      body.translation_mask[axis] = (dofs >> axis) & 1u ? T(1) : T(0);
      body.rotation_mask[axis] = (dofs >> (axis + 3)) & 1u ? T(1) : T(0);
    }
    // Locked as Jolt's SetLinearVelocity / SetAngularVelocity do at creation.
    body.linear_velocity = body.LockTranslation(ToVec3<T>(settings.linear_velocity));
    body.angular_velocity = body.LockAngular(ToVec3<T>(settings.angular_velocity));
  }
  if (settings.motion_type == MotionType::kDynamic) {
    // Jolt's SetMassProperties: no allowed translation ⇒ m⁻¹ = 0; no allowed
    // rotation ⇒ D = 0 and an identity inertia rotation.
    if (can_translate) body.inv_mass = InverseOrZero<T>(settings.mass);
    if (can_rotate) {
      body.inv_inertia_diagonal =
          Vec3<T>(InverseOrZero<T>(settings.inertia_diagonal[0]),
                  InverseOrZero<T>(settings.inertia_diagonal[1]),
                  InverseOrZero<T>(settings.inertia_diagonal[2]));
    } else {
      body.inertia_rotation = Quat<T>::Identity();
    }
  }
  return body;
}

template <class T>
BodyMotionSettings<T> MakeBodyMotionSettings(const BodySettings& settings) {
  BodyMotionSettings<T> motion;
  motion.linear_damping = T(settings.linear_damping);
  motion.angular_damping = T(settings.angular_damping);
  motion.max_linear_velocity = T(settings.max_linear_velocity);
  motion.max_angular_velocity = T(settings.max_angular_velocity);
  motion.gravity_factor = T(settings.gravity_factor);
  return motion;
}

// ---- constraint geometry ----

// The two bodies of a constraint as they were when the scene was made: the poses
// that world-space settings refer to.
template <class T>
struct ConstraintBodies {
  const Body<T>& body1;
  const Body<T>& body2;
  ConstraintSpace space;

  bool world_space() const { return space == ConstraintSpace::kWorldSpace; }

  // Anchor relative to a body's COM in body space: Rᵀ (p − x) for world points.
  static Vec3<T> LocalPoint(const Body<T>& body, bool world, const Float3& point) {
    const Vec3<T> p = ToVec3<T>(point);
    return world ? Vec3<T>(body.rotation.conjugate() * (p - body.position)) : p;
  }
  // Unit axis in body space: normalize(Rᵀ a) for world axes.
  static Vec3<T> LocalAxis(const Body<T>& body, bool world, const Float3& axis) {
    const Vec3<T> a = ToVec3<T>(axis);
    return (world ? Vec3<T>(body.rotation.conjugate() * a) : a).normalized();
  }

  Vec3<T> LocalPoint1(const Float3& p) const { return LocalPoint(body1, world_space(), p); }
  Vec3<T> LocalPoint2(const Float3& p) const { return LocalPoint(body2, world_space(), p); }
  Vec3<T> LocalAxis1(const Float3& a) const { return LocalAxis(body1, world_space(), a); }
  Vec3<T> LocalAxis2(const Float3& a) const { return LocalAxis(body2, world_space(), a); }

  // r0⁻¹ from frames given in the settings' space (spec 2.6): the frame helper's
  // result, moved into body space for world-space frames.
  Quat<T> BodySpaceInvInitialOrientation(const Quat<T>& from_frames) const {
    if (!world_space()) return from_frames;
    return InvInitialOrientationFromWorldSpace(from_frames, body1.rotation, body2.rotation);
  }
};

// The anchor of an auto-detected Fixed or Slider constraint, in world space (see
// the header comment): a static body never moves, so the anchor sits on the other
// body; otherwise the lighter body pulls the anchor towards itself.
template <class T>
Vec3<T> AutoDetectedAnchor(const Body<T>& body1, const Body<T>& body2) {
  if (body1.IsStatic()) return body2.position;
  if (body2.IsStatic()) return body1.position;
  const T total_inv_mass = body1.inv_mass + body2.inv_mass;
  if (total_inv_mass == T(0)) return body1.position;
  return (body1.inv_mass * body1.position + body2.inv_mass * body2.position) / total_inv_mass;
}

// Anchors (body-space points of both bodies) of a Fixed or Slider constraint.
template <class T>
struct LocalAnchors {
  Vec3<T> point1;
  Vec3<T> point2;
};

template <class T>
LocalAnchors<T> FixedOrSliderAnchors(const ConstraintBodies<T>& bodies, bool auto_detect_point,
                                     const Float3& point1, const Float3& point2) {
  if (auto_detect_point && bodies.world_space()) {
    const Vec3<T> anchor = AutoDetectedAnchor(bodies.body1, bodies.body2);
    return {Vec3<T>(bodies.body1.rotation.conjugate() * (anchor - bodies.body1.position)),
            Vec3<T>(bodies.body2.rotation.conjugate() * (anchor - bodies.body2.position))};
  }
  return {bodies.LocalPoint1(point1), bodies.LocalPoint2(point2)};
}

// Body indices must name bodies of the scene; the reference refuses anything else
// with an exception (the batch gives the user-facing SceneError).
inline void CheckBodyIndices(std::size_t body1, std::size_t body2, std::size_t body_count,
                             std::size_t constraint) {
  if (body1 >= body_count || body2 >= body_count || body1 == body2) {
    throw std::invalid_argument("reference::World: constraint " + std::to_string(constraint) +
                                " has invalid body indices");
  }
}

}  // namespace manyworlds::reference
