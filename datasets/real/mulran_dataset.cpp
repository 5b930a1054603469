#include "datasets/real/mulran_dataset.hpp"

#include <cmath>
#include <system_error>

#include <fmt/format.h>

#include "datasets/real/polar_png_sequence.hpp"
#include "datasets/real/real_dataset_keys.hpp"
#include "datasets/real/text_table.hpp"

namespace radarpr {

PoseTrack read_mulran_global_pose(const std::filesystem::path& path) {
  TextTable table(path, TextTable::Separator::comma,
                  "MulRan's global_pose.csv (t_ns then a row-major 3x4 [R|t] per line)");
  std::vector<PoseSample> samples;
  while (table.next()) {
    table.require_fields(13);
    // Row: t, R00 R01 R02 tx, R10 R11 R12 ty, R20 R21 R22 tz.
    const double r00 = table.number(1);
    const double r10 = table.number(5);
    samples.push_back(
        {table.unix_time_ns(0), Pose2D{table.number(4), table.number(8), std::atan2(r10, r00)}});
  }
  return PoseTrack(std::move(samples));
}

std::unique_ptr<ScanSequence> open_mulran(const MulranOptions& options) {
  const auto& common = options.common;
  const std::filesystem::path folder =
      resolve_sequence_folder(common, "a MulRan copy (holding DCC01/, KAIST03/, ...)",
                              "a MulRan sequence with sensor_data/radar/polar/ and "
                              "global_pose.csv");
  const std::filesystem::path radar = folder / "sensor_data" / "radar";
  std::error_code error;
  bool oxford_form = options.folder == MulranPolarFolder::polar_oxford_form;
  if (options.folder == MulranPolarFolder::automatic) {
    oxford_form = !std::filesystem::is_directory(radar / "polar", error) &&
                  std::filesystem::is_directory(radar / "polar_oxford_form", error);
  }
  const std::string subfolder = oxford_form ? "polar_oxford_form" : "polar";

  PolarPngSequenceSetup setup;
  setup.type = "mulran";
  setup.name = sequence_name("mulran", common);
  setup.location = folder;
  setup.scans = list_timestamped_pngs(
      radar / subfolder, oxford_form ? "MulRan Oxford-layout polar scans named <t_ns>.png"
                                     : "MulRan polar scans named <t_ns>.png (range x azimuth)");
  setup.window = common.window;
  setup.decode.range_resolution_m =
      checked_resolution(common.range_resolution_m.value_or(kMulranRangeResolution), setup.name);
  setup.decode.layout = oxford_form ? PolarPngLayout::oxford : PolarPngLayout::mulran_native;
  setup.poses = read_mulran_global_pose(folder / "global_pose.csv");
  setup.frame = PositionFrame::global;
  setup.max_pose_gap_s = common.max_pose_gap_s;
  setup.report.layout = fmt::format(
      "{} (sensor_data/radar/{}/{})", oxford_form ? "oxford" : "mulran_native: range x azimuth",
      subfolder, options.folder == MulranPolarFolder::automatic ? ", chosen automatically" : "");
  setup.report.resolution_source =
      common.range_resolution_m ? "configured" : "MulRan CIR204-H, 200 m / 3360";
  setup.report.pose_source = "global_pose.csv (t, 3x4 [R|t])";
  setup.report.scan_time_reference = "the last azimuth of the sweep (MulRan names files by it)";
  setup.expected_range_bins = 3360;
  setup.sensor = "MulRan CIR204-H (200 m / 0.0595 m)";
  setup.fingerprint_options = "folder=" + subfolder;
  return std::make_unique<PolarPngSequence>(std::move(setup));
}

SequenceConfig parse_mulran_keys(DatasetKeys& keys) {
  const RealDatasetOptions common = read_real_dataset_keys(keys);
  const std::string folder = read_choice(keys, "polar", {"auto", "polar", "polar_oxford_form"});
  const MulranOptions options{common, folder == "polar" ? MulranPolarFolder::polar
                                      : folder == "polar_oxford_form"
                                          ? MulranPolarFolder::polar_oxford_form
                                          : MulranPolarFolder::automatic};
  keys.finish();
  return real_sequence_config("mulran", options, &open_mulran);
}

}  // namespace radarpr
