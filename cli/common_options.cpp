#include "cli/common_options.hpp"

#include <algorithm>
#include <memory>

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <CLI/CLI.hpp>

#include "cli/number_options.hpp"
#include "cli/suggestion.hpp"
#include "evaluation/parallel.hpp"
#include "evaluation/report/report.hpp"

namespace radarpr::cli {

CLI::Option* add_config_argument(CLI::App& verb, std::string& path) {
  return verb.add_option("CONFIG", path, "the experiment, a JSON file (see configs/)")
      ->type_name("CONFIG");
}

CLI::Option* add_set_option(CLI::App& verb, std::vector<std::string>& overrides) {
  return verb
      .add_option("--set", overrides,
                  "change a config value before validation, e.g. --set "
                  "protocol.revisit_radius_m=5 --set datasets.0.query.scans=200 --set "
                  "descriptors.1.params.z_q=3; the value is read as JSON when it is JSON, else "
                  "taken as a string. A key or value the config refuses is blamed on this --set")
      ->type_name("KEY.PATH=VALUE")
      ->allow_extra_args(false);
}

CLI::Option* add_threads_option(CLI::App& verb, std::optional<long long>& threads,
                                const std::string& work) {
  CLI::Option* option = add_whole_number_option(
      verb, "--threads", threads, {0, kMaxThreads}, "N",
      work +
          "; 0: one per processor this process may run on (its CPU affinity), fewer when "
          "$SLURM_CPUS_PER_TASK is smaller");
  option->default_str("0");
  // Every parallel loop of the process follows it, not only those the verb hands it to.
  option->each([](const std::string& text) {
    set_default_thread_count(static_cast<int>(*parse_whole_number(text)));
  });
  return option;
}

CLI::Option* add_choice_option(CLI::App& verb, const std::string& name, std::string& target,
                               const std::vector<std::string>& choices, const std::string& help) {
  auto check = [choices](std::string& text) -> std::string {
    if (std::find(choices.begin(), choices.end(), text) != choices.end()) return "";
    std::string problem = fmt::format("'{}' is not one of {}", text, fmt::join(choices, ", "));
    if (const auto meant = closest_match(text, choices)) {
      problem += fmt::format("; did you mean '{}'?", *meant);
    }
    return problem;
  };
  return verb.add_option(name, target, help)
      ->check(CLI::Validator(check, "", "choice"))
      ->type_name(fmt::format("{}", fmt::join(choices, "|")))
      ->capture_default_str();
}

CLI::Option* add_style_option(CLI::App& verb, std::string& style) {
  return add_choice_option(verb, "--style", style, {"screen", "paper"},
                           "the figures' style: screen (large, titled, for the page) or paper "
                           "(one 3.5 in IEEE column, 8 pt, key inside, no title; for a paper's "
                           "PDF figures)")
      ->default_str("the config's report.style, else screen");
}

CLI::Option* add_plugin_option(CLI::App& app, std::vector<std::string>& paths) {
  return app
      .add_option("--plugin", paths,
                  "load a descriptor plugin, a shared library built against this radarpr, before "
                  "the verb runs")
      ->type_name("PATH")
      ->allow_extra_args(false);
}

void print_report_warnings(const ReportOutcome& outcome) {
  for (const auto& warning : outcome.warnings) {
    fmt::print(stderr, "radarpr: warning: {}\n", warning);
  }
}

}  // namespace radarpr::cli
