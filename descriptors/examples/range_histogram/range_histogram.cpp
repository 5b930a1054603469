// An out-of-tree descriptor plugin: a rotation-invariant range histogram.
//
// For each of `bands` equal bands of range bins it counts the cells, over every azimuth, whose
// intensity exceeds `threshold`, and divides by the count of all bands (L1 normalisation): where
// along the range the returns lie, whatever the heading. Summing over azimuths is what makes it
// rotation-invariant; normalising makes it indifferent to how much the radar sees overall.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <descriptors/plugins/plugin.hpp>

namespace range_histogram {

using radarpr::DescriptorValue;

enum class Distance { l2, l1 };

class RangeHistogram final : public radarpr::Descriptor {
 public:
  RangeHistogram(int bands, int threshold, Distance distance)
      : bands_(bands), threshold_(threshold), distance_(distance) {}

  DescriptorValue extract(const radarpr::PolarImage& scan) const override {
    // 8-bit power, row = azimuth, column = range bin (radarpr::ByteImage).
    const radarpr::ByteImage& power = scan.power;
    if (power.empty()) {
      throw std::invalid_argument("range_histogram: expected a non-empty polar scan");
    }
    const int range_bins = power.cols();
    if (bands_ > range_bins) {
      throw std::invalid_argument("range_histogram: bands (" + std::to_string(bands_) +
                                  ") exceeds the scan's range bins (" + std::to_string(range_bins) +
                                  ")");
    }
    // Band of each range bin, once: bin r lies in band floor(r * bands / range_bins).
    std::vector<int> band_of(static_cast<std::size_t>(range_bins));
    for (int r = 0; r < range_bins; ++r) {
      band_of[static_cast<std::size_t>(r)] = static_cast<int>(
          static_cast<std::int64_t>(r) * bands_ / static_cast<std::int64_t>(range_bins));
    }
    std::vector<std::int64_t> counts(static_cast<std::size_t>(bands_), 0);
    for (int a = 0; a < power.rows(); ++a) {
      const std::uint8_t* row = power.row(a);
      for (int r = 0; r < range_bins; ++r) {
        if (row[r] > threshold_)
          ++counts[static_cast<std::size_t>(band_of[static_cast<std::size_t>(r)])];
      }
    }
    std::int64_t total = 0;
    for (const std::int64_t count : counts) total += count;
    DescriptorValue value{1, bands_, std::vector<float>(counts.size(), 0.0f)};
    // An empty scan (nothing above the threshold) stays all zeros rather than dividing by zero.
    if (total > 0) {
      for (std::size_t b = 0; b < counts.size(); ++b) {
        value.values[b] =
            static_cast<float>(static_cast<double>(counts[b]) / static_cast<double>(total));
      }
    }
    return value;
  }

  double distance(const DescriptorValue& a, const DescriptorValue& b) const override {
    if (a.values.size() != b.values.size()) {
      throw std::invalid_argument("range_histogram: values of " + std::to_string(a.values.size()) +
                                  " and " + std::to_string(b.values.size()) +
                                  " bands cannot be compared");
    }
    double sum = 0.0;
    for (std::size_t i = 0; i < a.values.size(); ++i) {
      const double difference = static_cast<double>(a.values[i]) - static_cast<double>(b.values[i]);
      sum += distance_ == Distance::l1 ? std::abs(difference) : difference * difference;
    }
    return distance_ == Distance::l1 ? sum : std::sqrt(sum);
  }

  bool rotation_invariant() const override { return true; }

  radarpr::DescriptorShape shape(const radarpr::ScanGeometry& /*geometry*/) const override {
    return {1, bands_};
  }

  // L2 between the values is what a KD-tree searches exactly; L1 needs the exhaustive search.
  radarpr::RetrievalMethod retrieval_method() const override {
    return distance_ == Distance::l2 ? radarpr::RetrievalMethod::kdtree
                                     : radarpr::RetrievalMethod::exhaustive;
  }

 private:
  int bands_;
  int threshold_;
  Distance distance_;
};

radarpr::DescriptorInfo make_range_histogram_info() {
  radarpr::DescriptorInfo info;
  info.name = "range_histogram";
  info.summary =
      "Example plugin: rotation-invariant histogram of the returns above a threshold per range "
      "band, L1-normalised";
  // Defaults picked on the synthetic town (experiment.json): a low threshold keeps the weak
  // returns that carry most of the structure; coarse bands tolerate the drive's lateral offsets.
  info.parameters = {
      {.name = "bands",
       .kind = radarpr::ParameterKind::integer,
       .default_value = std::int64_t{10},
       .description = "equal bands of range bins",
       .minimum = 1,
       .maximum = 4096},
      {.name = "threshold",
       .kind = radarpr::ParameterKind::integer,
       .default_value = std::int64_t{15},
       .description = "a cell counts when its intensity exceeds this",
       .minimum = 0,
       .maximum = 254},
      {.name = "distance",
       .kind = radarpr::ParameterKind::choice,
       .default_value = std::string("l2"),
       .description = "distance between histograms",
       .choices = {"l2", "l1"}},
  };
  info.create = [](const radarpr::ParameterValues& values) -> std::unique_ptr<radarpr::Descriptor> {
    return std::make_unique<RangeHistogram>(
        static_cast<int>(values.integer("bands")), static_cast<int>(values.integer("threshold")),
        radarpr::choice_value<Distance>(values, "distance",
                                        {{"l2", Distance::l2}, {"l1", Distance::l1}}));
  };
  return info;
}

void register_range_histogram(radarpr::DescriptorRegistry& registry) {
  registry.add(make_range_histogram_info());
}

}  // namespace range_histogram

RADARPR_PLUGIN(range_histogram::register_range_histogram);
