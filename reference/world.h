// The scalar reference stepper: ONE world of a manyworlds::Scene, stepped exactly
// as Jolt's PhysicsSystem::Update steps a constraint-only island (spec 4.1). It is
// the oracle the SIMD batch is checked against, so it favours plain, readable
// code over speed.
//
// One Step(settings) with n = settings.substeps:
//
//   dt    = delta_time / n
//   ratio = dt / dt_prev of the previous Step (0 on the very first Step, 0 when
//           warm_start is off); only the first sub-step uses it, later sub-steps
//           use 1 (spec 4.1). dt_prev := dt.
//   n times:
//     1. dynamic bodies:  with settings.gyroscopic, ω ← the implicit-midpoint
//                         gyroscopic step (reference/gyroscopic.h); then
//                         v ← lockT(v + dt·(g_factor·g + m⁻¹F)),  ω ← ω + dt·I⁻¹τ,
//                         v ← v·max(0, 1 − c_lin·dt),  ω ← ω·max(0, 1 − c_ang·dt),
//                         clamp |v| ≤ v_max, |ω| ≤ ω_max (uniform rescale)
//     2. constraints with at least one dynamic body (Jolt solves no others), in
//        scene order: Setup (poses at the start of the sub-step); then the
//        contact slots in the order of their body pairs: detection and Setup
//        (reference/contact_constraint.h, docs/contacts.md)
//     3. WarmStart(ratio) of each, contacts after the joints
//     4. up to N_v velocity iterations over all of them, contacts after the
//        joints; stop after an iteration in which neither a joint nor a contact
//        applied an impulse (result-neutral, spec 1.1)
//     5. integrate: dynamic bodies clamp v, ω again; every non-static body
//        q ← AddRotationStep(ω·dt) (rotation first), then x ← x + lockT(v·dt)
//     6. up to N_p position iterations (Baumgarte β), joints then contacts,
//        stop when nothing moved
//   forces and torques set for this Step are then cleared (Jolt's AddForce: they
//   act in every sub-step of the Step they were set for).
//
// Allowed DOFs (spec 4.3): lockT zeroes a body's locked translation axes, here
// and in every linear velocity or position step of the parts; I⁻¹ has the rows
// and columns of locked rotation axes zeroed (reference/body.h).
//
// The constraint types and what each solves are in reference/*_constraint.h; the
// scene conversion (mass, inertia, world-space settings to body space, anchors,
// r0⁻¹) in reference/world_setup.h.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <set>
#include <span>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

#include "manyworlds/batch.h"
#include "manyworlds/scene.h"
#include "reference/body.h"
#include "reference/cone_constraint.h"
#include "reference/contact_constraint.h"
#include "reference/distance_constraint.h"
#include "reference/exact_solve.h"
#include "reference/fixed_constraint.h"
#include "reference/gear_constraint.h"
#include "reference/gyroscopic.h"
#include "reference/hinge_constraint.h"
#include "reference/math.h"
#include "reference/point_constraint.h"
#include "reference/pulley_constraint.h"
#include "reference/rack_and_pinion_constraint.h"
#include "reference/slider_constraint.h"
#include "reference/path_constraint.h"
#include "reference/six_dof_constraint.h"
#include "reference/solver_state.h"
#include "reference/swing_twist_constraint.h"
#include "reference/world_setup.h"

namespace manyworlds::reference {

template <class T>
class World {
 public:
  // Same order as manyworlds::ConstraintSettings.
  using Constraint =
      std::variant<PointConstraint<T>, FixedConstraint<T>, HingeConstraint<T>,
                   SliderConstraint<T>, GearConstraint<T>, RackAndPinionConstraint<T>,
                   DistanceConstraint<T>, PulleyConstraint<T>, ConeConstraint<T>,
                   SwingTwistConstraint<T>, SixDofConstraint<T>, PathConstraint<T>>;

  // Converts every body and constraint (world-space settings refer to the poses
  // in the scene) and makes the contact slots. Throws std::invalid_argument for
  // body or helper indices that do not fit, for a gear or rack-and-pinion with a
  // static body, for a plane shape on a body that is not static and for a pair
  // of shapes that collide but is not supported (naming both bodies).
  explicit World(const Scene& scene);

  // One step of settings.delta_time (see the header comment). Throws
  // std::invalid_argument for bad settings (contact settings negative or not
  // finite included).
  void Step(const StepSettings& settings);

  // ---- actions: world-space force / torque through the COM for the next Step.
  void SetForce(std::size_t body, const Vec3<T>& force) { motion_.at(body).force = force; }
  void SetTorque(std::size_t body, const Vec3<T>& torque) { motion_.at(body).torque = torque; }

  // Hinge: rad/s; slider and path: m/s.
  void SetTargetVelocity(std::size_t constraint, T velocity) {
    if (auto* hinge = std::get_if<HingeConstraint<T>>(&constraints_.at(constraint))) {
      hinge->SetTargetAngularVelocity(velocity);
    } else if (auto* slider = std::get_if<SliderConstraint<T>>(&constraints_.at(constraint))) {
      slider->SetTargetVelocity(velocity);
    } else if (auto* path = std::get_if<PathConstraint<T>>(&constraints_.at(constraint))) {
      path->SetTargetVelocity(velocity);
    } else {
      throw std::invalid_argument(NotA("hinge, slider or path", constraint));
    }
  }
  // Hinge: rad; slider: m (both clamped into the limits, spec 3); path: the
  // target path fraction.
  void SetTargetPosition(std::size_t constraint, T position) {
    if (auto* hinge = std::get_if<HingeConstraint<T>>(&constraints_.at(constraint))) {
      hinge->SetTargetAngle(position);
    } else if (auto* slider = std::get_if<SliderConstraint<T>>(&constraints_.at(constraint))) {
      slider->SetTargetPosition(position);
    } else if (auto* path = std::get_if<PathConstraint<T>>(&constraints_.at(constraint))) {
      path->SetTargetFraction(position);
    } else {
      throw std::invalid_argument(NotA("hinge, slider or path", constraint));
    }
  }

