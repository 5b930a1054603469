// Synthetic scans against the real MulRan, Oxford and Boreas samples (skipped when absent), on
// the statistics descriptors depend on: the intensity histogram, the mean range profile, Cen 2018
// features per azimuth and the farthest feature's range. Each synthetic sensor preset, averaged
// over scans along a city drive, must fall inside the range the real scans span. The table it
// prints is the README's ("The embedded default: a synthetic radar world").
#include <algorithm>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "datasets/synthetic/synthetic_sequence.hpp"
#include "datasets/synthetic/world_presets.hpp"
#include "tests/datasets/real_scan_samples.hpp"
#include "tests/datasets/scan_statistics.hpp"

namespace radarpr {
namespace {

using test::ScanStatistics;

struct Statistic {
  std::string name;
  std::function<double(const ScanStatistics&)> of;
};

std::vector<Statistic> statistics() {
  std::vector<Statistic> all = {
      {"intensity median", [](const ScanStatistics& s) { return s.median; }},
      {"intensity p90", [](const ScanStatistics& s) { return s.p90; }},
      {"intensity p99", [](const ScanStatistics& s) { return s.p99; }},
      {"share >= 80", [](const ScanStatistics& s) { return s.bright_fraction; }},
  };
  for (std::size_t b = 0; b + 1 < test::kProfileBandEdgesM.size(); ++b) {
    all.push_back({fmt::format("mean {:.0f}-{:.0f} m", test::kProfileBandEdgesM[b],
                               test::kProfileBandEdgesM[b + 1]),
                   [b](const ScanStatistics& s) { return s.profile[b]; }});
  }
  all.push_back(
      {"features / azimuth", [](const ScanStatistics& s) { return s.features_per_azimuth; }});
  all.push_back(
      {"farthest feature m", [](const ScanStatistics& s) { return s.farthest_feature_m; }});
  return all;
}

// The mean of each statistic over scans spread along a drive of `world` with radar `radar`.
std::vector<ScanStatistics> synthetic_scans(const std::string& radar, const std::string& world) {
  SyntheticConfig config;
  const auto preset = synthetic::world_preset(world);
  config.city = preset.layout;
  config.world = preset.params;
  config.radar = synthetic::radar_preset(radar);
  config.radar.ground_clutter = preset.ground_clutter;
  config.radar.ground_clutter_falloff_m = preset.ground_clutter_falloff_m;
  config.scan_count = 200;
  const SyntheticSequence sequence(config);
  std::vector<ScanStatistics> scans;
  for (std::size_t i = 5; i < sequence.size(); i += 25) {
    scans.push_back(test::scan_statistics(sequence.load_image(i)));
  }
  return scans;
}

double mean_of(const std::vector<ScanStatistics>& scans, const Statistic& statistic) {
  double sum = 0.0;
  for (const auto& s : scans) sum += statistic.of(s);
  return sum / static_cast<double>(scans.size());
}

TEST(SyntheticCredibility, PresetsFallInsideTheRealScansRanges) {
  const std::vector<test::RealSource> sources = test::real_sources();
  if (sources.size() < 3) {
    GTEST_SKIP() << "real MulRan, Oxford and Boreas samples absent: "
                 << test::real_data("").string();
  }
  std::vector<ScanStatistics> real;
  std::vector<std::pair<std::string, std::vector<ScanStatistics>>> per_source;
  for (const auto& source : sources) {
    std::vector<ScanStatistics> scans;
    for (const auto& scan : source.scans) scans.push_back(test::scan_statistics(scan));
    real.insert(real.end(), scans.begin(), scans.end());
    per_source.emplace_back(fmt::format("{} ({} scans)", source.name, scans.size()), scans);
  }
  const std::vector<std::pair<std::string, std::vector<ScanStatistics>>> checked = {
      {"synthetic cir204h, city", synthetic_scans("cir204h", "city")},
      {"synthetic cts350x, city", synthetic_scans("cts350x", "city")},
  };
  // For the record (not checked: no real sample of those places), the other worlds.
  const std::vector<std::pair<std::string, std::vector<ScanStatistics>>> shown = {
      {"synthetic short, campus", synthetic_scans("short", "campus")},
      {"synthetic cir204h, riverside", synthetic_scans("cir204h", "riverside")},
      {"synthetic cir204h, offroad", synthetic_scans("cir204h", "offroad")},
  };

  std::string table = "| statistic | real range |";
  std::string rule = "|---|---|";
  for (const auto& [name, scans] : per_source) {
    table += fmt::format(" {} |", name);
    rule += "---:|";
  }
  for (const auto& [name, scans] : checked) {
    table += fmt::format(" {} |", name);
    rule += "---:|";
  }
  for (const auto& [name, scans] : shown) {
    table += fmt::format(" {} |", name);
    rule += "---:|";
  }
  table += fmt::format("\n{}\n", rule);
  for (const Statistic& statistic : statistics()) {
    double low = std::numeric_limits<double>::infinity();
    double high = -low;
    for (const auto& s : real) {
      low = std::min(low, statistic.of(s));
      high = std::max(high, statistic.of(s));
    }
    const char* format = high < 1.0 ? "{:.4f}" : "{:.1f}";
    auto show = [&](double v) { return fmt::format(fmt::runtime(format), v); };
    table += fmt::format("| {} | {} - {} |", statistic.name, show(low), show(high));
    for (const auto& [name, scans] : per_source)
      table += fmt::format(" {} |", show(mean_of(scans, statistic)));
    for (const auto& [name, scans] : checked) {
      const double value = mean_of(scans, statistic);
      table += fmt::format(" {} |", show(value));
      EXPECT_GE(value, low) << name << ": " << statistic.name;
      EXPECT_LE(value, high) << name << ": " << statistic.name;
    }
    for (const auto& [name, scans] : shown)
      table += fmt::format(" {} |", show(mean_of(scans, statistic)));
    table.push_back('\n');
  }
  fmt::print("{}", table);
}

}  // namespace
}  // namespace radarpr
