#include "benchmarks/startup_benchmarks.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>

#include <cerrno>
#include <cstring>
#include <string>

#include <fmt/format.h>

extern char** environ;

namespace radarpr::bench {
namespace {

// posix_spawn's file actions, released however the spawn ends.
class SilentOutput {
 public:
  SilentOutput() {
    ::posix_spawn_file_actions_init(&actions_);
    ::posix_spawn_file_actions_addopen(&actions_, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
    ::posix_spawn_file_actions_addopen(&actions_, STDERR_FILENO, "/dev/null", O_WRONLY, 0);
  }
  ~SilentOutput() { ::posix_spawn_file_actions_destroy(&actions_); }
  SilentOutput(const SilentOutput&) = delete;
  SilentOutput& operator=(const SilentOutput&) = delete;
  const posix_spawn_file_actions_t* get() const { return &actions_; }

 private:
  posix_spawn_file_actions_t actions_;
};

double seconds_of(const timeval& time) {
  return static_cast<double>(time.tv_sec) + 1e-6 * static_cast<double>(time.tv_usec);
}

// What one run of a process cost, or why it failed.
struct ProcessRun {
  double cpu_seconds = 0.0;
  std::string error;  // empty when the process ran and exited with 0
};

// Runs `arguments` (arguments[0] the program) to its end with its output discarded: the CPU
// seconds it used, or an error text naming what failed.
ProcessRun run_process(const std::vector<std::string>& arguments) {
  std::vector<char*> argv;
  for (const std::string& argument : arguments) argv.push_back(const_cast<char*>(argument.c_str()));
  argv.push_back(nullptr);
  const SilentOutput output;
  pid_t child = 0;
  if (const int failed =
          ::posix_spawn(&child, argv[0], output.get(), nullptr, argv.data(), environ)) {
    return {0.0, fmt::format("cannot start {}: {}", arguments[0], std::strerror(failed))};
  }
  int status = 0;
  rusage usage{};
  while (::wait4(child, &status, 0, &usage) < 0) {
    if (errno != EINTR) return {0.0, fmt::format("cannot wait for {}", arguments[0])};
  }
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    std::string command;
    for (const std::string& argument : arguments)
      command += (command.empty() ? "" : " ") + argument;
    return {0.0, fmt::format("`{}` failed (wait status {})", command, status)};
  }
  return {seconds_of(usage.ru_utime) + seconds_of(usage.ru_stime), ""};
}

void time_process(benchmark::State& state, const std::vector<std::string>& arguments) {
  double cpu_seconds = 0.0;
  for (auto _ : state) {
    const ProcessRun run = run_process(arguments);
    if (!run.error.empty()) {
      state.SkipWithError(run.error.c_str());
      break;
    }
    cpu_seconds += run.cpu_seconds;
  }
  if (state.iterations() > 0) {
    state.counters["process_cpu_seconds"] = cpu_seconds / static_cast<double>(state.iterations());
  }
}

}  // namespace

void add_startup_benchmarks(BenchPlan& plan, const std::vector<BenchScan>& scans,
                            const std::filesystem::path& program) {
  if (program.empty()) return;
  BenchCase version;
  version.name = "startup/version";
  version.kind = CaseKind::startup;
  plan.add(
      version,
      [arguments = std::vector<std::string>{program.string(), "--version"}](
          benchmark::State& state) { time_process(state, arguments); },
      true, true);
  if (scans.empty()) return;
  // The first scan (MulRan's 400 x 3360), with the decoding options the benchmarks use.
  const BenchScan& scan = scans.front();
  BenchCase extract;
  extract.name = "startup/extract/referee/" + scan.label;
  extract.kind = CaseKind::startup;
  extract.scan = scan.label;
  extract.descriptor = "referee";
  std::vector<std::string> arguments{program.string(),
                                     "extract",
                                     "referee",
                                     scan.png.string(),
                                     "--range-resolution",
                                     fmt::format("{}", scan.options.range_resolution_m),
                                     "--threads",
                                     "1"};
  plan.add(
      extract,
      [arguments = std::move(arguments)](benchmark::State& state) {
        time_process(state, arguments);
      },
      true, true);
}

}  // namespace radarpr::bench
