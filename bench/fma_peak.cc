// This machine's FMA peak, measured: a Highway kernel, compiled per target and
// dispatched like the library's kernels, doing nothing but independent
// fused multiply-adds (bench/fma_peak.h).
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "bench/fma_peak.cc"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "bench/fma_peak.h"

HWY_BEFORE_NAMESPACE();
namespace manyworlds::bench::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// 12 independent accumulator chains: an FMA's result is needed again only 12
// FMAs later, which covers latency x pipes on current x86 cores (4 cycles x 2
// FMA pipes = 8 in flight on Zen 4/5 and Skylake-X) and, with the two
// constants, still fits AVX2's 16 vector registers without spilling.
// acc = acc * m + a converges to a / (1 - m) and never overflows or goes
// subnormal, so every FMA runs at full speed.
double FmaRounds(std::uint64_t rounds, float* sink) {
  const hn::ScalableTag<float> d;
  const auto m = hn::Set(d, 0.9999f);
  const auto a = hn::Set(d, 1.0e-3f);
  auto c0 = hn::Set(d, 0.0f), c1 = hn::Set(d, 0.1f), c2 = hn::Set(d, 0.2f),
       c3 = hn::Set(d, 0.3f), c4 = hn::Set(d, 0.4f), c5 = hn::Set(d, 0.5f),
       c6 = hn::Set(d, 0.6f), c7 = hn::Set(d, 0.7f), c8 = hn::Set(d, 0.8f),
       c9 = hn::Set(d, 0.9f), c10 = hn::Set(d, 1.0f), c11 = hn::Set(d, 1.1f);
  for (std::uint64_t r = 0; r < rounds; ++r) {
    c0 = hn::MulAdd(c0, m, a);
    c1 = hn::MulAdd(c1, m, a);
    c2 = hn::MulAdd(c2, m, a);
    c3 = hn::MulAdd(c3, m, a);
    c4 = hn::MulAdd(c4, m, a);
    c5 = hn::MulAdd(c5, m, a);
    c6 = hn::MulAdd(c6, m, a);
    c7 = hn::MulAdd(c7, m, a);
    c8 = hn::MulAdd(c8, m, a);
    c9 = hn::MulAdd(c9, m, a);
    c10 = hn::MulAdd(c10, m, a);
    c11 = hn::MulAdd(c11, m, a);
  }
  const auto sum = hn::Add(
      hn::Add(hn::Add(hn::Add(c0, c1), hn::Add(c2, c3)), hn::Add(hn::Add(c4, c5), hn::Add(c6, c7))),
      hn::Add(hn::Add(c8, c9), hn::Add(c10, c11)));
  *sink = hn::GetLane(hn::SumOfLanes(d, sum));  // keeps the loop alive
  // 12 FMAs of Lanes(d) lanes, 2 flops each, per round.
  return double(rounds) * 12.0 * 2.0 * double(hn::Lanes(d));
}

const char* FmaTargetName() { return hwy::TargetName(HWY_TARGET); }

}  // namespace manyworlds::bench::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace manyworlds::bench {

HWY_EXPORT(FmaRounds);
HWY_EXPORT(FmaTargetName);

double FmaPeakFlops(std::uint64_t rounds, float* sink) {
  return HWY_DYNAMIC_DISPATCH(FmaRounds)(rounds, sink);
}

const char* FmaPeakTarget() { return HWY_DYNAMIC_DISPATCH(FmaTargetName)(); }

}  // namespace manyworlds::bench
#endif  // HWY_ONCE
