#include "evaluation/descriptor_extraction.hpp"

#include <chrono>
#include <stdexcept>

#include <fmt/format.h>

#include "evaluation/parallel.hpp"
#include "evaluation/progress.hpp"

namespace radarpr {

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
        extracted.values[d][i] = descriptors[d].descriptor->extract(image);
        seconds[d][i] =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
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
