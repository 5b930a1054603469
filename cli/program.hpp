#pragma once

#include <memory>
#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace radarpr::cli {

// The radarpr program: every verb of cli/verbs.cpp on one CLI11 app (each with --plugin and
// --help; a verb's options are defined when the command line names it), the command line parsed,
// the plugins loaded, the verb run, and each outcome mapped to an exit code: 0 done, 1 error
// ("radarpr: error: ..."), 2 a command line it cannot use ("radarpr VERB: ... (see radarpr VERB
// --help)", with a guess for a mistyped verb, option or choice).
class Program {
 public:
  Program();
  ~Program();
  Program(const Program&) = delete;
  Program& operator=(const Program&) = delete;

  // Runs `radarpr arguments...` (without the program's name); returns the exit code. Once.
  int run(const std::vector<std::string>& arguments);

  // The definitions of every verb (for tests that compare the help and docs/cli.md with them).
  const CLI::App& app();

 private:
  struct VerbSlot;
  void define_verb(VerbSlot& verb);
  void define_all_verbs();
  // `radarpr --help`: every verb with its arguments and options.
  std::string program_help();
  int run_verb(VerbSlot& verb);
  int usage_error(const std::string& message) const;
  std::vector<std::string> verb_names() const;
  // What CLI11 could not place, as a message with a guess ("unknown option '--ot'; did you mean
  // '--out'?"); empty when nothing was left over.
  std::string unexpected_word() const;

  std::unique_ptr<CLI::App> app_;
  std::vector<std::string> plugins_;  // the program's --plugin, before the verb's
  std::vector<std::unique_ptr<VerbSlot>> verbs_;
};

}  // namespace radarpr::cli