  // Swing-twist and six-DOF rotation drives: body 2's frame in body 1's
  // (clamped into the limits) and the angular velocity about body 2's frame axes.
  void SetTargetOrientation(std::size_t constraint, const Quat<T>& orientation) {
    if (auto* c = std::get_if<SwingTwistConstraint<T>>(&constraints_.at(constraint))) {
      c->SetTargetOrientation(orientation.normalized());
    } else if (auto* d = std::get_if<SixDofConstraint<T>>(&constraints_.at(constraint))) {
      d->SetTargetOrientation(orientation.normalized());
    } else {
      throw std::invalid_argument(NotA("swing-twist or six-DOF", constraint));
    }
  }
  void SetTargetAngularVelocity(std::size_t constraint, const Vec3<T>& angular_velocity) {
    if (auto* c = std::get_if<SwingTwistConstraint<T>>(&constraints_.at(constraint))) {
      c->SetTargetAngularVelocity(angular_velocity);
    } else if (auto* d = std::get_if<SixDofConstraint<T>>(&constraints_.at(constraint))) {
      d->SetTargetAngularVelocity(angular_velocity);
    } else {
      throw std::invalid_argument(NotA("swing-twist or six-DOF", constraint));
    }
  }
  // Six-DOF translation drives, body 1's constraint frame.
  void SetTargetTranslation(std::size_t constraint, const Vec3<T>& translation) {
    SixDof(constraint).SetTargetTranslation(translation);
  }
  void SetTargetLinearVelocity(std::size_t constraint, const Vec3<T>& velocity) {
    SixDof(constraint).SetTargetLinearVelocity(velocity);
  }

  // ---- state
  const Body<T>& body(std::size_t i) const { return bodies_.at(i); }
  Body<T>& body(std::size_t i) { return bodies_.at(i); }  // to set state
  std::size_t body_count() const { return bodies_.size(); }
  std::size_t constraint_count() const { return constraints_.size(); }
  const Constraint& constraint(std::size_t i) const { return constraints_.at(i); }
  // Contact slots (docs/contacts.md), in the order of their body pairs (i, j).
  std::size_t contact_count() const { return contacts_.size(); }
  const ContactConstraint<T>& contact(std::size_t i) const { return contacts_.at(i); }

  // Solver state (reference/solver_state.h): what the constraints, in scene
  // order, then the contact slots carry from one step to the next, in the
  // batch's layout (Batch::GetSolverState). SetSolverState throws
  // std::invalid_argument, writing nothing, for a count that does not fit. It
  // also sets the exact solve's point-group impulses (the geometric
  // stiffness's pulls, apart here) from the point parts' accumulated
  // impulses, where the batch keeps them (the exact solve keeps no other
  // group's impulse).
  std::vector<T> SolverState() const;
  void SetSolverState(std::span<const T> values);

  // The hinge's current angle (body 2 relative to body 1, in (−π, π]) and the
  // slider's current position, from the bodies as they are now.
  T HingeAngle(std::size_t constraint) const {
    const auto* hinge = std::get_if<HingeConstraint<T>>(&constraints_.at(constraint));
    if (hinge == nullptr) throw std::invalid_argument(NotA("hinge", constraint));
    return hinge->CurrentAngle(bodies_[hinge->body1()], bodies_[hinge->body2()]);
  }
  // The same angle unwrapped: continuous across +-pi, whole turns counted at
  // every setup (what the gear and rack-and-pinion position steps read).
  T HingeUnwrappedAngle(std::size_t constraint) const {
    const auto* hinge = std::get_if<HingeConstraint<T>>(&constraints_.at(constraint));
    if (hinge == nullptr) throw std::invalid_argument(NotA("hinge", constraint));
    return hinge->UnwrappedAngle(bodies_[hinge->body1()], bodies_[hinge->body2()]);
  }
  T SliderPosition(std::size_t constraint) const {
    const auto* slider = std::get_if<SliderConstraint<T>>(&constraints_.at(constraint));
    if (slider == nullptr) throw std::invalid_argument(NotA("slider", constraint));
    return slider->CurrentPosition(bodies_[slider->body1()], bodies_[slider->body2()]);
  }

 private:
  SixDofConstraint<T>& SixDof(std::size_t constraint) {
    auto* c = std::get_if<SixDofConstraint<T>>(&constraints_.at(constraint));
    if (c == nullptr) throw std::invalid_argument(NotA("six-DOF", constraint));
    return *c;
  }

  static std::string NotA(const char* what, std::size_t constraint) {
    return "reference::World: constraint " + std::to_string(constraint) + " is not a " + what;
  }

