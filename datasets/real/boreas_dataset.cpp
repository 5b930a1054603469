#include "datasets/real/boreas_dataset.hpp"

#include <fmt/format.h>

#include "datasets/real/polar_png_sequence.hpp"
#include "datasets/real/real_dataset_keys.hpp"
#include "datasets/real/text_table.hpp"

namespace radarpr {

double boreas_range_resolution(std::int64_t first_scan_ns) {
  return first_scan_ns < kBoreasResolutionChangeUnixS * 1'000'000'000 ? kBoreasEarlyRangeResolution
                                                                      : kBoreasLateRangeResolution;
}

PoseTrack read_boreas_radar_poses(const std::filesystem::path& path) {
  TextTable table(path, TextTable::Separator::comma,
                  "Boreas applanix/radar_poses.csv (GPSTime, easting, northing, ..., heading)");
  table.read_header();
  const std::size_t time = table.column({"GPSTime"});
  const std::size_t easting = table.column({"easting"});
  const std::size_t northing = table.column({"northing"});
  const std::size_t heading = table.column({"heading"});
  std::vector<PoseSample> samples;
  while (table.next()) {
    samples.push_back(
        {table.unix_time_ns(time),
         Pose2D{table.number(easting), table.number(northing), wrap_angle(table.number(heading))}});
  }
  return PoseTrack(std::move(samples));
}

std::unique_ptr<ScanSequence> open_boreas(const BoreasOptions& options) {
  const auto& common = options.common;
  const std::filesystem::path folder =
      resolve_sequence_folder(common, "a Boreas copy (holding boreas-<date>-<time>/ sequences)",
                              "a Boreas sequence with radar/ and applanix/radar_poses.csv");

  PolarPngSequenceSetup setup;
  setup.type = "boreas";
  setup.name = sequence_name("boreas", common);
  setup.location = folder;
  setup.scans = list_timestamped_pngs(folder / "radar",
                                      "Oxford-layout radar scans named by their time (µs or ns)");
  setup.window = common.window;
  const std::int64_t first_ns = setup.scans.front().timestamp_ns;
  setup.decode.range_resolution_m = checked_resolution(
      common.range_resolution_m.value_or(boreas_range_resolution(first_ns)), setup.name);
  setup.decode.layout = PolarPngLayout::oxford;
  setup.poses = read_boreas_radar_poses(folder / "applanix" / "radar_poses.csv");
  setup.frame = PositionFrame::global;
  setup.max_pose_gap_s = common.max_pose_gap_s;
  setup.report.layout = "oxford (radar/)";
  setup.report.resolution_source = common.range_resolution_m ? "configured"
                                   : first_ns < kBoreasResolutionChangeUnixS * 1'000'000'000
                                       ? "by date: recorded before 2021-09-21"
                                       : "by date: recorded from 2021-09-21 on";
  setup.report.pose_source = "applanix/radar_poses.csv (easting, northing, heading)";
  setup.report.scan_time_reference = "the middle azimuth of the sweep (Boreas names files by it)";
  setup.report.notes.push_back("range offset -0.31 m not applied");
  // No expected R: the CIR304-H and Boreas-RT's RAS6 differ, and both are Boreas.
  return std::make_unique<PolarPngSequence>(std::move(setup));
}

SequenceConfig parse_boreas_keys(DatasetKeys& keys) {
  const BoreasOptions options{read_real_dataset_keys(keys)};
  keys.finish();
  return real_sequence_config("boreas", options, &open_boreas);
}

}  // namespace radarpr
