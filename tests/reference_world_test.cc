// The scalar reference stepper (reference/world.h): the tests that read its
// internal state (a part's accumulated impulse, a stored motor target), in
// float and double.
//
// Jolt's behaviour tests (spec section 6) and the physical invariants and
// pipeline rules run on every stepper, the reference and the SIMD batch on
// every Highway target, in tests/jolt_behaviour_test.cc; that file also has
// the observable forms of the two tests here.
#include <gtest/gtest.h>

#include <cstddef>
#include <variant>

#include "manyworlds/batch.h"
#include "manyworlds/scene.h"
#include "reference/world.h"

namespace manyworlds::reference {
namespace {

constexpr double kDensity = 1000.0;  // kg/m³, Jolt's default shape density

// ---------------------------------------------------------------- helpers

BodySettings Box(Float3 half_extent, Float3 position,
                 MotionType motion_type = MotionType::kDynamic) {
  const double hx = half_extent[0], hy = half_extent[1], hz = half_extent[2];
  const double mass = kDensity * 8.0 * hx * hy * hz;
  BodySettings body;
  body.motion_type = motion_type;
  body.mass = float(mass);
  // Solid box: I_x = m/12·((2hy)² + (2hz)²) = m/3·(hy² + hz²), etc.
  body.inertia_diagonal = {float(mass / 3.0 * (hy * hy + hz * hz)),
                           float(mass / 3.0 * (hx * hx + hz * hz)),
                           float(mass / 3.0 * (hx * hx + hy * hy))};
  body.position = position;
  body.linear_damping = 0.0f;
  body.angular_damping = 0.0f;
  return body;
}

// Jolt's Body::sFixedToWorld: a static body at the origin.
BodySettings FixedToWorld() {
  BodySettings body;
  body.motion_type = MotionType::kStatic;
  return body;
}

template <class T>
class ReferenceWorldTest : public ::testing::Test {};
using Scalars = ::testing::Types<float, double>;
TYPED_TEST_SUITE(ReferenceWorldTest, Scalars);

// A 1 m bar (0.1 × 0.1 cross-section) hinged about Z at one end (the origin),
// reaching out along +X, limits [−0.5, 0.5] rad. Gravity turns it towards its
// min limit. Returns the scene; body 1 the bar, constraint 0 the hinge.
Scene HingedBar() {
  Scene scene;
  scene.AddBody(FixedToWorld());
  scene.AddBody(Box({0.5f, 0.05f, 0.05f}, {0.5f, 0, 0}));
  HingeConstraintSettings hinge;
  hinge.body1 = 0;
  hinge.body2 = 1;
  hinge.hinge_axis1 = hinge.hinge_axis2 = {0, 0, 1};
  hinge.normal_axis1 = hinge.normal_axis2 = {1, 0, 0};
  hinge.limits_min = -0.5f;
  hinge.limits_max = 0.5f;
  scene.AddConstraint(hinge);
  return scene;
}

// Spec 1.3: when the position phase finds a hard limit no longer violated it
// deactivates the limit row, which also zeroes the impulse the row accumulated
// in this step's velocity phase (next step then starts that limit cold). Setup:
// the bar rests with gravity against its min limit, 0.001 rad past it, and its
// hinge anchor is displaced sideways so that the point row's position step turns
// the bar back inside the limits. With no position iterations the limit keeps
// its impulse; with two it is zeroed. (Observable form, on every stepper:
// HingeLimitDeactivatedInPositionPhaseStartsNextStepCold.)
TYPED_TEST(ReferenceWorldTest, HingeLimitDeactivatedInPositionPhaseLosesImpulse) {
  using T = TypeParam;
  const auto make_world = [] {
    World<T> world(HingedBar());
    const T angle = T(-0.501);
    Body<T>& bar = world.body(1);
    bar.rotation = Quat<T>(Eigen::AngleAxis<T>(angle, Vec3<T>::UnitZ()));
    // Anchor (local (−0.5, 0, 0)) moved 0.05 m against the direction a positive
    // turn about the COM would move it; correcting it turns the bar positive.
    const Vec3<T> lever = bar.rotation * Vec3<T>(T(-0.5), T(0), T(0));
    const Vec3<T> positive_turn = Vec3<T>::UnitZ().cross(lever).normalized();
    bar.position = -lever - T(0.05) * positive_turn;
    return world;
  };
  const auto limit_impulse = [](const World<T>& world) {
    return double(std::get<HingeConstraint<T>>(world.constraint(0)).limit_part().GetTotalLambda());
  };

  StepSettings velocity_only;
  velocity_only.position_iterations = 0;
  World<T> without_position_phase = make_world();
  without_position_phase.Step(velocity_only);
  EXPECT_GT(limit_impulse(without_position_phase), 0.0);  // holds the bar up

  World<T> world = make_world();
  world.Step(StepSettings{});
  EXPECT_GT(double(world.HingeAngle(0)), -0.5);  // back inside the limits
  EXPECT_EQ(limit_impulse(world), 0.0);
}

// Target positions are clamped into the limits (spec 3). (Observable form, on
// every stepper: TargetPositionIsClampedIntoLimits.)
TYPED_TEST(ReferenceWorldTest, TargetPositionIsClampedIntoLimits) {
  World<TypeParam> hinge_world(HingedBar());
  hinge_world.SetTargetPosition(0, TypeParam(2));
  EXPECT_EQ(std::get<HingeConstraint<TypeParam>>(hinge_world.constraint(0)).target_angle(),
            TypeParam(0.5f));
}

}  // namespace
}  // namespace manyworlds::reference
