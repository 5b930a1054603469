#pragma once

#include <stdexcept>
#include <string>
#include <vector>

namespace radarpr {
struct ReportOutcome;
}

namespace radarpr::cli {

// Thrown for a malformed command line: main prints it with a pointer to --help, exit code 2.
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Loads the descriptor plugins named by $RADARPR_PLUGINS (colon-separated paths) and by every
// "--plugin PATH" / "--plugin=PATH" in `args`, and returns `args` without those options. Every
// command accepts them, so plugin descriptors work in run, list, extract, inspect and bench.
std::vector<std::string> load_plugins_and_strip_options(const std::vector<std::string>& args);

// Each command takes the arguments after its verb and returns the process exit code.
int run_command(const std::vector<std::string>& args);
int list_command(const std::vector<std::string>& args);
int extract_command(const std::vector<std::string>& args);
int inspect_command(const std::vector<std::string>& args);
int simulate_command(const std::vector<std::string>& args);
int bench_command(const std::vector<std::string>& args);  // built with RADARPR_BUILD_BENCHMARKS
int report_command(const std::vector<std::string>& args);
int compare_command(const std::vector<std::string>& args);

// "radarpr: warning: ..." on stderr for each of the report's warnings (run, report, compare).
void print_report_warnings(const ReportOutcome& outcome);

extern const char* const kRunHelp;
extern const char* const kListHelp;
extern const char* const kExtractHelp;
extern const char* const kInspectHelp;
extern const char* const kSimulateHelp;
extern const char* const kBenchHelp;
extern const char* const kReportHelp;
extern const char* const kCompareHelp;

}  // namespace radarpr::cli
