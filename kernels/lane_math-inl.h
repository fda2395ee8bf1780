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

// Masks with every lane of a chunk set / none set (Highway 1.0.3 has no MaskFalse).
HWY_INLINE hn::Mask<LaneTag> AllLanes() { return hn::FirstN(LaneTag(), kLaneWidth); }
HWY_INLINE hn::Mask<LaneTag> NoLanes() { return hn::FirstN(LaneTag(), 0); }

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

// 1/x where x != 0, else 0, with `nonzero` telling which: Jolt's rule that an
// exactly zero inverse effective mass (or determinant) means inactive.
HWY_INLINE LaneVec ReciprocalOrZero(LaneVec x, hn::Mask<LaneTag>& nonzero) {
  nonzero = hn::Ne(x, Zero());
  return hn::IfThenElseZero(nonzero,
                            hn::Div(Splat(1.0f), hn::IfThenElse(nonzero, x, Splat(1.0f))));
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

HWY_INLINE Quat IdentityQuat() { return {Zero(), Zero(), Zero(), Splat(1.0f)}; }

HWY_INLINE LaneVec QuatDot(const Quat& a, const Quat& b) {
  return hn::MulAdd(a.x, b.x, hn::MulAdd(a.y, b.y, hn::MulAdd(a.z, b.z, hn::Mul(a.w, b.w))));
}

// Jolt's Quat::GetTwist about the principal axis `axis` (0 = X, 1 = Y, 2 = Z):
// the rotation about that axis in a swing-twist split of q, i.e. q's
// component along the axis and w, normalised; the identity where both are 0.
HWY_INLINE Quat TwistAboutAxis(const Quat& q, int axis) {
  const LaneVec along = axis == 0 ? q.x : axis == 1 ? q.y : q.z;
  const LaneVec length_squared = hn::MulAdd(along, along, hn::Mul(q.w, q.w));
  const LaneMask regular = hn::Ne(length_squared, Zero());
  const LaneVec inv_length =
      hn::Div(Splat(1.0f), hn::Sqrt(hn::IfThenElse(regular, length_squared, Splat(1.0f))));
  const LaneVec a = hn::IfThenElse(regular, hn::Mul(along, inv_length), Zero());
  const LaneVec w = hn::IfThenElse(regular, hn::Mul(q.w, inv_length), Splat(1.0f));
  return {axis == 0 ? a : Zero(), axis == 1 ? a : Zero(), axis == 2 ? a : Zero(), w};
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
  // A NaN x gives a NaN quadrant, and converting NaN to int is undefined
  // behaviour on Highway's SCALAR target (a plain static_cast; UBSan reports
  // it). Such lanes come out NaN whatever the quadrant, so convert 0 instead.
  const auto quadrant_int =
      hn::ConvertTo(di, hn::IfThenElseZero(hn::Eq(quadrant, quadrant), quadrant));
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
  // A chunk where no lane turns (bodies at rest, a part with no error)
  // skips the division, sine, cosine and normalisation: every lane keeps q,
  // as the select below would give it.
  if (hn::AllFalse(LaneTag(), rotates)) return q;
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

HWY_INLINE Vec3 Column(const Mat33& m, int j) { return {m.m[0][j], m.m[1][j], m.m[2][j]}; }

// out = m, entry by entry. Where a Mat33 is assigned to an existing object
// (an out parameter, a member, one of two values chosen at run time) the
// compiler may keep the aggregate in memory and copy it whole: 288 bytes on
// AVX2's 32-byte vectors became `rep movsq`, too long for its move-by-pieces
// limit, and those copies took 40 % of the exact solve's K assembly there.
// Entry by entry, the values stay in registers or plain vector moves.
HWY_INLINE void Assign(Mat33& out, const Mat33& m) {
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) out.m[i][j] = m.m[i][j];
  }
}

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
  const Vec3 col_x = Column(a, 0);
  const Vec3 col_y = Column(a, 1);
  const Vec3 col_z = Column(a, 2);
  // Rows of the adjugate are the cross products of pairs of columns.
  const Vec3 row0 = Cross(col_y, col_z);
  const Vec3 row1 = Cross(col_z, col_x);
  const Vec3 row2 = Cross(col_x, col_y);
  const LaneVec det = Dot(col_x, row0);
  const LaneVec inv_det = ReciprocalOrZero(det, invertible);
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

