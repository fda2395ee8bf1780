// libFuzzer target: random bytes -> a scene (every motion type, every
// constraint type of scene.h with random settings, every shape type in
// random frames, so bodies start inside each other and the ground), sometimes passed through
// LimitMassRange, a Batch of a few worlds, then a few steps with random
// actions, states, resets and per-world parameters written in (NaN,
// infinities and huge values included), with either joint solver.
//
// What must hold for every input (built with -fsanitize=fuzzer,address,
// undefined, so any bad access, leak or undefined behaviour aborts):
//   - a bad scene, bad step settings or a bad call is refused with SceneError,
//     std::invalid_argument or std::out_of_range, never a crash;
//   - WorldHealth() has one byte per world, holding only WorldHealthBits;
//   - with UnhealthyWorlds::kKeep, a world whose state is not finite after a
//     step is flagged kNonFiniteState (the health check misses nothing);
//   - with UnhealthyWorlds::kReset, no world is left non-finite;
//   - a refused call or step changes no byte of the batch (Snapshot bytes);
//   - a step restored from a snapshot and taken again gives the same bytes;
//   - a step stopped before it began steps no world and flags every one.
// A broken property calls __builtin_trap(), which libFuzzer reports as a crash.
//
// The byte decoder favours values a Batch accepts (unit axes from a short
// list, perpendicular normals, masses in [0.01, 100]) so that most inputs get
// past the scene checks and reach the stepper; one byte in ~16 picks a
// special value instead (see Float below).

#include <fuzzer/FuzzedDataProvider.h>

#include <cfloat>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <iterator>
#include <limits>
#include <optional>
#include <stop_token>
#include <stdexcept>
#include <vector>

#include "hwy/targets.h"
#include "manyworlds/batch.h"
#include "manyworlds/error.h"
#include "manyworlds/mass_range.h"
#include "manyworlds/scene.h"

