#include <fmt/format.h>
#include <gtest/gtest.h>

#include "datasets/synthetic/synthetic_sequence.hpp"
#include "tests/datasets/real_scan_samples.hpp"
#include "tests/datasets/scan_statistics.hpp"

namespace radarpr {
namespace {

void print(const std::string& name, const test::ScanStatistics& s) {
  fmt::print(
      "{:10} med {:5.1f} p90 {:5.1f} p99 {:5.1f} bright {:.4f} prof {:5.1f} {:5.1f} {:5.1f} "
      "{:5.1f} feat {:5.2f} far {:6.1f}\n",
      name, s.median, s.p90, s.p99, s.bright_fraction, s.profile[0], s.profile[1], s.profile[2],
      s.profile[3], s.features_per_azimuth, s.farthest_feature_m);
}

TEST(SyntheticCredibility, Explore) {
  for (const auto& source : test::real_sources()) {
    for (const auto& scan : source.scans) print(source.name, test::scan_statistics(scan));
  }
  SyntheticConfig config;
  config.scan_count = 120;
  config.radar.range_bin_count = 3360;
  const SyntheticSequence seq(config);
  for (std::size_t i : {0, 30, 60, 90}) print("synth", test::scan_statistics(seq.load_image(i)));
}

}  // namespace
}  // namespace radarpr
