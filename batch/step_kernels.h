// The step of one block of worlds, compiled once per Highway target: the
// whole of Jolt's pipeline (spec 4.1) runs on one block while it is in cache.
#pragma once

#include <cstddef>
#include <cstdint>

#include "batch/plan.h"
#include "kernels/kernel_table.h"
#include "manyworlds/batch.h"  // StepPhase
#include "manyworlds/scene.h"

namespace manyworlds {

// Uniform across the batch for one Step call.
struct StepParams {
  float substep_delta_time;
  int substeps;
  float first_warm_start_ratio;  // dt / dt_prev of the first substep (0: cold)
  int velocity_iterations;
  float velocity_tolerance;  // StepSettings::velocity_tolerance (0: every pass)
  int position_iterations;
  float baumgarte;
  Float3 gravity;
  bool gyroscopic;  // StepSettings::gyroscopic
  JointSolver solver;     // kExact: batch/exact_solve-inl.h (the plan allows it)
  float exact_tolerance;  // m
  bool exact_curvature_velocity;
  // StepSettings::exact_geometric_stiffness x substep dt, times dt / dt_prev
  // in the first substep: the stiffness comes from the last solve's impulses,
  // which acted over the previous substep (1 where there was none).
  float exact_first_stiffness, exact_stiffness;
  // Contacts (StepSettings, docs/contacts.md).
  float speculative_contact_distance, penetration_slop, max_penetration_distance,
      min_velocity_for_restitution;
  bool speculative_contacts_from_velocity;
};

struct StepKernels {
  TargetInfo target;
  // Steps the block and checks the health of its worlds (WorldHealthLanes);
  // true if any lane of the block is unhealthy. next_block (or nullptr) is
  // the block the same thread steps next: brought into L2 meanwhile.
  bool (*step_block)(const StepPlan& plan, std::byte* block, const std::byte* next_block,
                     const StepParams& params);
  // The same step, bit for bit, adding the nanoseconds spent in each phase
  // to phase_ns[StepPhase] (kStepPhaseCount sums).
  bool (*step_block_profiled)(const StepPlan& plan, std::byte* block,
                              const std::byte* next_block, const StepParams& params,
                              std::uint64_t* phase_ns);
  // Every one of the block's `arrays` LaneArrays takes the lanes of
  // `initial` where take[lane] != 0 and keeps its own elsewhere (a select
  // and a whole store: moves only, every bit kept; one vector per array on
  // AVX-512 however many of the block's worlds reset. AVX-512's masked store
  // was no faster on the Intel Xeon it was measured on).
  void (*reset_lanes)(std::byte* block, const std::byte* initial, std::size_t arrays,
                      const LaneArray& take);
};

MANYWORLDS_DECLARE_KERNEL_TABLE(StepKernels)

}  // namespace manyworlds
