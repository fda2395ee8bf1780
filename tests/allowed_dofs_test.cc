// Allowed degrees of freedom (Jolt's EAllowedDOFs, spec 4.3 and 1.1), in the
// batch on every Highway target this CPU runs and in the scalar reference:
//  (a) a 2D body (kPlane2D) pushed and twisted out of its plane, on a pivot,
//      on a hinge whose axis is tilted out of the plane and tied to a second 2D
//      body by a point constraint that can never close out of the plane, stays
//      exactly in the plane: z = 0 and rotation about Z only (quaternion
//      x = y = 0), every step, and so does the second body;
//  (b) a body that may only translate keeps its rotation bit for bit;
//  (c) a scene mixing restricted and unrestricted bodies with point, hinge and
//      slider constraints matches the reference step by step;
//  (d) a dynamic body without any allowed DOF is refused.
//
// Exactness in (a) and (b) is bitwise. The masks are selects, so a locked
// component is +0, never a rounding residue or -0; and a quaternion whose x and
// y are +0 keeps them +0 through AddRotationStep about Z, as the last term of
// the product's x is (+0) * cos(angle / 2) with cos > 0 (steps below pi), and
// +0 + (+-0) is +0.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "manyworlds/batch.h"
#include "manyworlds/error.h"
#include "manyworlds/scene.h"
#include "reference/world.h"
#include "tests/lane_vs_reference.h"
#include "tests/step_targets.h"

