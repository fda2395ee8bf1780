// Running another program without a shell (issue 21): found on PATH here and
// started with an argument vector, so no character of an argument or of the
// folder it runs in is ever read as shell syntax.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace manyworlds::tools {

// The absolute path of the executable `name` in the first folder of $PATH
// that holds one (the folders execvp searches; /usr/bin:/bin when PATH is
// unset), or an empty path when none does.
std::filesystem::path FindOnPath(const std::string& name);

// Runs `program` with the arguments `args` (argv[1] on) in the working folder
// `folder`, and waits for it. Throws std::runtime_error naming the command and
// the folder when it cannot be started or does not exit with code 0.
void RunInFolder(const std::filesystem::path& program, const std::vector<std::string>& args,
                 const std::filesystem::path& folder);

}  // namespace manyworlds::tools
