// Lane maths: 3-vectors, quaternions and 3x3 / symmetric matrices whose
// components are Highway vectors, one world per lane.
//
// Everything here is per-target code (included once per Highway target through
// foreach_target.h). There are no loops over lanes: every function works on
// whole vectors, and data-dependent decisions (singular matrices, tiny
// rotations) are masks and selects.
//
// Conventions follow Jolt (docs/jolt-constraint-parts.md): quaternions are
// (x, y, z, w) with w the real part, rotations are active, matrices act on
// column vectors.

// Per-target include guard (Highway idiom): toggled for every target pass.
#if defined(MANYWORLDS_KERNELS_LANE_MATH_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef MANYWORLDS_KERNELS_LANE_MATH_INL_H_
#undef MANYWORLDS_KERNELS_LANE_MATH_INL_H_
#else
#define MANYWORLDS_KERNELS_LANE_MATH_INL_H_
#endif

#include <cstddef>

#include "hwy/highway.h"
#include "manyworlds/lanes.h"

HWY_BEFORE_NAMESPACE();
namespace manyworlds {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// One chunk of a block: as many lanes as the target's vector holds, never more
// than a block (so AVX-512 processes a block in one chunk, AVX2 in two).
using LaneTag = hn::CappedTag<float, kLaneWidth>;
using LaneVec = hn::Vec<LaneTag>;
using LaneMask = hn::Mask<LaneTag>;

// Calls chunk(offset) for every chunk of a block, in lane order.
template <class ChunkFn>
HWY_INLINE void ForEachChunk(ChunkFn&& chunk) {
  const LaneTag d;
  const std::size_t step = hn::Lanes(d);
  for (std::size_t offset = 0; offset < kLaneWidth; offset += step) {
    chunk(offset);
  }
}

HWY_INLINE LaneVec Splat(float value) { return hn::Set(LaneTag(), value); }
HWY_INLINE LaneVec Zero() { return hn::Zero(LaneTag()); }

HWY_INLINE LaneVec Load(const LaneArray& array, std::size_t offset) {
  return hn::Load(LaneTag(), array.lanes + offset);
}
HWY_INLINE void Store(LaneVec value, LaneArray& array, std::size_t offset) {
  hn::Store(value, LaneTag(), array.lanes + offset);
}

// a*b - c*d with the rounding error of c*d compensated when the target has FMA
// (Kahan's algorithm, as Jolt's DifferenceOfProducts). Keeps 2x2 determinants
// and cross products of nearly parallel vectors accurate.
HWY_INLINE LaneVec DifferenceOfProducts(LaneVec a, LaneVec b, LaneVec c,
                                        LaneVec d) {
  const LaneVec cd = hn::Mul(c, d);
  const LaneVec cd_error = hn::NegMulAdd(c, d, cd);  // cd - c*d (exact with FMA)
  const LaneVec ab_minus_cd = hn::MulSub(a, b, cd);  // a*b - cd
  return hn::Add(ab_minus_cd, cd_error);
}

// ---------------------------------------------------------------- 3-vectors

struct Vec3 {
  LaneVec x, y, z;
};

HWY_INLINE Vec3 LoadVec3(const Vec3Lanes& v, std::size_t offset) {
  return {Load(v.x, offset), Load(v.y, offset), Load(v.z, offset)};
}
HWY_INLINE void StoreVec3(const Vec3& v, Vec3Lanes& out, std::size_t offset) {
  Store(v.x, out.x, offset);
  Store(v.y, out.y, offset);
  Store(v.z, out.z, offset);
}
HWY_INLINE Vec3 ZeroVec3() { return {Zero(), Zero(), Zero()}; }

HWY_INLINE Vec3 Add(const Vec3& a, const Vec3& b) {
  return {hn::Add(a.x, b.x), hn::Add(a.y, b.y), hn::Add(a.z, b.z)};
}
HWY_INLINE Vec3 Sub(const Vec3& a, const Vec3& b) {
  return {hn::Sub(a.x, b.x), hn::Sub(a.y, b.y), hn::Sub(a.z, b.z)};
}
HWY_INLINE Vec3 Neg(const Vec3& a) {
  return {hn::Neg(a.x), hn::Neg(a.y), hn::Neg(a.z)};
}
HWY_INLINE Vec3 Scale(const Vec3& a, LaneVec s) {
  return {hn::Mul(a.x, s), hn::Mul(a.y, s), hn::Mul(a.z, s)};
}
// a*s + c
HWY_INLINE Vec3 MulAdd(const Vec3& a, LaneVec s, const Vec3& c) {
  return {hn::MulAdd(a.x, s, c.x), hn::MulAdd(a.y, s, c.y),
          hn::MulAdd(a.z, s, c.z)};
}
// c - a*s
HWY_INLINE Vec3 NegMulAdd(const Vec3& a, LaneVec s, const Vec3& c) {
  return {hn::NegMulAdd(a.x, s, c.x), hn::NegMulAdd(a.y, s, c.y),
          hn::NegMulAdd(a.z, s, c.z)};
}
HWY_INLINE LaneVec Dot(const Vec3& a, const Vec3& b) {
  return hn::MulAdd(a.x, b.x, hn::MulAdd(a.y, b.y, hn::Mul(a.z, b.z)));
}
HWY_INLINE LaneVec LengthSquared(const Vec3& a) { return Dot(a, a); }
HWY_INLINE Vec3 Cross(const Vec3& a, const Vec3& b) {
  return {DifferenceOfProducts(a.y, b.z, a.z, b.y),
          DifferenceOfProducts(a.z, b.x, a.x, b.z),
          DifferenceOfProducts(a.x, b.y, a.y, b.x)};
}
HWY_INLINE Vec3 Select(LaneMask mask, const Vec3& yes, const Vec3& no) {
  return {hn::IfThenElse(mask, yes.x, no.x), hn::IfThenElse(mask, yes.y, no.y),
          hn::IfThenElse(mask, yes.z, no.z)};
}

// ------------------------------------------------------------- quaternions

struct Quat {
  LaneVec x, y, z, w;
};

HWY_INLINE Quat LoadQuat(const QuatLanes& q, std::size_t offset) {
  return {Load(q.x, offset), Load(q.y, offset), Load(q.z, offset),
          Load(q.w, offset)};
}
HWY_INLINE void StoreQuat(const Quat& q, QuatLanes& out, std::size_t offset) {
  Store(q.x, out.x, offset);
  Store(q.y, out.y, offset);
  Store(q.z, out.z, offset);
  Store(q.w, out.w, offset);
}

HWY_INLINE Quat Conjugate(const Quat& q) {
  return {hn::Neg(q.x), hn::Neg(q.y), hn::Neg(q.z), q.w};
}

// Hamilton product a*b: w = aw*bw - a.b, xyz = aw*b + bw*a + a x b.
HWY_INLINE Quat Mul(const Quat& a, const Quat& b) {
  const Vec3 av{a.x, a.y, a.z};
  const Vec3 bv{b.x, b.y, b.z};
  const Vec3 xyz = MulAdd(bv, a.w, MulAdd(av, b.w, Cross(av, bv)));
  return {xyz.x, xyz.y, xyz.z, hn::MulSub(a.w, b.w, Dot(av, bv))};
}

HWY_INLINE Quat Normalize(const Quat& q) {
  const LaneVec length_squared = hn::MulAdd(
      q.x, q.x, hn::MulAdd(q.y, q.y, hn::MulAdd(q.z, q.z, hn::Mul(q.w, q.w))));
  const LaneVec inv_length = hn::Div(Splat(1.0f), hn::Sqrt(length_squared));
  return {hn::Mul(q.x, inv_length), hn::Mul(q.y, inv_length),
          hn::Mul(q.z, inv_length), hn::Mul(q.w, inv_length)};
}

HWY_INLINE Quat Select(LaneMask mask, const Quat& yes, const Quat& no) {
  return {hn::IfThenElse(mask, yes.x, no.x), hn::IfThenElse(mask, yes.y, no.y),
          hn::IfThenElse(mask, yes.z, no.z), hn::IfThenElse(mask, yes.w, no.w)};
}

// Rotates v by the unit quaternion q: v + 2w(u x v) + 2u x (u x v), u = q.xyz.
HWY_INLINE Vec3 Rotate(const Quat& q, const Vec3& v) {
  const Vec3 u{q.x, q.y, q.z};
  const Vec3 t = Scale(Cross(u, v), Splat(2.0f));
  return Add(MulAdd(t, q.w, v), Cross(u, t));
}
HWY_INLINE Vec3 InverseRotate(const Quat& q, const Vec3& v) {
  return Rotate(Conjugate(q), v);
}

// sin(x) and cos(x) together. Cephes single-precision minimax polynomials on
// [-pi/4, pi/4] after reducing x by the nearest multiple of pi/2 in three
// parts (Cody-Waite), so the reduction is exact for |x| up to ~8000. Absolute
// error below 2 ulp of 1 on that range (tested against the C library).
HWY_INLINE void SinCos(LaneVec x, LaneVec& sin_out, LaneVec& cos_out) {
  const LaneTag d;
  const hn::RebindToSigned<LaneTag> di;
  const LaneVec abs_x = hn::Abs(x);
  const LaneVec quadrant = hn::Round(hn::Mul(abs_x, Splat(0.63661977236758134f)));
  const auto quadrant_int = hn::ConvertTo(di, quadrant);
  // abs_x - quadrant * pi/2, with pi/2 split into three exactly multipliable parts.
  LaneVec y = hn::NegMulAdd(quadrant, Splat(1.5703125f), abs_x);
  y = hn::NegMulAdd(quadrant, Splat(4.837512969970703125e-4f), y);
  y = hn::NegMulAdd(quadrant, Splat(7.54978995489188216e-8f), y);
  const LaneVec y2 = hn::Mul(y, y);

  LaneVec sin_poly = Splat(-1.9515295891e-4f);
  sin_poly = hn::MulAdd(sin_poly, y2, Splat(8.3321608736e-3f));
  sin_poly = hn::MulAdd(sin_poly, y2, Splat(-1.6666654611e-1f));
  sin_poly = hn::MulAdd(hn::Mul(sin_poly, y2), y, y);

  LaneVec cos_poly = Splat(2.443315711809948e-5f);
  cos_poly = hn::MulAdd(cos_poly, y2, Splat(-1.388731625493765e-3f));
  cos_poly = hn::MulAdd(cos_poly, y2, Splat(4.166664568298827e-2f));
  cos_poly = hn::MulAdd(hn::Mul(cos_poly, y2), y2,
                        hn::NegMulAdd(y2, Splat(0.5f), Splat(1.0f)));

  // Quadrant q: sin = (s, c, -s, -c)[q & 3], cos = (c, -s, -c, s)[q & 3].
  const auto one = hn::Set(di, 1);
  const auto two = hn::Set(di, 2);
  const LaneMask swap =
      hn::RebindMask(d, hn::Eq(hn::And(quadrant_int, one), one));
  const LaneMask negate_sin =
      hn::RebindMask(d, hn::Eq(hn::And(quadrant_int, two), two));
  const LaneMask negate_cos = hn::RebindMask(
      d, hn::Eq(hn::And(hn::Add(quadrant_int, one), two), two));
  const LaneVec sin_abs = hn::IfThenElse(swap, cos_poly, sin_poly);
  const LaneVec cos_abs = hn::IfThenElse(swap, sin_poly, cos_poly);
  // sin is odd: the sign of x flips it on top of the quadrant sign.
  const LaneVec sin_signed = hn::IfThenElse(negate_sin, hn::Neg(sin_abs), sin_abs);
  sin_out = hn::CopySign(hn::Abs(sin_signed), hn::Xor(sin_signed, x));
  cos_out = hn::IfThenElse(negate_cos, hn::Neg(cos_abs), cos_abs);
}

// Rotation of `angle` radians about the unit axis.
HWY_INLINE Quat QuatFromAxisAngle(const Vec3& unit_axis, LaneVec angle) {
  LaneVec half_sin, half_cos;
  SinCos(hn::Mul(angle, Splat(0.5f)), half_sin, half_cos);
  return {hn::Mul(unit_axis.x, half_sin), hn::Mul(unit_axis.y, half_sin),
          hn::Mul(unit_axis.z, half_sin), half_cos};
}

// Jolt's AddRotationStep (spec 1.2): q <- normalize(quat(theta) * q), but only
// in lanes where |theta| > 1e-6; tiny rotations leave q bit-identical.
HWY_INLINE Quat AddRotationStep(const Quat& q, const Vec3& theta) {
  const LaneVec angle = hn::Sqrt(LengthSquared(theta));
  const LaneMask rotates = hn::Gt(angle, Splat(1.0e-6f));
  // Lanes that do not rotate divide by 1 instead of by a tiny or zero angle.
  const LaneVec safe_angle = hn::IfThenElse(rotates, angle, Splat(1.0f));
  const Vec3 axis = Scale(theta, hn::Div(Splat(1.0f), safe_angle));
  const Quat rotated = Normalize(Mul(QuatFromAxisAngle(axis, safe_angle), q));
  return Select(rotates, rotated, q);
}

// ------------------------------------------------------------ 3x3 matrices

// Row-major: m[row][column].
struct Mat33 {
  LaneVec m[3][3];
};

// Symmetric 3x3 (inverse inertia, effective mass): six distinct entries.
struct Sym33 {
  LaneVec xx, xy, xz, yy, yz, zz;
};

// Symmetric 2x2 (two-row parts).
struct Sym22 {
  LaneVec xx, xy, yy;
};

HWY_INLINE Sym22 LoadSym22(const Sym22Lanes& s, std::size_t offset) {
  return {Load(s.xx, offset), Load(s.xy, offset), Load(s.yy, offset)};
}
HWY_INLINE void StoreSym22(const Sym22& s, Sym22Lanes& out, std::size_t offset) {
  Store(s.xx, out.xx, offset);
  Store(s.xy, out.xy, offset);
  Store(s.yy, out.yy, offset);
}

// Rotation matrix of a unit quaternion.
HWY_INLINE Mat33 RotationMatrix(const Quat& q) {
  const LaneVec one = Splat(1.0f);
  const LaneVec two = Splat(2.0f);
  const LaneVec x2 = hn::Mul(q.x, two), y2 = hn::Mul(q.y, two),
                z2 = hn::Mul(q.z, two);
  const LaneVec xx = hn::Mul(q.x, x2), yy = hn::Mul(q.y, y2),
                zz = hn::Mul(q.z, z2);
  const LaneVec xy = hn::Mul(q.x, y2), xz = hn::Mul(q.x, z2),
                yz = hn::Mul(q.y, z2);
  const LaneVec wx = hn::Mul(q.w, x2), wy = hn::Mul(q.w, y2),
                wz = hn::Mul(q.w, z2);
  Mat33 r;
  r.m[0][0] = hn::Sub(one, hn::Add(yy, zz));
  r.m[0][1] = hn::Sub(xy, wz);
  r.m[0][2] = hn::Add(xz, wy);
  r.m[1][0] = hn::Add(xy, wz);
  r.m[1][1] = hn::Sub(one, hn::Add(xx, zz));
  r.m[1][2] = hn::Sub(yz, wx);
  r.m[2][0] = hn::Sub(xz, wy);
  r.m[2][1] = hn::Add(yz, wx);
  r.m[2][2] = hn::Sub(one, hn::Add(xx, yy));
  return r;
}

HWY_INLINE Vec3 Multiply(const Mat33& a, const Vec3& v) {
  return {hn::MulAdd(a.m[0][0], v.x, hn::MulAdd(a.m[0][1], v.y, hn::Mul(a.m[0][2], v.z))),
          hn::MulAdd(a.m[1][0], v.x, hn::MulAdd(a.m[1][1], v.y, hn::Mul(a.m[1][2], v.z))),
          hn::MulAdd(a.m[2][0], v.x, hn::MulAdd(a.m[2][1], v.y, hn::Mul(a.m[2][2], v.z)))};
}

HWY_INLINE Vec3 Multiply(const Sym33& a, const Vec3& v) {
  return {hn::MulAdd(a.xx, v.x, hn::MulAdd(a.xy, v.y, hn::Mul(a.xz, v.z))),
          hn::MulAdd(a.xy, v.x, hn::MulAdd(a.yy, v.y, hn::Mul(a.yz, v.z))),
          hn::MulAdd(a.xz, v.x, hn::MulAdd(a.yz, v.y, hn::Mul(a.zz, v.z)))};
}

// (K * (x, y)) for a symmetric 2x2 K.
HWY_INLINE void Multiply(const Sym22& k, LaneVec x, LaneVec y, LaneVec& out_x,
                         LaneVec& out_y) {
  out_x = hn::MulAdd(k.xx, x, hn::Mul(k.xy, y));
  out_y = hn::MulAdd(k.xy, x, hn::Mul(k.yy, y));
}

// World-space inverse inertia I^-1 = (R_q R_I) diag(D) (R_q R_I)^T (spec 4.3),
// built from the body rotation q, the inertia rotation q_I and the diagonal D.
HWY_INLINE Sym33 WorldInverseInertia(const Quat& rotation,
                                     const Quat& inertia_rotation,
                                     const Vec3& inv_inertia_diagonal) {
  const Mat33 r = RotationMatrix(Mul(rotation, inertia_rotation));
  const LaneVec d[3] = {inv_inertia_diagonal.x, inv_inertia_diagonal.y,
                        inv_inertia_diagonal.z};
  // entry(i, j) = sum_k r[i][k] * d[k] * r[j][k]
  auto entry = [&](int i, int j) {
    return hn::MulAdd(hn::Mul(r.m[i][0], d[0]), r.m[j][0],
                      hn::MulAdd(hn::Mul(r.m[i][1], d[1]), r.m[j][1],
                                 hn::Mul(hn::Mul(r.m[i][2], d[2]), r.m[j][2])));
  };
  return {entry(0, 0), entry(0, 1), entry(0, 2),
          entry(1, 1), entry(1, 2), entry(2, 2)};
}

// I^-1 v in vector form (spec 1.4): rotate into inertia space, scale, rotate back.
HWY_INLINE Vec3 MultiplyWorldInverseInertia(const Quat& rotation,
                                            const Quat& inertia_rotation,
                                            const Vec3& inv_inertia_diagonal,
                                            const Vec3& v) {
  const Quat to_world = Mul(rotation, inertia_rotation);
  const Vec3 local = InverseRotate(to_world, v);
  const Vec3 scaled{hn::Mul(local.x, inv_inertia_diagonal.x),
                    hn::Mul(local.y, inv_inertia_diagonal.y),
                    hn::Mul(local.z, inv_inertia_diagonal.z)};
  return Rotate(to_world, scaled);
}

// Inverse of a symmetric 2x2 matrix by the closed formula. Jolt's rule: a
// determinant of exactly zero means singular; those lanes get a zero inverse
// and `invertible` is false there. No conditioning threshold (spec 5).
HWY_INLINE Sym22 InverseSym22(const Sym22& k, LaneMask& invertible) {
  const LaneVec det = DifferenceOfProducts(k.xx, k.yy, k.xy, k.xy);
  invertible = hn::Ne(det, Zero());
  const LaneVec safe_det = hn::IfThenElse(invertible, det, Splat(1.0f));
  const LaneVec inv_det = hn::Div(Splat(1.0f), safe_det);
  return {hn::IfThenElseZero(invertible, hn::Mul(k.yy, inv_det)),
          hn::IfThenElseZero(invertible, hn::Neg(hn::Mul(k.xy, inv_det))),
          hn::IfThenElseZero(invertible, hn::Mul(k.xx, inv_det))};
}

// Inverse of a general 3x3 matrix: adjugate / det with det = X.(Y x Z) of the
// columns (precise cross products). det == 0 exactly => zero inverse, not
// invertible (Jolt's SetInversed3x3 rule).
HWY_INLINE Mat33 Inverse33(const Mat33& a, LaneMask& invertible) {
  const Vec3 col_x{a.m[0][0], a.m[1][0], a.m[2][0]};
  const Vec3 col_y{a.m[0][1], a.m[1][1], a.m[2][1]};
  const Vec3 col_z{a.m[0][2], a.m[1][2], a.m[2][2]};
  // Rows of the adjugate are the cross products of pairs of columns.
  const Vec3 row0 = Cross(col_y, col_z);
  const Vec3 row1 = Cross(col_z, col_x);
  const Vec3 row2 = Cross(col_x, col_y);
  const LaneVec det = Dot(col_x, row0);
  invertible = hn::Ne(det, Zero());
  const LaneVec inv_det = hn::IfThenElseZero(
      invertible, hn::Div(Splat(1.0f), hn::IfThenElse(invertible, det, Splat(1.0f))));
  Mat33 inverse;
  const Vec3 rows[3] = {Scale(row0, inv_det), Scale(row1, inv_det),
                        Scale(row2, inv_det)};
  for (int i = 0; i < 3; ++i) {
    inverse.m[i][0] = rows[i].x;
    inverse.m[i][1] = rows[i].y;
    inverse.m[i][2] = rows[i].z;
  }
  return inverse;
}

// Symmetric 3x3 inverse through the general one (the adjugate of a symmetric
// matrix is symmetric).
HWY_INLINE Sym33 InverseSym33(const Sym33& k, LaneMask& invertible) {
  Mat33 full;
  full.m[0][0] = k.xx; full.m[0][1] = k.xy; full.m[0][2] = k.xz;
  full.m[1][0] = k.xy; full.m[1][1] = k.yy; full.m[1][2] = k.yz;
  full.m[2][0] = k.xz; full.m[2][1] = k.yz; full.m[2][2] = k.zz;
  const Mat33 inverse = Inverse33(full, invertible);
  return {inverse.m[0][0], inverse.m[0][1], inverse.m[0][2],
          inverse.m[1][1], inverse.m[1][2], inverse.m[2][2]};
}

// Per-lane flags (0 = off) as masks and back.
HWY_INLINE LaneMask LoadFlags(const LaneFlags& flags, std::size_t offset) {
  return hn::Ne(Load(flags, offset), Zero());
}
HWY_INLINE void StoreFlags(LaneMask mask, LaneFlags& flags, std::size_t offset) {
  Store(hn::IfThenElseZero(mask, Splat(1.0f)), flags, offset);
}
// field = 0 in the lanes of `mask` (Deactivate's write).
HWY_INLINE void ClearWhere(LaneMask mask, LaneArray& field, std::size_t offset) {
  Store(hn::IfThenZeroElse(mask, Load(field, offset)), field, offset);
}

// True if any lane of the mask is set (for "did any world apply an impulse").
HWY_INLINE bool AnyLane(LaneMask mask) { return !hn::AllFalse(LaneTag(), mask); }

}  // namespace HWY_NAMESPACE
}  // namespace manyworlds
HWY_AFTER_NAMESPACE();

#endif  // MANYWORLDS_KERNELS_LANE_MATH_INL_H_