  template <class Settings>
  Constraint MakeConstraint(const Settings& settings, std::size_t index) const {
    CheckBodyIndices(settings.body1, settings.body2, bodies_.size(), index);
    const Body<T>& body1 = bodies_[settings.body1];
    const Body<T>& body2 = bodies_[settings.body2];
    if constexpr (std::is_same_v<Settings, PointConstraintSettings>) {
      return PointConstraint<T>(settings, body1, body2);
    } else if constexpr (std::is_same_v<Settings, FixedConstraintSettings>) {
      return FixedConstraint<T>(settings, body1, body2);
    } else if constexpr (std::is_same_v<Settings, HingeConstraintSettings>) {
      return HingeConstraint<T>(settings, body1, body2);
    } else if constexpr (std::is_same_v<Settings, SliderConstraintSettings>) {
      return SliderConstraint<T>(settings, body1, body2);
    } else if constexpr (std::is_same_v<Settings, DistanceConstraintSettings>) {
      return DistanceConstraint<T>(settings, body1, body2);
    } else if constexpr (std::is_same_v<Settings, PulleyConstraintSettings>) {
      return PulleyConstraint<T>(settings, body1, body2);
    } else if constexpr (std::is_same_v<Settings, ConeConstraintSettings>) {
      return ConeConstraint<T>(settings, body1, body2);
    } else if constexpr (std::is_same_v<Settings, SwingTwistConstraintSettings>) {
      return SwingTwistConstraint<T>(settings, body1, body2);
    } else if constexpr (std::is_same_v<Settings, SixDofConstraintSettings>) {
      return SixDofConstraint<T>(settings, body1, body2);
    } else if constexpr (std::is_same_v<Settings, PathConstraintSettings>) {
      return PathConstraint<T>(settings, body1, body2);
    } else {
      // Gear and rack-and-pinion read both bodies' motion properties (spec 1.5).
      if (body1.IsStatic() || body2.IsStatic()) {
        throw std::invalid_argument("reference::World: constraint " + std::to_string(index) +
                                    " (gear or rack-and-pinion) has a static body");
      }
      if constexpr (std::is_same_v<Settings, GearConstraintSettings>) {
        return GearConstraint<T>(settings, body1, body2);
      } else {
        static_assert(std::is_same_v<Settings, RackAndPinionConstraintSettings>);
        return RackAndPinionConstraint<T>(settings, body1, body2);
      }
    }
  }

  // A helper (gear's hinges, rack-and-pinion's hinge and slider) must be of the
  // right type and hold the body it measures.
  template <class Helper>
  void CheckHelper(std::size_t helper, std::size_t body, std::size_t index) const {
    if (helper == kNoConstraint) return;
    const Helper* c = helper < constraints_.size() ? std::get_if<Helper>(&constraints_[helper])
                                                   : nullptr;
    if (c == nullptr || (c->body1() != body && c->body2() != body)) {
      throw std::invalid_argument("reference::World: constraint " + std::to_string(index) +
                                  " names helper constraint " + std::to_string(helper) +
                                  " which is not of the right type or lacks its body");
    }
  }

  void CheckHelpers(std::size_t index) const {
    if (const auto* gear = std::get_if<GearConstraint<T>>(&constraints_[index])) {
      CheckHelper<HingeConstraint<T>>(gear->hinge1(), gear->body1(), index);
      CheckHelper<HingeConstraint<T>>(gear->hinge2(), gear->body2(), index);
    } else if (const auto* rack =
                   std::get_if<RackAndPinionConstraint<T>>(&constraints_[index])) {
      CheckHelper<HingeConstraint<T>>(rack->hinge(), rack->body1(), index);
      CheckHelper<SliderConstraint<T>>(rack->slider(), rack->body2(), index);
    }
  }

  // The rotation of `body` as hinge `hinge` measures it: the hinge angle is body 2
  // relative to body 1, so a body that is the hinge's body 1 turned the other way.
  T RotationMeasuredByHinge(std::size_t hinge, std::size_t body) const {
    const T angle = HingeUnwrappedAngle(hinge);
    return std::get<HingeConstraint<T>>(constraints_[hinge]).body2() == body ? angle : -angle;
  }
  // Likewise the translation of `body` as slider `slider` measures it.
  T TranslationMeasuredBySlider(std::size_t slider, std::size_t body) const {
    const T position = SliderPosition(slider);
    return std::get<SliderConstraint<T>>(constraints_[slider]).body2() == body ? position
                                                                               : -position;
  }

  static std::string BodyName(const Scene& scene, std::size_t index) {
    const std::string& name = scene.bodies()[index].name;
    return "body " + std::to_string(index) + (name.empty() ? "" : " ('" + name + "')");
  }

