// The measured values of the behaviour tests (jolt_behaviour_test,
// contact_behaviour_test): every bounded quantity is recorded with its bound,
// and when a test ends the worst of each (worst relative to its bound) is
// printed as "[measured] <stepper> <what> = <value> (bound <bound>)" and
// recorded as a test property, so a run shows how close each check came.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <utility>

namespace manyworlds::stepper_test {

class Measurements {
 public:
  static Measurements& Get() {
    static Measurements measurements;
    return measurements;
  }
  void Clear() { worst_.clear(); }
  void Record(const std::string& what, double value, double bound) {
    auto [it, inserted] = worst_.try_emplace(what, value, bound);
    if (!inserted && !(it->second.first / it->second.second >= value / bound)) {
      it->second = {value, bound};
    }
  }
  void Print(const std::string& stepper) const {
    for (const auto& [what, entry] : worst_) {
      std::printf("  [measured] %s %s = %.3g (bound %.3g)\n", stepper.c_str(), what.c_str(),
                  entry.first, entry.second);
      ::testing::Test::RecordProperty(what, std::to_string(entry.first));
    }
  }

 private:
  std::map<std::string, std::pair<double, double>> worst_;
};

// A measured quantity that a test bounds itself (EXPECT_LE etc.).
inline void Report(const std::string& what, double value, double bound) {
  Measurements::Get().Record(what, value, bound);
}

// value ≤ bound (EXPECT_LE), recorded under `what`.
inline ::testing::AssertionResult AtMost(const std::string& what, double value, double bound) {
  Measurements::Get().Record(what, value, bound);
  if (value <= bound) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << what << ": " << value << " > " << bound;
}
#define EXPECT_AT_MOST(what, value, bound) \
  EXPECT_TRUE(::manyworlds::stepper_test::AtMost((what), (value), (bound)))

// |actual − expected| ≤ tolerance (EXPECT_NEAR), the distance recorded under `what`.
inline ::testing::AssertionResult Near(const std::string& what, double actual, double expected,
                                       double tolerance) {
  const double distance = std::abs(actual - expected);
  Measurements::Get().Record(what, distance, tolerance);
  if (distance <= tolerance) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << what << ": actual " << actual << ", expected "
                                       << expected << ", distance " << distance << " > "
                                       << tolerance;
}
#define EXPECT_MEASURED_NEAR(what, actual, expected, tolerance) \
  EXPECT_TRUE(::manyworlds::stepper_test::Near((what), (actual), (expected), (tolerance)))
#define ASSERT_MEASURED_NEAR(what, actual, expected, tolerance) \
  ASSERT_TRUE(::manyworlds::stepper_test::Near((what), (actual), (expected), (tolerance)))

}  // namespace manyworlds::stepper_test
