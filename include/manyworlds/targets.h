// Which SIMD target the kernels run on. Highway compiles every kernel for
// several instruction sets (AVX-512, AVX2, SSE4, NEON, SVE, ... and a scalar
// fallback) and picks the best one the CPU supports at run time.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace manyworlds {

// Name of the target the kernels dispatch to on this CPU, e.g. "AVX2".
std::string DispatchedTargetName();

// Floats per vector on the dispatched target.
std::size_t DispatchedVectorLanes();

// Every target compiled into the library, best first.
std::vector<std::string> CompiledTargetNames();

// The compiled targets this CPU can run, best first.
std::vector<std::string> SupportedTargetNames();

}  // namespace manyworlds
