// Contact constraint of the reference world: one slot, a pair of bodies with
// shapes (body 1 the lower index), solved after the joints in every phase of a
// substep as Jolt solves its contact manifolds (docs/contacts.md, which follows
// ../shared/docs/jolt-contacts.md §3-§6 in its snapshot friction model).
// Scalar reference, written from those texts; nothing of batch/ or kernels/.
//
// Supported pairs: a plane (static body) with a sphere, capsule or box; every
// pair of spheres, capsules and boxes (any motion types, one dynamic). Their
// points come from reference/contact_points.h (planes, spheres and capsules)
// and reference/box_contact_points.h (a box with a sphere, capsule or box).
//
// ---- Rows (Jolt's snapshot model) ----
// Per kept point i, at the midpoint p_i = (p1_i + p2_i)/2, r1 = p_i − x1,
// r2 = p_i − x2:
//   normal:   K = m1⁻¹ + (r1×n)·I1⁻¹(r1×n) + m2⁻¹ + (r2×n)·I2⁻¹(r2×n)
//             (dynamic bodies only), m_eff = 1/K (K = 0: inactive, Λ = 0)
//             v_n = (v2 + ω2×r2 − v1 − ω1×r1)·n, b_spec = max(0, s/dt)
//             b = e (v_n − Δv_f) if e > 0, v_n < −v_min_restitution and
//             v_n < −b_spec; else b = b_spec.
//             Δv_f = min(0, dt a_rel·n), a_rel = a2 − a1, a = γ g + m⁻¹ F for
//             a dynamic body, 0 otherwise (the velocity the substep's forces
//             added, so a bounce uses the approach speed before them).
// Friction (μ > 0): one anchor c = mean of the midpoints; t1 = perp(n),
// t2 = n × t1; two linear rows at c (b = 0); with ≥ 2 points an angular row
// about n, K_a = n·I1⁻¹n + n·I2⁻¹n. d_i = |(p_i − c) − ((p_i − c)·n) n|.
//
// Each row (axis u, levers a1, a2; the angular row has u = 0, a1 = a2 = n):
//   ċ = u·(v2 − v1) + a2·ω2 − a1·ω1,  Λ* = Λ + m_eff (−ċ − b)
//   Δ = Λ_new − Λ:  v1 −= Δ m1⁻¹ u, ω1 −= Δ I1⁻¹a1, v2 += Δ m2⁻¹ u, ω2 += Δ I2⁻¹a2
//
// Velocity pass: L = μ Σ Λn_i, A = μ Σ d_i Λn_i (impulses so far); both
// linear friction Λ* from the same velocities, scaled together onto the circle
// |Λt| ≤ L; angular Λa = clamp(Λa*, −A, A); then each normal Λn = max(0, Λn*).
// The bodies' velocities are read once, updated as rows are solved and written
// back once (linear DOF mask at write-back), jolt-contacts.md §5.2.
//
// Warm start (ratio ρ): t1, t2, angular, normals in point order: Λ ← ρΛ, apply.
// Persistence (to the next substep): a point takes the normal impulse of the
// first of last substep's points whose body-local points (each body's COM
// frame) are both within 1 cm of its own; friction impulses carry over when
// the manifold existed last substep.
//
// Position pass, point by point, with the setup's n and body-local points:
// p1, p2 from the transforms when this slot's pass starts, C = max(s + slop,
// −max_penetration); if C < 0: r from the midpoint to the CURRENT centres of
// mass, K with the current rotations, λ = −β C / K, x1 −= λ m1⁻¹ n,
// q1 ← rotate(−λ I1⁻¹(r1×n)), x2 += λ m2⁻¹ n, q2 ← rotate(λ I2⁻¹(r2×n)).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <stdexcept>
#include <tuple>
#include <utility>

#include "manyworlds/scene.h"
#include "reference/body.h"
#include "reference/box_contact_points.h"
#include "reference/contact_points.h"
#include "reference/math.h"
#include "reference/solver_state.h"
#include "reference/world_setup.h"

