// Temporary folder trees laid out like the real datasets, filled at test time with copies of the
// real samples in ../shared/data/real (never copied into the project).
#pragma once

#include <atomic>
#include <cstdint>
#include <exception>
#include <filesystem>
#include <fstream>
#include <functional>
#include <initializer_list>
#include <string>

#include <unistd.h>

#include <gtest/gtest.h>

namespace radarpr::test {

namespace fs = std::filesystem;

inline fs::path real_data(const std::string& relative) {
  return fs::path(RADARPR_SOURCE_DIR) / "../shared/data/real" / relative;
}

// Skips the calling test when a real sample is absent.
#define RADARPR_SKIP_WITHOUT(location, what)                                             \
  do {                                                                                   \
    if (!std::filesystem::exists(location)) {                                            \
      GTEST_SKIP() << (what) << " absent: " << std::filesystem::path(location).string(); \
    }                                                                                    \
  } while (false)

// A fresh folder per instance, removed with everything in it.
class TempTree {
 public:
  TempTree() {
    static std::atomic<int> counter{0};
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    root_ = fs::temp_directory_path() /
            (std::string("radarpr_tree_") + (info ? info->name() : "none") + "_" +
             std::to_string(::getpid()) + "_" + std::to_string(counter++));
    fs::remove_all(root_);
    fs::create_directories(root_);
  }
  ~TempTree() {
    std::error_code ignored;
    fs::remove_all(root_, ignored);
  }
  TempTree(const TempTree&) = delete;
  TempTree& operator=(const TempTree&) = delete;

  const fs::path& root() const { return root_; }
  fs::path path(const std::string& relative) const { return root_ / relative; }

  // Copies `from` to root/relative, creating the folders on the way.
  fs::path copy(const fs::path& from, const std::string& relative) const {
    const fs::path to = path(relative);
    fs::create_directories(to.parent_path());
    fs::copy_file(from, to, fs::copy_options::overwrite_existing);
    return to;
  }
  fs::path write(const std::string& relative, const std::string& text) const {
    const fs::path to = path(relative);
    fs::create_directories(to.parent_path());
    std::ofstream(to, std::ios::binary) << text;
    return to;
  }
  fs::path folder(const std::string& relative) const {
    fs::create_directories(path(relative));
    return path(relative);
  }

 private:
  fs::path root_;
};

// Expects `action` to throw an `Exception` whose message contains every fragment.
template <typename Exception = std::exception>
void expect_error(const std::function<void()>& action,
                  std::initializer_list<std::string> fragments) {
  try {
    action();
    ADD_FAILURE() << "no exception; expected one mentioning " << *fragments.begin();
  } catch (const Exception& error) {
    const std::string message = error.what();
    for (const std::string& fragment : fragments) {
      EXPECT_NE(message.find(fragment), std::string::npos)
          << "'" << fragment << "' not in: " << message;
    }
  }
}

}  // namespace radarpr::test
