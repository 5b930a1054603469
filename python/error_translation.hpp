#pragma once

#include <stdexcept>
#include <string>
#include <utility>

#include <pybind11/pybind11.h>

#include "evaluation/config/config_error.hpp"

namespace radarpr::python {

namespace py = pybind11;

// A file that cannot be read or written: becomes OSError carrying radarpr's one-line message.
class FileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Runs `body`, turning a std::runtime_error it throws (a file that is missing, unreadable or
// malformed) into a FileError with the same message. ConfigError and invalid_argument pass
// through unchanged.
template <typename Body>
decltype(auto) reading_files(Body&& body) {
  try {
    return std::forward<Body>(body)();
  } catch (const ConfigError&) {
    throw;
  } catch (const FileError&) {
    throw;
  } catch (const std::runtime_error& error) {
    throw FileError(error.what());
  }
}

}  // namespace radarpr::python
