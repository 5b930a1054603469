#include "datasets/real/oord_dataset.hpp"

#include <stdexcept>

#include <fmt/format.h>

#include "datasets/real/polar_png_sequence.hpp"
#include "datasets/real/real_dataset_keys.hpp"
#include "datasets/real/text_table.hpp"
#include "datasets/scan_sequence.hpp"

namespace radarpr {

PoseTrack read_oord_gps(const std::filesystem::path& path) {
  TextTable table(path, TextTable::Separator::comma,
                  "OORD MicrostrainMIP/gps.csv (timestamp, utm_northing, utm_easting, ...)");
  table.read_header();
  const std::size_t time = table.column({"timestamp"});
  const std::size_t northing = table.column({"utm_northing", "northing"});
  const std::size_t easting = table.column({"utm_easting", "easting"});
  std::vector<PoseSample> samples;
  while (table.next()) {
    samples.push_back(
        {table.unix_time_ns(time), Pose2D{table.number(easting), table.number(northing), 0.0}});
  }
  return PoseTrack(std::move(samples));
}

std::unique_ptr<ScanSequence> open_oord(const OordOptions& options) {
  const auto& common = options.common;
  if (options.azimuths < kMinScanAzimuths || options.azimuths > 100'000) {
    throw std::invalid_argument(fmt::format("oord: azimuths must be in [{}, 100000], got {}",
                                            kMinScanAzimuths, options.azimuths));
  }
  const std::filesystem::path folder = resolve_sequence_folder(
      common, "an OORD copy (holding <site>/<date>/ sequences)",
      "an OORD sequence <site>/<date> with Navtech_CTS350-X_Radar/ and MicrostrainMIP/gps.csv");

  PolarPngSequenceSetup setup;
  setup.type = "oord";
  setup.name = sequence_name("oord", common);
  setup.location = folder;
  setup.scans = list_timestamped_pngs(folder / "Navtech_CTS350-X_Radar",
                                      "Oxford-layout radar scans named by their time");
  setup.window = common.window;
  setup.decode.range_resolution_m =
      checked_resolution(common.range_resolution_m.value_or(kOordRangeResolution), setup.name);
  setup.decode.layout = PolarPngLayout::oxford;
  setup.decode.use_row_metadata = false;  // encoder bytes are unreliable
  setup.resample_azimuths = options.azimuths;
  setup.poses = read_oord_gps(folder / "MicrostrainMIP" / "gps.csv");
  setup.frame = PositionFrame::global;
  setup.max_pose_gap_s = common.max_pose_gap_s;
  setup.report.layout = "oxford (Navtech_CTS350-X_Radar/), row metadata ignored";
  setup.report.resolution_source = common.range_resolution_m ? "configured" : "CTS350-X default";
  setup.report.pose_source = "MicrostrainMIP/gps.csv (utm_easting, utm_northing; yaw 0)";
  setup.report.notes.push_back(
      fmt::format("azimuths assumed uniform; scans with missing rows are resampled to {} rows",
                  options.azimuths));
  setup.report.scan_time_reference =
      "the file name's time, taken as the first azimuth as in Oxford RobotCar (OORD does not "
      "document it)";
  setup.expected_range_bins = 3768;
  setup.sensor = "OORD CTS350-X";
  setup.fingerprint_options = fmt::format("azimuths={}", options.azimuths);
  return std::make_unique<PolarPngSequence>(std::move(setup));
}

SequenceConfig parse_oord_keys(DatasetKeys& keys) {
  const RealDatasetOptions common = read_real_dataset_keys(keys);
  const auto azimuths = keys.integer_or("azimuths", 400);
  if (azimuths < kMinScanAzimuths || azimuths > 100'000) {
    keys.fail("azimuths",
              fmt::format("must be in [{}, 100000], got {}", kMinScanAzimuths, azimuths));
  }
  keys.finish();
  return real_sequence_config("oord", OordOptions{common, static_cast<int>(azimuths)}, &open_oord);
}

}  // namespace radarpr
