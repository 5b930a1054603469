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
#include "datasets/synthetic/world/world_presets.hpp"
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
  config.drive.lap_pattern = std::string("F");  // one way round: all streets allow it
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

struct Range {
  double low = std::numeric_limits<double>::infinity();
  double high = -std::numeric_limits<double>::infinity();
  bool holds(double value) const { return value >= low && value <= high; }
};

Range range_of(const std::vector<ScanStatistics>& scans, const Statistic& statistic) {
  Range range;
  for (const auto& s : scans) {
    range.low = std::min(range.low, statistic.of(s));
    range.high = std::max(range.high, statistic.of(s));
  }
  return range;
}

std::string show(const Statistic& statistic, double value) {
  return fmt::format(fmt::runtime(statistic.name == "share >= 80" ? "{:.4f}" : "{:.1f}"), value);
}

using Columns = std::vector<std::pair<std::string, std::vector<ScanStatistics>>>;

std::string header(const std::string& first, const Columns& columns) {
  std::string table = fmt::format("| statistic | {} |", first);
  std::string rule = "|---|---|";
  for (const auto& [name, scans] : columns) {
    table += fmt::format(" {} |", name);
    rule += "---:|";
  }
  return table + "\n" + rule + "\n";
}

std::vector<ScanStatistics> statistics_of(const test::RealSource& source) {
  std::vector<ScanStatistics> scans;
  for (const auto& scan : source.scans) scans.push_back(test::scan_statistics(scan));
  return scans;
}

TEST(SyntheticCredibility, PresetsFallInsideTheRealScansRanges) {
  const std::vector<test::RealSource> sources = test::real_sources();
  if (sources.size() < 3) {
    GTEST_SKIP() << "real MulRan, Oxford and Boreas samples absent: "
                 << test::real_data("").string();
  }
  std::vector<ScanStatistics> real;
  Columns per_source;
  for (const auto& source : sources) {
    const std::vector<ScanStatistics> scans = statistics_of(source);
    real.insert(real.end(), scans.begin(), scans.end());
    per_source.emplace_back(fmt::format("{} ({} scans)", source.name, scans.size()), scans);
  }
  const Columns checked = {
      {"synthetic cir204h, city", synthetic_scans("cir204h", "city")},
      {"synthetic cts350x, city", synthetic_scans("cts350x", "city")},
  };
  // For the record (not checked: no real sample of those places), the other worlds.
  const Columns shown = {
      {"synthetic cir204h, campus", synthetic_scans("cir204h", "campus")},
      {"synthetic cir204h, riverside", synthetic_scans("cir204h", "riverside")},
      {"synthetic cir204h, suburban", synthetic_scans("cir204h", "suburban")},
      {"synthetic cir204h, offroad", synthetic_scans("cir204h", "offroad")},
  };
  Columns all = per_source;
  all.insert(all.end(), checked.begin(), checked.end());
  all.insert(all.end(), shown.begin(), shown.end());
  std::string table = header("real range", all);
  for (const Statistic& statistic : statistics()) {
    const Range range = range_of(real, statistic);
    table += fmt::format("| {} | {} - {} |", statistic.name, show(statistic, range.low),
                         show(statistic, range.high));
    for (const auto& [name, scans] : all) {
      table += fmt::format(" {} |", show(statistic, mean_of(scans, statistic)));
    }
    for (const auto& [name, scans] : checked) {
      EXPECT_TRUE(range.holds(mean_of(scans, statistic))) << name << ": " << statistic.name;
    }
    table.push_back('\n');
  }
  fmt::print("{}", table);
}

// Each sensor against the dataset recorded with it: the CIR204-H preset with MulRan's scans,
// the CTS350-X preset with Oxford's (min - max over that dataset's scans; printed, and checked
// on what the descriptors count: features per azimuth and how far they reach).
TEST(SyntheticCredibility, EachSensorAgainstItsOwnDataset) {
  const std::vector<test::RealSource> sources = test::real_sources();
  if (sources.size() < 3) {
    GTEST_SKIP() << "real MulRan, Oxford and Boreas samples absent: "
                 << test::real_data("").string();
  }
  struct Pair {
    std::string dataset;
    std::string radar;
  };
  std::string table;
  for (const Pair& pair : {Pair{"MulRan", "cir204h"}, Pair{"Oxford", "cts350x"}}) {
    const auto source = std::find_if(sources.begin(), sources.end(),
                                     [&](const auto& s) { return s.name == pair.dataset; });
    ASSERT_NE(source, sources.end());
    const std::vector<ScanStatistics> real = statistics_of(*source);
    const Columns synthetic = {
        {fmt::format("synthetic {}, city", pair.radar), synthetic_scans(pair.radar, "city")}};
    table += header(fmt::format("{} range ({} scans)", pair.dataset, real.size()), synthetic);
    for (const Statistic& statistic : statistics()) {
      const Range range = range_of(real, statistic);
      const double value = mean_of(synthetic[0].second, statistic);
      table += fmt::format("| {} | {} - {} | {} |\n", statistic.name, show(statistic, range.low),
                           show(statistic, range.high), show(statistic, value));
    }
    table += "\n";
  }
  fmt::print("{}", table);
}

}  // namespace
}  // namespace radarpr
