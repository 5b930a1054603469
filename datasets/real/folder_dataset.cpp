#include "datasets/real/folder_dataset.hpp"

#include <stdexcept>

#include <fmt/format.h>

#include "datasets/real/polar_png_sequence.hpp"
#include "datasets/real/real_dataset_keys.hpp"
#include "datasets/real/text_table.hpp"

namespace radarpr {

PoseTrack read_folder_poses(const std::filesystem::path& path) {
  TextTable table(path, TextTable::Separator::comma,
                  "a poses CSV with the header timestamp,x,y[,yaw]");
  table.read_header();
  const std::size_t time = table.column({"timestamp"});
  const std::size_t x = table.column({"x"});
  const std::size_t y = table.column({"y"});
  const auto yaw = table.find_column({"yaw"});
  std::vector<PoseSample> samples;
  while (table.next()) {
    samples.push_back(
        {table.unix_time_ns(time),
         Pose2D{table.number(x), table.number(y), yaw ? wrap_angle(table.number(*yaw)) : 0.0}});
  }
  return PoseTrack(std::move(samples));
}

std::unique_ptr<ScanSequence> open_folder(const FolderOptions& options) {
  const auto& common = options.common;
  const std::string name = sequence_name("folder", common);
  if (!common.range_resolution_m) {
    throw std::invalid_argument(fmt::format(
        "{}: range_resolution_m is required for a folder dataset (metres per range bin)", name));
  }
  if (options.frame == PositionFrame::none) {
    throw std::invalid_argument(fmt::format(
        "{}: the position frame of a folder dataset is global or local; leave poses empty for "
        "none",
        name));
  }
  const std::filesystem::path folder = resolve_sequence_folder(
      common, "a folder dataset root",
      fmt::format("a folder with {}/ (polar PNGs named by time) and {}", options.scans,
                  options.poses.empty() ? "no poses" : options.poses));

  PolarPngSequenceSetup setup;
  setup.type = "folder";
  setup.name = name;
  setup.location = folder;
  setup.scans = list_timestamped_pngs(folder / options.scans,
                                      "polar PNGs named by their Unix time in µs or ns");
  setup.window = common.window;
  setup.decode.range_resolution_m = checked_resolution(*common.range_resolution_m, name);
  setup.decode.layout = options.layout;
  if (!options.poses.empty()) {
    setup.poses = read_folder_poses(folder / options.poses);
    setup.frame = options.frame;
    setup.report.pose_source = options.poses + " (timestamp, x, y[, yaw])";
  } else {
    setup.report.pose_source = "no poses file configured";
  }
  setup.max_pose_gap_s = common.max_pose_gap_s;
  setup.report.layout = fmt::format(
      "{}({}/)", options.layout ? std::string(to_string(*options.layout)) + " " : std::string(),
      options.scans);
  setup.report.resolution_source = "configured";
  setup.report.scan_time_reference =
      "the file name's time (whichever moment of the sweep the data's producer stamped)";
  setup.fingerprint_options = fmt::format("scans={},poses={}", options.scans, options.poses);
  return std::make_unique<PolarPngSequence>(std::move(setup));
}

SequenceConfig parse_folder_keys(DatasetKeys& keys) {
  FolderOptions options;
  options.common = read_real_dataset_keys(keys);
  if (!options.common.range_resolution_m) {
    keys.fail("range_resolution_m",
              "required for a folder dataset (metres per range bin; PNGs do not carry it)");
  }
  options.scans = keys.string_or("scans", options.scans);
  if (options.scans.empty()) keys.fail("scans", "must name the folder of PNGs");
  options.poses = keys.string_or("poses", options.poses);
  const std::string layout = read_choice(keys, "layout", {"auto", "oxford", "mulran_native"});
  if (layout == "oxford") options.layout = PolarPngLayout::oxford;
  if (layout == "mulran_native") options.layout = PolarPngLayout::mulran_native;
  const std::string frame = read_choice(keys, "position_frame", {"global", "local"});
  options.frame = frame == "local" ? PositionFrame::local : PositionFrame::global;
  keys.finish();
  return real_sequence_config("folder", options, &open_folder);
}

}  // namespace radarpr