  // The contact slots of docs/contacts.md: every pair i < j of bodies with
  // shapes whose groups and masks meet, with at least one dynamic body, not
  // joined by a constraint (unless either shape collides with joined bodies).
  // Such a pair must be a plane with a sphere, capsule or box, or two of
  // sphere, capsule and box; a plane is on a static body (so two planes never
  // make a slot).
  void MakeContacts(const Scene& scene) {
    const std::vector<BodySettings>& settings = scene.bodies();
    for (std::size_t i = 0; i < settings.size(); ++i) {
      if (settings[i].shape.type == ShapeType::kPlane &&
          settings[i].motion_type != MotionType::kStatic) {
        throw std::invalid_argument("reference::World: " + BodyName(scene, i) +
                                    " has a plane shape but is not static");
      }
    }
    std::set<std::pair<std::size_t, std::size_t>> joined;
    for (const Constraint& constraint : constraints_) {
      std::visit(
          [&](const auto& c) {
            joined.insert({std::min(c.body1(), c.body2()), std::max(c.body1(), c.body2())});
          },
          constraint);
    }
    for (std::size_t i = 0; i < settings.size(); ++i) {
      for (std::size_t j = i + 1; j < settings.size(); ++j) {
        const ShapeSettings& shape_i = settings[i].shape;
        const ShapeSettings& shape_j = settings[j].shape;
        if (shape_i.type == ShapeType::kNone || shape_j.type == ShapeType::kNone) continue;
        if ((shape_i.collision_group & shape_j.collision_mask) == 0 ||
            (shape_j.collision_group & shape_i.collision_mask) == 0) {
          continue;
        }
        if (!bodies_[i].IsDynamic() && !bodies_[j].IsDynamic()) continue;
        if (joined.count({i, j}) != 0 && !shape_i.collide_with_joined &&
            !shape_j.collide_with_joined) {
          continue;
        }
        if (!ContactConstraint<T>::Supports(shape_i.type, shape_j.type)) {
          throw std::invalid_argument(
              "reference::World: " + BodyName(scene, i) + " and " + BodyName(scene, j) +
              " collide but their pair of shapes is not supported (only a plane with a "
              "sphere, capsule or box, and spheres, capsules and boxes with each other): put "
              "them in collision groups that do not meet");
        }
        contacts_.emplace_back(i, j, shape_i, shape_j);
      }
    }
  }

  // Jolt solves a constraint only if at least one of its bodies is dynamic (spec 1.5).
  bool IsSolved(const Constraint& constraint) const {
    return std::visit(
        [&](const auto& c) {
          return bodies_[c.body1()].IsDynamic() || bodies_[c.body2()].IsDynamic();
        },
        constraint);
  }

  static void ClampVelocities(Body<T>& body, const BodyMotionSettings<T>& motion) {
    const auto clamp = [](Vec3<T>& v, T max_length) {
      const T length_squared = v.squaredNorm();
      if (length_squared > max_length * max_length) v *= max_length / std::sqrt(length_squared);
    };
    clamp(body.linear_velocity, motion.max_linear_velocity);
    clamp(body.angular_velocity, motion.max_angular_velocity);
  }

  // Step 1: the opt-in gyroscopic step (reference/gyroscopic.h), gravity,
  // forces, damping, clamps (dynamic bodies).
  void ApplyForcesAndDamping(T dt, const Vec3<T>& gravity, bool gyroscopic) {
    for (std::size_t i = 0; i < bodies_.size(); ++i) {
      Body<T>& body = bodies_[i];
      if (!body.IsDynamic()) continue;
      if (gyroscopic) ApplyGyroscopicStep(body, dt);
      const BodyMotionSettings<T>& motion = motion_[i];
      body.AddLinearVelocityStep(dt *
                                 (motion.gravity_factor * gravity + body.inv_mass * motion.force));
      body.angular_velocity += dt * body.MultiplyInverseInertia(motion.torque);
      body.linear_velocity *= std::max(T(0), T(1) - motion.linear_damping * dt);
      body.angular_velocity *= std::max(T(0), T(1) - motion.angular_damping * dt);
      ClampVelocities(body, motion);
    }
  }

  // Step 5: symplectic Euler with the solved velocities, rotation first.
  void Integrate(T dt) {
    for (std::size_t i = 0; i < bodies_.size(); ++i) {
      Body<T>& body = bodies_[i];
      if (body.IsStatic()) continue;
      if (body.IsDynamic()) ClampVelocities(body, motion_[i]);
      body.AddRotationStep(body.angular_velocity * dt);
      body.AddPositionStep(body.linear_velocity * dt);  // x ← x + lockT(v·dt)
    }
  }

  bool SolvePosition(Constraint& constraint, T dt, T baumgarte) {
    return std::visit(
        [&](auto& c) -> bool {
          using Type = std::decay_t<decltype(c)>;
          Body<T>& body1 = bodies_[c.body1()];
          Body<T>& body2 = bodies_[c.body2()];
          if constexpr (std::is_same_v<Type, GearConstraint<T>>) {
            if (!c.HasPositionCorrection()) return false;
            // Measured now, after the constraints before this one moved the bodies.
            return c.SolvePositionConstraint(body1, body2,
                                             RotationMeasuredByHinge(c.hinge1(), c.body1()),
                                             RotationMeasuredByHinge(c.hinge2(), c.body2()),
                                             baumgarte);
          } else if constexpr (std::is_same_v<Type, RackAndPinionConstraint<T>>) {
            if (!c.HasPositionCorrection()) return false;
            return c.SolvePositionConstraint(body1, body2,
                                             RotationMeasuredByHinge(c.hinge(), c.body1()),
                                             TranslationMeasuredBySlider(c.slider(), c.body2()),
                                             baumgarte);
          } else {
            return c.SolvePositionConstraint(body1, body2, dt, baumgarte);
          }
        },
        constraint);
  }

  // The constraints the exact solve leaves whole to Gauss-Seidel
  // (ExactSolvePlan::SolvedWhole): none of their rows is in K. A six-DOF
  // constraint is solved whole without an all-fixed shortcut, a distance
  // constraint unless it is a rod with a group (ChooseRodGroups).
  template <class Type>
  static constexpr bool kMaySolveWhole =
      std::is_same_v<Type, DistanceConstraint<T>> || std::is_same_v<Type, PulleyConstraint<T>> ||
      std::is_same_v<Type, SixDofConstraint<T>> || std::is_same_v<Type, PathConstraint<T>>;
  template <class Type>
  static bool IsSolvedWhole(const Type& c) {
    if constexpr (std::is_same_v<Type, SixDofConstraint<T>>) {
      return !c.HasExactGroups();
    } else if constexpr (std::is_same_v<Type, DistanceConstraint<T>>) {
      return !c.exact_group();
    } else {
      return kMaySolveWhole<Type>;
    }
  }