namespace manyworlds {
namespace {

using ::testing::AllOf;
using ::testing::HasSubstr;

constexpr int kSteps = 300;
constexpr std::size_t kWorlds = 20;  // two blocks, the second mostly padding

// Rotation by `angle` about world Z, (x, y, z, w).
Quaternion AboutZ(float angle) { return {0, 0, std::sin(angle / 2), std::cos(angle / 2)}; }

// Different actions per world so that the lanes differ.
Float3 ForceFor(std::size_t world, int step) {
  const float s = 0.01f * float(world) + 0.02f * float(step % 7);
  return {0.5f + s, -0.3f, 3.0f - s};
}
Float3 TorqueFor(std::size_t world, int step) {
  const float s = 0.02f * float(world) - 0.01f * float(step % 5);
  return {1.0f + s, -2.0f, 0.5f + s};
}

template <class T>
reference::Vec3<T> ToVec(const Float3& v) {
  return reference::Vec3<T>(T(v[0]), T(v[1]), T(v[2]));
}

// ---------------------------------------------------------------- (a) 2D body

constexpr std::size_t kDisc = 1, kSatellite = 2;

// A 2D disc swinging on a pivot, tied to a free flap by a hinge whose axis is
// tilted out of the plane, and to a second 2D body by a point constraint that
// cannot close out of the plane.
//
// The tilted hinge joins the disc to a free body, not to the world: a 2D body
// can only turn about Z, so between it and a static body the hinge's two
// rotation rows see a rank-1 inverse inertia. Their 2x2 effective mass is then
// singular in exact arithmetic but not in floats (Jolt's test is det == 0, and
// with FMA the determinant comes out ~1e-12 instead of 0), so the impulses
// overflow -- in Jolt as here. With the free flap the block is well posed and
// every one of its impulses still pushes the disc about X and Y.
Scene PlanarScene() {
  Scene scene;
  BodySettings ground;
  ground.name = "ground";
  ground.motion_type = MotionType::kStatic;
  scene.AddBody(ground);

  BodySettings disc;
  disc.name = "disc";
  disc.allowed_dofs = AllowedDofs::kPlane2D;
  disc.position = {1.0f, 0.0f, 0.0f};
  disc.rotation = AboutZ(0.4f);
  disc.mass = 1.5f;
  disc.inertia_diagonal = {0.1f, 0.2f, 0.3f};
  // Principal axes not along the world axes: the world inverse inertia couples
  // X, Y and Z, so only the row-and-column masking keeps the rotation about Z.
  disc.inertia_rotation = {0.1f, -0.2f, 0.3f, 0.927362f};
  disc.linear_velocity = {0.3f, 0.1f, 0.5f};     // z is locked away at creation
  disc.angular_velocity = {0.4f, -0.2f, 1.0f};   // so are x and y
  scene.AddBody(disc);

  BodySettings satellite = disc;
  satellite.name = "satellite";
  satellite.position = {2.0f, 0.0f, 0.0f};
  satellite.rotation = AboutZ(-0.7f);
  satellite.mass = 0.5f;
  satellite.inertia_diagonal = {0.02f, 0.03f, 0.04f};
  satellite.linear_velocity = {0, 0, -1};
  satellite.angular_velocity = {2, 0, 0};
  scene.AddBody(satellite);

  BodySettings flap;
  flap.name = "flap";
  flap.position = {1.4f, -0.2f, 0.3f};
  flap.mass = 0.4f;
  flap.inertia_diagonal = {0.01f, 0.02f, 0.015f};
  flap.angular_velocity = {0.5f, 0.0f, -0.5f};
  const std::size_t flap_index = scene.AddBody(flap);

  PointConstraintSettings pivot;
  pivot.name = "pivot";
  pivot.body1 = 0;
  pivot.body2 = kDisc;
  pivot.point1 = pivot.point2 = {0, 0, 0};
  scene.AddConstraint(pivot);

  // Hinge axis tilted out of the plane: its rotation rows push about X and Y.
  HingeConstraintSettings hinge;
  hinge.name = "tilted hinge";
  hinge.body1 = kDisc;
  hinge.body2 = flap_index;
  hinge.point1 = hinge.point2 = {1.3f, -0.1f, 0.1f};
  hinge.hinge_axis1 = hinge.hinge_axis2 = {0.3f, 0.2f, 1.0f};
  hinge.normal_axis1 = hinge.normal_axis2 = {1.0f, 0.0f, -0.3f};
  hinge.motor_state = MotorState::kVelocity;
  hinge.target_angular_velocity = 3.0f;
  hinge.motor.min_force_limit = -1.0f;
  hinge.motor.max_force_limit = 1.0f;
  scene.AddConstraint(hinge);

  // Anchors 0.5 m apart in Z in every pose a 2D body can reach: the position
  // phase pushes along Z every iteration, and only the mask stops it.
  PointConstraintSettings tie;
  tie.name = "out-of-plane tie";
  tie.body1 = kDisc;
  tie.body2 = kSatellite;
  tie.space = ConstraintSpace::kLocalToBodyCOM;
  tie.point1 = {0.5f, 0.0f, 0.3f};
  tie.point2 = {-0.5f, 0.0f, -0.2f};
  scene.AddConstraint(tie);
  return scene;
}

class AllowedDofsTargetTest : public ::testing::TestWithParam<std::int64_t> {
 protected:
  BatchOptions options() const { return BatchOptions{1, 0, GetParam()}; }
};

// Bitwise +0.
template <class T>
bool IsPlusZero(T x) {
  return x == T(0) && !std::signbit(x);
}

// The lane's body stays in the XY plane; returns false (with a failure) once.
bool ExpectInPlane(const float* s, const std::string& where) {
  const bool in_plane = IsPlusZero(s[2]) && IsPlusZero(s[3]) && IsPlusZero(s[4]) &&
                        IsPlusZero(s[9]) && IsPlusZero(s[10]) && IsPlusZero(s[11]);
  bool finite = true;
  for (int i = 0; i < 13; ++i) finite = finite && std::isfinite(s[i]);
  EXPECT_TRUE(in_plane && finite)
      << where << ": z " << s[2] << ", q.x " << s[3] << ", q.y " << s[4] << ", v.z " << s[9]
      << ", w.x " << s[10] << ", w.y " << s[11];
  return in_plane && finite;
}

TEST_P(AllowedDofsTargetTest, PlanarBodyStaysExactlyInItsPlane) {
  const Scene scene = PlanarScene();
  Batch batch(scene, kWorlds, options());
  const std::size_t per_world = batch.body_count() * kStateFloatsPerBody;
  std::vector<float> state(kWorlds * per_world);
  batch.GetState(state);
  const std::vector<float> initial = state;
  for (int step = 0; step < kSteps; ++step) {
    for (std::size_t w = 0; w < kWorlds; ++w) {
      for (std::size_t body : {kDisc, kSatellite}) {
        batch.SetForce(w, body, ForceFor(w, step));
        batch.SetTorque(w, body, TorqueFor(w, step));
      }
    }
    batch.Step({});
    batch.GetState(state);
    for (std::size_t w = 0; w < kWorlds; ++w) {
      for (std::size_t body : {kDisc, kSatellite}) {
        const std::string where = "step " + std::to_string(step) + ", world " +
                                  std::to_string(w) + ", body " + std::to_string(body);
        if (!ExpectInPlane(state.data() + w * per_world + body * kStateFloatsPerBody, where)) {
          return;
        }
      }
    }
  }
  // It did move in the plane (x, y and the angle about Z).
  const float* disc = state.data() + kDisc * kStateFloatsPerBody;
  const float* disc0 = initial.data() + kDisc * kStateFloatsPerBody;
  EXPECT_GT(std::abs(disc[0] - disc0[0]) + std::abs(disc[1] - disc0[1]), 1e-2f);
  EXPECT_GT(std::abs(disc[5] - disc0[5]), 1e-2f);
}

template <class T>
void ExpectReferenceStaysInPlane() {
  const Scene scene = PlanarScene();
  reference::World<T> world(scene);
  const reference::Vec3<T> start = world.body(kDisc).position;
  const T start_z_rotation = world.body(kDisc).rotation.z();
  for (int step = 0; step < kSteps; ++step) {
    for (std::size_t body : {kDisc, kSatellite}) {
      world.SetForce(body, ToVec<T>(ForceFor(3, step)));
      world.SetTorque(body, ToVec<T>(TorqueFor(3, step)));
    }
    world.Step({});
    for (std::size_t body : {kDisc, kSatellite}) {
      const reference::Body<T>& b = world.body(body);
      ASSERT_TRUE(IsPlusZero(b.position.z()) && IsPlusZero(b.rotation.x()) &&
                  IsPlusZero(b.rotation.y()) && IsPlusZero(b.linear_velocity.z()) &&
                  IsPlusZero(b.angular_velocity.x()) && IsPlusZero(b.angular_velocity.y()))
          << "step " << step << ", body " << body << ": z " << b.position.z() << ", q.x "
          << b.rotation.x() << ", q.y " << b.rotation.y();
      ASSERT_TRUE(b.position.allFinite() && b.rotation.coeffs().allFinite());
    }
  }
  const reference::Body<T>& disc = world.body(kDisc);
  EXPECT_GT((disc.position - start).norm(), T(1e-2));
  EXPECT_GT(std::abs(disc.rotation.z() - start_z_rotation), T(1e-2));
}

TEST(AllowedDofsReferenceTest, PlanarBodyStaysExactlyInItsPlane) {
  ExpectReferenceStaysInPlane<float>();
  ExpectReferenceStaysInPlane<double>();
}

// ------------------------------------------------------- (b) translation only

constexpr std::size_t kCrate = 1, kBall = 2;

Scene TranslationOnlyScene() {
  Scene scene;
  BodySettings ground;
  ground.name = "ground";
  ground.motion_type = MotionType::kStatic;
  scene.AddBody(ground);

  BodySettings crate;
  crate.name = "crate";
  crate.allowed_dofs =
      AllowedDofs::kTranslationX | AllowedDofs::kTranslationY | AllowedDofs::kTranslationZ;
  crate.position = {0.4f, -0.8f, 0.2f};
  crate.rotation = {0.05f, 0.1f, -0.08f, 0.99f};  // normalised by the batch
  crate.mass = 2.0f;
  crate.inertia_diagonal = {0.1f, 0.05f, 0.12f};
  crate.inertia_rotation = {0.1f, -0.2f, 0.3f, 0.927362f};
  crate.linear_velocity = {0.2f, 0.0f, -0.1f};
  crate.angular_velocity = {1.0f, 2.0f, -3.0f};  // locked away at creation
  scene.AddBody(crate);

  BodySettings ball;
  ball.name = "ball";
  ball.position = {0.9f, -1.2f, 0.4f};
  ball.mass = 0.5f;
  ball.inertia_diagonal = {0.01f, 0.012f, 0.015f};
  ball.angular_velocity = {0.3f, -0.5f, 0.2f};
  scene.AddBody(ball);

  // On a rail anchored off its centre, so that every rail impulse has a lever
  // arm about the crate's COM. (A ball joint to the world would simply hold a
  // body that cannot rotate in place.)
  SliderConstraintSettings rail;
  rail.name = "rail";
  rail.body1 = 0;
  rail.body2 = kCrate;
  rail.point1 = rail.point2 = {0.5f, -0.6f, 0.3f};
  rail.slider_axis1 = rail.slider_axis2 = {1.0f, 0.0f, 0.3f};
  rail.normal_axis1 = rail.normal_axis2 = {0.0f, 1.0f, 0.0f};
  scene.AddConstraint(rail);

  HingeConstraintSettings arm;
  arm.name = "arm";
  arm.body1 = kCrate;
  arm.body2 = kBall;
  arm.point1 = arm.point2 = {0.7f, -1.0f, 0.3f};
  arm.hinge_axis1 = arm.hinge_axis2 = {0.3f, 1.0f, 0.2f};
  arm.normal_axis1 = arm.normal_axis2 = {1.0f, -0.3f, 0.0f};
  arm.motor_state = MotorState::kVelocity;
  arm.target_angular_velocity = 2.0f;
  arm.motor.min_force_limit = -5.0f;
  arm.motor.max_force_limit = 5.0f;
  scene.AddConstraint(arm);
  return scene;
}

TEST_P(AllowedDofsTargetTest, TranslationOnlyBodyKeepsItsRotationBitForBit) {
  const Scene scene = TranslationOnlyScene();
  Batch batch(scene, kWorlds, options());
  const std::size_t per_world = batch.body_count() * kStateFloatsPerBody;
  std::vector<float> state(kWorlds * per_world);
  batch.GetState(state);
  const std::vector<float> initial = state;
  for (int step = 0; step < kSteps; ++step) {
    for (std::size_t w = 0; w < kWorlds; ++w) {
      batch.SetForce(w, kCrate, ForceFor(w, step));
      batch.SetTorque(w, kCrate, TorqueFor(w, step));
    }
    batch.Step({});
    batch.GetState(state);
    for (std::size_t w = 0; w < kWorlds; ++w) {
      const std::size_t at = w * per_world + kCrate * kStateFloatsPerBody;
      bool same = true;
      for (int i = 3; i < 7; ++i) {
        same = same && std::memcmp(&state[at + i], &initial[at + i], sizeof(float)) == 0;
      }
      const bool still = state[at + 10] == 0.0f && state[at + 11] == 0.0f &&
                         state[at + 12] == 0.0f;
      ASSERT_TRUE(same && still) << "step " << step << ", world " << w << ": q ("
                                 << state[at + 3] << ", " << state[at + 4] << ", "
                                 << state[at + 5] << ", " << state[at + 6] << "), w ("
                                 << state[at + 10] << ", " << state[at + 11] << ", "
                                 << state[at + 12] << ")";
    }
  }
  const std::size_t at = kCrate * kStateFloatsPerBody;
  EXPECT_GT(std::abs(state[at] - initial[at]) + std::abs(state[at + 1] - initial[at + 1]),
            1e-3f)
      << "the crate should slide along its rail";
}

template <class T>
void ExpectReferenceKeepsRotation() {
  const Scene scene = TranslationOnlyScene();
  reference::World<T> world(scene);
  const reference::Quat<T> start = world.body(kCrate).rotation;
  const reference::Vec3<T> start_position = world.body(kCrate).position;
  for (int step = 0; step < kSteps; ++step) {
    world.SetForce(kCrate, ToVec<T>(ForceFor(5, step)));
    world.SetTorque(kCrate, ToVec<T>(TorqueFor(5, step)));
    world.Step({});
    const reference::Body<T>& crate = world.body(kCrate);
    ASSERT_EQ(std::memcmp(crate.rotation.coeffs().data(), start.coeffs().data(), 4 * sizeof(T)),
              0)
        << "step " << step << ": q (" << crate.rotation.coeffs().transpose() << ")";
    ASSERT_TRUE(crate.angular_velocity.isZero(T(0))) << "step " << step;
  }
  EXPECT_GT((world.body(kCrate).position - start_position).norm(), T(1e-3));
}

TEST(AllowedDofsReferenceTest, TranslationOnlyBodyKeepsItsRotationBitForBit) {
  ExpectReferenceKeepsRotation<float>();
  ExpectReferenceKeepsRotation<double>();
}

// ---------------------------------------------------- (c) batch vs reference

// Restricted and unrestricted bodies on point, hinge and slider constraints:
// a 2D arm on a hinge about Z carrying a free bob on a ball joint; a
// translation-only carriage on a rail (slider with limits and a motor) carrying
// a puck that moves in the XZ plane on a second slider; a rotation-only wheel
// pinned at its centre (hinge with a motor) swinging a free weight. Each
// restricted body meets constraints that are well posed for it and nothing is
// over-constrained, so the comparison measures the masks, not the conditioning
// of a degenerate mechanism. (Where a masked inertia makes a rotation block
// exactly singular, e.g. the rotation rows of a translation-only body's
// slider, both sides deactivate it by Jolt's det == 0 rule.)
constexpr std::size_t kMixedDynamicBodies[] = {1, 2, 3, 4, 5, 6};

Scene MixedDofScene() {
  Scene scene;
  auto body = [&](const char* name, MotionType type, AllowedDofs dofs, Float3 position,
                  Quaternion rotation, float mass, Float3 inertia, Float3 velocity,
                  Float3 spin) {
    BodySettings b;
    b.name = name;
    b.motion_type = type;
    b.allowed_dofs = dofs;
    b.position = position;
    b.rotation = rotation;
    b.mass = mass;
    b.inertia_diagonal = inertia;
    b.inertia_rotation = {0.1f, -0.2f, 0.3f, 0.927362f};
    b.linear_velocity = velocity;
    b.angular_velocity = spin;
    b.linear_damping = 0.1f;
    return scene.AddBody(b);
  };
  const AllowedDofs translation =
      AllowedDofs::kTranslationX | AllowedDofs::kTranslationY | AllowedDofs::kTranslationZ;
  const AllowedDofs rotation =
      AllowedDofs::kRotationX | AllowedDofs::kRotationY | AllowedDofs::kRotationZ;
  const AllowedDofs plane_xz =
      AllowedDofs::kTranslationX | AllowedDofs::kTranslationZ | AllowedDofs::kRotationY;
  const Quaternion tilted{0.05f, 0.1f, -0.08f, 0.99f};
  const std::size_t ground = body("ground", MotionType::kStatic, AllowedDofs::kAll, {0, 0, 0},
                                  {0, 0, 0, 1}, 1, {1, 1, 1}, {}, {});
  const std::size_t arm = body("arm", MotionType::kDynamic, AllowedDofs::kPlane2D,
                               {0.5f, -0.3f, 0.0f}, AboutZ(0.3f), 2.0f, {0.1f, 0.05f, 0.12f},
                               {0.2f, 0.0f, 0.7f}, {0.5f, 1.0f, -0.3f});
  const std::size_t bob = body("bob", MotionType::kDynamic, AllowedDofs::kAll,
                               {1.0f, -0.6f, 0.2f}, tilted, 0.5f, {0.03f, 0.035f, 0.04f},
                               {0.0f, 0.3f, 0.0f}, {0.2f, -0.4f, 0.1f});
  const std::size_t carriage = body("carriage", MotionType::kDynamic, translation,
                                    {0.8f, 0.5f, 0.1f}, tilted, 0.7f, {0.01f, 0.02f, 0.015f},
                                    {0.1f, 0.2f, 0.3f}, {1.0f, 2.0f, 3.0f});
  const std::size_t puck = body("puck", MotionType::kDynamic, plane_xz, {1.3f, 0.5f, 0.5f},
                                {0, 0.2f, 0, 0.98f}, 0.3f, {0.004f, 0.003f, 0.005f},
                                {0.1f, 0.5f, 0.0f}, {0.3f, 0.6f, 0.0f});
  const std::size_t wheel = body("wheel", MotionType::kDynamic, rotation, {-0.6f, 0.2f, 0.0f},
                                 tilted, 1.5f, {0.03f, 0.03f, 0.05f}, {0.4f, 0.0f, 0.0f},
                                 {0.0f, 0.0f, 2.0f});
  const std::size_t weight = body("weight", MotionType::kDynamic, AllowedDofs::kAll,
                                  {-0.4f, -0.3f, 0.05f}, tilted, 0.4f,
                                  {0.008f, 0.01f, 0.012f}, {}, {0.1f, 0.0f, -0.2f});

  HingeConstraintSettings shoulder;
  shoulder.name = "shoulder";
  shoulder.body1 = ground;
  shoulder.body2 = arm;
  shoulder.point1 = shoulder.point2 = {0, 0, 0};
  shoulder.hinge_axis1 = shoulder.hinge_axis2 = {0, 0, 1};
  shoulder.normal_axis1 = shoulder.normal_axis2 = {1, 0, 0};
  shoulder.limits_min = -1.0f;
  shoulder.limits_max = 0.8f;
  scene.AddConstraint(shoulder);

  PointConstraintSettings elbow;  // out of the arm's plane
  elbow.name = "elbow";
  elbow.body1 = arm;
  elbow.body2 = bob;
  elbow.point1 = elbow.point2 = {0.9f, -0.55f, 0.1f};
  scene.AddConstraint(elbow);

  SliderConstraintSettings rail;
  rail.name = "rail";
  rail.body1 = ground;
  rail.body2 = carriage;
  rail.point1 = rail.point2 = {0.8f, 0.5f, 0.1f};
  rail.slider_axis1 = rail.slider_axis2 = {1.0f, 0.0f, 0.3f};
  rail.normal_axis1 = rail.normal_axis2 = {0.0f, 1.0f, 0.0f};
  rail.limits_min = -0.2f;
  rail.limits_max = 0.3f;
  rail.motor_state = MotorState::kVelocity;
  rail.target_velocity = 0.5f;
  rail.motor.min_force_limit = -3.0f;
  rail.motor.max_force_limit = 3.0f;
  scene.AddConstraint(rail);

  SliderConstraintSettings drawer;
  drawer.name = "drawer";
  drawer.body1 = carriage;
  drawer.body2 = puck;
  drawer.auto_detect_point = true;
  drawer.slider_axis1 = drawer.slider_axis2 = {0.0f, 0.0f, 1.0f};
  drawer.normal_axis1 = drawer.normal_axis2 = {1.0f, 0.0f, 0.0f};
  drawer.limits_min = -0.3f;
  drawer.limits_max = 0.4f;
  drawer.limits_spring.frequency_or_stiffness = 3.0f;
  drawer.limits_spring.damping = 0.3f;
  scene.AddConstraint(drawer);

  HingeConstraintSettings axle;  // pinned at the centre of a rotation-only wheel
  axle.name = "axle";
  axle.body1 = ground;
  axle.body2 = wheel;
  axle.point1 = axle.point2 = {-0.6f, 0.2f, 0.0f};
  axle.hinge_axis1 = axle.hinge_axis2 = {0, 0.2f, 1};
  axle.normal_axis1 = axle.normal_axis2 = {1, 0, 0};
  axle.motor_state = MotorState::kVelocity;
  axle.target_angular_velocity = 1.5f;
  axle.motor.min_force_limit = -2.0f;
  axle.motor.max_force_limit = 2.0f;
  scene.AddConstraint(axle);

  PointConstraintSettings hang;  // the wheel's rim to a free weight
  hang.name = "hang";
  hang.body1 = wheel;
  hang.body2 = weight;
  hang.point1 = hang.point2 = {-0.4f, 0.2f, 0.0f};
  scene.AddConstraint(hang);
  return scene;
}

// The bound of scene_comparison_test's scenes with a few rows per world (32
// FLT_EPSILON x scale; its mixed scene measures 5), because nothing here should
// need more: the masks are selects, exact in both implementations, so they add
// no rounding of their own -- a locked component is exactly zero on both sides
// and the rest is the same Gauss-Seidel arithmetic over a comparable number of
// rows (6 constraints, at most 24 rows). Measured worst over all targets: 9.1
// (velocity, float reference), 6.4 against the double reference; the same
// scene with every DOF allowed measures 12.6, so the masks cost no accuracy.
constexpr double kStepTolerance = 32.0;

TEST_P(AllowedDofsTargetTest, MixedScenesMatchTheReferenceStepByStep) {
  const Scene scene = MixedDofScene();
  Batch batch(scene, kWorlds, options());
  std::vector<reference::World<float>> float_worlds(kWorlds, reference::World<float>(scene));
  std::vector<reference::World<double>> double_worlds(kWorlds, reference::World<double>(scene));
  const std::size_t per_world = batch.body_count() * kStateFloatsPerBody;
  std::vector<float> state(kWorlds * per_world);
  Deviation worst_float, worst_double;
  for (int step = 0; step < kSteps; ++step) {
    batch.GetState(state);
    for (std::size_t w = 0; w < kWorlds; ++w) {
      SyncReferenceWorld(float_worlds[w], batch, w, state.data() + w * per_world);
      SyncReferenceWorld(double_worlds[w], batch, w, state.data() + w * per_world);
      for (std::size_t body : kMixedDynamicBodies) {
        // Gentler than (a): the bodies here are light (3-15 g m^2).
        const Float3 f = ForceFor(w, step), t = TorqueFor(w, step);
        const Float3 force{0.5f * f[0], 0.5f * f[1], 0.5f * f[2]};
        const Float3 torque{0.02f * t[0], 0.02f * t[1], 0.02f * t[2]};
        batch.SetForce(w, body, force);
        batch.SetTorque(w, body, torque);
        float_worlds[w].SetForce(body, ToVec<float>(force));
        float_worlds[w].SetTorque(body, ToVec<float>(torque));
        double_worlds[w].SetForce(body, ToVec<double>(force));
        double_worlds[w].SetTorque(body, ToVec<double>(torque));
      }
      float_worlds[w].Step({});
      double_worlds[w].Step({});
    }
    batch.Step({});
    batch.GetState(state);
    for (std::size_t w = 0; w < kWorlds; ++w) {
      for (std::size_t b = 0; b < batch.body_count(); ++b) {
        const float* lane = state.data() + w * per_world + b * kStateFloatsPerBody;
        worst_float.Max(Compare(lane, float_worlds[w].body(b)));
        worst_double.Max(Compare(lane, double_worlds[w].body(b)));
      }
    }
  }
  std::printf("mixed allowed-DOF scene on %s: worst one-step deviation in FLT_EPSILON x "
              "scale: float ref (x %.1f, q %.1f, v %.1f), double ref (x %.1f, q %.1f, v %.1f)\n",
              batch.SimdTarget(), worst_float.position, worst_float.rotation,
              worst_float.velocity, worst_double.position, worst_double.rotation,
              worst_double.velocity);
  EXPECT_LT(worst_float.position, kStepTolerance) << "position vs reference<float>";
  EXPECT_LT(worst_float.rotation, kStepTolerance) << "rotation vs reference<float>";
  EXPECT_LT(worst_float.velocity, kStepTolerance) << "velocity vs reference<float>";
  EXPECT_LT(worst_double.position, kStepTolerance) << "position vs reference<double>";
  EXPECT_LT(worst_double.rotation, kStepTolerance) << "rotation vs reference<double>";
  EXPECT_LT(worst_double.velocity, kStepTolerance) << "velocity vs reference<double>";
}

INSTANTIATE_TEST_SUITE_P(EveryTarget, AllowedDofsTargetTest,
                         ::testing::ValuesIn(SupportedStepTargets()),
                         [](const auto& info) { return std::string(hwy::TargetName(info.param)); });

// ------------------------------------------------------------- (d) refusal

TEST(AllowedDofsSceneTest, DynamicBodyWithoutAnyDofIsRefused) {
  Scene scene = PlanarScene();
  scene.bodies()[kDisc].allowed_dofs = AllowedDofs::kNone;
  EXPECT_THAT([&] { Batch batch(scene, 4); },
              ::testing::ThrowsMessage<SceneError>(
                  AllOf(HasSubstr("body #1 'disc'"), HasSubstr("allowed_dofs"))));
  // Bits outside the six DOFs are refused for any body.
  scene.bodies()[kDisc].allowed_dofs = static_cast<AllowedDofs>(64 | 1);
  EXPECT_THAT([&] { Batch batch(scene, 4); },
              ::testing::ThrowsMessage<SceneError>(
                  AllOf(HasSubstr("body #1 'disc'"), HasSubstr("allowed_dofs"))));
  // A static body never moves: no DOF is fine.
  scene.bodies()[kDisc].allowed_dofs = AllowedDofs::kPlane2D;
  scene.bodies()[0].allowed_dofs = AllowedDofs::kNone;
  EXPECT_NO_THROW(Batch(scene, 4));
}

}  // namespace
}  // namespace manyworlds
