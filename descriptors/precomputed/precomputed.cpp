#include "descriptors/precomputed/precomputed.hpp"

#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

#include "datasets/npy_file.hpp"
#include "datasets/real/text_table.hpp"

namespace radarpr {
namespace {

bool has_placeholder(const std::string& path) {
  return path.find('{') != std::string::npos;
}

void replace_all(std::string& text, const std::string& from, const std::string& to) {
  for (std::size_t at = text.find(from); at != std::string::npos; at = text.find(from, at)) {
    text.replace(at, from.size(), to);
    at += to.size();
  }
}

double squared_norm(const std::vector<float>& values) {
  double sum = 0.0;
  for (const float v : values) sum += static_cast<double>(v) * v;
  return sum;
}

void check_same_size(const DescriptorValue& a, const DescriptorValue& b) {
  if (a.values.size() != b.values.size()) {
    throw std::invalid_argument(
        fmt::format("precomputed: values of {} and {} elements cannot be compared", a.values.size(),
                    b.values.size()));
  }
}

// The number of value columns of a values file, read without loading it; 0 when it cannot be
// read now (values_for reports why, with the sequence it was read for).
int dimension_of(const std::string& path, bool has_time_file) {
  try {
    if (std::filesystem::path(path).extension() == ".npy") {
      const NpyFile file = NpyFile::open(path);
      if (file.shape().size() == 2) return static_cast<int>(file.shape()[1]);
      return file.shape().size() == 1 ? 1 : 0;
    }
    TextTable csv(path, TextTable::Separator::comma, "the precomputed descriptor's values");
    csv.read_header();
    const bool has_time_column = !has_time_file && csv.find_column({"timestamp", "timestamp_ns"});
    return static_cast<int>(csv.header().size()) - (has_time_column ? 1 : 0);
  } catch (const std::exception&) {
    return 0;
  }
}

}  // namespace

std::string expand_precomputed_path(const std::string& pattern, const ExternalSequence& sequence) {
  std::string path = pattern;
  replace_all(path, "{dataset}", sequence.dataset);
  replace_all(path, "{role}", sequence.role);
  return path;
}

PrecomputedDescriptor::PrecomputedDescriptor(PrecomputedParams params)
    : params_(std::move(params)) {
  if (!params_.values.empty() && !has_placeholder(params_.values)) {
    dimension_ = dimension_of(params_.values, !params_.timestamps.empty());
  }
}

DescriptorValue PrecomputedDescriptor::extract(const PolarImage& /*scan*/) const {
  throw std::invalid_argument(
      "precomputed: the values come from the file its 'values' parameter names, matched to scans "
      "by time; it does not describe a scan image (use it in an experiment config)");
}

double PrecomputedDescriptor::distance(const DescriptorValue& a, const DescriptorValue& b) const {
  check_same_size(a, b);
  if (params_.distance == PrecomputedDistance::l2) {
    double sum = 0.0;
    for (std::size_t i = 0; i < a.values.size(); ++i) {
      const double difference = static_cast<double>(a.values[i]) - b.values[i];
      sum += difference * difference;
    }
    return std::sqrt(sum);
  }
  const double norm_a = std::sqrt(squared_norm(a.values));
  const double norm_b = std::sqrt(squared_norm(b.values));
  if (norm_a == 0.0 && norm_b == 0.0) return 0.0;
  if (norm_a == 0.0 || norm_b == 0.0) return 0.5;
  double dot = 0.0;
  for (std::size_t i = 0; i < a.values.size(); ++i) {
    dot += static_cast<double>(a.values[i]) * b.values[i];
  }
  return 1.0 - dot / (norm_a * norm_b);
}

DescriptorShape PrecomputedDescriptor::shape(const ScanGeometry& /*geometry*/) const {
  return {dimension_.load(), 1};
}

std::vector<float> PrecomputedDescriptor::search_key(const DescriptorValue& value) const {
  if (params_.distance == PrecomputedDistance::l2) return value.values;
  const double norm = std::sqrt(squared_norm(value.values));
  std::vector<float> key(value.values.size(), 0.0f);
  if (norm == 0.0) return key;
  for (std::size_t i = 0; i < key.size(); ++i) key[i] = static_cast<float>(value.values[i] / norm);
  return key;
}

std::vector<DescriptorValue> PrecomputedDescriptor::values_for(
    const ExternalSequence& sequence) const {
  const std::string values = expand_precomputed_path(params_.values, sequence);
  const std::string timestamps = expand_precomputed_path(params_.timestamps, sequence);
  const PrecomputedTable table = read_precomputed_table(values, timestamps, params_.time_unit);
  const auto tolerance_ns = static_cast<std::int64_t>(std::llround(params_.tolerance_ms * 1e6));
  std::vector<DescriptorValue> matched =
      match_rows_to_scans(table, sequence.records, tolerance_ns, sequence.name);
  int expected = 0;
  const int dimension = static_cast<int>(table.dimension);
  if (!dimension_.compare_exchange_strong(expected, dimension) && expected != dimension) {
    throw std::runtime_error(
        fmt::format("{}: {} values per row, but another sequence's file had {}", table.source,
                    dimension, expected));
  }
  return matched;
}

DescriptorInfo make_precomputed_info() {
  const PrecomputedParams defaults;
  std::vector<ParameterSpec> parameters = {
      {.name = "values",
       .kind = ParameterKind::text,
       .default_value = std::string(),
       .description = "the values: a .npy N x D (float32/float64) or a CSV with a header; "
                      "{dataset} and {role} are replaced per sequence"},
      {.name = "timestamps",
       .kind = ParameterKind::text,
       .default_value = std::string(),
       .description = "the rows' times: a .npy of N (int64 or float64) or one per line; empty: "
                      "the CSV's timestamp column"},
      {.name = "time_unit",
       .kind = ParameterKind::choice,
       .default_value = std::string("ns"),
       .description = "the unit of the times",
       .choices = {"ns", "us", "ms", "s"}},
      {.name = "tolerance_ms",
       .kind = ParameterKind::number,
       .default_value = defaults.tolerance_ms,
       .description = "how far a row's time may be from its scan's",
       .minimum = 0.0,
       .maximum = 1e6},
      {.name = "distance",
       .kind = ParameterKind::choice,
       .default_value = std::string("l2"),
       .description = "Euclidean distance, or 1 - cosine similarity",
       .choices = {"l2", "cosine"}},
      {.name = "rotation_invariant",
       .kind = ParameterKind::boolean,
       .default_value = defaults.rotation_invariant,
       .description = "whether the values are invariant to the sensor's heading (for the tables)"},
  };
  return DescriptorInfo{
      "precomputed",
      "Descriptor values computed outside radarpr (.npy or CSV), matched to the scans by time",
      std::move(parameters), [](const ParameterValues& values) -> std::unique_ptr<Descriptor> {
        PrecomputedParams params;
        params.values = values.text("values");
        params.timestamps = values.text("timestamps");
        params.time_unit = choice_value<PrecomputedTimeUnit>(values, "time_unit",
                                                             {{"ns", PrecomputedTimeUnit::ns},
                                                              {"us", PrecomputedTimeUnit::us},
                                                              {"ms", PrecomputedTimeUnit::ms},
                                                              {"s", PrecomputedTimeUnit::s}});
        params.tolerance_ms = values.number("tolerance_ms");
        params.distance = choice_value<PrecomputedDistance>(
            values, "distance",
            {{"l2", PrecomputedDistance::l2}, {"cosine", PrecomputedDistance::cosine}});
        params.rotation_invariant = values.boolean("rotation_invariant");
        return std::make_unique<PrecomputedDescriptor>(std::move(params));
      }};
}

RADARPR_REGISTER_DESCRIPTOR(precomputed, make_precomputed_info)

}  // namespace radarpr
