// Fuzz target: the experiment config reader with the command line's --set overrides. Input:
// lines "--set key=value" first, then the config file's text. The config's "plugins" (and any
// override of them) are dropped: loading a shared library runs its code by design, so which
// files a config may name as plugins is the loader's check (fuzzed by plugin_abi_fuzz.cpp), not
// this reader's.
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "evaluation/config/config_overrides.hpp"
#include "evaluation/config/experiment_config.hpp"
#include "tests/fuzz/fuzz_target.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace radarpr;
  std::string_view text = fuzz::as_text(data, size);
  constexpr std::string_view kSet = "--set ";
  std::vector<std::string> overrides;
  while (text.starts_with(kSet)) {
    const auto end = text.find('\n');
    std::string assignment(text.substr(kSet.size(), end - kSet.size()));
    if (assignment.starts_with("plugins")) return 0;
    overrides.push_back(std::move(assignment));
    text = end == std::string_view::npos ? std::string_view() : text.substr(end + 1);
  }

  // Parsed here first only to drop "plugins"; the reader parses the file again itself.
  std::string file_text(text);
  try {
    nlohmann::json config = nlohmann::json::parse(text, nullptr, /*allow_exceptions=*/true,
                                                  /*ignore_comments=*/true);
    if (config.is_object() && config.contains("plugins")) {
      config.erase("plugins");
      file_text = config.dump();
    }
  } catch (const nlohmann::json::exception&) {
    // Not JSON: the reader must say so, naming the file.
  }
  const auto path = fuzz::write_scratch_file("config.json", file_text);
  try {
    static_cast<void>(load_experiment_config(path, overrides));
  } catch (const OverrideError& error) {
    fuzz::require_names(error, "--set ");
  } catch (const std::exception& error) {
    fuzz::require_names(error, path.string());
  }
  return 0;
}
