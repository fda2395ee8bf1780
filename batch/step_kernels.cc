// One step of one block (spec 4.1), per Highway target:
//
//   for each substep (dt = step dt / substeps):
//     1. forces, gravity, damping, velocity clamps      (dynamic bodies)
//     2. setup of every constraint, in scene order      (positions at step start)
//        then of every contact slot (its points found, docs/contacts.md)
//     3. warm start: impulses *= dt / dt_prev (first substep, 0 if off; 1 later)
//     4. velocity iterations, until none of the block's worlds applied an impulse
//        (with a velocity tolerance: until every world's last pass changed
//        its velocities by at most that, batch/velocity_convergence-inl.h)
//     5. integration                                    (dynamic and kinematic)
//     6. position iterations, until none moved
//   Contacts follow the constraints in every phase (Jolt's order).
//   With JointSolver::kExact, 2-4 are one exact solve of every equality
//   row's velocity and 6 Newton steps of the same system per world until its
//   rows are within the tolerance (batch/exact_solve-inl.h).
//   forces and torques cleared; the health of every world checked (non-finite
//   state, velocity overflow in the force step, coordinates out of range).
//
// The same code runs with a phase clock (BatchOptions::profile_phases): a
// steady_clock read after each of those phases (StepPhase, batch.h), summed
// per phase; the plain step's clock is empty and compiles away.
//
// The early-outs are result-neutral (spec 7): a pass in which no lane applied
// an impulse leaves every velocity unchanged, so the next pass would too.
// Scene-uniform decisions (constraint types, body kinds, features) are plain
// control flow from the plan; per-world ones are masks inside the parts.

#include "batch/step_kernels.h"

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <optional>

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "batch/step_kernels.cc"
#include "hwy/foreach_target.h"  // IWYU pragma: keep

#include "batch/constraint_block.h"
#include "batch/constraint_verbs-inl.h"
#include "batch/contact_constraint-inl.h"
#include "batch/exact_solve-inl.h"
#include "batch/velocity_convergence-inl.h"
#include "hwy/highway.h"
#include "kernels/integration-inl.h"

HWY_BEFORE_NAMESPACE();
namespace manyworlds {
namespace HWY_NAMESPACE {

// The phase clock of StepBlockWith: NoClock compiles to nothing (the plain
// step); SteadyClock adds the time since its last lap to its phase's sum.
struct NoClock {
  void Start() {}
  void Lap(StepPhase) {}
};
struct SteadyClock {
  std::uint64_t* phase_ns;
  std::chrono::steady_clock::time_point last;
  void Start() { last = std::chrono::steady_clock::now(); }
  void Lap(StepPhase phase) {
    const auto now = std::chrono::steady_clock::now();
    phase_ns[static_cast<std::size_t>(phase)] += static_cast<std::uint64_t>(
        std::chrono::duration_cast<std::chrono::nanoseconds>(now - last).count());
    last = now;
  }
};

// Brings the block stepped next into L2 while this one steps, a few cache
// lines per constraint visited, so that its first touch does not wait for
// memory (a block's plan-ordered accesses jump between its arrays, which the
// hardware prefetchers do not follow). Locality 2 is x86's PREFETCHT1 (L2
// and outward, not L1: the current block's working set stays in L1) and
// Arm's PLDL2KEEP. Spread over every visit of the first substep's passes;
// whatever early-outs left is requested at the end.
class NextBlockPrefetch {
 public:
  NextBlockPrefetch(const std::byte* next, std::size_t bytes, std::size_t visits)
      : next_(next), end_(next == nullptr ? nullptr : next + bytes),
        lines_per_visit_((bytes / kCacheLine + visits - 1) / visits) {}
  void Visit() { Request(lines_per_visit_); }
  void Rest() { Request(static_cast<std::size_t>(end_ - next_) / kCacheLine); }

