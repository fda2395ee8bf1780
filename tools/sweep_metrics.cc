// Accuracy metrics of `manyworlds sweep` (see sweep_metrics.h).

#include "tools/sweep_metrics.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <type_traits>
#include <variant>

#include "manyworlds/batch.h"

namespace manyworlds::tools {
namespace {

template <class T>
Eigen::Vector3d Vector(std::span<const T> s, std::size_t offset) {
  return Eigen::Vector3d(double(s[offset]), double(s[offset + 1]), double(s[offset + 2]));
}

// The state stores quaternions as (x, y, z, w).
template <class T>
Eigen::Quaterniond Rotation(std::span<const T> s, std::size_t offset) {
  return Eigen::Quaterniond(double(s[offset + 3]), double(s[offset]), double(s[offset + 1]),
                            double(s[offset + 2]));
}

Eigen::Quaterniond Rotation(const Quaternion& q) {
  return Eigen::Quaterniond(double(q[3]), double(q[0]), double(q[1]), double(q[2]));
}

std::size_t BodyOffset(std::size_t body, StateField field) {
  return body * kStateFloatsPerBody + StateFieldOffset(field);
}

}  // namespace

double MechanicalEnergy(const Scene& scene, std::span<const float> world_state, Float3 gravity) {
  const Eigen::Vector3d g(gravity[0], gravity[1], gravity[2]);
  double energy = 0.0;
  for (std::size_t i = 0; i < scene.bodies().size(); ++i) {
    const BodySettings& body = scene.bodies()[i];
    if (body.motion_type != MotionType::kDynamic) continue;
    const Eigen::Vector3d x = Vector(world_state, BodyOffset(i, StateField::kPosition));
    const Eigen::Vector3d v = Vector(world_state, BodyOffset(i, StateField::kLinearVelocity));
    const Eigen::Vector3d w = Vector(world_state, BodyOffset(i, StateField::kAngularVelocity));
    // Principal frame = body rotation times the inertia rotation.
    const Eigen::Quaterniond principal =
        (Rotation(world_state, BodyOffset(i, StateField::kRotation)).normalized() *
         Rotation(body.inertia_rotation).normalized());
    const Eigen::Vector3d w_p = principal.conjugate() * w;
    const Eigen::Vector3d inertia(body.inertia_diagonal[0], body.inertia_diagonal[1],
                                  body.inertia_diagonal[2]);
    energy += 0.5 * body.mass * v.squaredNorm() + 0.5 * w_p.dot(inertia.cwiseProduct(w_p)) -
              body.mass * body.gravity_factor * g.dot(x);
  }
  return energy;
}

bool EnergyIsConserved(const Scene& scene, const SceneActions& actions) {
  if (!actions.empty()) return false;
  for (const BodySettings& body : scene.bodies()) {
    if (body.motion_type == MotionType::kKinematic) return false;
    if (body.motion_type == MotionType::kDynamic &&
        (body.linear_damping != 0.0f || body.angular_damping != 0.0f)) {
      return false;
    }
  }
  for (const ConstraintSettings& constraint : scene.constraints()) {
    const bool conservative = std::visit(
        [](const auto& c) {
          using Type = std::decay_t<decltype(c)>;
          if constexpr (std::is_same_v<Type, HingeConstraintSettings>) {
            return c.motor_state == MotorState::kOff && c.max_friction_torque == 0.0f &&
                   !c.limits_spring.HasStiffnessOrDamping();
          } else if constexpr (std::is_same_v<Type, SliderConstraintSettings>) {
            return c.motor_state == MotorState::kOff && c.max_friction_force == 0.0f &&
                   !c.limits_spring.HasStiffnessOrDamping();
          } else if constexpr (std::is_same_v<Type, DistanceConstraintSettings>) {
            return !c.limits_spring.HasStiffnessOrDamping();
          } else if constexpr (std::is_same_v<Type, SwingTwistConstraintSettings>) {
            return c.swing_motor_state == MotorState::kOff &&
                   c.twist_motor_state == MotorState::kOff && c.max_friction_torque == 0.0f;
          } else if constexpr (std::is_same_v<Type, SixDofConstraintSettings>) {
            const auto off = [](MotorState state) { return state == MotorState::kOff; };
            const auto zero = [](float friction) { return friction == 0.0f; };
            const auto no_spring = [](const SpringSettings& spring) {
              return !spring.HasStiffnessOrDamping();
            };
            return std::all_of(c.motor_state.begin(), c.motor_state.end(), off) &&
                   std::all_of(c.max_friction.begin(), c.max_friction.end(), zero) &&
                   std::all_of(c.limits_spring.begin(), c.limits_spring.end(), no_spring);
          } else {
            return true;  // point, fixed, gear, rack, pulley, cone: no motors, friction or springs
          }
        },
        constraint);
    if (!conservative) return false;
  }
  return true;
}

std::vector<std::size_t> CouplingConstraints(const Scene& scene) {
  std::vector<std::size_t> couplings;
  for (std::size_t i = 0; i < scene.constraints().size(); ++i) {
    const ConstraintSettings& c = scene.constraints()[i];
    if (const auto* gear = std::get_if<GearConstraintSettings>(&c)) {
      if (gear->hinge1 != kNoConstraint && gear->hinge2 != kNoConstraint) couplings.push_back(i);
    } else if (const auto* rack = std::get_if<RackAndPinionConstraintSettings>(&c)) {
      if (rack->hinge != kNoConstraint && rack->slider != kNoConstraint) couplings.push_back(i);
    }
  }
  return couplings;
}

PoseError BodyPoseError(const Scene& scene, std::span<const float> world_state,
                        std::span<const double> reference_state) {
  PoseError error;
  for (std::size_t i = 0; i < scene.bodies().size(); ++i) {
    if (scene.bodies()[i].motion_type == MotionType::kStatic) continue;
    const std::size_t x = BodyOffset(i, StateField::kPosition);
    const std::size_t q = BodyOffset(i, StateField::kRotation);
    error.position = std::max(
        error.position, (Vector(world_state, x) - Vector(reference_state, x)).norm());
    const Eigen::Quaterniond difference =
        Rotation(reference_state, q).normalized().conjugate() *
        Rotation(world_state, q).normalized();
    // q and -q are the same rotation: the angle of the shorter way round.
    error.rotation = std::max(
        error.rotation, 2.0 * std::atan2(difference.vec().norm(), std::abs(difference.w())));
  }
  return error;
}

}  // namespace manyworlds::tools
