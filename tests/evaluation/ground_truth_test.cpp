#include "evaluation/ground_truth.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

namespace radarpr {
namespace {

std::vector<ScanRecord> records_at(const std::vector<std::int64_t>& timestamps_ns) {
  std::vector<ScanRecord> records;
  for (const std::int64_t t : timestamps_ns) records.push_back({t, {}, "test"});
  return records;
}

// The definition, checked against every eligible frame.
bool brute_force_revisit(const std::vector<Position2D>& database, const Position2D& query,
                         std::size_t end, double radius) {
  for (std::size_t j = 0; j < end; ++j) {
    const double dx = query.x - database[j].x;
    const double dy = query.y - database[j].y;
    if (dx * dx + dy * dy <= radius * radius) return true;
  }
  return false;
}

TEST(PositionsOf, TakesXAndYOfEachPose) {
  std::vector<ScanRecord> records(2);
  records[0].pose = {1.5, -2.0, 0.3};
  records[1].pose = {10.0, 20.0, -1.0};
  const std::vector<Position2D> positions = positions_of(records);
  ASSERT_EQ(positions.size(), 2u);
  EXPECT_EQ(positions[0].x, 1.5);
  EXPECT_EQ(positions[0].y, -2.0);
  EXPECT_EQ(positions[1].x, 10.0);
  EXPECT_EQ(positions[1].y, 20.0);
}

TEST(EligibleEnds, FramesExcludeTheMostRecent) {
  Protocol protocol;
  protocol.exclude_recent_frames = 2;
  // q may match j when q - j >= 2: end = q - 1 for q >= 1, clamped at 0.
  // q=0: none; q=1: j <= -1 none; q=2: j=0 -> 1; q=3: 2; q=4: 3; q=5: 4.
  const auto ends = single_session_eligible_ends(records_at({0, 1, 2, 3, 4, 5}), protocol);
  EXPECT_EQ(ends, (std::vector<std::size_t>{0, 0, 1, 2, 3, 4}));
}

TEST(EligibleEnds, ExcludeOneFrameAllowsEveryOlderFrame) {
  Protocol protocol;
  protocol.exclude_recent_frames = 1;
  // q - j >= 1: every older frame, end = q.
  const auto ends = single_session_eligible_ends(records_at({0, 1, 2}), protocol);
  EXPECT_EQ(ends, (std::vector<std::size_t>{0, 1, 2}));
}

TEST(EligibleEnds, ShortSequenceHasNoEligibleFrame) {
  const Protocol protocol;  // 50 frames
  const auto ends = single_session_eligible_ends(records_at({0, 1, 2}), protocol);
  EXPECT_EQ(ends, (std::vector<std::size_t>{0, 0, 0}));
}

TEST(EligibleEnds, SecondsReplaceFramesAndAreInclusive) {
  Protocol protocol;
  protocol.exclude_recent_frames = 1;  // ignored once seconds are set
  protocol.exclude_recent_seconds = 1.0;
  // t = 0, 0.5, 1.0, 1.6, 2.0, 3.0 s; j eligible when t_q - t_j >= 1 s.
  // q0: none -> 0; q1 (0.5): 0.5 < 1 -> 0; q2 (1.0): j0 (1.0) -> 1;
  // q3 (1.6): j0 (1.6), j1 (1.1), not j2 (0.6) -> 2; q4 (2.0): j0, j1, j2 (exactly 1.0) -> 3;
  // q5 (3.0): j0..j3 (1.4), j4 (exactly 1.0) -> 5.
  const auto ends = single_session_eligible_ends(
      records_at({0, 500'000'000, 1'000'000'000, 1'600'000'000, 2'000'000'000, 3'000'000'000}),
      protocol);
  EXPECT_EQ(ends, (std::vector<std::size_t>{0, 0, 1, 2, 3, 5}));
}

TEST(EligibleEnds, EqualTimestampsAreNotOlder) {
  Protocol protocol;
  protocol.exclude_recent_seconds = 0.5;
  // t = 0, 0, 1, 1 s: q2 and q3 may match j0 and j1 (1 s older), never each other.
  const auto ends =
      single_session_eligible_ends(records_at({0, 0, 1'000'000'000, 1'000'000'000}), protocol);
  EXPECT_EQ(ends, (std::vector<std::size_t>{0, 0, 2, 2}));
}

TEST(EligibleEnds, RejectsWindowsThatWouldMatchTheQueryItself) {
  Protocol protocol;
  protocol.exclude_recent_frames = 0;
  EXPECT_THROW(single_session_eligible_ends(records_at({0, 1}), protocol), std::invalid_argument);
  protocol.exclude_recent_frames = -3;
  EXPECT_THROW(single_session_eligible_ends(records_at({0, 1}), protocol), std::invalid_argument);
  for (const double seconds : {0.0, -1.0, std::nan(""), std::numeric_limits<double>::infinity()}) {
    protocol.exclude_recent_seconds = seconds;
    EXPECT_THROW(single_session_eligible_ends(records_at({0, 1}), protocol), std::invalid_argument)
        << seconds;
  }
}

TEST(EligibleEnds, SecondsNeedTimeOrder) {
  Protocol protocol;
  protocol.exclude_recent_seconds = 1.0;
  EXPECT_THROW(
      single_session_eligible_ends(records_at({0, 2'000'000'000, 1'000'000'000}), protocol),
      std::invalid_argument);
}

TEST(RevisitGroundTruth, RadiusIsInclusive) {
  const RevisitGroundTruth truth({{0.0, 0.0}}, 5.0);
  // (3, 4) is exactly 5 m away: 3^2 + 4^2 = 25 = 5^2.
  EXPECT_TRUE(truth.is_positive({3.0, 4.0}, 0));
  EXPECT_TRUE(truth.has_revisit({3.0, 4.0}, 1));
  EXPECT_TRUE(truth.has_revisit({-5.0, 0.0}, 1));
  EXPECT_TRUE(truth.has_revisit({0.0, -5.0}, 1));
  // (3, 4.5): 9 + 20.25 = 29.25 > 25.
  EXPECT_FALSE(truth.is_positive({3.0, 4.5}, 0));
  EXPECT_FALSE(truth.has_revisit({3.0, 4.5}, 1));
  EXPECT_FALSE(truth.has_revisit({5.0, 5.0}, 1));
  EXPECT_EQ(truth.radius_m(), 5.0);
  EXPECT_EQ(truth.database_size(), 1u);
}

TEST(RevisitGroundTruth, StrictRadiusLeavesOutTheBoundary) {
  // The MulRan evaluator's dist < criteria: (3, 4), exactly 5 m away, is not a revisit.
  const RevisitGroundTruth truth({{0.0, 0.0}}, 5.0, RadiusComparison::strict);
  EXPECT_FALSE(truth.is_positive({3.0, 4.0}, 0));
  EXPECT_FALSE(truth.has_revisit({3.0, 4.0}, 1));
  EXPECT_FALSE(truth.has_revisit({-5.0, 0.0}, 1));
  EXPECT_TRUE(truth.is_positive({3.0, 3.99}, 0));
  EXPECT_TRUE(truth.has_revisit({3.0, 3.99}, 1));
}

TEST(RevisitGroundTruth, OnlyFramesBeforeTheEligibleEndCount) {
  const RevisitGroundTruth truth({{0.0, 0.0}, {100.0, 100.0}, {1.0, 1.0}}, 2.0);
  EXPECT_FALSE(truth.has_revisit({1.0, 0.0}, 0));  // nothing eligible
  EXPECT_TRUE(truth.has_revisit({1.0, 0.0}, 1));   // frame 0 is 1 m away
  EXPECT_FALSE(truth.has_revisit({100.0, 99.0}, 1));
  EXPECT_TRUE(truth.has_revisit({100.0, 99.0}, 2));  // frame 1 is 1 m away
  EXPECT_FALSE(truth.has_revisit({3.0, 3.0}, 2));    // frame 2 (2.83 m) is not eligible
  EXPECT_FALSE(truth.has_revisit({3.0, 3.0}, 3));    // and is beyond 2 m anyway
  EXPECT_TRUE(truth.has_revisit({2.0, 2.0}, 3));     // frame 2 is 1.41 m away
}

TEST(RevisitGroundTruth, FarQueriesAndEmptyDatabaseHaveNoRevisit) {
  const RevisitGroundTruth truth({{0.0, 0.0}, {10.0, 0.0}}, 3.0);
  EXPECT_FALSE(truth.has_revisit({1e12, -1e12}, 2));
  EXPECT_FALSE(truth.has_revisit({-4.0, 0.0}, 2));
  const RevisitGroundTruth empty({}, 3.0);
  EXPECT_FALSE(empty.has_revisit({0.0, 0.0}, 0));
}

TEST(RevisitGroundTruth, MatchesBruteForceOnIntegerGridWithBoundaryDistances) {
  // Integer coordinates and radius 5 give many pairs at exactly 5 m ((3,4), (5,0), ...).
  std::mt19937 rng(11);
  std::uniform_int_distribution<int> coordinate(0, 60);
  std::uniform_int_distribution<int> query_coordinate(-10, 70);
  std::vector<Position2D> database;
  for (int i = 0; i < 400; ++i)
    database.push_back({double(coordinate(rng)), double(coordinate(rng))});
  const RevisitGroundTruth truth(database, 5.0);
  std::uniform_int_distribution<std::size_t> end_of(0, database.size());
  int boundary_queries = 0;
  int revisits = 0;
  for (int i = 0; i < 3000; ++i) {
    const Position2D query{double(query_coordinate(rng)), double(query_coordinate(rng))};
    const std::size_t end = end_of(rng);
    const bool expected = brute_force_revisit(database, query, end, 5.0);
    ASSERT_EQ(truth.has_revisit(query, end), expected)
        << "query (" << query.x << ", " << query.y << ") end " << end;
    revisits += expected ? 1 : 0;
    // Queries whose nearest eligible frame is exactly 5 m away exercise the boundary.
    if (expected && !brute_force_revisit(database, query, end, 4.999)) ++boundary_queries;
  }
  EXPECT_GT(boundary_queries, 10);
  EXPECT_GT(revisits, 100);
  EXPECT_LT(revisits, 2900);
}

TEST(RevisitGroundTruth, MatchesBruteForceOnRandomPositions) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> coordinate(-300.0, 300.0);
  std::vector<Position2D> database;
  for (int i = 0; i < 2000; ++i) database.push_back({coordinate(rng), coordinate(rng)});
  for (const double radius : {0.5, 7.3, 40.0}) {
    const RevisitGroundTruth truth(database, radius);
    std::uniform_int_distribution<std::size_t> end_of(0, database.size());
    std::uniform_real_distribution<double> query_coordinate(-350.0, 350.0);
    for (int i = 0; i < 2000; ++i) {
      Position2D query{query_coordinate(rng), query_coordinate(rng)};
      // Every fourth query sits near a database frame, so both answers occur for every radius.
      if (i % 4 == 0) {
        const Position2D& near = database[end_of(rng) % database.size()];
        query = {near.x + radius * 0.9, near.y + radius * 0.3};
      }
      const std::size_t end = end_of(rng);
      ASSERT_EQ(truth.has_revisit(query, end), brute_force_revisit(database, query, end, radius))
          << "radius " << radius << " query (" << query.x << ", " << query.y << ") end " << end;
    }
  }
}

TEST(RevisitGroundTruth, RejectsBadInput) {
  const double nan = std::nan("");
  const double inf = std::numeric_limits<double>::infinity();
  for (const double radius : {0.0, -1.0, nan, inf}) {
    EXPECT_THROW(RevisitGroundTruth({{0.0, 0.0}}, radius), std::invalid_argument) << radius;
  }
  EXPECT_THROW(RevisitGroundTruth({{0.0, 0.0}, {nan, 1.0}}, 5.0), std::invalid_argument);
  EXPECT_THROW(RevisitGroundTruth({{0.0, inf}}, 5.0), std::invalid_argument);
  // 1e10 m at a 1 mm radius is more cells than the grid allows.
  EXPECT_THROW(RevisitGroundTruth({{0.0, 0.0}, {1e10, 0.0}}, 0.001), std::invalid_argument);

  const RevisitGroundTruth truth({{0.0, 0.0}}, 5.0);
  EXPECT_THROW(truth.is_positive({0.0, 0.0}, 1), std::out_of_range);
  EXPECT_THROW(truth.has_revisit({0.0, 0.0}, 2), std::invalid_argument);
  EXPECT_THROW(truth.has_revisit({nan, 0.0}, 1), std::invalid_argument);
}

}  // namespace
}  // namespace radarpr

