// An out-of-tree descriptor plugin built on radarpr's own building blocks: a ReFeree variant.
//
// ReFeree (the built-in `referee`) measures, per azimuth, the free cells before the *farthest*
// Cen 2018 feature, averaged over `alpha` blocks of azimuths. This variant measures the free
// cells before the *nearest* feature instead: the open space right around the vehicle. It takes
// the Cen 2018 feature extractor, the parameters every Cen-based descriptor shares, the block
// averaging, the scan check, the L2 distance and the two timed stages from the installed
// radarpr::plugin_api (descriptors/features/cen2018_parameters.hpp and
// descriptors/referee/referee_common.hpp), so only the per-azimuth rule below is its own.
#include <memory>
#include <span>

#include <descriptors/features/cen2018_parameters.hpp>
#include <descriptors/plugins/plugin.hpp>
#include <descriptors/referee/referee_common.hpp>

namespace referee_nearest {

using radarpr::DescriptorValue;
using radarpr::PolarFeatures;

// alpha x 1: per block, the mean over its azimuths of (cells before the nearest feature) / R;
// an azimuth without a feature counts 0, as in ReFeree.
DescriptorValue from_features(const PolarFeatures& features, int alpha) {
  return radarpr::azimuth_block_profile(
      features, alpha,
      [](std::span<const int> bins) -> double { return bins.empty() ? 0.0 : bins.front(); },
      "referee_nearest");
}

class RefereeNearest final : public radarpr::Descriptor {
 public:
  RefereeNearest(int alpha, radarpr::Cen2018Params cen) : alpha_(alpha), cen_(cen) {
    radarpr::cen2018_kernel(cen_);  // a bad sigma is refused now, not on the first scan
  }

  DescriptorValue extract(const radarpr::PolarImage& scan) const override {
    radarpr::check_polar_scan(scan, "referee_nearest");
    return from_features(radarpr::extract_cen2018_features(scan, cen_), alpha_);
  }

  double distance(const DescriptorValue& a, const DescriptorValue& b) const override {
    return radarpr::l2_distance(a, b, "referee_nearest");
  }

  // L2 between the values: what a KD-tree searches exactly.
  radarpr::RetrievalMethod retrieval_method() const override {
    return radarpr::RetrievalMethod::kdtree;
  }
  bool rotation_invariant() const override { return false; }
  radarpr::DescriptorShape shape(const radarpr::ScanGeometry& /*geometry*/) const override {
    return {alpha_, 1};
  }

  int alpha() const { return alpha_; }
  const radarpr::Cen2018Params& cen() const { return cen_; }

 private:
  int alpha_;
  radarpr::Cen2018Params cen_;
};

radarpr::DescriptorInfo make_referee_nearest_info() {
  radarpr::DescriptorInfo info;
  info.name = "referee_nearest";
  info.summary =
      "Example plugin: ReFeree measured to the nearest Cen 2018 feature of each azimuth instead "
      "of the farthest";
  // alpha and the Cen 2018 parameters under the names and defaults `referee` uses.
  info.parameters = radarpr::with_cen2018_parameters({radarpr::alpha_parameter_spec()});
  info.create = [](const radarpr::ParameterValues& values) -> std::unique_ptr<radarpr::Descriptor> {
    return std::make_unique<RefereeNearest>(static_cast<int>(values.integer("alpha")),
                                            radarpr::cen2018_params_from(values));
  };
  // `radarpr bench` times the features and the block profile apart, as for `referee`.
  info.stages = [](const radarpr::Descriptor& descriptor, const radarpr::PolarImage& scan) {
    const auto& self = dynamic_cast<const RefereeNearest&>(descriptor);
    return radarpr::cen2018_then_descriptor_stages(
        self.cen(), scan,
        [alpha = self.alpha()](const PolarFeatures& features) {
          return from_features(features, alpha);
        },
        "the nearest-feature block profile");
  };
  return info;
}

void register_referee_nearest(radarpr::DescriptorRegistry& registry) {
  registry.add(make_referee_nearest_info());
}

}  // namespace referee_nearest

RADARPR_PLUGIN(referee_nearest::register_referee_nearest);