namespace manyworlds::reference {

// StepSettings' contact fields in T (docs/contacts.md, Settings).
template <class T>
struct ContactSettings {
  T speculative_contact_distance = T(0.02);
  T penetration_slop = T(0.02);
  T max_penetration_distance = T(0.2);
  T min_velocity_for_restitution = T(1);
  // StepSettings::speculative_contacts_from_velocity: D grows by the
  // shapes' approach in the substep (docs/contacts.md, "Settings").
  bool from_velocity = false;
};

template <class T>
class ContactConstraint {
 public:
  // Bodies body1 < body2 (scene indices) and their shapes: a plane with a
  // sphere, capsule or box (either way round), or two of sphere, capsule, box.
  // μ = sqrt(μ1 μ2), e = max(e1, e2).
  ContactConstraint(std::size_t body1, std::size_t body2, const ShapeSettings& shape1,
                    const ShapeSettings& shape2)
      : body1_(body1),
        body2_(body2),
        shape1_(MakeContactShape<T>(shape1)),
        shape2_(MakeContactShape<T>(shape2)),
        plane_is_body1_(shape1.type == ShapeType::kPlane),
        friction_(std::sqrt(T(shape1.friction) * T(shape2.friction))),
        restitution_(std::max(T(shape1.restitution), T(shape2.restitution))) {
    if (IsPlanePair(shape1.type, shape2.type)) {
      kind_ = PairKind::kPlane;
    } else if (IsRound(shape1.type) && IsRound(shape2.type)) {
      kind_ = PairKind::kRound;
    } else if (IsSolid(shape1.type) && IsSolid(shape2.type)) {
      kind_ = PairKind::kBox;
    } else {
      throw std::invalid_argument(
          "reference::ContactConstraint: only a plane with a sphere, capsule or box, or two "
          "of sphere, capsule and box");
    }
  }

  // Whether a slot of these two shape types (either order) is supported.
  static bool Supports(ShapeType type1, ShapeType type2) {
    return IsPlanePair(type1, type2) || (IsSolid(type1) && IsSolid(type2));
  }

  // The most points the slot can hold in a substep: plane with a sphere 1,
  // with a capsule 2, with a box 4; two spheres or capsules 1; a box with a
  // sphere 1, with a capsule 2, with a box 4.
  int MaxPointCount() const {
    if (kind_ == PairKind::kRound) return 1;
    const bool other_is_body2 =
        kind_ == PairKind::kPlane ? plane_is_body1_ : shape1_.type == ShapeType::kBox;
    switch ((other_is_body2 ? shape2_ : shape1_).type) {
      case ShapeType::kSphere: return 1;
      case ShapeType::kCapsule: return 2;
      default: return 4;  // the box
    }
  }

  std::size_t body1() const { return body1_; }
  std::size_t body2() const { return body2_; }

