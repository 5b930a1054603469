#include "benchmarks/machine_description.hpp"

#include <fstream>
#include <thread>

#include <benchmark/benchmark.h>
#include <nlohmann/json.hpp>

#include "evaluation/machine_summary.hpp"
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
  machine.cpu_model = cpu_model();
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
