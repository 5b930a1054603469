#include "descriptors/radar_scan_context/radar_scan_context.hpp"

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <numbers>
#include <optional>
#include <random>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include "descriptors/opencv_image.hpp"
#include "descriptors/radar_scan_context/area_average.hpp"
#include "descriptors/radar_scan_context/column_alignment.hpp"
#include "tests/descriptors/mulran_frames.hpp"

namespace radarpr {
namespace {

using testing::native_frame;
using testing::read_native;

constexpr double kPi = std::numbers::pi;

PolarImage scan_of(const cv::Mat& power) {
  PolarImage scan;
  scan.power = to_byte_image(power);
  scan.range_resolution_m = 0.05;
  return scan;
}

// A hand-made context of `rings` rows, given column by column.
DescriptorValue context_from_columns(const std::vector<std::vector<float>>& columns) {
  const int rings = static_cast<int>(columns.front().size());
  const int sectors = static_cast<int>(columns.size());
  DescriptorValue value{rings, sectors, std::vector<float>(columns.size() * columns[0].size())};
  for (int j = 0; j < sectors; ++j) {
    for (int i = 0; i < rings; ++i) {
      value.values[static_cast<std::size_t>(i * sectors + j)] =
          columns[static_cast<std::size_t>(j)][static_cast<std::size_t>(i)];
    }
  }
  return value;
}

TEST(AreaSpans, SplitBinsAtFractionalBoundaries) {
  // 5 bins -> 2 cells, units of 1/2 bin: cell 0 = [0, 5) = bins 0, 1 and the first half of bin 2
  // (bin 2 = [4, 6) sticks out by 1 unit); cell 1 = [5, 10) = the second half of bin 2, 3, 4.
  EXPECT_EQ(area_spans(5, 2), (std::vector<AreaSpan>{{0, 2, 0, 1}, {2, 4, 1, 0}}));
  // 400 azimuths -> 60 sectors, units of 1/60 row: sector 1 = [400, 800) = rows 6.67 .. 13.33:
  // rows 6..13, row 6 = [360, 420) starts 40 units early, row 13 = [780, 840) ends 40 late;
  // weights 60 * 8 - 40 - 40 = 400 = the sector's length in units.
  const std::vector<AreaSpan> sectors = area_spans(400, 60);
  ASSERT_EQ(sectors.size(), 60u);
  EXPECT_EQ(sectors[1], (AreaSpan{6, 13, 40, 40}));
  EXPECT_EQ(sectors[59], (AreaSpan{393, 399, 20, 0}));  // [23600, 24000): row 393 = [23580, ..)
  // Integer ratio: 3360 / 20 = 168 whole bins per ring, no overhang.
  EXPECT_EQ(area_spans(3360, 20)[3], (AreaSpan{504, 671, 0, 0}));
  EXPECT_EQ(area_spans(7, 7)[4], (AreaSpan{4, 4, 0, 0}));
  EXPECT_THROW(area_spans(5, 6), std::invalid_argument);
  EXPECT_THROW(area_spans(5, 0), std::invalid_argument);
}

TEST(AreaAverage, WholeBlocksTransposeToRangeByAzimuth) {
  // A = 4 azimuths x R = 6 bins, P[a][r] = 10 a + r -> 3 rings x 2 sectors of 2 bins x 2 rows.
  // Cell (i, j) = mean of r in {2i, 2i+1}, a in {2j, 2j+1} = 10 (2j + 0.5) + (2i + 0.5)
  // = 20 j + 2 i + 5.5: ring 0 = {5.5, 25.5}, ring 1 = {7.5, 27.5}, ring 2 = {9.5, 29.5}.
  cv::Mat power(4, 6, CV_8UC1);
  for (int a = 0; a < 4; ++a) {
    for (int r = 0; r < 6; ++r)
      power.at<std::uint8_t>(a, r) = static_cast<std::uint8_t>(10 * a + r);
  }
  EXPECT_EQ(area_average_range_by_azimuth(power, 3, 2),
            (std::vector<float>{5.5f, 25.5f, 7.5f, 27.5f, 9.5f, 29.5f}));
}

TEST(AreaAverage, WeighsSplitBinsByTheirOverlap) {
  // A = 3 azimuths x R = 5 bins -> 2 rings x 2 sectors: 2.5 bins per ring, 1.5 rows per sector.
  // Along range: ring 0 = (p0 + p1 + p2 / 2) / 2.5, ring 1 = (p2 / 2 + p3 + p4) / 2.5:
  //   row 0 {5, 0, 10, 20, 0} -> 4, 10;  row 1 {0, 0, 0, 0, 50} -> 0, 20;
  //   row 2 {25, 0, 0, 5, 0}  -> 10, 2.
  // Along azimuth: sector 0 = (row 0 + row 1 / 2) / 1.5, sector 1 = (row 1 / 2 + row 2) / 1.5:
  //   ring 0: (4 + 0) / 1.5 = 8/3, (0 + 10) / 1.5 = 20/3; ring 1: (10 + 10) / 1.5 = 40/3,
  //   (10 + 2) / 1.5 = 8. Check: equal cell areas, so the mean 23/3 = pixel sum 115 / 15.
  const cv::Mat power = (cv::Mat_<std::uint8_t>(3, 5) << 5, 0, 10, 20, 0,  //
                         0, 0, 0, 0, 50,                                   //
                         25, 0, 0, 5, 0);
  const std::vector<float> context = area_average_range_by_azimuth(power, 2, 2);
  ASSERT_EQ(context.size(), 4u);
  EXPECT_FLOAT_EQ(context[0], 8.0f / 3.0f);
  EXPECT_FLOAT_EQ(context[1], 20.0f / 3.0f);
  EXPECT_FLOAT_EQ(context[2], 40.0f / 3.0f);
  EXPECT_FLOAT_EQ(context[3], 8.0f);
}

TEST(AreaAverage, AgreesWithOpenCvInterAreaOnMulranGeometry) {
  // cv::resize INTER_AREA is an area average too (float accumulation); 400 -> 60 azimuths is a
  // non-integer ratio, 3360 -> 20 an integer one. Equal cell areas keep the image mean.
  std::mt19937 generator(42);
  std::uniform_int_distribution<int> level(0, 255);
  cv::Mat power(400, 3360, CV_8UC1);
  for (int a = 0; a < power.rows; ++a) {
    for (int r = 0; r < power.cols; ++r) {
      power.at<std::uint8_t>(a, r) = static_cast<std::uint8_t>(level(generator));
    }
  }
  cv::Mat range_by_azimuth;
  cv::transpose(power, range_by_azimuth);
  range_by_azimuth.convertTo(range_by_azimuth, CV_32F);
  for (const auto& [rings, sectors] : {std::pair{20, 60}, {40, 120}, {5, 10}, {7, 13}}) {
    cv::Mat expected;
    cv::resize(range_by_azimuth, expected, cv::Size(sectors, rings), 0, 0, cv::INTER_AREA);
    const std::vector<float> context = area_average_range_by_azimuth(power, rings, sectors);
    double context_sum = 0.0;
    for (int i = 0; i < rings; ++i) {
      for (int j = 0; j < sectors; ++j) {
        const float value = context[static_cast<std::size_t>(i * sectors + j)];
        ASSERT_NEAR(value, expected.at<float>(i, j), 1e-3) << rings << " x " << sectors;
        context_sum += value;
      }
    }
    EXPECT_NEAR(context_sum / (rings * sectors), cv::mean(power)[0], 1e-4);
  }
}

TEST(AreaAverage, RejectsScansSmallerThanTheContext) {
  const cv::Mat power(10, 30, CV_8UC1, cv::Scalar(1));
  EXPECT_NO_THROW(area_average_range_by_azimuth(power, 30, 10));
  EXPECT_THROW(area_average_range_by_azimuth(power, 31, 10), std::invalid_argument);
  EXPECT_THROW(area_average_range_by_azimuth(power, 20, 11), std::invalid_argument);
  EXPECT_THROW(area_average_range_by_azimuth(cv::Mat(10, 30, CV_32F), 2, 2), std::invalid_argument);
  EXPECT_THROW(area_average_range_by_azimuth(cv::Mat(), 2, 2), std::invalid_argument);
}

TEST(RadarScanContextRingKey, IsTheMeanOfEachRing) {
  // Rings {1, 2, 3} and {4, 5, 9}: means 2 and 6.
  EXPECT_EQ(radar_scan_context_ring_key(DescriptorValue{2, 3, {1, 2, 3, 4, 5, 9}}),
            (std::vector<float>{2.0f, 6.0f}));
  const RadarScanContextDescriptor descriptor({.rings = 2, .sectors = 3, .candidates = 5});
  EXPECT_EQ(descriptor.search_key(DescriptorValue{2, 3, {1, 2, 3, 4, 5, 9}}),
            (std::vector<float>{2.0f, 6.0f}));
  EXPECT_THROW(descriptor.search_key(DescriptorValue{3, 2, {1, 2, 3, 4, 5, 9}}),
               std::invalid_argument);
  EXPECT_THROW(radar_scan_context_ring_key(DescriptorValue{2, 3, {1, 2}}), std::invalid_argument);
}

// The definition, one shift and one column pair after another: sum over qualifying columns of
// cos(a_s[:, j], b[:, j]), each cosine the dot product of unit columns summed ring by ring.
std::optional<ColumnAlignment> column_alignment_by_definition(const std::vector<float>& a,
                                                              const std::vector<float>& b,
                                                              int rings, int sectors) {
  const auto unit = [&](const std::vector<float>& context, int j, std::vector<double>& column) {
    double squares = 0.0;
    for (int i = 0; i < rings; ++i) {
      column[static_cast<std::size_t>(i)] = context[static_cast<std::size_t>(i * sectors + j)];
      squares += column[static_cast<std::size_t>(i)] * column[static_cast<std::size_t>(i)];
    }
    if (squares == 0.0) return false;
    const double inverse = 1.0 / std::sqrt(squares);
    for (double& value : column) value *= inverse;
    return true;
  };
  std::optional<ColumnAlignment> best;
  std::vector<double> column_a(static_cast<std::size_t>(rings));
  std::vector<double> column_b(static_cast<std::size_t>(rings));
  for (int s = 0; s < sectors; ++s) {
    double sum = 0.0;
    int pairs = 0;
    for (int j = 0; j < sectors; ++j) {
      if (!unit(a, (j - s + sectors) % sectors, column_a) || !unit(b, j, column_b)) continue;
      double dot = 0.0;
      for (int i = 0; i < rings; ++i) {
        dot += column_a[static_cast<std::size_t>(i)] * column_b[static_cast<std::size_t>(i)];
      }
      sum += dot;
      ++pairs;
    }
    if (pairs == 0) continue;
    const double similarity = sum / pairs;
    if (!best || similarity > best->similarity) best = ColumnAlignment{s, similarity};
  }
  return best;
}

// The shifts are summed four side by side (SIMD); every one must still be the definition's sum,
// bit for bit, whatever the number of sectors, with zero columns in either context.
TEST(ColumnAlignment, EqualsTheDefinitionBitForBit) {
  std::mt19937 generator(5);
  // Named variables, not a structured binding: the lambda below captures them (clang 14).
  for (const auto& size :
       std::vector<std::pair<int, int>>{{1, 1}, {3, 2}, {5, 10}, {20, 21}, {20, 60}, {40, 120}}) {
    const int rings = size.first;
    const int sectors = size.second;
    for (int trial = 0; trial < 5; ++trial) {
      const auto context = [&] {
        std::vector<float> values(static_cast<std::size_t>(rings * sectors));
        for (float& value : values) value = static_cast<float>(generator() % 1000) / 7.0f;
        for (int j = 0; j < sectors; ++j) {
          if (generator() % 5 != 0) continue;  // about one column in five all zero
          for (int i = 0; i < rings; ++i) values[static_cast<std::size_t>(i * sectors + j)] = 0;
        }
        return values;
      };
      const std::vector<float> a = context();
      const std::vector<float> b = context();
      const auto expected = column_alignment_by_definition(a, b, rings, sectors);
      const auto actual = best_column_alignment(a, b, rings, sectors);
      ASSERT_EQ(actual.has_value(), expected.has_value()) << rings << " x " << sectors;
      if (!expected) continue;
      EXPECT_EQ(actual->shift, expected->shift) << rings << " x " << sectors;
      EXPECT_EQ(actual->similarity, expected->similarity) << rings << " x " << sectors;
    }
  }
}

TEST(ColumnAlignment, SkipsColumnsThatAreZeroInEitherContext) {
  // a columns: a0 = (1, 0), a1 = (0, 0), a2 = (1, 1); b: b0 = (1, 1), b1 = (0, 2), b2 = (3, 0).
  // a_s[:, j] = a[:, (j - s) mod 3]; the zero column a1 never counts:
  //   s = 0: cos(a0, b0) = 1/sqrt2, cos(a2, b2) = 1/sqrt2             -> sim = 0.70711
  //   s = 1: cos(a2, b0) = 1, cos(a0, b1) = 0                         -> sim = 0.5
  //   s = 2: cos(a2, b1) = 1/sqrt2, cos(a0, b2) = 1                   -> sim = 0.85355
  // Best s = 2, d = 1 - (1 + 1/sqrt2) / 2 = 0.14645 (counting a1 as cosine 0 would give 0.431).
  const DescriptorValue a = context_from_columns({{1, 0}, {0, 0}, {1, 1}});
  const DescriptorValue b = context_from_columns({{1, 1}, {0, 2}, {3, 0}});
  ASSERT_EQ(a.values, (std::vector<float>{1, 0, 1, 0, 0, 1}));  // row-major, row = ring
  const auto best = best_column_alignment(a.values, b.values, 2, 3);
  ASSERT_TRUE(best.has_value());
  EXPECT_EQ(best->shift, 2);
  EXPECT_NEAR(best->similarity, (1.0 + 1.0 / std::sqrt(2.0)) / 2.0, 1e-12);

  const RadarScanContextDescriptor descriptor({.rings = 2, .sectors = 3, .candidates = 5});
  const double expected = (1.0 - 1.0 / std::sqrt(2.0)) / 2.0;
  EXPECT_NEAR(descriptor.distance(a, b), expected, 1e-12);
  EXPECT_NEAR(descriptor.distance(b, a), expected, 1e-12);  // shifting b by -s pairs the same
  // s = 2 -> 2 pi * 2 / 3 = 4 pi / 3, wrapped to -2 pi / 3.
  const auto yaw = descriptor.estimate_yaw(a, b);
  ASSERT_TRUE(yaw.has_value());
  EXPECT_NEAR(*yaw, -2.0 * kPi / 3.0, 1e-12);
}

TEST(ColumnAlignment, DistanceIsOneWhenNoColumnPairQualifies) {
  const RadarScanContextDescriptor descriptor({.rings = 2, .sectors = 3, .candidates = 5});
  const DescriptorValue zero{2, 3, std::vector<float>(6, 0.0f)};
  const DescriptorValue some = context_from_columns({{1, 0}, {0, 0}, {1, 1}});
  EXPECT_EQ(best_column_alignment(zero.values, some.values, 2, 3), std::nullopt);
  EXPECT_EQ(descriptor.distance(zero, some), 1.0);
  EXPECT_EQ(descriptor.distance(some, zero), 1.0);
  EXPECT_EQ(descriptor.distance(zero, zero), 1.0);
  EXPECT_EQ(descriptor.estimate_yaw(zero, some), std::nullopt);
}

TEST(ColumnAlignment, OppositeColumnsGiveTheLargestDistance) {
  // One ring: every column is a 1-vector, cos((1), (-2)) = -1 for every shift -> d = 2.
  const RadarScanContextDescriptor descriptor({.rings = 1, .sectors = 2, .candidates = 5});
  EXPECT_DOUBLE_EQ(
      descriptor.distance(DescriptorValue{1, 2, {1, 3}}, DescriptorValue{1, 2, {-2, -1}}), 2.0);
}

TEST(ColumnAlignment, RejectsMismatchedOrNonFiniteContexts) {
  const RadarScanContextDescriptor descriptor({.rings = 2, .sectors = 3, .candidates = 5});
  const DescriptorValue good{2, 3, {1, 2, 3, 4, 5, 6}};
  EXPECT_THROW(descriptor.distance(good, DescriptorValue{3, 2, {1, 2, 3, 4, 5, 6}}),
               std::invalid_argument);
  EXPECT_THROW(descriptor.distance(DescriptorValue{2, 3, {1, 2, 3}}, good), std::invalid_argument);
  DescriptorValue bad = good;
  bad.values[4] = std::numeric_limits<float>::quiet_NaN();
  EXPECT_THROW(descriptor.distance(good, bad), std::invalid_argument);
  bad.values[4] = std::numeric_limits<float>::infinity();
  EXPECT_THROW(descriptor.estimate_yaw(bad, good), std::invalid_argument);
  const std::vector<float> six(6, 1.0f);
  EXPECT_THROW(best_column_alignment(six, six, 2, 2), std::invalid_argument);
  EXPECT_THROW(best_column_alignment(six, six, 0, 6), std::invalid_argument);
}

// 3 rings x 6 sectors, pairwise non-parallel columns, so only the true shift reaches sim = 1.
const std::vector<std::vector<float>> kColumns = {{1, 0, 5}, {2, 1, 4}, {3, 4, 3},
                                                  {4, 2, 2}, {5, 2, 1}, {6, 4, 0}};

// Query column j = database column (j + m) mod 6: query row a sees what database row a + m
// sectors' worth of rows saw.
DescriptorValue columns_turned_by(int m) {
  std::vector<std::vector<float>> columns;
  for (int j = 0; j < 6; ++j)
    columns.push_back(kColumns[static_cast<std::size_t>((j + m + 6) % 6)]);
  return context_from_columns(columns);
}

TEST(RadarScanContextDescriptor, ShiftedCopiesAreAtDistanceZeroWithTheirYaw) {
  const RadarScanContextDescriptor descriptor({.rings = 3, .sectors = 6, .candidates = 5});
  const DescriptorValue database = columns_turned_by(0);
  EXPECT_NEAR(descriptor.distance(database, database), 0.0, 1e-12);
  EXPECT_EQ(descriptor.estimate_yaw(database, database), 0.0);

  // m = 2: a_s[:, j] = query[:, j - s] = database[:, j - s + 2] -> s = 2, yaw = 2 pi * 2 / 6.
  const DescriptorValue forward = columns_turned_by(2);
  EXPECT_NEAR(descriptor.distance(forward, database), 0.0, 1e-12);
  const auto forward_yaw = descriptor.estimate_yaw(forward, database);
  ASSERT_TRUE(forward_yaw.has_value());
  EXPECT_NEAR(*forward_yaw, 2.0 * kPi / 3.0, 1e-12);

  // Not trivially 0: swapping two columns is no circular shift. Best s = 0 keeps 4 columns
  // (cos 1) and pairs (1, 0, 5) with (2, 1, 4) twice: cos = 22 / (sqrt26 sqrt21) = 0.94148,
  // sim = (4 + 2 * 0.94148) / 6 -> d = 0.019507.
  std::vector<std::vector<float>> swapped = kColumns;
  std::swap(swapped[0], swapped[1]);
  EXPECT_NEAR(descriptor.distance(context_from_columns(swapped), database),
              (2.0 - 2.0 * 22.0 / std::sqrt(26.0 * 21.0)) / 6.0, 1e-12);

  // m = -1: s = 5 -> 2 pi * 5 / 6 wraps to -pi / 3; swapping the roles flips the sign.
  const auto back_yaw = descriptor.estimate_yaw(columns_turned_by(-1), database);
  ASSERT_TRUE(back_yaw.has_value());
  EXPECT_NEAR(*back_yaw, -kPi / 3.0, 1e-12);
  const auto swapped_yaw = descriptor.estimate_yaw(database, columns_turned_by(-1));
  ASSERT_TRUE(swapped_yaw.has_value());
  EXPECT_NEAR(*swapped_yaw, kPi / 3.0, 1e-12);

  // Half a turn: s = 3 -> +pi exactly (the interval is (-pi, pi]).
  const auto half_turn = descriptor.estimate_yaw(columns_turned_by(3), database);
  ASSERT_TRUE(half_turn.has_value());
  EXPECT_DOUBLE_EQ(*half_turn, kPi);
}

TEST(RadarScanContextDescriptor, ExtractsRingsBySectorsAndChecksTheScan) {
  const RadarScanContextDescriptor descriptor({.rings = 3, .sectors = 4, .candidates = 5});
  EXPECT_TRUE(descriptor.rotation_invariant());
  EXPECT_EQ(descriptor.retrieval_method(), RetrievalMethod::key_then_rerank);
  EXPECT_EQ(descriptor.rerank_candidates(), 5u);
  EXPECT_EQ(descriptor.shape(ScanGeometry{}), (DescriptorShape{3, 4}));

  // A = 12 azimuths x R = 30 bins, one pixel of 90 at azimuth 4, bin 25: ring 2 (bins 20..29),
  // sector 1 (azimuths 3..5) -> 90 / (10 * 3) = 3 at row 2, column 1; everything else 0.
  cv::Mat power = cv::Mat::zeros(12, 30, CV_8UC1);
  power.at<std::uint8_t>(4, 25) = 90;
  const DescriptorValue value = descriptor.extract(scan_of(power));
  EXPECT_EQ(value.rows, 3);
  EXPECT_EQ(value.cols, 4);
  std::vector<float> expected(12, 0.0f);
  expected[2 * 4 + 1] = 3.0f;
  EXPECT_EQ(value.values, expected);

  EXPECT_THROW(descriptor.extract(scan_of(cv::Mat::zeros(12, 2, CV_8UC1))), std::invalid_argument);
  EXPECT_THROW(descriptor.extract(scan_of(cv::Mat::zeros(3, 30, CV_8UC1))), std::invalid_argument);
  EXPECT_THROW(RadarScanContextDescriptor({.rings = 0, .sectors = 4, .candidates = 5}),
               std::invalid_argument);
  EXPECT_THROW(RadarScanContextDescriptor({.rings = 3, .sectors = 4, .candidates = 0}),
               std::invalid_argument);
}

TEST(RadarScanContextRegistration, DefaultsAndTheDownsizedConfig) {
  const DescriptorRegistry& registry = DescriptorRegistry::global();
  const DescriptorInstance defaults = registry.create_from_id("radar_scan_context");
  EXPECT_EQ(defaults.id, "radar_scan_context");
  EXPECT_EQ(defaults.parameters.integer("rings"), 20);
  EXPECT_EQ(defaults.parameters.integer("sectors"), 60);
  EXPECT_EQ(defaults.parameters.integer("candidates"), 5);
  EXPECT_EQ(defaults.descriptor->shape(ScanGeometry{}), (DescriptorShape{20, 60}));
  EXPECT_EQ(defaults.descriptor->retrieval_method(), RetrievalMethod::key_then_rerank);
  EXPECT_EQ(defaults.descriptor->rerank_candidates(), 5u);
  EXPECT_TRUE(defaults.descriptor->rotation_invariant());

  // RadarSC-DS; the id is canonical whatever the key order.
  const DescriptorInstance downsized =
      registry.create_from_id("radar_scan_context:sectors=10,rings=5");
  EXPECT_EQ(downsized.id, "radar_scan_context:rings=5,sectors=10");
  EXPECT_EQ(registry.create_from_id("radar_scan_context:rings=5,sectors=10").id, downsized.id);
  EXPECT_EQ(downsized.descriptor->shape(ScanGeometry{}), (DescriptorShape{5, 10}));
  const DescriptorValue value =
      downsized.descriptor->extract(scan_of(cv::Mat(400, 3360, CV_8UC1, cv::Scalar(7))));
  EXPECT_EQ(value.rows, 5);
  EXPECT_EQ(value.cols, 10);
  EXPECT_EQ(value.values, std::vector<float>(50, 7.0f));

  EXPECT_EQ(registry.create("radar_scan_context", nlohmann::json{{"candidates", 50}}).id,
            "radar_scan_context:candidates=50");
  EXPECT_THROW(registry.create("radar_scan_context", nlohmann::json{{"rings", 0}}), ParameterError);
  EXPECT_THROW(registry.create("radar_scan_context", nlohmann::json{{"sectors", 2.5}}),
               ParameterError);
}

// Row a of the result holds row (a + rows) mod A of `scan`: the sensor turned by +rows azimuths.
PolarImage turned_by_rows(const PolarImage& scan, int rows) {
  const int azimuths = scan.azimuth_count();
  PolarImage turned = scan;
  turned.power = ByteImage(scan.power.rows(), scan.power.cols());
  for (int a = 0; a < azimuths; ++a) {
    std::copy_n(scan.power.row(((a + rows) % azimuths + azimuths) % azimuths), scan.power.cols(),
                turned.power.row(a));
  }
  return turned;
}

TEST(RadarScanContextOnMulran, WholeSectorTurnsGiveDistanceZeroAndTheirYaw) {
  SKIP_WITHOUT_FRAMES("000000");
  const PolarImage scan = read_native("000000");
  ASSERT_EQ(scan.azimuth_count(), 400);
  // (rings, sectors, rows per turn): 20 rows = 3 sectors of 400/60, 6 of 400/120, half of 40.
  for (const auto& [rings, sectors, rows] :
       {std::tuple{20, 60, 20}, {20, 60, -100}, {40, 120, 20}, {5, 10, 120}}) {
    const RadarScanContextDescriptor descriptor(
        {.rings = rings, .sectors = sectors, .candidates = 5});
    const DescriptorValue database = descriptor.extract(scan);
    const DescriptorValue query = descriptor.extract(turned_by_rows(scan, rows));
    // The turn permutes whole sectors, so the columns match exactly; only rounding remains.
    EXPECT_NEAR(descriptor.distance(query, database), 0.0, 1e-9) << sectors << " " << rows;
    const auto yaw = descriptor.estimate_yaw(query, database);
    ASSERT_TRUE(yaw.has_value());
    // +rows azimuths of 2 pi / 400: 20 -> pi / 10, -100 -> -pi / 2, 120 -> 0.6 pi.
    EXPECT_NEAR(*yaw, 2.0 * kPi * rows / 400.0, 1e-9) << sectors << " " << rows;
  }
}

TEST(RadarScanContextOnMulran, PartSectorTurnsStayCloseWithTheYawWithinOneSector) {
  SKIP_WITHOUT_FRAMES("000000");
  const PolarImage scan = read_native("000000");
  const RadarScanContextDescriptor descriptor(RadarScanContextParams{});
  const DescriptorValue database = descriptor.extract(scan);
  const double sector = 2.0 * kPi / 60.0;  // 400 / 60 = 6.67 azimuth rows
  // A turn of n rows that is no whole number of sectors makes every query column a blend of two
  // neighbouring database sectors; the best shift leaves a residual of e rows, and the cosine
  // loss grows with e (about as e^2, observed). Observed on frame 000000:
  //   +-7 rows: s = +-1, e = 1/3 row (5 % of a sector)  -> d = 6.2e-4 / 5.6e-4;
  //    3 rows:  s = 0,   e = 3 rows (45 % of a sector)  -> d = 0.037,
  // against 0.0028 between consecutive frames: bounds 2e-3 and 0.06.
  for (const auto& [rows, bound] : {std::pair{7, 2e-3}, {-7, 2e-3}, {3, 0.06}}) {
    const DescriptorValue query = descriptor.extract(turned_by_rows(scan, rows));
    EXPECT_LT(descriptor.distance(query, database), bound) << rows;
    const auto yaw = descriptor.estimate_yaw(query, database);
    ASSERT_TRUE(yaw.has_value());
    EXPECT_LT(std::abs(*yaw - 2.0 * kPi * rows / 400.0), sector) << rows;
  }
  // The residual, not the turn, sets the distance: 3 rows is farther than 7.
  EXPECT_GT(descriptor.distance(descriptor.extract(turned_by_rows(scan, 3)), database),
            descriptor.distance(descriptor.extract(turned_by_rows(scan, 7)), database));
  const auto seven = descriptor.estimate_yaw(descriptor.extract(turned_by_rows(scan, 7)), database);
  ASSERT_TRUE(seven.has_value());
  EXPECT_NEAR(*seven, sector, 1e-12);  // s = 1: 6 deg for a true 6.3 deg
}

TEST(RadarScanContextOnMulran, NextFrameIsCloserThanTheTenth) {
  SKIP_WITHOUT_FRAMES("000000", "000001", "000010");
  const RadarScanContextDescriptor descriptor(RadarScanContextParams{});
  const DescriptorValue first = descriptor.extract(read_native("000000"));
  const DescriptorValue next = descriptor.extract(read_native("000001"));
  const DescriptorValue tenth = descriptor.extract(read_native("000010"));
  // Observed: 0.0028 vs 0.0051.
  EXPECT_GT(descriptor.distance(first, next), 0.0);
  EXPECT_LT(descriptor.distance(first, next), descriptor.distance(first, tenth));
}

}  // namespace
}  // namespace radarpr
