// LimitMassRange (include/manyworlds/mass_range.h): which bodies it raises,
// by how much, and what it leaves alone. A raised body's mass is the floor
// itself (heaviest / max_ratio, one float division); its inertia is the old
// inertia times the factor floor / mass (in double), rounded once to float,
// so both are compared with the same product in double within FLT_EPSILON
// relative (a rounding to float is at most half of that).
#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
#include <variant>
#include <vector>

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

void ExpectScaled(const BodySettings& before, const BodySettings& after, double factor) {
  const double mass = double(before.mass) * factor;
  EXPECT_NEAR(after.mass, mass, FLT_EPSILON * mass);
  for (int k = 0; k < 3; ++k) {
    const double expected = double(before.inertia_diagonal[k]) * factor;
    EXPECT_NEAR(after.inertia_diagonal[k], expected, FLT_EPSILON * expected) << k;
  }
}

// The stress scene it was made for: 1e-3 ... 1e6 kg hanging from the ground.
// With 1e3 the six links under 1e3 kg become 1e3 kg; the rest keep their bits.
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
    EXPECT_DOUBLE_EQ(raised[i].factor,
                     double(heaviest / 1e3f) / double(original.bodies()[body].mass));
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

// Every constraint type passes impulses, so each of them joins its two bodies
// (only body1 and body2 are read: a gear's hinges need not exist here).
template <std::size_t... kTypes>
std::vector<bool> EachTypeJoins(std::index_sequence<kTypes...>) {
  const auto joins = [](auto settings) {
    Scene scene;
    scene.AddBody(Body(1e4f));
    scene.AddBody(Body(1.0f));
    settings.body1 = 0;
    settings.body2 = 1;
    scene.AddConstraint(settings);
    const std::vector<MassRaise> raised = LimitMassRange(scene, 10.0f);
    return raised.size() == 1 && raised[0].body == 1 && scene.bodies()[1].mass == 1e3f;
  };
  return {joins(std::variant_alternative_t<kTypes, ConstraintSettings>{})...};
}
TEST(LimitMassRange, EveryConstraintTypeJoins) {
  const std::vector<bool> joined =
      EachTypeJoins(std::make_index_sequence<std::variant_size_v<ConstraintSettings>>{});
  ASSERT_EQ(joined.size(), 12u);  // every type of scene.h
  for (std::size_t type = 0; type < joined.size(); ++type) {
    EXPECT_TRUE(joined[type]) << "alternative " << type << " of ConstraintSettings";
  }
}

// A dynamic body locked in every translation has inverse mass 0: to its
// joints it is the ground. It neither sets its neighbours' floor nor joins
// them; a rotation-only flywheel of 1e6 kg leaves the 1 kg arm on it alone.
TEST(LimitMassRange, ATranslationLockedBodyIsGround) {
  Scene scene;
  BodySettings flywheel = Body(1e6f);
  flywheel.allowed_dofs = AllowedDofs::kRotationZ;
  scene.AddBody(flywheel);
  scene.AddBody(Body(1.0f));
  scene.AddBody(Body(1e-3f));
  scene.AddConstraint(Ball(0, 1));
  scene.AddConstraint(Ball(0, 2));
  EXPECT_TRUE(LimitMassRange(scene, 100.0f).empty());  // 1 and 1e-3 kg: separate groups
  EXPECT_EQ(scene.bodies()[0].mass, 1e6f);
  scene.AddConstraint(Ball(1, 2));  // now one group of 1 kg and 1e-3 kg
  const std::vector<MassRaise> raised = LimitMassRange(scene, 100.0f);
  ASSERT_EQ(raised.size(), 1u);
  EXPECT_EQ(raised[0].body, 2u);
  EXPECT_EQ(scene.bodies()[2].mass, 0.01f);
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