// ------------------------------------- unit vectors (added with hinge rotation)

// v / |v|; a zero vector stays zero instead of becoming NaN, so zeroed
// padding lanes stay finite. (FLT_MIN changes no non-zero float vector whose
// squared length is a normal float.)
HWY_INLINE Vec3 Normalize(const Vec3& v) {
  const LaneVec length_squared = hn::Max(LengthSquared(v), Splat(1.17549435e-38f));
  return Scale(v, hn::Div(Splat(1.0f), hn::Sqrt(length_squared)));
}

// A unit vector perpendicular to the unit vector v, chosen as Jolt's
// Vec3::GetNormalizedPerpendicular does (per lane): (z, 0, -x)/sqrt(x^2+z^2) if
// |x| > |y|, else (0, z, -y)/sqrt(y^2+z^2). The choice decides the basis of the
// hinge's two rows, so it must match Jolt's, ties (|x| == |y|) included.
// The zero vector (padding lanes) gives zero, not NaN.
HWY_INLINE Vec3 NormalizedPerpendicular(const Vec3& v) {
  const LaneMask use_x = hn::Gt(hn::Abs(v.x), hn::Abs(v.y));
  const LaneVec x_or_y = hn::IfThenElse(use_x, v.x, v.y);
  // For a unit v the squared length is >= 1/2, so the floor changes nothing.
  const LaneVec length_squared = hn::Max(hn::MulAdd(x_or_y, x_or_y, hn::Mul(v.z, v.z)),
                                         Splat(1.17549435e-38f));
  const LaneVec inv_length = hn::Div(Splat(1.0f), hn::Sqrt(length_squared));
  return {hn::IfThenElseZero(use_x, hn::Mul(v.z, inv_length)),
          hn::IfThenZeroElse(use_x, hn::Mul(v.z, inv_length)),
          hn::Neg(hn::Mul(x_or_y, inv_length))};
}

// ------------------------------------------ end of the hinge-rotation helpers

// ---------------------------------------- angles: atan, atan2, wrap (begin)
// Added with the swing-twist part; Highway 1.0.3's contrib/math has no Atan2,
// so all three are written here from polynomials.

// pi and pi/2 as the nearest float, and the float nearest to the rest of
// pi/2 (adding it last makes atan's pi/2 + r and pi/4 + r accurate to
// ~1 ulp instead of ~1.5).
inline constexpr float kPiHigh = 3.14159274101257324f;
inline constexpr float kHalfPiHigh = 1.57079637050628662f;
inline constexpr float kHalfPiLow = -4.37113882867379289e-8f;

