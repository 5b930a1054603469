// The command line around plugins: every command's help names --plugin, and printing help or the
// version never loads a plugin (so a stale $RADARPR_PLUGINS cannot break them).
#include <string>

#include <gtest/gtest.h>

#include "tests/cli/cli_runner.hpp"

namespace radarpr {
namespace {

using testing::run_cli;

#define EXPECT_CONTAINS(text, part) \
  EXPECT_NE(std::string(text).find(part), std::string::npos) << "in: " << (text)

TEST(PluginCli, EveryCommandsHelpMentionsPlugin) {
  for (const std::string command : {"run", "list", "extract", "inspect", "bench"}) {
    const auto help = run_cli(command + " --help");
    if (command == "bench" && help.output.find("built without benchmarks") != std::string::npos) {
      continue;
    }
    EXPECT_EQ(help.exit_code, 0) << command << ": " << help.output;
    EXPECT_CONTAINS(help.output, "--plugin PATH");
  }
}

TEST(PluginCli, HelpAndVersionLoadNoPlugin) {
  const std::string broken = "RADARPR_PLUGINS=/nonexistent/libbroken.so";
  for (const std::string arguments :
       {"--version", "--help", "help", "list --help", "run --help", "--version --plugin /no.so"}) {
    const auto result = run_cli(arguments, broken);
    EXPECT_EQ(result.exit_code, 0) << arguments << ": " << result.output;
    EXPECT_EQ(result.output.find("libbroken.so"), std::string::npos) << result.output;
  }
  // Real work still loads them, and fails on the broken one.
  const auto listed = run_cli("list", broken);
  EXPECT_EQ(listed.exit_code, 1);
  EXPECT_CONTAINS(listed.output, "plugin /nonexistent/libbroken.so: file not found");
}

TEST(PluginCli, AnUnknownDescriptorOnTheCommandLineHintsAtPlugin) {
  const auto result = run_cli("list range_histogram");
  EXPECT_EQ(result.exit_code, 1) << result.output;
  EXPECT_CONTAINS(result.output, "unknown descriptor 'range_histogram'");
  EXPECT_CONTAINS(result.output, "--plugin PATH");
}

}  // namespace
}  // namespace radarpr
