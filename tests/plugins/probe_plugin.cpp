// A tiny descriptor plugin for the loader tests, compiled into several MODULE targets: its name
// (PROBE_DESCRIPTOR_NAME) and, for the mismatch tests, the version and ABI it declares
// (RADARPR_PLUGIN_DECLARED_*) come from compile definitions (tests/plugins/CMakeLists.txt).
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>

#include "descriptors/plugins/plugin.hpp"

#ifndef PROBE_DESCRIPTOR_NAME
#error "PROBE_DESCRIPTOR_NAME names the probe's descriptor"
#endif

namespace probe {

// The scan's mean intensity, so that its values are checkable by hand; `fail` makes extract throw,
// to check that exceptions cross from the plugin to the host as their own types.
class MeanIntensity final : public radarpr::Descriptor {
 public:
  explicit MeanIntensity(std::string fail) : fail_(std::move(fail)) {}

  radarpr::DescriptorValue extract(const radarpr::PolarImage& scan) const override {
    if (fail_ == "invalid_argument") throw std::invalid_argument("probe: extract asked to fail");
    if (fail_ == "parameter_error") throw radarpr::ParameterError("fail", "probe: asked to fail");
    double sum = 0.0;
    for (int a = 0; a < scan.power.rows(); ++a) {
      const std::uint8_t* row = scan.power.row(a);
      for (int r = 0; r < scan.power.cols(); ++r) sum += row[r];
    }
    const double cells = static_cast<double>(scan.power.rows()) * scan.power.cols();
    return {1, 1, {static_cast<float>(cells > 0 ? sum / cells : 0.0)}};
  }
  double distance(const radarpr::DescriptorValue& a,
                  const radarpr::DescriptorValue& b) const override {
    const double difference = static_cast<double>(a.values.at(0)) - b.values.at(0);
    return difference < 0 ? -difference : difference;
  }
  bool rotation_invariant() const override { return true; }
  radarpr::DescriptorShape shape(const radarpr::ScanGeometry& /*geometry*/) const override {
    return {1, 1};
  }

 private:
  std::string fail_;
};

void register_probe(radarpr::DescriptorRegistry& registry) {
  radarpr::DescriptorInfo info;
  info.name = PROBE_DESCRIPTOR_NAME;
  info.summary = "Test plugin: the mean intensity of the scan";
  info.parameters = {{.name = "fail",
                      .kind = radarpr::ParameterKind::choice,
                      .default_value = std::string("none"),
                      .description = "make extract throw this",
                      .choices = {"none", "invalid_argument", "parameter_error"}}};
  info.create = [](const radarpr::ParameterValues& values) {
    return std::make_unique<MeanIntensity>(values.choice("fail"));
  };
  registry.add(std::move(info));
}

}  // namespace probe

RADARPR_PLUGIN(probe::register_probe);