// atan(t) for t >= 0 (including +inf). Cephes atanf: reduce to |r| <=
// tan(pi/8) with atan(t) = pi/2 + atan(-1/t) above tan(3 pi/8) and
// pi/4 + atan((t - 1)/(t + 1)) above tan(pi/8), then the degree-9 odd minimax
// polynomial. One division whatever the branch (selects, not branches).
HWY_INLINE LaneVec AtanOfNonNegative(LaneVec t) {
  const LaneVec one = Splat(1.0f);
  const LaneMask above_3pi_8 = hn::Gt(t, Splat(2.414213562373095f));
  const LaneMask above_pi_8 = hn::Gt(t, Splat(0.4142135623730950f));
  const LaneVec numerator = hn::IfThenElse(
      above_3pi_8, hn::Neg(one), hn::IfThenElse(above_pi_8, hn::Sub(t, one), t));
  const LaneVec denominator = hn::IfThenElse(
      above_3pi_8, t, hn::IfThenElse(above_pi_8, hn::Add(t, one), one));
  const LaneVec r = hn::Div(numerator, denominator);
  const LaneVec offset_high = hn::IfThenElse(
      above_3pi_8, Splat(kHalfPiHigh),
      hn::IfThenElseZero(above_pi_8, Splat(0.5f * kHalfPiHigh)));
  const LaneVec offset_low = hn::IfThenElse(
      above_3pi_8, Splat(kHalfPiLow),
      hn::IfThenElseZero(above_pi_8, Splat(0.5f * kHalfPiLow)));
  const LaneVec z = hn::Mul(r, r);
  LaneVec p = Splat(8.05374449538e-2f);
  p = hn::MulAdd(p, z, Splat(-1.38776856032e-1f));
  p = hn::MulAdd(p, z, Splat(1.99777106478e-1f));
  p = hn::MulAdd(p, z, Splat(-3.33329491539e-1f));
  // r + r z p, then the offset's low part, then its high part: smallest first.
  const LaneVec atan_r = hn::MulAdd(hn::Mul(p, z), r, r);
  return hn::Add(offset_high, hn::Add(atan_r, offset_low));
}

// atan(x) for every float: odd, so atan(|x|) with the sign of x (atan(-0) =
// -0, atan(+-inf) = +-pi/2, NaN stays NaN).
HWY_INLINE LaneVec Atan(LaneVec x) {
  return hn::CopySign(AtanOfNonNegative(hn::Abs(x)), x);
}

// atan2(y, x) with the C library's quadrants and special cases: the sign of
// y (also of +-0) gives the sign of the result, a negative x (also -0) the
// half plane, so atan2(+-0, +0) = +-0, atan2(+-0, -0) = +-pi, atan2(y, +-0) =
// +-pi/2, atan2(+-inf, +-inf) = +-pi/4 or +-3pi/4; NaN in, NaN out.
// The smaller magnitude is divided by the larger, so the ratio is in [0, 1]
// and never overflows.
HWY_INLINE LaneVec Atan2(LaneVec y, LaneVec x) {
  const LaneVec abs_x = hn::Abs(x);
  const LaneVec abs_y = hn::Abs(y);
  const LaneMask y_larger = hn::Lt(abs_x, abs_y);  // false for NaN: NaN / ... = NaN
  const LaneVec smaller = hn::IfThenElse(y_larger, abs_x, abs_y);
  const LaneVec larger = hn::IfThenElse(y_larger, abs_y, abs_x);
  // Equal magnitudes: ratio 1 (inf / inf would be NaN), or 0 when both are
  // zero (0 / 0 would be NaN).
  const LaneMask equal = hn::Eq(smaller, larger);
  const LaneVec equal_ratio = hn::IfThenElseZero(hn::Ne(larger, Zero()), Splat(1.0f));
  const LaneVec ratio =
      hn::IfThenElse(equal, equal_ratio, hn::Div(smaller, larger));
  LaneVec angle = AtanOfNonNegative(ratio);  // in [0, pi/4]
  // atan(|y|/|x|) = pi/2 - atan(|x|/|y|)
  angle = hn::IfThenElse(y_larger, hn::Sub(Splat(kHalfPiHigh), angle), angle);
  // Left half plane, including x = -0: pi - angle.
  const LaneMask x_negative = hn::Lt(hn::CopySign(Splat(1.0f), x), Zero());
  angle = hn::IfThenElse(x_negative, hn::Sub(Splat(kPiHigh), angle), angle);
  return hn::CopySign(angle, y);
}

// x - turns * 2 pi with 2 pi in three parts (Cody-Waite): the first two
// products are exact for |turns| < 2^13, so the result is x minus whole turns
// of the true 2 pi, rounded about once.
HWY_INLINE LaneVec SubtractTurns(LaneVec x, LaneVec turns) {
  LaneVec r = hn::NegMulAdd(turns, Splat(6.28125f), x);
  r = hn::NegMulAdd(turns, Splat(1.93500518798828125e-3f), r);
  return hn::NegMulAdd(turns, Splat(3.01991598195675286e-7f), r);
}

