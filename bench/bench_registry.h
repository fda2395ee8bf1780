// How each part plugs its benchmarks into part_bench.
//
// A part's bench file (bench/<part>_bench.cc) defines a batch type and its
// verbs and registers them at static-initialisation time:
//
//   class AxisBatch {
//    public:
//     AxisBatch(const AxisKernels& kernels, std::size_t worlds);  // random
//         // per-world inputs (fixed seed), properties already calculated
//     std::string Insane() const;  // "" if every value is finite and bounded
//     ...
//   };
//   const bool kRegistered = RegisterPartBenchmarks<AxisBatch, AxisKernels>(
//       "axis", {{"calculate_properties", &CalculateProperties},
//                {"solve_velocity", &SolveVelocity}, ...});
//
// where each verb is `bool (*)(AxisBatch&, std::size_t iteration)`: it runs
// the verb over every block once and returns what the kernels returned (so
// nothing is dead code). part_bench registers every (part, verb) on the
// dispatched target and on Highway's scalar target and prints their ratio.
#pragma once

#include <cstddef>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "kernels/kernel_table.h"

namespace manyworlds::bench {

// One verb's batch, ready to run.
class VerbRun {
 public:
  virtual ~VerbRun() = default;
  virtual bool Run(std::size_t iteration) = 0;
  virtual std::string Insane() const = 0;
};

struct VerbBenchmark {
  std::string part;
  std::string verb;
  // Builds the batch on one target; nullptr if the target has no table.
  std::function<std::unique_ptr<VerbRun>(const TargetInfo& target, std::size_t worlds)>
      make;
};

// Every registered verb benchmark, in registration order.
std::vector<VerbBenchmark>& Registry();

template <class Batch>
using VerbFunction = bool (*)(Batch&, std::size_t iteration);

template <class Batch, class Table>
bool RegisterPartBenchmarks(
    const char* part, std::vector<std::pair<const char*, VerbFunction<Batch>>> verbs) {
  class BatchRun final : public VerbRun {
   public:
    BatchRun(const Table& kernels, std::size_t worlds, VerbFunction<Batch> verb)
        : batch_(kernels, worlds), verb_(verb) {}
    bool Run(std::size_t iteration) override { return verb_(batch_, iteration); }
    std::string Insane() const override { return batch_.Insane(); }

   private:
    Batch batch_;
    VerbFunction<Batch> verb_;
  };
  for (const auto& [verb_name, verb] : verbs) {
    Registry().push_back(
        {part, verb_name,
         [verb = verb](const TargetInfo& target,
                       std::size_t worlds) -> std::unique_ptr<VerbRun> {
           const Table* kernels = KernelsForTarget<Table>(target.bits);
           if (kernels == nullptr) return nullptr;
           return std::make_unique<BatchRun>(*kernels, worlds, verb);
         }});
  }
  return true;
}

}  // namespace manyworlds::bench
