// The gnuplot script of `manyworlds sweep` (tools/sweep_report.h) quotes what
// it did not write itself (issue 21): a scene id with a quote, a command line
// with a line break or a trailing backslash cannot end a string or a comment
// and become a gnuplot command (gnuplot's system() runs a shell).

#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "tools/sweep_report.h"

namespace manyworlds::tools {
namespace {

std::string GnuplotOf(const std::string& scene, const std::string& command_line) {
  Row row;
  row.scene = scene;
  row.ns_per_world_step = 10.0;
  row.position.Add(1e-3);
  SweepConfig config;
  config.scenes = {scene};
  config.command_line = command_line;
  std::ostringstream gp;
  WriteGnuplot(gp, {row}, config, Machine{"AVX3", 16, 1, "process CPU time"});
  return gp.str();
}

std::vector<std::string> LinesOf(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream stream(text);
  for (std::string line; std::getline(stream, line);) lines.push_back(line);
  return lines;
}

TEST(SweepReportTest, GnuplotStringsDoubleTheirQuotes) {
  const std::string gp = GnuplotOf("it's", "manyworlds sweep");
  EXPECT_NE(gp.find("set output 'it''s.png'\n"), std::string::npos) << gp;
  EXPECT_NE(gp.find("title 'it''s: error against cost"), std::string::npos) << gp;
}

TEST(SweepReportTest, CommandLineStaysInOneComment) {
  const std::string gp =
      GnuplotOf("chain16", "manyworlds sweep --out 'a\nsystem \"touch INJECTED\"\r\nb\\");
  const std::vector<std::string> lines = LinesOf(gp);
  ASSERT_GE(lines.size(), 3u);
  EXPECT_EQ(lines[1], "# manyworlds sweep --out 'a system \"touch INJECTED\"  b\\ ");
  // The comment is not continued (a line ending in a backslash would be) and
  // the line after it is the script's own.
  EXPECT_EQ(lines[2], "# Run: gnuplot sweep.gp (in this directory).");
  for (const std::string& line : lines) {
    EXPECT_FALSE(line.starts_with("system")) << line;
    EXPECT_FALSE(line.ends_with('\\')) << line;
  }
}

}  // namespace
}  // namespace manyworlds::tools