// Jolt's CenterAngleAroundZero (spec 5) without its loop: x - 2 pi k with
// k = round(x / 2 pi), accurate for |x| up to ~50000 (2^13 turns).
// Semantics of the loop kept exactly where it matters:
//  - |x| <= pi (float pi) returns x bit for bit (k = 0), including +-pi and -0;
//  - the result is in [-pi, pi]; an input that lands on the boundary gives
//    +pi when x > 0 and -pi when x < 0, as the loop does (it stops at the
//    first value inside the range).
HWY_INLINE LaneVec CenterAngleAroundZero(LaneVec x) {
  const LaneVec pi = Splat(kPiHigh);
  const LaneVec one = Splat(1.0f);
  LaneVec turns = hn::Round(hn::Mul(x, Splat(0.159154943091895336f)));
  const LaneVec first = SubtractTurns(x, turns);
  // x / 2 pi rounded in float can pick the neighbouring turn near odd
  // multiples of pi: take one turn more or less and reduce again (instead of
  // adding a float 2 pi, whose error is 0.7 ulp of pi).
  turns = hn::Add(turns, hn::IfThenElseZero(hn::Gt(first, pi), one));
  turns = hn::Sub(turns, hn::IfThenElseZero(hn::Lt(first, hn::Neg(pi)), one));
  const LaneVec r = SubtractTurns(x, turns);
  // On the boundary the loop keeps the sign of x. (Inside the range turns is
  // 0: pi * 1/(2 pi) rounds to exactly 0.5, which rounds to even 0, so r is
  // x bit for bit there, and this select keeps +-pi as they are.)
  return hn::IfThenElse(hn::Eq(hn::Abs(r), pi), hn::CopySign(pi, x), r);
}

// (-pi, pi] angles a and b: a - b folded once into [-pi, pi].
HWY_INLINE LaneVec FoldedDifference(LaneVec a, LaneVec b) {
  const LaneVec two_pi = Splat(6.2831853071795865f);
  const LaneVec d = hn::Sub(a, b);
  const LaneVec up = hn::IfThenElse(hn::Gt(d, Splat(kPiHigh)), hn::Sub(d, two_pi), d);
  return hn::IfThenElse(hn::Lt(up, Splat(-kPiHigh)), hn::Add(up, two_pi), up);
}

// A hinge's unwrapped angle: its angle now, theta in (-pi, pi], continued
// from the angle and the whole turns counted at its last setup (reference
// in (-pi, pi], turns): reference + 2 pi turns + (theta - reference) folded
// once, so a hinge that turned less than pi since the setup reads on
// continuously across +-pi.
HWY_INLINE LaneVec UnwrappedAngle(LaneVec theta, LaneVec reference, LaneVec turns) {
  return hn::Add(hn::MulAdd(Splat(6.2831853071795865f), turns, reference),
                 FoldedDifference(theta, reference));
}
// ------------------------------------------ angles: atan, atan2, wrap (end)

// ------------- 3x3 storage, quaternion from matrix (begin)
// Added with the point and rotation Euler/quat parts.

HWY_INLINE Sym33 LoadSym33(const Sym33Lanes& s, std::size_t offset) {
  return {Load(s.xx, offset), Load(s.xy, offset), Load(s.xz, offset),
          Load(s.yy, offset), Load(s.yz, offset), Load(s.zz, offset)};
}
HWY_INLINE void StoreSym33(const Sym33& s, Sym33Lanes& out, std::size_t offset) {
  Store(s.xx, out.xx, offset);
  Store(s.xy, out.xy, offset);
  Store(s.xz, out.xz, offset);
  Store(s.yy, out.yy, offset);
  Store(s.yz, out.yz, offset);
  Store(s.zz, out.zz, offset);
}
HWY_INLINE Mat33 LoadMat33(const Mat33Lanes& m, std::size_t offset) {
  Mat33 out;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) out.m[i][j] = Load(m.m[i][j], offset);
  }
  return out;
}
HWY_INLINE void StoreMat33(const Mat33& m, Mat33Lanes& out, std::size_t offset) {
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) Store(m.m[i][j], out.m[i][j], offset);
  }
}

