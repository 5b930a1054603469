#pragma once

#include <memory>

#include "datasets/scan_sequence.hpp"
#include "datasets/synthetic/synthetic_sequence.hpp"

namespace radarpr {

// A synthetic sequence as a run reads it, through the same decoder and loader as real data:
// - with a cache directory (datasets/cache_directory.hpp), each scan is rendered once, written
//   in the layout `radarpr simulate` writes (<cache>/synthetic/<key>/scans/<t_us>.png in the
//   Oxford layout, poses.csv) and decoded from that file; once every scan of the sequence is
//   there, later runs open the folder with the `folder` loader and render nothing;
// - without one (--no-cache), each scan is rendered and passed through the Oxford layout in
//   memory.
// Either way the pixels, azimuth times and angles are the same, and the name and fingerprint are
// the generator's (a cache folder is keyed by that fingerprint, so a changed config or generator
// version never reads stale scans). A cached scan that cannot be read is rendered again, and a
// cache that cannot be written costs the cache, not the run.
std::unique_ptr<ScanSequence> open_synthetic(const SyntheticConfig& config);

}  // namespace radarpr
