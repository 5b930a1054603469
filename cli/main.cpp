// The radarpr command line: one verb per job (run, report, compare, inspect, list, extract,
// simulate, bench); cli/program.cpp parses, cli/verbs.cpp lists the verbs.
#include <string>
#include <vector>

#include "cli/program.hpp"

int main(int argc, char** argv) {
  radarpr::cli::Program program;
  return program.run({argv + 1, argv + argc});
}
