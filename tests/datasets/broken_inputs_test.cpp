// Broken inputs give one clear error naming the file and what was expected: a truncated PNG, a
// PNG of the wrong width, a poses file with a bad row, an empty folder, a missing root.
#include <cstdint>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "datasets/real/boreas_dataset.hpp"
#include "datasets/real/mulran_dataset.hpp"
#include "datasets/real/oxford_dataset.hpp"
#include "tests/datasets/dataset_tree.hpp"

namespace radarpr {
namespace {

using test::expect_error;
using test::real_data;
using test::TempTree;
namespace fs = std::filesystem;

constexpr const char* kOxford = "oxford_radar_robotcar_tiny_radarslampy";
constexpr const char* kMulran = "referee_mulran_kaist03";

// Writes the first half of `from`'s bytes to `to`.
void write_truncated(const fs::path& from, const fs::path& to) {
  std::ifstream in(from, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::ofstream(to, std::ios::binary) << bytes.substr(0, bytes.size() / 2);
}

// An Oxford run with three scans and gps.csv.
OxfordOptions oxford_run(const TempTree& tree) {
  const fs::path sample = real_data(kOxford);
  for (const char* name :
       {"1547131046353776.png", "1547131046606586.png", "1547131046858560.png"}) {
    tree.copy(sample / "radar" / name, std::string("run/radar/") + name);
  }
  tree.copy(sample / "gps" / "gps.csv", "run/gps/gps.csv");
  OxfordOptions o;
  o.common.root = tree.root();
  o.common.sequence = "run";
  return o;
}

std::string read_bytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

void put_big_endian(std::string& bytes, std::size_t at, std::uint32_t value) {
  for (int i = 0; i < 4; ++i) bytes[at + i] = static_cast<char>(value >> (24 - 8 * i));
}

// Every scan's PNG header and end are checked when the sequence opens, so a truncated file late
// in a sequence stops it before any extraction, not hours into it.
TEST(BrokenInputs, ATruncatedLaterPngFailsWhenTheSequenceIsOpened) {
  RADARPR_SKIP_WITHOUT(real_data(kOxford), "Oxford tiny sample");
  TempTree tree;
  const auto o = oxford_run(tree);
  const fs::path broken = tree.path("run/radar/1547131046858560.png");
  write_truncated(real_data(kOxford) / "radar/1547131046858560.png", broken);
  expect_error<std::runtime_error>([&] { open_oxford(o); },
                                   {broken.string(), "does not end with an IEND chunk"});
}

// A later scan whose header claims what its file cannot hold (100000 x 100000 pixels, a 2 GiB
// ancillary chunk) stops the sequence when it opens, naming the file: no scan is decoded, and
// nothing near what the header claims is allocated.
TEST(BrokenInputs, ALaterPngClaimingHugeSizesFailsWhenTheSequenceIsOpened) {
  RADARPR_SKIP_WITHOUT(real_data(kOxford), "Oxford tiny sample");
  TempTree tree;
  const auto o = oxford_run(tree);
  const fs::path later = tree.path("run/radar/1547131046858560.png");
  const std::string valid = read_bytes(later);
  std::string huge = valid;
  put_big_endian(huge, 16, 100000);  // IHDR width
  put_big_endian(huge, 20, 100000);  // IHDR height
  tree.write("run/radar/1547131046858560.png", huge);
  expect_error<std::runtime_error>([&] { open_oxford(o); },
                                   {later.string(), "declares 100000 x 100000 pixels"});
  // A text chunk of 2 GiB right after IHDR (8 signature bytes + 25 of IHDR).
  std::string chunk(16, 'x');
  put_big_endian(chunk, 0, 0x8000'0000u);
  chunk.replace(4, 4, "tEXt");
  tree.write("run/radar/1547131046858560.png", valid.substr(0, 33) + chunk + valid.substr(33));
  expect_error<std::runtime_error>([&] { open_oxford(o); },
                                   {later.string(), "'tEXt' chunk at byte 33 declares 2147483648"});
}

// A poses file saved with a UTF-8 byte order mark (as some spreadsheet programs do) reads like
// the same file without one (its first column used to be called "\ufefftimestamp").
TEST(BrokenInputs, APoseFileWithAByteOrderMarkIsRead) {
  RADARPR_SKIP_WITHOUT(real_data(kOxford), "Oxford tiny sample");
  TempTree tree;
  const auto o = oxford_run(tree);
  const auto plain = open_oxford(o);
  const fs::path gps = tree.path("run/gps/gps.csv");
  tree.write("run/gps/gps.csv", "\xEF\xBB\xBF" + read_bytes(gps));
  const auto marked = open_oxford(o);
  ASSERT_EQ(marked->size(), plain->size());
  ASSERT_GT(plain->size(), 0u);
  for (std::size_t i = 0; i < plain->size(); ++i) {
    EXPECT_EQ(marked->records()[i].pose.x, plain->records()[i].pose.x) << i;
    EXPECT_EQ(marked->records()[i].pose.y, plain->records()[i].pose.y) << i;
    EXPECT_EQ(marked->records()[i].pose.yaw, plain->records()[i].pose.yaw) << i;
  }
}

TEST(BrokenInputs, AFileThatIsNotAPngFailsWhenTheSequenceIsOpened) {
  RADARPR_SKIP_WITHOUT(real_data(kOxford), "Oxford tiny sample");
  TempTree tree;
  const auto o = oxford_run(tree);
  const fs::path odd = tree.write("run/radar/1547131047000000.png", std::string(100, 'x'));
  expect_error<std::runtime_error>([&] { open_oxford(o); }, {odd.string(), "not a PNG"});
  tree.write("run/radar/1547131047000000.png", "tiny");
  expect_error<std::runtime_error>([&] { open_oxford(o); }, {odd.string(), "too short"});
}

TEST(BrokenInputs, ATruncatedFirstPngFailsWhenTheSequenceIsOpened) {
  RADARPR_SKIP_WITHOUT(real_data(kOxford), "Oxford tiny sample");
  TempTree tree;
  const auto o = oxford_run(tree);
  const fs::path broken = tree.path("run/radar/1547131046353776.png");
  write_truncated(real_data(kOxford) / "radar/1547131046353776.png", broken);
  expect_error<std::runtime_error>([&] { open_oxford(o); }, {broken.string(), "could not decode"});
}

TEST(BrokenInputs, APngOfTheWrongWidthIsFoundWhenTheSequenceIsOpened) {
  RADARPR_SKIP_WITHOUT(real_data(kMulran), "MulRan KAIST03 sample");
  RADARPR_SKIP_WITHOUT(real_data(kOxford), "Oxford tiny sample");
  TempTree tree;
  // A MulRan Oxford-form scan (3371 wide) after Oxford scans (3779 wide).
  const auto o = oxford_run(tree);
  const fs::path odd =
      tree.copy(real_data(kMulran) / "oxford_form/000000.png", "run/radar/1547131047000000.png");
  expect_error<std::runtime_error>(
      [&] { open_oxford(o); },
      {odd.string(), "3371 x 400 pixels (400 azimuths x 3360 range bins)", "1547131046353776.png",
       "is 3779 x 400 (400 azimuths x 3768 range bins)", "same size"});
  // Outside the window it is never read, so it does not matter.
  OxfordOptions first_three = o;
  first_three.common.window.end = 3;
  EXPECT_EQ(open_oxford(first_three)->size(), 3u);
}

TEST(BrokenInputs, APoseFileWithABadRowNamesFileLineAndColumn) {
  RADARPR_SKIP_WITHOUT(real_data("boreas_rt_single_frame"), "Boreas-RT frame");
  TempTree tree;
  tree.copy(real_data("boreas_rt_single_frame/test_frame.png"), "seq/radar/1733239501984460.png");
  const fs::path poses = tree.write(
      "seq/applanix/radar_poses.csv",
      "GPSTime,easting,northing,altitude,vel_east,vel_north,vel_up,roll,pitch,heading,angvel_z,"
      "angvel_y,angvel_x\n"
      "1733239501734460,623425.0,4848820.5,150,0,0,0,0,0,0.3,0,0,0\n"
      "1733239501984460,6234x5.0,4848820.5,150,0,0,0,0,0,0.3,0,0,0\n");
  BoreasOptions o;
  o.common.root = tree.root();
  o.common.sequence = "seq";
  expect_error<std::runtime_error>([&] { open_boreas(o); },
                                   {poses.string() + ":3:", "column 2 (easting)", "'6234x5.0'"});
}

TEST(BrokenInputs, AnEmptyScanFolderIsNamed) {
  TempTree tree;
  tree.folder("run/radar");
  tree.write("run/gps/gps.csv", "timestamp,northing,easting\n");
  OxfordOptions o;
  o.common.root = tree.root();
  o.common.sequence = "run";
  expect_error<std::runtime_error>([&] { open_oxford(o); },
                                   {tree.path("run/radar").string(), "no .png file"});
}

TEST(BrokenInputs, AMissingRootOrSequenceIsNamedWithWhatIsThere) {
  TempTree tree;
  MulranOptions o;
  o.common.root = tree.path("no_such_root");
  o.common.sequence = "KAIST03";
  expect_error<std::runtime_error>(
      [&] { open_mulran(o); }, {tree.path("no_such_root").string(), "folder not found", "MulRan"});
  tree.folder("DCC01");
  tree.folder("KAIST03");
  o.common.root = tree.root();
  o.common.sequence = "KAIST09";
  expect_error<std::runtime_error>(
      [&] { open_mulran(o); },
      {tree.path("KAIST09").string(), "sequence folder not found", "it holds DCC01, KAIST03"});
  // The sequence exists but its scans do not.
  o.common.sequence = "KAIST03";
  expect_error<std::runtime_error>(
      [&] { open_mulran(o); },
      {tree.path("KAIST03/sensor_data/radar/polar").string(), "folder not found"});
}

TEST(BrokenInputs, AScanNameThatIsNotATimestampIsNamed) {
  TempTree tree;
  const fs::path odd = tree.write("run/radar/scan_0001.png", "not read");
  OxfordOptions o;
  o.common.root = tree.root();
  o.common.sequence = "run";
  expect_error<std::runtime_error>([&] { open_oxford(o); }, {odd.string(), "not a Unix timestamp"});
}

}  // namespace
}  // namespace radarpr
