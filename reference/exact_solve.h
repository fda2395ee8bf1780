// The exact joint solve of one world (JointSolver::kExact), as a dense
// solve: the oracle of batch/exact_solve-inl.h, which factors the same
// system sparsely in float.
//
// The world's equality rows come as row groups (reference/exact_rows.h, J
// and C at the current poses; a function called whenever the poses have
// changed). J's columns are the dynamic bodies' linear then angular
// velocities; static and kinematic bodies are not unknowns (infinite mass),
// though a kinematic body's velocity still enters J v. K = J M^-1 J^T,
// dense, factored by Eigen's LDL^T.
//
//   velocity:  lambda = K^-1 (-J v), v += M^-1 J^T lambda   (then J v = 0),
//              with each dynamic body's I replaced by I + G, G summing over
//              its point groups  stiffness * max(0, s lambda_prev . r) (E - r^ r^T)
//              (s = -1 on body 1, lambda_prev the group's impulse of the last
//              velocity solve, kept in `impulses`): the implicit geometric
//              stiffness of batch/exact_system-inl.h
//   curvature: in a world whose joints are all equality row groups, after
//              the integration, v += w M~^-1 J^T K^-1 (C(q_n) - C) / dt
//              with the velocity solve's J, K and C(q_n) (CurvatureVelocity)
//   position:  up to `passes` times, while some group's |C| > tolerance:
//              lambda = K^-1 (-C) at the current poses,
//              x += s m^-1 (J^T lambda)_linear,
//              q <- AddRotationStep(q, s I^-1 (J^T lambda)_angular),
//              s = min(1, kExactMaxNewtonTurn / the largest |rotation step|)
//              then a Baumgarte step of every hard limit (continuing while
//              one moved)
// Motors, friction and limits are the world's (reference/world.h), solved
// around SolveVelocity as batch/exact_inequality_rows-inl.h says.
#pragma once

#include <Eigen/Dense>

#include <algorithm>
#include <cstddef>
#include <functional>
#include <vector>

#include "manyworlds/batch.h"
#include "reference/body.h"
#include "reference/exact_rows.h"
#include "reference/math.h"

namespace manyworlds::reference {

template <class T>
class ExactJointSolve {
 public:
  using Matrix = Eigen::Matrix<T, Eigen::Dynamic, Eigen::Dynamic>;
  using Vector = Eigen::Matrix<T, Eigen::Dynamic, 1>;
  using Rows = std::function<std::vector<ExactRowGroup<T>>()>;

  // `impulses`: one per group, the last velocity solve's (zero at first),
  // updated by SolveVelocity for point groups.
  ExactJointSolve(std::vector<Body<T>>& bodies, Rows rows, std::vector<Vec3<T>>& impulses,
                  T stiffness)
      : bodies_(bodies), rows_(std::move(rows)), impulses_(impulses), stiffness_(stiffness),
        column_(bodies.size(), kNotUnknown) {
    for (std::size_t b = 0; b < bodies_.size(); ++b) {
      if (bodies_[b].IsDynamic()) column_[b] = 6 * dynamic_++;
    }
  }

  // `accumulate`: a later pass of the block Gauss-Seidel around motors and
  // limits, with the rows, inertias and K of the first (the batch factors K
  // once per velocity phase); the point groups' impulses are then added to
  // `impulses` instead of replacing them.
  void SolveVelocity(bool accumulate = false) {
    if (!accumulate) velocity_geometry_ = Assemble(rows_(), stiffness_);
    const Geometry& g = velocity_geometry_;
    // -J v, kinematic bodies' velocities included.
    Vector b = Vector::Zero(g.j.rows());
    std::size_t row = 0;
    for (const ExactRowGroup<T>& group : g.groups) {
      const Body<T>& body1 = bodies_[group.body1];
      const Body<T>& body2 = bodies_[group.body2];
      for (const ExactRow<T>& r : group.rows) {
        b[row++] = -(r.linear1.dot(body1.LinearVelocity()) + r.angular1.dot(body1.AngularVelocity()) +
                     r.linear2.dot(body2.LinearVelocity()) + r.angular2.dot(body2.AngularVelocity()));
      }
    }
    const Vector lambda = g.k.ldlt().solve(b);
    row = 0;
    for (std::size_t k = 0; k < g.groups.size(); ++k) {
      if (g.groups[k].point) {
        const Vec3<T> impulse = lambda.template segment<3>(row);
        impulses_[k] = accumulate ? Vec3<T>(impulses_[k] + impulse) : impulse;
      }
      row += g.groups[k].rows.size();
    }
    const Vector impulse = g.j.transpose() * lambda;
    for (std::size_t body = 0; body < bodies_.size(); ++body) {
      if (column_[body] == kNotUnknown) continue;
      Body<T>& bd = bodies_[body];
      bd.AddLinearVelocityStep(bd.inv_mass * impulse.template segment<3>(column_[body]));
      bd.angular_velocity += g.inverse_inertia[body] * impulse.template segment<3>(column_[body] + 3);
    }
  }

