// Running another program without a shell (see subprocess.h).

#include "tools/subprocess.h"

#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <string_view>
#include <system_error>

extern char** environ;

namespace manyworlds::tools {

std::filesystem::path FindOnPath(const std::string& name) {
  const char* variable = std::getenv("PATH");
  const std::string_view folders = variable != nullptr ? variable : "/usr/bin:/bin";
  for (std::size_t start = 0;;) {
    std::size_t end = folders.find(':', start);
    if (end == std::string_view::npos) end = folders.size();
    // An empty entry is the current folder, as for execvp.
    const std::string_view folder = folders.substr(start, end - start);
    const std::filesystem::path candidate =
        std::filesystem::path(folder.empty() ? "." : std::string(folder)) / name;
    std::error_code error;
    if (std::filesystem::is_regular_file(candidate, error) &&
        ::access(candidate.c_str(), X_OK) == 0) {
      // Absolute: the program starts in another folder, where a relative
      // PATH entry would name something else.
      return std::filesystem::absolute(candidate, error);
    }
    if (end == folders.size()) return {};
    start = end + 1;
  }
}

void RunInFolder(const std::filesystem::path& program, const std::vector<std::string>& args,
                 const std::filesystem::path& folder) {
  std::vector<std::string> strings{program.string()};
  strings.insert(strings.end(), args.begin(), args.end());
  std::vector<char*> argv;
  std::string command;
  for (std::string& s : strings) {
    argv.push_back(s.data());
    command += (command.empty() ? "" : " ") + s;
  }
  argv.push_back(nullptr);
  const std::string what = "'" + command + "' in '" + folder.string() + "'";

  // posix_spawn rather than fork + chdir + exec: glibc's reports a failed
  // chdir or exec as its return value, where a forked child could only
  // hint at it through its exit code.
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addchdir_np(&actions, folder.c_str());
  std::fflush(nullptr);  // what we printed so far before what the program prints
  pid_t pid = 0;
  const int error = posix_spawn(&pid, program.c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (error != 0) throw std::runtime_error("could not run " + what + ": " + std::strerror(error));

  int status = 0;
  while (::waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) {
      throw std::runtime_error("lost " + what + ": " + std::strerror(errno));
    }
  }
  if (WIFEXITED(status) && WEXITSTATUS(status) == 0) return;
  throw std::runtime_error(what + (WIFEXITED(status)
                                       ? " exited with code " + std::to_string(WEXITSTATUS(status))
                                       : " was killed by signal " + std::to_string(WTERMSIG(status))));
}

}  // namespace manyworlds::tools
