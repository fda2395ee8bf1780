// The exact joint solve across worlds (JointSolver::kExact): all equality
// rows of a world solved at once, each block's 16 lanes with the same
// instructions. The plan (batch/exact_plan.h) fixes the row groups and the
// elimination order; batch/exact_rows-inl.h has each group's J and C.
//
// The system K and its block LDL^T are in batch/exact_system-inl.h.
//
// Velocity phase (replaces setup, warm start and the velocity iterations):
//   b = -J v, lambda = K^-1 b, applied to both bodies: J v = 0 afterwards.
//   M's rotational blocks carry the joints' geometric stiffness from the last
//   substep's impulses (Inertia), taken implicitly.
// Motors, friction and limits (bounded rows) are solved around this by
// Gauss-Seidel, K's factors reused (batch/exact_inequality_rows-inl.h).
//
// Curvature correction (scenes whose joints are all equalities, after the
//   integration): v += w M~^-1 J^T K^-1 (C(q_n) - C(q~)) / dt with the
//   velocity solve's factors, the normal velocity the curved path needs
//   over the step (exact::CurvatureVelocity).
//
// Position phase (replaces the Baumgarte iterations): Newton steps on C = 0
//   at the current poses (J and K re-assembled there), lambda = K^-1 (-C),
//   applied as position and rotation steps, in each world until every
//   group's |C_k| <= tolerance (metres or radians; at most `passes` steps).
//   A world's step is scaled down whole where it would turn a body by more
//   than kExactMaxNewtonTurn (a trust region: the rotation rows' J is exact
//   only near C = 0, and a hinge far from its axis got steps of tens of
//   radians).
//   A world that has converged is left exactly as it is while others
//   continue, so what a world does never depends on the other worlds of its
//   block.

#if defined(MANYWORLDS_BATCH_EXACT_SOLVE_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef MANYWORLDS_BATCH_EXACT_SOLVE_INL_H_
#undef MANYWORLDS_BATCH_EXACT_SOLVE_INL_H_
#else
#define MANYWORLDS_BATCH_EXACT_SOLVE_INL_H_
#endif

#include <cstddef>
#include <vector>

#include "batch/constraint_block.h"
#include "batch/exact_inequality_rows-inl.h"
#include "batch/exact_plan.h"
#include "batch/exact_rows-inl.h"
#include "batch/exact_system-inl.h"
#include "batch/velocity_convergence-inl.h"
#include "kernels/lane_math-inl.h"
#include "kernels/point-inl.h"