HWY_INLINE Sym33 ZeroSym33() {
  return {Zero(), Zero(), Zero(), Zero(), Zero(), Zero()};
}
HWY_INLINE Mat33 ZeroMat33() {
  Mat33 zero;
  for (auto& row : zero.m) row[0] = row[1] = row[2] = Zero();
  return zero;
}

// Lanes where any component is non-zero (an impulse was applied, a matrix is
// not the zero of a deactivated part).
HWY_INLINE LaneMask AnyComponentNonZero(const Vec3& v) {
  return hn::Or(hn::Or(hn::Ne(v.x, Zero()), hn::Ne(v.y, Zero())), hn::Ne(v.z, Zero()));
}
HWY_INLINE LaneMask AnyComponentNonZero(LaneVec a, LaneVec b) {
  return hn::Or(hn::Ne(a, Zero()), hn::Ne(b, Zero()));
}
HWY_INLINE LaneMask AnyComponentNonZero(const Sym33& s) {
  return hn::Or(AnyComponentNonZero(Vec3{s.xx, s.xy, s.xz}),
                AnyComponentNonZero(Vec3{s.yy, s.yz, s.zz}));
}

// Every field = 0 in the lanes of `mask` (Deactivate's write).
HWY_INLINE void ClearWhere(LaneMask mask, Vec3Lanes& v, std::size_t offset) {
  ClearWhere(mask, v.x, offset);
  ClearWhere(mask, v.y, offset);
  ClearWhere(mask, v.z, offset);
}
HWY_INLINE void ClearWhere(LaneMask mask, Sym33Lanes& s, std::size_t offset) {
  for (LaneArray* field : {&s.xx, &s.xy, &s.xz, &s.yy, &s.yz, &s.zz}) {
    ClearWhere(mask, *field, offset);
  }
}
HWY_INLINE void ClearWhere(LaneMask mask, Mat33Lanes& m, std::size_t offset) {
  for (auto& row : m.m) {
    for (LaneArray& field : row) ClearWhere(mask, field, offset);
  }
}

HWY_INLINE Sym33 Add(const Sym33& a, const Sym33& b) {
  return {hn::Add(a.xx, b.xx), hn::Add(a.xy, b.xy), hn::Add(a.xz, b.xz),
          hn::Add(a.yy, b.yy), hn::Add(a.yz, b.yz), hn::Add(a.zz, b.zz)};
}

HWY_INLINE Mat33 Transpose(const Mat33& a) {
  Mat33 t;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) t.m[i][j] = a.m[j][i];
  }
  return t;
}

// a * b for a symmetric a (column j of the product is a * column j of b).
HWY_INLINE Mat33 Multiply(const Sym33& a, const Mat33& b) {
  Mat33 product;
  for (int j = 0; j < 3; ++j) {
    const Vec3 column = Multiply(a, Vec3{b.m[0][j], b.m[1][j], b.m[2][j]});
    product.m[0][j] = column.x;
    product.m[1][j] = column.y;
    product.m[2][j] = column.z;
  }
  return product;
}

// q where w >= 0, else -q: the same rotation, the shorter way round (Jolt's
// EnsureWPositive).
HWY_INLINE Quat EnsureWPositive(const Quat& q) {
  const LaneMask negative = hn::Lt(q.w, Zero());
  return {hn::IfThenElse(negative, hn::Neg(q.x), q.x),
          hn::IfThenElse(negative, hn::Neg(q.y), q.y),
          hn::IfThenElse(negative, hn::Neg(q.z), q.z),
          hn::IfThenElse(negative, hn::Neg(q.w), q.w)};
}

