// Padding lanes never change real worlds, for both parts on every Highway
// target this CPU supports: 7 real worlds (dynamic-dynamic, random inputs)
// run calculate_properties, warm_start(0.9), solve_velocity x3,
// calculate_properties, solve_position(0.2) in one block
//   (a) with the 9 padding lanes inert (InertBody(), zero geometry and state),
//   (b) with garbage (NaN, +-Inf, +-1e30, FLT_MAX, denormals, -0, random) in
//       every padding lane of every input field: both bodies (but for lane 0
//       of the scene's DOF flag, FillBodyPaddingWithGarbage), the geometry,
//       the separation / position error and the whole part state,
//   (c) with the 7 worlds in reversed lane order (lanes 15..9, so they cross
//       the chunk boundaries of every target), padding inert,
//   (d) reversed and garbage together.
// Bodies and accumulated impulses of the 7 real worlds must be bit-identical
// (memcmp) in all four runs.
#include <gtest/gtest.h>

#include <array>
#include <cfloat>
#include <cmath>
#include <cstring>
#include <limits>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

#include "batch/part_binding.h"
#include "batch/world_blocks.h"
#include "kernels/dual_axis.h"
#include "kernels/dual_axis.h"
#include "kernels/lane_math.h"
#include "kernels/rack_and_pinion.h"
#include "kernels/rack_and_pinion.h"
#include "tests/test_support.h"