  // Whether the last SolveVelocity without `accumulate` had any row group
  // (a world whose constraints are all solved whole has none).
  bool HasGroups() const { return !velocity_geometry_.groups.empty(); }

  // The curvature correction after the integration (batch/exact_solve-inl.h,
  // CurvatureVelocity), for a world whose joints are all equality row
  // groups: v += w s M~^-1 J^T K^-1 (C(q_n) - C(q~)) / dt with the last
  // velocity solve's J, K, inverse inertias M~ = (I + G)^-1 and errors
  // C(q_n), C(q~) at the current poses, s the
  // trust region's factor (no body's rotation step above
  // kExactMaxNewtonTurn) and w = clamp(2 - 2 t / kExactCurvatureTransverseLimit,
  // 0, 1), t the largest tr(G I^-1) over the dynamic bodies (G of this
  // step's impulses with factor dt).
  void CurvatureVelocity(T dt) {
    const Geometry& g = velocity_geometry_;
    if (g.groups.empty()) return;
    const std::vector<Mat33<T>> stiffness = GeometricStiffness(g.groups, dt);
    T hardest = T(0);
    for (std::size_t body = 0; body < bodies_.size(); ++body) {
      if (column_[body] == kNotUnknown) continue;
      hardest = std::max(hardest, (stiffness[body] * bodies_[body].InverseInertia()).trace());
    }
    const T weight =
        std::min(T(1), std::max(T(0), T(2) - T(2) * hardest / T(kExactCurvatureTransverseLimit)));
    if (!(weight > T(0))) return;
    // The drift C(q~) - C(q_n), C(q_n) from the velocity solve's rows.
    Vector drift(g.j.rows());
    std::size_t row = 0;
    for (const ExactRowGroup<T>& group : rows_()) {
      for (const ExactRow<T>& r : group.rows) drift[row++] = r.error;
    }
    row = 0;
    for (const ExactRowGroup<T>& group : g.groups) {
      for (const ExactRow<T>& r : group.rows) drift[row++] -= r.error;
    }
    const Vector impulse = g.j.transpose() * g.k.ldlt().solve(-drift);
    std::vector<Vec3<T>> rotations;
    const T factor = weight * RotationSteps(g, impulse, rotations) / dt;
    for (std::size_t body = 0; body < bodies_.size(); ++body) {
      if (column_[body] == kNotUnknown) continue;
      Body<T>& bd = bodies_[body];
      bd.AddLinearVelocityStep(factor * bd.inv_mass * impulse.template segment<3>(column_[body]));
      bd.angular_velocity += factor * rotations[body];
    }
  }

  // Returns the number of passes taken. `limits` takes one Baumgarte step of
  // every hard limit after each Newton step and says whether any moved
  // (batch/exact_inequality_rows-inl.h); `has_limits` whether there are any.
  int SolvePosition(int passes, T tolerance, const std::function<bool()>& limits,
                    bool has_limits) {
    bool limits_moved = has_limits;
    int pass = 0;
    for (; pass < passes; ++pass) {
      const Geometry g = Assemble(rows_(), T(0));
      Vector c(g.j.rows());
      bool converged = true;
      std::size_t row = 0;
      for (const ExactRowGroup<T>& group : g.groups) {
        T squared = T(0);
        for (const ExactRow<T>& r : group.rows) {
          c[row++] = r.error;
          squared += r.error * r.error;
        }
        if (!(squared <= tolerance * tolerance)) converged = false;
      }
      if (converged && !limits_moved) break;
      if (!converged) {
        const Vector lambda = g.k.ldlt().solve(-c);
        const Vector impulse = g.j.transpose() * lambda;
        std::vector<Vec3<T>> rotations;
        const T scale = RotationSteps(g, impulse, rotations);
        for (std::size_t body = 0; body < bodies_.size(); ++body) {
          if (column_[body] == kNotUnknown) continue;
          Body<T>& bd = bodies_[body];
          bd.AddPositionStep(scale * bd.inv_mass * impulse.template segment<3>(column_[body]));
          bd.AddRotationStep(scale * rotations[body]);
        }
      }
      limits_moved = has_limits && limits();
    }
    return pass;
  }

 private:
  static constexpr std::size_t kNotUnknown = static_cast<std::size_t>(-1);

  struct Geometry {
    std::vector<ExactRowGroup<T>> groups;
    std::vector<Mat33<T>> inverse_inertia;  // per body (dynamic ones), with G
    Matrix j, k;
  };

