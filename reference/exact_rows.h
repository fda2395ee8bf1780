// The equality rows of one world's constraints for the exact solve
// (reference/exact_solve.h), in double where T is double: the oracle of
// batch/exact_rows-inl.h, written from the same maths (see there) but on
// whole rows, with no padding and no special case for ball joints.
//
// Each row group holds J's rows on both bodies (columns: linear, then
// angular velocity of body 1, then of body 2) and the position error C,
// with dC/dt = J v.
#pragma once

#include <cstddef>
#include <vector>

#include "reference/body.h"
#include "reference/distance_constraint.h"
#include "reference/fixed_constraint.h"
#include "reference/gear_constraint.h"
#include "reference/hinge_constraint.h"
#include "reference/hinge_rotation_part.h"
#include "reference/math.h"
#include "reference/point_constraint.h"
#include "reference/rack_and_pinion_constraint.h"
#include "reference/slider_constraint.h"

namespace manyworlds::reference {

template <class T>
struct ExactRow {
  Vec3<T> linear1 = Vec3<T>::Zero(), angular1 = Vec3<T>::Zero();
  Vec3<T> linear2 = Vec3<T>::Zero(), angular2 = Vec3<T>::Zero();
  T error = T(0);
};

template <class T>
struct ExactRowGroup {
  std::size_t body1, body2;
  std::vector<ExactRow<T>> rows;
  // Point groups: the lever arms (their pulls make the geometric stiffness).
  bool point = false;
  Vec3<T> r1 = Vec3<T>::Zero(), r2 = Vec3<T>::Zero();
  std::size_t constraint = 0;  // its index in the scene (set by World::ExactRowGroups)
};

// C = p2 - p1:  J_i = [-e_i, -(r1 x e_i), e_i, r2 x e_i].
template <class T>
ExactRowGroup<T> PointRows(std::size_t b1, std::size_t b2, const std::vector<Body<T>>& bodies,
                           const Vec3<T>& local_point1, const Vec3<T>& local_point2) {
  ExactRowGroup<T> group{b1, b2, {}, true};
  group.r1 = bodies[b1].rotation * local_point1;
  group.r2 = bodies[b2].rotation * local_point2;
  const Vec3<T> separation =
      bodies[b2].position + group.r2 - bodies[b1].position - group.r1;
  for (int i = 0; i < 3; ++i) {
    const Vec3<T> e = Vec3<T>::Unit(i);
    group.rows.push_back({-e, -group.r1.cross(e), e, group.r2.cross(e), separation[i]});
  }
  return group;
}

// C = (a1 . b2, a1 . c2):  J_i = [0, -(e_i x a1), 0, e_i x a1].
template <class T>
ExactRowGroup<T> HingeRotationRows(const HingeConstraint<T>& hinge,
                                   const std::vector<Body<T>>& bodies) {
  const Body<T>& body1 = bodies[hinge.body1()];
  const Body<T>& body2 = bodies[hinge.body2()];
  const Vec3<T> a1 = body1.rotation * hinge.local_hinge_axis1();
  const HingeRotationBasis<T> basis =
      HingeRotationPerpendiculars(a1, Vec3<T>(body2.rotation * hinge.local_hinge_axis2()));
  ExactRowGroup<T> group{hinge.body1(), hinge.body2(), {}};
  for (const Vec3<T>& e : {basis.b2, basis.c2}) {
    const Vec3<T> axis = e.cross(a1);
    group.rows.push_back({Vec3<T>::Zero(), -axis, Vec3<T>::Zero(), axis, a1.dot(e)});
  }
  return group;
}

// C = 2 xyz(q2 r0^-1 q1*) with w >= 0:  J = [0, -E, 0, E].
template <class T>
ExactRowGroup<T> RotationRows(std::size_t b1, std::size_t b2, const std::vector<Body<T>>& bodies,
                              const Quat<T>& inv_initial_orientation) {
  Quat<T> diff = bodies[b2].rotation * inv_initial_orientation * bodies[b1].rotation.conjugate();
  if (diff.w() < T(0)) diff.coeffs() = -diff.coeffs();
  ExactRowGroup<T> group{b1, b2, {}};
  for (int i = 0; i < 3; ++i) {
    const Vec3<T> e = Vec3<T>::Unit(i);
    group.rows.push_back({Vec3<T>::Zero(), -e, Vec3<T>::Zero(), e, T(2) * diff.vec()[i]});
  }
  return group;
}

// The lever arms of a row between a constraint's two anchors (body space
// local_point1/2): r2, r1 + u = x2 + r2 - x1 (body 1's arm reaching body 2's
// anchor) and u = p2 - p1.
template <class T>
struct AnchorArms {
  Vec3<T> r2, r1_plus_u, u;
};
template <class T, class C>
AnchorArms<T> AnchorArmsOf(const C& c, const std::vector<Body<T>>& bodies) {
  const Body<T>& body1 = bodies[c.body1()];
  const Body<T>& body2 = bodies[c.body2()];
  AnchorArms<T> arms;
  arms.r2 = body2.rotation * c.local_point2();
  arms.r1_plus_u = body2.position + arms.r2 - body1.position;
  arms.u = arms.r1_plus_u - body1.rotation * c.local_point1();
  return arms;
}

// C_i = u . n_i:  J_i = [-n_i, -((r1 + u) x n_i), n_i, r2 x n_i].
template <class T>
ExactRowGroup<T> SliderAxesRows(const SliderConstraint<T>& slider,
                                const std::vector<Body<T>>& bodies) {
  const AnchorArms<T> arms = AnchorArmsOf(slider, bodies);
  ExactRowGroup<T> group{slider.body1(), slider.body2(), {}};
  for (const Vec3<T>& local : {slider.local_normal1(), slider.local_normal2()}) {
    const Vec3<T> n = bodies[slider.body1()].rotation * local;
    group.rows.push_back({-n, -arms.r1_plus_u.cross(n), n, arms.r2.cross(n), arms.u.dot(n)});
  }
  return group;
}

// C = |u| - l with n = u / |u| (the stored normal where u = 0):
// J = [-n, -((r1 + u) x n), n, r2 x n].
template <class T>
ExactRowGroup<T> DistanceRows(const DistanceConstraint<T>& rod,
                              const std::vector<Body<T>>& bodies) {
  const AnchorArms<T> arms = AnchorArmsOf(rod, bodies);
  const T length = arms.u.norm();
  const Vec3<T> n = length > T(0) ? Vec3<T>(arms.u / length) : rod.normal();
  ExactRowGroup<T> group{rod.body1(), rod.body2(), {}};
  group.rows.push_back(
      {-n, -arms.r1_plus_u.cross(n), n, arms.r2.cross(n), length - rod.min_distance()});
  return group;
}

// C = theta1 + r theta2:  J = [0, a, 0, r b].
template <class T>
ExactRowGroup<T> GearRows(const GearConstraint<T>& gear, const std::vector<Body<T>>& bodies,
                          T theta1, T theta2) {
  ExactRowGroup<T> group{gear.body1(), gear.body2(), {}};
  group.rows.push_back({Vec3<T>::Zero(), bodies[gear.body1()].rotation * gear.local_hinge_axis1(),
                        Vec3<T>::Zero(),
                        gear.ratio() * (bodies[gear.body2()].rotation * gear.local_hinge_axis2()),
                        theta1 + gear.ratio() * theta2});
  return group;
}

// C = theta1 - r d2:  J = [0, a, -r b, 0].
template <class T>
ExactRowGroup<T> RackAndPinionRows(const RackAndPinionConstraint<T>& rack,
                                   const std::vector<Body<T>>& bodies, T theta1, T d2) {
  ExactRowGroup<T> group{rack.body1(), rack.body2(), {}};
  group.rows.push_back({Vec3<T>::Zero(), bodies[rack.body1()].rotation * rack.local_hinge_axis1(),
                        -rack.ratio() * (bodies[rack.body2()].rotation * rack.local_slider_axis2()),
                        Vec3<T>::Zero(), theta1 - rack.ratio() * d2});
  return group;
}

}  // namespace manyworlds::reference