  // Such a constraint seen as the rows around the exact solve: every row of
  // it, with its own verbs.
  template <class C>
  struct SolvedWhole {
    C& c;
    void SetupInequalityRows(const Body<T>& body1, const Body<T>& body2, T dt) {
      c.SetupVelocityConstraint(body1, body2, dt);
    }
    void WarmStartInequalityRows(Body<T>& body1, Body<T>& body2, T warm_start_ratio) {
      c.WarmStartVelocityConstraint(body1, body2, warm_start_ratio);
    }
    bool SolveInequalityVelocity(Body<T>& body1, Body<T>& body2, T dt) {
      return c.SolveVelocityConstraint(body1, body2, dt);
    }
    bool SolveLimitPosition(Body<T>& body1, Body<T>& body2, T dt, T baumgarte) {
      return c.SolvePositionConstraint(body1, body2, dt, baumgarte);
    }
  };

  // JointSolver::kExact (reference/exact_solve.h): the equality rows of
  // point, hinge, fixed, slider, gear, rack-and-pinion, swing-twist and cone
  // constraints, the rods with a group and the six-DOF constraints'
  // all-fixed shortcuts; the hinges' and sliders' motors, friction and
  // limits, the swing-twist limits and drives, the cone rows, the six-DOF
  // constraints' other rows and every row of the other distance
  // constraints, the pulley and path constraints (and of six-DOF constraints
  // without a shortcut) by Gauss-Seidel around them; every constraint with
  // row groups on at least one dynamic body with all six degrees of freedom
  // (what the batch's plan takes).
  ExactJointSolve<T> ExactSolve(T stiffness) {
    // A constraint with row groups needs a dynamic body with all six DOFs
    // (batch/exact_plan.cc).
    for (std::size_t index = 0; index < constraints_.size(); ++index) {
      if (!IsSolved(constraints_[index])) continue;
      std::visit(
          [&](const auto& c) {
            if (!IsSolvedWhole(c) && !IsFreeBody(c.body1()) && !IsFreeBody(c.body2())) {
              throw std::invalid_argument("reference::World: constraint " +
                                          std::to_string(index) +
                                          " joins no unrestricted dynamic body (exact solve)");
            }
          },
          constraints_[index]);
    }
    return ExactJointSolve<T>(bodies_, [this] { return ExactRowGroups(); }, exact_impulses_,
                              stiffness);
  }

  // A dynamic body with all six DOFs (what a constraint with row groups
  // needs on one side).
  bool IsFreeBody(std::size_t b) const {
    return bodies_[b].IsDynamic() && bodies_[b].translation_mask == Vec3<T>::Ones() &&
           bodies_[b].rotation_mask == Vec3<T>::Ones();
  }

  // The rods whose row the exact solve factors, as the batch's plan chooses
  // them (batch/exact_plan.h, ChooseRodGroups): a free body on one side, and
  // a pair of bodies (non-dynamic ones one fixed frame) that no constraint
  // with groups and no earlier rod with one joins.
  void ChooseRodGroups() {
    const std::size_t fixed_frame = bodies_.size();
    const auto end = [&](std::size_t b) { return bodies_[b].IsDynamic() ? b : fixed_frame; };
    std::set<std::pair<std::size_t, std::size_t>> joined;
    for (const Constraint& constraint : constraints_) {
      std::visit(
          [&](const auto& c) {
            using Type = std::decay_t<decltype(c)>;
            if constexpr (!std::is_same_v<Type, DistanceConstraint<T>>) {
              if (!IsSolvedWhole(c)) joined.insert(std::minmax(end(c.body1()), end(c.body2())));
            }
          },
          constraint);
    }
    for (Constraint& constraint : constraints_) {
      auto* rod = std::get_if<DistanceConstraint<T>>(&constraint);
      if (rod == nullptr || !rod->rigid() ||
          (!IsFreeBody(rod->body1()) && !IsFreeBody(rod->body2()))) {
        continue;
      }
      rod->set_exact_group(
          joined.insert(std::minmax(end(rod->body1()), end(rod->body2()))).second);
    }
  }