  // Points and rows from the poses at the start of the substep and the
  // velocities after its forces; motion1/2 give the gravity factors and forces
  // of the restitution's Δv_f. Carries the last substep's impulses over.
  void Setup(const Body<T>& body1, const BodyMotionSettings<T>& motion1, const Body<T>& body2,
             const BodyMotionSettings<T>& motion2, T dt, const Vec3<T>& gravity,
             const ContactSettings<T>& settings) {
    // Last substep's manifold, for point matching and the friction carry-over.
    const int old_count = count_;
    const std::array<Vec3<T>, kMaxContactPoints> old_local1 = local1_;
    const std::array<Vec3<T>, kMaxContactPoints> old_local2 = local2_;
    std::array<T, kMaxContactPoints> old_lambda{};
    for (int i = 0; i < kMaxContactPoints; ++i) old_lambda[i] = normal_[i].lambda;
    const bool existed = old_count > 0;
    const T old_t1 = tangent1_.lambda, old_t2 = tangent2_.lambda, old_a = angular_.lambda;

    count_ = 0;
    normal_direction_.setZero();
    for (Row& row : normal_) row = Row{};
    tangent1_ = Row{};
    tangent2_ = Row{};
    angular_ = Row{};
    friction_active_ = false;

    // ---- points (count_, normal_direction_, point1_, point2_)
    switch (kind_) {
      case PairKind::kPlane: FindPlanePoints(body1, body2, settings, dt); break;
      case PairKind::kRound: FindRoundPoint(body1, body2, settings, dt); break;
      case PairKind::kBox: FindBoxPoints(body1, body2, settings, dt); break;
    }
    if (count_ == 0) return;  // no manifold this substep
    const Vec3<T>& n = normal_direction_;

    // ---- normal rows, with the impulse of the matching old point
    const Vec3<T> v_rel_linear = body2.LinearVelocity() - body1.LinearVelocity();
    const Vec3<T> a_rel = Acceleration(body2, motion2, gravity) - Acceleration(body1, motion1, gravity);
    const T gravity_dv = std::min(T(0), dt * a_rel.dot(n));  // Δv_f
    for (int i = 0; i < count_; ++i) {
      local1_[i] = body1.rotation.conjugate() * (point1_[i] - body1.position);
      local2_[i] = body2.rotation.conjugate() * (point2_[i] - body2.position);
      const Vec3<T> p = (point1_[i] + point2_[i]) / T(2);
      const Vec3<T> r1 = p - body1.position;
      const Vec3<T> r2 = p - body2.position;
      Row& row = normal_[i];
      row = LinearRow(body1, r1, body2, r2, n);
      separation_[i] = (point2_[i] - point1_[i]).dot(n);
      const T v_n = n.dot(v_rel_linear) + body2.AngularVelocity().cross(r2).dot(n) -
                    body1.AngularVelocity().cross(r1).dot(n);
      const T speculative_bias = std::max(T(0), separation_[i] / dt);
      row.bias = speculative_bias;
      if (restitution_ > T(0) && v_n < -settings.min_velocity_for_restitution &&
          v_n < -speculative_bias) {
        // The gap closes within this substep: bounce off the approach speed
        // the bodies had before this substep's gravity and forces.
        row.bias = restitution_ * (v_n - gravity_dv);
      }
      if (row.effective_mass != T(0)) {
        for (int j = 0; j < old_count; ++j) {
          if ((local1_[i] - old_local1[j]).squaredNorm() <= T(1e-4) &&
              (local2_[i] - old_local2[j]).squaredNorm() <= T(1e-4)) {
            row.lambda = old_lambda[j];
            break;
          }
        }
      }
    }

    // ---- friction at one anchor (snapshot model)
    if (friction_ > T(0)) {
      friction_active_ = true;
      anchor_.setZero();
      for (int i = 0; i < count_; ++i) anchor_ += (point1_[i] + point2_[i]) / T(2);
      anchor_ /= T(count_);
      for (int i = 0; i < count_; ++i) {
        const Vec3<T> offset = (point1_[i] + point2_[i]) / T(2) - anchor_;
        distance_[i] = (offset - offset.dot(n) * n).norm();
      }
      const Vec3<T> r1 = anchor_ - body1.position;
      const Vec3<T> r2 = anchor_ - body2.position;
      tangent1_direction_ = NormalizedPerpendicular(n);
      tangent2_direction_ = n.cross(tangent1_direction_);
      tangent1_ = LinearRow(body1, r1, body2, r2, tangent1_direction_);
      tangent2_ = LinearRow(body1, r1, body2, r2, tangent2_direction_);
      if (count_ >= 2) angular_ = AngularRow(body1, body2, n);
      // Per manifold, whatever the points did: Jolt inherits them when the
      // manifold existed last substep (the tangents are rebuilt from n).
      if (existed) {
        if (tangent1_.effective_mass != T(0)) tangent1_.lambda = old_t1;
        if (tangent2_.effective_mass != T(0)) tangent2_.lambda = old_t2;
        if (angular_.effective_mass != T(0)) angular_.lambda = old_a;
      }
    }
  }

  // Λ ← ρΛ and applied: t1, t2, angular, then the normals in point order.
  void WarmStart(Body<T>& body1, Body<T>& body2, T warm_start_ratio) {
    if (count_ == 0) return;
    Velocities vel = Velocities::Read(body1, body2);
    for (Row* row : {&tangent1_, &tangent2_, &angular_}) {
      row->lambda *= warm_start_ratio;
      Apply(*row, row->lambda, vel);
    }
    for (int i = 0; i < count_; ++i) {
      normal_[i].lambda *= warm_start_ratio;
      Apply(normal_[i], normal_[i].lambda, vel);
    }
    vel.Write(body1, body2);
  }

