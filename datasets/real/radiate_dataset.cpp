#include "datasets/real/radiate_dataset.hpp"

#include <algorithm>
#include <stdexcept>
#include <system_error>

#include <fmt/format.h>

#include "datasets/real/polar_png_sequence.hpp"
#include "datasets/real/real_dataset_keys.hpp"
#include "datasets/real/text_table.hpp"

namespace radarpr {
namespace {

// Compares the GPS clock with the radar clock: the sample's GPS starts ~64 s after its last
// scan, so its positions cannot be matched to scans. The file is optional and only used for this
// check, so a malformed one is a warning, not a reason to refuse the scans.
void check_gps_clock(const std::filesystem::path& gps_times, const TimeSpan& radar,
                     DatasetReport& report) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(gps_times, error)) return;
  std::map<std::int64_t, std::int64_t> times;
  try {
    times = read_radiate_frame_times(gps_times);
  } catch (const std::exception& problem) {
    report.warnings.push_back(fmt::format(
        "GPS_IMU_Twist.txt could not be read, so the GPS clock is not checked against the radar "
        "clock: {}",
        problem.what()));
    return;
  }
  if (times.empty()) return;
  std::int64_t first = times.begin()->second;
  std::int64_t last = first;
  for (const auto& [frame, t] : times) {
    first = std::min(first, t);
    last = std::max(last, t);
  }
  const TimeSpan gps{first, last};
  if (gps.overlaps(radar)) {
    report.notes.push_back(
        fmt::format("GPS_IMU_Twist.txt ({} samples) overlaps the radar clock but is not used as "
                    "ground truth (latitude/longitude, no evaluation frame)",
                    times.size()));
    return;
  }
  const double offset_s =
      static_cast<double>(gps.first_ns > radar.last_ns ? gps.first_ns - radar.last_ns
                                                       : radar.first_ns - gps.last_ns) *
      1e-9;
  report.warnings.push_back(fmt::format(
      "the GPS clock of GPS_IMU_Twist.txt ({} .. {}) does not overlap the radar clock of "
      "Navtech_Polar.txt ({} .. {}): it starts {:.1f} s {} the radar; its positions cannot be "
      "matched to scans",
      format_utc(gps.first_ns), format_utc(gps.last_ns), format_utc(radar.first_ns),
      format_utc(radar.last_ns), offset_s,
      gps.first_ns > radar.last_ns ? "after the last scan of" : "before the first scan of"));
}

}  // namespace

std::map<std::int64_t, std::int64_t> read_radiate_frame_times(const std::filesystem::path& path) {
  TextTable table(path, TextTable::Separator::whitespace,
                  "RADIATE frame times ('Frame: <n> Time: <unix s>' per line)");
  std::map<std::int64_t, std::int64_t> times;
  while (table.next()) {
    if (table.field_count() < 4 || table.text(0) != "Frame:" || table.text(2) != "Time:") {
      table.fail("expected 'Frame: <n> Time: <unix seconds>'");
    }
    const std::int64_t frame = table.integer(1);
    if (!times.emplace(frame, table.unix_time_ns(3)).second) {
      table.fail(fmt::format("frame {} is listed twice", frame));
    }
  }
  return times;
}

std::unique_ptr<ScanSequence> open_radiate(const RadiateOptions& options) {
  const auto& common = options.common;
  const std::filesystem::path folder =
      resolve_sequence_folder(common, "a RADIATE copy (holding sequences such as fog_6_0/)",
                              "a RADIATE sequence with Navtech_Polar/ and Navtech_Polar.txt");
  const std::filesystem::path images = folder / "Navtech_Polar";
  require_folder(images, "RADIATE polar scans named <frame>.png");
  const auto frame_times = read_radiate_frame_times(folder / "Navtech_Polar.txt");

  PolarPngSequenceSetup setup;
  setup.type = "radiate";
  setup.name = sequence_name("radiate", common);
  setup.location = folder;
  for (const auto& entry : std::filesystem::directory_iterator(images)) {
    const std::filesystem::path& path = entry.path();
    if (path.extension() != ".png" || !entry.is_regular_file()) continue;
    std::int64_t frame = 0;
    try {
      std::size_t used = 0;
      frame = std::stoll(path.stem().string(), &used);
      if (used != path.stem().string().size()) throw std::invalid_argument("trailing text");
    } catch (const std::exception&) {
      throw std::runtime_error(
          fmt::format("{}: the file name is not a frame number, expected Navtech_Polar/<frame>.png",
                      path.string()));
    }
    const auto time = frame_times.find(frame);
    if (time == frame_times.end()) {
      throw std::runtime_error(fmt::format("{}: frame {} has no line in {}", path.string(), frame,
                                           (folder / "Navtech_Polar.txt").string()));
    }
    setup.scans.push_back({path, time->second});
  }
  if (setup.scans.empty()) {
    throw std::runtime_error(fmt::format(
        "{}: no .png file in the folder, expected RADIATE polar scans", images.string()));
  }
  sort_scans_by_time(setup.scans);
  if (frame_times.size() > setup.scans.size()) {
    setup.report.notes.push_back(fmt::format("Navtech_Polar.txt lists {} frames without a PNG",
                                             frame_times.size() - setup.scans.size()));
  }
  setup.window = common.window;
  setup.decode.range_resolution_m =
      checked_resolution(common.range_resolution_m.value_or(kRadiateRangeResolution), setup.name);
  setup.decode.layout = PolarPngLayout::mulran_native;  // range rows x azimuth columns
  setup.report.layout = "range rows x azimuth columns, as MulRan's native (Navtech_Polar/)";
  setup.report.resolution_source =
      common.range_resolution_m ? "configured" : "RADIATE config, 100 m / 576";
  setup.report.pose_source = "RADIATE ships no ground truth";
  setup.report.scan_time_reference =
      "the frame time of Navtech_Polar.txt (RADIATE does not say which azimuth's)";
  setup.expected_range_bins = 576;
  setup.sensor = "RADIATE CTS350-X (100 m / 0.1736 m)";
  check_gps_clock(folder / "GPS_IMU_Twist.txt",
                  TimeSpan{setup.scans.front().timestamp_ns, setup.scans.back().timestamp_ns},
                  setup.report);
  // No poses: the sequence lists every scan with a zero pose and says its frame is `none`.
  return std::make_unique<PolarPngSequence>(std::move(setup));
}

SequenceConfig parse_radiate_keys(DatasetKeys& keys) {
  const RadiateOptions options{read_real_dataset_keys(keys)};
  keys.finish();
  return real_sequence_config("radiate", options, &open_radiate);
}

}  // namespace radarpr
