#include "evaluation/descriptor_extraction.hpp"

#include <chrono>
#include <stdexcept>

#include <fmt/format.h>

#include "evaluation/parallel.hpp"
#include "evaluation/progress.hpp"

namespace radarpr {
namespace {

// Listings and result rows report shape(); a value that disagrees (a plugin's bug) would make
// them wrong and retrieval compare unlike things.
void check_declared_shape(const DescriptorInstance& instance, const PolarImage& image,
                          const DescriptorValue& value) {
  const DescriptorShape declared = instance.descriptor->shape(geometry_of(image));
  if (value.rows != declared.rows || value.cols != declared.cols ||
      value.values.size() != declared.element_count()) {
    throw std::runtime_error(fmt::format(
        "descriptor {} returned {}x{} ({} floats) but declares shape {}x{} for a {}x{} scan",
        instance.id, value.rows, value.cols, value.values.size(), declared.rows, declared.cols,
        image.azimuth_count(), image.range_bin_count()));
  }
}

}  // namespace

ExtractedDescriptors extract_descriptors(const ScanSequence& sequence,
                                         const std::vector<DescriptorInstance>& descriptors,
                                         int threads, const std::string& progress_label,
                                         bool show_progress) {
  const std::size_t scans = sequence.size();
  ExtractedDescriptors extracted;
  extracted.values.assign(descriptors.size(), std::vector<DescriptorValue>(scans));
  std::vector<std::vector<double>> seconds(descriptors.size(), std::vector<double>(scans, 0.0));
  Progress progress(progress_label, scans, show_progress);
  parallel_for(scans, threads, [&](std::size_t i) {
    try {
      const PolarImage image = sequence.load_image(i);
      for (std::size_t d = 0; d < descriptors.size(); ++d) {
        const auto start = std::chrono::steady_clock::now();
        DescriptorValue value = descriptors[d].descriptor->extract(image);
        seconds[d][i] =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        check_declared_shape(descriptors[d], image, value);
        extracted.values[d][i] = std::move(value);
      }
    } catch (const std::exception& error) {
      throw std::runtime_error(fmt::format("{}: scan {} ({}): {}", sequence.name(), i,
                                           sequence.records()[i].source, error.what()));
    }
    progress.advance();
  });
  progress.finish();
  for (const auto& per_scan : seconds) {
    double total = 0.0;
    for (double s : per_scan) total += s;
    extracted.mean_extract_ms.push_back(scans == 0 ? 0.0
                                                   : 1000.0 * total / static_cast<double>(scans));
  }
  return extracted;
}

}  // namespace radarpr
