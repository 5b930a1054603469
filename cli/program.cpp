#include "cli/program.hpp"

#include <algorithm>
#include <cstdlib>
#include <exception>
#include <functional>

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include "cli/common_options.hpp"
#include "cli/help_formatter.hpp"
#include "cli/suggestion.hpp"
#include "cli/verbs.hpp"
#include "descriptors/plugins/plugin_loader.hpp"
#include "evaluation/config/config_overrides.hpp"
#include "evaluation/text_escaping.hpp"
#include "evaluation/version.hpp"

namespace radarpr::cli {

struct Program::VerbSlot {
  CLI::App* app = nullptr;                      // named and described from the start
  std::function<VerbAction(CLI::App&)> define;  // adds its options, once: see define_verb()
  bool defined = false;
  VerbAction action;
  std::vector<std::string> plugins;
};

namespace {

constexpr const char* kFooter =
    R"(A descriptor plugin is a shared library built against this radarpr (docs/plugins.md); the
paths in $RADARPR_PLUGINS (colon-separated) are loaded first, then every --plugin, before the verb
runs; a config may list its own under "plugins". Help and --version load none.

Exit codes: 0 done, 1 an error (printed as "radarpr: error: ..."), 2 a command line radarpr
cannot use (printed with a pointer to the verb's --help). docs/cli.md describes every verb.
`radarpr VERB --help` explains a verb.)";

// Every name the app's options answer to, for "did you mean".
std::vector<std::string> option_names(const CLI::App& app) {
  std::vector<std::string> names;
  for (const CLI::Option* option : app.get_options()) {
    for (const auto& name : option->get_lnames()) names.push_back("--" + name);
    for (const auto& name : option->get_snames()) names.push_back("-" + name);
  }
  return names;
}

std::string with_guess(std::string message, const std::string& word,
                       const std::vector<std::string>& candidates) {
  if (const auto meant = closest_match(word, candidates)) {
    message += fmt::format("; did you mean '{}'?", *meant);
  }
  return message;
}

void load_plugins(const std::vector<std::string>& program_paths,
                  const std::vector<std::string>& verb_paths) {
  // The environment's plugins first, then the command line's, each in the order given.
  if (const char* listed = std::getenv("RADARPR_PLUGINS"); listed != nullptr) {
    for (const auto& path : split_plugin_list(listed)) load_descriptor_plugin(path);
  }
  for (const std::string& path : program_paths) load_descriptor_plugin(path);
  for (const std::string& path : verb_paths) load_descriptor_plugin(path);
}

}  // namespace

Program::Program()
    : app_(std::make_unique<CLI::App>("radarpr - benchmark radar place-recognition descriptors",
                                      "radarpr")) {
  app_->formatter(make_help_formatter());
  app_->set_help_flag("-h,--help", "print this help and exit");
  app_->require_subcommand(0, 1);
  add_plugin_option(*app_, plugins_);
  app_->set_version_flag("--version", fmt::format("radarpr {}", radarpr_version()),
                         "print the version and exit");
  for (Verb& verb : all_verbs()) {
    auto slot = std::make_unique<VerbSlot>();
    slot->app = app_->add_subcommand(verb.name, verb.description);
    slot->define = std::move(verb.define);
    verbs_.push_back(std::move(slot));
  }
  app_->footer(kFooter);  // after the verbs: they would inherit it
}

// A verb's options are added only when the command line names the verb (or a help lists them):
// defining all of them takes about 90 us of CPU and faults in the code of every verb, which every
// process paid before, `radarpr --version` and `radarpr extract` alike. The subcommand itself
// exists from the start (its name and description), and a verb's definition is the same whenever
// it happens: its options, then --plugin.
void Program::define_verb(VerbSlot& verb) {
  if (verb.defined) return;
  verb.defined = true;
  verb.action = verb.define(*verb.app);
  add_plugin_option(*verb.app, verb.plugins);
}

void Program::define_all_verbs() {
  for (auto& slot : verbs_) define_verb(*slot);
}

std::string Program::program_help() {
  define_all_verbs();  // it lists every verb's arguments and options
  return app_->help();
}

const CLI::App& Program::app() {
  define_all_verbs();
  return *app_;
}

Program::~Program() = default;

int Program::usage_error(const std::string& message) const {
  const auto parsed = app_->get_subcommands();
  const std::string where = parsed.empty() ? "radarpr" : "radarpr " + parsed.front()->get_name();
  fmt::print(stderr, "{}: {} (see {} --help)\n", where, message, where);
  return 2;
}

std::vector<std::string> Program::verb_names() const {
  std::vector<std::string> names;
  for (const auto& slot : verbs_) names.push_back(slot->app->get_name());
  return names;
}

std::string Program::unexpected_word() const {
  const auto parsed = app_->get_subcommands();
  const CLI::App& where = parsed.empty() ? *app_ : *parsed.front();
  const std::vector<std::string> extras = where.remaining();
  if (extras.empty()) return "";
  const std::string& word = extras.front();
  if (word.starts_with("-")) {
    const std::string name = word.substr(0, word.find('='));
    return with_guess(fmt::format("unknown option '{}'", name), name, option_names(where));
  }
  if (parsed.empty()) {
    return with_guess(fmt::format("unknown verb '{}'", word), word, verb_names());
  }
  return fmt::format("unexpected argument '{}'", word);
}

int Program::run(const std::vector<std::string>& arguments) {
  if (arguments.empty()) {
    fmt::print("{}", program_help());
    return 2;
  }
  if (arguments.front() == "help") {  // `radarpr help [VERB]`
    if (arguments.size() == 1) {
      fmt::print("{}", program_help());
      return 0;
    }
    for (const auto& slot : verbs_) {
      if (slot->app->get_name() == arguments[1]) {
        define_verb(*slot);
        fmt::print("{}", slot->app->help(app_->get_name()));
        return 0;
      }
    }
    return usage_error(
        with_guess(fmt::format("unknown verb '{}'", arguments[1]), arguments[1], verb_names()));
  }

  // Every verb the command line names, whether as the verb or as an argument's value (`radarpr
  // run list`): CLI11 takes the first word that is a verb's name as the verb, so defining each
  // named one is enough, and a word CLI11 takes as a value costs only that verb's definition.
  for (auto& slot : verbs_) {
    if (std::find(arguments.begin(), arguments.end(), slot->app->get_name()) != arguments.end()) {
      define_verb(*slot);
    }
  }
  try {
    std::vector<std::string> reversed(arguments.rbegin(), arguments.rend());
    app_->parse(reversed);
  } catch (const CLI::CallForHelp&) {
    // The verb's, when one was named.
    fmt::print("{}", app_->get_subcommands().empty() ? program_help() : app_->help());
    return 0;
  } catch (const CLI::CallForVersion& version) {
    fmt::print("{}\n", version.what());
    return 0;
  } catch (const CLI::ExtrasError&) {
    return usage_error(unexpected_word());
  } catch (const CLI::RequiredError& error) {
    // `run --bogus` misses CONFIG too, but the unknown option is the mistake to show.
    const std::string unexpected = unexpected_word();
    return usage_error(unexpected.empty() ? std::string(error.what()) : unexpected);
  } catch (const CLI::ParseError& error) {
    return usage_error(error.what());
  }

  const auto parsed = app_->get_subcommands();
  if (parsed.empty()) {  // only --plugin: nothing to do
    fmt::print("{}", program_help());
    return 2;
  }
  for (auto& slot : verbs_) {
    if (slot->app == parsed.front()) return run_verb(*slot);
  }
  return 1;  // unreachable: every subcommand is a verb
}

int Program::run_verb(VerbSlot& verb) {
  try {
    load_plugins(plugins_, verb.plugins);
    return verb.action();
  } catch (const UsageError& error) {
    return usage_error(error.what());
  } catch (const OverrideError& error) {
    return usage_error(error.what());
  } catch (const std::exception& error) {
    // Printable: a file name that is not UTF-8, or holds escape sequences, is shown as \xNN.
    fmt::print(stderr, "radarpr: error: {}\n", printable(error.what(), /*keep_newlines=*/true));
    return 1;
  }
}

}  // namespace radarpr::cli
