// Contacts in the batch (docs/contacts.md): which shape pairs make contact
// slots, what is refused (naming the body, pair or field, before anything is
// written), and per-lane decisions: worlds that touch and worlds that do not
// share a block without noticing each other. The physics of a contact is
// checked on both steppers in contact_behaviour_test.cc and lane by lane
// against the reference in scene_comparison_test.cc.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

#include "manyworlds/batch.h"
#include "manyworlds/error.h"
#include "manyworlds/scene.h"
#include "tests/step_targets.h"

namespace manyworlds {
namespace {

using ::testing::HasSubstr;

BodySettings Ground() {
  BodySettings ground;
  ground.name = "ground";
  ground.motion_type = MotionType::kStatic;
  ground.shape.type = ShapeType::kPlane;
  return ground;
}

// Dynamic shapes here meet the ground (group 1) but not each other (group 2,
// mask 1), so that each test's slots are the ones it names.
BodySettings Ball(const std::string& name, Float3 position) {
  BodySettings ball;
  ball.name = name;
  ball.position = position;
  ball.inertia_diagonal = {0.1f, 0.1f, 0.1f};
  ball.linear_damping = ball.angular_damping = 0.0f;
  ball.shape.type = ShapeType::kSphere;
  ball.shape.radius = 0.5f;
  ball.shape.collision_group = 2;
  ball.shape.collision_mask = 1;
  return ball;
}

// The SceneError message of building a batch of `scene`; "" if it is built.
std::string BuildRefusal(const Scene& scene) {
  try {
    Batch batch(scene, 4);
  } catch (const SceneError& e) {
    return e.what();
  }
  return "";
}

TEST(ContactPlanTest, APlaneAndEachShapeMakeOneSlotInBodyOrder) {
  Scene scene;
  scene.AddBody(Ground());
  scene.AddBody(Ball("ball", {0, 2, 0}));
  BodySettings box = Ball("box", {3, 2, 0});
  box.shape.type = ShapeType::kBox;
  scene.AddBody(box);
  BodySettings capsule = Ball("capsule", {6, 2, 0});
  capsule.shape.type = ShapeType::kCapsule;
  scene.AddBody(capsule);
  const Batch batch(scene, 4);
  const std::string plan = batch.Plan();
  EXPECT_THAT(plan, HasSubstr("contacts in solve order (after the constraints): 3"));
  const auto ball = plan.find("contact body #0 'ground' / body #1 'ball'");
  const auto boxes = plan.find("contact body #0 'ground' / body #2 'box'");
  const auto capsules = plan.find("contact body #0 'ground' / body #3 'capsule'");
  ASSERT_NE(ball, std::string::npos) << plan;
  ASSERT_NE(boxes, std::string::npos) << plan;
  ASSERT_NE(capsules, std::string::npos) << plan;
  EXPECT_LT(ball, boxes);
  EXPECT_LT(boxes, capsules);
  EXPECT_THAT(plan, HasSubstr("plane-sphere, up to 1 point(s)"));
  EXPECT_THAT(plan, HasSubstr("plane-box, up to 4 point(s)"));
  EXPECT_THAT(plan, HasSubstr("plane-capsule, up to 2 point(s)"));
  // Friction sqrt(0.2 0.2) and restitution max(0, 0): Jolt's defaults.
  EXPECT_THAT(plan, HasSubstr("friction 0.2, restitution 0"));
}

// Steps a ball dropped from 1 m for 1 s and returns its final height.
float HeightAfterDrop(const Scene& scene, std::size_t ball) {
  Batch batch(scene, 1);
  for (int i = 0; i < 60; ++i) batch.Step(StepSettings{});
  std::vector<float> state(scene.bodies().size() * kStateFloatsPerBody);
  batch.GetState(state);
  return state[ball * kStateFloatsPerBody + 1];
}

TEST(ContactPlanTest, FiltersDecideWhichPairsTouch) {
  Scene scene;
  scene.AddBody(Ground());
  scene.AddBody(Ball("ball", {0, 1, 0}));
  // Touching: the ball rests on the ground (within the 2 cm slop).
  EXPECT_NEAR(HeightAfterDrop(scene, 1), 0.5f, 0.02f);

  // Groups that do not meet: no slot, the ball falls through.
  Scene apart = scene;
  apart.bodies()[1].shape.collision_mask = 4;
  EXPECT_THAT(Batch(apart, 1).Plan(), HasSubstr("contacts in solve order (after the constraints): 0"));
  EXPECT_LT(HeightAfterDrop(apart, 1), -3.0f);

  // Joined bodies do not collide unless a shape asks to.
  Scene joined = scene;
  DistanceConstraintSettings rope;
  rope.body1 = 0;
  rope.body2 = 1;
  rope.point1 = {0, 10, 0};
  rope.point2 = {0, 1, 0};
  rope.min_distance = 0.0f;
  rope.max_distance = 20.0f;
  joined.AddConstraint(rope);
  EXPECT_THAT(Batch(joined, 1).Plan(), HasSubstr("contacts in solve order (after the constraints): 0"));
  joined.bodies()[1].shape.collide_with_joined = true;
  EXPECT_THAT(Batch(joined, 1).Plan(), HasSubstr("contacts in solve order (after the constraints): 1"));
  EXPECT_NEAR(HeightAfterDrop(joined, 1), 0.5f, 0.02f);

  // Two non-dynamic bodies never make a slot.
  Scene statics;
  statics.AddBody(Ground());
  BodySettings fixed_ball = Ball("fixed ball", {0, 0, 0});
  fixed_ball.motion_type = MotionType::kKinematic;
  statics.AddBody(fixed_ball);
  statics.AddBody(Ball("ball", {5, 1, 0}));
  EXPECT_THAT(Batch(statics, 1).Plan(), HasSubstr("contacts in solve order (after the constraints): 1"));
}

TEST(ContactRefusalTest, BadShapesAndPairsAreNamed) {
  Scene plane_on_dynamic;
  BodySettings slab = Ball("slab", {0, 0, 0});
  slab.shape.type = ShapeType::kPlane;
  plane_on_dynamic.AddBody(slab);
  const std::string plane = BuildRefusal(plane_on_dynamic);
  EXPECT_THAT(plane, HasSubstr("slab"));
  EXPECT_THAT(plane, HasSubstr("shape.type"));
  EXPECT_THAT(plane, HasSubstr("only a static body"));

  // Every pair of sphere, capsule and box makes a slot, whichever is body 1,
  // with the points its kind reserves.
  struct PairCase {
    ShapeType left, right;
    const char* plan;
  };
  for (const PairCase& c :
       {PairCase{ShapeType::kSphere, ShapeType::kCapsule, "sphere-capsule, up to 1 point(s)"},
        PairCase{ShapeType::kSphere, ShapeType::kBox, "sphere-box, up to 1 point(s)"},
        PairCase{ShapeType::kBox, ShapeType::kSphere, "sphere-box, up to 1 point(s)"},
        PairCase{ShapeType::kCapsule, ShapeType::kBox, "capsule-box, up to 2 point(s)"},
        PairCase{ShapeType::kBox, ShapeType::kCapsule, "capsule-box, up to 2 point(s)"},
        PairCase{ShapeType::kBox, ShapeType::kBox, "box-box, up to 4 point(s)"}}) {
    Scene pair;
    pair.AddBody(Ball("left", {0, 0, 0}));
    pair.AddBody(Ball("right", {2, 0, 0}));
    pair.bodies()[0].shape.type = c.left;
    pair.bodies()[1].shape.type = c.right;
    pair.bodies()[0].shape.collision_mask = pair.bodies()[1].shape.collision_mask = 2;
    const std::string plan = Batch(pair, 1).Plan();
    EXPECT_THAT(plan, HasSubstr("contact body #0 'left' / body #1 'right'")) << c.plan;
    EXPECT_THAT(plan, HasSubstr(c.plan));
  }

  const auto refusal_of = [](const char* field, auto edit) {
    Scene scene;
    scene.AddBody(Ground());
    BodySettings body = Ball("body", {0, 2, 0});
    edit(body.shape);
    scene.AddBody(body);
    const std::string message = BuildRefusal(scene);
    EXPECT_THAT(message, HasSubstr("body")) << field;
    EXPECT_THAT(message, HasSubstr(field));
  };
  refusal_of("shape.radius", [](ShapeSettings& s) { s.radius = 0.0f; });
  refusal_of("shape.radius", [](ShapeSettings& s) { s.radius = NAN; });
  refusal_of("shape.half_height", [](ShapeSettings& s) {
    s.type = ShapeType::kCapsule;
    s.half_height = -1.0f;
  });
  refusal_of("shape.half_extents[2]", [](ShapeSettings& s) {
    s.type = ShapeType::kBox;
    s.half_extents[2] = INFINITY;
  });
  refusal_of("shape.position", [](ShapeSettings& s) { s.position[1] = NAN; });
  refusal_of("shape.rotation", [](ShapeSettings& s) { s.rotation = {0, 0, 0, 0}; });
  refusal_of("shape.friction", [](ShapeSettings& s) { s.friction = -0.1f; });
  refusal_of("shape.restitution", [](ShapeSettings& s) { s.restitution = 1.5f; });
  refusal_of("shape.type", [](ShapeSettings& s) { s.type = static_cast<ShapeType>(9); });
}

TEST(ContactRefusalTest, BadStepSettingsAreRefusedBeforeAnythingMoves) {
  Scene scene;
  scene.AddBody(Ground());
  scene.AddBody(Ball("ball", {0, 2, 0}));
  Batch batch(scene, 3);
  std::vector<float> before(batch.world_count() * 2 * kStateFloatsPerBody), after = before;
  batch.GetState(before);
  const auto refusal = [&](const char* field, auto edit) {
    StepSettings settings;
    edit(settings);
    try {
      batch.Step(settings);
      ADD_FAILURE() << field << " was taken";
    } catch (const SceneError& e) {
      EXPECT_THAT(std::string(e.what()), HasSubstr(field));
    }
    batch.GetState(after);
    EXPECT_EQ(0, std::memcmp(before.data(), after.data(), before.size() * sizeof(float)))
        << field;
  };
  refusal("speculative_contact_distance",
          [](StepSettings& s) { s.speculative_contact_distance = -0.01f; });
  refusal("penetration_slop", [](StepSettings& s) { s.penetration_slop = NAN; });
  refusal("max_penetration_distance",
          [](StepSettings& s) { s.max_penetration_distance = INFINITY; });
  refusal("min_velocity_for_restitution",
          [](StepSettings& s) { s.min_velocity_for_restitution = -1.0f; });
}

// GetContacts: a box resting on the ground carries m g on its 4 points; a box
// sliding along X feels mu m g of friction against its motion; a ball in
// the air touches nothing.
TEST(ContactReadoutTest, ForcesAreWhatTheBodiesFeel) {
  Scene scene;
  scene.AddBody(Ground());
  BodySettings resting = Ball("resting box", {0, 0.5f, 0});
  resting.mass = 2.0f;
  resting.shape.type = ShapeType::kBox;
  scene.AddBody(resting);
  BodySettings sliding = Ball("sliding box", {3, 0.5f, 0});
  sliding.shape.type = ShapeType::kBox;
  sliding.linear_velocity = {4.0f, 0.0f, 0.0f};
  scene.AddBody(sliding);
  scene.AddBody(Ball("flying ball", {6, 5, 0}));
  Batch batch(scene, 3);
  ASSERT_EQ(batch.ContactSlotCount(), 3u);
  const Batch::ContactSlot first = batch.GetContactSlot(0);
  EXPECT_EQ(first.body1, 0u);
  EXPECT_EQ(first.body2, 1u);
  EXPECT_EQ(first.max_points, 4u);
  EXPECT_THROW(batch.GetContactSlot(3), std::out_of_range);
  std::vector<float> contacts(3 * 3 * Batch::kContactFloats);
  batch.GetContacts(contacts);
  for (const float x : contacts) EXPECT_EQ(x, 0.0f) << "before the first step";
  for (int step = 0; step < 10; ++step) batch.Step(StepSettings{});
  batch.GetContacts(contacts);
  const float g = 9.81f, mu = 0.2f;  // sqrt(0.2 * 0.2): Jolt's default frictions
  for (std::size_t w = 0; w < 3; ++w) {
    const float* rest = contacts.data() + w * 3 * Batch::kContactFloats;
    const float* slide = rest + Batch::kContactFloats;
    const float* fly = slide + Batch::kContactFloats;
    // The resting box: 4 points, normal force m g up (float rounding of the
    // impulses over 10 passes: 1e-4 relative).
    EXPECT_EQ(rest[0], 4.0f);
    EXPECT_NEAR(rest[1], 2.0f * g, 2e-3f);
    EXPECT_NEAR(rest[3], 2.0f * g, 2e-3f);
    EXPECT_NEAR(rest[6], 1.0f, 1e-6f);  // normal +Y (ground is body 1)
    // The sliding box (still sliding after 1/6 s: 4 - mu g / 6 = 3.67 m/s):
    // friction mu m g against +X, normal m g.
    EXPECT_NEAR(slide[1], g, 1e-3f);
    EXPECT_NEAR(slide[2], -mu * g, 1e-3f);
    EXPECT_NEAR(slide[4], 0.0f, 1e-4f);
    for (std::size_t i = 0; i < Batch::kContactFloats; ++i) EXPECT_EQ(fly[i], 0.0f) << i;
  }
}

// Every world of a block at its own height and speed: some lanes touch,
// some are speculative, some far away, some moving away. Each world must
// come out bit for bit as the same world stepped alone, on every target.
class ContactLanesTest : public ::testing::TestWithParam<std::int64_t> {};

TEST_P(ContactLanesTest, TouchingAndFreeWorldsShareABlockWithoutNoticing) {
  Scene scene;
  scene.AddBody(Ground());
  BodySettings box = Ball("box", {0, 2, 0});
  box.shape.type = ShapeType::kBox;
  box.shape.half_extents = {0.5f, 0.3f, 0.4f};
  box.shape.restitution = 0.5f;
  scene.AddBody(box);
  BatchOptions options;
  options.target = GetParam();
  constexpr std::size_t kWorlds = 37;
  Batch together(scene, kWorlds, options);
  std::vector<float> state(kWorlds * 2 * kStateFloatsPerBody);
  together.GetState(state);
  for (std::size_t w = 0; w < kWorlds; ++w) {
    float* body = state.data() + (w * 2 + 1) * kStateFloatsPerBody;
    body[1] = 0.25f + 0.05f * float(w);           // from 5 cm deep to far above
    body[8] = -3.0f + 0.2f * float(w % 11);        // falling fast to rising
    body[10] = 0.3f * std::sin(float(w));          // tumbling a little
    body[12] = 0.3f * std::cos(float(w));
  }
  together.SetState(state);
  for (int step = 0; step < 90; ++step) together.Step(StepSettings{});
  std::vector<float> final_state(state.size());
  together.GetState(final_state);

  for (const std::size_t w : {0u, 5u, 16u, 36u}) {
    Batch alone(scene, 1, options);
    alone.SetState(std::vector<float>(state.begin() + long(w * 2 * kStateFloatsPerBody),
                                      state.begin() + long((w + 1) * 2 * kStateFloatsPerBody)));
    for (int step = 0; step < 90; ++step) alone.Step(StepSettings{});
    std::vector<float> one(2 * kStateFloatsPerBody);
    alone.GetState(one);
    EXPECT_EQ(0, std::memcmp(one.data(), final_state.data() + w * 2 * kStateFloatsPerBody,
                             one.size() * sizeof(float)))
        << "world " << w;
    // And it rests on the ground: a box 0.3 m half-high.
    EXPECT_NEAR(one[kStateFloatsPerBody + 1], 0.3f, 0.025f) << "world " << w;
  }
}

INSTANTIATE_TEST_SUITE_P(Targets, ContactLanesTest, ::testing::ValuesIn(SupportedStepTargets()),
                         [](const auto& info) { return std::string(hwy::TargetName(info.param)); });

}  // namespace
}  // namespace manyworlds
