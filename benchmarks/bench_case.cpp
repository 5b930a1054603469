#include "benchmarks/bench_case.hpp"

#include "descriptors/extraction_stages.hpp"

namespace radarpr::bench {

std::string_view to_string(CaseKind kind) {
  switch (kind) {
    case CaseKind::floor:
      return "floor";
    case CaseKind::png_decode:
      return "png_decode";
    case CaseKind::extraction:
      return "extraction";
    case CaseKind::stage:
      return "stage";
    case CaseKind::index_build:
      return "index_build";
    case CaseKind::retrieval:
      return "retrieval";
    case CaseKind::matrix_product:
      return "matrix_product";
    case CaseKind::startup:
      return "startup";
    case CaseKind::process_floor:
      return "process_floor";
  }
  return "unknown";
}

std::string_view to_string(Stage stage) {
  switch (stage) {
    case Stage::preparation:
      return kPreparationStage;
    case Stage::features:
      return kFeaturesStage;
    case Stage::descriptor:
      return kDescriptorStage;
  }
  return "unknown";
}

}  // namespace radarpr::bench
