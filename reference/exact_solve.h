// The exact joint solve of one world (JointSolver::kExact), as a dense
// solve: the oracle of batch/exact_solve-inl.h, which factors the same
// system sparsely in float.
//
// For the world's ball joints k (lever arms r1, r2 from the COMs at the
// current rotations, anchors p1 = x1 + r1, p2 = x2 + r2) and its dynamic
// bodies, J has the rows of C = p2 - p1: body 1 [-E, [r1]x], body 2
// [E, -[r2]x] (columns linear then angular velocity). Static and kinematic
// bodies are not unknowns (infinite mass); a kinematic body's velocity still
// enters J v. K = J M^-1 J^T, dense, factored by Eigen's LDL^T.
//
//   velocity:  lambda = K^-1 (-J v), v += M^-1 J^T lambda   (then J v = 0),
//              with each dynamic body's I replaced by I + G, G summing over
//              its joints  stiffness * max(0, s lambda_prev . r) (E - r^ r^T)
//              (s = -1 on body 1, lambda_prev the joint's impulse of the last
//              velocity solve, kept in `impulses`): the implicit geometric
//              stiffness of batch/exact_solve-inl.h
//   position:  up to `passes` times, while some |C_k| > tolerance:
//              lambda = K^-1 (-C) at the current poses,
//              x += m^-1 (J^T lambda)_linear,
//              q <- AddRotationStep(q, I^-1 (J^T lambda)_angular)
#pragma once

#include <Eigen/Dense>

#include <algorithm>
#include <cstddef>
#include <vector>

#include "reference/body.h"
#include "reference/math.h"
#include "reference/point_constraint.h"

namespace manyworlds::reference {

template <class T>
class ExactJointSolve {
 public:
  using Matrix = Eigen::Matrix<T, Eigen::Dynamic, Eigen::Dynamic>;
  using Vector = Eigen::Matrix<T, Eigen::Dynamic, 1>;

  // `impulses`: one per joint, the last velocity solve's, updated by
  // SolveVelocity (zero at first).
  ExactJointSolve(std::vector<Body<T>>& bodies, std::vector<const PointConstraint<T>*> joints,
                  std::vector<Vec3<T>>& impulses, T stiffness)
      : bodies_(bodies), joints_(std::move(joints)), impulses_(impulses), stiffness_(stiffness),
        column_(bodies.size(), kNotUnknown) {
    impulses_.resize(joints_.size(), Vec3<T>::Zero());
    for (std::size_t b = 0; b < bodies_.size(); ++b) {
      if (bodies_[b].IsDynamic()) column_[b] = 6 * dynamic_++;
    }
  }

  void SolveVelocity() {
    const Geometry g = Assemble(stiffness_);
    Vector b(3 * joints_.size());
    for (std::size_t k = 0; k < joints_.size(); ++k) {
      const PointConstraint<T>& joint = *joints_[k];
      const Body<T>& body1 = bodies_[joint.body1()];
      const Body<T>& body2 = bodies_[joint.body2()];
      const Vec3<T> v1 = body1.LinearVelocity() + body1.AngularVelocity().cross(g.r1[k]);
      const Vec3<T> v2 = body2.LinearVelocity() + body2.AngularVelocity().cross(g.r2[k]);
      b.template segment<3>(3 * k) = v1 - v2;  // -J v
    }
    const Vector lambda = g.k.ldlt().solve(b);
    for (std::size_t k = 0; k < joints_.size(); ++k) impulses_[k] = lambda.template segment<3>(3 * k);
    const Vector impulse = g.j.transpose() * lambda;
    for (std::size_t body = 0; body < bodies_.size(); ++body) {
      if (column_[body] == kNotUnknown) continue;
      Body<T>& bd = bodies_[body];
      bd.AddLinearVelocityStep(bd.inv_mass * impulse.template segment<3>(column_[body]));
      bd.angular_velocity += g.inverse_inertia[body] * impulse.template segment<3>(column_[body] + 3);
    }
  }

  // Returns the number of Newton steps taken.
  int SolvePosition(int passes, T tolerance) {
    int pass = 0;
    for (; pass < passes; ++pass) {
      const Geometry g = Assemble(T(0));
      Vector c(3 * joints_.size());
      bool converged = true;
      for (std::size_t k = 0; k < joints_.size(); ++k) {
        const Vec3<T> separation = bodies_[joints_[k]->body2()].position + g.r2[k] -
                                   bodies_[joints_[k]->body1()].position - g.r1[k];
        c.template segment<3>(3 * k) = separation;
        if (!(separation.squaredNorm() <= tolerance * tolerance)) converged = false;
      }
      if (converged) break;
      const Vector lambda = g.k.ldlt().solve(-c);
      const Vector impulse = g.j.transpose() * lambda;
      for (std::size_t body = 0; body < bodies_.size(); ++body) {
        if (column_[body] == kNotUnknown) continue;
        Body<T>& bd = bodies_[body];
        const Vec3<T> rotation =
            g.inverse_inertia[body] * impulse.template segment<3>(column_[body] + 3);
        bd.AddPositionStep(bd.inv_mass * impulse.template segment<3>(column_[body]));
        bd.AddRotationStep(rotation);
      }
    }
    return pass;
  }

