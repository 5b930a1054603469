#pragma once

#include <vector>

#include "cli/verb.hpp"

namespace radarpr::cli {

// Every verb, in the order `radarpr --help` lists them (cli/verbs.cpp).
std::vector<Verb> all_verbs();

}  // namespace radarpr::cli
