// Command-line options of the manyworlds program's commands: "--name value",
// "--name=value" and bare flags, checked against the options a command knows;
// each at most once.
#pragma once

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <cstdint>
#include <map>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace manyworlds::tools {

// A bad command line: the one-line message names the argument and what
// would be accepted; exit code 2.
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// "a, b, c": for messages that list what is accepted.
inline std::string JoinNames(const std::vector<std::string_view>& names) {
  std::string text;
  for (const std::string_view name : names) {
    text += (text.empty() ? "" : ", ") + std::string(name);
  }
  return text;
}

// A number as a person writes it in a range ("0.001", "1e+30"), not
// std::to_string's "0.001000".
inline std::string ShortNumber(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

class Options {
 public:
  // argv[1] is the command; options start at argv[2]. `flags` take no value.
  Options(int argc, char** argv, std::vector<std::string_view> known,
          std::vector<std::string_view> flags = {}) {
    for (int i = 2; i < argc; ++i) {
      std::string_view arg = argv[i];
      if (!arg.starts_with("--")) {
        throw UsageError("unexpected argument '" + std::string(arg) + "' for '" + argv[1] +
                         "'; it takes options only: " + Accepted(known, flags));
      }
      if (std::find(flags.begin(), flags.end(), arg) != flags.end()) {
        Set(arg, "");
        continue;
      }
      std::string_view value;
      bool has_value = false;
      if (const std::size_t eq = arg.find('='); eq != std::string_view::npos) {
        value = arg.substr(eq + 1);
        arg = arg.substr(0, eq);
        has_value = true;
      }
      if (std::find(known.begin(), known.end(), arg) == known.end()) {
        throw UsageError("unknown option '" + std::string(arg) + "' for '" + argv[1] +
                         "'; accepted: " + Accepted(known, flags));
      }
      if (!has_value) {
        if (i + 1 >= argc) {
          throw UsageError(std::string(arg) + " needs a value (" + std::string(arg) +
                           " VALUE or " + std::string(arg) + "=VALUE)");
        }
        value = argv[++i];
      }
      Set(arg, value);
    }
  }

  bool Has(const std::string& name) const { return values_.contains(name); }

  std::string Text(const std::string& name) const {
    const auto found = values_.find(name);
    if (found == values_.end()) throw UsageError(name + " is required");
    return found->second;
  }
  std::string Text(const std::string& name, const std::string& fallback) const {
    return Has(name) ? Text(name) : fallback;
  }

  // A whole number in [min, max]; `fallback` when the option is absent.
  std::uint64_t Number(const std::string& name, std::uint64_t fallback, std::uint64_t min,
                       std::uint64_t max) const {
    const auto found = values_.find(name);
    if (found == values_.end()) return fallback;
    const std::string& text = found->second;
    std::uint64_t value = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc() || end != text.data() + text.size() || value < min || value > max) {
      throw UsageError(name + " = '" + text + "' is not a whole number from " +
                       std::to_string(min) + " to " + std::to_string(max));
    }
    return value;
  }

  // A finite number in [min, max]; `fallback` when the option is absent.
  double Real(const std::string& name, double fallback, double min, double max) const {
    const auto found = values_.find(name);
    if (found == values_.end()) return fallback;
    const std::string& text = found->second;
    double value = 0.0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc() || end != text.data() + text.size() || !(value >= min) ||
        !(value <= max)) {
      throw UsageError(name + " = '" + text + "' is not a number from " + ShortNumber(min) +
                       " to " + ShortNumber(max));
    }
    return value;
  }

 private:
  static std::string Accepted(const std::vector<std::string_view>& known,
                              const std::vector<std::string_view>& flags) {
    std::vector<std::string_view> all = known;
    all.insert(all.end(), flags.begin(), flags.end());
    return JoinNames(all);
  }

  // An option given twice is refused: which of the two was meant is a guess.
  void Set(std::string_view name, std::string_view value) {
    if (!values_.emplace(name, value).second) {
      throw UsageError(std::string(name) + " given twice");
    }
  }

  std::map<std::string, std::string> values_;
};

// --mass-range-limit R of the run and sweep commands: the max_ratio of
// LimitMassRange (manyworlds/mass_range.h), at least 1; 0 or absent: off.
inline double MassRangeLimitOption(const Options& options) {
  const double limit = options.Real("--mass-range-limit", 0, 0, 1e30);
  if (limit != 0 && limit < 1) {
    throw UsageError("--mass-range-limit = '" + options.Text("--mass-range-limit") +
                     "' is neither 0 (off) nor a number from 1 to 1e+30");
  }
  return limit;
}

}  // namespace manyworlds::tools