  // Every solved constraint's row groups at the current poses, in scene order.
  std::vector<ExactRowGroup<T>> ExactRowGroups() const {
    std::vector<ExactRowGroup<T>> groups;
    for (std::size_t index = 0; index < constraints_.size(); ++index) {
      const Constraint& constraint = constraints_[index];
      if (!IsSolved(constraint)) continue;
      const std::size_t first_group = groups.size();
      std::visit(
          [&](const auto& c) {
            using Type = std::decay_t<decltype(c)>;
            if constexpr (std::is_same_v<Type, PointConstraint<T>> ||
                          std::is_same_v<Type, SwingTwistConstraint<T>> ||
                          std::is_same_v<Type, ConeConstraint<T>>) {
              groups.push_back(PointRows(c.body1(), c.body2(), bodies_, c.local_point1(), c.local_point2()));
            } else if constexpr (std::is_same_v<Type, HingeConstraint<T>>) {
              groups.push_back(PointRows(c.body1(), c.body2(), bodies_, c.local_point1(), c.local_point2()));
              groups.push_back(HingeRotationRows(c, bodies_));
            } else if constexpr (std::is_same_v<Type, FixedConstraint<T>>) {
              groups.push_back(PointRows(c.body1(), c.body2(), bodies_, c.local_point1(), c.local_point2()));
              groups.push_back(RotationRows(c.body1(), c.body2(), bodies_, c.inv_initial_orientation()));
            } else if constexpr (std::is_same_v<Type, SliderConstraint<T>>) {
              groups.push_back(SliderAxesRows(c, bodies_));
              groups.push_back(RotationRows(c.body1(), c.body2(), bodies_, c.inv_initial_orientation()));
            } else if constexpr (std::is_same_v<Type, DistanceConstraint<T>>) {
              if (c.exact_group()) groups.push_back(DistanceRows(c, bodies_));
            } else if constexpr (std::is_same_v<Type, SixDofConstraint<T>>) {
              if (c.translation_point()) {
                groups.push_back(PointRows(c.body1(), c.body2(), bodies_, c.fixed_point1(), c.local_point2()));
              }
              if (c.rotation_euler()) {
                groups.push_back(RotationRows(c.body1(), c.body2(), bodies_, c.inv_initial_orientation()));
              }
            } else if constexpr (std::is_same_v<Type, GearConstraint<T>>) {
              const bool measured = c.HasPositionCorrection();
              groups.push_back(GearRows(c, bodies_,
                                        measured ? RotationMeasuredByHinge(c.hinge1(), c.body1()) : T(0),
                                        measured ? RotationMeasuredByHinge(c.hinge2(), c.body2()) : T(0)));
            } else if constexpr (std::is_same_v<Type, RackAndPinionConstraint<T>>) {
              const bool measured = c.HasPositionCorrection();
              groups.push_back(RackAndPinionRows(
                  c, bodies_, measured ? RotationMeasuredByHinge(c.hinge(), c.body1()) : T(0),
                  measured ? TranslationMeasuredBySlider(c.slider(), c.body2()) : T(0)));
            }
          },
          constraint);
      for (std::size_t k = first_group; k < groups.size(); ++k) groups[k].constraint = index;
    }
    return groups;
  }

