#include "datasets/dataset_types.hpp"

#include <fmt/format.h>

#include "datasets/real/boreas_dataset.hpp"
#include "datasets/real/folder_dataset.hpp"
#include "datasets/real/mulran_dataset.hpp"
#include "datasets/real/oord_dataset.hpp"
#include "datasets/real/oxford_dataset.hpp"
#include "datasets/real/radiate_dataset.hpp"
#include "datasets/synthetic/synthetic_keys.hpp"

namespace radarpr {

const std::vector<DatasetType>& dataset_types() {
  static const std::vector<DatasetType> types = {
      {"synthetic", &parse_synthetic_keys},  // docs/synthetic-world.md
      {"mulran", &parse_mulran_keys},        // the rest: docs/datasets.md
      {"oxford", &parse_oxford_keys},       {"boreas", &parse_boreas_keys},
      {"oord", &parse_oord_keys},           {"radiate", &parse_radiate_keys},
      {"folder", &parse_folder_keys},
  };
  return types;
}

SequenceConfig parse_sequence_keys(DatasetKeys& keys) {
  const std::string type = keys.required_string("type");
  std::vector<std::string> names;
  for (const DatasetType& row : dataset_types()) {
    if (row.name == type) return row.parse(keys);
    names.push_back(row.name);
  }
  keys.fail("type",
            fmt::format("unknown sequence type '{}' (known: {})", type, fmt::join(names, ", ")));
}

}  // namespace radarpr
