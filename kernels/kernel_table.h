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

// The slot of `target` in a table made by HWY_EXPORT: Highway's own layout
// (hwy/targets.h, HWY_CHOSEN_TARGET_SHIFT): slot 0 initialises dispatch, then
// one slot per dynamic target, best first, then the fallback (SCALAR or
// EMU128). Reading a slot changes nothing global, unlike restricting
// Highway's supported targets, which raced with every other thread's dispatch
// (a Batch built meanwhile could get a slower target's kernels).
inline std::size_t DispatchSlot(std::int64_t target) {
  const std::int64_t dynamic = HWY_CHOSEN_TARGET_SHIFT(target);
  if (dynamic == 0) return HWY_MAX_DYNAMIC_TARGETS + 1;  // the fallback
  return hwy::Num0BitsBelowLS1Bit_Nonzero64(static_cast<std::uint64_t>(dynamic));
}

// The tables of every target compiled here that this CPU runs, best first.
template <class Table, class Getter>
std::vector<const Table*> CollectSupportedTables(Getter* const* dispatch_table) {
  std::vector<const Table*> tables;
  for (const std::int64_t target : hwy::SupportedAndGeneratedTargets()) {
    Getter* const getter = dispatch_table[DispatchSlot(target)];
    if (getter != nullptr) tables.push_back(getter());
  }
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
// The dispatched table is the first (best) supported one, as Highway's own
// dispatch would pick, so no call here touches Highway's global state.
#define MANYWORLDS_EXPORT_KERNEL_TABLE(Table, getter)                     \
  HWY_EXPORT(getter);                                                    \
  template <>                                                            \
  const std::vector<const Table*>& SupportedKernels<Table>() {           \
    static const std::vector<const Table*> tables =                      \
        detail::CollectSupportedTables<Table>(HWY_DISPATCH_TABLE(getter)); \
    return tables;                                                       \
  }                                                                      \
  template <>                                                            \
  const Table& DispatchedKernels<Table>() {                              \
    return *SupportedKernels<Table>().front();                           \
  }

// In a part's _kernels.cc, inside HWY_NAMESPACE: this target's TargetInfo.
#define MANYWORLDS_THIS_TARGET \
  ::manyworlds::TargetInfo { HWY_TARGET, hwy::TargetName(HWY_TARGET), hn::Lanes(LaneTag()) }
