// Every key the config reader accepts is in docs/configs.md's "Every key" tables, with a type, a
// range and a default, and every documented number is range-checked where it is read.
//
// The accepted keys are not listed here by hand: each object of a config that parses is given one
// unknown key, and the reader's error lists the keys it accepts there. So a key added to a reader
// without a row in the docs, or a row left behind by a removed key, fails this test.
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "evaluation/config/config_error.hpp"
#include "evaluation/config/experiment_config.hpp"

namespace radarpr {
namespace {

const char* const kUnknownKey = "zz_not_a_key";

struct DocumentedKey {
  std::string type;   // "integer", "number or null", ...
  std::string range;  // the values it takes
  std::string fallback;
};

// docs/configs.md from "## Every key" on: each heading's table rows, by key.
std::map<std::string, std::map<std::string, DocumentedKey>> documented_tables() {
  std::ifstream file(std::string(RADARPR_SOURCE_DIR) + "/docs/configs.md");
  EXPECT_TRUE(file) << "docs/configs.md not found";
  std::map<std::string, std::map<std::string, DocumentedKey>> tables;
  std::string line;
  bool in_section = false;
  std::string heading;
  while (std::getline(file, line)) {
    if (line.rfind("## ", 0) == 0) in_section = line == "## Every key";
    if (!in_section) continue;
    if (line.rfind("###", 0) == 0) {
      heading = line.substr(line.find(' ') + 1);
      continue;
    }
    if (line.rfind("| `", 0) != 0) continue;
    std::vector<std::string> cells;
    std::stringstream row(line.substr(1));
    std::string cell;
    while (std::getline(row, cell, '|')) {
      const auto first = cell.find_first_not_of(' ');
      const auto last = cell.find_last_not_of(' ');
      cells.push_back(first == std::string::npos ? "" : cell.substr(first, last - first + 1));
    }
    if (!cells.empty() && cells.back().empty()) cells.pop_back();  // after the closing '|'
    EXPECT_EQ(cells.size(), 4u) << "docs/configs.md, under '" << heading
                                << "': expected | key | type | range | default |: " << line;
    if (cells.size() != 4) continue;
    const std::string key = cells[0].substr(1, cells[0].size() - 2);  // inside the backticks
    for (std::size_t i = 1; i < 4; ++i) {
      EXPECT_FALSE(cells[i].empty())
          << "docs/configs.md: `" << key << "` under '" << heading << "' has an empty cell";
    }
    EXPECT_TRUE(tables[heading].emplace(key, DocumentedKey{cells[1], cells[2], cells[3]}).second)
        << "docs/configs.md: `" << key << "` twice under '" << heading << "'";
  }
  return tables;
}

nlohmann::json synthetic_sequence(int session) {
  return {{"type", "synthetic"}, {"world", "city"},    {"radar", "tiny"},
          {"weather", "clear"},  {"session", session}, {"scans", 40}};
}

// A config that parses and sets every optional object, so that each can be probed.
nlohmann::json full_config() {
  return {
      {"experiment", "keys"},
      {"description", "every object set"},
      {"threads", 1},
      {"plugins", nlohmann::json::array()},
      {"datasets",
       {{{"name", "town"},
         {"query", synthetic_sequence(1)},
         {"database", synthetic_sequence(0)},
         {"training", synthetic_sequence(2)}}}},
      {"descriptors",
       {{{"name", "referee"}, {"params", nlohmann::json::object()}, {"label", "R"}}}},
      {"protocol",
       {{"train_on", "training_sequence"}, {"recall_at_k", {1}}, {"exclude_recent_seconds", 5}}},
      {"report", {{"style", "paper"}, {"recall_curve_n", 10}}},
  };
}

nlohmann::json matrix_config() {
  nlohmann::json config = full_config();
  config["datasets"] = {{
      {"kind", "session_matrix"},
      {"name", "loop"},
      {"sessions",
       {{{"name", "a"}, {"sequence", synthetic_sequence(0)}},
        {{"name", "b"}, {"sequence", synthetic_sequence(1)}}}},
      {"pairs", {{{"query", "a"}, {"database", "b"}}}},
      {"training", synthetic_sequence(2)},
  }};
  return config;
}

nlohmann::json real_sequence_config(const std::string& type) {
  nlohmann::json config = full_config();
  nlohmann::json sequence = {{"type", type}, {"root", "/nonexistent/dataset"}};
  if (type == "folder") sequence["range_resolution_m"] = 0.1;
  config["datasets"][0]["query"] = sequence;
  return config;
}

// One object of a config: where it is, and the doc headings whose tables list its keys.
struct Probe {
  std::string name;
  nlohmann::json config;
  std::string pointer;  // JSON pointer to the object
  std::vector<std::string> headings;
};

std::vector<Probe> probes() {
  const std::string real = "Sequence keys of every real dataset type";
  std::vector<Probe> list = {
      {"top level", full_config(), "", {"Top level"}},
      {"dataset", full_config(), "/datasets/0", {"Dataset entries"}},
      {"session matrix", matrix_config(), "/datasets/0", {"Session matrix entries"}},
      {"matrix session", matrix_config(), "/datasets/0/sessions/0", {"`sessions` elements"}},
      {"matrix pair", matrix_config(), "/datasets/0/pairs/0", {"`pairs` elements"}},
      {"synthetic sequence", full_config(), "/datasets/0/query", {"`synthetic` sequences"}},
      {"descriptor", full_config(), "/descriptors/0", {"Descriptor entries"}},
      {"protocol", full_config(), "/protocol", {"Protocol"}},
      {"report", full_config(), "/report", {"Report"}},
  };
  // boreas and radiate take only the keys every real type takes.
  for (const std::string type : {"boreas", "radiate"}) {
    list.push_back({type + " sequence", real_sequence_config(type), "/datasets/0/query", {real}});
  }
  for (const std::string type : {"mulran", "oxford", "oord", "folder"}) {
    list.push_back({type + " sequence",
                    real_sequence_config(type),
                    "/datasets/0/query",
                    {real, "`" + type + "` sequences"}});
  }
  return list;
}

// The keys the reader accepts in the probe's object, from its error for an unknown key.
std::set<std::string> accepted_keys(const Probe& probe) {
  nlohmann::json config = probe.config;
  config[nlohmann::json::json_pointer(probe.pointer)][kUnknownKey] = 1;
  try {
    parse_experiment_config(config);
  } catch (const ConfigError& error) {
    const std::string prefix = "unknown key (expected one of: ";
    EXPECT_EQ(error.message().rfind(prefix, 0), 0u) << probe.name << ": " << error.what();
    if (error.message().rfind(prefix, 0) != 0) return {};
    const std::string list =
        error.message().substr(prefix.size(), error.message().size() - prefix.size() - 1);
    std::set<std::string> keys;
    std::stringstream stream(list);
    std::string key;
    while (std::getline(stream, key, ',')) keys.insert(key.substr(key.find_first_not_of(' ')));
    return keys;
  }
  ADD_FAILURE() << probe.name << ": the unknown key was accepted";
  return {};
}

std::map<std::string, DocumentedKey> documented_keys(
    const Probe& probe, const std::map<std::string, std::map<std::string, DocumentedKey>>& docs) {
  std::map<std::string, DocumentedKey> keys;
  for (const std::string& heading : probe.headings) {
    const auto table = docs.find(heading);
    if (table == docs.end()) {
      ADD_FAILURE() << "docs/configs.md has no table under '### " << heading << "'";
      continue;
    }
    keys.insert(table->second.begin(), table->second.end());
  }
  return keys;
}

TEST(ConfigKeysDocumented, TheProbedConfigsParse) {
  for (const Probe& probe : probes()) {
    EXPECT_NO_THROW(parse_experiment_config(probe.config)) << probe.name;
  }
}

TEST(ConfigKeysDocumented, EveryKeyTheReaderAcceptsHasARowAndEveryRowIsAccepted) {
  const auto docs = documented_tables();
  for (const Probe& probe : probes()) {
    const std::set<std::string> accepted = accepted_keys(probe);
    EXPECT_FALSE(accepted.empty()) << probe.name;
    const auto documented = documented_keys(probe, docs);
    for (const std::string& key : accepted) {
      EXPECT_EQ(documented.count(key), 1u)
          << probe.name << ": the reader accepts `" << key
          << "`, which docs/configs.md does not list in its table(s) under: "
          << testing::PrintToString(probe.headings);
    }
    for (const auto& [key, _] : documented) {
      EXPECT_EQ(accepted.count(key), 1u)
          << probe.name << ": docs/configs.md lists `" << key << "`, which the reader refuses";
    }
  }
}

// A number far out of any range on either side is an error that names the key, for every key
// documented as a number or an integer: no key converts a value it has not checked.
TEST(ConfigKeysDocumented, EveryNumericKeyRefusesValuesOutsideItsRangeNamingTheKey) {
  const auto docs = documented_tables();
  for (const Probe& probe : probes()) {
    for (const auto& [key, documented] : documented_keys(probe, docs)) {
      if (documented.type.rfind("number", 0) != 0 && documented.type.rfind("integer", 0) != 0) {
        continue;
      }
      for (const double value : {1e300, -1e300, 9.3e18, -9.3e18}) {
        nlohmann::json config = probe.config;
        config[nlohmann::json::json_pointer(probe.pointer)][key] = value;
        std::string blamed = "(parsed)";
        try {
          parse_experiment_config(config);
        } catch (const ConfigError& error) {
          blamed = error.key_path();
        }
        const std::string suffix = "." + key;
        const bool names_key = blamed == key || (blamed.size() > suffix.size() &&
                                                 blamed.compare(blamed.size() - suffix.size(),
                                                                suffix.size(), suffix) == 0);
        EXPECT_TRUE(names_key) << probe.name << ": `" << key << "` = " << value
                               << " (documented range: " << documented.range
                               << ") blamed: " << blamed;
      }
    }
  }
}

}  // namespace
}  // namespace radarpr
