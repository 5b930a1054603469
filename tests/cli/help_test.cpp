// The help is generated from the command line's definitions: every option of every verb appears
// in its --help (with its default), every verb in the program's help, and docs/cli.md carries the
// program's own help text (RADARPR_UPDATE_CLI_DOCS=1 rewrites its blocks after a change).
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <CLI/CLI.hpp>

#include "cli/help_formatter.hpp"
#include "cli/program.hpp"
#include "tests/cli/cli_runner.hpp"

namespace radarpr {
namespace {

using testing::run_cli;

#define EXPECT_CONTAINS(text, part) \
  EXPECT_NE(std::string(text).find(part), std::string::npos) << "missing: " << (part)

std::vector<const CLI::App*> verbs_of(const CLI::App& app) {
  return app.get_subcommands({});
}

// The text with every run of spaces and line breaks made one space: a note the help wrapped
// over two lines is still found.
std::string flowed(const std::string& text) {
  std::string out;
  for (const char c : text) {
    const bool space = c == ' ' || c == '\n';
    if (space && (out.empty() || out.back() == ' ')) continue;
    out += space ? ' ' : c;
  }
  return out;
}

TEST(Help, EveryOptionOfEveryVerbIsInItsHelp) {
  cli::Program program;
  const auto verbs = verbs_of(program.app());
  ASSERT_GE(verbs.size(), 8u);
  for (const CLI::App* verb : verbs) {
    const auto help = run_cli(verb->get_name() + " --help");
    ASSERT_EQ(help.exit_code, 0) << verb->get_name() << ": " << help.output;
    EXPECT_CONTAINS(help.output, "usage: radarpr " + verb->get_name());
    for (const CLI::Option* option : verb->get_options()) {
      SCOPED_TRACE(verb->get_name() + " " + option->get_name());
      for (const auto& name : option->get_lnames()) EXPECT_CONTAINS(help.output, "--" + name);
      for (const auto& name : option->get_snames()) EXPECT_CONTAINS(help.output, "-" + name);
      if (option->get_positional()) {
        EXPECT_CONTAINS(help.output, option->get_name());
      }
      if (!option->get_default_str().empty()) {
        EXPECT_CONTAINS(flowed(help.output), "default: " + option->get_default_str());
      }
      EXPECT_FALSE(option->get_description().empty());
    }
  }
}

// The program's help lists every verb with every argument and option (--plugin once, for all).
TEST(Help, TheProgramsHelpListsEveryVerbWithItsOptions) {
  cli::Program program;
  const auto help = run_cli("--help");
  ASSERT_EQ(help.exit_code, 0);
  for (const CLI::App* verb : verbs_of(program.app())) {
    EXPECT_CONTAINS(help.output, "radarpr " + verb->get_name() + " ");
    EXPECT_CONTAINS(help.output, verb->get_description().substr(0, 40));
    for (const CLI::Option* option : verb->get_options()) {
      if (option == verb->get_help_ptr()) continue;
      if (option->get_positional()) {
        EXPECT_CONTAINS(help.output, option->get_name());
      } else {
        EXPECT_CONTAINS(help.output, "--" + option->get_lnames().front());
      }
    }
  }
  for (const char* option : {"--plugin PATH", "--version", "-h, --help"}) {
    EXPECT_CONTAINS(help.output, option);
  }
  EXPECT_CONTAINS(help.output, "Exit codes: 0 done, 1 an error");
  EXPECT_EQ(run_cli("help").output, help.output);
  EXPECT_EQ(run_cli("help run").output, run_cli("run --help").output);
}

TEST(Help, RunsHelpNamesEveryTableTheReportWrites) {
  const auto help = run_cli("run --help");
  EXPECT_CONTAINS(help.output, "table1/table2/table3/table4.{md,csv,tex}");
  EXPECT_CONTAINS(run_cli("report --help").output, "table3.{md,csv,tex}");
  EXPECT_CONTAINS(run_cli("report --help").output, "table4.{md,csv,tex}");
}

TEST(Help, LinesFitTheWidth) {
  for (const std::string arguments : {"--help", "run --help", "inspect --help", "bench --help",
                                      "extract --help", "simulate --help"}) {
    std::istringstream lines(run_cli(arguments).output);
    std::string line;
    while (std::getline(lines, line)) {
      // µ is two bytes; the width is in characters.
      std::size_t characters = 0;
      for (const unsigned char c : line) characters += (c & 0xC0) != 0x80 ? 1 : 0;
      EXPECT_LE(characters, cli::kHelpWidth) << arguments << ": " << line;
    }
  }
}

// docs/cli.md's help blocks: a line "<!-- radarpr VERB --help -->", then a ```text block.
struct HelpBlock {
  std::string command;    // "radarpr run --help"
  std::size_t begin = 0;  // the block's text, in the file
  std::size_t end = 0;
};

std::vector<HelpBlock> help_blocks(const std::string& text) {
  std::vector<HelpBlock> blocks;
  const std::string marker = "\n<!-- ";
  std::size_t at = 0;
  while ((at = text.find(marker + "radarpr", at)) != std::string::npos) {
    const std::size_t close = text.find(" -->", at);
    const std::string command = text.substr(at + marker.size(), close - at - marker.size());
    const std::size_t fence = text.find("```text\n", close);
    const std::size_t begin = fence + 8;
    const std::size_t end = text.find("```\n", begin);
    if (close == std::string::npos || fence == std::string::npos || end == std::string::npos) {
      ADD_FAILURE() << "docs/cli.md: no ```text block after <!-- " << command << " -->";
      break;
    }
    blocks.push_back({command, begin, end});
    at = end;
  }
  return blocks;
}

TEST(Help, DocsCliShowsTheProgramsOwnHelp) {
  const std::filesystem::path path = std::filesystem::path(RADARPR_SOURCE_DIR) / "docs/cli.md";
  std::ifstream file(path);
  ASSERT_TRUE(file) << path;
  std::stringstream read;
  read << file.rdbuf();
  std::string text = read.str();

  cli::Program program;
  std::vector<std::string> expected = {"radarpr --help"};
  for (const CLI::App* verb : verbs_of(program.app())) {
    expected.push_back("radarpr " + verb->get_name() + " --help");
  }
  std::vector<std::string> documented;
  const bool update = std::getenv("RADARPR_UPDATE_CLI_DOCS") != nullptr;
  auto blocks = help_blocks(text);
  for (auto block = blocks.rbegin(); block != blocks.rend();
       ++block) {  // from the end: offsets hold
    documented.insert(documented.begin(), block->command);
    const std::string shown = text.substr(block->begin, block->end - block->begin);
    const auto actual = run_cli(block->command.substr(std::string("radarpr ").size()));
    ASSERT_EQ(actual.exit_code, 0) << block->command;
    if (update) {
      text.replace(block->begin, block->end - block->begin, actual.output);
    } else {
      EXPECT_EQ(shown, actual.output)
          << "docs/cli.md's block for `" << block->command << "` differs from the program's; "
          << "rerun this test with RADARPR_UPDATE_CLI_DOCS=1 to copy it";
    }
  }
  if (update) std::ofstream(path, std::ios::binary) << text;
  EXPECT_EQ(documented, expected) << "docs/cli.md needs one help block per verb, in this order";
}

}  // namespace
}  // namespace radarpr
