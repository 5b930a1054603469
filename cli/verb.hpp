#pragma once

// One verb of the radarpr program (`radarpr VERB ...`). A verb is one file, cli/VERB_command.cpp,
// defining `Verb VERB_verb()`, and one line in cli/verbs.cpp; docs/cli.md shows an example.
#include <functional>
#include <stdexcept>
#include <string>

namespace CLI {
class App;
}

namespace radarpr::cli {

// A command line that CLI11 accepted but the verb cannot use (two ways of naming a dataset, a
// key=value without '='): the program prints it with a pointer to the verb's --help, exit code 2.
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// What a verb does once its command line is parsed and the plugins are loaded. Returns the exit
// code: 0 done, 1 failed. A std::exception thrown out of it is printed as "radarpr: error: ..."
// with exit code 1, a UsageError with exit code 2.
using VerbAction = std::function<int()>;

struct Verb {
  std::string name;
  // The first line is the summary `radarpr --help` lists; the whole text opens `radarpr VERB
  // --help`, printed as written (wrap it at 100 columns).
  std::string description;
  // Adds the verb's arguments and options to its CLI11 subcommand (named and described already;
  // the program adds --plugin and --help) and returns its action, which reads what they parsed.
  std::function<VerbAction(CLI::App& verb)> define;
};

}  // namespace radarpr::cli
