#pragma once

// Arguments and options several verbs share, defined once so that they read, check and explain
// themselves the same way on every verb.
#include <optional>
#include <string>
#include <vector>

namespace CLI {
class App;
class Option;
}  // namespace CLI

namespace radarpr {
struct ReportOutcome;
}

namespace radarpr::cli {

// CONFIG: the experiment, a JSON file (see configs/).
CLI::Option* add_config_argument(CLI::App& verb, std::string& path);

// --set KEY.PATH=VALUE (repeatable): a config value changed before validation.
CLI::Option* add_set_option(CLI::App& verb, std::vector<std::string>& overrides);

// --threads N on a verb that computes: N threads for all its parallel work, instead of the
// processors this process may use (default_thread_count()). Takes effect when parsed; `threads`
// keeps the value for a verb that also hands it on (run: the config's "threads"). `work` names
// what runs in parallel when a verb has one specific thing (merge: the figures).
CLI::Option* add_threads_option(CLI::App& verb, std::optional<long long>& threads,
                                const std::string& work = "threads for the parallel work");

// `--name A|B|C`: one of `choices`; anything else is refused naming the choices (and the one
// meant, for a typo).
CLI::Option* add_choice_option(CLI::App& verb, const std::string& name, std::string& target,
                               const std::vector<std::string>& choices, const std::string& help);

// --style screen|paper on a verb that draws the report: `style` stays empty when not given (the
// run's config decides, else screen).
CLI::Option* add_style_option(CLI::App& verb, std::string& style);

// --plugin PATH (repeatable): a descriptor plugin to load before the verb runs. The program adds
// it to itself and to every verb.
CLI::Option* add_plugin_option(CLI::App& app, std::vector<std::string>& paths);

// "radarpr: warning: ..." on stderr for each of the report's warnings (run, report, compare).
void print_report_warnings(const ReportOutcome& outcome);

}  // namespace radarpr::cli