  // One Gauss-Seidel pass over the slot's rows; true iff any impulse changed.
  bool SolveVelocity(Body<T>& body1, Body<T>& body2) {
    if (count_ == 0) return false;
    bool applied = false;
    Velocities vel = Velocities::Read(body1, body2);
    if (friction_active_) {
      // Limits from the normal impulses so far (previous pass or warm start):
      // a new contact has none in its first pass.
      T normal_sum = T(0), moment_sum = T(0);
      for (int i = 0; i < count_; ++i) {
        normal_sum += normal_[i].lambda;
        moment_sum += distance_[i] * normal_[i].lambda;
      }
      const T max_linear = friction_ * normal_sum;
      const T max_angular = friction_ * moment_sum;
      // Both tangent rows from the same velocities, then clamped together to a
      // circle, so the friction force does not depend on the tangent basis.
      T new1 = tangent1_.lambda + tangent1_.effective_mass * (-RowVelocity(tangent1_, vel));
      T new2 = tangent2_.lambda + tangent2_.effective_mass * (-RowVelocity(tangent2_, vel));
      const T length_squared = new1 * new1 + new2 * new2;
      if (length_squared > max_linear * max_linear) {
        const T scale = max_linear / std::sqrt(length_squared);
        new1 *= scale;
        new2 *= scale;
      }
      applied |= Apply(tangent1_, new1 - tangent1_.lambda, vel);
      tangent1_.lambda = new1;
      applied |= Apply(tangent2_, new2 - tangent2_.lambda, vel);
      tangent2_.lambda = new2;
      if (angular_.effective_mass != T(0)) {
        const T unclamped = angular_.lambda + angular_.effective_mass * (-RowVelocity(angular_, vel));
        const T new_a = std::min(std::max(unclamped, -max_angular), max_angular);
        applied |= Apply(angular_, new_a - angular_.lambda, vel);
        angular_.lambda = new_a;
      }
    }
    // Normals last: the rows solved last dominate, and non-penetration matters most.
    for (int i = 0; i < count_; ++i) {
      Row& row = normal_[i];
      const T unclamped = row.lambda + row.effective_mass * (-RowVelocity(row, vel) - row.bias);
      const T new_lambda = std::max(T(0), unclamped);
      applied |= Apply(row, new_lambda - row.lambda, vel);
      row.lambda = new_lambda;
    }
    vel.Write(body1, body2);
    return applied;
  }

  // One Baumgarte pass over the points; true iff a body was moved.
  bool SolvePosition(Body<T>& body1, Body<T>& body2, T baumgarte, T slop, T max_penetration) {
    if (count_ == 0) return false;
    // The points move with the transforms of when this slot's pass starts; the
    // lever arms reach the centres of mass as earlier points left them.
    const Vec3<T> x1 = body1.position, x2 = body2.position;
    const Quat<T> q1 = body1.rotation, q2 = body2.rotation;
    const Vec3<T>& n = normal_direction_;
    bool moved = false;
    for (int i = 0; i < count_; ++i) {
      const Vec3<T> p1 = x1 + q1 * local1_[i];
      const Vec3<T> p2 = x2 + q2 * local2_[i];
      // Penetration up to the slop is left alone; a step corrects at most
      // max_penetration of it.
      const T c = std::max((p2 - p1).dot(n) + slop, -max_penetration);
      if (!(c < T(0))) continue;
      const Vec3<T> p = (p1 + p2) / T(2);
      const Row row = LinearRow(body1, p - body1.position, body2, p - body2.position, n);
      if (row.effective_mass == T(0)) continue;
      const T lambda = -baumgarte * c * row.effective_mass;  // −β C / K
      if (body1.IsDynamic()) {
        body1.SubPositionStep((lambda * body1.inv_mass) * n);
        body1.SubRotationStep(lambda * row.inv_i1_angular1);
      }
      if (body2.IsDynamic()) {
        body2.AddPositionStep((lambda * body2.inv_mass) * n);
        body2.AddRotationStep(lambda * row.inv_i2_angular2);
      }
      moved = true;
    }
    return moved;
  }