HWY_BEFORE_NAMESPACE();
namespace manyworlds {
namespace HWY_NAMESPACE {

namespace exact {

// The anchors' separation C = p2 - p1 with the lever arms LeverArms cached.
HWY_INLINE Vec3 Separation(const ConstraintBlock& c, std::size_t offset) {
  const PointLanes& part = PointPart(c);
  const Vec3 p1 = Add(LoadVec3(c.bodies.body1->position, offset), LoadVec3(part.r1, offset));
  const Vec3 p2 = Add(LoadVec3(c.bodies.body2->position, offset), LoadVec3(part.r2, offset));
  return Sub(p2, p1);
}

// The angular step of the impulse lambda at lever arm r: I^-1 (r x lambda)
// with the solve's inverse inertia, the torque first as the dense reference
// forms J^T lambda.
HWY_INLINE Vec3 AngularStep(const Sym33Lanes& inverse_inertia, const Vec3& r,
                            const Vec3& lambda, std::size_t offset) {
  return Multiply(LoadSym33(inverse_inertia, offset), Cross(r, lambda));
}

// Adds the position and rotation steps of lambda on one dynamic body (sign
// -1 for a joint's body 1) to that body's sums for this Newton step.
HWY_INLINE void AddBodyStep(const BodyLanes& body, const Sym33Lanes& inverse_inertia,
                            LaneVec sign, const Vec3& r, const Vec3& lambda,
                            Vec3Lanes& translation, Vec3Lanes& rotation, std::size_t offset) {
  const Vec3 signed_lambda = Scale(lambda, sign);
  StoreVec3(MulAdd(signed_lambda, Load(body.inv_mass, offset), LoadVec3(translation, offset)),
            translation, offset);
  StoreVec3(Add(LoadVec3(rotation, offset), AngularStep(inverse_inertia, r, signed_lambda, offset)),
            rotation, offset);
}

// The impulse lambda of a group other than a point group on one side's
// dynamic body: linear m^-1 L^T lambda, angular I^-1 A^T lambda.
HWY_INLINE void GroupStep(const ExactScratch::GroupJacobian& jacobian, int side,
                          LaneVec inv_mass, const Vec3& lambda, std::size_t offset,
                          Vec3& linear, Vec3& angular) {
  linear = Scale(TransposeTimes(LoadMat33(jacobian.linear[side], offset), lambda), inv_mass);
  angular = Multiply(LoadMat33(jacobian.inv_i_angular[side], offset), lambda);
}

// Calls apply(body index, body, linear step, angular step, offset) for each
// dynamic body of the group at `position` (not a point group), with the steps
// of the impulse Solve left in rhs.
template <class Apply>
void ForEachGroupBodyStep(const StepPlan& plan, std::byte* block, const ExactScratch& scratch,
                          std::size_t position, Apply&& apply) {
  const ConstraintBlock c = GroupAt(plan, block, position);
  const ExactScratch::GroupJacobian& jacobian = scratch.jacobians[position];
  ForEachChunk([&](std::size_t offset) {
    const Vec3 lambda = LoadVec3(scratch.rhs[position], offset);
    for (int side = 0; side < 2; ++side) {
      if ((side == 1 ? c.bodies.motion2 : c.bodies.motion1) != MotionType::kDynamic) continue;
      const std::size_t b = side == 1 ? c.plan.body2 : c.plan.body1;
      BodyLanes& body = side == 1 ? *c.bodies.body2 : *c.bodies.body1;
      Vec3 linear, angular;
      GroupStep(jacobian, side, Load(body.inv_mass, offset), lambda, offset, linear, angular);
      apply(b, body, linear, angular, offset);
    }
  });
}

// rhs = -J v at the current velocities, for every group.
template <class Visit>
void VelocityRhs(const StepPlan& plan, std::byte* block, ExactScratch& scratch, Visit&& visit) {
  const ExactSolvePlan& exact = plan.exact;
  for (std::size_t p = 0; p < exact.group_count(); ++p) {
    visit();
    const ConstraintBlock c = GroupAt(plan, block, p);
    if (!IsPoint(exact, p)) {
      const ExactScratch::GroupJacobian& jacobian = scratch.jacobians[p];
      ForEachChunk([&](std::size_t offset) {
        Vec3 b = ZeroVec3();
        for (int side = 0; side < 2; ++side) {
          if ((side == 1 ? c.bodies.motion2 : c.bodies.motion1) == MotionType::kStatic) continue;
          const BodyLanes& body = side == 1 ? *c.bodies.body2 : *c.bodies.body1;
          b = Sub(b, Multiply(LoadMat33(jacobian.linear[side], offset),
                              LoadVec3(body.linear_velocity, offset)));
          b = Sub(b, Multiply(LoadMat33(jacobian.angular[side], offset),
                              LoadVec3(body.angular_velocity, offset)));
        }
        StoreVec3(b, scratch.rhs[p], offset);
      });
      continue;
    }
    const PointLanes& part = PointPart(c);
    ForEachChunk([&](std::size_t offset) {
      // b = -J v = v1 + w1 x r1 ... written as the point part's s.
      Vec3 s = ZeroVec3();
      if (c.bodies.motion1 != MotionType::kStatic) {
        s = Sub(LoadVec3(c.bodies.body1->linear_velocity, offset),
                Cross(LoadVec3(part.r1, offset), LoadVec3(c.bodies.body1->angular_velocity, offset)));
      }
      if (c.bodies.motion2 != MotionType::kStatic) {
        s = Add(Sub(s, LoadVec3(c.bodies.body2->linear_velocity, offset)),
                Cross(LoadVec3(part.r2, offset), LoadVec3(c.bodies.body2->angular_velocity, offset)));
      }
      StoreVec3(s, scratch.rhs[p], offset);
    });
  }
}

// Applies the impulses Solve left in rhs as velocity steps; the point
// groups' impulses become (or, `accumulate`, are added to) their parts'
// total_lambda.
template <class Visit>
void ApplyVelocityImpulses(const StepPlan& plan, std::byte* block, const ExactScratch& scratch,
                           bool accumulate, Visit&& visit) {
  const ExactSolvePlan& exact = plan.exact;
  for (std::size_t p = 0; p < exact.group_count(); ++p) {
    visit();
    if (!IsPoint(exact, p)) {
      ForEachGroupBodyStep(
          plan, block, scratch, p,
          [](std::size_t, BodyLanes& body, const Vec3& linear, const Vec3& angular,
             std::size_t offset) { AddVelocityStep(body, linear, angular, offset); });
      continue;
    }
    const ConstraintBlock c = GroupAt(plan, block, p);
    PointLanes& part = PointPart(c);
    ForEachChunk([&](std::size_t offset) {
      const Vec3 lambda = LoadVec3(scratch.rhs[p], offset);
      StoreVec3(accumulate ? Add(LoadVec3(part.persistent.total_lambda, offset), lambda) : lambda,
                part.persistent.total_lambda, offset);
      if (c.bodies.motion1 == MotionType::kDynamic) {
        BodyLanes& body = *c.bodies.body1;
        AddVelocityStep(body, Scale(lambda, hn::Neg(Load(body.inv_mass, offset))),
                        Neg(AngularStep(scratch.inverse_inertia[c.plan.body1],
                                        LoadVec3(part.r1, offset), lambda, offset)),
                        offset);
      }
      if (c.bodies.motion2 == MotionType::kDynamic) {
        BodyLanes& body = *c.bodies.body2;
        AddVelocityStep(body, Scale(lambda, Load(body.inv_mass, offset)),
                        AngularStep(scratch.inverse_inertia[c.plan.body2],
                                    LoadVec3(part.r2, offset), lambda, offset),
                        offset);
      }
    });
  }
}

// Each dynamic body's step for the impulses Solve left in rhs, summed over
// its groups (as J^T lambda) into scratch.translation and scratch.rotation:
// linear m^-1 J_L^T lambda, angular I^-1 J_A^T lambda, with the lever arms
// cached in the point parts, the other groups' rows in scratch.jacobians and
// the inverse inertias in scratch.inverse_inertia. One step moves each body
// once: rotation steps applied group after group would compose, and a
// link's two nearly opposite turns would not cancel.
template <class Visit>
void SumBodySteps(const StepPlan& plan, std::byte* block, ExactScratch& scratch, Visit&& visit) {
  const ExactSolvePlan& exact = plan.exact;
  for (Vec3Lanes& sum : scratch.translation) {
    ForEachChunk([&](std::size_t offset) { StoreVec3(ZeroVec3(), sum, offset); });
  }
  for (Vec3Lanes& sum : scratch.rotation) {
    ForEachChunk([&](std::size_t offset) { StoreVec3(ZeroVec3(), sum, offset); });
  }
  for (std::size_t p = 0; p < exact.group_count(); ++p) {
    visit();
    const ConstraintBlock c = GroupAt(plan, block, p);
    if (!IsPoint(exact, p)) {
      ForEachGroupBodyStep(
          plan, block, scratch, p,
          [&](std::size_t b, BodyLanes&, const Vec3& linear, const Vec3& angular,
              std::size_t offset) {
            StoreVec3(Add(LoadVec3(scratch.translation[b], offset), linear),
                      scratch.translation[b], offset);
            StoreVec3(Add(LoadVec3(scratch.rotation[b], offset), angular), scratch.rotation[b],
                      offset);
          });
      continue;
    }
    const PointLanes& part = PointPart(c);
    ForEachChunk([&](std::size_t offset) {
      const Vec3 lambda = LoadVec3(scratch.rhs[p], offset);
      if (c.bodies.motion1 == MotionType::kDynamic) {
        AddBodyStep(*c.bodies.body1, scratch.inverse_inertia[c.plan.body1], Splat(-1.0f),
                    LoadVec3(part.r1, offset), lambda, scratch.translation[c.plan.body1],
                    scratch.rotation[c.plan.body1], offset);
      }
      if (c.bodies.motion2 == MotionType::kDynamic) {
        AddBodyStep(*c.bodies.body2, scratch.inverse_inertia[c.plan.body2], Splat(1.0f),
                    LoadVec3(part.r2, offset), lambda, scratch.translation[c.plan.body2],
                    scratch.rotation[c.plan.body2], offset);
      }
    });
  }
}

// One Newton step of the equality rows in the worlds scratch.moving marks
// (C's negation in rhs and the other groups' rows from the convergence
// check).
template <class Visit>
void NewtonStep(const StepPlan& plan, std::byte* block, ExactScratch& scratch, Visit&& visit) {
  const ExactSolvePlan& exact = plan.exact;
  Inertia(plan, block, scratch, 0.0f);
  AssembleK(plan, block, scratch);
  Factor(exact, scratch, visit);
  Solve(exact, scratch);
  SumBodySteps(plan, block, scratch, visit);
  // The trust region (kExactMaxNewtonTurn): in a world where some body
  // would turn further, every body's step is scaled by the same factor. A
  // world whose step is NaN keeps scale 1 (the comparison is false): it is
  // lost either way, and the health check flags it.
  ForEachChunk([&](std::size_t offset) {
    Store(TrustRegionScale(plan, scratch, offset), scratch.step_scale, offset);
  });
  for (std::size_t b = 0; b < plan.bodies.size(); ++b) {
    if (plan.bodies[b].motion != MotionType::kDynamic) continue;
    BodyLanes& body = BodyAt(plan, block, b);
    ForEachChunk([&](std::size_t offset) {
      // Worlds that have converged keep every bit.
      const LaneMask moving = hn::Ne(Load(scratch.moving, offset), Zero());
      const Vec3 x = LoadVec3(body.position, offset);
      const Quat q = LoadQuat(body.rotation, offset);
      // A scale of 1 gives the unscaled step's bits (x + 1 t = x + t).
      const LaneVec scale = Load(scratch.step_scale, offset);
      // Without the locked axes of a restricted body (K counted none).
      const Vec3 translation =
          LockTranslation(body, LoadVec3(scratch.translation[b], offset), offset);
      const Vec3 moved = MulAdd(translation, scale, x);
      const Quat turned = AddRotationStep(q, Scale(LoadVec3(scratch.rotation[b], offset), scale));
      StoreVec3(Select(moving, moved, x), body.position, offset);
      StoreQuat(Select(moving, turned, q), body.rotation, offset);
    });
  }
}

// C at the current poses for every group into `errors`, leaving the cached
// lever arms and rows as they are (CurvatureVelocity corrects along the
// velocity solve's).
inline void ErrorsAtCurrentPoses(const StepPlan& plan, std::byte* block,
                                 std::vector<Vec3Lanes>& errors) {
  const ExactSolvePlan& exact = plan.exact;
  for (std::size_t p = 0; p < exact.group_count(); ++p) {
    const ConstraintBlock c = GroupAt(plan, block, p);
    const bool point = IsPoint(exact, p);
    ForEachChunk([&](std::size_t offset) {
      Vec3 error;
      if (point) {
        const PointGeometry& anchors = PointAnchors(c);
        const Vec3 p1 = Add(LoadVec3(c.bodies.body1->position, offset),
                            Rotate(LoadQuat(c.bodies.body1->rotation, offset),
                                   LoadVec3(anchors.r1_local, offset)));
        const Vec3 p2 = Add(LoadVec3(c.bodies.body2->position, offset),
                            Rotate(LoadQuat(c.bodies.body2->rotation, offset),
                                   LoadVec3(anchors.r2_local, offset)));
        error = Sub(p2, p1);
      } else {
        error = RowsOfChunk(plan, c, exact.order[p].rows, true, offset).error;
      }
      StoreVec3(error, errors[p], offset);
    });
  }
}

// Whether the step takes the curvature correction (CurvatureVelocity): a
// scene with row groups whose joints are all equalities, without contacts.
HWY_INLINE bool CurvatureApplies(const StepPlan& plan, bool curvature) {
  return curvature && plan.exact.group_count() != 0 && plan.exact.inequality.empty() &&
         plan.contacts.empty();
}

// Per world, the weight of the curvature correction, into
// scratch.velocity_weight: 1 while every dynamic body's tr(G I^-1) is at
// most half of kExactCurvatureTransverseLimit (its header comment), falling
// linearly to 0 at the limit, so that a world's step changes continuously as
// its pulls grow. G = dt * sum over the body's point groups of
// max(0, s lambda . r) (E - r^ r^T), with this step's impulses and the
// velocity solve's lever arms, summed in scratch.stiffness by
// SumGeometricStiffness as Inertia sums the velocity solve's (which is done
// with it); tr(G I^-1) is the sum of their entries' products, both
// symmetric. NaN pulls weigh 0.
inline void CurvatureWeights(const StepPlan& plan, std::byte* block, ExactScratch& scratch,
                             float dt) {
  SumGeometricStiffness(plan, block, scratch, dt);
  const LaneVec fade = Splat(2.0f / kExactCurvatureTransverseLimit);
  ForEachChunk([&](std::size_t offset) {
    LaneVec largest = Zero();
    for (std::size_t b = 0; b < plan.bodies.size(); ++b) {
      if (plan.bodies[b].motion != MotionType::kDynamic) continue;
      const Sym33 g = LoadSym33(scratch.stiffness[b], offset);
      const Sym33 i = BodyInverseInertia(BodyAt(plan, block, b), offset);
      const LaneVec diagonal =
          hn::MulAdd(g.zz, i.zz, hn::MulAdd(g.yy, i.yy, hn::Mul(g.xx, i.xx)));
      const LaneVec off_diagonal =
          hn::MulAdd(g.yz, i.yz, hn::MulAdd(g.xz, i.xz, hn::Mul(g.xy, i.xy)));
      largest = hn::Max(largest, hn::MulAdd(Splat(2.0f), off_diagonal, diagonal));
    }
    // 2 - 2 tr / limit, clamped to [0, 1] (a NaN fails the comparison).
    const LaneVec weight =
        hn::Min(Splat(1.0f), hn::Max(Zero(), hn::NegMulAdd(largest, fade, Splat(2.0f))));
    Store(hn::IfThenElseZero(hn::Gt(weight, Zero()), weight), scratch.velocity_weight, offset);
  });
}

// The curvature correction of the velocities (StepSettings::
// exact_curvature_velocity), after the integration and before the Newton
// steps: SHAKE's first chord step (Ryckaert, Ciccotti and Berendsen, 1977)
// taken by the velocities alone,
//   v += w M~^-1 J(q_n)^T K^-1 (C(q_n) - C(q~)) / dt,
// with the velocity solve's J, inverse inertias M~ and factors of K (no new
// factorisation), C at the step's start q_n (scratch.start_error, from the
// velocity phase) and at the integrated poses q~, and w the world's weight
// (CurvatureWeights). The velocity solve leaves v tangent to the joints at
// the step's start; along a curved path the poses then drift off by
// C(q~) - C(q_n), and this is the normal velocity that keeps them on:
// without it the next velocity solve removes that component, and the
// motion loses energy at first order in dt (docs/accuracy.md, "Energy").
// What C(q_n) was (at most the tolerance the last Newton steps stopped at)
// is the positions' to correct, not the velocities'. The correction is
// explicit in the transverse swing the joints' pulls drive, hence the
// weight. As a Newton step, the world's correction is scaled down whole
// where it would turn a body by more than kExactMaxNewtonTurn (in dt). The
// positions are left to the Newton steps.
template <class Visit>
void CurvatureVelocity(const StepPlan& plan, std::byte* block, ExactScratch& scratch, float dt,
                       Visit&& visit) {
  CurvatureWeights(plan, block, scratch, dt);
  bool any = false;
  ForEachChunk([&](std::size_t offset) {
    any |= AnyLane(hn::Gt(Load(scratch.velocity_weight, offset), Zero()));
  });
  if (!any) return;
  ErrorsAtCurrentPoses(plan, block, scratch.rhs);
  for (std::size_t p = 0; p < plan.exact.group_count(); ++p) {
    ForEachChunk([&](std::size_t offset) {
      StoreVec3(Sub(LoadVec3(scratch.start_error[p], offset), LoadVec3(scratch.rhs[p], offset)),
                scratch.rhs[p], offset);
    });
  }
  Solve(plan.exact, scratch);
  SumBodySteps(plan, block, scratch, visit);
  const LaneVec inverse_dt = Splat(1.0f / dt);
  ForEachChunk([&](std::size_t offset) {
    const LaneVec scale = TrustRegionScale(plan, scratch, offset);
    Store(hn::Mul(hn::Mul(Load(scratch.velocity_weight, offset), scale), inverse_dt),
          scratch.step_scale, offset);
  });
  for (std::size_t b = 0; b < plan.bodies.size(); ++b) {
    if (plan.bodies[b].motion != MotionType::kDynamic) continue;
    BodyLanes& body = BodyAt(plan, block, b);
    ForEachChunk([&](std::size_t offset) {
      // Worlds of weight 0 keep every bit (w * x + v is not v for x = NaN).
      const LaneVec factor = Load(scratch.step_scale, offset);
      const LaneMask takes = hn::Gt(factor, Zero());
      const Vec3 v = LoadVec3(body.linear_velocity, offset);
      const Vec3 w = LoadVec3(body.angular_velocity, offset);
      const Vec3 linear = LockTranslation(body, LoadVec3(scratch.translation[b], offset), offset);
      StoreVec3(Select(takes, MulAdd(linear, factor, v), v), body.linear_velocity, offset);
      StoreVec3(Select(takes, MulAdd(LoadVec3(scratch.rotation[b], offset), factor, w), w),
                body.angular_velocity, offset);
    });
  }
}

}  // namespace exact

// Velocity phase: J v = 0 for every group at once (see the header comment),
// with the geometric stiffness `stiffness` * (pull) (Inertia). With
// `curvature` (and exact::CurvatureApplies) the joints' errors at the
// step's start are kept for exact::CurvatureVelocity. With
// inequality rows (motors, friction, limits; batch/exact_inequality_rows-inl.h)
// `iterations` passes of block Gauss-Seidel around the exact solve, which
// factors K once and ends with the equality rows exact; with a velocity
// tolerance (`convergence`, or nullptr) each world stops after the first pass
// from the second on that changed its velocities by at most it
// (batch/velocity_convergence-inl.h). Contacts are
// inequality rows too: `contacts` is a ContactPhases (step_kernels.cc) set
// up before the joints' inequality rows, warm-started after them, and whose
// velocity pass follows theirs in every pass (docs/contacts.md).
// The point groups' impulses are kept as their parts' total_lambda (the
// next substep's pulls).
// `visit()` is called three times per group (the step's prefetch of the next
// block, spread thin so that its requests never queue up).
template <class Visit, class Contacts>
void ExactSolveVelocity(const StepPlan& plan, std::byte* block, ExactScratch& scratch,
                        float stiffness, bool curvature, const StepScalars& step, int iterations,
                        VelocityConvergence* convergence, Visit&& visit, Contacts&& contacts) {
  const ExactSolvePlan& exact = plan.exact;
  // A scene whose constraints are all solved whole (distance, pulley,
  // six-DOF, path) has no group: nothing to factor, and its inertias would
  // be computed for nothing.
  const bool factored = exact.group_count() != 0;
  exact::HingeTurns(plan, block);
  if (factored) {
    exact::LeverArms(plan, block);
    exact::GroupJacobians(plan, block, scratch);
    exact::Inertia(plan, block, scratch, stiffness);
    exact::AssembleK(plan, block, scratch);
  }
  if (exact::CurvatureApplies(plan, curvature)) {
    exact::ErrorsAtCurrentPoses(plan, block, scratch.start_error);
  }
  // The contacts' rows from the velocities after the forces (their
  // restitution reads them), as in the Gauss-Seidel step; their warm start
  // after the joints'.
  contacts.Setup();
  for (std::size_t i : exact.inequality) {
    exact::InequalitySetupAndWarmStart(ConstraintInBlock(plan, i, block), step);
  }
  contacts.WarmStart();
  if (factored) {
    exact::VelocityRhs(plan, block, scratch, visit);
    exact::Factor(exact, scratch, visit);
    exact::Solve(exact, scratch);
    exact::ApplyVelocityImpulses(plan, block, scratch, false, visit);
  }
  if (exact.inequality.empty() && plan.contacts.empty()) return;
  // The first pass solved the joints alone, so what it changed says nothing
  // of the inequality rows: the tolerance is tested from the second pass on,
  // the first that visits every row.
  // Without groups the passes are Gauss-Seidel's alone, and stop as its do
  // once no lane applied an impulse (a pass then changes nothing).
  const auto no_visit = [] {};
  for (int pass = 1; pass < iterations; ++pass) {
    if (convergence) convergence->BeforePass();
    bool applied = false;
    for (std::size_t i : exact.inequality) {
      applied |= exact::InequalitySolveVelocity(ConstraintInBlock(plan, i, block));
    }
    applied |= contacts.SolveVelocity();
    if (factored) {
      exact::VelocityRhs(plan, block, scratch, no_visit);
      exact::Solve(exact, scratch);
      exact::ApplyVelocityImpulses(plan, block, scratch, true, no_visit);
    } else if (!applied) {
      break;
    }
    if (convergence && convergence->AfterPass()) break;
  }
  if (convergence) convergence->Finish();
}

// Position phase: in a scene whose joints are all equality row groups (no
// inequality rows, no contacts) and with `curvature`, the curvature
// correction of the velocities (exact::CurvatureVelocity); then Newton
// steps until each world's groups are within `tolerance`, at most `passes`,
// each followed by a Baumgarte step of every hard limit and then every
// contact (`contacts`, as for the velocity phase). Returns the number of
// Newton passes taken (by the slowest world of the block).
template <class Visit, class Contacts>
int ExactSolvePosition(const StepPlan& plan, std::byte* block, ExactScratch& scratch,
                       bool curvature, int passes, float tolerance, const StepScalars& step,
                       Visit&& visit, Contacts&& contacts) {
  const ExactSolvePlan& exact = plan.exact;
  const LaneVec tolerance_squared = Splat(tolerance * tolerance);
  // Whether a hard limit or a contact moved a world in the last pass
  // (unknown before the first: batch/exact_inequality_rows-inl.h).
  const bool limited = exact.hard_limits || !plan.contacts.empty();
  bool limits_moved = limited;
  if (exact::CurvatureApplies(plan, curvature)) {
    exact::CurvatureVelocity(plan, block, scratch, step.delta_time, visit);
  }
  int pass = 0;
  for (; pass < passes; ++pass) {
    // The mass metric (no stiffness); K only once some world has to move.
    exact::LeverArms(plan, block);
    ForEachChunk([&](std::size_t offset) { Store(Zero(), scratch.moving, offset); });
    for (std::size_t p = 0; p < exact.group_count(); ++p) {
      visit();
      const ConstraintBlock c = exact::GroupAt(plan, block, p);
      const bool point = exact::IsPoint(exact, p);
      ForEachChunk([&](std::size_t offset) {
        Vec3 error;
        if (point) {
          error = exact::Separation(c, offset);
        } else {
          const exact::GroupRows rows =
              exact::RowsOfChunk(plan, c, exact.order[p].rows, true, offset);
          exact::StoreRows(rows, scratch.jacobians[p], offset);
          error = rows.error;
        }
        StoreVec3(Neg(error), scratch.rhs[p], offset);
        // NaN errors count as not converged (the comparison is false).
        const LaneMask within = hn::Le(LengthSquared(error), tolerance_squared);
        const LaneVec moving = hn::IfThenZeroElse(within, Splat(1.0f));
        Store(hn::Max(Load(scratch.moving, offset), moving), scratch.moving, offset);
      });
    }
    bool any_moving = false;
    ForEachChunk([&](std::size_t offset) {
      any_moving |= AnyLane(hn::Ne(Load(scratch.moving, offset), Zero()));
    });
    if (!any_moving && !limits_moved) break;
    if (any_moving) exact::NewtonStep(plan, block, scratch, visit);
    limits_moved = false;
    if (!limited) continue;
    if (exact.hard_limits) {
      for (std::size_t i : exact.inequality) {
        limits_moved |= exact::LimitSolvePosition(plan, ConstraintInBlock(plan, i, block), step);
      }
    }
    limits_moved |= contacts.SolvePosition();
  }
  return pass;
}

}  // namespace HWY_NAMESPACE
}  // namespace manyworlds
HWY_AFTER_NAMESPACE();

#endif  // MANYWORLDS_BATCH_EXACT_SOLVE_INL_H_
