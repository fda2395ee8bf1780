// Contacts of a box with a sphere, capsule or box in the scalar reference world
// (reference/box_contact_points.h through reference/contact_constraint.h,
// docs/contacts.md "Points of a box with a sphere, capsule or box"), in float
// and double: the manifolds (point counts, points, normal, separations, body
// order) of scenes whose expected points are worked out by hand below, and
// what the bodies then do (a stack of boxes, a heavy box on a light one, a
// sphere rolling off a box's edge).
//
// Setup as tests/reference_contact_test.cc: a floor is a static plane at
// y = 0, dt = 1/60, g = −9.81 m/s², density 1000 kg/m³. A manifold is read
// after one zero-gravity step of a scene: it is found at the start of that
// step, from the scene's poses. Every expectation comes from the geometry or
// the physics, never from running this code; each tolerance says why.
#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

#include "manyworlds/batch.h"
#include "manyworlds/scene.h"
#include "reference/world.h"
#include "tests/contact_test_scenes.h"

namespace manyworlds::reference {
namespace {

using namespace ::manyworlds::contact_test;  // NOLINT(google-build-using-namespace)

template <class T>
class ReferenceBoxContactTest : public ::testing::Test {};
using Scalars = ::testing::Types<float, double>;
TYPED_TEST_SUITE(ReferenceBoxContactTest, Scalars);

using Vec3d = Vec3<double>;

// Points of lengths up to ~2 m through a few float roundings (a rotation, a
// clamp, a normalisation): 1e-6 m when the shapes are axis-aligned, 1e-5 m
// when a rotation by a float quaternion is involved; far tighter in double.
constexpr double kTol = 1e-6;
constexpr double kRotatedTol = 1e-5;

constexpr Quaternion kIdentity{0.0f, 0.0f, 0.0f, 1.0f};

Float3 F3(const Vec3d& v) { return {float(v.x()), float(v.y()), float(v.z())}; }
Vec3d D3(const Float3& v) { return {v[0], v[1], v[2]}; }

// The scene's rotation in double, normalised as the world normalises it.
Quat<double> Rotation(const Quaternion& q) {
  return Quat<double>(q[3], q[0], q[1], q[2]).normalized();
}

BodySettings BoxAt(Vec3d half, Vec3d centre, Quaternion rotation = kIdentity) {
  BodySettings box = Box(F3(half), F3(centre));
  box.rotation = rotation;
  return box;
}
BodySettings SphereAt(double radius, Vec3d centre) {
  return Sphere(float(radius), F3(centre));
}
BodySettings CapsuleAt(double radius, double half_height, Vec3d centre, Quaternion rotation) {
  BodySettings capsule = Capsule(float(radius), float(half_height), F3(centre));
  capsule.rotation = rotation;
  return capsule;
}

// The slot of a scene of just `body0` and `body1` after one step of
// `settings` (zero gravity): every point, the normal, the separations.
struct Manifold {
  int count = 0;
  int max_points = 0;
  Vec3d normal = Vec3d::Zero();
  std::vector<Vec3d> p1, p2;  // on body 1 (the lower index), on body 2
  std::vector<double> separation;
};

template <class T>
Manifold ManifoldOf(const BodySettings& body0, const BodySettings& body1,
                    const StepSettings& settings = ZeroGravity()) {
  Scene scene;
  scene.AddBody(body0);
  scene.AddBody(body1);
  World<T> world(scene);
  Manifold out;
  EXPECT_EQ(world.contact_count(), 1u);
  if (world.contact_count() != 1u) return out;
  world.Step(settings);
  const ContactConstraint<T>& contact = world.contact(0);
  out.count = contact.PointCount();
  out.max_points = contact.MaxPointCount();
  out.normal = contact.Normal().template cast<double>();
  for (int k = 0; k < out.count; ++k) {
    out.p1.push_back(contact.Point1(k).template cast<double>());
    out.p2.push_back(contact.Point2(k).template cast<double>());
    out.separation.push_back(double(contact.Separation(k)));
  }
  return out;
}

// Point k is (p1, p2) with separation (p2 − p1)·n.
void ExpectPoint(const Manifold& m, int k, const Vec3d& p1, const Vec3d& p2, double tolerance) {
  SCOPED_TRACE("point " + std::to_string(k));
  ASSERT_LT(k, m.count);
  EXPECT_LE((m.p1[k] - p1).norm(), tolerance) << m.p1[k].transpose() << " vs " << p1.transpose();
  EXPECT_LE((m.p2[k] - p2).norm(), tolerance) << m.p2[k].transpose() << " vs " << p2.transpose();
  EXPECT_NEAR(m.separation[k], (p2 - p1).dot(m.normal), tolerance);
}

void ExpectNormal(const Manifold& m, const Vec3d& n, double tolerance) {
  EXPECT_LE((m.normal - n).norm(), tolerance) << m.normal.transpose() << " vs " << n.transpose();
}

// ================================================================ sphere–box

// A box (half 0.5, 0.3, 0.4) and a sphere (r 0.2) whose centre is l in the
// box's frame: q = clamp(l, −h, h), L = |l − q|, m = (l − q)/L, the points
// q on the box and l − r m on the sphere, separation L − r. The box is posed
// at (1, 2, 3) turned by 0.7 rad about (0.6, 0, 0.8), so the frame change is
// exercised: the expected world points are c + R(local).
TYPED_TEST(ReferenceBoxContactTest, SphereBoxOutsideAFaceAnEdgeACorner) {
  using T = TypeParam;
  const Vec3d h(0.5, 0.3, 0.4), c(1.0, 2.0, 3.0);
  const Quaternion rotation = RotationAbout({0.6f, 0.0f, 0.8f}, 0.7);
  const Quat<double> R = Rotation(rotation);
  const BodySettings box = BoxAt(h, c, rotation);
  struct Case {
    const char* name;
    Vec3d l;   // the sphere's centre in the box's frame
    double r;  // its radius
    Vec3d q;   // the nearest box point
  };
  for (const Case& s : {
           // Above the +Y face: m = +Y, L = 0.21, separation 0.01.
           Case{"face", {0.1, 0.51, -0.1}, 0.2, {0.1, 0.3, -0.1}},
           // Beyond the edge (+X, +Y): m = (1, 1, 0)/√2, L = 0.1√2 = 0.1414,
           // separation 0.0114.
           Case{"edge", {0.6, 0.4, 0.0}, 0.13, {0.5, 0.3, 0.0}},
           // Beyond the corner (+X, −Y, +Z): m = (1, −1, 1)/√3, L = 0.1√3 =
           // 0.1732, separation 0.0132.
           Case{"corner", {0.6, -0.4, 0.5}, 0.16, {0.5, -0.3, 0.4}},
       }) {
    SCOPED_TRACE(s.name);
    const Vec3d world_centre = c + R * s.l;
    const BodySettings sphere = SphereAt(s.r, world_centre);
    // The world's sphere centre is a float: l as the world sees it.
    const Vec3d l = R.conjugate() * (D3(sphere.position) - c);
    const double distance = (l - s.q).norm();
    const Vec3d m = (l - s.q) / distance;
    // Box first (body 1): n from the box to the sphere, p1 on the box.
    const Manifold a = ManifoldOf<T>(box, sphere);
    ASSERT_EQ(a.count, 1);
    EXPECT_EQ(a.max_points, 1);
    ExpectNormal(a, R * m, kRotatedTol);
    ExpectPoint(a, 0, c + R * s.q, c + R * (l - s.r * m), kRotatedTol);
    EXPECT_NEAR(a.separation[0], distance - s.r, kRotatedTol);
    EXPECT_LT(a.separation[0], kSpeculative);
    // Sphere first: the normal negated and the pair swapped.
    const Manifold b = ManifoldOf<T>(sphere, box);
    ASSERT_EQ(b.count, 1);
    ExpectNormal(b, -(R * m), kRotatedTol);
    ExpectPoint(b, 0, c + R * (l - s.r * m), c + R * s.q, kRotatedTol);
    EXPECT_NEAR(b.separation[0], distance - s.r, kRotatedTol);
  }
}

// Sphere as body 1 and as body 2 above an axis-aligned box (half 0.5, 0.3,
// 0.4 at the origin), centre (0.1, 0.51, −0.1), r 0.2: the box's point
// (0.1, 0.3, −0.1), the sphere's (0.1, 0.31, −0.1), separation 0.01; the
// normal is +Y from the box, −Y from the sphere. 0.025 apart: no manifold.
TYPED_TEST(ReferenceBoxContactTest, SphereBoxBodyOrder) {
  using T = TypeParam;
  const BodySettings box = BoxAt({0.5, 0.3, 0.4}, Vec3d::Zero());
  const BodySettings sphere = SphereAt(0.2, {0.1, 0.51, -0.1});
  const Vec3d on_box(0.1, 0.3, -0.1), on_sphere(0.1, 0.31, -0.1);
  const Manifold box_first = ManifoldOf<T>(box, sphere);
  ASSERT_EQ(box_first.count, 1);
  ExpectNormal(box_first, Vec3d::UnitY(), kTol);
  ExpectPoint(box_first, 0, on_box, on_sphere, kTol);
  EXPECT_NEAR(box_first.separation[0], 0.01, kTol);
  const Manifold sphere_first = ManifoldOf<T>(sphere, box);
  ASSERT_EQ(sphere_first.count, 1);
  ExpectNormal(sphere_first, -Vec3d::UnitY(), kTol);
  ExpectPoint(sphere_first, 0, on_sphere, on_box, kTol);
  EXPECT_NEAR(sphere_first.separation[0], 0.01, kTol);
  EXPECT_EQ(ManifoldOf<T>(box, SphereAt(0.2, {0.1, 0.525, -0.1})).count, 0);
  EXPECT_EQ(ManifoldOf<T>(SphereAt(0.2, {0.1, 0.525, -0.1}), box).count, 0);
}

// The sphere's centre inside the box: out through the face of least depth
// g_k = h_k − |l_k| (first index on a tie), m = sign(l_k) e_k, L = −g_k, the
// box's point l with l_k ← sign(l_k) h_k, the sphere's l − r m, separation
// −g_k − r.
TYPED_TEST(ReferenceBoxContactTest, SphereCentreInsideTheBox) {
  using T = TypeParam;
  struct Case {
    const char* name;
    Vec3d half, l;
    int k;
    double sign;
  };
  for (const Case& s : {
           // g = (0.2, 0.15, 0.35): the −Y face (l_y < 0), 0.15 deep.
           Case{"least depth", {0.5, 0.3, 0.4}, {0.3, -0.15, 0.05}, 1, -1.0},
           // g = (0.25, 0.25, 0.5), exact in float: the first, +X.
           Case{"tie", {0.5, 0.5, 0.5}, {0.25, 0.25, 0.0}, 0, 1.0},
           // The centre itself: g all 0.5, the first, and sign(0) = +1: +X.
           Case{"centre", {0.5, 0.5, 0.5}, {0.0, 0.0, 0.0}, 0, 1.0},
           // g = (0.35, 0.3, 0.1): the −Z face.
           Case{"z", {0.5, 0.5, 0.5}, {0.15, -0.2, -0.4}, 2, -1.0},
       }) {
    SCOPED_TRACE(s.name);
    const double r = 0.2;
    const Vec3d offset(1.0, 0.5, -2.0);  // the box's centre: exact in float
    const Manifold m =
        ManifoldOf<T>(BoxAt(s.half, offset), SphereAt(r, offset + s.l));
    ASSERT_EQ(m.count, 1);
    const Vec3d n = s.sign * Vec3d::Unit(s.k);
    ExpectNormal(m, n, kTol);
    Vec3d on_box = s.l;
    on_box[s.k] = s.sign * s.half[s.k];
    const double depth = s.half[s.k] - std::abs(s.l[s.k]);
    ExpectPoint(m, 0, offset + on_box, offset + s.l - r * n, kTol);
    EXPECT_NEAR(m.separation[0], -depth - r, kTol);
  }
}

// =============================================================== capsule–box

// Body Y along world +X and along world −X (exact in float; see
// tests/contact_test_scenes.h).
constexpr Quaternion kYToMinusX{0.5f, -0.5f, 0.5f, 0.5f};

// A capsule (r 0.2, h 0.5) lying along X on the top face of a box (half
// 1, 0.5, 1), its core 0.705 up: ends a = (−0.4, 0.705, 0.2), b = (0.6, 0.705,
// 0.2). Not touching; the nearest is end a over the face (L = 0.205, m = +Y,
// b ties and comes later). α = â·m = 0: two points, the capsule's face a − r ŵ,
// b − r ŵ (ŵ = +Y) at y = 0.505 over the box's face y = 0.5, t ∈ [0, 1]
// (the face spans x ∈ [−1, 1]), separation 0.005 each, a then b. The other
// body order negates n and swaps the pairs.
TYPED_TEST(ReferenceBoxContactTest, CapsuleLyingOnABoxFace) {
  using T = TypeParam;
  const BodySettings box = BoxAt({1.0, 0.5, 1.0}, Vec3d::Zero());
  const BodySettings capsule = CapsuleAt(0.2, 0.5, {0.1, 0.705, 0.2}, kYToX);
  const Manifold m = ManifoldOf<T>(box, capsule);
  ASSERT_EQ(m.count, 2);
  EXPECT_EQ(m.max_points, 2);
  ExpectNormal(m, Vec3d::UnitY(), kTol);
  ExpectPoint(m, 0, {-0.4, 0.5, 0.2}, {-0.4, 0.505, 0.2}, kTol);
  ExpectPoint(m, 1, {0.6, 0.5, 0.2}, {0.6, 0.505, 0.2}, kTol);
  for (int k = 0; k < 2; ++k) EXPECT_NEAR(m.separation[k], 0.005, kTol);
  const Manifold swapped = ManifoldOf<T>(capsule, box);
  ASSERT_EQ(swapped.count, 2);
  ExpectNormal(swapped, -Vec3d::UnitY(), kTol);
  ExpectPoint(swapped, 0, {-0.4, 0.505, 0.2}, {-0.4, 0.5, 0.2}, kTol);
  ExpectPoint(swapped, 1, {0.6, 0.505, 0.2}, {0.6, 0.5, 0.2}, kTol);
  // The same capsule turned end for end (â = −X): a and b trade places.
  const Manifold reversed = ManifoldOf<T>(box, CapsuleAt(0.2, 0.5, {0.1, 0.705, 0.2}, kYToMinusX));
  ASSERT_EQ(reversed.count, 2);
  ExpectPoint(reversed, 0, {0.6, 0.5, 0.2}, {0.6, 0.505, 0.2}, kTol);
  ExpectPoint(reversed, 1, {-0.4, 0.5, 0.2}, {-0.4, 0.505, 0.2}, kTol);
}

// A capsule (r 0.2, h 0.5) lying along X across the +X edge of a box (half
// 0.5): core x ∈ [0.1, 1.1] at y = 0.705, z = 0; the nearest pair is 0.205
// apart, m = +Y. Two points along the face, P(t) = (0.1 + t, 0.505, 0): the
// projection P'(t) = (0.1 + t, 0.5, 0) lies within x ≤ 0.5 for t ≤ 0.4
// (f = +P'_x: f0 = 0.1, f1 = 1, t_out = (0.5 − 0.1)/1, with the face's
// bound widened to 1.0001 · 0.5: 0.40005). The points at t = 0 and at the
// edge, separation 0.005 each.
TYPED_TEST(ReferenceBoxContactTest, CapsuleAcrossTheEdgeOfABox) {
  using T = TypeParam;
  const Manifold m = ManifoldOf<T>(BoxAt({0.5, 0.5, 0.5}, Vec3d::Zero()),
                                   CapsuleAt(0.2, 0.5, {0.6, 0.705, 0.0}, kYToX));
  ASSERT_EQ(m.count, 2);
  ExpectNormal(m, Vec3d::UnitY(), kTol);
  ExpectPoint(m, 0, {0.1, 0.5, 0.0}, {0.1, 0.505, 0.0}, kTol);
  ExpectPoint(m, 1, {0.50005, 0.5, 0.0}, {0.50005, 0.505, 0.0}, kTol);
}

// A capsule (r 0.2, h 0.5) standing upright on a box (half 0.5), its lower
// end a = (0.1, 0.705, 0.2) 0.205 above the top face: m = +Y, α = 1 (not
// lying along the face), one point: a − r m = (0.1, 0.505, 0.2) on the
// capsule, (0.1, 0.5, 0.2) on the box, separation 0.005. Lying along the
// face but tilted so one end is 3 cm higher than the other: still one point
// (|2 h α| = 0.03 ≥ the 2 cm slop); 1 cm higher: two.
TYPED_TEST(ReferenceBoxContactTest, CapsuleStandingOnABoxGetsOnePoint) {
  using T = TypeParam;
  const BodySettings box = BoxAt({0.5, 0.5, 0.5}, Vec3d::Zero());
  const Manifold m = ManifoldOf<T>(box, CapsuleAt(0.2, 0.5, {0.1, 1.205, 0.2}, kIdentity));
  ASSERT_EQ(m.count, 1);
  ExpectNormal(m, Vec3d::UnitY(), kTol);
  ExpectPoint(m, 0, {0.1, 0.5, 0.2}, {0.1, 0.505, 0.2}, kTol);
  EXPECT_NEAR(m.separation[0], 0.005, kTol);
  for (const double rise : {0.01, 0.03}) {
    SCOPED_TRACE(rise);
    // Turned about Z from along X by asin(rise / 2h): the lower end a at
    // x < 0, 0.005 + r above the face (the nearest pair: a and its foot).
    const double tilt = std::asin(rise / 1.0);
    const Vec3d axis(std::cos(tilt), std::sin(tilt), 0.0);
    const Vec3d centre = Vec3d(0.0, 0.705, 0.0) + 0.5 * axis;
    const BodySettings capsule =
        CapsuleAt(0.2, 0.5, centre, RotationAbout({0, 0, 1}, -(kPiD / 2.0 - tilt)));
    EXPECT_EQ(ManifoldOf<T>(box, capsule).count, rise < 0.02 ? 2 : 1);
  }
}

// The capsule's core inside the box: out through the face that needs the
// least push, g = h_k − min(σ a_k, σ b_k) over (0,+), (0,−), (1,+), ..., m =
// σ e_k, L = −g, P the end with the smaller σ x_k, Q = P clamped, Q_k = σ h_k;
// one pair (P − r m, Q), separation −g − r, unless the capsule lies along
// the face. Box half 0.5 at the origin, capsule r 0.1, h 0.5.
TYPED_TEST(ReferenceBoxContactTest, CapsuleCorePiercingTheBox) {
  using T = TypeParam;
  const BodySettings box = BoxAt({0.5, 0.5, 0.5}, Vec3d::Zero());
  {
    SCOPED_TRACE("upright through the top");
    // a = (0.1, 0.2, 0.05), b = (0.1, 1.2, 0.05): g = 0.4, 0.6, 0.3, 1.7,
    // 0.45, 0.55: the +Y face, 0.3 deep; P = a (lower), Q = (0.1, 0.5, 0.05).
    const Manifold m = ManifoldOf<T>(box, CapsuleAt(0.1, 0.5, {0.1, 0.7, 0.05}, kIdentity));
    ASSERT_EQ(m.count, 1);
    ExpectNormal(m, Vec3d::UnitY(), kTol);
    ExpectPoint(m, 0, {0.1, 0.5, 0.05}, {0.1, 0.1, 0.05}, kTol);
    EXPECT_NEAR(m.separation[0], -0.4, kTol);
  }
  {
    SCOPED_TRACE("end on through the -X face");
    // a = (−1.3, 0.1, 0), b = (−0.3, 0.1, 0): g = 1.8, 0.2, 0.4, 0.6, 0.5,
    // 0.5: the −X face, 0.2 deep; P = b (the smaller −x), Q = (−0.5, 0.1, 0);
    // α = −1: one point, P − r m = (−0.2, 0.1, 0), separation −0.3.
    const Manifold m = ManifoldOf<T>(box, CapsuleAt(0.1, 0.5, {-0.8, 0.1, 0.0}, kYToX));
    ASSERT_EQ(m.count, 1);
    ExpectNormal(m, -Vec3d::UnitX(), kTol);
    ExpectPoint(m, 0, {-0.5, 0.1, 0.0}, {-0.2, 0.1, 0.0}, kTol);
    EXPECT_NEAR(m.separation[0], -0.3, kTol);
  }
  {
    SCOPED_TRACE("lying inside under the top");
    // a = (−0.3, 0.4, 0.1), b = (0.7, 0.4, 0.1): g = 0.8, 1.2, 0.1, 0.9, 0.4,
    // 0.6: the +Y face, m = +Y; α = 0: two points along it, the capsule's
    // face at y = 0.3 (λ = −0.2), clipped to x ≤ 1.0001 · 0.5: t ∈ [0, 0.80005].
    const Manifold m = ManifoldOf<T>(box, CapsuleAt(0.1, 0.5, {0.2, 0.4, 0.1}, kYToX));
    ASSERT_EQ(m.count, 2);
    ExpectNormal(m, Vec3d::UnitY(), kTol);
    ExpectPoint(m, 0, {-0.3, 0.5, 0.1}, {-0.3, 0.3, 0.1}, kTol);
    ExpectPoint(m, 1, {0.50005, 0.5, 0.1}, {0.50005, 0.3, 0.1}, kTol);
    for (int k = 0; k < 2; ++k) EXPECT_NEAR(m.separation[k], -0.2, kTol);
  }
}

// A capsule beyond the box's +X+Y edge (along Z at x = y = 0.5): along X
// (r 0.1, h 0.5) at (1.05, 0.6, 0), core x ∈ [0.55, 1.55] at y = 0.6. The
// nearest pair is end a = (0.55, 0.6, 0) and its clamp, the edge point
// (0.5, 0.5, 0) (the edge's closest pair is the same and comes later):
// L = √(0.05² + 0.1²) = 0.1118, m = (1, 2, 0)/√5, separation 0.0118. α =
// â·m = 1/√5: not lying along a face, so the one pair (a − r m, (0.5, 0.5, 0)).
TYPED_TEST(ReferenceBoxContactTest, CapsuleBeyondAnEdgeGetsTheNearestPair) {
  using T = TypeParam;
  const Manifold m = ManifoldOf<T>(BoxAt({0.5, 0.5, 0.5}, Vec3d::Zero()),
                                   CapsuleAt(0.1, 0.5, {1.05, 0.6, 0.0}, kYToX));
  ASSERT_EQ(m.count, 1);
  const Vec3d n = Vec3d(1.0, 2.0, 0.0) / std::sqrt(5.0);
  ExpectNormal(m, n, kTol);
  ExpectPoint(m, 0, {0.5, 0.5, 0.0}, Vec3d(0.55, 0.6, 0.0) - 0.1 * n, kTol);
  EXPECT_NEAR(m.separation[0], std::sqrt(0.05 * 0.05 + 0.1 * 0.1) - 0.1, kTol);
}

// =================================================================== box–box

// Looks for (p1, p2) among the manifold's points; returns its index or −1.
int FindPoint(const Manifold& m, const Vec3d& p1, const Vec3d& p2, double tolerance) {
  for (int k = 0; k < m.count; ++k) {
    if ((m.p1[k] - p1).norm() <= tolerance && (m.p2[k] - p2).norm() <= tolerance) return k;
  }
  return -1;
}

// Two boxes of half 0.5, the upper one 5 mm above: n = +Y (face axis 1, the
// first of the best), the four corners of the touching faces, each once,
// separation 0.005. (Equal faces make 16 candidates at the 4 corners, B's
// and A's corners and the edges crossing there; pruned to 4, one per
// corner.) 25 mm above: beyond D, no manifold; 19 mm: a speculative one.
TYPED_TEST(ReferenceBoxContactTest, BoxOnBoxFaceToFace) {
  using T = TypeParam;
  const BodySettings lower = BoxAt({0.5, 0.5, 0.5}, Vec3d::Zero());
  const Manifold m = ManifoldOf<T>(lower, BoxAt({0.5, 0.5, 0.5}, {0.0, 1.005, 0.0}));
  ASSERT_EQ(m.count, 4);
  EXPECT_EQ(m.max_points, 4);
  ExpectNormal(m, Vec3d::UnitY(), kTol);
  std::vector<int> found;
  for (const double x : {-0.5, 0.5}) {
    for (const double z : {-0.5, 0.5}) {
      const int k = FindPoint(m, {x, 0.5, z}, {x, 0.505, z}, kTol);
      EXPECT_GE(k, 0) << x << " " << z;
      found.push_back(k);
    }
  }
  for (std::size_t i = 0; i < found.size(); ++i) {
    for (std::size_t j = i + 1; j < found.size(); ++j) {
      if (found[i] >= 0) {
        EXPECT_NE(found[i], found[j]);
      }
    }
  }
  for (int k = 0; k < 4; ++k) EXPECT_NEAR(m.separation[k], 0.005, kTol);
  // The upper box as body 1: n = −Y (turned so that n·t ≥ 0), A's face its
  // bottom, the points on it first.
  const BodySettings upper = BoxAt({0.5, 0.5, 0.5}, {0.0, 1.005, 0.0});
  const Manifold down = ManifoldOf<T>(upper, lower);
  ASSERT_EQ(down.count, 4);
  ExpectNormal(down, -Vec3d::UnitY(), kTol);
  for (const double x : {-0.5, 0.5}) {
    for (const double z : {-0.5, 0.5}) {
      EXPECT_GE(FindPoint(down, {x, 0.505, z}, {x, 0.5, z}, kTol), 0) << x << " " << z;
    }
  }
  for (int k = 0; k < 4; ++k) EXPECT_NEAR(down.separation[k], 0.005, kTol);
  EXPECT_EQ(ManifoldOf<T>(lower, BoxAt({0.5, 0.5, 0.5}, {0.0, 1.025, 0.0})).count, 0);
  EXPECT_EQ(ManifoldOf<T>(lower, BoxAt({0.5, 0.5, 0.5}, {0.0, 1.019, 0.0})).count, 4);
}

// A smaller box B (half 0.3, 0.2, 0.25) on a larger A (half 1, 0.5, 1),
// 4 mm up, centred at (0.1, −, −0.2): B's bottom corners project inside A's
// top face, A's corners lie outside B's face and no edges cross: 4 points,
// B's corners q_0..q_3 in polygon order (x, z) = (−,−), (+,−), (+,+), (−,+).
// Upside down (the larger box as body 2, on the smaller one): A's corners
// p_0..p_3 instead, each with its projection on B's face.
TYPED_TEST(ReferenceBoxContactTest, SmallerAndLargerBoxOnABox) {
  using T = TypeParam;
  const Vec3d small(0.3, 0.2, 0.25), large(1.0, 0.5, 1.0);
  const double sx[4] = {-1, 1, 1, -1}, sz[4] = {-1, -1, 1, 1};
  {
    SCOPED_TRACE("smaller on larger");
    const Vec3d c(0.1, 0.5 + 0.2 + 0.004, -0.2);
    const Manifold m = ManifoldOf<T>(BoxAt(large, Vec3d::Zero()), BoxAt(small, c));
    ASSERT_EQ(m.count, 4);
    ExpectNormal(m, Vec3d::UnitY(), kTol);
    for (int j = 0; j < 4; ++j) {
      const double x = c.x() + sx[j] * small.x(), z = c.z() + sz[j] * small.z();
      ExpectPoint(m, j, {x, 0.5, z}, {x, 0.504, z}, kTol);
      EXPECT_NEAR(m.separation[j], 0.004, kTol);
    }
  }
  {
    SCOPED_TRACE("larger on smaller");
    const Vec3d c(0.1, 0.2 + 0.5 + 0.004, -0.2);
    const Manifold m = ManifoldOf<T>(BoxAt(small, Vec3d::Zero()), BoxAt(large, c));
    ASSERT_EQ(m.count, 4);
    ExpectNormal(m, Vec3d::UnitY(), kTol);
    for (int i = 0; i < 4; ++i) {
      const double x = sx[i] * small.x(), z = sz[i] * small.z();
      ExpectPoint(m, i, {x, 0.2, z}, {x, 0.204, z}, kTol);
      EXPECT_NEAR(m.separation[i], 0.004, kTol);
    }
  }
}

// A cube B (half 0.5) turned 45° about Y, 5 mm above a box A (half 0.55,
// 0.5, 0.45) with its centre at (0.05, −, 0.02): B's bottom face is a diamond
// |dx + dz| ≤ K, |dx − dz| ≤ K (K = 0.5√2, d from B's centre), A's top face
// the rectangle |x| ≤ 0.55, |z| ≤ 0.45; no corner of either lies in the other,
// so the 8 points are edge crossings (the octagon), all 5 mm apart: pruned to
// 4 about A's centre (the weights are equal):
//   P1, the farthest: (0.55, K − 0.48) = (0.55, 0.2271), |q|² = 0.354 (next:
//       (0.55, −0.1871), 0.338);
//   P2, the farthest from P1: (−0.55, 0.62 − K) = (−0.55, −0.0871), 1.309
//       (next: (−0.55, 0.1271), 1.220);
//   across P1→P2, e = (q2 − q1) × Y = (0.314, 0, −1.1): P3 the most negative
//       side, (0.48 − K, 0.45) = (−0.2271, 0.45) at −0.489 (next −0.315), P4
//       the most positive, (K − 0.42, −0.45) = (0.2871, −0.45) at 0.662
//       (next 0.513);
// in the order P1, P3, P2, P4.
TYPED_TEST(ReferenceBoxContactTest, BoxTurned45DegreesOnABoxPrunesEightPointsToFour) {
  using T = TypeParam;
  const double K = 0.5 * std::sqrt(2.0);
  const Manifold m =
      ManifoldOf<T>(BoxAt({0.55, 0.5, 0.45}, Vec3d::Zero()),
                    BoxAt({0.5, 0.5, 0.5}, {0.05, 1.005, 0.02}, RotationAbout({0, 1, 0}, kPiD / 4)));
  ASSERT_EQ(m.count, 4);
  ExpectNormal(m, Vec3d::UnitY(), kRotatedTol);
  const double xz[4][2] = {{0.55, K - 0.48}, {0.48 - K, 0.45}, {-0.55, 0.62 - K}, {K - 0.42, -0.45}};
  for (int k = 0; k < 4; ++k) {
    ExpectPoint(m, k, {xz[k][0], 0.5, xz[k][1]}, {xz[k][0], 0.505, xz[k][1]}, kRotatedTol);
    EXPECT_NEAR(m.separation[k], 0.005, kRotatedTol);
  }
}

// Edge on edge: A (half 0.5) turned 30° about Z, its highest edge along Z
// at x = 0.5 cos 30° − 0.5 sin 30° = 0.1830, y = 0.5 (sin 30° + cos 30°) =
// 0.6830; B (half 0.5) turned 20° about X, its lowest edge along X at
// y_B − 0.5 (cos 20° + sin 20°) = y_B − 0.6408, z = z_B + 0.5 (cos 20° − sin
// 20°) = z_B + 0.2988. With B's centre (0.1, 0.6830 + 0.6408 + 0.01, −0.1)
// the edges cross 1 cm apart at (0.1830, −, 0.1988): the edge axis A's Z × B's
// X (world Y) separates by 0.01, every face axis by less (B's edge dips
// below A's tilted faces' planes); the crossing of edge 1 of A's top face and
// edge 2 of B's bottom face is the one candidate within K. One point,
// n = +Y, separation 0.01.
TYPED_TEST(ReferenceBoxContactTest, BoxEdgeOnBoxEdge) {
  using T = TypeParam;
  const double a = 30.0 * kPiD / 180.0, b = 20.0 * kPiD / 180.0;
  const double top = 0.5 * (std::sin(a) + std::cos(a)), x = 0.5 * (std::cos(a) - std::sin(a));
  const double drop = 0.5 * (std::cos(b) + std::sin(b)), dz = 0.5 * (std::cos(b) - std::sin(b));
  const Vec3d c(0.1, top + drop + 0.01, -0.1);
  const Manifold m =
      ManifoldOf<T>(BoxAt({0.5, 0.5, 0.5}, Vec3d::Zero(), RotationAbout({0, 0, 1}, a)),
                    BoxAt({0.5, 0.5, 0.5}, c, RotationAbout({1, 0, 0}, b)));
  ASSERT_EQ(m.count, 1);
  ExpectNormal(m, Vec3d::UnitY(), kRotatedTol);
  ExpectPoint(m, 0, {x, top, c.z() + dz}, {x, top + 0.01, c.z() + dz}, kRotatedTol);
  EXPECT_NEAR(m.separation[0], 0.01, kRotatedTol);
  // The other body order (the upper box is A, its X × the lower box's Z):
  // n = −Y, the same pair swapped.
  const Manifold swapped =
      ManifoldOf<T>(BoxAt({0.5, 0.5, 0.5}, c, RotationAbout({1, 0, 0}, b)),
                    BoxAt({0.5, 0.5, 0.5}, Vec3d::Zero(), RotationAbout({0, 0, 1}, a)));
  ASSERT_EQ(swapped.count, 1);
  ExpectNormal(swapped, -Vec3d::UnitY(), kRotatedTol);
  ExpectPoint(swapped, 0, {x, top + 0.01, c.z() + dz}, {x, top, c.z() + dz}, kRotatedTol);
}

// With speculative_contacts_from_velocity, D grows by the approach in the
// substep, whichever body the box is: a sphere (r 0.2) 3 cm above a box
// (half 0.5) falling at 3 m/s (5 cm per substep) is caught; without it, not.
TYPED_TEST(ReferenceBoxContactTest, SpeculativeDistanceFromVelocity) {
  using T = TypeParam;
  const BodySettings box = BoxAt({0.5, 0.5, 0.5}, Vec3d::Zero());
  BodySettings sphere = SphereAt(0.2, {0.0, 0.73, 0.0});
  sphere.linear_velocity = {0.0f, -3.0f, 0.0f};
  StepSettings from_velocity = ZeroGravity();
  from_velocity.speculative_contacts_from_velocity = true;
  EXPECT_EQ(ManifoldOf<T>(box, sphere).count, 0);
  EXPECT_EQ(ManifoldOf<T>(sphere, box).count, 0);
  EXPECT_EQ(ManifoldOf<T>(box, sphere, from_velocity).count, 1);
  EXPECT_EQ(ManifoldOf<T>(sphere, box, from_velocity).count, 1);
  // Moving away at 3 m/s: D stays 0.02.
  sphere.linear_velocity = {0.0f, 3.0f, 0.0f};
  EXPECT_EQ(ManifoldOf<T>(box, sphere, from_velocity).count, 0);
  EXPECT_EQ(ManifoldOf<T>(sphere, box, from_velocity).count, 0);
}

// ================================================================= behaviour

// Five cubes (half 0.5) stacked on the floor stand for 10 s (600 steps): no
// box moves more than 1 cm from where it started, nor turns by more than
// 0.01 rad. Each resting pair keeps its 4 corners.
TYPED_TEST(ReferenceBoxContactTest, FiveBoxStackStands) {
  using T = TypeParam;
  Scene scene;
  scene.AddBody(Floor(0.5f));
  for (int i = 0; i < 5; ++i) {
    BodySettings box = Box({0.5f, 0.5f, 0.5f}, {0.0f, 0.5f + float(i), 0.0f});
    box.shape.friction = 0.5f;
    scene.AddBody(box);
  }
  World<T> world(scene);
  Simulate(world, Settings(), 10.0);
  for (int i = 0; i < 5; ++i) {
    SCOPED_TRACE("box " + std::to_string(i));
    const Body<T>& body = world.body(std::size_t(i + 1));
    EXPECT_LE(Distance(body.position, 0.0, 0.5 + i, 0.0), 0.01);
    EXPECT_LE(double(body.rotation.angularDistance(Quat<T>::Identity())), 0.01);
  }
  // Slots in pair order: the floor with each box, then the boxes with each
  // other; the touching ones (floor–box 1, box i – box i+1) hold 4 points.
  ASSERT_EQ(world.contact_count(), 15u);
  for (std::size_t k = 0; k < world.contact_count(); ++k) {
    const ContactConstraint<T>& contact = world.contact(k);
    const bool touching = contact.body2() == contact.body1() + 1;
    EXPECT_EQ(contact.PointCount(), touching ? 4 : 0) << contact.body1() << " " << contact.body2();
  }
}

// A 100 kg cube (half 0.5) on a 1 kg cube on the floor. With 4 substeps
// (Jolt's advice for large mass ratios) both stay within 5 mm and 0.01 rad of
// where they started for 5 s, and the light box's top carries the heavy
// one's weight: its 4 points' impulses in the last substep sum to
// 100 kg · g · dt/4 (within 1 %: four rows sharing one load, converged to
// about that). With one substep of 10 iterations the 100:1 ratio does not
// converge: the boxes sink into the slop of both contacts (2 cm each) and
// wander by 1-2.5 cm, but the stack stands: no tilt beyond 0.01 rad, within
// 3 cm across and one slop per contact below it + 3 mm down.
TYPED_TEST(ReferenceBoxContactTest, HeavyBoxOnLightBoxStaysPut) {
  using T = TypeParam;
  Scene scene;
  scene.AddBody(Floor());
  BodySettings light = Box({0.5f, 0.5f, 0.5f}, {0.0f, 0.5f, 0.0f});
  BodySettings heavy = Box({0.5f, 0.5f, 0.5f}, {0.0f, 1.5f, 0.0f});
  for (const auto& [body, mass] : {std::pair{&light, 1.0}, std::pair{&heavy, 100.0}}) {
    const double inertia = mass / 6.0;  // a solid cube of side s = 1: m s² / 6
    body->mass = float(mass);
    body->inertia_diagonal = {float(inertia), float(inertia), float(inertia)};
  }
  scene.AddBody(light);
  scene.AddBody(heavy);
  for (const int substeps : {4, 1}) {
    SCOPED_TRACE("substeps " + std::to_string(substeps));
    World<T> world(scene);
    Simulate(world, Settings(kDt, substeps), 5.0);
    for (const std::size_t i : {1u, 2u}) {
      SCOPED_TRACE("box " + std::to_string(i));
      const Vec3d x = world.body(i).position.template cast<double>();
      const double start_y = i == 1 ? 0.5 : 1.5;
      if (substeps == 4) {
        EXPECT_LE(Distance(world.body(i).position, 0.0, start_y, 0.0), 0.005);
      } else {
        EXPECT_LE(std::hypot(x.x(), x.z()), 0.03);
        EXPECT_LE(start_y - x.y(), double(i) * kSlop + 0.003);  // one slop per contact below
        EXPECT_LE(x.y(), start_y + 0.001);
      }
      EXPECT_LE(double(world.body(i).rotation.angularDistance(Quat<T>::Identity())), 0.01);
    }
    ASSERT_EQ(world.contact_count(), 3u);
    const ContactConstraint<T>& boxes = world.contact(2);
    ASSERT_EQ(boxes.body1(), 1u);
    ASSERT_EQ(boxes.PointCount(), 4);
    if (substeps == 4) {
      double impulse = 0.0;
      for (int k = 0; k < 4; ++k) impulse += double(boxes.NormalImpulse(k));
      const double weight = 100.0 * kG * kDt / 4.0;
      EXPECT_NEAR(impulse, weight, 0.01 * weight);
    }
  }
}

// A sphere (r 0.25) rolling at 2 m/s along +X on a static table box (half 1,
// 0.5, 1, top at y = 1) from x = 0.5 rolls off the edge at x = 1 and falls
// to the floor: after 2 s it is past the table's edge and rolling on the
// floor, no longer touching the table. It lands from 1 m at 4.4 m/s, 7 cm a
// step, so up to a step's travel inside the floor; the position passes push
// it back out to the slop, 2 cm, as its contact point measures it: that point
// is fixed to the sphere and turns by ω dt = 0.13 rad before the pass, rising
// r (1 − cos ω dt) = 2.2 mm, so the centre rests between r − 2.5 cm and r.
TYPED_TEST(ReferenceBoxContactTest, SphereRollsOffABoxEdgeAndFalls) {
  using T = TypeParam;
  Scene scene;
  scene.AddBody(Floor(0.5f));
  BodySettings table = Box({1.0f, 0.5f, 1.0f}, {0.0f, 0.5f, 0.0f});
  table.motion_type = MotionType::kStatic;
  table.shape.friction = 0.5f;
  scene.AddBody(table);
  BodySettings sphere = Sphere(0.25f, {0.5f, 1.25f, 0.0f});
  sphere.linear_velocity = {2.0f, 0.0f, 0.0f};
  sphere.angular_velocity = {0.0f, 0.0f, -8.0f};  // rolling: ω = −v/r about Z
  sphere.shape.friction = 0.5f;
  scene.AddBody(sphere);
  World<T> world(scene);
  ASSERT_EQ(world.contact_count(), 2u);  // floor–sphere, table–sphere
  world.Step(Settings());
  EXPECT_EQ(world.contact(1).PointCount(), 1);  // on the table at first
  Simulate(world, Settings(), 2.0);
  const Body<T>& body = world.body(2);
  EXPECT_GT(double(body.position.x()), 1.25);
  EXPECT_GT(double(body.position.y()), 0.25 - 0.025);
  EXPECT_LT(double(body.position.y()), 0.25);
  EXPECT_EQ(world.contact(1).PointCount(), 0);
  EXPECT_EQ(world.contact(0).PointCount(), 1);
}

}  // namespace
}  // namespace manyworlds::reference