  // Solver state (reference/solver_state.h), in the batch's layout: the
  // friction impulses (t1, t2, angular), then kMaxContactPoints times: 1 for a
  // kept point (else 0 and the rest of the point 0), its local points on body
  // 1 and 2 and its normal impulse. The batch keeps points in fixed slots; here
  // they are compacted in slot order, which keeps the first match of the next
  // setup's point matching the same.
  void SaveSolverState(SolverStateWriter<T>& out) const {
    out(tangent1_.lambda);
    out(tangent2_.lambda);
    out(angular_.lambda);
    for (int i = 0; i < kMaxContactPoints; ++i) {
      const bool kept = i < count_;
      out(kept ? T(1) : T(0));
      out(kept ? local1_[i] : Vec3<T>(Vec3<T>::Zero()));
      out(kept ? local2_[i] : Vec3<T>(Vec3<T>::Zero()));
      out(kept ? normal_[i].lambda : T(0));
    }
  }
  void RestoreSolverState(SolverStateReader<T>& in) {
    tangent1_.lambda = in.Scalar();
    tangent2_.lambda = in.Scalar();
    angular_.lambda = in.Scalar();
    count_ = 0;
    for (int i = 0; i < kMaxContactPoints; ++i) {
      const bool kept = in.Scalar() != T(0);
      const Vec3<T> local1 = in.Vector3();
      const Vec3<T> local2 = in.Vector3();
      const T lambda = in.Scalar();
      if (!kept) continue;
      local1_[count_] = local1;
      local2_[count_] = local2;
      normal_[count_].lambda = lambda;
      ++count_;
    }
    for (int i = count_; i < kMaxContactPoints; ++i) normal_[i].lambda = T(0);
  }

  // ---- read-only views (this substep's manifold), for tests
  bool Exists() const { return count_ > 0; }
  int PointCount() const { return count_; }
  const Vec3<T>& Normal() const { return normal_direction_; }  // body 1 to body 2; 0 if none
  T NormalImpulse(int k) const { return normal_.at(std::size_t(k)).lambda; }
  const Vec3<T>& Point1(int k) const { return point1_.at(std::size_t(k)); }  // world, setup
  const Vec3<T>& Point2(int k) const { return point2_.at(std::size_t(k)); }
  T Separation(int k) const { return separation_.at(std::size_t(k)); }  // (p2 − p1)·n at setup
  T FrictionImpulse1() const { return tangent1_.lambda; }  // along Tangent1()
  T FrictionImpulse2() const { return tangent2_.lambda; }
  T AngularFrictionImpulse() const { return angular_.lambda; }  // about Normal()
  const Vec3<T>& Tangent1() const { return tangent1_direction_; }
  const Vec3<T>& Tangent2() const { return tangent2_direction_; }
  T Friction() const { return friction_; }        // sqrt(μ1 μ2)
  T Restitution() const { return restitution_; }  // max(e1, e2)

 private:
  static bool IsRound(ShapeType type) {
    return type == ShapeType::kSphere || type == ShapeType::kCapsule;
  }
  static bool IsSolid(ShapeType type) { return IsRound(type) || type == ShapeType::kBox; }
  static bool IsPlanePair(ShapeType type1, ShapeType type2) {
    const auto plane_with = [](ShapeType plane, ShapeType other) {
      return plane == ShapeType::kPlane && (IsRound(other) || other == ShapeType::kBox);
    };
    return plane_with(type1, type2) || plane_with(type2, type1);
  }

  // A shape's centre and rotation in world space.
  static Vec3<T> ShapeCentre(const Body<T>& body, const ContactShape<T>& shape) {
    return body.position + body.rotation * shape.position;
  }
  static Quat<T> ShapeRotation(const Body<T>& body, const ContactShape<T>& shape) {
    return body.rotation * shape.rotation;
  }

  // How far a shape reaches from its body's centre of mass: |p| plus the
  // sphere's radius, the capsule's half height and radius, the box's half
  // diagonal; a plane 0.
  static T Reach(const ContactShape<T>& shape) {
    const T centre = shape.position.norm();
    switch (shape.type) {
      case ShapeType::kSphere: return centre + shape.radius;
      case ShapeType::kCapsule: return centre + shape.half_height + shape.radius;
      case ShapeType::kBox: return centre + shape.half_extents.norm();
      default: return T(0);
    }
  }