  // Per body, G = factor * sum over its point groups of max(0, s lambda . r)
  // (E - r^ r^T): r the lever arm, lambda the group's impulse of the last
  // velocity solve (impulses_, sized by Assemble), s = -1 on body 1.
  std::vector<Mat33<T>> GeometricStiffness(const std::vector<ExactRowGroup<T>>& groups,
                                           T factor) const {
    std::vector<Mat33<T>> g(bodies_.size(), Mat33<T>::Zero());
    if (!(factor > T(0))) return g;
    const auto pull = [&](std::size_t body, const Vec3<T>& r, T sign, const Vec3<T>& lambda) {
      const T w = factor * std::max(T(0), sign * lambda.dot(r));
      if (w > T(0)) g[body] += w * (Mat33<T>::Identity() - r * r.transpose() / r.squaredNorm());
    };
    for (std::size_t k = 0; k < groups.size(); ++k) {
      const ExactRowGroup<T>& group = groups[k];
      if (!group.point) continue;
      if (column_[group.body1] != kNotUnknown) pull(group.body1, group.r1, T(-1), impulses_[k]);
      if (column_[group.body2] != kNotUnknown) pull(group.body2, group.r2, T(1), impulses_[k]);
    }
    return g;
  }

  // Each dynamic body's rotation step I~^-1 (J^T lambda)_angular for the
  // impulse J^T lambda, into `rotations`, and the trust region's factor: no
  // body turns more than kExactMaxNewtonTurn, the whole step scaled by one
  // factor (1 if none would).
  T RotationSteps(const Geometry& g, const Vector& impulse,
                  std::vector<Vec3<T>>& rotations) const {
    rotations.assign(bodies_.size(), Vec3<T>::Zero());
    T largest = T(0);
    for (std::size_t body = 0; body < bodies_.size(); ++body) {
      if (column_[body] == kNotUnknown) continue;
      rotations[body] = g.inverse_inertia[body] * impulse.template segment<3>(column_[body] + 3);
      largest = std::max(largest, rotations[body].norm());
    }
    const T max_turn = T(kExactMaxNewtonTurn);
    return largest > max_turn ? max_turn / largest : T(1);
  }

  Geometry Assemble(std::vector<ExactRowGroup<T>> groups, T stiffness) const {
    Geometry g;
    g.groups = std::move(groups);
    impulses_.resize(g.groups.size(), Vec3<T>::Zero());  // zero before the first solve
    g.inverse_inertia.resize(bodies_.size(), Mat33<T>::Zero());
    const std::vector<Mat33<T>> stiffness_of = GeometricStiffness(g.groups, stiffness);
    for (std::size_t body = 0; body < bodies_.size(); ++body) {
      if (column_[body] == kNotUnknown) continue;
      const Mat33<T> inverse = bodies_[body].InverseInertia();
      // (I + G)^-1 = I^-1 (E + G I^-1)^-1: no inverse of I needed.
      g.inverse_inertia[body] = inverse * (Mat33<T>::Identity() + stiffness_of[body] * inverse).inverse();
    }
    std::size_t rows = 0;
    for (const ExactRowGroup<T>& group : g.groups) rows += group.rows.size();
    g.j = Matrix::Zero(rows, 6 * dynamic_);
    Matrix inverse_mass = Matrix::Zero(6 * dynamic_, 6 * dynamic_);
    for (std::size_t body = 0; body < bodies_.size(); ++body) {
      if (column_[body] == kNotUnknown) continue;
      const std::size_t c = column_[body];
      // m^-1 along the free translation axes only (the steps lock the others).
      inverse_mass.template block<3, 3>(c, c) =
          bodies_[body].inv_mass * Mat33<T>(bodies_[body].translation_mask.asDiagonal());
      inverse_mass.template block<3, 3>(c + 3, c + 3) = g.inverse_inertia[body];
    }
    std::size_t row = 0;
    for (const ExactRowGroup<T>& group : g.groups) {
      for (const ExactRow<T>& r : group.rows) {
        if (column_[group.body1] != kNotUnknown) {
          g.j.template block<1, 3>(row, column_[group.body1]) = r.linear1.transpose();
          g.j.template block<1, 3>(row, column_[group.body1] + 3) = r.angular1.transpose();
        }
        if (column_[group.body2] != kNotUnknown) {
          g.j.template block<1, 3>(row, column_[group.body2]) += r.linear2.transpose();
          g.j.template block<1, 3>(row, column_[group.body2] + 3) += r.angular2.transpose();
        }
        ++row;
      }
    }
    g.k = g.j * inverse_mass * g.j.transpose();
    return g;
  }

  std::vector<Body<T>>& bodies_;
  Rows rows_;
  Geometry velocity_geometry_;  // of the last SolveVelocity without `accumulate`
  std::vector<Vec3<T>>& impulses_;
  T stiffness_;  // geometric stiffness factor x dt
  std::vector<std::size_t> column_;  // first column of each dynamic body in J
  std::size_t dynamic_ = 0;
};

}  // namespace manyworlds::reference
