#include "benchmarks/machine_description.hpp"

#include <sys/utsname.h>

#include <chrono>
#include <ctime>
#include <fstream>
#include <thread>

#include <benchmark/benchmark.h>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "evaluation/version.hpp"

namespace radarpr::bench {
namespace {

// The value of the first "key : value" line of a /proc file whose key is `key`.
std::string proc_value(const char* file, const std::string& key) {
  std::ifstream in(file);
  std::string line;
  while (std::getline(in, line)) {
    const auto colon = line.find(':');
    if (colon == std::string::npos) continue;
    std::string name = line.substr(0, colon);
    while (!name.empty() && (name.back() == ' ' || name.back() == '\t')) name.pop_back();
    if (name != key) continue;
    std::string value = line.substr(colon + 1);
    const auto first = value.find_first_not_of(" \t");
    return first == std::string::npos ? std::string() : value.substr(first);
  }
  return {};
}

std::string operating_system() {
  utsname names{};
  if (uname(&names) != 0) return "unknown";
  std::string pretty;
  std::ifstream release("/etc/os-release");
  std::string line;
  while (std::getline(release, line)) {
    if (line.rfind("PRETTY_NAME=", 0) == 0) {
      pretty = line.substr(12);
      if (pretty.size() >= 2 && pretty.front() == '"') pretty = pretty.substr(1, pretty.size() - 2);
    }
  }
  return fmt::format("{}{}{} {} {}", pretty, pretty.empty() ? "" : ", ", names.sysname,
                     names.release, names.machine);
}

std::string compiler() {
#if defined(__clang__)
  return fmt::format("clang {}", __clang_version__);
#elif defined(__GNUC__)
  return fmt::format("GCC {}", __VERSION__);
#else
  return "unknown";
#endif
}

std::string utc_now() {
  const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  std::tm utc{};
  gmtime_r(&now, &utc);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &utc);
  return text;
}

}  // namespace

bool optimised_build() {
#if defined(NDEBUG) && defined(__OPTIMIZE__)
  return true;
#else
  return false;
#endif
}

MachineDescription describe_this_machine() {
  MachineDescription machine;
  machine.cpu_model = proc_value("/proc/cpuinfo", "model name");
  if (machine.cpu_model.empty()) machine.cpu_model = "unknown";
  machine.logical_cores = static_cast<int>(std::thread::hardware_concurrency());
  const std::string memory = proc_value("/proc/meminfo", "MemTotal");  // "24576000 kB"
  if (!memory.empty()) machine.memory_gib = std::stod(memory) / (1024.0 * 1024.0);
  machine.operating_system = operating_system();
  machine.compiler = compiler();
  machine.build_type = RADARPR_BUILD_TYPE;
  machine.optimised = optimised_build();
  machine.radarpr_version = std::string(radarpr_version());
  machine.date_utc = utc_now();
  machine.load_average = benchmark::CPUInfo::Get().load_avg;
  return machine;
}

nlohmann::json to_json(const MachineDescription& machine) {
  return {{"cpu_model", machine.cpu_model},   {"logical_cores", machine.logical_cores},
          {"memory_gib", machine.memory_gib}, {"operating_system", machine.operating_system},
          {"compiler", machine.compiler},     {"build_type", machine.build_type},
          {"optimised", machine.optimised},   {"radarpr_version", machine.radarpr_version},
          {"date_utc", machine.date_utc},     {"load_average", machine.load_average}};
}

}  // namespace radarpr::bench
