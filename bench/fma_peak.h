// This machine's FMA peak, measured in the benchmark's own run (the roofline's
// denominator, docs/benchmarks.md "Roofline"): a Highway kernel of independent
// fused multiply-adds, dispatched to the best target the CPU supports, the
// same choice as the library's kernels.
#pragma once

#include <cstdint>

namespace manyworlds::bench {

// Runs `rounds` rounds of 12 independent vector FMAs on the dispatched target
// and returns the flops done (an FMA = 2 flops per lane). The result goes to
// *sink so that the loop is not optimised away.
double FmaPeakFlops(std::uint64_t rounds, float* sink);

// The Highway target FmaPeakFlops runs on, e.g. "AVX3".
const char* FmaPeakTarget();

}  // namespace manyworlds::bench
