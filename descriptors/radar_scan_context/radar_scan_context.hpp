#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "descriptors/descriptor.hpp"
#include "descriptors/descriptor_registry.hpp"

namespace radarpr {

// Radar Scan Context (RadarSC; Kim et al., MulRan, ICRA 2020), descriptors.md §4: the scan's
// power averaged over rings (range) x sectors (azimuth), compared by the best circular column
// shift. Registered as `radar_scan_context`.
// How the scan is shrunk to rings x sectors: radarpr's exact area average, or MATLAB's imresize
// (bicubic with anti-aliasing, descriptors/resampling/matlab_imresize.hpp) as the MulRan
// evaluator's makeExperience.m calls it on the range x azimuth image.
enum class RadarScanContextResize { area, matlab_bicubic };

struct RadarScanContextParams {
  RadarScanContextResize resize = RadarScanContextResize::area;
  // Round the context to 0..255 integers (half away from zero), as MATLAB's imresize of a uint8
  // image does (after each of its two passes when resize = matlab_bicubic).
  bool round_to_uint8 = false;
  int rings = 20;  // the ReFeree paper's 20 x 60; MulRan's evaluator 40 x 120; RadarSC-DS 5 x 10
  int sectors = 60;
  int candidates = 5;  // ring-key neighbours re-ranked by the context distance
};

// The ring key of a rings x sectors context: the mean of each ring (row), rotation-invariant.
// Throws std::invalid_argument when the value is not rows x cols with rows * cols values.
std::vector<float> radar_scan_context_ring_key(const DescriptorValue& context);

class RadarScanContextDescriptor final : public Descriptor {
 public:
  // Throws std::invalid_argument when a parameter is < 1.
  explicit RadarScanContextDescriptor(RadarScanContextParams params);

  // rings x sectors, row-major (row = ring): the A x R scan transposed to range x azimuth and
  // shrunk as params().resize says - area-averaged (area_average_range_by_azimuth), so sector j
  // covers azimuth rows [j A / sectors, (j + 1) A / sectors), or MATLAB's imresize - then
  // rounded when params().round_to_uint8. Throws std::invalid_argument for a scan with fewer
  // range bins than rings or fewer azimuths than sectors.
  DescriptorValue extract(const PolarImage& scan) const override;
  // 1 - max over circular column shifts s of sim(s) (best_column_alignment, query = a), in
  // [0, 2]; 1 when no column pair is non-zero in both contexts for any shift.
  double distance(const DescriptorValue& a, const DescriptorValue& b) const override;
  // The column shift makes it invariant up to the sector width (360 deg / sectors).
  bool rotation_invariant() const override { return true; }
  DescriptorShape shape(const ScanGeometry& /*geometry*/) const override {
    return {params_.rings, params_.sectors};
  }

  RetrievalMethod retrieval_method() const override { return RetrievalMethod::key_then_rerank; }
  std::vector<float> search_key(const DescriptorValue& value) const override;  // the ring key
  std::size_t rerank_candidates() const override {
    return static_cast<std::size_t>(params_.candidates);
  }

  // yaw = 2 pi s / sectors wrapped to (-pi, pi], s the best shift of `query` against `database`
  // (query columns j - s line up with database columns j). Sign, as referee_a: a positive yaw
  // means the query sensor is turned by yaw in the direction of increasing azimuth index
  // relative to the database one - query row a sees what database row a + yaw / (2 pi / A) saw.
  // Quantised to whole sectors. Empty when no column pair qualifies.
  std::optional<double> estimate_yaw(const DescriptorValue& query,
                                     const DescriptorValue& database) const override;

  const RadarScanContextParams& params() const { return params_; }

 private:
  // Throws std::invalid_argument unless `value` is a rings x sectors context.
  void check_context(const DescriptorValue& value, const char* role) const;

  RadarScanContextParams params_;
};

// Registry entry: parity (radarpr|official), resize (auto|area|matlab_bicubic), rounding
// (auto|none|uint8), rings (20), sectors (60), candidates (5). parity=official is the MulRan
// evaluator's makeExperience.m: matlab_bicubic and uint8.
DescriptorInfo make_radar_scan_context_info();

}  // namespace radarpr
