#pragma once

#include <cstddef>
#include <cstdint>
#include <exception>
#include <filesystem>
#include <string>
#include <string_view>

// What every fuzz target shares. A target defines LLVMFuzzerTestOneInput: libFuzzer drives it
// (RADARPR_FUZZ=ON), or corpus_runner.cpp runs it once per file of a corpus (any compiler).
//
// The property each target checks is the project's rule for bad input: any bytes give either a
// result or a std::exception whose message names the input (the file, or the config source), so
// the user knows what to fix. A crash, a sanitizer report, a hang, an allocation beyond
// libFuzzer's limit, another exception type or an anonymous message is a finding.
extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

namespace radarpr::fuzz {

// The fuzz input as text (any bytes, NUL included).
inline std::string_view as_text(const std::uint8_t* data, std::size_t size) {
  return {reinterpret_cast<const char*>(data), size};
}

// A folder of this process's own under the temporary directory, emptied at each call and removed
// when the process ends normally; targets whose code under test reads files write the input here.
const std::filesystem::path& scratch_folder();

// Writes `bytes` to `relative` inside scratch_folder() (folders created) and returns the path.
std::filesystem::path write_scratch_file(const std::filesystem::path& relative,
                                         std::string_view bytes);

// Aborts (a finding) unless `error`'s message mentions `source`: an error that does not say which
// file or config it is about breaks the project's rule for bad input.
void require_names(const std::exception& error, const std::string& source);

}  // namespace radarpr::fuzz
