// The generic folder layout: scans/<t>.png in either layout and poses.csv with a header.
#include "datasets/real/folder_dataset.hpp"

#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "tests/datasets/dataset_tree.hpp"

namespace radarpr {
namespace {

using test::expect_error;
using test::real_data;
using test::TempTree;

constexpr const char* kSample = "referee_mulran_kaist03";

void add_scans(const TempTree& tree, const std::string& layout) {
  // Named by µs (the files' last-azimuth times rounded), either layout.
  tree.copy(real_data(kSample) / layout / "000000.png", "drive/scans/1567410201812841.png");
  tree.copy(real_data(kSample) / layout / "000001.png", "drive/scans/1567410202062436.png");
}

FolderOptions options(const TempTree& tree) {
  FolderOptions o;
  o.common.root = tree.root();
  o.common.sequence = "drive";
  o.common.range_resolution_m = 0.0595238;
  return o;
}

TEST(FolderDataset, ReadsEitherLayoutAndPosesWithSecondsAndYaw) {
  RADARPR_SKIP_WITHOUT(real_data(kSample), "MulRan KAIST03 sample");
  TempTree tree;
  add_scans(tree, "oxford_form");
  tree.write("drive/poses.csv", "timestamp,x,y,yaw\n1567410201.5,0,0,0\n1567410202.5,10,20,1\n");
  const auto sequence = open_folder(options(tree));
  ASSERT_EQ(sequence->size(), 2u);
  EXPECT_EQ(sequence->position_frame(), PositionFrame::global);
  // Scan 0 at 1567410201.812841 s: f = 0.312841 of the way from the first pose to the second.
  const ScanRecord& first = sequence->records()[0];
  EXPECT_EQ(first.timestamp_ns, 1'567'410'201'812'841'000);
  EXPECT_NEAR(first.pose.x, 3.12841, 1e-9);
  EXPECT_NEAR(first.pose.y, 6.25682, 1e-9);
  EXPECT_NEAR(first.pose.yaw, 0.312841, 1e-9);
  const PolarImage image = sequence->load_image(1);
  EXPECT_EQ(image.azimuth_count(), 400);
  EXPECT_EQ(image.range_bin_count(), 3360);
  EXPECT_NE(sequence->describe().layout.find("oxford, detected"), std::string::npos)
      << sequence->describe().layout;
}

TEST(FolderDataset, NativeLayoutNanosecondPosesWithoutYawInALocalFrame) {
  RADARPR_SKIP_WITHOUT(real_data(kSample), "MulRan KAIST03 sample");
  TempTree tree;
  add_scans(tree, "native");
  tree.write("drive/odometry.csv",
             "timestamp,x,y\n1567410201000000000,0,0\n1567410203000000000,-4,0\n");
  auto o = options(tree);
  o.poses = "odometry.csv";
  o.frame = PositionFrame::local;
  const auto sequence = open_folder(o);
  EXPECT_EQ(sequence->position_frame(), PositionFrame::local);
  ASSERT_EQ(sequence->size(), 2u);
  // 1.062436 s of 2 s: x = -4 * 0.531218.
  EXPECT_NEAR(sequence->records()[1].pose.x, -2.124872, 1e-9);
  EXPECT_EQ(sequence->records()[1].pose.yaw, 0.0);
  EXPECT_NE(sequence->describe().layout.find("mulran_native, detected"), std::string::npos);
}

TEST(FolderDataset, NeedsTheRangeResolution) {
  TempTree tree;
  auto o = options(tree);
  o.common.range_resolution_m.reset();
  expect_error<std::invalid_argument>([&] { open_folder(o); }, {"range_resolution_m"});
}

}  // namespace
}  // namespace radarpr
