#include "benchmarks/speed_targets.hpp"

#include <algorithm>

namespace radarpr::bench {
namespace {

using enum TargetMeasure;

// The descriptors' parity presets of the ReFeree paper's code: the journal release (R-ReFeree,
// box kernel, z_q = 3) and the workshop release (Gaussian kernel, z_q = 3); and the defaults.
constexpr SpeedTarget kTargets[] = {
    {"extraction", extraction_over_floor, "referee_r:kernel=box,z_q=3", "400x3360", 0, 3.0,
     "Cen 2018 + R-ReFeree, journal parameters (box kernel, z_q = 3): within 3x the plain pass"},
    {"extraction", extraction_over_floor, "referee:z_q=3", "400x3360", 0, 3.0,
     "Cen 2018 + ReFeree, workshop parameters (Gaussian, z_q = 3): within 3x the plain pass"},
    {"extraction", extraction_over_floor, "referee", "400x3360", 0, 3.0,
     "Cen 2018 + ReFeree, defaults: within 3x the plain pass"},
    {"extraction", extraction_over_floor, "referee_a", "400x3360", 0, 3.0,
     "Cen 2018 + A-ReFeree, defaults: within 3x the plain pass"},
    {"extraction", extraction_over_floor, "referee_r", "400x3360", 0, 3.0,
     "Cen 2018 + R-ReFeree, defaults: within 3x the plain pass"},
    {"extraction", extraction_over_png_decode, "referee", "400x3360", 0, 1.0,
     "Cen 2018 + ReFeree: no slower than decoding the scan's PNG"},
    {"extraction", extraction_milliseconds, "raplace", "400x3360", 0, 3.0,
     "RaPlace extraction: at most 3 ms"},
    {"extraction", extraction_milliseconds, "open_radvlad", "400x3360", 0, 1.5,
     "Open-RadVLAD encoding: at most 1.5 ms"},
    {"retrieval", search_seconds, "referee", "single", 100'000, 2.0,
     "ReFeree search, 10^5 scans, single session, exact top-1: under 2 s"},
    {"retrieval", search_seconds, "referee", "multi", 100'000, 2.0,
     "ReFeree search, 10^5 scans, multi session, exact top-1: under 2 s"},
    {"retrieval", search_seconds, "radar_scan_context", "single", 100'000, 5.0,
     "Radar Scan Context search, 10^5 scans, single session: under 5 s"},
    {"retrieval", search_seconds, "raplace", "single", 100'000, 180.0,
     "RaPlace search, 10^5 scans, single session: under 3 min"},
    {"retrieval", search_within_memory, "open_radvlad", "single", 100'000, 8.0,
     "Open-RadVLAD 32,768-D search, 10^5 scans, single session: runs, values memory-mapped and "
     "the search streamed, within 8 GB of peak memory (time extrapolated from sampled queries)"},
    {"retrieval", search_over_product, "open_radvlad*", "single", 0, 1.2,
     "Open-RadVLAD search, single session: within 1.2x the Eigen product of its shapes"},
    {"retrieval", search_over_product, "open_radvlad*", "multi", 0, 1.2,
     "Open-RadVLAD search, multi session: within 1.2x the Eigen product of its shapes"},
    {"start-up", startup_milliseconds, "", "", 0, 20.0,
     "`radarpr --version`, whole process: at most 20 ms"},
    {"start-up", startup_over_extraction, "referee", "400x3360", 0, 2.0,
     "`radarpr extract referee` on one scan, whole process: within 2x its PNG decode + "
     "extraction"},
};

}  // namespace

std::span<const SpeedTarget> speed_targets() {
  return kTargets;
}

std::vector<std::string> extraction_target_descriptor_ids() {
  std::vector<std::string> ids;
  for (const SpeedTarget& target : kTargets) {
    if (target.part != "extraction" || target.descriptor.ends_with('*')) continue;
    const std::string id(target.descriptor);
    if (std::find(ids.begin(), ids.end(), id) == ids.end()) ids.push_back(id);
  }
  return ids;
}

}  // namespace radarpr::bench
