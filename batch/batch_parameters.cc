// Batch: per-world parameters (domain randomisation). Every value goes
// through the same check as the scene's setting of it (batch/scene_checks.h)
// and is refused by name, before anything is written, where the scene would
// refuse it.

#include <string>

#include "batch/batch_impl.h"
#include "batch/scene_checks.h"
#include "batch/scene_setup.h"
#include "manyworlds/batch.h"
#include "manyworlds/error.h"

namespace manyworlds {

void Batch::SetMassProperties(std::size_t world, std::size_t body, float mass,
                              Float3 inertia_diagonal) {
  Impl& batch = impl();
  batch.Motion(world, body, "mass properties");
  CheckMassProperties(batch.InWorld(batch.plan_.bodies[body].label, world), mass,
                      inertia_diagonal);
  const InverseMassProperties inverse =
      InverseMassPropertiesOf(batch.scene_.bodies()[body], mass, inertia_diagonal);
  BodyLanes& b = batch.Body(world, body);
  const std::size_t l = Impl::Lane(world);
  b.inv_mass[l] = inverse.inv_mass;
  b.inv_inertia_diagonal.x[l] = inverse.inv_inertia_diagonal[0];
  b.inv_inertia_diagonal.y[l] = inverse.inv_inertia_diagonal[1];
  b.inv_inertia_diagonal.z[l] = inverse.inv_inertia_diagonal[2];
}

void Batch::SetDamping(std::size_t world, std::size_t body, float linear, float angular) {
  Impl& batch = impl();
  BodyMotionLanes& m = batch.Motion(world, body, "damping");
  CheckDamping(batch.InWorld(batch.plan_.bodies[body].label, world), linear, angular);
  m.linear_damping[Impl::Lane(world)] = linear;
  m.angular_damping[Impl::Lane(world)] = angular;
}

void Batch::SetGravityFactor(std::size_t world, std::size_t body, float factor) {
  Impl& batch = impl();
  BodyMotionLanes& m = batch.Motion(world, body, "a gravity factor");
  CheckGravityFactor(batch.InWorld(batch.plan_.bodies[body].label, world), factor);
  m.gravity_factor[Impl::Lane(world)] = factor;
}

void Batch::SetLimits(std::size_t world, std::size_t constraint, float min, float max) {
  Impl& batch = impl();
  batch.WithLimits(world, constraint, "limits", [&](auto& limit, const ConstraintPlan& c) {
    const std::string what = batch.InWorld(c.label, world);
    LimitRange range{};
    switch (c.type) {
      case ConstraintType::kHinge: range = CheckHingeLimits(what, min, max); break;
      case ConstraintType::kDistance:
        range = CheckDistanceLimits(what, min, max);
        // Its rigidity is the scene's (the exact solve factors a rod's row):
        // a rod's length may change per world, but it stays a rod.
        if (c.rod && min != max) {
          Refuse(what, "min_distance / max_distance",
                 "must stay equal: a rod in the scene (DistanceConstraintSettings::rigid) "
                 "stays a rod (got " + ValueText(min) + ", " + ValueText(max) + ")");
        }
        break;
      default:
        range = CheckTranslationLimits(what, "limits_min", "limits_max", min, max, true);
    }
    limit.min[Impl::Lane(world)] = range.min;
    limit.max[Impl::Lane(world)] = range.max;
  });
}

void Batch::SetLimitsSpring(std::size_t world, std::size_t constraint,
                            float frequency_or_stiffness, float damping) {
  Impl& batch = impl();
  batch.WithLimits(world, constraint, "a limits spring",
                   [&](auto& limit, const ConstraintPlan& c) {
                     const std::string what = batch.InWorld(c.label, world);
                     CheckSpring(what, "limits_spring",
                                 {c.limit_spring_mode, frequency_or_stiffness, damping});
                     // The plan skips position-phase limit steps for soft limits,
                     // so a world may tune its spring but not switch hard <-> soft.
                     if ((frequency_or_stiffness > 0.0f) != c.soft_limits) {
                       Refuse(what, "limits_spring",
                              c.soft_limits
                                  ? "must keep a positive frequency (soft in the scene)"
                                  : "must stay <= 0 (hard limits in the scene)");
                     }
                     limit.geometry.spring.frequency_or_stiffness[Impl::Lane(world)] =
                         frequency_or_stiffness;
                     limit.geometry.spring.damping[Impl::Lane(world)] = damping;
                   });
}

void Batch::SetMotorSpring(std::size_t world, std::size_t constraint,
                           float frequency_or_stiffness, float damping) {
  Impl& batch = impl();
  batch.WithMotor(world, constraint, "a motor spring",
                  [&](auto& motor, const ConstraintPlan& c) {
                    CheckMotorSpring(batch.InWorld(c.label, world), "motor.spring", c.drive,
                                     {c.motor_spring_mode, frequency_or_stiffness, damping});
                    motor.geometry.spring.frequency_or_stiffness[Impl::Lane(world)] =
                        frequency_or_stiffness;
                    motor.geometry.spring.damping[Impl::Lane(world)] = damping;
                  });
}

void Batch::SetMotorLimits(std::size_t world, std::size_t constraint, float min, float max) {
  Impl& batch = impl();
  batch.WithMotor(world, constraint, "motor limits", [&](auto& motor, const ConstraintPlan& c) {
    CheckMotorLimits(batch.InWorld(c.label, world), "motor.min_force_limit / max_force_limit",
                     min, max);
    motor.min_force_limit[Impl::Lane(world)] = min;
    motor.max_force_limit[Impl::Lane(world)] = max;
  });
}

void Batch::SetMaxFriction(std::size_t world, std::size_t constraint, float max_friction) {
  Impl& batch = impl();
  batch.WithMotor(world, constraint, "a max friction",
                  [&](auto& motor, const ConstraintPlan& c) {
                    CheckMaxFriction(batch.InWorld(c.label, world), "max friction",
                                     max_friction);
                    motor.max_friction[Impl::Lane(world)] = max_friction;
                  });
}

void Batch::SetRatio(std::size_t world, std::size_t constraint, float ratio) {
  Impl& batch = impl();
  batch.CheckWorld(world);
  const ConstraintPlan& c = batch.Constraint(constraint);
  const std::string what = batch.InWorld(c.label, world);
  CheckFinite(what, "ratio", ratio);
  const std::size_t l = Impl::Lane(world);
  if (c.type == ConstraintType::kGear) {
    batch.In<GearConstraintLanes>(world, c.offset).geometry.ratio[l] = ratio;
  } else if (c.type == ConstraintType::kRackAndPinion) {
    batch.In<RackAndPinionConstraintLanes>(world, c.offset).geometry.ratio[l] = ratio;
  } else if (c.type == ConstraintType::kPulley) {
    if (!(ratio > 0.0f)) Refuse(what, "ratio", "must be positive for a pulley");
    batch.In<PulleyConstraintLanes>(world, c.offset).geometry.ratio[l] = ratio;
  } else {
    throw SceneError(c.label +
                     ": ratio applies to gear, rack-and-pinion and pulley constraints only");
  }
}

}  // namespace manyworlds
