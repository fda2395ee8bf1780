// One constraint (or body) of one block, as the step kernels see it: typed
// views into the block's bytes at the offsets of the plan.
#pragma once

#include <cstddef>

#include "batch/constraint_lanes.h"
#include "batch/plan.h"
#include "kernels/body_lanes.h"

namespace manyworlds {

template <class Lanes>
Lanes& At(std::byte* block, std::size_t offset) {
  return *reinterpret_cast<Lanes*>(block + offset);
}
template <class Lanes>
const Lanes& At(const std::byte* block, std::size_t offset) {
  return *reinterpret_cast<const Lanes*>(block + offset);
}

inline BodyLanes& BodyAt(const StepPlan& plan, std::byte* block, std::size_t body) {
  return At<BodyLanes>(block, plan.bodies[body].offset);
}

// A constraint of the plan inside one block.
struct ConstraintBlock {
  const ConstraintPlan& plan;
  std::byte* block;
  BodyPair bodies;

  template <class Lanes>
  Lanes& Main() const { return At<Lanes>(block, plan.offset); }
  // The type's ...Scratch struct: only inside a working block (a step).
  template <class Lanes>
  Lanes& Scratch() const { return At<Lanes>(block, plan.scratch_offset); }
  // The limit and motor rows as the step uses them (...Row): only inside
  // a working block.
  template <class Row>
  Row& Limit() const { return At<Row>(block, plan.limit_scratch_offset); }
  template <class Row>
  Row& Motor() const { return At<Row>(block, plan.motor_scratch_offset); }
};

inline ConstraintBlock ConstraintInBlock(const StepPlan& plan, std::size_t constraint,
                                         std::byte* block) {
  const ConstraintPlan& c = plan.constraints[constraint];
  return ConstraintBlock{c, block,
                         BodyPair{&BodyAt(plan, block, c.body1), c.motion1,
                                  &BodyAt(plan, block, c.body2), c.motion2}};
}

// Per-step numbers every constraint verb may need, uniform across the block.
struct StepScalars {
  float delta_time;          // of one substep
  float warm_start_ratio;    // dt / dt_prev (first substep), 0 without warm start
  float baumgarte;
};

}  // namespace manyworlds