  // D, or with from_velocity D + dt max(0, −(v2 − v1)·n + |ω1| R1 + |ω2| R2):
  // how far the shapes may approach along n within the substep.
  T SpeculativeDistance(const Body<T>& body1, const Body<T>& body2, const Vec3<T>& n,
                        const ContactSettings<T>& settings, T dt) const {
    if (!settings.from_velocity) return settings.speculative_contact_distance;
    const T approach = -(body2.LinearVelocity() - body1.LinearVelocity()).dot(n) +
                       body1.AngularVelocity().norm() * Reach(shape1_) +
                       body2.AngularVelocity().norm() * Reach(shape2_);
    return settings.speculative_contact_distance + dt * std::max(T(0), approach);
  }

  // A plane with a sphere, capsule or box: the candidates of the other shape,
  // the manifold when the deepest has φ < D, the candidates with φ < D + 1 mm.
  void FindPlanePoints(const Body<T>& body1, const Body<T>& body2,
                       const ContactSettings<T>& settings, T dt) {
    const Body<T>& plane_body = plane_is_body1_ ? body1 : body2;
    const Body<T>& other_body = plane_is_body1_ ? body2 : body1;
    const ContactShape<T>& plane = plane_is_body1_ ? shape1_ : shape2_;
    const ContactShape<T>& other = plane_is_body1_ ? shape2_ : shape1_;
    const Vec3<T> n_p = ShapeRotation(plane_body, plane) * Vec3<T>::UnitY();
    const Vec3<T> origin = ShapeCentre(plane_body, plane);
    const PlaneCandidates<T> candidates = PlaneContactCandidates<T>(
        n_p, other, ShapeCentre(other_body, other), ShapeRotation(other_body, other));
    std::array<T, kMaxContactPoints> phi{};
    T deepest = std::numeric_limits<T>::infinity();
    for (int j = 0; j < candidates.count; ++j) {
      phi[j] = n_p.dot(candidates.on_shape[j] - origin);
      deepest = std::min(deepest, phi[j]);
    }
    const Vec3<T> normal = plane_is_body1_ ? n_p : Vec3<T>(-n_p);
    const T speculative = SpeculativeDistance(body1, body2, normal, settings, dt);
    const T keep = speculative + T(0.001);  // Jolt's 1 mm tolerance
    if (!(deepest < speculative)) return;

    normal_direction_ = normal;
    for (int j = 0; j < candidates.count; ++j) {
      if (!(phi[j] < keep)) continue;
      const Vec3<T> on_shape = candidates.on_shape[j];
      const Vec3<T> on_plane = on_shape - phi[j] * n_p;
      point1_[count_] = plane_is_body1_ ? on_plane : on_shape;
      point2_[count_] = plane_is_body1_ ? on_shape : on_plane;
      ++count_;
    }
  }

  // Two spheres or capsules: the closest points s1, s2 of the cores, n from
  // s1 to s2, p1 = s1 + r1 n, p2 = s2 − r2 n; the one point exists when
  // L − r1 − r2 < D.
  void FindRoundPoint(const Body<T>& body1, const Body<T>& body2,
                      const ContactSettings<T>& settings, T dt) {
    const RoundCore<T> core1 =
        MakeRoundCore(shape1_, ShapeCentre(body1, shape1_), ShapeRotation(body1, shape1_));
    const RoundCore<T> core2 =
        MakeRoundCore(shape2_, ShapeCentre(body2, shape2_), ShapeRotation(body2, shape2_));
    const RoundCandidate<T> candidate =
        RoundContactCandidate(core1, core2);
    if (!(candidate.distance - core1.radius - core2.radius <
          SpeculativeDistance(body1, body2, candidate.normal, settings, dt))) {
      return;
    }
    normal_direction_ = candidate.normal;
    point1_[0] = candidate.s1 + core1.radius * candidate.normal;
    point2_[0] = candidate.s2 - core2.radius * candidate.normal;
    count_ = 1;
  }

