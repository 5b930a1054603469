#pragma once

// Runs the built radarpr program (RADARPR_CLI_PATH) for the CLI tests.
#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <string>

namespace radarpr::testing {

struct CommandResult {
  int exit_code = -1;
  std::string output;  // stdout and stderr
};

// `environment` ("NAME=value ...") goes in front of the command.
inline CommandResult run_cli(const std::string& arguments, const std::string& environment = "") {
  const std::string command =
      environment + " " + std::string(RADARPR_CLI_PATH) + " " + arguments + " 2>&1";
  CommandResult result;
  FILE* pipe = ::popen(command.c_str(), "r");
  if (pipe == nullptr) return result;
  std::array<char, 4096> buffer{};
  while (std::fgets(buffer.data(), buffer.size(), pipe) != nullptr) result.output += buffer.data();
  const int status = ::pclose(pipe);
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return result;
}

}  // namespace radarpr::testing