namespace radarpr {
namespace {

constexpr double kDegree = std::numbers::pi / 180.0;

// Heading-aware ground truth: within the radius AND headings at most the limit apart, the
// smaller angle between them (359 degrees and 1 degree are 2 apart).
TEST(RevisitGroundTruth, AHeadingLimitAlsoNeedsTheHeadingsClose) {
  const std::vector<Position2D> database = {{0.0, 0.0, 0.0},
                                            {1.0, 0.0, 180.0 * kDegree},
                                            {2.0, 0.0, 359.0 * kDegree},
                                            {3.0, 0.0, 30.0 * kDegree}};
  const RevisitGroundTruth position_only(database, 5.0);
  const RevisitGroundTruth heading(database, 5.0, RadiusComparison::inclusive, 30.0);
  const Position2D query{0.5, 0.0, 1.0 * kDegree};
  for (std::size_t i = 0; i < database.size(); ++i) {
    EXPECT_TRUE(position_only.is_positive(query, i)) << i;
  }
  EXPECT_TRUE(heading.is_positive(query, 0));   // 1 degree apart
  EXPECT_FALSE(heading.is_positive(query, 1));  // 179 degrees apart: the reverse direction
  EXPECT_TRUE(heading.is_positive(query, 2));   // 2 degrees apart across 0
  EXPECT_TRUE(heading.is_positive(query, 3));   // 29 degrees apart
  EXPECT_FALSE(heading.is_positive({0.5, 0.0, -30.0 * kDegree}, 3));  // 60 degrees apart
  // has_revisit follows: facing the other way, only frame 1 is a revisit.
  const Position2D reverse{0.5, 0.0, 181.0 * kDegree};
  EXPECT_FALSE(heading.has_revisit(reverse, 1));
  EXPECT_TRUE(heading.has_revisit(reverse, 2));
  EXPECT_TRUE(position_only.has_revisit(reverse, 1));
  // Still a position test first: a frame beyond the radius is no revisit whatever its heading.
  EXPECT_FALSE(heading.is_positive({10.0, 0.0, 0.0}, 0));
  // 180 degrees accepts every heading.
  const RevisitGroundTruth any(database, 5.0, RadiusComparison::inclusive, 180.0);
  EXPECT_TRUE(any.is_positive(reverse, 0));
}

TEST(RevisitGroundTruth, AHeadingLimitRefusesBadLimitsAndHeadings) {
  for (const double limit : {0.0, -5.0, 180.5, std::numeric_limits<double>::quiet_NaN()}) {
    EXPECT_THROW(RevisitGroundTruth({{0.0, 0.0, 0.0}}, 5.0, RadiusComparison::inclusive, limit),
                 std::invalid_argument)
        << limit;
  }
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(RevisitGroundTruth({{0.0, 0.0, nan}}, 5.0, RadiusComparison::inclusive, 30.0),
               std::invalid_argument);
  // Without a limit a heading is never read.
  EXPECT_NO_THROW(RevisitGroundTruth({{0.0, 0.0, nan}}, 5.0));
  const RevisitGroundTruth truth({{0.0, 0.0, 0.0}}, 5.0, RadiusComparison::inclusive, 30.0);
  EXPECT_THROW(truth.is_positive({0.0, 0.0, nan}, 0), std::invalid_argument);
}

// Poses read without a heading have yaw 0 everywhere: a heading limit over them would accept
// every heading, so it is refused, saying why.
TEST(RevisitGroundTruth, AHeadingLimitRefusesPosesWithoutAHeading) {
  const std::vector<Position2D> no_heading = {{0.0, 0.0, 0.0}, {1.0, 0.0, 0.0}, {2.0, 0.0, 0.0}};
  try {
    RevisitGroundTruth(no_heading, 5.0, RadiusComparison::inclusive, 30.0);
    FAIL() << "expected a refusal";
  } catch (const std::invalid_argument& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("all 3 database poses have yaw 0"), std::string::npos) << message;
    EXPECT_NE(message.find("revisit_max_yaw_deg"), std::string::npos) << message;
  }
  EXPECT_NO_THROW(RevisitGroundTruth(no_heading, 5.0));  // without a limit yaw is never read
  EXPECT_NO_THROW(RevisitGroundTruth({{0.0, 0.0, 0.0}, {1.0, 0.0, 0.1}}, 5.0,
                                     RadiusComparison::inclusive, 30.0));
}

// positions_of carries the scan's yaw, so that a run's ground truth sees the headings.
TEST(PositionsOf, CarriesTheYaw) {
  ScanRecord record;
  record.pose = {1.0, 2.0, 0.5};
  const auto positions = positions_of({record});
  ASSERT_EQ(positions.size(), 1u);
  EXPECT_EQ(positions[0].yaw, 0.5);
}

}  // namespace
}  // namespace radarpr
