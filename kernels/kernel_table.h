// Per-target tables of kernels and how to reach them.
//
// Every constraint part compiles its kernels once per Highway target (in its
// own kernels/<part>_kernels.cc) into a table of function pointers whose first
// member is `TargetInfo target`. At run time:
//   DispatchedKernels<Table>()   the table of the best target this CPU runs,
//   SupportedKernels<Table>()    the tables of every compiled target this CPU
//                                runs, best first (tests run all of them),
//   KernelsForTarget<Table>(t)   one of them, e.g. HWY_SCALAR for baselines.
#pragma once

#include <cstddef>
#include <cstdint>
#include <mutex>
#include <vector>

#include "hwy/targets.h"

namespace manyworlds {

struct TargetInfo {
  std::int64_t bits;         // Highway target bit (HWY_AVX2, HWY_SCALAR, ...)
  const char* name;          // Highway's name of it ("AVX2", "SCALAR", ...)
  std::size_t vector_lanes;  // floats per vector on this target
};

template <class Table>
const Table& DispatchedKernels();

template <class Table>
const std::vector<const Table*>& SupportedKernels();

template <class Table>
const Table* KernelsForTarget(std::int64_t target) {
  for (const Table* table : SupportedKernels<Table>()) {
    if (table->target.bits == target) return table;
  }
  return nullptr;
}

namespace detail {

// One lock for every table type: the target restriction below is global.
inline std::mutex& TargetRestrictionMutex() {
  static std::mutex mutex;
  return mutex;
}

// Highway only dispatches to its chosen target; to reach the others we
// restrict the supported set to one target at a time (the mechanism of
// Highway's own per-target tests), then restore normal dispatch. Serialised,
// because the restriction is global; each table collects once (on first use),
// so do that before starting threads that dispatch Highway code themselves.
template <class Table, class Dispatch>
std::vector<const Table*> CollectSupportedTables(Dispatch dispatch) {
  const std::lock_guard<std::mutex> lock(TargetRestrictionMutex());
  std::vector<const Table*> tables;
  for (const std::int64_t target : hwy::SupportedAndGeneratedTargets()) {
    hwy::SetSupportedTargetsForTest(target);
    tables.push_back(dispatch());
  }
  hwy::SetSupportedTargetsForTest(0);
  return tables;
}

}  // namespace detail
}  // namespace manyworlds

// In a part's header: declares the accessors of its table.
#define MANYWORLDS_DECLARE_KERNEL_TABLE(Table)                           \
  template <>                                                            \
  const Table& DispatchedKernels<Table>();                               \
  template <>                                                            \
  const std::vector<const Table*>& SupportedKernels<Table>();

// In a part's _kernels.cc, inside namespace manyworlds under HWY_ONCE, where
// `getter` is the per-target function returning that target's table.
#define MANYWORLDS_EXPORT_KERNEL_TABLE(Table, getter)                     \
  HWY_EXPORT(getter);                                                    \
  template <>                                                            \
  const Table& DispatchedKernels<Table>() {                              \
    return *HWY_DYNAMIC_DISPATCH(getter)();                              \
  }                                                                      \
  template <>                                                            \
  const std::vector<const Table*>& SupportedKernels<Table>() {           \
    static const std::vector<const Table*> tables =                      \
        detail::CollectSupportedTables<Table>(                           \
            [] { return HWY_DYNAMIC_DISPATCH(getter)(); });              \
    return tables;                                                       \
  }

// In a part's _kernels.cc, inside HWY_NAMESPACE: this target's TargetInfo.
#define MANYWORLDS_THIS_TARGET \
  ::manyworlds::TargetInfo { HWY_TARGET, hwy::TargetName(HWY_TARGET), hn::Lanes(LaneTag()) }