  void StepOnce(const StepSettings& settings, T dt, T warm_start_ratio, T stiffness_ratio) {
    ApplyForcesAndDamping(dt, ToVec3<T>(settings.gravity), settings.gyroscopic);

    // Contacts come after every joint in each phase (docs/contacts.md); every
    // slot has a dynamic body (MakeContacts), so all are solved.
    const ContactSettings<T> contact_settings{
        T(settings.speculative_contact_distance), T(settings.penetration_slop),
        T(settings.max_penetration_distance), T(settings.min_velocity_for_restitution),
        settings.speculative_contacts_from_velocity};
    const Vec3<T> gravity = ToVec3<T>(settings.gravity);
    const auto setup_contacts = [&] {
      for (ContactConstraint<T>& contact : contacts_) {
        contact.Setup(bodies_[contact.body1()], motion_[contact.body1()],
                      bodies_[contact.body2()], motion_[contact.body2()], dt, gravity,
                      contact_settings);
      }
    };
    const auto warm_start_contacts = [&] {
      for (ContactConstraint<T>& contact : contacts_) {
        contact.WarmStart(bodies_[contact.body1()], bodies_[contact.body2()], warm_start_ratio);
      }
    };
    const auto solve_contact_velocities = [&] {
      bool applied = false;
      for (ContactConstraint<T>& contact : contacts_) {
        applied |= contact.SolveVelocity(bodies_[contact.body1()], bodies_[contact.body2()]);
      }
      return applied;
    };
    const auto solve_contact_positions = [&] {
      bool moved = false;
      for (ContactConstraint<T>& contact : contacts_) {
        moved |= contact.SolvePosition(bodies_[contact.body1()], bodies_[contact.body2()],
                                       T(settings.baumgarte), contact_settings.penetration_slop,
                                       contact_settings.max_penetration_distance);
      }
      return moved;
    };

    // StepSettings::velocity_tolerance: the velocity passes stop after the
    // first pass that changed no velocity component of a dynamic body by
    // more than it (Gauss-Seidel's passes and the exact solve's).
    const T tolerance = T(settings.velocity_tolerance);
    std::vector<Vec3<T>> before(2 * bodies_.size());
    // Every component within the tolerance (false for a NaN change).
    const auto converged = [&] {
      for (std::size_t b = 0; b < bodies_.size(); ++b) {
        if (!bodies_[b].IsDynamic()) continue;
        const Vec3<T> linear = bodies_[b].linear_velocity - before[2 * b];
        const Vec3<T> angular = bodies_[b].angular_velocity - before[2 * b + 1];
        for (int i = 0; i < 3; ++i) {
          for (const T d : {linear[i], angular[i]}) {
            if (!(d <= tolerance && d >= -tolerance)) return false;
          }
        }
      }
      return true;
    };
    const auto remember_velocities = [&] {
      for (std::size_t b = 0; b < bodies_.size() && tolerance > T(0); ++b) {
        before[2 * b] = bodies_[b].linear_velocity;
        before[2 * b + 1] = bodies_[b].angular_velocity;
      }
    };
    const auto within_tolerance = [&] { return tolerance > T(0) && converged(); };

    if (settings.solver == JointSolver::kExact && !constraints_.empty()) {
      ExactJointSolve<T> exact =
          ExactSolve(T(settings.exact_geometric_stiffness) * dt * stiffness_ratio);
      // The hinges' turn counts, which their velocity setup would update.
      for (Constraint& constraint : constraints_) {
        if (auto* hinge = std::get_if<HingeConstraint<T>>(&constraint)) {
          hinge->CountTurnsAt(bodies_[hinge->body1()], bodies_[hinge->body2()]);
        }
      }
      // The hinges' and sliders' motors, friction and limits: block
      // Gauss-Seidel around the exact solve (batch/exact_inequality_rows-inl.h).
      std::vector<Constraint*> bounded;
      for (Constraint& constraint : constraints_) {
        const bool has = std::visit(
            [](const auto& c) {
              using Type = std::decay_t<decltype(c)>;
              if constexpr (std::is_same_v<Type, HingeConstraint<T>> ||
                            std::is_same_v<Type, SliderConstraint<T>> ||
                            std::is_same_v<Type, SixDofConstraint<T>>) {
                return IsSolvedWhole(c) || c.HasInequalityRows();
              } else {
                // The swing-twist limits (and drives), the cone row, and
                // the constraints solved whole.
                return std::is_same_v<Type, SwingTwistConstraint<T>> ||
                       std::is_same_v<Type, ConeConstraint<T>> || IsSolvedWhole(c);
              }
            },
            constraint);
        if (has && IsSolved(constraint)) bounded.push_back(&constraint);
      }
      const auto for_each_bounded = [&](auto&& action) {
        bool any = false;
        for (Constraint* constraint : bounded) {
          std::visit(
              [&](auto& c) {
                using Type = std::decay_t<decltype(c)>;
                if constexpr (kMaySolveWhole<Type>) {
                  if (IsSolvedWhole(c)) {
                    SolvedWhole<Type> whole{c};
                    any |= action(whole, bodies_[c.body1()], bodies_[c.body2()]);
                    return;
                  }
                }
                if constexpr (std::is_same_v<Type, HingeConstraint<T>> ||
                              std::is_same_v<Type, SliderConstraint<T>> ||
                              std::is_same_v<Type, SwingTwistConstraint<T>> ||
                              std::is_same_v<Type, ConeConstraint<T>> ||
                              std::is_same_v<Type, SixDofConstraint<T>>) {
                  any |= action(c, bodies_[c.body1()], bodies_[c.body2()]);
                }
              },
              *constraint);
        }
        return any;
      };
      // Contacts are inequality rows too: set up from the velocities after
      // the forces, warm-started after the joints' rows, solved after them
      // in every pass and after their Baumgarte step in every Newton pass.
      setup_contacts();
      for_each_bounded([&](auto& c, Body<T>& body1, Body<T>& body2) {
        c.SetupInequalityRows(body1, body2, dt);
        c.WarmStartInequalityRows(body1, body2, warm_start_ratio);
        return false;
      });
      warm_start_contacts();
      exact.SolveVelocity();
      // The tolerance is tested from the second pass on, the first that
      // visits the inequality rows. Without row groups (every constraint
      // solved whole) the passes are Gauss-Seidel's, and stop as its do.
      const bool factored = exact.HasGroups();
      if (!bounded.empty() || !contacts_.empty()) {
        for (int pass = 1; pass < settings.velocity_iterations; ++pass) {
          remember_velocities();
          bool applied = for_each_bounded([&](auto& c, Body<T>& body1, Body<T>& body2) {
            return c.SolveInequalityVelocity(body1, body2, dt);
          });
          applied |= solve_contact_velocities();
          if (factored) {
            exact.SolveVelocity(true);
          } else if (!applied) {
            break;
          }
          if (within_tolerance()) break;
        }
      }
      Integrate(dt);
      if (settings.exact_curvature_velocity && bounded.empty() && contacts_.empty()) {
        exact.CurvatureVelocity(dt);
      }
      exact.SolvePosition(
          settings.position_iterations, T(settings.exact_tolerance),
          [&] {
            bool moved = for_each_bounded([&](auto& c, Body<T>& body1, Body<T>& body2) {
              return c.SolveLimitPosition(body1, body2, dt, T(settings.baumgarte));
            });
            moved |= solve_contact_positions();
            return moved;
          },
          !bounded.empty() || !contacts_.empty());
      return;
    }

    std::vector<Constraint*> solved;
    for (Constraint& constraint : constraints_) {
      if (IsSolved(constraint)) solved.push_back(&constraint);
    }
    const auto for_each_solved = [&](auto&& action) {
      for (Constraint* constraint : solved) {
        std::visit([&](auto& c) { action(c, bodies_[c.body1()], bodies_[c.body2()]); },
                   *constraint);
      }
    };

    for_each_solved([&](auto& c, Body<T>& body1, Body<T>& body2) {
      c.SetupVelocityConstraint(body1, body2, dt);
    });
    setup_contacts();
    for_each_solved([&](auto& c, Body<T>& body1, Body<T>& body2) {
      c.WarmStartVelocityConstraint(body1, body2, warm_start_ratio);
    });
    warm_start_contacts();
    for (int iteration = 0; iteration < settings.velocity_iterations; ++iteration) {
      remember_velocities();
      bool applied = false;
      for_each_solved([&](auto& c, Body<T>& body1, Body<T>& body2) {
        applied |= c.SolveVelocityConstraint(body1, body2, dt);
      });
      applied |= solve_contact_velocities();
      if (!applied || within_tolerance()) break;
    }

    Integrate(dt);

    const T baumgarte = T(settings.baumgarte);
    for (int iteration = 0; iteration < settings.position_iterations; ++iteration) {
      bool moved = false;
      for (Constraint* constraint : solved) moved |= SolvePosition(*constraint, dt, baumgarte);
      moved |= solve_contact_positions();
      if (!moved) break;
    }
  }

