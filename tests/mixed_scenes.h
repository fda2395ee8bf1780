// Two scenes with every constraint type and feature, out of plane, with
// uneven bodies, shared by the tests that need more than the planar
// reference scenes: scene_comparison_test.cc (every lane against the
// scalar reference stepper), joint_coordinate_kernels_test.cc (every
// joint-coordinate type against the double read-out), solver_state_test.cc
// and velocity_tolerance_test.cc.
#pragma once

#include <cstddef>
#include <string>

#include "manyworlds/scene.h"
#include "manyworlds/scenes.h"

namespace manyworlds::test_scenes {

// Every constraint type and feature, out of plane, with uneven bodies: the
// reference scenes are planar (hinges about Z), which leaves the hinge
// rotation and rotation Euler rows idle.
inline Scene MixedScene() {
  Scene scene;
  auto body = [&](const char* name, MotionType type, Float3 position, float mass,
                  Float3 inertia, Float3 velocity, Float3 spin) {
    BodySettings b;
    b.name = name;
    b.motion_type = type;
    b.position = position;
    b.mass = mass;
    b.inertia_diagonal = inertia;
    b.inertia_rotation = {0.1f, -0.2f, 0.3f, 0.927362f};
    b.rotation = {0.05f, 0.1f, -0.08f, 0.99f};
    b.linear_velocity = velocity;
    b.angular_velocity = spin;
    b.linear_damping = 0.1f;
    b.angular_damping = 0.05f;
    return scene.AddBody(b);
  };
  const std::size_t ground = body("ground", MotionType::kStatic, {0, 0, 0}, 1, {1, 1, 1}, {}, {});
  const std::size_t arm = body("arm", MotionType::kDynamic, {0.3f, -0.5f, 0.1f}, 2.0f,
                               {0.1f, 0.05f, 0.12f}, {0.2f, 0, -0.1f}, {0.5f, 1.0f, -0.3f});
  const std::size_t carriage = body("carriage", MotionType::kDynamic, {0.8f, -0.6f, 0.2f},
                                    0.7f, {0.01f, 0.02f, 0.015f}, {}, {0.2f, -0.4f, 0.1f});
  const std::size_t tool = body("tool", MotionType::kDynamic, {1.1f, -0.9f, 0.3f}, 0.3f,
                                {0.004f, 0.003f, 0.005f}, {0, 0.3f, 0}, {});
  const std::size_t wheel = body("wheel", MotionType::kDynamic, {-0.6f, 0.2f, 0.0f}, 1.5f,
                                 {0.03f, 0.03f, 0.05f}, {}, {0, 0, 2.0f});
  const std::size_t pusher = body("pusher", MotionType::kKinematic, {0, 1, 0}, 1, {1, 1, 1},
                                  {0.3f, 0, 0.1f}, {0, 0.5f, 0});
  const std::size_t bob = body("bob", MotionType::kDynamic, {0, 0.5f, 0.2f}, 0.5f,
                               {0.01f, 0.01f, 0.01f}, {}, {});

  HingeConstraintSettings shoulder;
  shoulder.name = "shoulder";
  shoulder.body1 = ground;
  shoulder.body2 = arm;
  shoulder.point1 = shoulder.point2 = {0.1f, -0.2f, 0.05f};
  shoulder.hinge_axis1 = shoulder.hinge_axis2 = {0.3f, 1.0f, 0.2f};
  shoulder.normal_axis1 = shoulder.normal_axis2 = {1.0f, -0.3f, 0.0f};
  shoulder.limits_min = -0.5f;
  shoulder.limits_max = 0.3f;
  shoulder.motor_state = MotorState::kVelocity;
  shoulder.target_angular_velocity = 1.5f;
  shoulder.motor.min_force_limit = -10.0f;
  shoulder.motor.max_force_limit = 10.0f;
  const std::size_t shoulder_index = scene.AddConstraint(shoulder);

  SliderConstraintSettings rail;
  rail.name = "rail";
  rail.body1 = arm;
  rail.body2 = carriage;
  rail.auto_detect_point = true;
  rail.slider_axis1 = rail.slider_axis2 = {1.0f, -0.2f, 0.2f};
  rail.normal_axis1 = rail.normal_axis2 = {0.2f, 1.0f, 0.0f};
  rail.limits_min = -0.2f;
  rail.limits_max = 0.12f;
  rail.limits_spring.frequency_or_stiffness = 3.0f;
  rail.limits_spring.damping = 0.3f;
  rail.motor_state = MotorState::kPosition;
  rail.target_position = 0.1f;
  rail.motor.min_force_limit = -2.0f;
  rail.motor.max_force_limit = 2.0f;
  const std::size_t rail_index = scene.AddConstraint(rail);

  FixedConstraintSettings weld;
  weld.name = "weld";
  weld.body1 = carriage;
  weld.body2 = tool;
  weld.auto_detect_point = true;
  scene.AddConstraint(weld);

  HingeConstraintSettings axle;
  axle.name = "axle";
  axle.body1 = wheel;  // the other way round: the gear and rack read -angle
  axle.body2 = ground;
  axle.point1 = axle.point2 = {-0.6f, 0.2f, 0.0f};
  axle.hinge_axis1 = axle.hinge_axis2 = {0, 0.2f, 1};
  axle.normal_axis1 = axle.normal_axis2 = {1, 0, 0};
  axle.limits_min = -2.0f;
  axle.limits_max = 2.5f;
  axle.limits_spring.frequency_or_stiffness = 2.0f;
  axle.limits_spring.damping = 0.5f;
  axle.max_friction_torque = 0.2f;
  const std::size_t axle_index = scene.AddConstraint(axle);

  GearConstraintSettings gear;
  gear.name = "gear";
  gear.body1 = arm;
  gear.body2 = wheel;
  gear.hinge_axis1 = {0.3f, 1.0f, 0.2f};
  gear.hinge_axis2 = {0, 0.2f, 1};
  gear.ratio = 1.5f;
  gear.hinge1 = shoulder_index;
  gear.hinge2 = axle_index;
  scene.AddConstraint(gear);

  RackAndPinionConstraintSettings rack;
  rack.name = "rack";
  rack.body1 = wheel;
  rack.body2 = carriage;
  rack.hinge_axis1 = {0, 0.2f, 1};
  rack.slider_axis2 = {1.0f, -0.2f, 0.2f};
  rack.ratio = -2.0f;
  rack.hinge = axle_index;
  rack.slider = rail_index;
  scene.AddConstraint(rack);

  PointConstraintSettings tether;
  tether.name = "tether";
  tether.body1 = pusher;
  tether.body2 = bob;
  tether.point1 = tether.point2 = {0, 0.75f, 0.1f};
  scene.AddConstraint(tether);
  return scene;
}

// The constraint types of issue 5 with every mode they have, out of plane:
// distance as a rod (0.95 m, started 0.986 m apart), a rope (only a max), a
// strut (min above the initial length, so it pushes from the first step) and
// a spring (min = max with a limits spring), between static-dynamic and
// dynamic-dynamic pairs; a pulley with a block and tackle (ratio 2); two
// cones in a row, one violated from the start; swing-twist joints with locked
// and free axes on a spun limb. No rod
// starts exactly at its length: Jolt's position
// phase measures the error from the anchors stored at setup and recomputes
// only where it is non-zero, so a rod whose error is 0 in float and 1e-17 in
// double takes its second position iteration from different anchors, a
// legitimate discontinuity of the algorithm that would hide kernel errors
// behind a 5e-6 m difference (the default "initial length" bounds are
// checked in batch_test.cc instead).
inline Scene MoreTypesScene() {
  Scene scene;
  auto body = [&](const char* name, MotionType type, Float3 position, float mass,
                  Float3 inertia, Float3 velocity) {
    BodySettings b;
    b.name = name;
    b.motion_type = type;
    b.position = position;
    b.mass = mass;
    b.inertia_diagonal = inertia;
    b.rotation = {0.1f, -0.05f, 0.08f, 0.99f};
    b.linear_velocity = velocity;
    b.angular_velocity = {0.3f, -0.2f, 0.5f};
    return scene.AddBody(b);
  };
  const std::size_t ground = body("ground", MotionType::kStatic, {0, 0, 0}, 1, {1, 1, 1}, {});
  const std::size_t bob = body("bob", MotionType::kDynamic, {0.4f, -1.0f, 0.2f}, 1.0f,
                               {0.02f, 0.03f, 0.025f}, {0.5f, 0, -0.2f});
  const std::size_t weight = body("weight", MotionType::kDynamic, {0.9f, -1.6f, -0.1f}, 3.0f,
                                  {0.05f, 0.04f, 0.06f}, {});
  const std::size_t swing = body("swing", MotionType::kDynamic, {-0.8f, -0.7f, 0.3f}, 0.5f,
                                 {0.01f, 0.012f, 0.008f}, {0, 0, 0.8f});
  const std::size_t spring_mass = body("spring mass", MotionType::kDynamic, {0.2f, 0.6f, -0.7f},
                                       0.8f, {0.01f, 0.01f, 0.01f}, {0.3f, 0.4f, 0});

  DistanceConstraintSettings rod;
  rod.name = "rod";
  rod.min_distance = rod.max_distance = 0.95f;
  rod.body1 = ground;
  rod.body2 = bob;
  rod.point1 = {0.05f, 0.0f, 0.0f};
  rod.point2 = {0.4f, -0.9f, 0.2f};
  scene.AddConstraint(rod);

  DistanceConstraintSettings rope;  // slack until it is 0.9 m long
  rope.name = "rope";
  rope.body1 = bob;
  rope.body2 = weight;
  rope.point1 = {0.4f, -1.1f, 0.2f};
  rope.point2 = {0.9f, -1.5f, -0.1f};
  rope.min_distance = 0.0f;
  rope.max_distance = 0.6f;
  scene.AddConstraint(rope);

  DistanceConstraintSettings strut;  // min above the initial length: pushes
  strut.name = "strut";
  strut.body1 = swing;
  strut.body2 = ground;
  strut.space = ConstraintSpace::kLocalToBodyCOM;
  strut.point1 = {0.1f, 0.05f, 0.0f};
  strut.point2 = {-0.5f, 0.0f, 0.1f};
  strut.min_distance = 1.0f;
  strut.max_distance = 1.5f;
  scene.AddConstraint(strut);

  DistanceConstraintSettings spring;  // min = max = 0.5 m, soft
  spring.name = "spring";
  spring.body1 = swing;
  spring.body2 = spring_mass;
  spring.point1 = {-0.8f, -0.6f, 0.3f};
  spring.point2 = {0.2f, 0.6f, -0.7f};
  spring.min_distance = spring.max_distance = 0.5f;
  spring.limits_spring.frequency_or_stiffness = 3.0f;
  spring.limits_spring.damping = 0.2f;
  scene.AddConstraint(spring);

  // A block and tackle (ratio 2) of fixed length (both bounds negative: the
  // initial length). The ropes hold the bodies 5 cm off their centres of
  // mass. Inequality rows that rest on their bound (a taut rope that may go
  // slack) flip between active and inactive on rounding, so one step can
  // differ between float and double by anything up to the whole impulse: the
  // slack-taut pulley is checked physically in jolt_behaviour_test.cc.
  const std::size_t bucket = body("bucket", MotionType::kDynamic, {1.5f, -0.5f, 0.0f}, 1.2f,
                                  {0.09f, 0.08f, 0.09f}, {0.1f, 0, 0});
  const std::size_t counterweight = body("counterweight", MotionType::kDynamic,
                                         {2.2f, -0.3f, 0.1f}, 3.0f, {0.2f, 0.2f, 0.15f}, {});
  PulleyConstraintSettings pulley;
  pulley.name = "pulley";
  pulley.body1 = bucket;
  pulley.body2 = counterweight;
  pulley.body_point1 = {1.5f, -0.45f, 0.0f};
  pulley.fixed_point1 = {1.5f, 1.0f, 0.0f};
  pulley.body_point2 = {2.2f, -0.25f, 0.1f};
  pulley.fixed_point2 = {2.3f, 1.0f, 0.1f};
  pulley.ratio = 2.0f;
  pulley.min_length = pulley.max_length = -1.0f;
  scene.AddConstraint(pulley);

  // Two cones in a row: a 0.4 rad cone from the ground to an arm that starts
  // 0.6 rad out (pushed back in from the first step), and a 0.8 rad cone
  // from the arm to a forearm, twist axes along the links, local frames.
  const std::size_t arm = body("arm", MotionType::kDynamic, {-1.5f, -0.4f, 0.0f}, 1.0f,
                               {0.01f, 0.05f, 0.05f}, {0, 0, 0.5f});
  const std::size_t forearm = body("forearm", MotionType::kDynamic, {-1.5f, -1.2f, 0.2f}, 0.7f,
                                   {0.008f, 0.03f, 0.03f}, {0.4f, 0, 0});
  ConeConstraintSettings shoulder;
  shoulder.name = "shoulder cone";
  shoulder.body1 = ground;
  shoulder.body2 = arm;
  shoulder.point1 = shoulder.point2 = {-1.5f, 0.0f, 0.0f};
  shoulder.twist_axis1 = {0.0f, -1.0f, 0.0f};
  shoulder.twist_axis2 = {0.565f, -0.825f, 0.0f};  // 0.6 rad from -Y
  shoulder.half_cone_angle = 0.4f;
  scene.AddConstraint(shoulder);
  ConeConstraintSettings elbow;
  elbow.name = "elbow cone";
  elbow.body1 = arm;
  elbow.body2 = forearm;
  elbow.space = ConstraintSpace::kLocalToBodyCOM;
  elbow.point1 = {0.0f, -0.4f, 0.0f};
  elbow.point2 = {0.0f, 0.4f, -0.1f};
  elbow.twist_axis1 = {0.0f, -1.0f, 0.0f};
  elbow.twist_axis2 = {0.0f, -1.0f, 0.2f};
  elbow.half_cone_angle = 0.8f;
  scene.AddConstraint(elbow);

  // A limb on two swing-twist joints whose axes are only locked or free, so
  // every row is an equality: a locked twist with free swing from the ground
  // (world frames), then a locked swing about Y (local frames). Limited axes
  // are inequality rows; where one rests on its bound (a limb pressed into a
  // limit) it switches on and off with the last bit of the angle, and one
  // step can then differ between float and double by a whole impulse (the
  // float reference alone lands 1e5 FLT_EPSILON from the double one). The
  // limits are checked physically in jolt_behaviour_test.cc and lane by lane
  // at the part level in swing_twist_test.cc.
  const std::size_t upper = body("upper limb", MotionType::kDynamic, {1.0f, 1.0f, 0.5f}, 1.5f,
                                 {0.06f, 0.01f, 0.06f}, {0.5f, 0.3f, -0.4f});
  const std::size_t lower = body("lower limb", MotionType::kDynamic, {1.0f, 0.2f, 0.5f}, 1.0f,
                                 {0.04f, 0.008f, 0.04f}, {-0.3f, 0, 0.6f});
  SwingTwistConstraintSettings hip;
  hip.name = "hip";
  hip.body1 = ground;
  hip.body2 = upper;
  hip.point1 = hip.point2 = {1.0f, 1.4f, 0.5f};
  hip.twist_axis1 = hip.twist_axis2 = {0.0f, -1.0f, 0.0f};
  hip.plane_axis1 = hip.plane_axis2 = {0.0f, 0.0f, 1.0f};
  hip.swing_type = SwingType::kPyramid;
  hip.normal_half_cone_angle = hip.plane_half_cone_angle = kPi;  // free swing
  hip.twist_min_angle = hip.twist_max_angle = 0.0f;              // locked twist
  scene.AddConstraint(hip);
  SwingTwistConstraintSettings knee;
  knee.name = "knee";
  knee.body1 = upper;
  knee.body2 = lower;
  knee.space = ConstraintSpace::kLocalToBodyCOM;
  knee.point1 = {0.0f, -0.4f, 0.0f};
  knee.point2 = {0.0f, 0.4f, 0.0f};
  knee.twist_axis1 = knee.twist_axis2 = {0.0f, -1.0f, 0.0f};
  knee.plane_axis1 = knee.plane_axis2 = {1.0f, 0.0f, 0.0f};
  knee.swing_type = SwingType::kPyramid;
  knee.normal_half_cone_angle = kPi;  // free swing about Z
  knee.plane_half_cone_angle = 0.0f;  // locked swing about Y
  knee.twist_min_angle = -kPi;        // free twist
  knee.twist_max_angle = kPi;
  scene.AddConstraint(knee);

  // Swing-twist drives on a third limb: a torque-limited velocity motor on
  // the (free) twist and a position motor on the (free) swing towards a
  // target orientation; drives are equality rows (a clamped impulse is a
  // continuous function of the velocity, unlike a limit switching on).
  const std::size_t hand = body("hand", MotionType::kDynamic, {1.0f, -0.6f, 0.5f}, 0.6f,
                                {0.02f, 0.005f, 0.02f}, {0.2f, -0.4f, 0.1f});
  SwingTwistConstraintSettings wrist;
  wrist.name = "wrist";
  wrist.body1 = lower;
  wrist.body2 = hand;
  wrist.point1 = wrist.point2 = {1.0f, -0.2f, 0.5f};
  wrist.twist_axis1 = wrist.twist_axis2 = {0.0f, -1.0f, 0.0f};
  wrist.plane_axis1 = wrist.plane_axis2 = {0.0f, 0.0f, 1.0f};
  wrist.normal_half_cone_angle = wrist.plane_half_cone_angle = kPi;
  wrist.twist_min_angle = -kPi;
  wrist.twist_max_angle = kPi;
  wrist.twist_motor_state = MotorState::kVelocity;
  wrist.target_angular_velocity = {1.5f, 0.0f, 0.0f};
  wrist.twist_motor.min_force_limit = -0.05f;
  wrist.twist_motor.max_force_limit = 0.05f;
  wrist.swing_motor_state = MotorState::kPosition;
  wrist.swing_motor.spring.frequency_or_stiffness = 3.0f;
  wrist.target_orientation = {0.0f, 0.2f, 0.1f, 0.97f};
  scene.AddConstraint(wrist);

  // Six-DOF: a carriage free along X with a force-limited velocity motor, Y
  // fixed through a spring, Z fixed hard; twist free with a position motor,
  // swing locked (swing-twist part with equality rows only).
  const std::size_t carriage = body("carriage", MotionType::kDynamic, {-0.5f, 1.2f, -0.4f}, 2.0f,
                                    {0.05f, 0.07f, 0.06f}, {0.1f, 0.2f, 0});
  SixDofConstraintSettings rail;
  rail.name = "rail";
  rail.body1 = ground;
  rail.body2 = carriage;
  rail.position1 = rail.position2 = {-0.5f, 1.2f, -0.4f};
  rail.axis_x1 = rail.axis_x2 = {0.8f, 0.0f, 0.6f};
  rail.axis_y1 = rail.axis_y2 = {0.0f, 1.0f, 0.0f};
  rail.MakeFixedAxis(SixDofAxis::kTranslationY);
  rail.limits_spring[1].frequency_or_stiffness = 2.5f;
  rail.limits_spring[1].damping = 0.3f;
  rail.MakeFixedAxis(SixDofAxis::kTranslationZ);
  rail.MakeFixedAxis(SixDofAxis::kRotationY);
  rail.MakeFixedAxis(SixDofAxis::kRotationZ);
  rail.motor_state[0] = MotorState::kVelocity;
  rail.target_velocity = {0.7f, 0.0f, 0.0f};
  rail.motor[0].min_force_limit = -3.0f;
  rail.motor[0].max_force_limit = 3.0f;
  rail.motor_state[3] = MotorState::kPosition;
  rail.target_orientation = {0.3f, 0.0f, 0.0f, 0.95f};
  scene.AddConstraint(rail);

  // Six-DOF with every translation fixed, at an offset: the point shortcut on
  // an anchor moved by c1 min; every rotation limit is min = max too, but the
  // swing type is a cone's (the default), whose swing limits become the
  // symmetric +-max(0, max): the twist is fixed at 0.1 rad and the swings
  // limited to +-0.2 and +-0.3 rad (swing-twist rows, not the rotation-Euler
  // shortcut; tests/exact_solve_test.cc's Welded() has a pyramid's all-fixed
  // rotation). Between two dynamic bodies (local frames, turned
  // away from the bodies' axes; the weld starts 0.37 rad and ~0.1 m from
  // rest). The driven carriage under this weld has rare steps where a
  // world's rounding is amplified ~1e5-fold, in the float reference as in
  // the batch (printed when debugging: the same steps and worlds in both,
  // sometimes one larger, sometimes the other). With frames that differ
  // between the bodies (a 120 degree start) one such step put the batch 2.3x
  // beyond the per-body bound while the float reference led at others; the
  // equal frames here stay within it on every target.
  const std::size_t cargo = body("cargo", MotionType::kDynamic, {-0.3f, 1.6f, -0.2f}, 0.9f,
                                 {0.02f, 0.03f, 0.02f}, {0, 0, 0.3f});
  SixDofConstraintSettings weld;
  weld.name = "offset weld";
  weld.body1 = carriage;
  weld.body2 = cargo;
  weld.space = ConstraintSpace::kLocalToBodyCOM;
  weld.position1 = {0.1f, 0.3f, 0.1f};
  weld.position2 = {-0.1f, -0.1f, 0.0f};
  weld.axis_x1 = weld.axis_x2 = {0.0f, 0.0f, 1.0f};
  weld.axis_y1 = weld.axis_y2 = {1.0f, 0.0f, 0.0f};
  for (std::size_t i = 0; i < kSixDofAxes; ++i) {
    weld.limit_min[i] = weld.limit_max[i] = i < 3 ? 0.05f * float(i + 1) : 0.1f * float(i - 2);
  }
  scene.AddConstraint(weld);

  // Six-DOF gimbal: translation fixed (the point shortcut), rotation free
  // with position drives about X and Y only, so the orientation error is
  // projected onto those two axes (the twist about Z removed), and friction
  // about Z. (A reference that forgot the projection failed this scene by
  // 1e5 FLT_EPSILON.)
  const std::size_t gimbal = body("gimbal", MotionType::kDynamic, {0.6f, 1.8f, 0.9f}, 0.7f,
                                  {0.01f, 0.02f, 0.015f}, {0.1f, 0, 0});
  SixDofConstraintSettings mount;
  mount.name = "gimbal mount";
  mount.body1 = ground;
  mount.body2 = gimbal;
  mount.position1 = mount.position2 = {0.6f, 2.0f, 0.9f};
  for (std::size_t i = 0; i < 3; ++i) mount.MakeFixedAxis(SixDofAxis(i));
  mount.motor_state[3] = mount.motor_state[4] = MotorState::kPosition;
  mount.motor[4].spring = {SpringMode::kStiffnessAndDamping, 0.8f, 0.05f};
  mount.max_friction[5] = 0.02f;
  mount.target_orientation = {0.2f, -0.1f, 0.3f, 0.93f};
  scene.AddConstraint(mount);

  // Paths: a sled pushed along an open curved path by a force-limited
  // velocity motor, turning only about the path normal, kept away from the
  // ends (the end limit is an inequality, checked in jolt_behaviour_test.cc);
  // and a car on a looping path held at a target fraction by a position
  // motor, its frame held to the path's, both through the closest-point
  // search at every setup and position iteration. The car stays within its
  // segment: where the attachment passes a control point, Jolt's search
  // compares the control point's distance with the distance of Newton's
  // previous iterate, a tie that float and double can settle differently
  // (seen at fraction 2, and, with a rotation step that rounds differently,
  // in one world crossing the loop's end: 1600 FLT_EPSILON from both
  // references, against 256 allowed); the
  // crossing itself is checked in jolt_behaviour_test.cc. Its motor spring is
  // a stiffness (400 N per unit of fraction, 40 N s): the default 2 Hz is a
  // frequency of the motor row's effective mass, which the car's 2 m lever
  // arm to its attachment and small inertia make 0.012 kg, so it held the
  // 1.2 kg car with about 2 N per unit of fraction and the car swung round
  // the whole loop under gravity, crossing every control point.
  const std::size_t sled = body("sled", MotionType::kDynamic, {3.0f, 0.0f, 0.0f}, 0.8f,
                                {0.01f, 0.02f, 0.02f}, {0.1f, 0, 0});
  PathConstraintSettings slide;
  slide.name = "slide";
  slide.body1 = ground;
  slide.body2 = sled;
  slide.path_position = {3.0f, -1.0f, 0.0f};
  slide.path = {PathPoint{{-2, 1, 0}, {2, 0.5f, 0}, {0, 1, 0}},
                PathPoint{{0, 1.5f, 0.3f}, {2, 0, 0.5f}, {0, 1, 0}},
                PathPoint{{2, 1, 0}, {2, -1, 0}, {0.3f, 1, 0}},
                PathPoint{{4, 0, 0}, {2, 0, 0}, {0, 1, 0}}};
  slide.path_fraction = 1.0f;
  slide.rotation = PathRotation::kConstrainAroundNormal;
  slide.motor_state = MotorState::kVelocity;
  slide.target_velocity = 0.3f;
  slide.motor.min_force_limit = -2.0f;
  slide.motor.max_force_limit = 2.0f;
  scene.AddConstraint(slide);
  const std::size_t car = body("car", MotionType::kDynamic, {-3.0f, 2.0f, 1.0f}, 1.2f,
                               {0.02f, 0.05f, 0.05f}, {0, 0, 0});
  PathConstraintSettings track;
  track.name = "track";
  track.body1 = ground;
  track.body2 = car;
  track.path_position = {-3.0f, 2.0f, -1.0f};
  track.path_rotation = {0.2f, 0.0f, 0.0f, 0.98f};
  track.path = {PathPoint{{2, 0, 0}, {0, 3, 0}, {0, 0, 1}},
                PathPoint{{0, 2, 0}, {-3, 0, 0}, {0, 0, 1}},
                PathPoint{{-2, 0, 0.3f}, {0, -3, 0}, {0, 0, 1}},
                PathPoint{{0, -2, 0}, {3, 0, 0}, {0, 0, 1}}};
  track.looping = true;
  track.path_fraction = 1.4f;
  track.rotation = PathRotation::kConstrainToPath;
  track.motor_state = MotorState::kPosition;
  track.target_path_fraction = 1.5f;
  track.motor.spring = {SpringMode::kStiffnessAndDamping, 400.0f, 40.0f};
  scene.AddConstraint(track);
  return scene;
}

// "mixed", "more_types" or any id MakeScene takes.
inline Scene SceneById(const std::string& id) {
  if (id == "mixed") return MixedScene();
  if (id == "more_types") return MoreTypesScene();
  return MakeScene(id);
}

}  // namespace manyworlds::test_scenes
