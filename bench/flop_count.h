// Counted floating-point operations: a scalar type that does float (or
// double) arithmetic and tallies every operation, so that the scalar reference
// stepper (reference::World<Counted<float>>) counts the flops of one world-step
// from its own code instead of an estimate (docs/benchmarks.md, "Roofline").
//
// Counting rule (the usual one for flop rates):
//   +, -, *, / and sqrt      1 flop each (a*b + c is a multiply and an add: the
//                            reference writes no FMA, so an FMA counts as 2);
//   sin, cos                 12 each, atan 15, atan2 18, fmod 3: the flops of
//                            the kernels' own lane maths (kernels/lane_math-inl.h:
//                            SinCos is 24 for both, AtanOfNonNegative 15, Atan2 a
//                            division, it and two subtractions), which is what the
//                            SIMD stepper executes in their place; fmod as
//                            x - trunc(x / y) y;
//   negation, abs, min, max,
//   trunc, comparisons,
//   copies                   0 (sign-bit, rounding and select operations, not
//                            arithmetic).
// Transcendental calls are also tallied by themselves, so their share is visible.
//
// The reference calls std::sqrt, std::sin, ... qualified, which no
// argument-dependent lookup can redirect; so this header adds overloads of
// those functions for Counted<F> to namespace std. The standard leaves that
// undefined; g++ and clang find them by ordinary qualified lookup, provided
// this header is included BEFORE reference/world.h (it includes <cmath> and
// Eigen first for that reason). It is a benchmark tool and is compiled only
// into scene_bench and its test. std::numbers::pi_v and std::numeric_limits
// are specialised for Counted, which the standard allows for program-defined
// types.
#pragma once

#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <type_traits>

#include <Eigen/Core>

namespace manyworlds::bench {

// Operations since the last Reset(), per thread.
struct FlopTally {
  std::uint64_t add = 0;  // + and -
  std::uint64_t mul = 0;
  std::uint64_t div = 0;
  std::uint64_t sqrt = 0;
  std::uint64_t transcendental_calls = 0;  // sin, cos, atan, atan2, fmod
  std::uint64_t transcendental_flops = 0;  // their flops by the rule above

  std::uint64_t Flops() const { return add + mul + div + sqrt + transcendental_flops; }
};

inline FlopTally& Tally() {
  static thread_local FlopTally tally;
  return tally;
}
inline void ResetTally() { Tally() = FlopTally{}; }

// Flops charged per call of a transcendental (see the rule above).
inline constexpr std::uint64_t kSinFlops = 12, kCosFlops = 12, kAtanFlops = 15,
                               kAtan2Flops = 18, kFmodFlops = 3;

template <class F>
class Counted {
  static_assert(std::is_floating_point_v<F>);

 public:
  constexpr Counted() = default;
  // Explicit from any arithmetic value, as T(0.5) in the reference; implicit
  // conversions would make mixed expressions ambiguous and could hide an
  // uncounted operation done in plain float.
  template <class U, class = std::enable_if_t<std::is_arithmetic_v<U>>>
  constexpr explicit Counted(U value) : value_(F(value)) {}

  constexpr F value() const { return value_; }
  // Explicit, and not counted: the reference leaves T only in its ellipse
  // projection (reference/math.h, swing limits), which iterates in double.
  template <class U, class = std::enable_if_t<std::is_arithmetic_v<U>>>
  constexpr explicit operator U() const {
    return U(value_);
  }

  constexpr Counted operator-() const { return Counted(-value_); }  // sign flip: 0 flops
  constexpr Counted operator+() const { return *this; }

  friend constexpr Counted operator+(Counted a, Counted b) {
    Count(&FlopTally::add);
    return Counted(a.value_ + b.value_);
  }
  friend constexpr Counted operator-(Counted a, Counted b) {
    Count(&FlopTally::add);
    return Counted(a.value_ - b.value_);
  }
  friend constexpr Counted operator*(Counted a, Counted b) {
    Count(&FlopTally::mul);
    return Counted(a.value_ * b.value_);
  }
  friend constexpr Counted operator/(Counted a, Counted b) {
    Count(&FlopTally::div);
    return Counted(a.value_ / b.value_);
  }
  constexpr Counted& operator+=(Counted b) { return *this = *this + b; }
  constexpr Counted& operator-=(Counted b) { return *this = *this - b; }
  constexpr Counted& operator*=(Counted b) { return *this = *this * b; }
  constexpr Counted& operator/=(Counted b) { return *this = *this / b; }

  friend constexpr bool operator==(Counted a, Counted b) { return a.value_ == b.value_; }
  friend constexpr auto operator<=>(Counted a, Counted b) { return a.value_ <=> b.value_; }

