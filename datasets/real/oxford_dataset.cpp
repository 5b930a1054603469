#include "datasets/real/oxford_dataset.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <system_error>

#include <fmt/format.h>

#include "datasets/real/polar_png_sequence.hpp"
#include "datasets/real/real_dataset_keys.hpp"
#include "datasets/real/text_table.hpp"

namespace radarpr {
namespace {

PoseTrack read_northing_easting(const std::filesystem::path& path, const std::string& what,
                                bool with_heading) {
  TextTable table(path, TextTable::Separator::comma, what);
  table.read_header();
  const std::size_t time = table.column({"timestamp"});
  const std::size_t northing = table.column({"northing"});
  const std::size_t easting = table.column({"easting"});
  const std::size_t yaw = with_heading ? table.column({"yaw"}) : 0;
  std::vector<PoseSample> samples;
  while (table.next()) {
    const double heading = with_heading ? std::numbers::pi / 2 - table.number(yaw) : 0.0;
    samples.push_back({table.unix_time_ns(time),
                       Pose2D{table.number(easting), table.number(northing), wrap_angle(heading)}});
  }
  return PoseTrack(std::move(samples));
}

bool file_has_rows(const std::filesystem::path& path) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error)) return false;
  TextTable table(path, TextTable::Separator::comma, "a CSV file");
  return table.next() && table.next();  // a header and at least one row
}

// Compares radar/ with radar.timestamps; a mismatch means a partial download or copy.
void cross_check_timestamps(const std::filesystem::path& list, const std::vector<ScanFile>& scans,
                            DatasetReport& report) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(list, error)) {
    report.notes.push_back("no radar.timestamps beside radar/: not cross-checked");
    return;
  }
  TextTable table(list, TextTable::Separator::whitespace, "lines '<t_us> <valid>'");
  std::vector<std::int64_t> listed;
  std::size_t invalid = 0;
  while (table.next()) {
    listed.push_back(table.unix_time_ns(0));
    if (table.field_count() > 1 && table.integer(1) == 0) ++invalid;
  }
  std::sort(listed.begin(), listed.end());
  std::size_t on_disk_and_listed = 0;
  for (const ScanFile& scan : scans) {
    if (std::binary_search(listed.begin(), listed.end(), scan.timestamp_ns)) ++on_disk_and_listed;
  }
  const std::size_t missing_files = listed.size() - std::min(listed.size(), on_disk_and_listed);
  const std::size_t unlisted_files = scans.size() - on_disk_and_listed;
  if (missing_files > 0 || unlisted_files > 0) {
    report.warnings.push_back(fmt::format(
        "radar.timestamps lists {} scans and radar/ holds {} PNGs: {} listed scans have no PNG, "
        "{} PNGs are not listed",
        listed.size(), scans.size(), missing_files, unlisted_files));
  }
  if (invalid > 0) {
    report.notes.push_back(
        fmt::format("radar.timestamps marks {} scans as not valid (their PNGs are used)", invalid));
  }
}

}  // namespace

PoseTrack read_oxford_ins(const std::filesystem::path& path) {
  return read_northing_easting(
      path, "Oxford gps/ins.csv (timestamp, ..., northing, easting, ..., yaw)", true);
}

PoseTrack read_oxford_gps(const std::filesystem::path& path) {
  return read_northing_easting(path, "Oxford gps/gps.csv (timestamp, ..., northing, easting, ...)",
                               false);
}

PoseTrack integrate_oxford_radar_odometry(const std::filesystem::path& path) {
  TextTable table(path, TextTable::Separator::comma,
                  "Oxford gt/radar_odometry.csv (source/destination timestamps, x, y, ..., yaw)");
  table.read_header();
  const std::size_t source = table.column({"source_radar_timestamp", "source_timestamp"});
  const std::size_t destination =
      table.column({"destination_radar_timestamp", "destination_timestamp"});
  const std::size_t dx = table.column({"x"});
  const std::size_t dy = table.column({"y"});
  const std::size_t dyaw = table.column({"yaw"});

  std::vector<PoseSample> samples;
  while (table.next()) {
    const std::int64_t from = table.unix_time_ns(destination);
    const std::int64_t to = table.unix_time_ns(source);
    if (samples.empty()) {
      samples.push_back({from, Pose2D{}});  // the chain starts at the origin
    } else if (samples.back().timestamp_ns != from) {
      table.fail(
          fmt::format("{} = {} is not the previous row's {} ({} ns): the odometry chain is broken",
                      table.header()[destination], table.text(destination), table.header()[source],
                      samples.back().timestamp_ns));
    }
    const Pose2D& base = samples.back().pose;
    const double x = table.number(dx);
    const double y = table.number(dy);
    const double c = std::cos(base.yaw);
    const double s = std::sin(base.yaw);
    samples.push_back({to, Pose2D{base.x + c * x - s * y, base.y + s * x + c * y,
                                  wrap_angle(base.yaw + table.number(dyaw))}});
  }
  return PoseTrack(std::move(samples));
}

