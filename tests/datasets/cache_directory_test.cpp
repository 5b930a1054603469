#include "datasets/cache_directory.hpp"

#include <cstdlib>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

namespace radarpr {
namespace {

// Sets environment variables for one test and restores them afterwards.
class ScopedEnvironment {
 public:
  void set(const char* name, const char* value) {
    const char* old = std::getenv(name);
    saved_.push_back({name, old ? std::optional<std::string>(old) : std::nullopt});
    if (value) {
      ::setenv(name, value, 1);
    } else {
      ::unsetenv(name);
    }
  }
  ~ScopedEnvironment() {
    for (auto it = saved_.rbegin(); it != saved_.rend(); ++it) {
      if (it->second) {
        ::setenv(it->first.c_str(), it->second->c_str(), 1);
      } else {
        ::unsetenv(it->first.c_str());
      }
    }
    override_cache_directory(std::nullopt);
  }

 private:
  std::vector<std::pair<std::string, std::optional<std::string>>> saved_;
};

TEST(CacheDirectory, FollowsTheVariablesInOrderOfPrecedence) {
  ScopedEnvironment env;
  env.set("RADARPR_CACHE_DIR", nullptr);
  env.set("XDG_CACHE_HOME", nullptr);
  env.set("HOME", "/home/someone");
  EXPECT_EQ(cache_directory(), std::filesystem::path("/home/someone/.cache/radarpr"));
  env.set("XDG_CACHE_HOME", "/xdg");
  EXPECT_EQ(cache_directory(), std::filesystem::path("/xdg/radarpr"));
  env.set("RADARPR_CACHE_DIR", "/fast/disk");
  EXPECT_EQ(cache_directory(), std::filesystem::path("/fast/disk"));
  override_cache_directory("/from/the/command/line");
  EXPECT_EQ(cache_directory(), std::filesystem::path("/from/the/command/line"));
}

TEST(CacheDirectory, OffDisablesCachingFromTheVariableOrTheOverride) {
  ScopedEnvironment env;
  env.set("RADARPR_CACHE_DIR", "off");
  EXPECT_EQ(cache_directory(), std::nullopt);
  override_cache_directory("/somewhere");
  EXPECT_EQ(cache_directory(), std::filesystem::path("/somewhere"));
  override_cache_directory("off");
  env.set("RADARPR_CACHE_DIR", "/fast/disk");
  EXPECT_EQ(cache_directory(), std::nullopt);
}

}  // namespace
}  // namespace radarpr