  // A box (A) with a sphere, capsule or box (B), reference/box_contact_points.h:
  // the normal from A to B and pairs (on A, on B); when the box is body 2 the
  // normal is negated and each pair swapped. Two boxes: A is body 1's.
  void FindBoxPoints(const Body<T>& body1, const Body<T>& body2,
                     const ContactSettings<T>& settings, T dt) {
    const bool box_is_body1 = shape1_.type == ShapeType::kBox;
    const Body<T>& box_body = box_is_body1 ? body1 : body2;
    const Body<T>& other_body = box_is_body1 ? body2 : body1;
    const ContactShape<T>& box = box_is_body1 ? shape1_ : shape2_;
    const ContactShape<T>& other = box_is_body1 ? shape2_ : shape1_;
    const auto speculative = [&](const Vec3<T>& n) {  // n from A to B: the slot's is ±n
      return SpeculativeDistance(body1, body2, box_is_body1 ? n : Vec3<T>(-n), settings, dt);
    };
    const BoxPairPoints<T> found = BoxContactPoints(
        BoxFrame<T>{ShapeCentre(box_body, box), ShapeRotation(box_body, box), box.half_extents},
        other, ShapeCentre(other_body, other), ShapeRotation(other_body, other), body1.position,
        speculative);
    if (found.count == 0) return;
    count_ = found.count;
    normal_direction_ = box_is_body1 ? found.normal : Vec3<T>(-found.normal);
    for (int i = 0; i < count_; ++i) {
      point1_[i] = box_is_body1 ? found.on_a[i] : found.on_b[i];
      point2_[i] = box_is_body1 ? found.on_b[i] : found.on_a[i];
    }
  }

  // One row: ċ = axis·(v2 − v1) + angular2·ω2 − angular1·ω1.
  struct Row {
    Vec3<T> axis = Vec3<T>::Zero();  // zero for the angular row
    Vec3<T> angular1 = Vec3<T>::Zero();
    Vec3<T> angular2 = Vec3<T>::Zero();
    Vec3<T> inv_i1_angular1 = Vec3<T>::Zero();
    Vec3<T> inv_i2_angular2 = Vec3<T>::Zero();
    T inv_mass1 = T(0);  // dynamic bodies only
    T inv_mass2 = T(0);
    T effective_mass = T(0);  // 0: inactive
    T bias = T(0);
    T lambda = T(0);
  };

  static std::array<Vec3<T>, kMaxContactPoints> ZeroPoints() {
    std::array<Vec3<T>, kMaxContactPoints> points;
    points.fill(Vec3<T>::Zero());
    return points;
  }

  // Both bodies' velocities while a slot is solved (jolt-contacts.md §5.2).
  struct Velocities {
    Vec3<T> v1, w1, v2, w2;
    static Velocities Read(const Body<T>& body1, const Body<T>& body2) {
      return {body1.LinearVelocity(), body1.AngularVelocity(), body2.LinearVelocity(),
              body2.AngularVelocity()};
    }
    void Write(Body<T>& body1, Body<T>& body2) const {
      if (body1.IsDynamic()) {
        body1.linear_velocity = body1.LockTranslation(v1);
        body1.angular_velocity = w1;
      }
      if (body2.IsDynamic()) {
        body2.linear_velocity = body2.LockTranslation(v2);
        body2.angular_velocity = w2;
      }
    }
  };

  // γ g + m⁻¹ F for a dynamic body; a static or kinematic body gets nothing
  // from forces (docs/contacts.md: a kinematic body's gravity factor counts 0).
  static Vec3<T> Acceleration(const Body<T>& body, const BodyMotionSettings<T>& motion,
                              const Vec3<T>& gravity) {
    if (!body.IsDynamic()) return Vec3<T>::Zero();
    return motion.gravity_factor * gravity + body.inv_mass * motion.force;
  }

