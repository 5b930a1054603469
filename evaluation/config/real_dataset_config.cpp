#include "evaluation/config/real_dataset_config.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include <fmt/format.h>

#include "datasets/real/boreas_dataset.hpp"
#include "datasets/real/folder_dataset.hpp"
#include "datasets/real/mulran_dataset.hpp"
#include "datasets/real/oord_dataset.hpp"
#include "datasets/real/oxford_dataset.hpp"
#include "datasets/real/radiate_dataset.hpp"
#include "datasets/scan_sequence.hpp"
#include "evaluation/config/config_reader.hpp"
#include "evaluation/config/environment_expansion.hpp"

namespace radarpr {

bool is_real_dataset_type(const std::string& type) {
  return type == "mulran" || type == "oxford" || type == "boreas" || type == "oord" ||
         type == "radiate" || type == "folder";
}

namespace {

// A number in (0, high]: checked before it is converted (seconds to nanoseconds, metres to
// bins), so that a huge value cannot wrap into a negative or meaningless one.
std::optional<double> positive_number(ConfigReader& reader, const std::string& key, double high) {
  if (!reader.has(key)) {
    reader.number_or(key, 0.0);  // listed among the accepted keys
    return std::nullopt;
  }
  const double value = reader.number_or(key, 0.0);
  if (!(value > 0.0) || !(value <= high)) {
    reader.fail(key, fmt::format("must be a number in (0, {}], got {}", high, value));
  }
  return value;
}

RealDatasetOptions parse_common(ConfigReader& reader) {
  RealDatasetOptions options;
  const std::string root = reader.required_string("root");
  if (root.empty()) reader.fail("root", "must name the dataset's folder");
  options.root = expand_environment_variables(root, reader.path_of("root"));
  options.sequence = reader.string_or("sequence", "");
  const auto every_nth = reader.integer_or("every_nth", 1);
  if (every_nth < 1 || every_nth > 1'000'000) {
    reader.fail("every_nth", fmt::format("must be in [1, 1000000], got {}", every_nth));
  }
  options.window.every_nth = static_cast<std::size_t>(every_nth);
  const auto start = reader.integer_or("start", 0);
  if (start < 0) reader.fail("start", fmt::format("must be a scan index >= 0, got {}", start));
  options.window.start = static_cast<std::size_t>(start);
  if (!reader.value("end").is_null()) {
    const auto end = reader.integer_or("end", 0);
    if (end <= start) {
      reader.fail("end", fmt::format("must be a scan index > start ({}), got {} (end is exclusive)",
                                     start, end));
    }
    options.window.end = static_cast<std::size_t>(end);
  }
  options.range_resolution_m = positive_number(reader, "range_resolution_m", kMaxRangeResolutionM);
  options.max_pose_gap_s =
      positive_number(reader, "max_pose_gap_s", kMaxPoseGapS).value_or(options.max_pose_gap_s);
  return options;
}

// Reads a string key that must be one of `choices` (the first is the default).
std::string choice(ConfigReader& reader, const std::string& key,
                   const std::vector<std::string>& choices) {
  const std::string value = reader.string_or(key, choices.front());
  if (std::find(choices.begin(), choices.end(), value) == choices.end()) {
    reader.fail(key, fmt::format("'{}' is not one of: {}", value, fmt::join(choices, ", ")));
  }
  return value;
}

// Parsing checks the keys; the files are only read when the runner (or inspect) opens it.
template <typename Options>
SequenceConfig real_config(const std::string& type, Options options,
                           std::unique_ptr<ScanSequence> (*open)(const Options&)) {
  return {type, [options, open] { return open(options); }};
}

}  // namespace

SequenceConfig parse_real_dataset_config(const std::string& type, ConfigReader& reader) {
  RealDatasetOptions common = parse_common(reader);
  SequenceConfig spec;
  if (type == "mulran") {
    const std::string folder = choice(reader, "polar", {"auto", "polar", "polar_oxford_form"});
    MulranOptions options{common, folder == "polar" ? MulranPolarFolder::polar
                                  : folder == "polar_oxford_form"
                                      ? MulranPolarFolder::polar_oxford_form
                                      : MulranPolarFolder::automatic};
    spec = real_config(type, options, &open_mulran);
  } else if (type == "oxford") {
    const std::string poses = choice(reader, "poses", {"auto", "ins", "gps", "odometry"});
    OxfordOptions options{common, poses == "ins"        ? OxfordPoseSource::ins
                                  : poses == "gps"      ? OxfordPoseSource::gps
                                  : poses == "odometry" ? OxfordPoseSource::odometry
                                                        : OxfordPoseSource::automatic};
    spec = real_config(type, options, &open_oxford);
  } else if (type == "boreas") {
    spec = real_config(type, BoreasOptions{common}, &open_boreas);
  } else if (type == "oord") {
    const auto azimuths = reader.integer_or("azimuths", 400);
    if (azimuths < kMinScanAzimuths || azimuths > 100'000) {
      reader.fail("azimuths",
                  fmt::format("must be in [{}, 100000], got {}", kMinScanAzimuths, azimuths));
    }
    spec = real_config(type, OordOptions{common, static_cast<int>(azimuths)}, &open_oord);
  } else if (type == "radiate") {
    spec = real_config(type, RadiateOptions{common}, &open_radiate);
  } else {
    if (!common.range_resolution_m) {
      reader.fail("range_resolution_m",
                  "required for a folder dataset (metres per range bin; PNGs do not carry it)");
    }
    FolderOptions options;
    options.common = common;
    options.scans = reader.string_or("scans", options.scans);
    if (options.scans.empty()) reader.fail("scans", "must name the folder of PNGs");
    options.poses = reader.string_or("poses", options.poses);
    const std::string layout = choice(reader, "layout", {"auto", "oxford", "mulran_native"});
    if (layout == "oxford") options.layout = PolarPngLayout::oxford;
    if (layout == "mulran_native") options.layout = PolarPngLayout::mulran_native;
    const std::string frame = choice(reader, "position_frame", {"global", "local"});
    options.frame = frame == "local" ? PositionFrame::local : PositionFrame::global;
    spec = real_config(type, options, &open_folder);
  }
  reader.finish();
  return spec;
}

}  // namespace radarpr
