#include "benchmarks/startup_benchmarks.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>

#include <cerrno>
#include <cstring>
#include <string>
#include <utility>

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

// The minimal decoding program (png_decode_floor.cpp) installed with `program`: beside it in a
// build tree, in the package's libexec folder when installed. Empty when neither holds it.
std::filesystem::path floor_program(const std::filesystem::path& program) {
  const std::filesystem::path folder = program.parent_path();
  for (const std::filesystem::path& candidate :
       {folder / "radarpr_png_decode_floor", folder.parent_path() / RADARPR_INSTALL_LIBEXECDIR /
                                                 "radarpr" / "radarpr_png_decode_floor"}) {
    std::error_code unknown;
    if (std::filesystem::is_regular_file(candidate, unknown)) return candidate;
  }
  return {};
}

void add_process(BenchPlan& plan, BenchCase bench, std::vector<std::string> arguments) {
  plan.add(
      std::move(bench),
      [arguments = std::move(arguments)](benchmark::State& state) {
        time_process(state, arguments);
      },
      true, true);
}

// What any process costs here, beside what radarpr's costs: the minimal program started with
// nothing to do, and decoding the scan's PNG.
void add_floor_benchmarks(BenchPlan& plan, const BenchScan* scan,
                          const std::filesystem::path& program) {
  const std::filesystem::path floor = floor_program(program);
  BenchCase empty;
  empty.name = "startup/floor/empty";
  empty.kind = CaseKind::process_floor;
  BenchCase decode;
  if (scan != nullptr) {
    decode.name = "startup/floor/png_decode/" + scan->label;
    decode.kind = CaseKind::process_floor;
    decode.scan = scan->label;
  }
  if (floor.empty()) {
    const std::string reason = fmt::format(
        "radarpr_png_decode_floor is neither beside {} nor in the package's {}/radarpr folder",
        program.string(), RADARPR_INSTALL_LIBEXECDIR);
    if (plan.wanted(empty.name)) plan.skip(empty.name, reason);
    if (scan != nullptr && plan.wanted(decode.name)) plan.skip(decode.name, reason);
    return;
  }
  add_process(plan, std::move(empty), {floor.string()});
  if (scan != nullptr) add_process(plan, std::move(decode), {floor.string(), scan->png.string()});
}

}  // namespace

void add_startup_benchmarks(BenchPlan& plan, const std::vector<BenchScan>& scans,
                            const std::filesystem::path& program) {
  if (program.empty()) return;
  BenchCase version;
  version.name = "startup/version";
  version.kind = CaseKind::startup;
  add_process(plan, std::move(version), {program.string(), "--version"});
  add_floor_benchmarks(plan, scans.empty() ? nullptr : &scans.front(), program);
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
  add_process(plan, std::move(extract), std::move(arguments));
}

}  // namespace radarpr::bench
