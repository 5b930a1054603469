// Real pose tracks with loops (../shared/data/real/poses_only: two Boreas traversals of the Glen
// Shields loop, the integrated odometry of Oxford 2019-01-10-11-46-21), read by the loaders'
// pose readers, give the same revisit counts through the ground-truth code as a brute-force
// count over every pair.
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "datasets/real/boreas_dataset.hpp"
#include "datasets/real/oxford_dataset.hpp"
#include "evaluation/dataset_inspection.hpp"
#include "tests/datasets/dataset_tree.hpp"

namespace radarpr {
namespace {

using test::real_data;

constexpr const char* kBoreasAugust = "poses_only/boreas-2021-08-05-13-34_radar_poses.csv";
constexpr const char* kBoreasSeptember = "poses_only/boreas-2021-09-02-11-42_radar_poses.csv";
constexpr const char* kOxfordOdometry = "poses_only/oxford_2019-01-10-11-46-21_radar_odometry.csv";

std::vector<ScanRecord> records_of(const PoseTrack& track) {
  std::vector<ScanRecord> records;
  for (const PoseSample& sample : track.samples()) {
    records.push_back({sample.timestamp_ns, sample.pose, "pose"});
  }
  return records;
}

// Every pair, straight from protocols.md: a query counts when some database frame is eligible
// (single session: at least exclude_recent_frames older, or exclude_recent_seconds older), and
// is a revisit when an eligible frame lies within the radius (inclusive).
RevisitCount brute_force(const std::vector<ScanRecord>& query,
                         const std::vector<ScanRecord>* database, const Protocol& protocol) {
  const auto& db = database ? *database : query;
  RevisitCount count;
  for (std::size_t q = 0; q < query.size(); ++q) {
    bool eligible_any = false;
    bool revisit = false;
    for (std::size_t j = 0; j < db.size(); ++j) {
      bool eligible = true;
      if (!database) {
        eligible = protocol.exclude_recent_seconds
                       ? static_cast<double>(query[q].timestamp_ns - db[j].timestamp_ns) >=
                             *protocol.exclude_recent_seconds * 1e9
                       : j + protocol.exclude_recent_frames <= q;
      }
      if (!eligible) continue;
      eligible_any = true;
      const double dx = query[q].pose.x - db[j].pose.x;
      const double dy = query[q].pose.y - db[j].pose.y;
      if (dx * dx + dy * dy <= protocol.revisit_radius_m * protocol.revisit_radius_m) {
        revisit = true;
        break;
      }
    }
    count.queries += eligible_any ? 1 : 0;
    count.revisits += revisit ? 1 : 0;
  }
  return count;
}

Protocol protocol(double radius_m, int frames, std::optional<double> seconds = std::nullopt) {
  Protocol p;
  p.revisit_radius_m = radius_m;
  p.exclude_recent_frames = frames;
  p.exclude_recent_seconds = seconds;
  return p;
}

void expect_counts_match(const std::string& label, const std::vector<ScanRecord>& query,
                         const std::vector<ScanRecord>* database, const Protocol& p) {
  const RevisitCount fast = count_revisit_queries(query, database, p);
  const RevisitCount slow = brute_force(query, database, p);
  const std::string exclusion = database ? "multi session"
                                : p.exclude_recent_seconds
                                    ? std::to_string(*p.exclude_recent_seconds) + " s excluded"
                                    : std::to_string(p.exclude_recent_frames) + " frames excluded";
  std::printf("[ measured ] %s, %.0f m, %s: %zu revisits of %zu queries\n", label.c_str(),
              p.revisit_radius_m, exclusion.c_str(), fast.revisits, fast.queries);
  EXPECT_EQ(fast.queries, slow.queries) << label;
  EXPECT_EQ(fast.revisits, slow.revisits) << label;
  EXPECT_GT(fast.revisits, 0u) << label << ": a loop must give revisits";
}

TEST(RealPoseRevisits, BoreasGlenShieldsTraversals) {
  RADARPR_SKIP_WITHOUT(real_data(kBoreasAugust), "Boreas pose track");
  RADARPR_SKIP_WITHOUT(real_data(kBoreasSeptember), "Boreas pose track");
  const PoseTrack august = read_boreas_radar_poses(real_data(kBoreasAugust));
  const PoseTrack september = read_boreas_radar_poses(real_data(kBoreasSeptember));
  EXPECT_EQ(august.size(), 4477u);
  EXPECT_EQ(september.size(), 4134u);
  // 19-digit ns stamps and 16-digit µs stamps both land on their recording day.
  constexpr std::int64_t kDay = 86'400'000'000'000;
  EXPECT_EQ(august.first_ns() / kDay, 1'628'121'600'000'000'000 / kDay);     // 2021-08-05
  EXPECT_EQ(september.first_ns() / kDay, 1'630'540'800'000'000'000 / kDay);  // 2021-09-02
  const auto a = records_of(august);
  const auto s = records_of(september);
  expect_counts_match("Boreas 2021-08-05 single session", a, nullptr, protocol(20, 50));
  expect_counts_match("Boreas 2021-08-05 single session", a, nullptr, protocol(5, 50, 100.0));
  expect_counts_match("Boreas 2021-09-02 single session", s, nullptr, protocol(20, 50));
  expect_counts_match("Boreas 2021-09-02 against 2021-08-05", s, &a, protocol(20, 50));
  expect_counts_match("Boreas 2021-09-02 against 2021-08-05", s, &a, protocol(5, 50));
}

TEST(RealPoseRevisits, OxfordIntegratedOdometryClosesItsLoop) {
  RADARPR_SKIP_WITHOUT(real_data(kOxfordOdometry), "Oxford 11-46-21 odometry");
  const PoseTrack track = integrate_oxford_radar_odometry(real_data(kOxfordOdometry));
  ASSERT_EQ(track.size(), 8866u);  // 8865 relative poses chain 8866 scans
  // SOURCE.md: the integrated path ends within 1.6 m of its start; a wrong composition order
  // (destination in source frame) would not close the 9 km loop.
  const Pose2D& first = track.samples().front().pose;
  const Pose2D& last = track.samples().back().pose;
  const double gap = std::hypot(last.x - first.x, last.y - first.y);
  std::printf("[ measured ] Oxford 11-46-21 odometry: end %.2f m from the start\n", gap);
  EXPECT_LT(gap, 2.0);
  const auto records = records_of(track);
  expect_counts_match("Oxford 11-46-21 single session", records, nullptr, protocol(20, 50));
  expect_counts_match("Oxford 11-46-21 single session", records, nullptr, protocol(10, 50, 100.0));
}

}  // namespace
}  // namespace radarpr
