#include "descriptors/open_radvlad/open_radvlad.hpp"

#include <cmath>
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>

#include "descriptors/open_radvlad/codebook_file.hpp"
#include "descriptors/open_radvlad/codebook_state.hpp"
#include "descriptors/open_radvlad/kmeans.hpp"
#include "descriptors/open_radvlad/training_rows.hpp"
#include "descriptors/open_radvlad/vlad.hpp"
#include "descriptors/parity_preset.hpp"

namespace radarpr {

OpenRadVladDescriptor::OpenRadVladDescriptor(OpenRadVladParams params) : params_(params) {
  validate(params_.spectra);
  if (params_.clusters < 1) {
    throw std::invalid_argument("open_radvlad: clusters must be >= 1, got " +
                                std::to_string(params_.clusters));
  }
  if (params_.max_iterations < 1) {
    throw std::invalid_argument("open_radvlad: max_iterations must be >= 1, got " +
                                std::to_string(params_.max_iterations));
  }
  if (params_.max_training_rows != 0 &&
      params_.max_training_rows < static_cast<std::size_t>(params_.clusters)) {
    throw std::invalid_argument(
        "open_radvlad: max_training_rows (" + std::to_string(params_.max_training_rows) +
        ") must be 0 (all rows) or at least clusters (" + std::to_string(params_.clusters) + ")");
  }
  if (!params_.codebook_file.empty() && !params_.save_codebook_file.empty()) {
    throw std::invalid_argument(
        "open_radvlad: codebook (load a codebook) and save_codebook (save the trained one) "
        "exclude each other: a loaded codebook is not trained");
  }
  if (!params_.codebook_file.empty()) {
    codebook_ = read_codebook(params_.codebook_file, params_.clusters, params_.spectra.bin_dim);
    codebook_hash_ = radarpr::codebook_sha256(codebook_);
  }
}

DescriptorValue OpenRadVladDescriptor::extract(const PolarImage& scan) const {
  if (!is_trained()) {
    throw std::logic_error(
        "open_radvlad is not trained: it builds its codebook from training scans; radarpr run "
        "trains it on the database session (library callers: call train() before extract())");
  }
  const DescriptorShape value_shape = shape(geometry_of(scan));
  return {value_shape.rows, value_shape.cols,
          vlad_vector(azimuth_spectra(scan, params_.spectra), codebook_)};
}

double OpenRadVladDescriptor::distance(const DescriptorValue& a, const DescriptorValue& b) const {
  if (a.values.size() != b.values.size() || a.rows != b.rows || a.cols != b.cols) {
    throw std::invalid_argument("open_radvlad: cannot compare a " + std::to_string(a.rows) + " x " +
                                std::to_string(a.cols) + " descriptor with a " +
                                std::to_string(b.rows) + " x " + std::to_string(b.cols) + " one");
  }
  double sum = 0.0;
  for (std::size_t i = 0; i < a.values.size(); ++i) {
    const double d = static_cast<double>(a.values[i]) - b.values[i];
    sum += d * d;
  }
  return std::sqrt(sum);
}

DescriptorShape OpenRadVladDescriptor::shape(const ScanGeometry& /*geometry*/) const {
  // The resampling to bin_dim makes the shape independent of the scan's range bins.
  return {params_.clusters * params_.spectra.bin_dim, 1};
}

void OpenRadVladDescriptor::train(const TrainingScans& scans) {
  if (!trainable()) {
    throw std::logic_error("open_radvlad: the codebook was loaded from " + params_.codebook_file +
                           "; it is not trained");
  }
  const TrainingRows collected =
      collect_training_rows(scans, params_.spectra, params_.max_training_rows, params_.seed);
  const auto rows = static_cast<std::size_t>(collected.rows.rows);
  if (rows < static_cast<std::size_t>(params_.clusters)) {
    throw std::invalid_argument("open_radvlad: cannot train " + std::to_string(params_.clusters) +
                                " clusters on " + scans.description() + ": its " +
                                std::to_string(collected.scans_used) + " scans hold only " +
                                std::to_string(rows) + " azimuth rows");
  }
  KMeansResult result = kmeans(collected.rows, {.clusters = params_.clusters,
                                                .seed = params_.seed,
                                                .max_iterations = params_.max_iterations,
                                                .seeding = params_.seeding,
                                                .relative_tolerance = params_.relative_tolerance});
  if (!params_.save_codebook_file.empty())
    write_codebook(params_.save_codebook_file, result.centres);
  codebook_ = result.centres;
  codebook_hash_ = radarpr::codebook_sha256(codebook_);
  training_ = {.scans_used = collected.scans_used,
               .rows = rows,
               .iterations = result.iterations,
               .converged = result.converged};
}

std::string OpenRadVladDescriptor::save_training() const {
  if (!is_trained()) throw std::logic_error("open_radvlad: nothing to save before train()");
  return encode_codebook_state(codebook_);
}

void OpenRadVladDescriptor::load_training(std::string_view bytes) {
  codebook_ = decode_codebook_state(bytes, params_.clusters, params_.spectra.bin_dim);
  codebook_hash_ = radarpr::codebook_sha256(codebook_);
  training_ = {};
}

DescriptorInfo make_open_radvlad_info() {
  const OpenRadVladParams defaults;
  const auto integer = [](std::string name, std::int64_t value, std::string description,
                          double minimum, double maximum) {
    return ParameterSpec{.name = std::move(name),
                         .kind = ParameterKind::integer,
                         .default_value = value,
                         .description = std::move(description),
                         .minimum = minimum,
                         .maximum = maximum};
  };
  return DescriptorInfo{
      "open_radvlad",
      "Open-RadVLAD: VLAD of per-azimuth range spectra over a k-means codebook (trainable)",
      {
          parity_parameter("the public code, mttgdd/open-radvlad src/: resize=pillow_bicubic, "
                           "kmeans=sklearn"),
          {.name = "resize",
           .kind = ParameterKind::choice,
           .default_value = std::string("auto"),
           .description = "range resampling to bin_dim: area (radarpr) or pillow_bicubic "
                          "(Pillow's default resize; official)",
           .choices = {"auto", "area", "pillow_bicubic"}},
          {.name = "kmeans",
           .kind = ParameterKind::choice,
           .default_value = std::string("auto"),
           .description = "capped (k-means++, max_iterations Lloyd steps; radarpr) or sklearn "
                          "(scikit-learn's KMeans: greedy k-means++, to its tolerance; official)",
           .choices = {"auto", "capped", "sklearn"}},
          integer("min_bin", defaults.spectra.min_bin, "range bins r < min_bin are zeroed", 0.0,
                  100000.0),
          integer("max_bin", defaults.spectra.max_bin,
                  "crop to the first min(max_bin, R) range bins; 0 = all R (the paper: 3768)", 0.0,
                  100000.0),
          integer("bin_dim", defaults.spectra.bin_dim,
                  "range bins after area resampling = spectrum length (RadVLAD-DS: 10)", 1.0,
                  8192.0),
          integer("clusters", defaults.clusters, "k-means codebook size", 1.0, 4096.0),
          integer("seed", static_cast<std::int64_t>(defaults.seed),
                  "seed of the k-means++ seeding and of the training-row sample", 0.0,
                  4294967295.0),
          integer("max_iterations", 0,
                  "Lloyd iterations cap (stops earlier when no assignment changes); 0 = 20 for "
                  "kmeans=capped, 300 (scikit-learn's) for sklearn",
                  0.0, 100000.0),
          {.name = "codebook",
           .kind = ParameterKind::text,
           .default_value = std::string(),
           .description = "a codebook file to use instead of training: .npy, clusters x bin_dim "
                          "float32 (or float64), as save_codebook writes; empty = train"},
          {.name = "save_codebook",
           .kind = ParameterKind::text,
           .default_value = std::string(),
           .description = "write the trained codebook to this .npy (clusters x bin_dim float32); "
                          "a later run loads it with codebook="},
          integer("max_training_rows", static_cast<std::int64_t>(defaults.max_training_rows),
                  "cap on the azimuth rows k-means learns from: more are sampled by whole "
                  "scans with `seed`; 0 = all rows (the spec, the default)",
                  0.0, 1.0e9),
      },
      [](const ParameterValues& values) -> std::unique_ptr<Descriptor> {
        OpenRadVladParams params;
        params.spectra.resize =
            preset_choice(values, "resize", "area", "pillow_bicubic") == "pillow_bicubic"
                ? AzimuthResize::pillow_bicubic
                : AzimuthResize::area;
        const bool sklearn = preset_choice(values, "kmeans", "capped", "sklearn") == "sklearn";
        if (sklearn) {
          params.seeding = KMeansSeeding::greedy;
          params.relative_tolerance = 1e-4;
          params.max_iterations = 300;
        }
        params.spectra.min_bin = static_cast<int>(values.integer("min_bin"));
        params.spectra.max_bin = static_cast<int>(values.integer("max_bin"));
        params.spectra.bin_dim = static_cast<int>(values.integer("bin_dim"));
        params.clusters = static_cast<int>(values.integer("clusters"));
        params.seed = static_cast<std::uint64_t>(values.integer("seed"));
        if (values.integer("max_iterations") > 0) {
          params.max_iterations = static_cast<int>(values.integer("max_iterations"));
        }
        params.max_training_rows = static_cast<std::size_t>(values.integer("max_training_rows"));
        params.codebook_file = values.text("codebook");
        params.save_codebook_file = values.text("save_codebook");
        return std::make_unique<OpenRadVladDescriptor>(params);
      },
      [](const Descriptor& descriptor, const PolarImage& scan) {
        const AzimuthSpectraParams spectra =
            dynamic_cast<const OpenRadVladDescriptor&>(descriptor).params().spectra;
        return std::vector<ExtractionStage>{{std::string(kPreparationStage),
                                             "the per-azimuth range spectra (azimuth_spectra)",
                                             [spectra, &scan] { azimuth_spectra(scan, spectra); }}};
      }};
}

RADARPR_REGISTER_DESCRIPTOR(open_radvlad, make_open_radvlad_info)

}  // namespace radarpr