  // A linear row along unit `axis` with levers r1, r2 (from the centres of
  // mass). A static body's velocity is zero, so its levers are left zero; only
  // dynamic bodies have mass here.
  static Row LinearRow(const Body<T>& body1, const Vec3<T>& r1, const Body<T>& body2,
                       const Vec3<T>& r2, const Vec3<T>& axis) {
    Row row;
    row.axis = axis;
    T k = T(0);
    if (!body1.IsStatic()) row.angular1 = r1.cross(axis);
    if (body1.IsDynamic()) {
      row.inv_mass1 = body1.inv_mass;
      row.inv_i1_angular1 = body1.MultiplyInverseInertia(row.angular1);
      k += body1.inv_mass + row.angular1.dot(row.inv_i1_angular1);
    }
    if (!body2.IsStatic()) row.angular2 = r2.cross(axis);
    if (body2.IsDynamic()) {
      row.inv_mass2 = body2.inv_mass;
      row.inv_i2_angular2 = body2.MultiplyInverseInertia(row.angular2);
      k += body2.inv_mass + row.angular2.dot(row.inv_i2_angular2);
    }
    row.effective_mass = k == T(0) ? T(0) : T(1) / k;
    return row;
  }

  // The angular friction row about n: ċ = (ω2 − ω1)·n.
  static Row AngularRow(const Body<T>& body1, const Body<T>& body2, const Vec3<T>& n) {
    Row row;
    T k = T(0);
    if (!body1.IsStatic()) row.angular1 = n;
    if (body1.IsDynamic()) {
      row.inv_i1_angular1 = body1.MultiplyInverseInertia(n);
      k += n.dot(row.inv_i1_angular1);
    }
    if (!body2.IsStatic()) row.angular2 = n;
    if (body2.IsDynamic()) {
      row.inv_i2_angular2 = body2.MultiplyInverseInertia(n);
      k += n.dot(row.inv_i2_angular2);
    }
    row.effective_mass = k == T(0) ? T(0) : T(1) / k;
    return row;
  }

  static T RowVelocity(const Row& row, const Velocities& vel) {
    return row.axis.dot(vel.v2 - vel.v1) + row.angular2.dot(vel.w2) - row.angular1.dot(vel.w1);
  }

  // Applies impulse `delta` of `row` to the velocities; true iff delta != 0.
  static bool Apply(const Row& row, T delta, Velocities& vel) {
    vel.v1 -= (delta * row.inv_mass1) * row.axis;
    vel.w1 -= delta * row.inv_i1_angular1;
    vel.v2 += (delta * row.inv_mass2) * row.axis;
    vel.w2 += delta * row.inv_i2_angular2;
    return delta != T(0);
  }

  std::size_t body1_, body2_;
  ContactShape<T> shape1_;  // body 1's
  ContactShape<T> shape2_;  // body 2's
  bool plane_is_body1_;     // plane pairs: which body has the plane
  // A plane with a shape; two spheres or capsules; a box with a shape.
  enum class PairKind { kPlane, kRound, kBox };
  PairKind kind_ = PairKind::kPlane;
  T friction_;     // μ = sqrt(μ1 μ2)
  T restitution_;  // e = max(e1, e2)

  // This substep's manifold (kept until the next Setup: matching reads it).
  int count_ = 0;
  Vec3<T> normal_direction_ = Vec3<T>::Zero();
  // (Eigen leaves a default-constructed vector uninitialised: zeroed here.)
  std::array<Vec3<T>, kMaxContactPoints> point1_ = ZeroPoints();  // world, at setup
  std::array<Vec3<T>, kMaxContactPoints> point2_ = ZeroPoints();
  std::array<Vec3<T>, kMaxContactPoints> local1_ = ZeroPoints();  // body 1 COM frame
  std::array<Vec3<T>, kMaxContactPoints> local2_ = ZeroPoints();  // body 2 COM frame
  std::array<T, kMaxContactPoints> separation_{};
  std::array<T, kMaxContactPoints> distance_{};  // d_i from the friction anchor
  std::array<Row, kMaxContactPoints> normal_{};
  bool friction_active_ = false;
  Vec3<T> anchor_ = Vec3<T>::Zero();
  Vec3<T> tangent1_direction_ = Vec3<T>::Zero();
  Vec3<T> tangent2_direction_ = Vec3<T>::Zero();
  Row tangent1_;
  Row tangent2_;
  Row angular_;
};

}  // namespace manyworlds::reference
