// One rigid body of one world, as the scalar reference sees it (spec 4.3).
//
// Plain data plus the few accessors the constraint parts go through. Every Eigen
// member is initialised explicitly because Eigen leaves matrices uninitialised.
// Mass properties are stored for every motion type; the parts decide per spec 1.5
// whether to use them (most ignore them for static and kinematic bodies).
#pragma once

#include "manyworlds/motion_type.h"
#include "reference/math.h"

namespace manyworlds::reference {

template <class T>
struct Body {
  Vec3<T> position = Vec3<T>::Zero();  // centre of mass, world space
  Quat<T> rotation = Quat<T>::Identity();
  Vec3<T> linear_velocity = Vec3<T>::Zero();
  Vec3<T> angular_velocity = Vec3<T>::Zero();
  T inv_mass = T(0);
  Vec3<T> inv_inertia_diagonal = Vec3<T>::Zero();  // D in I_body^-1 = R_I D R_I^T
  Quat<T> inertia_rotation = Quat<T>::Identity();  // R_I, principal axes in body space
  MotionType motion_type = MotionType::kDynamic;

  bool IsDynamic() const { return motion_type == MotionType::kDynamic; }
  bool IsStatic() const { return motion_type == MotionType::kStatic; }

  // Velocities as the parts read them: a static body has none, whatever is stored
  // (Jolt's static bodies have no motion properties at all).
  Vec3<T> LinearVelocity() const { return IsStatic() ? Vec3<T>::Zero() : linear_velocity; }
  Vec3<T> AngularVelocity() const { return IsStatic() ? Vec3<T>::Zero() : angular_velocity; }

  // World-space inverse inertia from the current rotation (spec 1.4), matrix form.
  Mat33<T> InverseInertia() const {
    return WorldInverseInertia(rotation, inertia_rotation, inv_inertia_diagonal);
  }

  // I^-1 v from the current rotation, vector form (spec 1.4).
  Vec3<T> MultiplyInverseInertia(const Vec3<T>& v) const {
    return MultiplyWorldInverseInertia(rotation, inertia_rotation, inv_inertia_diagonal, v);
  }

  // Position-phase steps (spec 1.2). They do not check the motion type: the parts
  // only call them for the bodies they are allowed to move.
  void AddPositionStep(const Vec3<T>& dx) { position += dx; }
  void SubPositionStep(const Vec3<T>& dx) { position -= dx; }
  void AddRotationStep(const Vec3<T>& theta) { reference::AddRotationStep(rotation, theta); }
  void SubRotationStep(const Vec3<T>& theta) {
    const Vec3<T> minus_theta = -theta;
    reference::AddRotationStep(rotation, minus_theta);
  }
};

}  // namespace manyworlds::reference
