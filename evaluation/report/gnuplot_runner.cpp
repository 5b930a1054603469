#include "evaluation/report/gnuplot_runner.hpp"

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <vector>

#include <fmt/format.h>

#include "evaluation/text_escaping.hpp"

namespace radarpr {
namespace {

namespace fs = std::filesystem;

// A PATH folder that cannot be searched (no permission, a file, gone) is skipped, as a shell
// does: the throwing is_regular_file made such a folder end the run after its results.
bool executable(const fs::path& path) {
  std::error_code error;
  return fs::is_regular_file(path, error) && ::access(path.c_str(), X_OK) == 0;
}

}  // namespace

GnuplotLookup look_up_gnuplot() {
  if (const char* chosen = std::getenv("RADARPR_GNUPLOT"); chosen != nullptr && *chosen != '\0') {
    const std::string value(chosen);
    if (value == "off") return {std::nullopt, "gnuplot is off (RADARPR_GNUPLOT=off)"};
    // A path that is not a program is named, not taken for a missing install.
    if (!executable(value)) {
      return {std::nullopt, fmt::format("RADARPR_GNUPLOT names {}, which is not an executable file",
                                        printable(value))};
    }
    return {fs::path(value), ""};
  }
  const char* search = std::getenv("PATH");
  std::stringstream folders(search != nullptr ? search : "/usr/bin:/bin");
  std::string folder;
  while (std::getline(folders, folder, ':')) {
    if (folder.empty()) continue;
    const fs::path candidate = fs::path(folder) / "gnuplot";
    if (executable(candidate)) return {candidate, ""};
  }
  return {std::nullopt, "gnuplot not found on PATH (install gnuplot to draw them)"};
}

std::optional<fs::path> find_gnuplot() {
  return look_up_gnuplot().program;
}

std::optional<std::string> run_gnuplot(const fs::path& gnuplot, const fs::path& folder,
                                       const std::string& script) {
  // stderr goes to a file beside the figures, read back and removed: no pipe to drain, and the
  // child cannot block on a full one.
  const fs::path log = folder / (script + ".stderr");
  // Everything the child needs is built before fork: figures are drawn from several threads, and
  // a child allocating memory could wait forever on a lock another thread held at the fork.
  const std::string program = gnuplot.string();
  char* const argv[] = {const_cast<char*>(program.c_str()), const_cast<char*>(script.c_str()),
                        nullptr};
  const pid_t child = ::fork();
  if (child < 0) return "cannot start a process (fork failed)";
  if (child == 0) {
    // Only async-signal-safe calls between fork and exec.
    if (::chdir(folder.c_str()) != 0) ::_exit(126);
    const int err = ::open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int null = ::open("/dev/null", O_RDWR);
    if (err >= 0) ::dup2(err, STDERR_FILENO);
    if (null >= 0) {
      ::dup2(null, STDIN_FILENO);
      ::dup2(null, STDOUT_FILENO);
    }
    ::execv(program.c_str(), argv);
    ::_exit(127);
  }
  int status = 0;
  while (::waitpid(child, &status, 0) < 0) {
    if (errno != EINTR) return "lost the gnuplot process (waitpid failed)";
  }
  std::string errors;
  {
    std::ifstream file(log);
    std::stringstream text;
    text << file.rdbuf();
    errors = text.str();
  }
  std::error_code ignored;
  fs::remove(log, ignored);
  while (!errors.empty() && (errors.back() == '\n' || errors.back() == ' ')) errors.pop_back();
  if (WIFEXITED(status) && WEXITSTATUS(status) == 0) return std::nullopt;
  if (WIFEXITED(status) && WEXITSTATUS(status) == 127) {
    return fmt::format("cannot execute {}", gnuplot.string());
  }
  return fmt::format("gnuplot failed ({}){}{}",
                     WIFEXITED(status) ? fmt::format("exit code {}", WEXITSTATUS(status))
                                       : std::string("killed by a signal"),
                     errors.empty() ? "" : ": ", errors);
}

}  // namespace radarpr
