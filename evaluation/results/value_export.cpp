#include "evaluation/results/value_export.hpp"

#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>

#include <fmt/format.h>

#include "datasets/npy_file.hpp"
#include "evaluation/descriptor_cache.hpp"
#include "evaluation/descriptor_values.hpp"
#include "evaluation/results/results_writer.hpp"

namespace radarpr {
namespace {

namespace fs = std::filesystem;

void write_session(const fs::path& folder, const std::vector<ScanRecord>& records,
                   const std::vector<DescriptorInstance>& instances,
                   const std::vector<SessionValues>& sessions, std::vector<fs::path>& written) {
  fs::create_directories(folder);
  std::vector<std::int64_t> times;
  std::vector<double> positions;
  for (const ScanRecord& record : records) {
    times.push_back(record.timestamp_ns);
    positions.insert(positions.end(), {record.pose.x, record.pose.y, record.pose.yaw});
  }
  write_npy(folder / "timestamps.npy", {times.size()}, std::span<const std::int64_t>(times));
  written.push_back(folder / "timestamps.npy");
  write_npy(folder / "positions.npy", {records.size(), 3}, std::span<const double>(positions));
  written.push_back(folder / "positions.npy");
  for (std::size_t d = 0; d < instances.size(); ++d) {
    const std::vector<DescriptorValue>& values = sessions[d].values;
    const std::size_t width = values.empty() ? 0 : values.front().values.size();
    std::vector<float> flat;
    flat.reserve(values.size() * width);
    for (const DescriptorValue& value : values) {
      flat.insert(flat.end(), value.values.begin(), value.values.end());
    }
    const fs::path path = folder / (descriptor_folder_name(instances[d].id) + ".npy");
    write_npy(path, {values.size(), width}, std::span<const float>(flat));
    written.push_back(path);
  }
}

}  // namespace

std::vector<fs::path> export_descriptor_values(const ExperimentConfig& config, const fs::path& out,
                                               bool show_progress) {
  std::vector<fs::path> written;
  const DescriptorCache cache = DescriptorCache::from_environment();
  for (const DatasetConfig& dataset : config.datasets) {
    const std::unique_ptr<ScanSequence> query = open_sequence(dataset.query);
    const std::unique_ptr<ScanSequence> database =
        dataset.database ? open_sequence(*dataset.database) : nullptr;
    const DatasetValues values =
        obtain_dataset_values(config, dataset, *query, database.get(), cache, show_progress);
    write_session(out / dataset.name / "query", query->records(), values.instances, values.query,
                  written);
    if (database) {
      write_session(out / dataset.name / "database", database->records(), values.instances,
                    values.database, written);
    }
  }
  return written;
}

}  // namespace radarpr
