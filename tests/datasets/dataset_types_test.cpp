// The dataset types' table: one row per type, each parsing its own keys through DatasetKeys.
// (The experiment config's reader, which implements DatasetKeys over JSON, is tested with every
// type's keys in tests/evaluation/config/dataset_config_test.cpp.)
#include "datasets/dataset_types.hpp"

#include <map>
#include <set>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

namespace radarpr {
namespace {

// Keys from a map of strings, numbers given as text; errors are std::invalid_argument.
class MapKeys : public DatasetKeys {
 public:
  explicit MapKeys(std::map<std::string, std::string> values) : values_(std::move(values)) {}
  const std::string& path() const override { return path_; }
  bool has(const std::string& key) const override { return values_.contains(key); }
  bool is_set(const std::string& key) override { return find(key) != nullptr; }
  std::string required_string(const std::string& key) override {
    if (const auto* value = find(key)) return *value;
    fail(key, "missing");
  }
  std::string string_or(const std::string& key, const std::string& fallback) override {
    const auto* value = find(key);
    return value ? *value : fallback;
  }
  std::string required_path(const std::string& key) override { return required_string(key); }
  double number_or(const std::string& key, double fallback) override {
    const auto* value = find(key);
    return value ? std::stod(*value) : fallback;
  }
  std::int64_t integer_or(const std::string& key, std::int64_t fallback) override {
    const auto* value = find(key);
    return value ? std::stoll(*value) : fallback;
  }
  bool boolean_or(const std::string& key, bool fallback) override {
    const auto* value = find(key);
    return value ? *value == "true" : fallback;
  }
  void finish() const override {
    for (const auto& [key, value] : values_) {
      if (!asked_.contains(key)) fail(key, "unknown key");
    }
  }

 protected:
  void raise(const std::string& key, const std::string& message) const override {
    throw std::invalid_argument(key + ": " + message);
  }

 private:
  const std::string* find(const std::string& key) {
    asked_.insert(key);
    const auto it = values_.find(key);
    return it == values_.end() ? nullptr : &it->second;
  }
  std::map<std::string, std::string> values_;
  std::set<std::string> asked_;
  std::string path_ = "test";
};

std::string error_of(std::map<std::string, std::string> values) {
  MapKeys keys(std::move(values));
  try {
    parse_sequence_keys(keys);
  } catch (const std::invalid_argument& error) {
    return error.what();
  }
  return "";
}

TEST(DatasetTypes, OneRowPerTypeWithAParser) {
  std::set<std::string> names;
  for (const DatasetType& type : dataset_types()) {
    EXPECT_TRUE(names.insert(type.name).second) << type.name << " twice";
    EXPECT_NE(type.parse, nullptr) << type.name;
  }
  EXPECT_EQ(names, (std::set<std::string>{"synthetic", "mulran", "oxford", "boreas", "oord",
                                          "radiate", "folder"}));
}

TEST(DatasetTypes, AnUnknownTypeListsTheKnownOnes) {
  EXPECT_EQ(error_of({{"type", "mulram"}}),
            "type: unknown sequence type 'mulram' (known: synthetic, mulran, oxford, boreas, "
            "oord, radiate, folder)");
}

TEST(DatasetTypes, EachRowParsesItsOwnKeysAndOnlyThose) {
  // Parsing checks the keys and reads no file: a root that does not exist is fine until opened.
  for (const auto& [type, extra] : std::map<std::string, std::map<std::string, std::string>>{
           {"mulran", {{"polar", "polar"}}},
           {"oxford", {{"poses", "gps"}}},
           {"boreas", {}},
           {"oord", {{"azimuths", "400"}}},
           {"radiate", {}},
           {"folder", {{"range_resolution_m", "0.05"}, {"layout", "oxford"}}}}) {
    std::map<std::string, std::string> values = extra;
    values["type"] = type;
    values["root"] = "/nonexistent/radarpr";
    MapKeys keys(values);
    const SequenceConfig config = parse_sequence_keys(keys);
    EXPECT_EQ(config.type, type);
    EXPECT_TRUE(config.open) << type;
    values["speckle"] = "true";  // a synthetic key: not one of theirs
    EXPECT_EQ(error_of(values), "speckle: unknown key") << type;
  }
  MapKeys synthetic({{"type", "synthetic"}, {"seed", "3"}, {"scans", "20"}});
  const SequenceConfig config = parse_sequence_keys(synthetic);
  ASSERT_NE(config.synthetic, nullptr);
  EXPECT_EQ(config.synthetic->seed, 3u);
  EXPECT_EQ(config.synthetic->scan_count, 20);
}

TEST(DatasetTypes, BadValuesNameTheirKey) {
  EXPECT_EQ(error_of({{"type", "oord"}, {"root", "/r"}, {"azimuths", "0"}}),
            "azimuths: must be in [16, 100000], got 0");
  // Fewer than 16 azimuths or range bins: nearly one descriptor value for every scan.
  EXPECT_EQ(error_of({{"type", "oord"}, {"root", "/r"}, {"azimuths", "15"}}),
            "azimuths: must be in [16, 100000], got 15");
  EXPECT_EQ(error_of({{"type", "synthetic"}, {"azimuths", "2"}}),
            "azimuths: must be an integer in [16, 100000], got 2");
  EXPECT_EQ(error_of({{"type", "synthetic"}, {"range_bins", "3"}}),
            "range_bins: must be an integer in [16, 1000000], got 3");
  EXPECT_EQ(error_of({{"type", "mulran"}, {"root", "/r"}, {"polar", "cartesian"}}),
            "polar: 'cartesian' is not one of: auto, polar, polar_oxford_form");
  EXPECT_NE(error_of({{"type", "folder"}, {"root", "/r"}}).find("range_resolution_m: required"),
            std::string::npos);
  EXPECT_EQ(error_of({{"type", "boreas"}, {"root", "/r"}, {"start", "5"}, {"end", "5"}}),
            "end: must be a scan index > start (5), got 5 (end is exclusive)");
}

}  // namespace
}  // namespace radarpr
