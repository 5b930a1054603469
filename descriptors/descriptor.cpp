#include "descriptors/descriptor.hpp"

#include <stdexcept>

namespace radarpr {
namespace {

class PairwiseDistances final : public PreparedDistances {
 public:
  PairwiseDistances(const Descriptor& descriptor, const std::vector<DescriptorValue>& queries,
                    const std::vector<DescriptorValue>& database)
      : descriptor_(descriptor), queries_(queries), database_(database) {}

  double distance(std::size_t query, std::size_t database_index) const override {
    return descriptor_.distance(queries_[query], database_[database_index]);
  }

 private:
  const Descriptor& descriptor_;
  const std::vector<DescriptorValue>& queries_;
  const std::vector<DescriptorValue>& database_;
};

}  // namespace

ScanGeometry geometry_of(const PolarImage& scan) {
  return {scan.azimuth_count(), scan.range_bin_count(), scan.range_resolution_m};
}

std::unique_ptr<PreparedDistances> Descriptor::prepare_distances(
    const std::vector<DescriptorValue>& queries,
    const std::vector<DescriptorValue>& database) const {
  return std::make_unique<PairwiseDistances>(*this, queries, database);
}

void Descriptor::train(const TrainingScans& /*scans*/) {
  throw std::logic_error("this descriptor is not trainable");
}

std::string Descriptor::save_training() const {
  throw std::logic_error("this descriptor cannot save what it learnt");
}

void Descriptor::load_training(std::string_view /*bytes*/) {
  throw std::logic_error("this descriptor cannot load a training state");
}

}  // namespace radarpr
