// LimitMassRange (include/manyworlds/mass_range.h): which bodies it raises,
// by how much, and what it leaves alone. The arithmetic is exact where the
// test says so: a factor of 10^k of float masses that are themselves powers
// of ten is rounded once (mass = floor, inertia x factor), so the inertia is
// compared within 2 float ulps (the factor's rounding and the product's).
#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "manyworlds/batch.h"
#include "manyworlds/error.h"
#include "manyworlds/mass_range.h"
#include "manyworlds/scene.h"
#include "manyworlds/scenes.h"

namespace manyworlds {
namespace {

BodySettings Body(float mass, MotionType motion = MotionType::kDynamic) {
  BodySettings body;
  body.motion_type = motion;
  body.mass = mass;
  body.inertia_diagonal = {2.0f * mass, 3.0f * mass, 5.0f * mass};
  return body;
}

PointConstraintSettings Ball(std::size_t body1, std::size_t body2) {
  PointConstraintSettings ball;
  ball.body1 = body1;
  ball.body2 = body2;
  return ball;
}

void ExpectScaled(const BodySettings& before, const BodySettings& after, float factor) {
  EXPECT_NEAR(after.mass, before.mass * factor, 2.0f * FLT_EPSILON * after.mass);
  for (int k = 0; k < 3; ++k) {
    const float expected = before.inertia_diagonal[k] * factor;
    EXPECT_NEAR(after.inertia_diagonal[k], expected, 2.0f * FLT_EPSILON * expected) << k;
  }
}

// The stress scene it was made for: 1e-3 ... 1e6 kg hanging from the ground.
// With 1e3 the seven links under 1e3 kg become 1e3 kg; the rest keep their bits.
TEST(LimitMassRange, RaisesTheLightLinksOfMassRangeHanging) {
  const Scene original = MakeStressScene("mass-range-hanging");
  Scene scene = original;
  const std::vector<MassRaise> raised = LimitMassRange(scene, 1e3f);
  ASSERT_EQ(raised.size(), 6u);  // 1e-3 ... 1e2 kg (bodies 1-6); 1e3 kg is at the floor
  const float heaviest = original.bodies().back().mass;
  for (std::size_t i = 0; i < raised.size(); ++i) {
    const std::size_t body = i + 1;
    EXPECT_EQ(raised[i].body, body);
    EXPECT_EQ(scene.bodies()[body].mass, heaviest / 1e3f);
    EXPECT_NEAR(raised[i].factor, heaviest / 1e3f / original.bodies()[body].mass,
                FLT_EPSILON * raised[i].factor);
    ExpectScaled(original.bodies()[body], scene.bodies()[body], raised[i].factor);
  }
  for (std::size_t body = 7; body < scene.bodies().size(); ++body) {
    EXPECT_EQ(scene.bodies()[body].mass, original.bodies()[body].mass) << body;
    EXPECT_EQ(scene.bodies()[body].inertia_diagonal, original.bodies()[body].inertia_diagonal);
  }
  // The static anchor (body 0) is no mass and stays as it was.
  EXPECT_EQ(scene.bodies()[0].mass, original.bodies()[0].mass);
}

TEST(LimitMassRange, AnInRangeSceneIsUnchanged) {
  for (const std::string& id : ReferenceSceneIds()) {
    SCOPED_TRACE(id);
    const Scene original = MakeScene(id);
    Scene scene = original;
    // Every reference scene spans at most 1e3 (chain16-r1000), so 1e3 changes none.
    EXPECT_TRUE(LimitMassRange(scene, 1e3f).empty());
    for (std::size_t b = 0; b < scene.bodies().size(); ++b) {
      EXPECT_EQ(scene.bodies()[b].mass, original.bodies()[b].mass);
      EXPECT_EQ(scene.bodies()[b].inertia_diagonal, original.bodies()[b].inertia_diagonal);
    }
  }
}

// Bodies joined only through a static or kinematic body are separate groups:
// each is limited against its own heaviest body, not the scene's.
TEST(LimitMassRange, StaticAndKinematicBodiesSeparateGroups) {
  Scene scene;
  scene.AddBody(Body(1.0f, MotionType::kStatic));     // 0
  scene.AddBody(Body(1e6f));                          // 1: group A
  scene.AddBody(Body(1.0f));                          // 2: group A
  scene.AddBody(Body(1.0f, MotionType::kKinematic));  // 3
  scene.AddBody(Body(10.0f));                         // 4: group B
  scene.AddBody(Body(1e-3f));                         // 5: group B
  scene.AddBody(Body(1e-3f));                         // 6: alone (on the static body)
  scene.AddConstraint(Ball(0, 1));
  scene.AddConstraint(Ball(1, 2));
  scene.AddConstraint(Ball(2, 3));
  scene.AddConstraint(Ball(3, 4));
  scene.AddConstraint(Ball(4, 5));
  scene.AddConstraint(Ball(0, 6));
  const Scene original = scene;
  const std::vector<MassRaise> raised = LimitMassRange(scene, 100.0f);
  ASSERT_EQ(raised.size(), 2u);
  EXPECT_EQ(raised[0].body, 2u);  // 1 kg -> 1e6 / 100
  EXPECT_EQ(scene.bodies()[2].mass, 1e4f);
  EXPECT_EQ(raised[1].body, 5u);  // 1e-3 kg -> 10 / 100, not 1e6 / 100
  EXPECT_EQ(scene.bodies()[5].mass, 0.1f);
  ExpectScaled(original.bodies()[5], scene.bodies()[5], raised[1].factor);
  EXPECT_EQ(scene.bodies()[6].mass, 1e-3f);  // its group is itself
  EXPECT_EQ(scene.bodies()[3].mass, 1.0f);   // kinematic: untouched
}

// Every constraint type passes impulses, so any of them joins a group: a gear
// between two hinged wheels and a distance constraint are enough.
TEST(LimitMassRange, EveryConstraintTypeJoins) {
  Scene scene;
  scene.AddBody(Body(1.0f, MotionType::kStatic));
  scene.AddBody(Body(1e4f));
  scene.AddBody(Body(1.0f));
  scene.AddBody(Body(1.0f));
  HingeConstraintSettings hinge;
  hinge.body1 = 0;
  hinge.body2 = 1;
  scene.AddConstraint(hinge);
  GearConstraintSettings gear;
  gear.body1 = 1;
  gear.body2 = 2;
  scene.AddConstraint(gear);
  DistanceConstraintSettings rope;
  rope.body1 = 2;
  rope.body2 = 3;
  scene.AddConstraint(rope);
  LimitMassRange(scene, 10.0f);
  EXPECT_EQ(scene.bodies()[2].mass, 1e3f);
  EXPECT_EQ(scene.bodies()[3].mass, 1e3f);
}

TEST(LimitMassRange, RatioOneMakesAGroupEquallyHeavy) {
  Scene scene = MakeStressScene("mass-range");
  LimitMassRange(scene, 1.0f);
  for (std::size_t b = 1; b < scene.bodies().size(); ++b) EXPECT_EQ(scene.bodies()[b].mass, 1e6f);
}

TEST(LimitMassRange, RefusesARatioBelowOneOrNotFinite) {
  for (const float ratio : {0.0f, 0.5f, -10.0f, std::numeric_limits<float>::infinity(),
                            std::numeric_limits<float>::quiet_NaN()}) {
    Scene scene = MakeStressScene("mass-range");
    const Scene original = scene;
    try {
      LimitMassRange(scene, ratio);
      ADD_FAILURE() << "accepted max_ratio " << ratio;
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("max_ratio"), std::string::npos) << e.what();
    }
    for (std::size_t b = 0; b < scene.bodies().size(); ++b) {
      EXPECT_EQ(scene.bodies()[b].mass, original.bodies()[b].mass);  // nothing half-done
    }
  }
}

// Bad bodies and indices are left for Batch, which still refuses them by name.
TEST(LimitMassRange, LeavesBadInputForTheBatchToRefuse) {
  Scene scene;
  scene.AddBody(Body(1e6f));
  scene.AddBody(Body(std::numeric_limits<float>::quiet_NaN()));
  scene.AddBody(Body(-1.0f));
  scene.AddBody(Body(1.0f));
  scene.AddConstraint(Ball(0, 1));
  scene.AddConstraint(Ball(1, 2));
  scene.AddConstraint(Ball(2, 3));
  scene.AddConstraint(Ball(3, 99));  // out of range
  const std::vector<MassRaise> raised = LimitMassRange(scene, 10.0f);
  EXPECT_TRUE(raised.empty());  // body 3 is joined to body 0 only through bad bodies
  EXPECT_TRUE(std::isnan(scene.bodies()[1].mass));
  EXPECT_EQ(scene.bodies()[2].mass, -1.0f);
  try {
    Batch batch(scene, 1);
    ADD_FAILURE() << "the batch accepted a NaN mass";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("body #1"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("mass"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace manyworlds