 private:
  static constexpr std::size_t kNotUnknown = static_cast<std::size_t>(-1);

  struct Geometry {
    std::vector<Vec3<T>> r1, r2;
    std::vector<Mat33<T>> inverse_inertia;  // per body (dynamic ones), with G
    Matrix j, k;
  };

  Geometry Assemble(T stiffness) const {
    Geometry g;
    for (std::size_t k = 0; k < joints_.size(); ++k) {
      g.r1.push_back(bodies_[joints_[k]->body1()].rotation * joints_[k]->local_point1());
      g.r2.push_back(bodies_[joints_[k]->body2()].rotation * joints_[k]->local_point2());
    }
    g.inverse_inertia.resize(bodies_.size(), Mat33<T>::Zero());
    std::vector<Mat33<T>> stiffness_of(bodies_.size(), Mat33<T>::Zero());
    const auto pull = [&](std::size_t body, const Vec3<T>& r, T sign, const Vec3<T>& lambda) {
      const T w = stiffness * std::max(T(0), sign * lambda.dot(r));
      if (w > T(0)) stiffness_of[body] += w * (Mat33<T>::Identity() - r * r.transpose() / r.squaredNorm());
    };
    if (stiffness > T(0)) {
      for (std::size_t k = 0; k < joints_.size(); ++k) {
        if (column_[joints_[k]->body1()] != kNotUnknown) pull(joints_[k]->body1(), g.r1[k], T(-1), impulses_[k]);
        if (column_[joints_[k]->body2()] != kNotUnknown) pull(joints_[k]->body2(), g.r2[k], T(1), impulses_[k]);
      }
    }
    for (std::size_t body = 0; body < bodies_.size(); ++body) {
      if (column_[body] == kNotUnknown) continue;
      const Mat33<T> inverse = bodies_[body].InverseInertia();
      // (I + G)^-1 = I^-1 (E + G I^-1)^-1: no inverse of I needed.
      g.inverse_inertia[body] = inverse * (Mat33<T>::Identity() + stiffness_of[body] * inverse).inverse();
    }
    const std::size_t rows = 3 * joints_.size();
    g.j = Matrix::Zero(rows, 6 * dynamic_);
    Matrix inverse_mass = Matrix::Zero(6 * dynamic_, 6 * dynamic_);
    for (std::size_t body = 0; body < bodies_.size(); ++body) {
      if (column_[body] == kNotUnknown) continue;
      const std::size_t c = column_[body];
      inverse_mass.template block<3, 3>(c, c) = bodies_[body].inv_mass * Mat33<T>::Identity();
      inverse_mass.template block<3, 3>(c + 3, c + 3) = g.inverse_inertia[body];
    }
    for (std::size_t k = 0; k < joints_.size(); ++k) {
      const PointConstraint<T>& joint = *joints_[k];
      if (column_[joint.body1()] != kNotUnknown) {
        g.j.template block<3, 3>(3 * k, column_[joint.body1()]) = -Mat33<T>::Identity();
        g.j.template block<3, 3>(3 * k, column_[joint.body1()] + 3) = Cross(g.r1[k]);
      }
      if (column_[joint.body2()] != kNotUnknown) {
        g.j.template block<3, 3>(3 * k, column_[joint.body2()]) = Mat33<T>::Identity();
        g.j.template block<3, 3>(3 * k, column_[joint.body2()] + 3) = -Cross(g.r2[k]);
      }
    }
    g.k = g.j * inverse_mass * g.j.transpose();
    return g;
  }

  static Mat33<T> Cross(const Vec3<T>& r) {
    Mat33<T> m;
    m << T(0), -r.z(), r.y(), r.z(), T(0), -r.x(), -r.y(), r.x(), T(0);
    return m;
  }

  std::vector<Body<T>>& bodies_;
  std::vector<const PointConstraint<T>*> joints_;
  std::vector<Vec3<T>>& impulses_;
  T stiffness_;  // geometric stiffness factor x dt
  std::vector<std::size_t> column_;  // first column of each dynamic body in J
  std::size_t dynamic_ = 0;
};

}  // namespace manyworlds::reference
