// RotationEulerConstraintPart across worlds: three angular rows that keep the
// rotation of body 2 relative to body 1 at its rest value r0 (fixed, slider,
// six-DOF and path constraints; swing-twist's position phase). Spec 2.6.
//
//   r0^-1 = inverse rest rotation (q2 = q1 r0 at rest).
//   diff = q2 r0^-1 q1*, made w >= 0 (the shorter way round)
//   C    = 2 xyz(diff)          (small-angle rotation vector of the error)
//   J    = [ 0, -E, 0, E ]
//   K    = [dyn1] I1^-1 + [dyn2] I2^-1   (symmetric 3x3)
//
// Inversion with the zero-column fix (Jolt commit b385bc3d, for bodies whose
// rotation is locked about a world axis): where det K == 0, every all-zero
// column of K is replaced by the identity column and K inverted again; still
// singular => Deactivate. Locked axes stay locked because every impulse is
// multiplied by I^-1, which is zero on them. We apply the replacement before
// the first inversion: with finite entries a zero column makes det exactly 0,
// and an invertible K has no zero column, so one inversion gives the same
// result as Jolt's two. K is symmetric, so column i zero <=> row i zero, and
// the fixed K stays symmetric (only its diagonal entry becomes 1).
//
// Velocity step:  dL = K^-1 (w1 - w2),  L += dL,  w1 -= I1^-1 dL,  w2 += I2^-1 dL.
// Position step:  where C != 0: L = -beta K^-1 C, rotate body 1 by -I1^-1 L
//                 and body 2 by +I2^-1 L.
// Only dynamic bodies are written; static bodies read as zero velocity.
//
// The per-chunk functions RotationEulerPropertiesOfChunk and
// RotationEulerPositionStepOfChunk are also the building blocks of parts that
// solve their position phase with a temporary rotation-Euler part
// (swing-twist): they work on registers, with r0^-1 and the lanes to solve
// given per lane.

#if defined(MANYWORLDS_KERNELS_ROTATION_EULER_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef MANYWORLDS_KERNELS_ROTATION_EULER_INL_H_
#undef MANYWORLDS_KERNELS_ROTATION_EULER_INL_H_
#else
#define MANYWORLDS_KERNELS_ROTATION_EULER_INL_H_
#endif

#include <cstddef>

#include "kernels/body_access-inl.h"
#include "kernels/lane_math-inl.h"
#include "kernels/rotation_euler.h"