namespace manyworlds {
namespace {

constexpr std::size_t kMaxBodies = 6;
constexpr std::size_t kMaxConstraints = 8;
constexpr std::size_t kMaxWorlds = 40;  // up to 3 blocks, the last one partly padding
constexpr int kMaxSteps = 4;
constexpr int kMaxCallsPerStep = 8;

// Values that break float arithmetic or sit on a boundary the checks test.
constexpr float kSpecial[] = {
    0.0f, -0.0f, 1.0f, -1.0f, kPi, -kPi, 1e30f, -1e30f, FLT_MAX, -FLT_MAX, FLT_MIN,
    FLT_TRUE_MIN, FLT_EPSILON, 16777216.0f, 1e-30f,
    std::numeric_limits<float>::infinity(), -std::numeric_limits<float>::infinity(),
    std::numeric_limits<float>::quiet_NaN(),
};

// A float in [lo, hi] most of the time, else a special value or raw bits.
float Float(FuzzedDataProvider& in, float lo, float hi) {
  const std::uint8_t kind = in.ConsumeIntegral<std::uint8_t>();
  if (kind < 240) return in.ConsumeFloatingPointInRange(lo, hi);
  if (kind < 254) return kSpecial[in.ConsumeIntegralInRange<std::size_t>(0, std::size(kSpecial) - 1)];
  return in.ConsumeFloatingPoint<float>();  // any float, including NaN and denormals
}

Float3 Vec(FuzzedDataProvider& in, float lo, float hi) {
  return {Float(in, lo, hi), Float(in, lo, hi), Float(in, lo, hi)};
}

// An axis and a normal to it. Mostly a pair of unit axes from a short list
// (so the scene passes the perpendicularity checks), sometimes anything.
struct Frame {
  Float3 axis, normal;
};
Frame AxisPair(FuzzedDataProvider& in) {
  static constexpr Float3 kAxes[] = {{1, 0, 0},  {0, 1, 0},  {0, 0, 1},
                                     {-1, 0, 0}, {0, -1, 0}, {0, 0, -1}};
  const std::uint8_t kind = in.ConsumeIntegral<std::uint8_t>();
  if (kind < 224) {
    const std::size_t a = in.ConsumeIntegralInRange<std::size_t>(0, 5);
    const std::size_t n = (a + in.ConsumeIntegralInRange<std::size_t>(1, 2)) % 3 +
                          3 * in.ConsumeIntegralInRange<std::size_t>(0, 1);
    return {kAxes[a], kAxes[n]};
  }
  if (kind < 240) {  // perpendicular but not unit, or rotated off the grid
    const float s = Float(in, 0.01f, 10.0f), c = std::cos(Float(in, -kPi, kPi));
    const float t = std::sin(Float(in, -kPi, kPi));
    return {{s * c, s * t, 0}, {-t, c, 0}};
  }
  return {Vec(in, -2, 2), Vec(in, -2, 2)};
}

Quaternion Quat(FuzzedDataProvider& in) {
  const std::uint8_t kind = in.ConsumeIntegral<std::uint8_t>();
  if (kind < 64) return {0, 0, 0, 1};
  if (kind < 248) {  // any rotation; the batch normalises it
    return {Float(in, -1, 1), Float(in, -1, 1), Float(in, -1, 1), Float(in, -1, 1)};
  }
  return {0, 0, 0, 0};  // refused
}

// An enum value: one of its `count` enumerators, or one in ~30 times a value
// past them (a cast from a bad integer), which the batch must refuse by name.
template <class Enum>
Enum EnumValue(FuzzedDataProvider& in, int count) {
  if (in.ConsumeIntegral<std::uint8_t>() >= 248) {
    return static_cast<Enum>(count + in.ConsumeIntegralInRange<int>(0, 250 - count));
  }
  return static_cast<Enum>(in.ConsumeIntegralInRange<int>(0, count - 1));
}

std::size_t Index(FuzzedDataProvider& in, std::size_t count) {
  // One in ~30 out of range, to check that the batch refuses it.
  if (in.ConsumeIntegral<std::uint8_t>() >= 248) return count + in.ConsumeIntegral<std::uint8_t>();
  return count == 0 ? 0 : in.ConsumeIntegralInRange<std::size_t>(0, count - 1);
}

std::size_t Helper(FuzzedDataProvider& in, std::size_t constraints) {
  return in.ConsumeBool() ? kNoConstraint : Index(in, constraints);
}

SpringSettings Spring(FuzzedDataProvider& in) {
  SpringSettings spring;
  spring.mode = EnumValue<SpringMode>(in, 3);
  spring.frequency_or_stiffness = in.ConsumeBool() ? 0.0f : Float(in, -1, 100);
  spring.damping = Float(in, -0.5f, 5);
  return spring;
}

MotorSettings Motor(FuzzedDataProvider& in) {
  MotorSettings motor;
  if (in.ConsumeBool()) motor.spring = Spring(in);
  if (in.ConsumeBool()) {
    motor.min_force_limit = Float(in, -100, 10);
    motor.max_force_limit = Float(in, -10, 100);
  }
  return motor;
}

// A shape of any type (a plane on a moving body, zero or huge sizes and bad
// frictions now and then: refused by name), in a frame of its own; groups
// and masks that mostly meet.
ShapeSettings Shape(FuzzedDataProvider& in) {
  ShapeSettings shape;
  shape.type = EnumValue<ShapeType>(in, 5);
  shape.radius = Float(in, 0.02f, 2);
  shape.half_height = Float(in, 0.02f, 2);
  shape.half_extents = Vec(in, 0.02f, 2);
  if (in.ConsumeBool()) {
    shape.position = Vec(in, -1, 1);
    shape.rotation = Quat(in);
  }
  shape.friction = Float(in, 0, 2);
  shape.restitution = Float(in, 0, 1);
  if (in.ConsumeIntegral<std::uint8_t>() >= 224) {
    shape.collision_group = in.ConsumeIntegral<std::uint32_t>();
    shape.collision_mask = in.ConsumeIntegral<std::uint32_t>();
  }
  shape.collide_with_joined = in.ConsumeBool();
  return shape;
}

BodySettings Body(FuzzedDataProvider& in) {
  BodySettings body;
  body.motion_type = EnumValue<MotionType>(in, 3);
  body.mass = Float(in, 0.01f, 100);
  body.inertia_diagonal = Vec(in, 0.001f, 10);
  body.inertia_rotation = Quat(in);
  body.position = Vec(in, -10, 10);
  body.rotation = Quat(in);
  body.linear_velocity = Vec(in, -10, 10);
  body.angular_velocity = Vec(in, -10, 10);
  if (in.ConsumeBool()) {
    body.linear_damping = Float(in, 0, 2);
    body.angular_damping = Float(in, 0, 2);
    body.max_linear_velocity = Float(in, 0, 1000);
    body.max_angular_velocity = Float(in, 0, 100);
    body.gravity_factor = Float(in, -2, 2);
  }
  // Every bit pattern of the byte, including kNone and bits above kAll.
  if (in.ConsumeBool()) body.allowed_dofs = static_cast<AllowedDofs>(in.ConsumeIntegral<std::uint8_t>());
  if (in.ConsumeBool()) body.shape = Shape(in);
  return body;
}

template <class Settings>
void Common(FuzzedDataProvider& in, std::size_t bodies, Settings& c) {
  c.body1 = Index(in, bodies);
  c.body2 = Index(in, bodies);
  c.space = EnumValue<ConstraintSpace>(in, 2);
}

ConstraintSettings Constraint(FuzzedDataProvider& in, std::size_t bodies,
                              std::size_t constraints) {
  switch (in.ConsumeIntegralInRange<int>(0, 11)) {
    case 0: {
      PointConstraintSettings c;
      Common(in, bodies, c);
      c.point1 = Vec(in, -5, 5);
      c.point2 = in.ConsumeBool() ? c.point1 : Vec(in, -5, 5);
      return c;
    }
    case 1: {
      FixedConstraintSettings c;
      Common(in, bodies, c);
      c.auto_detect_point = in.ConsumeBool();
      c.point1 = Vec(in, -5, 5);
      c.point2 = in.ConsumeBool() ? c.point1 : Vec(in, -5, 5);
      const Frame f1 = AxisPair(in), f2 = in.ConsumeBool() ? f1 : AxisPair(in);
      c.axis_x1 = f1.axis, c.axis_y1 = f1.normal, c.axis_x2 = f2.axis, c.axis_y2 = f2.normal;
      return c;
    }
    case 2: {
      HingeConstraintSettings c;
      Common(in, bodies, c);
      c.point1 = Vec(in, -5, 5);
      c.point2 = in.ConsumeBool() ? c.point1 : Vec(in, -5, 5);
      const Frame f1 = AxisPair(in), f2 = in.ConsumeBool() ? f1 : AxisPair(in);
      c.hinge_axis1 = f1.axis, c.normal_axis1 = f1.normal;
      c.hinge_axis2 = f2.axis, c.normal_axis2 = f2.normal;
      if (in.ConsumeBool()) {
        c.limits_min = Float(in, -3.3f, 0.1f);
        c.limits_max = Float(in, -0.1f, 3.3f);
        c.limits_spring = Spring(in);
      }
      c.max_friction_torque = in.ConsumeBool() ? 0.0f : Float(in, -1, 10);
      c.motor = Motor(in);
      c.motor_state = EnumValue<MotorState>(in, 4);
      c.target_angular_velocity = Float(in, -10, 10);
      c.target_angle = Float(in, -4, 4);
      return c;
    }
    case 3: {
      SliderConstraintSettings c;
      Common(in, bodies, c);
      c.auto_detect_point = in.ConsumeBool();
      c.point1 = Vec(in, -5, 5);
      c.point2 = in.ConsumeBool() ? c.point1 : Vec(in, -5, 5);
      const Frame f1 = AxisPair(in), f2 = in.ConsumeBool() ? f1 : AxisPair(in);
      c.slider_axis1 = f1.axis, c.normal_axis1 = f1.normal;
      c.slider_axis2 = f2.axis, c.normal_axis2 = f2.normal;
      if (in.ConsumeBool()) {
        c.limits_min = Float(in, -5, 0.5f);
        c.limits_max = Float(in, -0.5f, 5);
        c.limits_spring = Spring(in);
      }
      c.max_friction_force = in.ConsumeBool() ? 0.0f : Float(in, -1, 10);
      c.motor = Motor(in);
      c.motor_state = EnumValue<MotorState>(in, 4);
      c.target_velocity = Float(in, -10, 10);
      c.target_position = Float(in, -10, 10);
      return c;
    }
    case 4: {
      GearConstraintSettings c;
      Common(in, bodies, c);
      c.hinge_axis1 = AxisPair(in).axis;
      c.hinge_axis2 = AxisPair(in).axis;
      c.ratio = Float(in, -5, 5);
      c.hinge1 = Helper(in, constraints);
      c.hinge2 = Helper(in, constraints);
      return c;
    }
    case 5: {
      RackAndPinionConstraintSettings c;
      Common(in, bodies, c);
      c.hinge_axis1 = AxisPair(in).axis;
      c.slider_axis2 = AxisPair(in).axis;
      c.ratio = Float(in, -5, 5);
      c.hinge = Helper(in, constraints);
      c.slider = Helper(in, constraints);
      return c;
    }
    case 6: {
      DistanceConstraintSettings c;
      Common(in, bodies, c);
      c.point1 = Vec(in, -5, 5);
      c.point2 = in.ConsumeBool() ? c.point1 : Vec(in, -5, 5);  // zero length too
      c.min_distance = Float(in, -2, 5);
      c.max_distance = Float(in, -2, 5);
      if (in.ConsumeBool()) c.limits_spring = Spring(in);
      return c;
    }
    case 7: {
      PulleyConstraintSettings c;
      Common(in, bodies, c);
      c.body_point1 = Vec(in, -5, 5);
      c.fixed_point1 = in.ConsumeBool() ? c.body_point1 : Vec(in, -5, 5);
      c.body_point2 = Vec(in, -5, 5);
      c.fixed_point2 = Vec(in, -5, 5);
      c.ratio = Float(in, -1, 4);
      c.min_length = Float(in, -2, 5);
      c.max_length = Float(in, -2, 10);
      return c;
    }
    case 8: {
      ConeConstraintSettings c;
      Common(in, bodies, c);
      c.point1 = Vec(in, -5, 5);
      c.point2 = in.ConsumeBool() ? c.point1 : Vec(in, -5, 5);
      c.twist_axis1 = AxisPair(in).axis;
      c.twist_axis2 = in.ConsumeBool() ? c.twist_axis1 : AxisPair(in).axis;
      c.half_cone_angle = Float(in, -0.5f, 3.5f);
      return c;
    }
    default: {
      SwingTwistConstraintSettings c;
      Common(in, bodies, c);
      c.point1 = Vec(in, -5, 5);
      c.point2 = in.ConsumeBool() ? c.point1 : Vec(in, -5, 5);
      const Frame f1 = AxisPair(in), f2 = in.ConsumeBool() ? f1 : AxisPair(in);
      c.twist_axis1 = f1.axis, c.plane_axis1 = f1.normal;
      c.twist_axis2 = f2.axis, c.plane_axis2 = f2.normal;
      c.swing_type = EnumValue<SwingType>(in, 2);
      // Locked (within 0.5 deg), limited and free (beyond 179.5 deg) axes.
      c.normal_half_cone_angle = Float(in, 0, 3.3f);
      c.plane_half_cone_angle = Float(in, 0, 3.3f);
      c.twist_min_angle = Float(in, -3.3f, 0.2f);
      c.twist_max_angle = Float(in, -0.2f, 3.3f);
      if (in.ConsumeBool()) {
        c.max_friction_torque = Float(in, -1, 10);
        c.twist_motor = Motor(in);
        c.swing_motor = Motor(in);
        c.twist_motor_state = EnumValue<MotorState>(in, 4);
        c.swing_motor_state = EnumValue<MotorState>(in, 4);
        c.target_angular_velocity = Vec(in, -10, 10);
        c.target_orientation = Quat(in);
      }
      return c;
    }
    case 11: {
      PathConstraintSettings c;
      c.body1 = Index(in, bodies);
      c.body2 = Index(in, bodies);
      c.space = EnumValue<ConstraintSpace>(in, 2);
      c.path_position = Vec(in, -5, 5);
      c.path_rotation = Quat(in);
      // 0 to 5 points (fewer than 2 is refused), tangents and normals that
      // may vanish or line up (refused), a loop that may repeat its start.
      const int points = in.ConsumeIntegralInRange<int>(0, 5);
      for (int i = 0; i < points; ++i) {
        PathPoint p;
        p.position = Vec(in, -3, 3);
        const Frame f = AxisPair(in);
        p.tangent = in.ConsumeBool() ? f.axis : Vec(in, -3, 3);
        p.normal = in.ConsumeBool() ? f.normal : Vec(in, -1, 1);
        c.path.push_back(p);
      }
      c.looping = in.ConsumeBool();
      if (c.looping && !c.path.empty() && in.ConsumeIntegral<std::uint8_t>() > 240) {
        c.path.push_back(c.path.front());
      }
      c.path_fraction = Float(in, -1, 6);
      c.rotation = static_cast<PathRotation>(in.ConsumeIntegralInRange<int>(0, 5));
      c.max_friction_force = Float(in, -1, 10);
      c.motor = Motor(in);
      c.motor_state = EnumValue<MotorState>(in, 4);
      c.target_velocity = Float(in, -5, 5);
      c.target_path_fraction = Float(in, -2, 6);
      return c;
    }
    case 10: {
      SixDofConstraintSettings c;
      Common(in, bodies, c);
      c.position1 = Vec(in, -5, 5);
      c.position2 = in.ConsumeBool() ? c.position1 : Vec(in, -5, 5);
      const Frame f1 = AxisPair(in), f2 = in.ConsumeBool() ? f1 : AxisPair(in);
      c.axis_x1 = f1.axis, c.axis_y1 = f1.normal;
      c.axis_x2 = f2.axis, c.axis_y2 = f2.normal;
      c.swing_type = EnumValue<SwingType>(in, 2);
      for (std::size_t axis = 0; axis < kSixDofAxes; ++axis) {
        // Fixed, free, limited, inverted and out-of-range limits.
        switch (in.ConsumeIntegralInRange<int>(0, 3)) {
          case 0: c.MakeFixedAxis(SixDofAxis(axis)); break;
          case 1: c.MakeFreeAxis(SixDofAxis(axis)); break;
          default: c.SetLimitedAxis(SixDofAxis(axis), Float(in, -4, 1), Float(in, -1, 4)); break;
        }
        if (in.ConsumeBool()) {
          c.motor[axis] = Motor(in);
          c.motor_state[axis] = EnumValue<MotorState>(in, 4);
          c.max_friction[axis] = Float(in, -1, 10);
        }
        if (axis < 3 && in.ConsumeBool()) c.limits_spring[axis] = Spring(in);
      }
      c.target_velocity = Vec(in, -10, 10);
      c.target_angular_velocity = Vec(in, -10, 10);
      c.target_position = Vec(in, -2, 2);
      c.target_orientation = Quat(in);
      return c;
    }
  }
}

StepSettings Settings(FuzzedDataProvider& in) {
  StepSettings s;
  // Mostly valid (the checks are tested once, in batch_test); sometimes not.
  // Float's special values include FLT_TRUE_MIN and 1e-30: a step so short
  // that 1/dt and the next warm-start ratio overflow, which must be refused.
  s.delta_time = in.ConsumeIntegral<std::uint8_t>() < 240 ? Float(in, 1e-4f, 0.1f)
                                                         : Float(in, -1, 1);
  s.substeps = in.ConsumeIntegralInRange<int>(in.ConsumeBool() ? 1 : -1, 3);
  s.velocity_iterations = in.ConsumeIntegralInRange<int>(in.ConsumeBool() ? 0 : -1, 12);
  s.position_iterations = in.ConsumeIntegralInRange<int>(0, 4);
  if (in.ConsumeIntegral<std::uint8_t>() >= 252) {  // past the caps: refused
    s.substeps = kMaxSubsteps + in.ConsumeIntegralInRange<int>(1, 1 << 20);
  }
  if (in.ConsumeIntegral<std::uint8_t>() >= 252) {
    s.velocity_iterations = kMaxIterations + in.ConsumeIntegralInRange<int>(1, 1 << 20);
  }
  s.baumgarte = Float(in, 0, 1);
  s.warm_start = in.ConsumeBool();
  if (in.ConsumeBool()) s.gravity = Vec(in, -20, 20);
  s.unhealthy_worlds = EnumValue<UnhealthyWorlds>(in, 2);
  s.gyroscopic = in.ConsumeBool();
  if (in.ConsumeBool()) {  // contact settings (negative or not finite: refused)
    s.speculative_contact_distance = Float(in, 0, 0.1f);
    s.penetration_slop = Float(in, 0, 0.05f);
    s.max_penetration_distance = Float(in, 0, 1);
    s.min_velocity_for_restitution = Float(in, 0, 5);
    s.speculative_contacts_from_velocity = in.ConsumeBool();
  }
  // Each world's own stop, snapshot and restore (negative or not finite:
  // refused).
  if (in.ConsumeBool()) s.velocity_tolerance = Float(in, 0, 0.1f);
  // The exact joint solve on every constraint type around it; refused for
  // bodies with restricted DOFs, two constraints with row groups between
  // the same bodies, and a tolerance or stiffness out of range.
  if (in.ConsumeBool()) {
    s.solver = JointSolver::kExact;
    s.position_iterations = in.ConsumeIntegralInRange<int>(0, 30);
    if (in.ConsumeBool()) s.exact_tolerance = Float(in, 0, 1e-2f);
    if (in.ConsumeBool()) s.exact_geometric_stiffness = Float(in, 0, 2);
    if (in.ConsumeBool()) s.exact_curvature_velocity = false;
  }
  return s;
}

std::vector<std::uint8_t> Mask(FuzzedDataProvider& in, std::size_t worlds) {
  std::vector<std::uint8_t> mask(worlds);
  for (auto& m : mask) m = in.ConsumeIntegral<std::uint8_t>() & 1;
  return mask;
}

// Fills `values` with plausible state numbers and, here and there, bad ones;
// rotations stay non-zero unless the input asks for a refused call.
void FillState(FuzzedDataProvider& in, std::vector<float>& values) {
  for (std::size_t i = 0; i < values.size() && in.remaining_bytes() > 0; ++i) {
    if (in.ConsumeIntegral<std::uint8_t>() < 224) continue;  // keep the current value
    values[i] = Float(in, -10, 10);
  }
}

// One call of the batch API with random arguments; refusals are expected.
void RandomCall(FuzzedDataProvider& in, Batch& batch) {
  const std::size_t worlds = batch.world_count(), bodies = batch.body_count();
  const std::size_t constraints = batch.constraint_count();
  const std::size_t w = Index(in, worlds), b = Index(in, bodies), c = Index(in, constraints);
  std::vector<float> state(worlds * bodies * kStateFloatsPerBody);
  switch (in.ConsumeIntegralInRange<int>(0, 23)) {
    case 0: batch.SetForce(w, b, Vec(in, -100, 100)); break;
    case 1: batch.SetTorque(w, b, Vec(in, -100, 100)); break;
    case 2: {
      std::vector<float> per_world(worlds * 3);
      for (float& v : per_world) v = Float(in, -100, 100);
      if (in.ConsumeBool()) batch.SetForces(b, per_world); else batch.SetTorques(b, per_world);
      break;
    }
    case 3: {
      std::vector<float> all(worlds * bodies * 3 + (in.ConsumeIntegral<std::uint8_t>() >= 250));
      for (float& v : all) v = Float(in, -100, 100);
      if (in.ConsumeBool()) batch.SetForces(all); else batch.SetTorques(all);
      break;
    }
    case 4: batch.SetTargetVelocity(w, c, Float(in, -10, 10)); break;
    case 5: batch.SetTargetPosition(w, c, Float(in, -10, 10)); break;
    case 6: {
      std::vector<float> per_world(worlds);
      for (float& v : per_world) v = Float(in, -10, 10);
      if (in.ConsumeBool()) batch.SetTargetVelocities(c, per_world);
      else batch.SetTargetPositions(c, per_world);
      break;
    }
    case 7: {
      batch.GetState(state);
      FillState(in, state);
      if (in.ConsumeBool()) batch.SetState(state, Mask(in, worlds)); else batch.SetState(state);
      break;
    }
    case 8: {
      const auto field = static_cast<StateField>(in.ConsumeIntegralInRange<int>(0, 3));
      std::vector<float> values(worlds * bodies * StateFieldSize(field));
      batch.GetField(field, values);
      FillState(in, values);
      batch.SetField(field, values);
      break;
    }
    case 9: batch.Reset(Mask(in, worlds)); break;
    case 10: {
      batch.GetState(state);
      FillState(in, state);
      batch.ResetTo(Mask(in, worlds), state);
      break;
    }
    case 11: batch.SetMassProperties(w, b, Float(in, 0.01f, 100), Vec(in, 0.001f, 10)); break;
    case 12: batch.SetDamping(w, b, Float(in, 0, 2), Float(in, 0, 2)); break;
    case 13: batch.SetGravityFactor(w, b, Float(in, -2, 2)); break;
    case 14: batch.SetLimits(w, c, Float(in, -4, 0.5f), Float(in, -0.5f, 4)); break;
    case 15: batch.SetLimitsSpring(w, c, Float(in, -1, 50), Float(in, 0, 5)); break;
    case 16: batch.SetMotorSpring(w, c, Float(in, -1, 50), Float(in, 0, 5)); break;
    case 17: batch.SetMotorLimits(w, c, Float(in, -100, 10), Float(in, -10, 100)); break;
    case 18: batch.SetMaxFriction(w, c, Float(in, -1, 10)); break;
    case 19: batch.SetTargetOrientation(w, c, Quat(in)); break;
    case 20: batch.SetTargetAngularVelocity(w, c, Vec(in, -10, 10)); break;
    case 21: batch.SetTargetTranslation(w, c, Vec(in, -2, 2)); break;
    case 22: batch.SetTargetLinearVelocity(w, c, Vec(in, -10, 10)); break;
    default: batch.SetRatio(w, c, Float(in, -5, 5)); break;
  }
}

void Check(bool ok) {
  if (!ok) __builtin_trap();
}

// The health flags after a step agree with the state the step left.
void CheckHealth(const Batch& batch, const StepSettings& settings) {
  const auto health = batch.WorldHealth();
  Check(health.size() == batch.world_count());
  const std::size_t floats = batch.body_count() * kStateFloatsPerBody;
  std::vector<float> state(batch.world_count() * floats);
  batch.GetState(state);
  std::size_t unhealthy = 0;
  for (std::size_t w = 0; w < batch.world_count(); ++w) {
    Check((health[w] & ~0xF) == 0);  // kNotStepped only with a stop token
    unhealthy += health[w] != 0;
    bool finite = true;
    for (std::size_t i = 0; i < floats; ++i) finite &= std::isfinite(state[w * floats + i]);
    if (settings.unhealthy_worlds == UnhealthyWorlds::kReset) {
      Check(finite);  // flagged worlds went back to the (finite) scene
    } else if (!finite) {
      Check((health[w] & kNonFiniteState) != 0);
    }
    (void)batch.MaxConstraintError(w);
  }
  Check(unhealthy == batch.UnhealthyWorldCount());
}

bool SameBytes(const BatchSnapshot& a, const BatchSnapshot& b) {
  return a.bytes().size() == b.bytes().size() &&
         std::memcmp(a.bytes().data(), b.bytes().data(), a.bytes().size()) == 0;
}

void CheckUnchanged(const Batch& batch, const BatchSnapshot& before) {
  Check(SameBytes(batch.Snapshot(), before));
}

// Back to the snapshot taken before the step just taken, and the same step
// again: every byte (state, impulses, health) must come out the same.
void CheckRestoredStepIsExact(Batch& batch, const StepSettings& settings,
                              const BatchSnapshot& before) {
  const BatchSnapshot after = batch.Snapshot();
  batch.Restore(before);
  batch.Step(settings);
  Check(SameBytes(batch.Snapshot(), after));
}

// A step whose stop was requested before it began steps nothing: every world
// flagged kNotStepped, every state bit as before. (Throws SceneError, like
// Step, for refused settings.)
void CheckStoppedStep(Batch& batch, const StepSettings& settings,
                      const BatchSnapshot& before) {
  std::vector<float> state_before(batch.world_count() * batch.body_count() *
                                  kStateFloatsPerBody);
  batch.GetState(state_before);
  std::stop_source stop;
  stop.request_stop();
  Check(!batch.Step(settings, stop.get_token()));
  std::vector<float> state_after(state_before.size());
  batch.GetState(state_after);
  Check(std::memcmp(state_before.data(), state_after.data(),
                    state_before.size() * sizeof(float)) == 0);
  for (const std::uint8_t bits : batch.WorldHealth()) Check(bits == kNotStepped);
  batch.Restore(before);  // the health of the last real step back
}

// The mass-range limit with a random ratio: a bad ratio is refused with
// std::invalid_argument and changes nothing; a good one only ever raises
// masses, and leaves the mass and inertia bits of every body it does not
// report.
void LimitMassRangeChecked(FuzzedDataProvider& in, Scene& scene) {
  const Scene before = scene;
  std::vector<MassRaise> raised;
  try {
    raised = LimitMassRange(scene, Float(in, 1.0f, 1e6f));
  } catch (const std::invalid_argument&) {
  }
  std::size_t next = 0;
  for (std::size_t i = 0; i < scene.bodies().size(); ++i) {
    const float old_mass = before.bodies()[i].mass, new_mass = scene.bodies()[i].mass;
    const bool reported = next < raised.size() && raised[next].body == i;
    if (reported) {
      ++next;
      if (!(new_mass > old_mass)) __builtin_trap();
    } else if (std::memcmp(&old_mass, &new_mass, sizeof old_mass) != 0 ||
               std::memcmp(before.bodies()[i].inertia_diagonal.data(),
                           scene.bodies()[i].inertia_diagonal.data(),
                           sizeof(Float3)) != 0) {
      __builtin_trap();
    }
  }
  if (next != raised.size()) __builtin_trap();
}

void Run(FuzzedDataProvider& in) {
  Scene scene;
  const std::size_t bodies = in.ConsumeIntegralInRange<std::size_t>(0, kMaxBodies);
  for (std::size_t i = 0; i < bodies; ++i) scene.AddBody(Body(in));
  const std::size_t constraints = in.ConsumeIntegralInRange<std::size_t>(0, kMaxConstraints);
  for (std::size_t i = 0; i < constraints; ++i) {
    scene.AddConstraint(Constraint(in, bodies, constraints));
  }
  if (in.ConsumeBool()) LimitMassRangeChecked(in, scene);
  const std::size_t worlds = in.ConsumeIntegralInRange<std::size_t>(0, kMaxWorlds);
  BatchOptions options;
  options.threads = in.ConsumeIntegralInRange<int>(0, 2);
  options.blocks_per_task = in.ConsumeIntegralInRange<std::size_t>(0, 2);
  switch (in.ConsumeIntegralInRange<int>(0, 7)) {
    case 0: options.target = HWY_SCALAR; break;  // refused where EMU128 is built instead
    case 1: options.target = HWY_SSE4; break;
    case 2: options.target = HWY_AVX2; break;
    case 3: options.target = HWY_AVX3; break;  // refused where the CPU lacks it
    case 4: options.target = in.ConsumeIntegral<std::int64_t>(); break;
    case 5: options.target = HWY_EMU128; break;  // clang's fallback (g++ 12.2: SCALAR)
    default: break;  // dispatch
  }

  std::optional<Batch> batch;
  try {
    batch.emplace(scene, worlds, options);
  } catch (const std::invalid_argument&) {  // SceneError is one
    return;
  } catch (const std::out_of_range&) {
    return;
  }

  const int steps = in.ConsumeIntegralInRange<int>(1, kMaxSteps);
  for (int step = 0; step < steps; ++step) {
    const int calls = in.ConsumeIntegralInRange<int>(0, kMaxCallsPerStep);
    for (int i = 0; i < calls; ++i) {
      const BatchSnapshot before = batch->Snapshot();
      try {
        RandomCall(in, *batch);
      } catch (const std::invalid_argument&) {
        CheckUnchanged(*batch, before);  // a refused call writes nothing
      } catch (const std::out_of_range&) {
        CheckUnchanged(*batch, before);
      }
    }
    const StepSettings settings = Settings(in);
    const BatchSnapshot before = batch->Snapshot();
    try {
      if (in.ConsumeIntegral<std::uint8_t>() >= 240) {
        CheckStoppedStep(*batch, settings, before);
        continue;
      }
      batch->Step(settings);
    } catch (const SceneError&) {
      CheckUnchanged(*batch, before);  // refused settings: nothing stepped
      continue;
    }
    CheckHealth(*batch, settings);
    if (in.ConsumeBool()) CheckRestoredStepIsExact(*batch, settings, before);
  }
  if (in.ConsumeBool()) (void)batch->Plan();
}

}  // namespace
}  // namespace manyworlds

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  FuzzedDataProvider in(data, size);
  manyworlds::Run(in);
  return 0;
}
