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
  // Allowed degrees of freedom (Jolt's EAllowedDOFs, spec 4.3): 1 where the body
  // may translate / rotate along that world axis, 0 where it is locked.
  Vec3<T> translation_mask = Vec3<T>::Ones();
  Vec3<T> rotation_mask = Vec3<T>::Ones();

  bool IsDynamic() const { return motion_type == MotionType::kDynamic; }
  bool IsStatic() const { return motion_type == MotionType::kStatic; }

  // Velocities as the parts read them: a static body has none, whatever is stored
  // (Jolt's static bodies have no motion properties at all).
  Vec3<T> LinearVelocity() const { return IsStatic() ? Vec3<T>::Zero() : linear_velocity; }
  Vec3<T> AngularVelocity() const { return IsStatic() ? Vec3<T>::Zero() : angular_velocity; }

  // v with the components of the locked world axes set to exactly zero.
  static Vec3<T> Lock(const Vec3<T>& v, const Vec3<T>& mask) {
    Vec3<T> locked = v;
    for (int i = 0; i < 3; ++i) {
      if (mask[i] == T(0)) locked[i] = T(0);
    }
    return locked;
  }
  // Jolt's LockTranslation / LockAngular.
  Vec3<T> LockTranslation(const Vec3<T>& v) const { return Lock(v, translation_mask); }
  Vec3<T> LockAngular(const Vec3<T>& v) const { return Lock(v, rotation_mask); }

  // World-space inverse inertia from the current rotation (spec 1.4), matrix form,
  // with the rows and columns of locked rotation axes zeroed (spec 4.3).
  Mat33<T> InverseInertia() const {
    Mat33<T> inverse = WorldInverseInertia(rotation, inertia_rotation, inv_inertia_diagonal);
    for (int i = 0; i < 3; ++i) {
      if (rotation_mask[i] != T(0)) continue;
      inverse.row(i).setZero();
      inverse.col(i).setZero();
    }
    return inverse;
  }

  // I^-1 v from the current rotation, vector form (spec 1.4): the input and the
  // output masked by the allowed rotation axes (spec 4.3).
  Vec3<T> MultiplyInverseInertia(const Vec3<T>& v) const {
    return LockAngular(MultiplyWorldInverseInertia(rotation, inertia_rotation,
                                                   inv_inertia_diagonal, LockAngular(v)));
  }

  // Velocity steps of the parts (spec 1.1): the linear velocity is written only
  // through these, v ← lockT(v ± dv); angular velocity needs no mask (the
  // inverse inertia that produced the increment is masked).
  void AddLinearVelocityStep(const Vec3<T>& dv) {
    linear_velocity = LockTranslation(linear_velocity + dv);
  }
  void SubLinearVelocityStep(const Vec3<T>& dv) {
    linear_velocity = LockTranslation(linear_velocity - dv);
  }

  // Position-phase steps (spec 1.2), x ← x ± lockT(dx). They do not check the
  // motion type: the parts only call them for the bodies they are allowed to move.
  void AddPositionStep(const Vec3<T>& dx) { position += LockTranslation(dx); }
  void SubPositionStep(const Vec3<T>& dx) { position -= LockTranslation(dx); }
  void AddRotationStep(const Vec3<T>& theta) { reference::AddRotationStep(rotation, theta); }
  void SubRotationStep(const Vec3<T>& theta) {
    const Vec3<T> minus_theta = -theta;
    reference::AddRotationStep(rotation, minus_theta);
  }
};

}  // namespace manyworlds::reference
