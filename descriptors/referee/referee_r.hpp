#pragma once

#include <vector>

#include "descriptors/descriptor.hpp"
#include "descriptors/descriptor_registry.hpp"
#include "descriptors/features/cen2018.hpp"
#include "descriptors/features/polar_features.hpp"

namespace radarpr {

// R-ReFeree (journal follow-up, arXiv 2410.01325), descriptors.md §3: free cells per range
// chunk, summed over all azimuths, hence rotation-invariant. Registered as `referee_r`.
enum class RefereeRBinning {
  chunks,     // n = floor(R / window) near-equal chunks, the first R mod n one bin longer
  cpp_quirk,  // the public C++: chunks close on r % window == 0 (see referee_r_chunks)
};
enum class RefereeRMetric {
  l2,      // Euclidean distance
  cosine,  // 1 - cosine similarity, the public C++ (parity only)
};

struct RefereeRParams {
  int window = 80;
  bool normalize = false;  // divide each chunk by A * its length (free-cell share in [0, 1])
  RefereeRBinning binning = RefereeRBinning::chunks;
  RefereeRMetric metric = RefereeRMetric::l2;
  Cen2018Params cen;
};

struct RangeChunk {
  int first = 0;  // first range bin
  int length = 0;
  friend bool operator==(const RangeChunk&, const RangeChunk&) = default;
};

// The range chunks of R bins. `cpp_quirk` reproduces a loop that adds Z_r and then closes the
// chunk whenever r % window == 0: chunk 0 is bin 0 alone, chunk k >= 1 is bins
// (k-1)*window + 1 .. k*window, and the bins after the last multiple of window below R are never
// closed, so they are dropped: 1 + floor((R - 1) / window) chunks (42 for R = 3360, the last 79
// bins dropped; 48 for R = 3768). Throws std::invalid_argument when R < window or window < 1.
std::vector<RangeChunk> referee_r_chunks(int range_bin_count, int window, RefereeRBinning binning);

// The chunk-count x 1 descriptor: v_j = sum over chunk j of Z_r, Z_r = #{a : F[a, r] = 0},
// divided by A * length_j when `normalize`. Only window, normalize and binning are used.
DescriptorValue referee_r_from_features(const PolarFeatures& features,
                                        const RefereeRParams& params);

class RefereeRDescriptor final : public Descriptor {
 public:
  explicit RefereeRDescriptor(RefereeRParams params);

  DescriptorValue extract(const PolarImage& scan) const override;
  // l2: Euclidean. cosine: 1 - cos(a, b) for non-zero vectors; with a zero vector it is
  // 0.5 * |key(a) - key(b)|^2 (0 for two zero vectors, 0.5 for one), the value 1 - cos takes on
  // unit keys, so the KD-tree order over search_key() equals this distance's order everywhere.
  double distance(const DescriptorValue& a, const DescriptorValue& b) const override;
  bool rotation_invariant() const override { return true; }
  // chunk count x 1 (42 x 1 for R = 3360, 47 x 1 for R = 3768 with the default window).
  DescriptorShape shape(const ScanGeometry& geometry) const override;
  // l2: the value. cosine: the value divided by its L2 norm (a zero vector stays zero), whose
  // squared L2 distances are 2 - 2 cos.
  std::vector<float> search_key(const DescriptorValue& value) const override;
  // Both metrics order values as the L2 distance of search_key() does (above).
  RetrievalMethod retrieval_method() const override { return RetrievalMethod::kdtree; }

  const RefereeRParams& params() const { return params_; }

 private:
  RefereeRParams params_;
};

// Registry entry: window (80), normalize (false), binning (chunks|cpp_quirk), metric
// (l2|cosine) plus the shared Cen 2018 parameters.
DescriptorInfo make_referee_r_info();

}  // namespace radarpr
