#pragma once

// Runs the built radarpr program (RADARPR_CLI_PATH) for the CLI tests.
#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <string>

namespace radarpr::testing {

struct CommandResult {
  int exit_code = -1;
  std::string output;  // stdout, and stderr where redirected
};

// Runs a shell command line; its stdout (add 2>&1 for stderr) and exit code.
inline CommandResult run_command_line(const std::string& command) {
  CommandResult result;
  FILE* pipe = ::popen(command.c_str(), "r");
  if (pipe == nullptr) return result;
  std::array<char, 4096> buffer{};
  while (std::fgets(buffer.data(), buffer.size(), pipe) != nullptr) result.output += buffer.data();
  const int status = ::pclose(pipe);
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return result;
}

// `environment` ("NAME=value ...") goes in front of the command.
inline CommandResult run_cli(const std::string& arguments, const std::string& environment = "") {
  return run_command_line(environment + " " + std::string(RADARPR_CLI_PATH) + " " + arguments +
                          " 2>&1");
}

// A copy of the built program alone in FOLDER (created): it finds no module beside it.
inline std::filesystem::path lone_program_copy(const std::filesystem::path& folder) {
  std::filesystem::create_directories(folder);
  std::filesystem::copy_file(RADARPR_CLI_PATH, folder / "radarpr");
  return folder / "radarpr";
}

}  // namespace radarpr::testing