std::unique_ptr<ScanSequence> open_oxford(const OxfordOptions& options) {
  const auto& common = options.common;
  const std::filesystem::path folder = resolve_sequence_folder(
      common, "an Oxford Radar RobotCar copy (holding <date>-radar-oxford-10k/ runs)",
      "an Oxford Radar RobotCar run with radar/ and gps/ or gt/");

  PolarPngSequenceSetup setup;
  setup.type = "oxford";
  setup.name = sequence_name("oxford", common);
  setup.location = folder;
  setup.scans =
      list_timestamped_pngs(folder / "radar", "Oxford-layout radar scans named <t_us>.png");
  cross_check_timestamps(folder / "radar.timestamps", setup.scans, setup.report);
  setup.window = common.window;
  setup.decode.range_resolution_m =
      checked_resolution(common.range_resolution_m.value_or(kOxfordRangeResolution), setup.name);
  setup.decode.layout = PolarPngLayout::oxford;
  setup.max_pose_gap_s = common.max_pose_gap_s;

  const std::filesystem::path ins = folder / "gps" / "ins.csv";
  const std::filesystem::path gps = folder / "gps" / "gps.csv";
  const std::filesystem::path odometry = folder / "gt" / "radar_odometry.csv";
  OxfordPoseSource source = options.poses;
  if (source == OxfordPoseSource::automatic) {
    std::error_code error;
    if (file_has_rows(ins)) {
      source = OxfordPoseSource::ins;
    } else if (file_has_rows(gps)) {
      source = OxfordPoseSource::gps;
    } else if (std::filesystem::is_regular_file(odometry, error)) {
      source = OxfordPoseSource::odometry;
    } else {
      throw std::runtime_error(fmt::format(
          "{}: no positions found, expected gps/ins.csv, gps/gps.csv or gt/radar_odometry.csv",
          folder.string()));
    }
  }
  switch (source) {
    case OxfordPoseSource::ins:
      setup.poses = read_oxford_ins(ins);
      setup.frame = PositionFrame::global;
      setup.report.pose_source = "gps/ins.csv (easting, northing, yaw)";
      break;
    case OxfordPoseSource::gps:
      setup.poses = read_oxford_gps(gps);
      setup.frame = PositionFrame::global;
      setup.report.pose_source = "gps/gps.csv (easting, northing; no heading, yaw 0)";
      break;
    case OxfordPoseSource::odometry:
    case OxfordPoseSource::automatic:
      setup.poses = integrate_oxford_radar_odometry(odometry);
      setup.frame = PositionFrame::local;
      setup.report.pose_source =
          "integrated gt/radar_odometry.csv (starts at the origin: single session only)";
      break;
  }
  setup.report.layout = "oxford (radar/)";
  setup.report.resolution_source =
      common.range_resolution_m ? "configured" : "Oxford SDK default for the CTS350-X";
  setup.report.scan_time_reference = "the first azimuth of the sweep (Oxford names files by it)";
  setup.expected_range_bins = 3768;
  setup.sensor = "Oxford RobotCar CTS350-X";
  setup.fingerprint_options = fmt::format("poses={}", setup.report.pose_source);
  return std::make_unique<PolarPngSequence>(std::move(setup));
}

SequenceConfig parse_oxford_keys(DatasetKeys& keys) {
  const RealDatasetOptions common = read_real_dataset_keys(keys);
  const std::string poses = read_choice(keys, "poses", {"auto", "ins", "gps", "odometry"});
  const OxfordOptions options{common, poses == "ins"        ? OxfordPoseSource::ins
                                      : poses == "gps"      ? OxfordPoseSource::gps
                                      : poses == "odometry" ? OxfordPoseSource::odometry
                                                            : OxfordPoseSource::automatic};
  keys.finish();
  return real_sequence_config("oxford", options, &open_oxford);
}

}  // namespace radarpr