namespace manyworlds::testing {
namespace {

constexpr std::size_t kRealWorlds = 7;

struct Layout {
  const char* name;
  bool garbage;   // padding lanes hold garbage instead of inert worlds
  bool reversed;  // world w in lane 15 - w instead of lane w
};
constexpr Layout kBaseline = {"inert padding", false, false};  // (a)
constexpr Layout kOtherLayouts[] = {
    {"garbage padding", true, false},                  // (b)
    {"reversed lane order", false, true},              // (c)
    {"reversed lane order, garbage padding", true, true},  // (d)
};

std::size_t LaneOf(std::size_t world, const Layout& layout) {
  return layout.reversed ? kLaneWidth - 1 - world : world;
}

std::array<bool, kLaneWidth> RealLanes(const Layout& layout) {
  std::array<bool, kLaneWidth> real{};
  for (std::size_t w = 0; w < kRealWorlds; ++w) real[LaneOf(w, layout)] = true;
  return real;
}

// Every field of these structs is a LaneArray (no padding bytes), so lane
// `lane` of field f is the float at byte f * sizeof(LaneArray) + 4 * lane.
static_assert(sizeof(BodyLanes) == 22 * sizeof(LaneArray));
static_assert(sizeof(DualAxisGeometry) == 12 * sizeof(LaneArray));
static_assert(sizeof(DualAxisLanes) == 29 * sizeof(LaneArray));
static_assert(sizeof(RackAndPinionGeometry) == 7 * sizeof(LaneArray));
static_assert(sizeof(RackAndPinionLanes) == 8 * sizeof(LaneArray));
static_assert(sizeof(Vec3Lanes) == 3 * sizeof(LaneArray));

// Fills every lane that holds no real world, in every LaneArray of `lanes`,
// with garbage. Each field's 9 padding lanes get all 9 kinds of value below
// (rotated per field, so fields see them in different lanes).
template <class LaneStruct>
void FillPaddingWithGarbage(LaneStruct& lanes, const std::array<bool, kLaneWidth>& real,
                            Random& random) {
  static_assert(std::is_trivially_copyable_v<LaneStruct>);
  static_assert(sizeof(LaneStruct) % sizeof(LaneArray) == 0);
  constexpr std::size_t kFields = sizeof(LaneStruct) / sizeof(LaneArray);
  unsigned char* bytes = reinterpret_cast<unsigned char*>(&lanes);
  std::size_t padding_index = 0;
  for (std::size_t field = 0; field < kFields; ++field) {
    for (std::size_t lane = 0; lane < kLaneWidth; ++lane) {
      if (real[lane]) continue;
      float value = 0;
      switch ((field + padding_index++) % 9) {
        case 0: value = std::numeric_limits<float>::quiet_NaN(); break;
        case 1: value = std::numeric_limits<float>::infinity(); break;
        case 2: value = -std::numeric_limits<float>::infinity(); break;
        case 3: value = 1e30f; break;
        case 4: value = -1e30f; break;
        case 5: value = FLT_MAX; break;
        case 6: value = std::numeric_limits<float>::denorm_min(); break;
        case 7: value = -0.0f; break;
        case 8: value = float(random.Uniform(-1e3, 1e3)); break;
      }
      std::memcpy(bytes + field * sizeof(LaneArray) + lane * sizeof(float), &value,
                  sizeof(float));
    }
  }
}

// A body's padding lanes with garbage, except lane 0 of dof_restricted: that
// flag is the scene body's, the same in every world, and the kernels read it
// from lane 0 (body_access-inl.h), which in a batch is always a real world
// (world 16 b of block b). Only a restricted body stores locks after its
// lanes (BodyLockLanes), so a flag set by garbage would read past these
// unrestricted test bodies; garbage in its other padding lanes stays.
void FillBodyPaddingWithGarbage(BodyLanes& lanes, const std::array<bool, kLaneWidth>& real,
                                Random& random) {
  FillPaddingWithGarbage(lanes, real, random);
  lanes.dof_restricted[0] = 0.0f;
}

// The garbage really lands in every padding lane of every field, and only
// there (else the bit-identity tests below would prove less than they claim).
TEST(PaddingGarbageTest, FillsEveryPaddingLaneOfEveryFieldAndNoRealLane) {
  for (const bool reversed : {false, true}) {
    const Layout layout = {"", true, reversed};
    const std::array<bool, kLaneWidth> real = RealLanes(layout);
    DualAxisLanes lanes{};  // zero: every bit pattern below is non-zero
    Random random(7);
    FillPaddingWithGarbage(lanes, real, random);
    const std::size_t fields = sizeof(DualAxisLanes) / sizeof(LaneArray);
    const unsigned char* bytes = reinterpret_cast<const unsigned char*>(&lanes);
    for (std::size_t field = 0; field < fields; ++field) {
      int nan = 0, plus_inf = 0, minus_inf = 0;
      for (std::size_t lane = 0; lane < kLaneWidth; ++lane) {
        float value;
        std::memcpy(&value, bytes + field * sizeof(LaneArray) + lane * sizeof(float),
                    sizeof(float));
        const float zero = 0.0f;
        const bool is_zero_bits = BitEqual(&value, &zero, sizeof(float));
        EXPECT_EQ(is_zero_bits, real[lane]) << "field " << field << ", lane " << lane;
        nan += std::isnan(value);
        plus_inf += value == std::numeric_limits<float>::infinity();
        minus_inf += value == -std::numeric_limits<float>::infinity();
      }
      EXPECT_EQ(nan, 1) << "field " << field;
      EXPECT_EQ(plus_inf, 1) << "field " << field;
      EXPECT_EQ(minus_inf, 1) << "field " << field;
    }
  }
}

// What a run leaves in one real world.
struct WorldResult {
  BodyState body1, body2;
  std::vector<float> lambda;
};

template <std::size_t N>
std::string Format(const std::array<float, N>& values) {
  std::ostringstream out;
  out.precision(9);
  out << "(";
  for (std::size_t i = 0; i < N; ++i) out << (i ? ", " : "") << values[i];
  return out.str() + ")";
}

// Field-by-field memcmp of one body, naming the world, body and field.
void ExpectBodyBitIdentical(const BodyState& actual, const BodyState& expected,
                            const std::string& where) {
  auto check = [&](const char* field, const auto& a, const auto& e) {
    EXPECT_TRUE(BitEqual(&a, &e, sizeof(a)))
        << where << ", " << field << ": " << Format(a) << " vs " << Format(e)
        << " with inert padding";
  };
  check("position", actual.position, expected.position);
  check("rotation", actual.rotation, expected.rotation);
  check("linear velocity", actual.linear_velocity, expected.linear_velocity);
  check("angular velocity", actual.angular_velocity, expected.angular_velocity);
  check("inverse mass", std::array<float, 1>{actual.inv_mass},
        std::array<float, 1>{expected.inv_mass});
  check("inverse inertia diagonal", actual.inv_inertia_diagonal,
        expected.inv_inertia_diagonal);
  check("inertia rotation", actual.inertia_rotation, expected.inertia_rotation);
}

void ExpectSameRealWorlds(const std::vector<WorldResult>& actual,
                          const std::vector<WorldResult>& baseline, const char* part,
                          const Layout& layout) {
  ASSERT_EQ(actual.size(), kRealWorlds);
  for (std::size_t w = 0; w < kRealWorlds; ++w) {
    const std::string where = std::string(part) + " with " + layout.name + ", world " +
                              std::to_string(w) + " (lane " +
                              std::to_string(LaneOf(w, layout)) + ")";
    ExpectBodyBitIdentical(actual[w].body1, baseline[w].body1, where + ", body 1");
    ExpectBodyBitIdentical(actual[w].body2, baseline[w].body2, where + ", body 2");
    ASSERT_EQ(actual[w].lambda.size(), baseline[w].lambda.size());
    for (std::size_t i = 0; i < actual[w].lambda.size(); ++i) {
      EXPECT_TRUE(BitEqual(&actual[w].lambda[i], &baseline[w].lambda[i], sizeof(float)))
          << where << ", accumulated impulse " << i << ": " << actual[w].lambda[i] << " vs "
          << baseline[w].lambda[i] << " with inert padding";
    }
  }
}

bool AllFinite(const BodyState& s) {
  static_assert(sizeof(BodyState) == 21 * sizeof(float));
  float values[21];
  std::memcpy(values, &s, sizeof(values));
  for (const float v : values) {
    if (!std::isfinite(v)) return false;
  }
  return true;
}

template <std::size_t N>
bool Changed(const std::array<float, N>& after, const std::array<float, N>& before) {
  return !BitEqual(&after, &before, sizeof(after));
}

// Parametrised by target (through the lane-maths table, which exists for
// every target); each part's table for that target is looked up.
class PaddingTest : public ::testing::TestWithParam<const LaneMathKernels*> {
 protected:
  template <class Table>
  const Table& Kernels() const {
    const Table* table = KernelsForTarget<Table>(GetParam()->target.bits);
    EXPECT_NE(table, nullptr) << GetParam()->target.name;
    return *table;
  }
};

// ------------------------------------------------------------------ dual axis

struct DualAxisWorld {
  BodyState body1, body2;
  Vec3d r1_plus_u, r2, n1, n2, separation;
  float lambda[2];
};

DualAxisWorld DualAxisInputs(std::size_t world) {
  Random random(5551u + 7919u * unsigned(world));
  DualAxisWorld in;
  in.body1 = RandomBodyState(random);
  in.body2 = RandomBodyState(random);
  in.r1_plus_u = random.Vector(2.0);
  in.r2 = random.Vector(2.0);
  in.n1 = random.UnitVector();
  in.n2 = random.Perpendicular(in.n1);
  // Separation along both axes (C != 0 in both rows) plus an off-axis part.
  in.separation = random.Uniform(0.05, 0.2) * in.n1 - random.Uniform(0.05, 0.2) * in.n2 +
                  random.Vector(0.05);
  in.lambda[0] = float(random.Uniform(-1, 1));
  in.lambda[1] = float(random.Uniform(-1, 1));
  return in;
}

std::vector<WorldResult> RunDualAxis(const DualAxisKernels& kernels, const Layout& layout) {
  BodyBlocks bodies({MotionType::kDynamic, MotionType::kDynamic}, kRealWorlds);
  const PartBinding binding =
      BindPart(bodies, "padding_slider", PartKind::kDualAxis, 0, 1);
  PartBlocks<DualAxisGeometry> geometry(1);
  PartBlocks<DualAxisLanes> parts(1);
  PartBlocks<Vec3Lanes> separation(1);
  for (std::size_t w = 0; w < kRealWorlds; ++w) {
    const DualAxisWorld in = DualAxisInputs(w);
    const std::size_t lane = LaneOf(w, layout);
    WriteLane(bodies.lanes(0, 0), lane, in.body1);
    WriteLane(bodies.lanes(0, 1), lane, in.body2);
    SetLaneVec3(geometry[0].r1_plus_u, lane, in.r1_plus_u);
    SetLaneVec3(geometry[0].r2, lane, in.r2);
    SetLaneVec3(geometry[0].n1, lane, in.n1);
    SetLaneVec3(geometry[0].n2, lane, in.n2);
    SetLaneVec3(separation[0], lane, in.separation);
    parts[0].persistent.total_lambda.x[lane] = in.lambda[0];
    parts[0].persistent.total_lambda.y[lane] = in.lambda[1];
  }
  if (layout.garbage) {
    const std::array<bool, kLaneWidth> real = RealLanes(layout);
    Random random(99);
    FillBodyPaddingWithGarbage(bodies.lanes(0, 0), real, random);
    FillBodyPaddingWithGarbage(bodies.lanes(0, 1), real, random);
    FillPaddingWithGarbage(geometry[0], real, random);
    FillPaddingWithGarbage(parts[0], real, random);
    FillPaddingWithGarbage(separation[0], real, random);
  }
  const BodyPair pair = PairInBlock(bodies, binding, 0);
  kernels.calculate_properties(pair, geometry[0], parts[0]);
  kernels.warm_start(pair, geometry[0], parts[0], 0.9f);
  for (int i = 0; i < 3; ++i) kernels.solve_velocity(pair, geometry[0], parts[0]);
  kernels.calculate_properties(pair, geometry[0], parts[0]);
  kernels.solve_position(pair, geometry[0], separation[0], parts[0], 0.2f);

  std::vector<WorldResult> results;
  for (std::size_t w = 0; w < kRealWorlds; ++w) {
    const std::size_t lane = LaneOf(w, layout);
    results.push_back({ReadLane(bodies.lanes(0, 0), lane), ReadLane(bodies.lanes(0, 1), lane),
                       {parts[0].persistent.total_lambda.x[lane],
                        parts[0].persistent.total_lambda.y[lane]}});
  }
  return results;
}

TEST_P(PaddingTest, DualAxisRealWorldsIgnorePaddingLanes) {
  const std::vector<WorldResult> baseline = RunDualAxis(Kernels<DualAxisKernels>(), kBaseline);
  // The sequence must really act on every world, or bit-identity proves nothing.
  for (std::size_t w = 0; w < kRealWorlds; ++w) {
    const DualAxisWorld in = DualAxisInputs(w);
    const WorldResult& out = baseline[w];
    const std::string where = "dual axis, world " + std::to_string(w);
    EXPECT_TRUE(AllFinite(out.body1) && AllFinite(out.body2)) << where;
    EXPECT_TRUE(Changed(out.body1.linear_velocity, in.body1.linear_velocity)) << where;
    EXPECT_TRUE(Changed(out.body1.angular_velocity, in.body1.angular_velocity)) << where;
    EXPECT_TRUE(Changed(out.body1.position, in.body1.position)) << where;
    EXPECT_TRUE(Changed(out.body2.linear_velocity, in.body2.linear_velocity)) << where;
    EXPECT_TRUE(Changed(out.body2.angular_velocity, in.body2.angular_velocity)) << where;
    EXPECT_TRUE(Changed(out.body2.position, in.body2.position)) << where;
    EXPECT_TRUE(std::isfinite(out.lambda[0]) && out.lambda[0] != 0.0f) << where;
    EXPECT_TRUE(std::isfinite(out.lambda[1]) && out.lambda[1] != 0.0f) << where;
  }
  for (const Layout& layout : kOtherLayouts) {
    ExpectSameRealWorlds(RunDualAxis(Kernels<DualAxisKernels>(), layout), baseline, "dual axis", layout);
  }
}

// ------------------------------------------------------------ rack and pinion

struct RackAndPinionWorld {
  BodyState pinion, rack;
  Vec3d hinge_axis, slider_axis;
  float ratio, error, lambda;
};

RackAndPinionWorld RackAndPinionInputs(std::size_t world) {
  Random random(6661u + 104729u * unsigned(world));
  RackAndPinionWorld in;
  in.pinion = RandomBodyState(random);
  in.rack = RandomBodyState(random);
  in.hinge_axis = random.UnitVector();
  in.slider_axis = random.UnitVector();
  in.ratio = float((random.Uniform(0, 1) < 0.5 ? -1 : 1) * random.LogUniform(0.1, 10.0));
  in.error = float((random.Uniform(0, 1) < 0.5 ? -1 : 1) * random.Uniform(0.05, 0.3));
  in.lambda = float(random.Uniform(-1, 1));
  return in;
}

std::vector<WorldResult> RunRackAndPinion(const RackAndPinionKernels& kernels, const Layout& layout) {
  BodyBlocks bodies({MotionType::kDynamic, MotionType::kDynamic}, kRealWorlds);
  const PartBinding binding =
      BindPart(bodies, "padding_rack", PartKind::kRackAndPinion, 0, 1);
  PartBlocks<RackAndPinionGeometry> geometry(1);
  PartBlocks<RackAndPinionLanes> parts(1);
  PartBlocks<LaneArray> error(1);
  for (std::size_t w = 0; w < kRealWorlds; ++w) {
    const RackAndPinionWorld in = RackAndPinionInputs(w);
    const std::size_t lane = LaneOf(w, layout);
    WriteLane(bodies.lanes(0, 0), lane, in.pinion);
    WriteLane(bodies.lanes(0, 1), lane, in.rack);
    SetLaneVec3(geometry[0].hinge_axis, lane, in.hinge_axis);
    SetLaneVec3(geometry[0].slider_axis, lane, in.slider_axis);
    geometry[0].ratio[lane] = in.ratio;
    error[0][lane] = in.error;
    parts[0].persistent.total_lambda[lane] = in.lambda;
  }
  if (layout.garbage) {
    const std::array<bool, kLaneWidth> real = RealLanes(layout);
    Random random(98);
    FillBodyPaddingWithGarbage(bodies.lanes(0, 0), real, random);
    FillBodyPaddingWithGarbage(bodies.lanes(0, 1), real, random);
    FillPaddingWithGarbage(geometry[0], real, random);
    FillPaddingWithGarbage(parts[0], real, random);
    FillPaddingWithGarbage(error[0], real, random);
  }
  const BodyPair pair = PairInBlock(bodies, binding, 0);
  kernels.calculate_properties(pair, geometry[0], parts[0]);
  kernels.warm_start(pair, parts[0], 0.9f);
  for (int i = 0; i < 3; ++i) {
    kernels.solve_velocity(pair, geometry[0], parts[0]);
  }
  kernels.calculate_properties(pair, geometry[0], parts[0]);
  kernels.solve_position(pair, error[0], parts[0], 0.2f);

  std::vector<WorldResult> results;
  for (std::size_t w = 0; w < kRealWorlds; ++w) {
    const std::size_t lane = LaneOf(w, layout);
    results.push_back({ReadLane(bodies.lanes(0, 0), lane), ReadLane(bodies.lanes(0, 1), lane),
                       {parts[0].persistent.total_lambda[lane]}});
  }
  return results;
}

TEST_P(PaddingTest, RackAndPinionRealWorldsIgnorePaddingLanes) {
  const std::vector<WorldResult> baseline = RunRackAndPinion(Kernels<RackAndPinionKernels>(), kBaseline);
  // The sequence must really act on every world: the pinion's angular and the
  // rack's linear velocity, the rack's position and the impulse change.
  for (std::size_t w = 0; w < kRealWorlds; ++w) {
    const RackAndPinionWorld in = RackAndPinionInputs(w);
    const WorldResult& out = baseline[w];
    const std::string where = "rack and pinion, world " + std::to_string(w);
    EXPECT_TRUE(AllFinite(out.body1) && AllFinite(out.body2)) << where;
    EXPECT_TRUE(Changed(out.body1.angular_velocity, in.pinion.angular_velocity)) << where;
    EXPECT_TRUE(Changed(out.body2.linear_velocity, in.rack.linear_velocity)) << where;
    EXPECT_TRUE(Changed(out.body2.position, in.rack.position)) << where;
    EXPECT_TRUE(std::isfinite(out.lambda[0]) && out.lambda[0] != 0.0f) << where;
  }
  for (const Layout& layout : kOtherLayouts) {
    ExpectSameRealWorlds(RunRackAndPinion(Kernels<RackAndPinionKernels>(), layout), baseline, "rack and pinion",
                         layout);
  }
}

INSTANTIATE_TEST_SUITE_P(EveryTarget, PaddingTest, ::testing::ValuesIn(SupportedKernels<LaneMathKernels>()),
                         TableName<LaneMathKernels>);

}  // namespace
}  // namespace manyworlds::testing