HWY_BEFORE_NAMESPACE();
namespace manyworlds {
namespace HWY_NAMESPACE {

// The calculated properties of one chunk of a rotation-Euler part.
struct RotationEulerChunk {
  Sym33 inv_i1;          // zero unless body 1 is dynamic
  Sym33 inv_i2;          // zero unless body 2 is dynamic
  Sym33 effective_mass;  // K^-1 after the zero-column fix; zero where singular
};

namespace rotation_euler {

// K with every all-zero column (and, K being symmetric, row) replaced by the
// identity's: only the diagonal entry changes.
HWY_INLINE Sym33 ReplaceZeroColumnsByIdentity(const Sym33& k) {
  const LaneVec one = Splat(1.0f);
  const LaneMask x_zero = hn::Not(AnyComponentNonZero(Vec3{k.xx, k.xy, k.xz}));
  const LaneMask y_zero = hn::Not(AnyComponentNonZero(Vec3{k.xy, k.yy, k.yz}));
  const LaneMask z_zero = hn::Not(AnyComponentNonZero(Vec3{k.xz, k.yz, k.zz}));
  return {hn::IfThenElse(x_zero, one, k.xx), k.xy, k.xz,
          hn::IfThenElse(y_zero, one, k.yy), k.yz,
          hn::IfThenElse(z_zero, one, k.zz)};
}

// Applies the angular impulse `lambda`: body 1 gets -I1^-1 lambda, body 2
// +I2^-1 lambda. kVelocity = false makes it a rotation step. `where` (velocity
// steps only): the lanes that take the step (AddAngularVelocityStep).
template <bool kVelocity, class Where = std::nullptr_t>
HWY_INLINE void ApplyImpulse(const BodyPair& bodies, const Sym33& inv_i1,
                             const Sym33& inv_i2, const Vec3& lambda,
                             std::size_t offset, Where where = nullptr) {
  if (bodies.motion1 == MotionType::kDynamic) {
    const Vec3 angular = Neg(Multiply(inv_i1, lambda));
    if (kVelocity) {
      AddAngularVelocityStep(*bodies.body1, angular, offset, where);
    } else {
      AddRotationStep(*bodies.body1, angular, offset);
    }
  }
  if (bodies.motion2 == MotionType::kDynamic) {
    const Vec3 angular = Multiply(inv_i2, lambda);
    if (kVelocity) {
      AddAngularVelocityStep(*bodies.body2, angular, offset, where);
    } else {
      AddRotationStep(*bodies.body2, angular, offset);
    }
  }
}

HWY_INLINE RotationEulerChunk LoadChunk(const RotationEulerLanes& part,
                                        std::size_t offset) {
  return {LoadSym33(part.inv_i1, offset), LoadSym33(part.inv_i2, offset),
          LoadSym33(part.effective_mass, offset)};
}

// quat(C) of the constraint frame with columns (a, b, c).
HWY_INLINE Quat FrameRotation(const Vec3& a, const Vec3& b, const Vec3& c) {
  Mat33 frame;
  const Vec3 columns[3] = {a, b, c};
  for (int j = 0; j < 3; ++j) {
    frame.m[0][j] = columns[j].x;
    frame.m[1][j] = columns[j].y;
    frame.m[2][j] = columns[j].z;
  }
  return QuatFromRotationMatrix(frame);
}

// r0^-1 = quat(C2) quat(C1)*, identity where both frames' axes are equal.
HWY_INLINE Quat InverseInitialOrientationFromFrames(const Vec3& first1,
                                                    const Vec3& second1,
                                                    const Quat& frame1,
                                                    const Vec3& first2,
                                                    const Vec3& second2,
                                                    const Quat& frame2) {
  const LaneMask same = hn::And(
      hn::Not(AnyComponentNonZero(Sub(first1, first2))),
      hn::Not(AnyComponentNonZero(Sub(second1, second2))));
  return Select(same, IdentityQuat(), Mul(frame2, Conjugate(frame1)));
}

// Stores one chunk's calculated properties into the part.
HWY_INLINE void StoreProperties(const RotationEulerChunk& chunk, RotationEulerLanes& part,
                                std::size_t offset) {
  StoreSym33(chunk.inv_i1, part.inv_i1, offset);
  StoreSym33(chunk.inv_i2, part.inv_i2, offset);
  StoreSym33(chunk.effective_mass, part.effective_mass, offset);
}

}  // namespace rotation_euler

// K = I1^-1 + I2^-1 at the bodies' current rotations, inverted with the
// zero-column fix. `active` = lanes whose K could be inverted.
HWY_INLINE RotationEulerChunk RotationEulerPropertiesOfChunk(const BodyPair& bodies,
                                                             std::size_t offset,
                                                             LaneMask& active) {
  RotationEulerChunk chunk{ZeroSym33(), ZeroSym33(), ZeroSym33()};
  if (bodies.motion1 == MotionType::kDynamic) {
    chunk.inv_i1 = BodyInverseInertia(*bodies.body1, offset);
  }
  if (bodies.motion2 == MotionType::kDynamic) {
    chunk.inv_i2 = BodyInverseInertia(*bodies.body2, offset);
  }
  const Sym33 k =
      rotation_euler::ReplaceZeroColumnsByIdentity(Add(chunk.inv_i1, chunk.inv_i2));
  chunk.effective_mass = InverseSym33(k, active);
  return chunk;
}

// C = 2 xyz(q2 r0^-1 q1*) with w >= 0, from the bodies' current rotations.
HWY_INLINE Vec3 RotationEulerError(const BodyPair& bodies,
                                   const Quat& inv_initial_orientation,
                                   std::size_t offset) {
  const Quat q1 = LoadQuat(bodies.body1->rotation, offset);
  const Quat q2 = LoadQuat(bodies.body2->rotation, offset);
  const Quat diff = EnsureWPositive(Mul(Mul(q2, inv_initial_orientation), Conjugate(q1)));
  const LaneVec two = Splat(2.0f);
  return {hn::Mul(diff.x, two), hn::Mul(diff.y, two), hn::Mul(diff.z, two)};
}

// One Baumgarte step of one chunk in the lanes of `solve_lanes` (others stay
// bit-identical). Returns the solved lanes whose error was non-zero.
HWY_INLINE LaneMask RotationEulerPositionStepOfChunk(const BodyPair& bodies,
                                                     const RotationEulerChunk& properties,
                                                     const Quat& inv_initial_orientation,
                                                     float baumgarte, LaneMask solve_lanes,
                                                     std::size_t offset) {
  const Vec3 c = RotationEulerError(bodies, inv_initial_orientation, offset);
  // Jolt skips the step when C == 0; the select keeps those lanes exact even
  // if K^-1 is huge (0 * inf would be NaN).
  const LaneMask solve = hn::And(solve_lanes, AnyComponentNonZero(c));
  const Vec3 k_inv_c = Multiply(properties.effective_mass, c);
  const Vec3 lambda = Select(solve, Scale(k_inv_c, Splat(-baumgarte)), ZeroVec3());
  rotation_euler::ApplyImpulse<false>(bodies, properties.inv_i1, properties.inv_i2,
                                      lambda, offset);
  return solve;
}

// True if C is exactly zero in every lane at the bodies' current rotations:
// the position step would then turn no body.
inline bool RotationEulerErrorIsZero(const BodyPair& bodies,
                                     const QuatLanes& inv_initial_orientation) {
  bool zero = true;
  ForEachChunk([&](std::size_t offset) {
    zero &= !AnyLane(AnyComponentNonZero(
        RotationEulerError(bodies, LoadQuat(inv_initial_orientation, offset), offset)));
  });
  return zero;
}

inline void RotationEulerCalculateProperties(const BodyPair& bodies,
                                             RotationEulerLanes& part) {
  ForEachChunk([&](std::size_t offset) {
    LaneMask active;
    const RotationEulerChunk chunk = RotationEulerPropertiesOfChunk(bodies, offset, active);
    rotation_euler::StoreProperties(chunk, part, offset);
    // Singular lanes are deactivated, which also clears their impulse.
    ClearWhere(hn::Not(active), part.persistent.total_lambda, offset);
  });
}

inline void RotationEulerWarmStart(const BodyPair& bodies, RotationEulerLanes& part,
                                   float warm_start_ratio) {
  const LaneVec ratio = Splat(warm_start_ratio);
  ForEachChunk([&](std::size_t offset) {
    const Vec3 lambda = Scale(LoadVec3(part.persistent.total_lambda, offset), ratio);
    StoreVec3(lambda, part.persistent.total_lambda, offset);
    rotation_euler::ApplyImpulse<true>(bodies, LoadSym33(part.inv_i1, offset),
                                       LoadSym33(part.inv_i2, offset), lambda, offset);
  });
}

// Returns true if any lane applied a non-zero impulse.
inline bool RotationEulerSolveVelocity(const BodyPair& bodies, RotationEulerLanes& part) {
  bool applied = false;
  ForEachChunk([&](std::size_t offset) {
    // -J v = w1 - w2
    const Vec3 relative = Sub(AngularVelocity(*bodies.body1, bodies.motion1, offset),
                              AngularVelocity(*bodies.body2, bodies.motion2, offset));
    // A lane whose bodies turn together exactly (every slider of a planar
    // mechanism) takes no step (SteppingLanes).
    const SteppingLanes turning = LanesThatStep(AnyComponentNonZero(relative));
    if (turning.none) return;
    const Vec3 delta = Multiply(LoadSym33(part.effective_mass, offset), relative);
    const Vec3 lambda = LoadVec3(part.persistent.total_lambda, offset);
    const Sym33 inv_i1 = LoadSym33(part.inv_i1, offset), inv_i2 = LoadSym33(part.inv_i2, offset);
    if (turning.every) {
      StoreVec3(Add(lambda, delta), part.persistent.total_lambda, offset);
      rotation_euler::ApplyImpulse<true>(bodies, inv_i1, inv_i2, delta, offset);
    } else {
      StoreVec3(Select(turning.mask, Add(lambda, delta), lambda), part.persistent.total_lambda,
                offset);
      rotation_euler::ApplyImpulse<true>(bodies, inv_i1, inv_i2, delta, offset, &turning.mask);
    }
    applied |= AnyLane(hn::And(turning.mask, AnyComponentNonZero(delta)));
  });
  return applied;
}

// Baumgarte step towards q2 = q1 r0 with the properties of the last
// CalculateProperties (callers recompute them first). Returns true if any
// lane had a non-zero error.
inline bool RotationEulerSolvePosition(const BodyPair& bodies,
                                       const QuatLanes& inv_initial_orientation,
                                       const RotationEulerLanes& part, float baumgarte) {
  bool applied = false;
  ForEachChunk([&](std::size_t offset) {
    const LaneMask solved = RotationEulerPositionStepOfChunk(
        bodies, rotation_euler::LoadChunk(part, offset),
        LoadQuat(inv_initial_orientation, offset), baumgarte, AllLanes(), offset);
    applied |= AnyLane(solved);
  });
  return applied;
}

// The position phase's verb: the properties at the current rotations, then
// one Baumgarte step. A lane whose C is exactly zero takes no step and is
// left exactly as it is (its impulse is not cleared even if K has become
// singular since the setup, where Jolt's recompute would clear it); where
// that holds in every world (no body 2 turned from its rest rotation at
// all: a planar slider, a weld that holds) K^-1 is not computed, and the
// part's cached properties keep their setup values, which nothing reads
// before the next setup. Returns true if any lane had a non-zero error.
inline bool RotationEulerRecomputeAndSolvePosition(const BodyPair& bodies,
                                                   const QuatLanes& inv_initial_orientation,
                                                   RotationEulerLanes& part,
                                                   float baumgarte) {
  if (RotationEulerErrorIsZero(bodies, inv_initial_orientation)) return false;
  bool applied = false;
  ForEachChunk([&](std::size_t offset) {
    const Quat inv_initial = LoadQuat(inv_initial_orientation, offset);
    const LaneMask off_rest =
        AnyComponentNonZero(RotationEulerError(bodies, inv_initial, offset));
    LaneMask active;
    const RotationEulerChunk chunk = RotationEulerPropertiesOfChunk(bodies, offset, active);
    rotation_euler::StoreProperties(chunk, part, offset);
    ClearWhere(hn::AndNot(active, off_rest), part.persistent.total_lambda, offset);
    applied |= AnyLane(RotationEulerPositionStepOfChunk(bodies, chunk, inv_initial, baumgarte,
                                                        AllLanes(), offset));
  });
  return applied;
}

// Jolt's Deactivate of the flagged lanes: K^-1 = 0 and accumulated impulse = 0.
inline void RotationEulerDeactivate(RotationEulerLanes& part, const LaneFlags& lanes) {
  DeactivateFlaggedLanes(part, lanes);
}

// flag = 1 where K^-1 != 0 (Jolt's IsActive), else 0.
inline void RotationEulerIsActive(const RotationEulerLanes& part, LaneFlags& active) {
  StoreActiveLanes(part, active);
}

// ---------------------------------------------- rest rotation r0^-1 (spec 2.6)

inline void RotationEulerInverseInitialOrientationFromBodies(
    const BodyPair& bodies, QuatLanes& inv_initial_orientation) {
  ForEachChunk([&](std::size_t offset) {
    const Quat q1 = LoadQuat(bodies.body1->rotation, offset);
    const Quat q2 = LoadQuat(bodies.body2->rotation, offset);
    StoreQuat(Mul(Conjugate(q2), q1), inv_initial_orientation, offset);
  });
}

inline void RotationEulerInverseInitialOrientationFromFramesXY(
    const Vec3Lanes& axis_x1, const Vec3Lanes& axis_y1, const Vec3Lanes& axis_x2,
    const Vec3Lanes& axis_y2, QuatLanes& inv_initial_orientation) {
  ForEachChunk([&](std::size_t offset) {
    const Vec3 x1 = LoadVec3(axis_x1, offset), y1 = LoadVec3(axis_y1, offset);
    const Vec3 x2 = LoadVec3(axis_x2, offset), y2 = LoadVec3(axis_y2, offset);
    const Quat frame1 = rotation_euler::FrameRotation(x1, y1, Cross(x1, y1));
    const Quat frame2 = rotation_euler::FrameRotation(x2, y2, Cross(x2, y2));
    StoreQuat(rotation_euler::InverseInitialOrientationFromFrames(x1, y1, frame1, x2,
                                                                  y2, frame2),
              inv_initial_orientation, offset);
  });
}

inline void RotationEulerInverseInitialOrientationFromFramesXZ(
    const Vec3Lanes& axis_x1, const Vec3Lanes& axis_z1, const Vec3Lanes& axis_x2,
    const Vec3Lanes& axis_z2, QuatLanes& inv_initial_orientation) {
  ForEachChunk([&](std::size_t offset) {
    const Vec3 x1 = LoadVec3(axis_x1, offset), z1 = LoadVec3(axis_z1, offset);
    const Vec3 x2 = LoadVec3(axis_x2, offset), z2 = LoadVec3(axis_z2, offset);
    const Quat frame1 = rotation_euler::FrameRotation(x1, Cross(z1, x1), z1);
    const Quat frame2 = rotation_euler::FrameRotation(x2, Cross(z2, x2), z2);
    StoreQuat(rotation_euler::InverseInitialOrientationFromFrames(x1, z1, frame1, x2,
                                                                  z2, frame2),
              inv_initial_orientation, offset);
  });
}

inline void RotationEulerInverseInitialOrientationWorldToLocal(
    const BodyPair& bodies, QuatLanes& inv_initial_orientation) {
  ForEachChunk([&](std::size_t offset) {
    const Quat q1 = LoadQuat(bodies.body1->rotation, offset);
    const Quat q2 = LoadQuat(bodies.body2->rotation, offset);
    const Quat world = LoadQuat(inv_initial_orientation, offset);
    StoreQuat(Mul(Mul(Conjugate(q2), world), q1), inv_initial_orientation, offset);
  });
}

}  // namespace HWY_NAMESPACE
}  // namespace manyworlds
HWY_AFTER_NAMESPACE();

#endif  // MANYWORLDS_KERNELS_ROTATION_EULER_INL_H_
