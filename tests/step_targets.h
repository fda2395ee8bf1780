// The Highway targets the batch stepper can run on this CPU, for tests that
// run once per target (BatchOptions::target).
#pragma once

#include <cstdint>
#include <vector>

#include "batch/step_kernels.h"
#include "hwy/targets.h"  // hwy::TargetName, for test names

namespace manyworlds {

inline std::vector<std::int64_t> SupportedStepTargets() {
  std::vector<std::int64_t> targets;
  for (const StepKernels* kernels : SupportedKernels<StepKernels>()) {
    targets.push_back(kernels->target.bits);
  }
  return targets;
}

}  // namespace manyworlds
