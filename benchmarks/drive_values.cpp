#include "benchmarks/drive_values.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "datasets/synthetic/random.hpp"
#include "evaluation/parallel.hpp"

namespace radarpr::bench {
namespace {

// Stream tags of the generator's independent random streams.
enum Stream : std::uint64_t { route = 1, mapping = 2, lap_shift = 3, element_noise = 4 };

void check(const DriveValuesSpec& spec) {
  if (spec.count < 1 || spec.rows < 1 || spec.cols < 1 || spec.laps < 1 ||
      spec.latent_dimensions < 1 || spec.modes < 1) {
    throw std::invalid_argument(
        "drive_values: count, rows, cols, laps, latent_dimensions and modes must all be >= 1, "
        "got " +
        std::to_string(spec.count) + ", " + std::to_string(spec.rows) + ", " +
        std::to_string(spec.cols) + ", " + std::to_string(spec.laps) + ", " +
        std::to_string(spec.latent_dimensions) + ", " + std::to_string(spec.modes));
  }
}

}  // namespace

DriveValueGenerator::DriveValueGenerator(const DriveValuesSpec& spec) : spec_(spec) {
  check(spec);
  const auto latent = static_cast<std::size_t>(spec.latent_dimensions);
  const auto modes = static_cast<std::size_t>(spec.modes);
  dimension_ = static_cast<std::size_t>(spec.rows) * static_cast<std::size_t>(spec.cols);

  // Route: cosine and sine coefficients per latent dimension and mode.
  synthetic::Rng route_rng(synthetic::hash_key({spec.seed, Stream::route}));
  coefficients_.resize(latent * modes * 2);
  for (double& c : coefficients_) c = route_rng.normal(0.0, 1.0);
  // Mapping into the elements, scaled so that an element varies about as much as a latent one.
  synthetic::Rng mapping_rng(synthetic::hash_key({spec.seed, Stream::mapping}));
  mapping_.resize(dimension_ * latent);
  const double mapping_scale = 1.0 / std::sqrt(static_cast<double>(latent));
  for (float& m : mapping_) m = static_cast<float>(mapping_rng.normal(0.0, mapping_scale));
  // A shift per lap of this session.
  synthetic::Rng lap_rng(synthetic::hash_key(
      {spec.seed, Stream::lap_shift, static_cast<std::uint64_t>(spec.session)}));
  lap_shifts_.resize(static_cast<std::size_t>(spec.laps) * latent);
  for (double& s : lap_shifts_) s = lap_rng.normal(0.0, spec.lap_variation);
}

void DriveValueGenerator::value(std::size_t i, float* out) const {
  const DriveValuesSpec& spec = spec_;
  const auto latent = static_cast<std::size_t>(spec.latent_dimensions);
  const auto modes = static_cast<std::size_t>(spec.modes);
  const double noise_half_width = spec.noise * std::sqrt(3.0);  // uniform with that std dev
  const double position = static_cast<double>(i) * spec.laps / static_cast<double>(spec.count);
  const auto lap = static_cast<std::size_t>(position);
  const double s = position - static_cast<double>(lap);  // along the route, [0, 1)
  std::vector<float> z(latent);
  for (std::size_t l = 0; l < latent; ++l) {
    double sum = lap_shifts_[lap * latent + l];
    for (std::size_t m = 0; m < modes; ++m) {
      const double angle = 2.0 * std::numbers::pi * static_cast<double>(m + 1) * s;
      const double* c = &coefficients_[(l * modes + m) * 2];
      sum += (c[0] * std::cos(angle) + c[1] * std::sin(angle)) / static_cast<double>(m + 1);
    }
    z[l] = static_cast<float>(sum);
  }
  synthetic::Rng noise_rng(synthetic::hash_key(
      {spec.seed, Stream::element_noise, static_cast<std::uint64_t>(spec.session), i}));
  for (std::size_t d = 0; d < dimension_; ++d) {
    const float* row = &mapping_[d * latent];
    float element = 1.0f;
    for (std::size_t l = 0; l < latent; ++l) element += row[l] * z[l];
    element += static_cast<float>(noise_rng.uniform(-noise_half_width, noise_half_width));
    out[d] = element;
  }
}

std::vector<DescriptorValue> drive_values(const DriveValuesSpec& spec) {
  const DriveValueGenerator generator(spec);
  std::vector<DescriptorValue> values(spec.count);
  parallel_for(spec.count, 0, [&](std::size_t i) {
    DescriptorValue& value = values[i];
    value.rows = spec.rows;
    value.cols = spec.cols;
    value.values.resize(generator.dimension());
    generator.value(i, value.values.data());
  });
  return values;
}

}  // namespace radarpr::bench