// Unit quaternion of a rotation matrix (Shepperd's method, branch choice as
// Jolt's Mat44::GetQuaternion): trace >= 0 solves for w first; otherwise for
// the component of the largest diagonal entry (first one on ties), which keeps
// the square root away from zero. One square root and one division per lane:
// the branch only selects what goes into them. The result's sign follows the
// branch (w > 0, or the chosen component > 0).
HWY_INLINE Quat QuatFromRotationMatrix(const Mat33& m) {
  const LaneVec one = Splat(1.0f), half = Splat(0.5f);
  const LaneVec m00 = m.m[0][0], m11 = m.m[1][1], m22 = m.m[2][2];
  const LaneMask solve_w = hn::Ge(hn::Add(hn::Add(m00, m11), m22), Zero());
  const LaneMask y_over_x = hn::Gt(m11, m00);
  const LaneVec largest_xy = hn::IfThenElse(y_over_x, m11, m00);
  const LaneMask solve_z = hn::AndNot(solve_w, hn::Gt(m22, largest_xy));
  const LaneMask solve_y =
      hn::AndNot(solve_w, hn::AndNot(hn::Gt(m22, largest_xy), y_over_x));
  const LaneMask solve_x = hn::AndNot(solve_w, hn::AndNot(solve_z, hn::Not(y_over_x)));
  // 4 c^2 - 1 for the component c solved first: 1 + trace for w,
  // 1 + 2 m_ii - trace for x, y, z.
  const LaneVec radicand = hn::IfThenElse(
      solve_w, hn::Add(hn::Add(hn::Add(m00, m11), m22), one),
      hn::IfThenElse(solve_x, hn::Add(hn::Sub(m00, hn::Add(m11, m22)), one),
                     hn::IfThenElse(solve_y, hn::Add(hn::Sub(m11, hn::Add(m22, m00)), one),
                                    hn::Add(hn::Sub(m22, hn::Add(m00, m11)), one))));
  const LaneVec s = hn::Sqrt(radicand);
  const LaneVec inv_4c = hn::Div(half, s);  // 1 / (4 c) with c = s / 2
  const LaneVec solved = hn::Mul(half, s);
  // 4 w x, 4 w y, 4 w z, 4 x y, 4 x z, 4 y z from the off-diagonal entries.
  const LaneVec wx = hn::Mul(hn::Sub(m.m[2][1], m.m[1][2]), inv_4c);
  const LaneVec wy = hn::Mul(hn::Sub(m.m[0][2], m.m[2][0]), inv_4c);
  const LaneVec wz = hn::Mul(hn::Sub(m.m[1][0], m.m[0][1]), inv_4c);
  const LaneVec xy = hn::Mul(hn::Add(m.m[0][1], m.m[1][0]), inv_4c);
  const LaneVec xz = hn::Mul(hn::Add(m.m[0][2], m.m[2][0]), inv_4c);
  const LaneVec yz = hn::Mul(hn::Add(m.m[1][2], m.m[2][1]), inv_4c);
  // Each other component is its product with the solved one over 4 c.
  auto pick = [&](LaneVec if_w, LaneVec if_x, LaneVec if_y, LaneVec if_z) {
    return hn::IfThenElse(
        solve_w, if_w,
        hn::IfThenElse(solve_x, if_x, hn::IfThenElse(solve_y, if_y, if_z)));
  };
  return {pick(wx, solved, xy, xz), pick(wy, xy, solved, yz),
          pick(wz, xz, yz, solved), pick(solved, wx, wy, wz)};
}
// --------------- 3x3 storage, quaternion from matrix (end)


// ----------------------------------------------------- Deactivate / IsActive
// Jolt's Deactivate and IsActive (spec 1.3) for every part that stores its
// effective mass as `effective_mass` (LaneArray, Sym22Lanes or Sym33Lanes) and
// its accumulated impulse as `persistent.total_lambda`.