  // Called by the math overloads below.
  static Counted Charged(F value, std::uint64_t FlopTally::*field, std::uint64_t flops = 1) {
    Count(field, flops);
    return Counted(value);
  }
  static Counted Transcendental(F value, std::uint64_t flops) {
    ++Tally().transcendental_calls;
    Count(&FlopTally::transcendental_flops, flops);
    return Counted(value);
  }

 private:
  // Constant evaluation (constexpr constants such as 2 pi) is not run time work.
  static constexpr void Count(std::uint64_t FlopTally::*field, std::uint64_t flops = 1) {
    if (!std::is_constant_evaluated()) Tally().*field += flops;
  }

  F value_ = F(0);
};

// Found by argument-dependent lookup (Eigen calls them unqualified).
template <class F>
Counted<F> sqrt(Counted<F> x) {
  return Counted<F>::Charged(std::sqrt(x.value()), &FlopTally::sqrt);
}
template <class F>
Counted<F> abs(Counted<F> x) {
  return Counted<F>(std::abs(x.value()));
}
template <class F>
Counted<F> trunc(Counted<F> x) {
  return Counted<F>(std::trunc(x.value()));
}
template <class F>
Counted<F> sin(Counted<F> x) {
  return Counted<F>::Transcendental(std::sin(x.value()), kSinFlops);
}
template <class F>
Counted<F> cos(Counted<F> x) {
  return Counted<F>::Transcendental(std::cos(x.value()), kCosFlops);
}
template <class F>
Counted<F> atan(Counted<F> x) {
  return Counted<F>::Transcendental(std::atan(x.value()), kAtanFlops);
}
template <class F>
Counted<F> atan2(Counted<F> y, Counted<F> x) {
  return Counted<F>::Transcendental(std::atan2(y.value(), x.value()), kAtan2Flops);
}
template <class F>
Counted<F> fmod(Counted<F> x, Counted<F> y) {
  return Counted<F>::Transcendental(std::fmod(x.value(), y.value()), kFmodFlops);
}
template <class F>
bool isfinite(Counted<F> x) {
  return std::isfinite(x.value());
}
template <class F>
bool isnan(Counted<F> x) {
  return std::isnan(x.value());
}
template <class F>
bool isinf(Counted<F> x) {
  return std::isinf(x.value());
}

}  // namespace manyworlds::bench

// The reference's qualified calls (see the header comment).
namespace std {
using manyworlds::bench::abs;
using manyworlds::bench::atan;
using manyworlds::bench::atan2;
using manyworlds::bench::cos;
using manyworlds::bench::fmod;
using manyworlds::bench::isfinite;
using manyworlds::bench::isinf;
using manyworlds::bench::isnan;
using manyworlds::bench::sin;
using manyworlds::bench::sqrt;
using manyworlds::bench::trunc;

template <class F>
class numeric_limits<manyworlds::bench::Counted<F>> : public numeric_limits<F> {
  using C = manyworlds::bench::Counted<F>;

 public:
  static constexpr C min() noexcept { return C(numeric_limits<F>::min()); }
  static constexpr C max() noexcept { return C(numeric_limits<F>::max()); }
  static constexpr C lowest() noexcept { return C(numeric_limits<F>::lowest()); }
  static constexpr C epsilon() noexcept { return C(numeric_limits<F>::epsilon()); }
  static constexpr C infinity() noexcept { return C(numeric_limits<F>::infinity()); }
  static constexpr C quiet_NaN() noexcept { return C(numeric_limits<F>::quiet_NaN()); }
};

namespace numbers {
template <class F>
inline constexpr manyworlds::bench::Counted<F> pi_v<manyworlds::bench::Counted<F>> =
    manyworlds::bench::Counted<F>(pi_v<F>);
}  // namespace numbers
}  // namespace std

namespace Eigen {
template <class F>
struct NumTraits<manyworlds::bench::Counted<F>> : NumTraits<F> {
  using Real = manyworlds::bench::Counted<F>;
  using NonInteger = Real;
  using Nested = Real;
  using Literal = Real;
  enum { IsComplex = 0, IsInteger = 0, IsSigned = 1, RequireInitialization = 1,
         ReadCost = 1, AddCost = 1, MulCost = 1 };
  static inline Real epsilon() { return Real(NumTraits<F>::epsilon()); }
  static inline Real dummy_precision() { return Real(NumTraits<F>::dummy_precision()); }
  static inline Real highest() { return Real(NumTraits<F>::highest()); }
  static inline Real lowest() { return Real(NumTraits<F>::lowest()); }
  static inline Real infinity() { return Real(NumTraits<F>::infinity()); }
  static inline Real quiet_NaN() { return Real(NumTraits<F>::quiet_NaN()); }
};
}  // namespace Eigen
