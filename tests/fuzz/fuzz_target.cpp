#include "tests/fuzz/fuzz_target.hpp"

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <system_error>

#include <unistd.h>

namespace radarpr::fuzz {
namespace fs = std::filesystem;

namespace {

// Owns the scratch folder; removes it at a normal exit (a crash leaves it for inspection).
struct ScratchFolder {
  fs::path path;
  ScratchFolder() {
    std::string pattern = (fs::temp_directory_path() / "radarpr-fuzz-XXXXXX").string();
    if (::mkdtemp(pattern.data()) == nullptr) {
      std::perror("radarpr fuzz: cannot create a scratch folder");
      std::abort();
    }
    path = pattern;
  }
  ~ScratchFolder() {
    std::error_code ignored;
    fs::remove_all(path, ignored);
  }
};

}  // namespace

const fs::path& scratch_folder() {
  static const ScratchFolder folder;
  return folder.path;
}

fs::path write_scratch_file(const fs::path& relative, std::string_view bytes) {
  const fs::path path = scratch_folder() / relative;
  fs::create_directories(path.parent_path());
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  out.close();
  if (!out) {
    std::fprintf(stderr, "radarpr fuzz: cannot write %s\n", path.c_str());
    std::abort();
  }
  return path;
}

void require_names(const std::exception& error, const std::string& source) {
  const std::string message = error.what();
  if (message.find(source) == std::string::npos) {
    std::fprintf(stderr, "radarpr fuzz: an error that does not name %s: %s\n", source.c_str(),
                 message.c_str());
    std::abort();
  }
}

}  // namespace radarpr::fuzz
