// Block layout of worlds (batch/world_blocks.h), binding parts to bodies
// (batch/part_binding.h), saving and restoring part state
// (batch/part_state.h) and the SIMD-target queries (manyworlds/targets.h).
// Plain tests: none of this depends on the Highway target.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cfloat>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "batch/part_binding.h"
#include "batch/part_state.h"
#include "batch/world_blocks.h"
#include "hwy/highway.h"
#include "kernels/dual_axis.h"
#include "kernels/lane_math.h"
#include "kernels/rack_and_pinion.h"
#include "manyworlds/error.h"
#include "manyworlds/targets.h"
#include "tests/test_support.h"

namespace manyworlds::testing {
namespace {

using ::testing::AllOf;
using ::testing::Contains;
using ::testing::HasSubstr;

// Every LaneArray of a body, by name (28 floats per world: 21 of state and
// mass properties, 7 of allowed degrees of freedom).
std::vector<std::pair<const char*, const LaneArray*>> FieldsOf(const BodyLanes& b) {
  return {{"position.x", &b.position.x},
          {"position.y", &b.position.y},
          {"position.z", &b.position.z},
          {"rotation.x", &b.rotation.x},
          {"rotation.y", &b.rotation.y},
          {"rotation.z", &b.rotation.z},
          {"rotation.w", &b.rotation.w},
          {"linear_velocity.x", &b.linear_velocity.x},
          {"linear_velocity.y", &b.linear_velocity.y},
          {"linear_velocity.z", &b.linear_velocity.z},
          {"angular_velocity.x", &b.angular_velocity.x},
          {"angular_velocity.y", &b.angular_velocity.y},
          {"angular_velocity.z", &b.angular_velocity.z},
          {"inv_mass", &b.inv_mass},
          {"inv_inertia_diagonal.x", &b.inv_inertia_diagonal.x},
          {"inv_inertia_diagonal.y", &b.inv_inertia_diagonal.y},
          {"inv_inertia_diagonal.z", &b.inv_inertia_diagonal.z},
          {"inertia_rotation.x", &b.inertia_rotation.x},
          {"inertia_rotation.y", &b.inertia_rotation.y},
          {"inertia_rotation.z", &b.inertia_rotation.z},
          {"inertia_rotation.w", &b.inertia_rotation.w},
          {"dof_restricted", &b.dof_restricted}};
}
static_assert(sizeof(BodyLanes) == 22 * sizeof(LaneArray),
              "FieldsOf must list every LaneArray of BodyLanes");

// Field-by-field bit comparison of two body states, naming the field.
void ExpectSameBits(const BodyState& actual, const BodyState& expected,
                    const std::string& where) {
  auto check = [&](const char* field, const auto& a, const auto& e) {
    EXPECT_TRUE(BitEqual(&a, &e, sizeof(a))) << where << ": field " << field << " differs";
  };
  check("position", actual.position, expected.position);
  check("rotation", actual.rotation, expected.rotation);
  check("linear_velocity", actual.linear_velocity, expected.linear_velocity);
  check("angular_velocity", actual.angular_velocity, expected.angular_velocity);
  check("inv_mass", actual.inv_mass, expected.inv_mass);
  check("inv_inertia_diagonal", actual.inv_inertia_diagonal, expected.inv_inertia_diagonal);
  check("inertia_rotation", actual.inertia_rotation, expected.inertia_rotation);
}

bool IsAligned(const void* address) {
  return reinterpret_cast<std::uintptr_t>(address) % kLaneAlignment == 0;
}

// --------------------------------------------------------------- BlockCount

TEST(BlockCountTest, RoundsUpToWholeBlocks) {
  static_assert(kLaneWidth == 16);
  EXPECT_EQ(BlockCount(0), 0u);
  EXPECT_EQ(BlockCount(1), 1u);
  EXPECT_EQ(BlockCount(7), 1u);
  EXPECT_EQ(BlockCount(15), 1u);
  EXPECT_EQ(BlockCount(16), 1u);
  EXPECT_EQ(BlockCount(17), 2u);
  EXPECT_EQ(BlockCount(32), 2u);
  EXPECT_EQ(BlockCount(33), 3u);
  EXPECT_EQ(BlockCount(1000), 63u);  // 62 full blocks and 8 worlds
}

// --------------------------------------------------------------- BodyBlocks

TEST(BodyBlocksTest, InertBodyIsAtRestAtTheOriginAndImmovable) {
  const BodyState inert = InertBody();
  EXPECT_EQ(inert.position, (std::array<float, 3>{0, 0, 0}));
  EXPECT_EQ(inert.rotation, (std::array<float, 4>{0, 0, 0, 1}));
  EXPECT_EQ(inert.linear_velocity, (std::array<float, 3>{0, 0, 0}));
  EXPECT_EQ(inert.angular_velocity, (std::array<float, 3>{0, 0, 0}));
  EXPECT_EQ(inert.inv_mass, 0.0f);
  EXPECT_EQ(inert.inv_inertia_diagonal, (std::array<float, 3>{0, 0, 0}));
  EXPECT_EQ(inert.inertia_rotation, (std::array<float, 4>{0, 0, 0, 1}));
}

TEST(BodyBlocksTest, PartialBlockIsPaddedWithInertBodies) {
  BodyBlocks bodies({MotionType::kDynamic, MotionType::kStatic, MotionType::kKinematic}, 7);
  EXPECT_EQ(bodies.world_count(), 7u);
  EXPECT_EQ(bodies.block_count(), 1u);
  EXPECT_EQ(bodies.body_count(), 3u);
  EXPECT_EQ(bodies.motion_type(0), MotionType::kDynamic);
  EXPECT_EQ(bodies.motion_type(1), MotionType::kStatic);
  EXPECT_EQ(bodies.motion_type(2), MotionType::kKinematic);
  const BodyState inert = InertBody();
  // Real worlds start inert too.
  for (std::size_t body = 0; body < 3; ++body) {
    for (std::size_t world = 0; world < 7; ++world) {
      ExpectSameBits(bodies.Get(world, body), inert,
                     "initial body " + std::to_string(body) + " of world " + std::to_string(world));
    }
  }
  // Setting every real world must leave padding lanes 7..15 inert.
  Random random(17);
  for (std::size_t body = 0; body < 3; ++body) {
    for (std::size_t world = 0; world < 7; ++world) {
      bodies.Set(world, body, RandomBodyState(random));
    }
  }
  for (std::size_t body = 0; body < 3; ++body) {
    for (std::size_t lane = 7; lane < kLaneWidth; ++lane) {
      ExpectSameBits(ReadLane(bodies.lanes(0, body), lane), inert,
                     "padding lane " + std::to_string(lane) + " of body " + std::to_string(body));
    }
  }
}

TEST(BodyBlocksTest, SetGetRoundTripIsExactAndTouchesOnlyItsWorldAndBody) {
  // 40 worlds: two full blocks and a partial one; 3 bodies. Every (world,
  // body) gets a distinct random state (every field different), so a write
  // to a wrong lane, block, body or field shows.
  const std::size_t worlds = 40, body_count = 3;
  BodyBlocks bodies({MotionType::kDynamic, MotionType::kKinematic, MotionType::kStatic}, worlds);
  ASSERT_EQ(bodies.block_count(), 3u);
  Random random(23);
  std::vector<BodyState> expected(worlds * body_count);
  for (std::size_t world = 0; world < worlds; ++world) {
    for (std::size_t body = 0; body < body_count; ++body) {
      BodyState state = RandomBodyState(random);
      // Values a float round trip must keep bit for bit.
      if (world == 3) state.position[0] = -0.0f;
      if (world == 4) state.inv_mass = std::numeric_limits<float>::denorm_min();
      if (world == 5) state.linear_velocity[2] = FLT_MAX;
      if (world == 6) state.angular_velocity[1] = -std::numeric_limits<float>::infinity();
      expected[world * body_count + body] = state;
      bodies.Set(world, body, state);
    }
  }
  for (std::size_t world = 0; world < worlds; ++world) {
    for (std::size_t body = 0; body < body_count; ++body) {
      const std::string where =
          "body " + std::to_string(body) + " of world " + std::to_string(world);
      const BodyState& want = expected[world * body_count + body];
      ExpectSameBits(bodies.Get(world, body), want, where + " (Get)");
      // The layout: world w is lane w % 16 of block w / 16.
      ExpectSameBits(ReadLane(bodies.lanes(world / kLaneWidth, body), world % kLaneWidth),
                     want, where + " (lane of its block)");
    }
  }
}

TEST(BodyBlocksTest, WriteLaneReadLaneRoundTripEveryLane) {
  BodyLanes lanes{};
  Random random(29);
  std::vector<BodyState> states;
  for (std::size_t lane = 0; lane < kLaneWidth; ++lane) {
    states.push_back(RandomBodyState(random));
    WriteLane(lanes, lane, states.back());
  }
  for (std::size_t lane = 0; lane < kLaneWidth; ++lane) {
    ExpectSameBits(ReadLane(lanes, lane), states[lane], "lane " + std::to_string(lane));
  }
}

// Calls f, expects std::out_of_range and returns its message.
template <class F>
std::string OutOfRangeMessage(F f) {
  try {
    f();
  } catch (const std::out_of_range& e) {
    return e.what();
  }
  ADD_FAILURE() << "no std::out_of_range thrown";
  return "";
}

TEST(BodyBlocksTest, OutOfRangeWorldOrBodyThrowsNamingTheIndex) {
  BodyBlocks bodies({MotionType::kDynamic, MotionType::kDynamic, MotionType::kStatic}, 7);
  const BodyState state = InertBody();
  // World 7 is a padding lane of block 0: in storage, but not a real world.
  EXPECT_THAT(OutOfRangeMessage([&] { bodies.Get(7, 0); }),
              AllOf(HasSubstr("world 7"), HasSubstr("7 worlds")));
  EXPECT_THAT(OutOfRangeMessage([&] { bodies.Set(7, 0, state); }), HasSubstr("world 7"));
  EXPECT_THAT(OutOfRangeMessage([&] { bodies.Get(1234, 1); }), HasSubstr("world 1234"));
  EXPECT_THAT(OutOfRangeMessage([&] { bodies.Set(99, 2, state); }), HasSubstr("world 99"));
  EXPECT_THAT(OutOfRangeMessage([&] { bodies.Get(0, 3); }),
              AllOf(HasSubstr("body 3"), HasSubstr("3 bodies")));
  EXPECT_THAT(OutOfRangeMessage([&] { bodies.Set(6, 5, state); }), HasSubstr("body 5"));
  // In range: no throw.
  EXPECT_NO_THROW(bodies.Get(6, 2));
  EXPECT_NO_THROW(bodies.Set(6, 2, state));
}

TEST(BodyBlocksTest, EveryLaneArrayIsAlignedToTheLaneAlignment) {
  static_assert(kLaneAlignment == 64);
  static_assert(alignof(LaneArray) == kLaneAlignment);
  BodyBlocks bodies({MotionType::kDynamic, MotionType::kStatic, MotionType::kKinematic}, 1000);
  for (std::size_t block = 0; block < bodies.block_count(); ++block) {
    for (std::size_t body = 0; body < bodies.body_count(); ++body) {
      for (const auto& [name, field] : FieldsOf(bodies.lanes(block, body))) {
        EXPECT_TRUE(IsAligned(field)) << name << " of body " << body << " in block " << block
                                      << " at " << static_cast<const void*>(field);
      }
    }
  }
}

TEST(PartBlocksTest, EveryBlockIsAlignedAndZeroInitialised) {
  PartBlocks<DualAxisLanes> dual_axis(5);
  PartBlocks<RackAndPinionLanes> rack(5);
  PartBlocks<DualAxisGeometry> geometry(5);
  PartBlocks<LaneArray> errors(5);
  for (std::size_t block = 0; block < 5; ++block) {
    EXPECT_TRUE(IsAligned(&dual_axis[block])) << "dual-axis block " << block;
    EXPECT_TRUE(IsAligned(&dual_axis[block].persistent.total_lambda.y)) << "block " << block;
    EXPECT_TRUE(IsAligned(&rack[block])) << "rack-and-pinion block " << block;
    EXPECT_TRUE(IsAligned(&rack[block].persistent.total_lambda)) << "block " << block;
    EXPECT_TRUE(IsAligned(&geometry[block])) << "geometry block " << block;
    EXPECT_TRUE(IsAligned(&errors[block])) << "error block " << block;
    for (std::size_t lane = 0; lane < kLaneWidth; ++lane) {
      EXPECT_EQ(dual_axis[block].persistent.total_lambda.x[lane], 0.0f);
      EXPECT_EQ(dual_axis[block].effective_mass.yy[lane], 0.0f);
      EXPECT_EQ(rack[block].persistent.total_lambda[lane], 0.0f);
      EXPECT_EQ(geometry[block].n2.z[lane], 0.0f);
      EXPECT_EQ(errors[block][lane], 0.0f);
    }
  }
}

// ---------------------------------------------------------------- BindPart

// Calls f, expects SceneError and returns its message.
template <class F>
std::string SceneErrorMessage(F f) {
  try {
    f();
  } catch (const SceneError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no SceneError thrown";
  return "";
}

TEST(BindPartTest, RackAndPinionRefusesAStaticPinionOrRack) {
  // Bodies: 0 dynamic, 1 kinematic, 2 static, 3 dynamic, 4 static.
  const BodyBlocks bodies({MotionType::kDynamic, MotionType::kKinematic, MotionType::kStatic,
                           MotionType::kDynamic, MotionType::kStatic},
                          3);
  EXPECT_THAT(SceneErrorMessage([&] {
                BindPart(bodies, "steering_rack", PartKind::kRackAndPinion, 4, 3);
              }),
              AllOf(HasSubstr("steering_rack"), HasSubstr("body1"), HasSubstr("body 4"),
                    HasSubstr("static")));
  EXPECT_THAT(SceneErrorMessage([&] {
                BindPart(bodies, "lift_gear", PartKind::kRackAndPinion, 1, 2);
              }),
              AllOf(HasSubstr("lift_gear"), HasSubstr("body2"), HasSubstr("body 2"),
                    HasSubstr("static")));
  // Both static: refused too (the first one is named).
  EXPECT_THAT(SceneErrorMessage([&] {
                BindPart(bodies, "both_static", PartKind::kRackAndPinion, 2, 4);
              }),
              AllOf(HasSubstr("both_static"), HasSubstr("static")));
}

TEST(BindPartTest, DualAxisAcceptsStaticBodies) {
  const BodyBlocks bodies(
      {MotionType::kStatic, MotionType::kDynamic, MotionType::kKinematic, MotionType::kStatic}, 3);
  for (const auto& [body1, body2] : std::vector<std::pair<std::size_t, std::size_t>>{
           {0, 1}, {1, 0}, {2, 3}, {3, 2}}) {
    PartBinding binding;
    ASSERT_NO_THROW(binding = BindPart(bodies, "slider", PartKind::kDualAxis, body1, body2))
        << "bodies " << body1 << ", " << body2;
    EXPECT_EQ(binding.constraint_name, "slider");
    EXPECT_EQ(binding.kind, PartKind::kDualAxis);
    EXPECT_EQ(binding.body1, body1);
    EXPECT_EQ(binding.body2, body2);
  }
}

TEST(BindPartTest, BothPartsAcceptKinematicBodies) {
  const BodyBlocks bodies({MotionType::kKinematic, MotionType::kKinematic, MotionType::kDynamic}, 3);
  for (const PartKind kind : {PartKind::kDualAxis, PartKind::kRackAndPinion}) {
    for (const auto& [body1, body2] : std::vector<std::pair<std::size_t, std::size_t>>{
             {0, 1}, {0, 2}, {2, 1}}) {
      PartBinding binding;
      ASSERT_NO_THROW(binding = BindPart(bodies, "gear", kind, body1, body2))
          << PartKindName(kind) << ", bodies " << body1 << ", " << body2;
      EXPECT_EQ(binding.kind, kind);
      EXPECT_EQ(binding.body1, body1);
      EXPECT_EQ(binding.body2, body2);
    }
  }
}

TEST(BindPartTest, MissingBodyOrTheSameBodyTwiceIsRefusedNamingTheField) {
  const BodyBlocks bodies({MotionType::kDynamic, MotionType::kDynamic, MotionType::kDynamic}, 3);
  for (const PartKind kind : {PartKind::kDualAxis, PartKind::kRackAndPinion}) {
    SCOPED_TRACE(PartKindName(kind));
    EXPECT_THAT(SceneErrorMessage([&] { BindPart(bodies, "hinge_a", kind, 3, 0); }),
                AllOf(HasSubstr("hinge_a"), HasSubstr("body1 = 3"), HasSubstr("3 bodies")));
    EXPECT_THAT(SceneErrorMessage([&] { BindPart(bodies, "hinge_b", kind, 1, 17); }),
                AllOf(HasSubstr("hinge_b"), HasSubstr("body2 = 17")));
    EXPECT_THAT(SceneErrorMessage([&] { BindPart(bodies, "hinge_c", kind, 2, 2); }),
                AllOf(HasSubstr("hinge_c"), HasSubstr("body1"), HasSubstr("body2"),
                      HasSubstr("body 2")));
  }
}

// ------------------------------------------------------------- part state

TEST(PartStateTest, SaveRestoreRoundTripIsBitExact) {
  const std::size_t worlds = 40;  // 3 blocks, the last partial
  PartBlocks<DualAxisLanes> dual_axis(BlockCount(worlds));
  PartBlocks<RackAndPinionLanes> rack(BlockCount(worlds));
  Random random(31);
  auto value = [&](std::size_t world) {
    // A few values whose bits a sloppy copy could change.
    if (world == 1) return -0.0f;
    if (world == 2) return std::numeric_limits<float>::denorm_min();
    if (world == 3) return std::numeric_limits<float>::quiet_NaN();
    return float(random.Uniform(-10, 10));
  };
  for (std::size_t world = 0; world < worlds; ++world) {
    SetTotalLambda(dual_axis, world, {value(world), value(world + 5)});
    SetTotalLambda(rack, world, value(world));
  }
  // Set/Get address the lane of the world's block.
  for (std::size_t world = 0; world < worlds; ++world) {
    const auto l = GetTotalLambda(dual_axis, world);
    const Vec2Lanes& lanes = dual_axis[world / kLaneWidth].persistent.total_lambda;
    EXPECT_TRUE(BitEqual(&l[0], &lanes.x.lanes[world % kLaneWidth], sizeof(float))) << "world " << world;
    EXPECT_TRUE(BitEqual(&l[1], &lanes.y.lanes[world % kLaneWidth], sizeof(float))) << "world " << world;
  }
  const auto saved_dual_axis = SavePartState(dual_axis);
  const auto saved_rack = SavePartState(rack);
  ASSERT_EQ(saved_dual_axis.size(), dual_axis.block_count());
  ASSERT_EQ(saved_rack.size(), rack.block_count());
  // Remember the values at save time, then overwrite every lane of every block.
  std::vector<std::array<float, 2>> dual_axis_at_save;
  std::vector<float> rack_at_save;
  for (std::size_t world = 0; world < worlds; ++world) {
    dual_axis_at_save.push_back(GetTotalLambda(dual_axis, world));
    rack_at_save.push_back(GetTotalLambda(rack, world));
  }
  for (std::size_t block = 0; block < dual_axis.block_count(); ++block) {
    for (std::size_t lane = 0; lane < kLaneWidth; ++lane) {
      dual_axis[block].persistent.total_lambda.x[lane] = 1234.5f;
      dual_axis[block].persistent.total_lambda.y[lane] = -1234.5f;
      rack[block].persistent.total_lambda[lane] = 777.0f;
    }
  }
  RestorePartState(dual_axis, saved_dual_axis);
  RestorePartState(rack, saved_rack);
  for (std::size_t world = 0; world < worlds; ++world) {
    const auto d = GetTotalLambda(dual_axis, world);
    const float r = GetTotalLambda(rack, world);
    EXPECT_TRUE(BitEqual(&d, &dual_axis_at_save[world], sizeof(d)))
        << "dual-axis impulse of world " << world;
    EXPECT_TRUE(BitEqual(&r, &rack_at_save[world], sizeof(r)))
        << "rack-and-pinion impulse of world " << world;
  }
}

TEST(PartStateTest, RestoreWithWrongBlockCountThrowsAndChangesNothing) {
  PartBlocks<DualAxisLanes> dual_axis(3);
  PartBlocks<RackAndPinionLanes> rack(3);
  SetTotalLambda(dual_axis, 20, {1.5f, -2.5f});
  SetTotalLambda(rack, 20, 3.5f);
  const PartBlocks<DualAxisLanes> two_blocks(2);
  const auto saved_dual_axis = SavePartState(two_blocks);
  const std::vector<RackAndPinionLanes::Persistent> saved_rack(4);
  try {
    RestorePartState(dual_axis, saved_dual_axis);
    ADD_FAILURE() << "restoring 2 saved blocks into 3 did not throw";
  } catch (const std::invalid_argument& e) {
    EXPECT_THAT(e.what(), AllOf(HasSubstr("2"), HasSubstr("3")));
  }
  EXPECT_THROW(RestorePartState(rack, saved_rack), std::invalid_argument);
  EXPECT_THROW(RestorePartState(rack, {}), std::invalid_argument);
  EXPECT_EQ(GetTotalLambda(dual_axis, 20), (std::array<float, 2>{1.5f, -2.5f}));
  EXPECT_EQ(GetTotalLambda(rack, 20), 3.5f);
}

// ----------------------------------------------------------------- targets

#if HWY_ARCH_X86
TEST(TargetsTest, X86BuildCompilesAvx3Avx2Sse4AndScalar) {
  const std::vector<std::string> compiled = CompiledTargetNames();
  EXPECT_THAT(compiled, Contains("AVX3"));
  EXPECT_THAT(compiled, Contains("AVX2"));
  EXPECT_THAT(compiled, Contains("SSE4"));
  EXPECT_THAT(compiled, Contains("SCALAR"));
}
#endif

TEST(TargetsTest, SupportedTargetsIncludeScalarAndTheDispatchedOne) {
  const std::vector<std::string> supported = SupportedTargetNames();
  const std::vector<std::string> compiled = CompiledTargetNames();
  EXPECT_THAT(supported, Contains("SCALAR"));
  EXPECT_THAT(supported, Contains(DispatchedTargetName()));
  for (const std::string& name : supported) {
    EXPECT_THAT(compiled, Contains(name)) << name << " is supported but not compiled";
  }
}

TEST(TargetsTest, DispatchedTableIsTheBestSupportedOne) {
  const auto& supported = SupportedKernels<LaneMathKernels>();
  ASSERT_FALSE(supported.empty());
  const LaneMathKernels& dispatched = DispatchedKernels<LaneMathKernels>();
  EXPECT_EQ(&dispatched, supported.front())
      << "dispatched " << dispatched.target.name << ", best supported "
      << supported.front()->target.name;
  EXPECT_EQ(DispatchedTargetName(), supported.front()->target.name);
  EXPECT_EQ(DispatchedVectorLanes(), supported.front()->target.vector_lanes);
  // Best first: Highway's target bits grow as targets get worse.
  for (std::size_t i = 1; i < supported.size(); ++i) {
    EXPECT_LT(supported[i - 1]->target.bits, supported[i]->target.bits)
        << supported[i - 1]->target.name << " before " << supported[i]->target.name;
  }
  // Every part's tables cover the same targets in the same order.
  const auto& dual_axis = SupportedKernels<DualAxisKernels>();
  const auto& rack_and_pinion = SupportedKernels<RackAndPinionKernels>();
  ASSERT_EQ(dual_axis.size(), supported.size());
  ASSERT_EQ(rack_and_pinion.size(), supported.size());
  for (std::size_t i = 0; i < supported.size(); ++i) {
    EXPECT_EQ(dual_axis[i]->target.bits, supported[i]->target.bits);
    EXPECT_EQ(rack_and_pinion[i]->target.bits, supported[i]->target.bits);
  }
}

TEST(TargetsTest, KernelsForTargetFindsEverySupportedTableAndScalar) {
  for (const LaneMathKernels* table : SupportedKernels<LaneMathKernels>()) {
    EXPECT_EQ(KernelsForTarget<LaneMathKernels>(table->target.bits), table) << table->target.name;
    // A chunk never exceeds a block and blocks are whole chunks.
    EXPECT_GE(table->target.vector_lanes, 1u) << table->target.name;
    EXPECT_LE(table->target.vector_lanes, kLaneWidth) << table->target.name;
    EXPECT_EQ(kLaneWidth % table->target.vector_lanes, 0u) << table->target.name;
  }
  const LaneMathKernels* scalar = KernelsForTarget<LaneMathKernels>(HWY_SCALAR);
  ASSERT_NE(scalar, nullptr) << "no kernel table for HWY_SCALAR";
  EXPECT_EQ(scalar->target.vector_lanes, 1u);
  EXPECT_STREQ(scalar->target.name, "SCALAR");
  EXPECT_EQ(KernelsForTarget<LaneMathKernels>(0), nullptr);
}

}  // namespace
}  // namespace manyworlds::testing