 private:
  static constexpr std::size_t kCacheLine = 64;
  void Request(std::size_t lines) {
    for (std::size_t k = 0; k < lines && next_ < end_; ++k, next_ += kCacheLine) {
      __builtin_prefetch(next_, 0, 2);
    }
  }
  const std::byte* next_;
  const std::byte* end_;
  std::size_t lines_per_visit_;
};

// The contacts' phases as the exact joint solve runs them around its own
// (batch/exact_solve-inl.h): `each` visits the slots in solve order.
template <class ForEachContact>
struct ContactPhases {
  ForEachContact& each;
  const ContactStepScalars& scalars;
  float warm_start_ratio;
  void Setup() const {
    each([&](const ContactBlock& c) { ContactSetup(c, scalars); });
  }
  void WarmStart() const {
    each([&](const ContactBlock& c) { ContactWarmStart(c, warm_start_ratio); });
  }
  bool SolveVelocity() const {
    bool applied = false;
    each([&](const ContactBlock& c) { applied |= ContactSolveVelocity(c); });
    return applied;
  }
  bool SolvePosition() const {
    bool moved = false;
    each([&](const ContactBlock& c) { moved |= ContactSolvePosition(c, scalars); });
    return moved;
  }
};

template <class Clock>
bool StepBlockWith(const StepPlan& plan, std::byte* block, const std::byte* next_block,
                   const StepParams& params, Clock& clock) {
  clock.Start();
  const std::size_t constraint_count = plan.constraints.size();
  const std::size_t contact_count = plan.contacts.size();
  const std::size_t solved_count = constraint_count + contact_count;
  // The exact solve visits each row group three times in its velocity
  // solve and three times per Newton step, whose number is known only as
  // they converge: its prefetch is spread over the velocity solve and the
  // first Newton step (a scene whose constraints are all solved whole has
  // no group: its requests wait for NextBlockPrefetch::Rest).
  const bool exact = params.solver == JointSolver::kExact && constraint_count != 0;
  const std::size_t visits =
      exact ? 6 * std::max<std::size_t>(1, plan.exact.group_count())
            : std::max<std::size_t>(1, solved_count) *
                  static_cast<std::size_t>(2 + params.velocity_iterations +
                                           params.position_iterations);
  NextBlockPrefetch prefetch(next_block, plan.block_bytes, visits);
  // Views of the plan's constraints in this block, in solve order: a few
  // offsets each, so built per pass rather than allocated per block.
  const auto for_each_constraint = [&](auto&& verb) {
    for (std::size_t i = 0; i < constraint_count; ++i) {
      verb(ConstraintInBlock(plan, i, block));
      prefetch.Visit();
    }
  };
  const auto for_each_contact = [&](auto&& verb) {
    for (std::size_t i = 0; i < contact_count; ++i) {
      verb(ContactInBlock(plan, i, block));
      prefetch.Visit();
    }
  };
  // The exact solve's contacts, outside its prefetch budget (6 visits per
  // group, spread over its own passes).
  const auto for_each_contact_of_exact = [&](auto&& verb) {
    for (std::size_t i = 0; i < contact_count; ++i) verb(ContactInBlock(plan, i, block));
  };
  const ContactStepScalars contact_scalars{
      ContactScalars{Splat(params.substep_delta_time), Splat(params.min_velocity_for_restitution),
                     Splat(params.penetration_slop), Splat(params.max_penetration_distance),
                     Splat(params.baumgarte)},
      Splat(params.speculative_contact_distance),
      Vec3{Splat(params.gravity[0]), Splat(params.gravity[1]), Splat(params.gravity[2])},
      params.speculative_contacts_from_velocity};
  const LaneVec dt = Splat(params.substep_delta_time);
  const Vec3 gravity{Splat(params.gravity[0]), Splat(params.gravity[1]),
                     Splat(params.gravity[2])};
  WorldHealthLanes& health = At<WorldHealthLanes>(block, plan.health_offset);
  health = WorldHealthLanes{};
  // The exact solve's working storage, per thread (Step refused kExact where
  // the plan cannot take it).
  thread_local ExactScratch scratch;
  if (exact) scratch.Fit(plan);
  thread_local VelocityConvergenceScratch convergence_scratch;

  for (int substep = 0; substep < params.substeps; ++substep) {
    // Jolt: the dt ratio (0 without warm start) in the first substep only;
    // later substeps continue from the previous substep's impulses.
    const float ratio = substep == 0 ? params.first_warm_start_ratio : 1.0f;
    const StepScalars step{params.substep_delta_time, ratio, params.baumgarte};

    for (const BodyPlan& body : plan.bodies) {
      if (body.motion != MotionType::kDynamic) continue;
      if (params.gyroscopic) ApplyGyroscopicStep(At<BodyLanes>(block, body.offset), dt);
      ApplyForcesAndDamping(At<BodyLanes>(block, body.offset),
                            At<BodyMotionLanes>(block, body.motion_offset), gravity, dt,
                            health);
    }
    clock.Lap(StepPhase::kForces);

    // With a velocity tolerance each world stops its velocity passes on its
    // own (batch/velocity_convergence-inl.h); without, every pass runs.
    std::optional<VelocityConvergence> convergence;
    if (params.velocity_tolerance > 0.0f && solved_count != 0) {
      convergence.emplace(plan, block, params.velocity_tolerance, convergence_scratch);
    }
    if (exact) {
      ExactSolveVelocity(plan, block, scratch,
                         substep == 0 ? params.exact_first_stiffness : params.exact_stiffness,
                         params.exact_curvature_velocity, step, params.velocity_iterations,
                         convergence ? &*convergence : nullptr, [&] { prefetch.Visit(); },
                         ContactPhases<decltype(for_each_contact_of_exact)>{
                             for_each_contact_of_exact, contact_scalars, ratio});
      clock.Lap(StepPhase::kVelocity);
    } else if (solved_count != 0) {
      for_each_constraint([&](const ConstraintBlock& c) { SetupConstraint(c, step); });
      for_each_contact([&](const ContactBlock& c) { ContactSetup(c, contact_scalars); });
      clock.Lap(StepPhase::kSetup);
      for_each_constraint([&](const ConstraintBlock& c) { WarmStartConstraint(c, step); });
      for_each_contact([&](const ContactBlock& c) { ContactWarmStart(c, ratio); });
      clock.Lap(StepPhase::kWarmStart);
      for (int iteration = 0; iteration < params.velocity_iterations; ++iteration) {
        if (convergence) convergence->BeforePass();
        bool applied = false;
        for_each_constraint(
            [&](const ConstraintBlock& c) { applied |= SolveConstraintVelocity(c); });
        for_each_contact([&](const ContactBlock& c) { applied |= ContactSolveVelocity(c); });
        if (!applied || (convergence && convergence->AfterPass())) break;
      }
      if (convergence) convergence->Finish();
      clock.Lap(StepPhase::kVelocity);
    }

    if (solved_count == 0) prefetch.Visit();
    for (const BodyPlan& body : plan.bodies) {
      if (body.motion == MotionType::kStatic) continue;
      const BodyMotionLanes* motion =
          body.motion == MotionType::kDynamic
              ? &At<BodyMotionLanes>(block, body.motion_offset)
              : nullptr;
      IntegrateBody(At<BodyLanes>(block, body.offset), motion, dt);
    }
    clock.Lap(StepPhase::kIntegration);

    if (exact) {
      ExactSolvePosition(plan, block, scratch, params.exact_curvature_velocity,
                         params.position_iterations, params.exact_tolerance, step,
                         [&] { prefetch.Visit(); },
                         ContactPhases<decltype(for_each_contact_of_exact)>{
                             for_each_contact_of_exact, contact_scalars, ratio});
      clock.Lap(StepPhase::kPosition);
    } else if (solved_count != 0) {
      for (int iteration = 0; iteration < params.position_iterations; ++iteration) {
        bool applied = false;
        for_each_constraint(
            [&](const ConstraintBlock& c) { applied |= SolveConstraintPosition(plan, c, step); });
        for_each_contact(
            [&](const ContactBlock& c) { applied |= ContactSolvePosition(c, contact_scalars); });
        if (!applied) break;
      }
      clock.Lap(StepPhase::kPosition);
    }
  }

  prefetch.Rest();

  // Forces act for one Step call (all its substeps), as Jolt's AddForce.
  for (const BodyPlan& body : plan.bodies) {
    if (body.motion != MotionType::kDynamic) continue;
    BodyMotionLanes& motion = At<BodyMotionLanes>(block, body.motion_offset);
    motion.force = Vec3Lanes{};
    motion.torque = Vec3Lanes{};
  }

  const LaneVec max_coordinate = Splat(kMaxHealthyCoordinate);
  for (const BodyPlan& body : plan.bodies) {
    CheckBodyHealth(At<BodyLanes>(block, body.offset), max_coordinate, health);
  }
  bool unhealthy = false;
  ForEachChunk([&](std::size_t offset) {
    const LaneVec any = hn::Max(Load(health.velocity_overflow, offset),
                                hn::Max(Load(health.non_finite, offset),
                                        Load(health.out_of_range, offset)));
    unhealthy |= !hn::AllTrue(LaneTag(), hn::Eq(any, Zero()));
  });
  clock.Lap(StepPhase::kFinish);
  return unhealthy;
}

bool StepBlock(const StepPlan& plan, std::byte* block, const std::byte* next_block,
               const StepParams& params) {
  NoClock clock;
  return StepBlockWith(plan, block, next_block, params, clock);
}

bool StepBlockProfiled(const StepPlan& plan, std::byte* block, const std::byte* next_block,
                       const StepParams& params, std::uint64_t* phase_ns) {
  SteadyClock clock{phase_ns, {}};
  return StepBlockWith(plan, block, next_block, params, clock);
}

// Array by array, each array's chunks in turn, so that every cache line of
// the block is loaded and written once: chunk by chunk over all arrays, a
// target with vectors narrower than 16 lanes walked the block once per chunk
// (AVX2 twice, SSE4 and NEON four times), and a block larger than L1 (ragdoll
// 103 KB, chain16 82 KB) came from L2 each time (docs/benchmarks.md, "RL
// calls"). `take` is copied first: the stores into the block could alias the
// caller's array, and a local one lets the compiler keep each chunk's mask in
// a register across the arrays instead of reloading it after every store.
void ResetLanesOfBlock(std::byte* block, const std::byte* initial, std::size_t arrays,
                       const LaneArray& take) {
  LaneArray* out = reinterpret_cast<LaneArray*>(block);
  const LaneArray* from = reinterpret_cast<const LaneArray*>(initial);
  const LaneArray lanes = take;
  for (std::size_t i = 0; i < arrays; ++i) {
    ForEachChunk([&](std::size_t offset) {
      const LaneMask reset = hn::Ne(Load(lanes, offset), Zero());
      Store(hn::IfThenElse(reset, Load(from[i], offset), Load(out[i], offset)), out[i], offset);
    });
  }
}

const StepKernels* GetStepKernels() {
  static const StepKernels kTable = {MANYWORLDS_THIS_TARGET, &StepBlock, &StepBlockProfiled,
                                     &ResetLanesOfBlock};
  return &kTable;
}

}  // namespace HWY_NAMESPACE
}  // namespace manyworlds
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace manyworlds {
MANYWORLDS_EXPORT_KERNEL_TABLE(StepKernels, GetStepKernels)
}  // namespace manyworlds
#endif  // HWY_ONCE
