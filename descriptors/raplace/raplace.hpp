#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "descriptors/descriptor.hpp"
#include "descriptors/descriptor_registry.hpp"
#include "descriptors/raplace/circular_correlation.hpp"
#include "descriptors/raplace/raplace_distance.hpp"

namespace radarpr {

// RaPlace (Jang et al., IROS 2023), descriptors.md §5: polar scan -> Cartesian image -> Radon
// sinogram -> |DFT along rho| -> z-score; compared by the best circular shift along theta.
// Registered as `raplace`.
// The Radon transform: radarpr's one point per pixel on ceil(diagonal) rho bins
// (radon_transform.hpp), or MATLAB's radon (2 x 2 sub-pixels, 2 L + 1 integer rho bins about its
// own centre; matlab_radon.hpp) as the public code calls it.
enum class RaplaceRadon { point_per_pixel, matlab };
// The sinogram's shrink: area averaging (cv::INTER_AREA) or MATLAB's imresize (bicubic,
// anti-aliased, symmetric padding; descriptors/resampling/matlab_imresize.hpp).
enum class RaplaceShrink { area, matlab_bicubic };

struct RaplaceParams {
  RaplaceRadon radon = RaplaceRadon::point_per_pixel;
  RaplaceShrink shrink = RaplaceShrink::area;
  // Round the Cartesian image to 0..255 integers, as the public code reads it from an 8-bit PNG.
  bool cart_uint8 = false;
  int cart_size = 280;        // Cartesian image side, pixels
  double cart_range_m = 0.0;  // half the image side in metres; 0 = the scan's R x resolution
  double resize = 0.1;        // sinogram shrink factor per axis (unless overridden below)
  int sinogram_rows = 0;      // rho rows after the shrink; 0 = round(n_rho x resize)
  int sinogram_cols = 0;      // theta columns after the shrink; 0 = round(180 x resize)
  raplace::ShiftAxis shift_axis = raplace::ShiftAxis::theta;
  RaplaceDistance distance = RaplaceDistance::normalized;
};

// Every size along the pipeline; a function of the parameters only.
struct RaplaceSizes {
  int rho_bins = 0;            // n_rho: ceil(cart_size x sqrt 2) (396), MATLAB's radon 399
  int sinogram_rows = 0;       // after the shrink (40; MATLAB's imresize: ceil(n_rho x resize))
  int sinogram_cols = 0;       // after the shrink (18)
  DescriptorShape descriptor;  // floor(sinogram_rows / 2) x sinogram_cols (20 x 18)
};

// Throws ParameterError (naming the parameter) when the shrunk sinogram would have fewer than 2
// rho rows or 1 theta column, or more than the sinogram has (n_rho, 180).
RaplaceSizes raplace_sizes(const RaplaceParams& params);

class RaplaceDescriptor final : public Descriptor {
 public:
  explicit RaplaceDescriptor(RaplaceParams params);  // throws like raplace_sizes

  // Throws std::invalid_argument for a scan polar_to_cartesian refuses.
  DescriptorValue extract(const PolarImage& scan) const override;
  // distance(query, database) as `params().distance` says; not symmetric (the query's C(Dq,Dq)
  // sets the scale). For z-scored values, normalized lies in [0, 2] and is 0 for a value and any
  // whole-column theta shift of it. Throws std::invalid_argument unless both values have this
  // descriptor's shape.
  double distance(const DescriptorValue& query, const DescriptorValue& database) const override;
  // C(Dq, Di), the best circular-shift correlation, and the shift achieving it (see
  // raplace::CircularCorrelation for the shift's direction).
  raplace::CorrelationPeak similarity(const DescriptorValue& query,
                                      const DescriptorValue& database) const;

  // Shifting along theta is a rotation of the sensor; shifting along rho frequencies is not.
  bool rotation_invariant() const override {
    return params_.shift_axis == raplace::ShiftAxis::theta;
  }
  DescriptorShape shape(const ScanGeometry& /*geometry*/) const override {
    return sizes_.descriptor;
  }
  RetrievalMethod retrieval_method() const override { return RetrievalMethod::exhaustive; }
  std::unique_ptr<PreparedDistances> prepare_distances(
      const std::vector<DescriptorValue>& queries,
      const std::vector<DescriptorValue>& database) const override;

  // Not offered (always empty). A sinogram over theta = 0..179 degrees is only pi-periodic: a
  // turn by pi maps every projection onto itself with rho mirrored, and |DFT along rho| erases
  // the mirror. So the best theta shift fixes the heading only modulo pi, and a value in
  // (-pi, pi], as this interface promises, would be off by pi on every reverse revisit. The
  // modulo-pi estimate is yaw_modulo_pi().
  std::optional<double> estimate_yaw(const DescriptorValue& /*query*/,
                                     const DescriptorValue& /*database*/) const override {
    return std::nullopt;
  }
  // The heading of `query` relative to `database` modulo pi, in (-pi/2, pi/2]: s pi / cols for
  // the best theta shift s, a resolution of 180 / cols degrees (10 at the defaults). The true
  // heading is this or this + pi. Sign as referee_a: a positive yaw means query row a sees what
  // database row a + yaw / (2 pi / A) saw. Empty for shift_axis = rho (no rotation information)
  // or when either value is all zero.
  std::optional<double> yaw_modulo_pi(const DescriptorValue& query,
                                      const DescriptorValue& database) const;

  const RaplaceParams& params() const { return params_; }
  const RaplaceSizes& sizes() const { return sizes_; }

 private:
  void check_shape(const DescriptorValue& value, const char* role) const;

  RaplaceParams params_;
  RaplaceSizes sizes_;
  raplace::CircularCorrelation correlation_;
};

// Registry entry: parity (radarpr|official), radon (auto|point_per_pixel|matlab), shrink
// (auto|area|matlab_bicubic), cart_rounding (auto|none|uint8), cart_size (280), cart_range_m (0),
// resize (0.1), sinogram_rows (0), sinogram_cols (0), shift_axis (auto|theta|rho), distance
// (auto|normalized|raw_over_1000). parity=official is the public MATLAB code (generateRadon.m,
// fast_dft.m, main.m): matlab, matlab_bicubic, uint8, rho, raw_over_1000.
DescriptorInfo make_raplace_info();

}  // namespace radarpr
