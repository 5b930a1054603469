#pragma once

#include <stdexcept>

namespace radarpr {

// A results folder that cannot be reported on: the message is "<path>: <what was expected>", so
// the CLI prints "radarpr: error: <path>: ..." and the user knows which file to fix.
class ResultsError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace radarpr
