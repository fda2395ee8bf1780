// The command-line options of the manyworlds program (tools/options.h): both
// forms of a value, flags, and an option given twice refused by name (issue
// 21: `--scene a --scene b` silently stepped b).

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "tools/options.h"

namespace manyworlds::tools {
namespace {

// Options of `manyworlds <args>` that knows --scene and --worlds and the
// flag --small.
Options Parse(std::vector<std::string> args) {
  args.insert(args.begin(), "manyworlds");
  std::vector<char*> argv;
  for (std::string& arg : args) argv.push_back(arg.data());
  return Options(int(argv.size()), argv.data(), {"--scene", "--worlds"}, {"--small"});
}

// The message of the UsageError that parsing `args` throws; "" if none.
std::string UsageErrorOf(const std::vector<std::string>& args) {
  try {
    Parse(args);
  } catch (const UsageError& e) {
    return e.what();
  }
  return "";
}

TEST(Options, ValuesInBothFormsAndFlags) {
  const Options options = Parse({"run", "--scene=chain16", "--worlds", "8", "--small"});
  EXPECT_EQ(options.Text("--scene"), "chain16");
  EXPECT_EQ(options.Number("--worlds", 1, 1, 100), 8u);
  EXPECT_TRUE(options.Has("--small"));
}

TEST(Options, AnOptionGivenTwiceIsRefusedByName) {
  EXPECT_EQ(UsageErrorOf({"run", "--scene", "a", "--scene", "b"}), "--scene given twice");
  EXPECT_EQ(UsageErrorOf({"run", "--scene=a", "--scene=b"}), "--scene given twice");
  EXPECT_EQ(UsageErrorOf({"run", "--worlds=1", "--worlds", "2"}), "--worlds given twice");
  EXPECT_EQ(UsageErrorOf({"run", "--worlds", "1", "--worlds=1"}), "--worlds given twice");
  EXPECT_EQ(UsageErrorOf({"run", "--small", "--scene", "a", "--small"}), "--small given twice");
}

}  // namespace
}  // namespace manyworlds::tools
