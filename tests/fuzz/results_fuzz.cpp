// Fuzz target: the results-folder reader that `radarpr report` and `radarpr compare` use, on a
// folder someone else wrote. Input: a packed folder, summary.json's text first, then each further
// file as a line "==> relative/path" followed by its bytes (pack_results_folder.sh makes one from
// a real results folder). Paths that would leave the folder, or that clash with a file or folder
// of the input written before them, are skipped.
#include <filesystem>
#include <iterator>
#include <stdexcept>
#include <string>

#include "evaluation/results/results_reader.hpp"
#include "tests/fuzz/fuzz_target.hpp"

namespace {

namespace fs = std::filesystem;

// A relative path of plain names: no "..", no absolute path, no empty or odd characters.
bool safe_relative_path(std::string_view path) {
  if (path.empty() || path.size() > 200 || path.front() == '/') return false;
  for (const char c : path) {
    const bool plain = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                       c == '_' || c == '-' || c == '.' || c == '/' || c == ':' || c == '=' ||
                       c == ',';
    if (!plain) return false;
  }
  // A file name at the end: "town/" or "town/." names a folder, which cannot be written as a
  // file (the harness used to abort on such a name, a finding of its own, not of the reader).
  const fs::path normal = fs::path(path).lexically_normal();
  if (!normal.has_filename() || normal.filename() == "." || path.back() == '/') return false;
  return normal.string().find("..") == std::string::npos;
}

// Whether `relative` can be written as a file under `root`: no folder already takes its name and
// no file already takes the name of one of its folders (a packed input may name "town" and then
// "town/referee/curve.csv", or the other way round; the later one is skipped).
bool fits(const fs::path& root, const fs::path& relative) {
  fs::path at = root;
  for (auto part = relative.begin(); part != relative.end(); ++part) {
    at /= *part;
    const bool last = std::next(part) == relative.end();
    if (last ? fs::is_directory(at) : fs::exists(at) && !fs::is_directory(at)) return false;
  }
  return true;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace radarpr;
  const fs::path folder = fuzz::scratch_folder() / "results";
  std::error_code ignored;
  fs::remove_all(folder, ignored);
  fs::create_directories(folder);

  constexpr std::string_view kMarker = "\n==> ";
  std::string_view text = fuzz::as_text(data, size);
  std::string name = "summary.json";
  while (true) {
    const auto next = text.find(kMarker);
    const std::string_view bytes = text.substr(0, next);
    if (safe_relative_path(name) && fits(folder, name)) {
      fuzz::write_scratch_file(fs::path("results") / name, bytes);
    }
    if (next == std::string_view::npos) break;
    text.remove_prefix(next + kMarker.size());
    const auto end_of_name = text.find('\n');
    name = std::string(text.substr(0, end_of_name));
    text =
        end_of_name == std::string_view::npos ? std::string_view() : text.substr(end_of_name + 1);
  }

  try {
    static_cast<void>(read_run_results(folder));
  } catch (const std::exception& error) {
    fuzz::require_names(error, folder.string());
  }
  return 0;
}
