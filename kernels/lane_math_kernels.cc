// Compiles the lane maths once per Highway target into a LaneMathKernels
// table (for the lane-by-lane tests), and answers which target the kernels
// dispatch to (include/manyworlds/targets.h).

#include "kernels/lane_math.h"

#include <string>
#include <vector>

#include "manyworlds/targets.h"

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "kernels/lane_math_kernels.cc"
#include "hwy/foreach_target.h"  // IWYU pragma: keep

#include "hwy/highway.h"
#include "kernels/body_access-inl.h"
#include "kernels/lane_math-inl.h"

HWY_BEFORE_NAMESPACE();
namespace manyworlds {
namespace HWY_NAMESPACE {
namespace {

// ---- Lane maths entry points (thin loops over the chunks of a block).

void MathSinCos(const LaneArray& x, LaneArray& sin, LaneArray& cos) {
  ForEachChunk([&](std::size_t offset) {
    LaneVec s, c;
    SinCos(Load(x, offset), s, c);
    Store(s, sin, offset);
    Store(c, cos, offset);
  });
}

void MathCrossDot(const Vec3Lanes& a, const Vec3Lanes& b, Vec3Lanes& cross,
                  LaneArray& dot) {
  ForEachChunk([&](std::size_t offset) {
    const Vec3 va = LoadVec3(a, offset), vb = LoadVec3(b, offset);
    StoreVec3(Cross(va, vb), cross, offset);
    Store(Dot(va, vb), dot, offset);
  });
}

void MathQuatMultiply(const QuatLanes& a, const QuatLanes& b, QuatLanes& product) {
  ForEachChunk([&](std::size_t offset) {
    StoreQuat(Mul(LoadQuat(a, offset), LoadQuat(b, offset)), product, offset);
  });
}

void MathQuatRotate(const QuatLanes& q, const Vec3Lanes& v, Vec3Lanes& rotated,
                    Vec3Lanes& inverse_rotated) {
  ForEachChunk([&](std::size_t offset) {
    const Quat quat = LoadQuat(q, offset);
    const Vec3 vec = LoadVec3(v, offset);
    StoreVec3(Rotate(quat, vec), rotated, offset);
    StoreVec3(InverseRotate(quat, vec), inverse_rotated, offset);
  });
}

void MathQuatNormalize(const QuatLanes& q, QuatLanes& normalized) {
  ForEachChunk([&](std::size_t offset) {
    StoreQuat(Normalize(LoadQuat(q, offset)), normalized, offset);
  });
}

void MathTwistAboutAxis(const QuatLanes& q, int axis, QuatLanes& twist) {
  ForEachChunk([&](std::size_t offset) {
    StoreQuat(TwistAboutAxis(LoadQuat(q, offset), axis), twist, offset);
  });
}

void MathQuatFromAxisAngle(const Vec3Lanes& unit_axis, const LaneArray& angle,
                           QuatLanes& q) {
  ForEachChunk([&](std::size_t offset) {
    StoreQuat(QuatFromAxisAngle(LoadVec3(unit_axis, offset), Load(angle, offset)),
              q, offset);
  });
}

void MathAddRotationStep(QuatLanes& q, const Vec3Lanes& theta) {
  ForEachChunk([&](std::size_t offset) {
    StoreQuat(AddRotationStep(LoadQuat(q, offset), LoadVec3(theta, offset)), q,
              offset);
  });
}

void MathWorldInverseInertia(const BodyLanes& body, Sym33Lanes& matrix) {
  ForEachChunk([&](std::size_t offset) {
    const Sym33 m = BodyInverseInertia(body, offset);
    Store(m.xx, matrix.xx, offset);
    Store(m.xy, matrix.xy, offset);
    Store(m.xz, matrix.xz, offset);
    Store(m.yy, matrix.yy, offset);
    Store(m.yz, matrix.yz, offset);
    Store(m.zz, matrix.zz, offset);
  });
}

void MathInverseInertiaTimes(const BodyLanes& body, const Vec3Lanes& v,
                             Vec3Lanes& product) {
  ForEachChunk([&](std::size_t offset) {
    StoreVec3(BodyInverseInertiaTimes(body, LoadVec3(v, offset), offset), product,
              offset);
  });
}

void MathInverseSym22(const Sym22Lanes& k, Sym22Lanes& inverse,
                      LaneFlags& invertible) {
  ForEachChunk([&](std::size_t offset) {
    LaneMask ok;
    StoreSym22(InverseSym22(LoadSym22(k, offset), ok), inverse, offset);
    StoreFlags(ok, invertible, offset);
  });
}

void MathInverse33(const Mat33Lanes& k, Mat33Lanes& inverse, LaneFlags& invertible) {
  ForEachChunk([&](std::size_t offset) {
    Mat33 m;
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) m.m[i][j] = Load(k.m[i][j], offset);
    }
    LaneMask ok;
    const Mat33 result = Inverse33(m, ok);
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) Store(result.m[i][j], inverse.m[i][j], offset);
    }
    StoreFlags(ok, invertible, offset);
  });
}

void MathAtan(const LaneArray& x, LaneArray& angle) {
  ForEachChunk([&](std::size_t offset) { Store(Atan(Load(x, offset)), angle, offset); });
}

void MathAtan2(const LaneArray& y, const LaneArray& x, LaneArray& angle) {
  ForEachChunk([&](std::size_t offset) {
    Store(Atan2(Load(y, offset), Load(x, offset)), angle, offset);
  });
}

void MathCenterAngleAroundZero(const LaneArray& x, LaneArray& centered) {
  ForEachChunk([&](std::size_t offset) {
    Store(CenterAngleAroundZero(Load(x, offset)), centered, offset);
  });
}

}  // namespace

const LaneMathKernels* GetLaneMathKernels() {
  static const LaneMathKernels kTable = {
      MANYWORLDS_THIS_TARGET,   &MathSinCos,
      &MathCrossDot,            &MathQuatMultiply,
      &MathQuatRotate,          &MathQuatNormalize,
      &MathQuatFromAxisAngle,   &MathAddRotationStep,
      &MathWorldInverseInertia, &MathInverseInertiaTimes,
      &MathInverseSym22,        &MathInverse33,
      &MathAtan,                &MathAtan2,
      &MathCenterAngleAroundZero, &MathTwistAboutAxis,
  };
  return &kTable;
}

}  // namespace HWY_NAMESPACE
}  // namespace manyworlds
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace manyworlds {

MANYWORLDS_EXPORT_KERNEL_TABLE(LaneMathKernels, GetLaneMathKernels)

std::string DispatchedTargetName() {
  return DispatchedKernels<LaneMathKernels>().target.name;
}

std::size_t DispatchedVectorLanes() {
  return DispatchedKernels<LaneMathKernels>().target.vector_lanes;
}

std::vector<std::string> CompiledTargetNames() {
  std::vector<std::string> names;
  for (std::int64_t bits = HWY_TARGETS; bits != 0; bits &= bits - 1) {
    names.emplace_back(hwy::TargetName(bits & -bits));  // lowest bit = best
  }
  return names;
}

std::vector<std::string> SupportedTargetNames() {
  std::vector<std::string> names;
  for (const LaneMathKernels* table : SupportedKernels<LaneMathKernels>()) {
    names.emplace_back(table->target.name);
  }
  return names;
}

}  // namespace manyworlds
#endif  // HWY_ONCE