  std::vector<Body<T>> bodies_;
  std::vector<BodyMotionSettings<T>> motion_;
  std::vector<Constraint> constraints_;
  std::vector<ContactConstraint<T>> contacts_;  // slots in the order of (body1, body2)
  T previous_step_dt_ = T(0);  // Jolt's mPreviousStepDeltaTime (warm-start ratio)
  // JointSolver::kExact: each row group's impulse of the last velocity solve
  // (kept for point groups). The
  // batch keeps it in the point part's accumulated impulse, which Gauss-Seidel
  // warm-starts from; here the two are apart, so a batch and a reference that
  // switch solvers between steps part ways (the tests never switch).
  std::vector<Vec3<T>> exact_impulses_;
};

// Defined out of the class so that `extern template` below keeps every
// translation unit that steps a World<float> or World<double> from compiling
// the whole stepper again (about 35 s each with Eigen at -O2): they are
// compiled once, in reference/world_float.cc and reference/world_double.cc.
// Other scalars (tests/flop_count_test.cc's counted float) instantiate here.
template <class T>
World<T>::World(const Scene& scene) {
  for (const BodySettings& settings : scene.bodies()) {
    bodies_.push_back(MakeBody<T>(settings));
    motion_.push_back(MakeBodyMotionSettings<T>(settings));
  }
  const auto& constraints = scene.constraints();
  for (std::size_t index = 0; index < constraints.size(); ++index) {
    constraints_.push_back(std::visit(
        [&](const auto& settings) { return MakeConstraint(settings, index); },
        constraints[index]));
  }
  for (std::size_t index = 0; index < constraints_.size(); ++index) CheckHelpers(index);
  ChooseRodGroups();
  MakeContacts(scene);
}

template <class T>
void World<T>::Step(const StepSettings& settings) {
  if (!(settings.delta_time > 0.0f) || settings.substeps < 1 ||
      settings.velocity_iterations < 0 || settings.position_iterations < 0 ||
      !(settings.velocity_tolerance >= 0.0f && std::isfinite(settings.velocity_tolerance))) {
    throw std::invalid_argument("reference::World::Step: invalid step settings");
  }
  for (const float value :
       {settings.speculative_contact_distance, settings.penetration_slop,
        settings.max_penetration_distance, settings.min_velocity_for_restitution}) {
    if (!(std::isfinite(value) && value >= 0.0f)) {
      throw std::invalid_argument("reference::World::Step: invalid contact settings");
    }
  }
  const T step_dt = T(settings.delta_time) / T(settings.substeps);
  const T first_ratio = settings.warm_start && previous_step_dt_ > T(0)
                            ? step_dt / previous_step_dt_
                            : T(0);
  // The exact solve's stiffness scales the last impulses by dt / dt_prev
  // (they acted over the previous substep), whatever warm_start says.
  const T first_stiffness_ratio =
      previous_step_dt_ > T(0) ? step_dt / previous_step_dt_ : T(1);
  previous_step_dt_ = step_dt;
  for (int substep = 0; substep < settings.substeps; ++substep) {
    StepOnce(settings, step_dt, substep == 0 ? first_ratio : T(1),
             substep == 0 ? first_stiffness_ratio : T(1));
  }
  for (BodyMotionSettings<T>& motion : motion_) {
    motion.force.setZero();
    motion.torque.setZero();
  }
}

template <class T>
std::vector<T> World<T>::SolverState() const {
  std::vector<T> values;
  SolverStateWriter<T> out(values);
  for (const Constraint& constraint : constraints_) {
    std::visit([&](const auto& c) { c.SaveSolverState(out); }, constraint);
  }
  for (const ContactConstraint<T>& contact : contacts_) contact.SaveSolverState(out);
  return values;
}

template <class T>
void World<T>::SetSolverState(std::span<const T> values) {
  const std::size_t expected = SolverState().size();
  if (values.size() != expected) {  // checked before anything is written
    throw std::invalid_argument("reference::World::SetSolverState: " +
                                std::to_string(values.size()) + " values, the layout has " +
                                std::to_string(expected));
  }
  SolverStateReader<T> in(values);
  for (Constraint& constraint : constraints_) {
    std::visit([&](auto& c) { c.RestoreSolverState(in); }, constraint);
  }
  for (ContactConstraint<T>& contact : contacts_) contact.RestoreSolverState(in);
  const std::vector<ExactRowGroup<T>> groups = ExactRowGroups();
  exact_impulses_.assign(groups.size(), Vec3<T>::Zero());
  for (std::size_t k = 0; k < groups.size(); ++k) {
    if (!groups[k].point) continue;
    std::visit(
        [&](const auto& c) {
          if constexpr (requires { c.PointImpulse(); }) exact_impulses_[k] = c.PointImpulse();
        },
        constraints_[groups[k].constraint]);
  }
}

extern template class World<float>;
extern template class World<double>;

}  // namespace manyworlds::reference
