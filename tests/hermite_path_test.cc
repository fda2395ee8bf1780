// The Hermite path maths of the path constraint (kernels/hermite_path-inl.h)
// on every Highway target, against the reference (reference/hermite_path.h)
// in double, and Jolt's own path test (spec 6, TestPathConstraintPathHermite)
// on the lanes and on the reference in float and double.
#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <string>
#include <vector>

#include "kernels/hermite_path.h"
#include "manyworlds/scene.h"
#include "reference/hermite_path.h"
#include "tests/test_support.h"

namespace manyworlds::testing {
namespace {

class HermitePathTest : public ::testing::TestWithParam<const HermitePathKernels*> {
 protected:
  const HermitePathKernels& Kernels() const { return *GetParam(); }
};

// The kernels' view of a scene path.
struct LanePath {
  explicit LanePath(const std::vector<PathPoint>& points, bool looping) {
    for (const PathPoint& p : points) {
      lanes.push_back({{p.position[0], p.position[1], p.position[2]},
                       {p.tangent[0], p.tangent[1], p.tangent[2]},
                       {p.normal[0], p.normal[1], p.normal[2]}});
    }
    path = HermitePath{lanes.data(), lanes.size(), looping};
  }
  std::vector<HermitePathPoint> lanes;
  HermitePath path;
};

// Jolt's test path: one straight segment (p2 - p1 = t2) whose first tangent
// is three times longer than the segment, so |P(t) - q|^2 has a second local
// minimum and Newton from the middle of [0, 1] alone would settle on it for
// q near the start (Jolt's reason for bracketing first).
std::vector<PathPoint> JoltStraightSegment() {
  return {PathPoint{{124.96313f, 68.565399f, 83.655975f}, {61.4222832f, 42.8926392f, 0.0f},
                    {0, 0, 1}},
          PathPoint{{145.20105f, 82.364319f, 83.655975f}, {20.2380009f, 13.7989082f, 0.0f},
                    {0, 0, 1}}};
}

// Fractions 0, 0.1, ..., 1: the point on the path at each, and the closest
// point of that point recovers the fraction within Jolt's 1e-4; points beyond
// the ends give exactly 0 and 1.
template <class ClosestPoint, class PointOnPath>
void ExpectJoltStraightSegment(ClosestPoint closest, PointOnPath point_on) {
  const std::vector<PathPoint> points = JoltStraightSegment();
  const Vec3d p1(points[0].position[0], points[0].position[1], points[0].position[2]);
  const Vec3d p2(points[1].position[0], points[1].position[1], points[1].position[2]);
  EXPECT_EQ(closest(p1 - (p2 - p1)), 0.0);
  EXPECT_EQ(closest(p2 + (p2 - p1)), 1.0);
  for (int i = 0; i <= 10; ++i) {
    const double fraction = 0.1 * i;
    EXPECT_NEAR(closest(point_on(fraction)), fraction, 1e-4) << "fraction " << fraction;
  }
}

TEST_P(HermitePathTest, JoltStraightSegmentRecoversEveryFraction) {
  LanePath lane_path(JoltStraightSegment(), false);
  const auto closest = [&](const Vec3d& q) {
    Vec3Lanes query;
    for (std::size_t lane = 0; lane < kLaneWidth; ++lane) SetLaneVec3(query, lane, q);
    LaneArray fraction;
    Kernels().closest_point(lane_path.path, query, fraction);
    for (std::size_t lane = 1; lane < kLaneWidth; ++lane) EXPECT_EQ(fraction[lane], fraction[0]);
    return double(fraction[0]);
  };
  const auto point_on = [&](double f) {
    LaneArray fraction;
    for (std::size_t lane = 0; lane < kLaneWidth; ++lane) fraction[lane] = float(f);
    Vec3Lanes position, tangent, normal, binormal;
    Kernels().point_on_path(lane_path.path, fraction, position, tangent, normal, binormal);
    return LaneVec3(position, 0);
  };
  ExpectJoltStraightSegment(closest, point_on);
}

template <class T>
void ReferenceStraightSegment() {
  const reference::HermitePath<T> path(JoltStraightSegment(), false);
  ExpectJoltStraightSegment(
      [&](const Vec3d& q) { return double(path.ClosestPoint(q.cast<T>())); },
      [&](double f) { return Vec3d(path.PointOnPath(T(f)).position.template cast<double>()); });
}
TEST(HermitePathReferenceTest, JoltStraightSegmentRecoversEveryFractionInFloat) {
  ReferenceStraightSegment<float>();
}
TEST(HermitePathReferenceTest, JoltStraightSegmentRecoversEveryFractionInDouble) {
  ReferenceStraightSegment<double>();
}

// A curved open path and a looping one (a rounded square), 4 points each.
std::vector<PathPoint> CurvedPath() {
  return {PathPoint{{0, 0, 0}, {2, 1, 0}, {0, 1, 0}}, PathPoint{{2, 1, 0.5f}, {1, 2, 0}, {-1, 1, 0}},
          PathPoint{{2.5f, 3, 0}, {-1, 2, 1}, {-1, 0, 0}},
          PathPoint{{1, 4, 1}, {-2, 0, 0}, {0, -1, 0}}};
}
std::vector<PathPoint> LoopPath() {
  return {PathPoint{{2, 0, 0}, {0, 3, 0}, {0, 0, 1}}, PathPoint{{0, 2, 0}, {-3, 0, 0}, {0, 0, 1}},
          PathPoint{{-2, 0, 0.3f}, {0, -3, 0}, {0, 0, 1}},
          PathPoint{{0, -2, 0}, {3, 0, 0}, {0, 0, 1}}};
}

// Every lane against the double reference for random query points around
// the path. The closest point search takes discrete decisions (which segment
// wins, when Newton stops) that rounding can tip, so the lanes' fraction is
// held to the distance it reaches: at most that of the reference's fraction
// plus 64 FLT_EPSILON x the coordinates' size (4), and the point on the path
// at any fraction to the reference's within the same bound (tangent,
// normal, binormal: unit vectors, scale 1, times the tangents' size, 3).
TEST_P(HermitePathTest, LanesMatchTheReference) {
  Random random(77);
  for (const bool looping : {false, true}) {
    const std::vector<PathPoint> points = looping ? LoopPath() : CurvedPath();
    LanePath lane_path(points, looping);
    const reference::HermitePath<double> ref(points, looping);
    for (int block = 0; block < 64; ++block) {
      Vec3Lanes query;
      LaneArray some_fraction;
      for (std::size_t lane = 0; lane < kLaneWidth; ++lane) {
        const double f = random.Uniform(-0.5, ref.max_fraction() + 0.5);
        SetLaneVec3(query, lane, ref.PointOnPath(f).position + random.Vector(1.5));
        some_fraction[lane] = float(f);
      }
      LaneArray fraction;
      Kernels().closest_point(lane_path.path, query, fraction);
      Vec3Lanes position, tangent, normal, binormal;
      Kernels().point_on_path(lane_path.path, some_fraction, position, tangent, normal, binormal);
      for (std::size_t lane = 0; lane < kLaneWidth; ++lane) {
        const std::string where = "lane " + std::to_string(lane) + " of block " +
                                  std::to_string(block) + (looping ? " (loop)" : " (open)");
        const Vec3d q = LaneVec3(query, lane);
        const double lane_distance = (ref.PointOnPath(fraction[lane]).position - q).norm();
        const double ref_distance = (ref.PointOnPath(ref.ClosestPoint(q)).position - q).norm();
        EXPECT_LE(lane_distance, ref_distance + Tolerance(4.0)) << where;
        EXPECT_GE(fraction[lane], 0.0f) << where;
        EXPECT_LE(fraction[lane], float(ref.max_fraction())) << where;
        const auto expected = ref.PointOnPath(some_fraction[lane]);
        EXPECT_LE((LaneVec3(position, lane) - expected.position).norm(), Tolerance(4.0)) << where;
        EXPECT_LE((LaneVec3(tangent, lane) - expected.tangent).norm(), Tolerance(3.0)) << where;
        EXPECT_LE((LaneVec3(normal, lane) - expected.normal).norm(), Tolerance(3.0)) << where;
        EXPECT_LE((LaneVec3(binormal, lane) - expected.binormal).norm(), Tolerance(3.0)) << where;
      }
    }
  }
}

INSTANTIATE_TEST_SUITE_P(EveryTarget, HermitePathTest,
                         ::testing::ValuesIn(SupportedKernels<HermitePathKernels>()),
                         TableName<HermitePathKernels>);

}  // namespace
}  // namespace manyworlds::testing
