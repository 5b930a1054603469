// Fuzz target: every loader's pose and timestamp parser. Input: one byte choosing the parser,
// then the file's bytes (or, for the Unix-time parser, the text).
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>
#include <string>

#include "datasets/pose_track.hpp"
#include "datasets/real/boreas_dataset.hpp"
#include "datasets/real/folder_dataset.hpp"
#include "datasets/real/mulran_dataset.hpp"
#include "datasets/real/oord_dataset.hpp"
#include "datasets/real/oxford_dataset.hpp"
#include "datasets/real/radiate_dataset.hpp"
#include "datasets/real/text_table.hpp"
#include "tests/fuzz/fuzz_target.hpp"

namespace {

using namespace radarpr;
namespace fs = std::filesystem;

// Queries a parsed track where interpolation and the gap rule work: the ends, the middle and
// just outside. A pose must be finite.
void query(const PoseTrack& track) {
  if (track.empty()) return;
  const std::int64_t first = track.first_ns(), last = track.last_ns();
  const std::int64_t middle = first + (last - first) / 2;
  for (const std::int64_t t : {first, middle, last, first - 1, last + 1}) {
    if (const auto pose = track.at(t, 5'000'000'000)) {
      if (!std::isfinite(pose->x) || !std::isfinite(pose->y) || !std::isfinite(pose->yaw)) {
        std::abort();
      }
    }
  }
  static_cast<void>(track.largest_gap_ns(first, last));
}

// The parsers, with the file names their datasets use.
constexpr int kParsers = 9;

void parse(int parser, std::string_view bytes) {
  switch (parser) {
    case 0:
      query(read_boreas_radar_poses(fuzz::write_scratch_file("radar_poses.csv", bytes)));
      break;
    case 1:
      query(read_folder_poses(fuzz::write_scratch_file("poses.csv", bytes)));
      break;
    case 2:
      query(read_mulran_global_pose(fuzz::write_scratch_file("global_pose.csv", bytes)));
      break;
    case 3:
      query(read_oord_gps(fuzz::write_scratch_file("gps.csv", bytes)));
      break;
    case 4:
      query(read_oxford_ins(fuzz::write_scratch_file("ins.csv", bytes)));
      break;
    case 5:
      query(read_oxford_gps(fuzz::write_scratch_file("gps.csv", bytes)));
      break;
    case 6:
      query(integrate_oxford_radar_odometry(fuzz::write_scratch_file("radar_odometry.csv", bytes)));
      break;
    case 7:
      static_cast<void>(
          read_radiate_frame_times(fuzz::write_scratch_file("Navtech_Polar.txt", bytes)));
      break;
    default:
      static_cast<void>(parse_unix_time_ns(bytes));
      break;
  }
}

const char* const kFileNames[] = {
    "radar_poses.csv", "poses.csv",          "global_pose.csv",   "gps.csv", "ins.csv",
    "gps.csv",         "radar_odometry.csv", "Navtech_Polar.txt", ""};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return 0;
  const int parser = data[0] % kParsers;
  try {
    parse(parser, fuzz::as_text(data + 1, size - 1));
  } catch (const std::exception& error) {
    // The Unix-time parser returns nullopt and never throws: any exception from it is a finding.
    if (parser == kParsers - 1) throw;
    fuzz::require_names(error, (fuzz::scratch_folder() / kFileNames[parser]).string());
  }
  return 0;
}
