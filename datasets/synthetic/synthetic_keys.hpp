#pragma once

#include "datasets/dataset_keys.hpp"
#include "datasets/dataset_types.hpp"

namespace radarpr {

// The "synthetic" dataset type: {"type": "synthetic", "world": <preset>, "radar": <preset>, ...}
// (docs/synthetic-world.md, "Config keys"). Every key is bounded so that a typo cannot ask for
// terabytes, and the drive is checked against the world's streets.
SequenceConfig parse_synthetic_keys(DatasetKeys& keys);

}  // namespace radarpr
