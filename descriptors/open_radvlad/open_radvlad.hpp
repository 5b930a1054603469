#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

#include <opencv2/core/mat.hpp>

#include "descriptors/descriptor.hpp"
#include "descriptors/descriptor_registry.hpp"
#include "descriptors/learnt_codebook.hpp"
#include "descriptors/open_radvlad/azimuth_spectra.hpp"
#include "descriptors/open_radvlad/kmeans.hpp"

namespace radarpr {

// Open-RadVLAD (Gadd & Newman, 2024), descriptors.md §6: VLAD over per-azimuth range spectra,
// with a k-means codebook learnt from training scans. Registered as `open_radvlad`; the one
// trainable descriptor.
struct OpenRadVladParams {
  AzimuthSpectraParams spectra;  // min_bin 60, max_bin 0 (= R), bin_dim 512
  int clusters = 64;
  std::uint64_t seed = 42;  // k-means++ seeding and the training-row sample
  // Lloyd iterations cap; Lloyd stops earlier when no assignment changes. Measured on the
  // synthetic 600-scan sequence (240,000 rows, 512 dims, 64 clusters, Release, one core): about
  // 0.38 s of CPU per iteration (docs/cluster.md, the 30-session cost), and the mean squared
  // residual after 20 iterations is within 0.3% of the one after 40, while full convergence takes
  // well over 40.
  int max_iterations = 20;
  // k-means seeding and stopping: radarpr's plain k-means++ and the cap above, or scikit-learn's
  // KMeans as the public code calls it (greedy k-means++, up to 300 iterations, stopping at its
  // tolerance 1e-4 relative to the mean feature variance).
  KMeansSeeding seeding = KMeansSeeding::plain;
  double relative_tolerance = 0.0;
  // Cap on the azimuth rows k-means sees; 0 = all rows, as the spec says (the default). Rows
  // take bin_dim floats each (2 KB at 512): a 600-scan sequence (240,000 rows) trains in about
  // 23 s and 0.5 GB, an 8,000-scan recorded sequence needs about 6.5 GB; a cap samples whole scans
  // with `seed` instead (see collect_training_rows).
  std::size_t max_training_rows = 0;
  // A codebook file (.npy, clusters x bin_dim) to use instead of training; empty = train.
  std::string codebook_file;
  // Where train() writes the codebook it learnt (.npy float32); empty = nowhere.
  std::string save_codebook_file;
};

// What the last successful train() did, for logs and measurements.
struct OpenRadVladTraining {
  std::size_t scans_used = 0;
  std::size_t rows = 0;
  int iterations = 0;
  bool converged = false;
};

class OpenRadVladDescriptor final : public Descriptor, public LearntCodebook {
 public:
  // Throws std::invalid_argument for a bad parameter, or when codebook_file cannot be read as a
  // clusters x bin_dim codebook (naming the file).
  explicit OpenRadVladDescriptor(OpenRadVladParams params);

  // clusters * bin_dim x 1. Throws std::logic_error before train().
  DescriptorValue extract(const PolarImage& scan) const override;
  double distance(const DescriptorValue& a, const DescriptorValue& b) const override;  // L2
  bool rotation_invariant() const override { return true; }  // orderless over azimuths
  DescriptorShape shape(const ScanGeometry& geometry) const override;
  RetrievalMethod retrieval_method() const override { return RetrievalMethod::exhaustive_l2; }

  // A loaded codebook needs no training.
  bool trainable() const override { return params_.codebook_file.empty(); }
  bool is_trained() const override { return !codebook_.empty(); }
  // Learns the codebook from the scans' azimuth spectra (k-means), then writes it to
  // save_codebook_file when set. Throws std::invalid_argument naming scans.description() when
  // they hold fewer rows than clusters or an unusable scan, or naming the file when it cannot be
  // written; a failed train() leaves the descriptor as it was. Deterministic for a given seed and
  // scans. std::logic_error when the codebook was loaded from a file.
  void train(const TrainingScans& scans) override;
  // The codebook (codebook_state.hpp); a loaded one has no OpenRadVladTraining record.
  bool saves_training() const override { return true; }
  std::string save_training() const override;
  void load_training(std::string_view bytes) override;

  std::string codebook_sha256() const override { return codebook_hash_; }
  std::string codebook_loaded_from() const override { return params_.codebook_file; }
  std::string codebook_saved_to() const override { return params_.save_codebook_file; }

  const OpenRadVladParams& params() const { return params_; }
  // clusters x bin_dim CV_32FC1, empty until trained.
  const cv::Mat& codebook() const { return codebook_; }
  const OpenRadVladTraining& training() const { return training_; }

 private:
  OpenRadVladParams params_;
  cv::Mat codebook_;
  std::string codebook_hash_;
  OpenRadVladTraining training_;
};

// Registry entry: parity (radarpr|official), resize (auto|area|pillow_bicubic), kmeans
// (auto|capped|sklearn), min_bin, max_bin, bin_dim, clusters, seed, max_iterations (0 = as the
// preset: 20, or 300 for sklearn), max_training_rows, codebook (a .npy to load instead of
// training), save_codebook (a .npy the trained codebook is written to). parity=official is the
// public code (mttgdd/open-radvlad src/): pillow_bicubic and sklearn.
DescriptorInfo make_open_radvlad_info();

}  // namespace radarpr