HWY_INLINE void ClearWhere(LaneMask mask, Vec2Lanes& v, std::size_t offset) {
  ClearWhere(mask, v.x, offset);
  ClearWhere(mask, v.y, offset);
}
HWY_INLINE void ClearWhere(LaneMask mask, Sym22Lanes& s, std::size_t offset) {
  ClearWhere(mask, s.xx, offset);
  ClearWhere(mask, s.xy, offset);
  ClearWhere(mask, s.yy, offset);
}

HWY_INLINE LaneMask NonZeroLanes(const LaneArray& field, std::size_t offset) {
  return hn::Ne(Load(field, offset), Zero());
}
HWY_INLINE LaneMask NonZeroLanes(const Sym22Lanes& s, std::size_t offset) {
  return hn::Or(hn::Or(NonZeroLanes(s.xx, offset), NonZeroLanes(s.xy, offset)),
                NonZeroLanes(s.yy, offset));
}
HWY_INLINE LaneMask NonZeroLanes(const Sym33Lanes& s, std::size_t offset) {
  return AnyComponentNonZero(LoadSym33(s, offset));
}

// Deactivate the flagged lanes: zero effective mass and accumulated impulse.
template <class PartLanes>
HWY_INLINE void DeactivateFlaggedLanes(PartLanes& part, const LaneFlags& lanes) {
  ForEachChunk([&](std::size_t offset) {
    const LaneMask off = LoadFlags(lanes, offset);
    ClearWhere(off, part.effective_mass, offset);
    ClearWhere(off, part.persistent.total_lambda, offset);
  });
}

// flag = 1 where the effective mass is not zero (active), else 0.
template <class PartLanes>
HWY_INLINE void StoreActiveLanes(const PartLanes& part, LaneFlags& active) {
  ForEachChunk([&](std::size_t offset) {
    StoreFlags(NonZeroLanes(part.effective_mass, offset), active, offset);
  });
}

// offset / length (divided as Jolt divides, per component), or `previous`
// where the length is not positive: the direction of a rope, rod or cone
// axis that keeps its last direction when it degenerates (spec 5).
HWY_INLINE Vec3 DirectionOrPrevious(const Vec3& offset_vector, LaneVec length,
                                    const Vec3& previous) {
  const LaneMask has_length = hn::Gt(length, Zero());
  const LaneVec divisor = hn::IfThenElse(has_length, length, Splat(1.0f));
  const Vec3 unit{hn::Div(offset_vector.x, divisor), hn::Div(offset_vector.y, divisor),
                  hn::Div(offset_vector.z, divisor)};
  return Select(has_length, unit, previous);
}

// For a struct made only of LaneArrays: the lanes of `value` that are not set
// in `changed` get `previous`'s bits back. For verbs that Jolt runs in some
// worlds only (a recompute where a position error is non-zero): run them in
// every lane on a copy's worth of state, then keep the result where they ran.
template <class Lanes>
HWY_INLINE void KeepChangedLanes(const LaneFlags& changed, Lanes& value, const Lanes& previous) {
  static_assert(sizeof(Lanes) % sizeof(LaneArray) == 0, "a struct of LaneArrays");
  constexpr std::size_t kArrays = sizeof(Lanes) / sizeof(LaneArray);
  LaneArray* out = reinterpret_cast<LaneArray*>(&value);
  const LaneArray* old = reinterpret_cast<const LaneArray*>(&previous);
  ForEachChunk([&](std::size_t offset) {
    const LaneMask keep_new = LoadFlags(changed, offset);
    for (std::size_t i = 0; i < kArrays; ++i) {
      Store(hn::IfThenElse(keep_new, Load(out[i], offset), Load(old[i], offset)), out[i],
            offset);
    }
  });
}

}  // namespace HWY_NAMESPACE
}  // namespace manyworlds
HWY_AFTER_NAMESPACE();

#endif  // MANYWORLDS_KERNELS_LANE_MATH_INL_H_
