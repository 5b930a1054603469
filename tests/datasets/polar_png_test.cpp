#include "datasets/polar_png.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <functional>
#include <numbers>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include "datasets/png_header.hpp"
#include "descriptors/opencv_image.hpp"

namespace radarpr {
namespace {

namespace fs = std::filesystem;
constexpr double kPi = std::numbers::pi;
constexpr double kMulranResolution = 0.0595238;
constexpr double kOxfordResolution = 0.0432;

fs::path real_data(const std::string& relative) {
  return fs::path(RADARPR_SOURCE_DIR) / "../shared/data/real" / relative;
}

// A fresh directory per test for the files the error cases write.
class TempDir {
 public:
  TempDir() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    path_ = fs::temp_directory_path() / (std::string("radarpr_polar_png_") + info->name() + "_" +
                                         std::to_string(reinterpret_cast<std::uintptr_t>(this)));
    fs::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ignored;
    fs::remove_all(path_, ignored);
  }
  fs::path file(const std::string& name) const { return path_ / name; }

 private:
  fs::path path_;
};

// Expects `action` to throw a std::exception whose message names `path` and contains
// `fragment`.
template <typename Exception = std::runtime_error>
void expect_error(const std::function<void()>& action, const std::string& path,
                  const std::string& fragment) {
  try {
    action();
    ADD_FAILURE() << "no exception for " << path;
  } catch (const Exception& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find(path), std::string::npos) << message;
    EXPECT_NE(message.find(fragment), std::string::npos) << message;
  }
}

void write_le(ByteImage& image, int row, int column, std::uint64_t value, int bytes) {
  for (int i = 0; i < bytes; ++i) {
    image(row, column + i) = static_cast<std::uint8_t>(value >> (8 * i));
  }
}

// A 4-azimuth, 5-bin Oxford-layout image with hand-chosen metadata: row a has stamp
// `first_stamp + a * stamp_step`, encoder 1400 a + 7, flag 255 on even rows, power 10 a + r.
ByteImage oxford_image(std::int64_t first_stamp, std::int64_t stamp_step) {
  ByteImage image(4, kOxfordMetadataColumns + 5);
  for (int a = 0; a < 4; ++a) {
    write_le(image, a, 0, static_cast<std::uint64_t>(first_stamp + a * stamp_step), 8);
    write_le(image, a, 8, static_cast<std::uint64_t>(1400 * a + 7), 2);
    image(a, 10) = a % 2 == 0 ? 255 : 0;
    for (int r = 0; r < 5; ++r) {
      image(a, kOxfordMetadataColumns + r) = static_cast<std::uint8_t>(10 * a + r);
    }
  }
  return image;
}

PolarPngOptions options(double resolution) {
  PolarPngOptions o;
  o.range_resolution_m = resolution;
  return o;
}

// ---- Hand-built images: every expected value follows from how the image was written. ----

TEST(PolarPng, DecodesHandBuiltOxfordLayoutWithMicrosecondStamps) {
  // 1.6e15 µs = 2020-09-13; rows 625 µs apart.
  const DecodedPolarPng d =
      decode_polar_png(oxford_image(1'600'000'000'000'000, 625), options(0.05), "hand-built");
  EXPECT_EQ(d.layout, PolarPngLayout::oxford);
  ASSERT_EQ(d.image.power.rows(), 4);
  ASSERT_EQ(d.image.power.cols(), 5);  // 16 columns - 11 metadata
  for (int a = 0; a < 4; ++a) {
    for (int r = 0; r < 5; ++r) EXPECT_EQ(d.image.power(a, r), 10 * a + r);
    // encoder 1400 a + 7 -> (1400 a + 7) / 5600 * 2 pi = a pi / 2 + 7 pi / 2800
    EXPECT_NEAR(d.image.azimuths_rad[a], a * kPi / 2 + 7 * kPi / 2800, 1e-12);
    // µs -> ns: (1.6e15 + 625 a) * 1000
    EXPECT_EQ(d.image.azimuth_times_ns[a], 1'600'000'000'000'000'000 + a * 625'000);
  }
  // Middle azimuth = row 4 / 2 = 2: 1.6e18 + 2 * 625000 ns.
  ASSERT_TRUE(d.timestamp_ns.has_value());
  EXPECT_EQ(*d.timestamp_ns, 1'600'000'000'001'250'000);
  EXPECT_EQ(d.row_flags, (std::vector<std::uint8_t>{255, 0, 255, 0}));
  EXPECT_EQ(d.image.range_resolution_m, 0.05);
}

TEST(PolarPng, KeepsNanosecondStampsAsTheyAre) {
  const DecodedPolarPng d = decode_polar_png(oxford_image(1'567'410'201'563'630'080, 640'000),
                                             options(kMulranResolution), "hand-built");
  EXPECT_EQ(d.image.azimuth_times_ns[0], 1'567'410'201'563'630'080);
  EXPECT_EQ(d.image.azimuth_times_ns[3], 1'567'410'201'563'630'080 + 3 * 640'000);
}

TEST(PolarPng, IgnoresRowMetadataWhenAsked) {
  PolarPngOptions o = options(0.05);
  o.use_row_metadata = false;
  const DecodedPolarPng d = decode_polar_png(oxford_image(1'600'000'000'000'000, 625), o, "x");
  // Uniform 2 pi a / 4 instead of the encoder's a pi / 2 + 7 pi / 2800.
  EXPECT_NEAR(d.image.azimuths_rad[1], kPi / 2, 1e-12);
  EXPECT_TRUE(d.image.azimuth_times_ns.empty());
  EXPECT_FALSE(d.timestamp_ns.has_value());
  EXPECT_TRUE(d.row_flags.empty());
  EXPECT_EQ(d.image.power(3, 4), 34);  // 10 * 3 + 4
}

TEST(PolarPng, TransposesHandBuiltNativeLayout) {
  // 6 range rows x 3 azimuth columns, value 20 r + a.
  ByteImage native(6, 3);
  for (int r = 0; r < 6; ++r) {
    for (int a = 0; a < 3; ++a) native(r, a) = static_cast<std::uint8_t>(20 * r + a);
  }
  const DecodedPolarPng d = decode_polar_png(native, options(0.1), "native");
  EXPECT_EQ(d.layout, PolarPngLayout::mulran_native);
  ASSERT_EQ(d.image.power.rows(), 3);
  ASSERT_EQ(d.image.power.cols(), 6);
  EXPECT_EQ(d.image.power(2, 5), 102);  // 20 * 5 + 2
  ASSERT_EQ(d.image.azimuths_rad.size(), 3u);
  EXPECT_NEAR(d.image.azimuths_rad[1], 2 * kPi / 3, 1e-12);
  EXPECT_TRUE(d.image.azimuth_times_ns.empty());
  EXPECT_FALSE(d.timestamp_ns.has_value());
}

TEST(PolarPng, AForcedLayoutSkipsDetectionButNotTheOrientationCheck) {
  // 6 range rows x 3 azimuth columns forced as native: the same as detected (3 x 6 azimuth-major).
  const ByteImage native(6, 3, 7);
  PolarPngOptions o = options(0.05);
  o.layout = PolarPngLayout::mulran_native;
  const DecodedPolarPng d = decode_polar_png(native, o, "tall");
  EXPECT_EQ(d.layout, PolarPngLayout::mulran_native);
  EXPECT_EQ(d.image.power.rows(), 3);
  EXPECT_EQ(d.image.power.cols(), 6);
  // The 16 wide x 4 high Oxford image forced as native would be read as 16 azimuths x 4 bins.
  expect_error([&] { decode_polar_png(oxford_image(1'600'000'000'000'000, 625), o, "wide.png"); },
               "wide.png", "16 wide x 4 high, expected the range x azimuth layout");
  // The tall image forced as Oxford would be read as 6 azimuths with metadata from 3 columns.
  o.layout = PolarPngLayout::oxford;
  expect_error([&] { decode_polar_png(native, o, "tall.png"); }, "tall.png",
               "3 wide x 6 high, expected the Oxford layout");
  // Wider than high but not wider than the 11 metadata bytes.
  expect_error([&] { decode_polar_png(ByteImage(4, 11), o, "narrow.png"); }, "narrow.png",
               "wider than 11");
}

TEST(PolarPng, LayoutNames) {
  EXPECT_EQ(to_string(PolarPngLayout::oxford), "oxford");
  EXPECT_EQ(to_string(PolarPngLayout::mulran_native), "mulran_native");
}

TEST(PolarPng, StampUnitsByMagnitude) {
  EXPECT_EQ(unix_stamp_to_ns(1'547'131'046'353'776), 1'547'131'046'353'776'000);      // µs, 2019
  EXPECT_EQ(unix_stamp_to_ns(1'567'410'201'812'840'960), 1'567'410'201'812'840'960);  // ns
  EXPECT_EQ(unix_stamp_to_ns(0), std::nullopt);
  EXPECT_EQ(unix_stamp_to_ns(1'567'410'201), std::nullopt);  // seconds are not accepted
  EXPECT_EQ(unix_stamp_to_ns(-1'547'131'046'353'776), std::nullopt);
}

// ---- Bad metadata and options. ----

TEST(PolarPngErrors, EncoderOutOfRange) {
  ByteImage image = oxford_image(1'600'000'000'000'000, 625);
  write_le(image, 2, 8, 5600, 2);  // one past the last valid count
  expect_error([&] { decode_polar_png(image, options(0.05), "enc.png"); }, "enc.png",
               "encoder value 5600");
}

TEST(PolarPngErrors, ImplausibleOrMixedTimestamps) {
  ByteImage zero = oxford_image(1'600'000'000'000'000, 625);
  write_le(zero, 1, 0, 0, 8);
  expect_error([&] { decode_polar_png(zero, options(0.05), "zero.png"); }, "zero.png",
               "timestamp 0");
  ByteImage mixed = oxford_image(1'600'000'000'000'000, 625);
  write_le(mixed, 3, 0, 1'600'000'000'000'000'000, 8);  // ns among µs
  expect_error([&] { decode_polar_png(mixed, options(0.05), "mixed.png"); }, "mixed.png",
               "different unit");
}

TEST(PolarPngErrors, RangeResolutionIsRequired) {
  expect_error<std::invalid_argument>(
      [&] { decode_polar_png(oxford_image(1'600'000'000'000'000, 625), {}, "nores.png"); },
      "nores.png", "range resolution");
}

TEST(PolarPngErrors, SquareImageIsAmbiguous) {
  const ByteImage square(20, 20);
  expect_error([&] { decode_polar_png(square, options(0.05), "square.png"); }, "square.png",
               "square");
}

// ---- Files on disk. ----

TEST(PolarPngErrors, MissingFile) {
  TempDir dir;
  const fs::path path = dir.file("does_not_exist.png");
  expect_error([&] { read_polar_png(path, options(0.05)); }, path.string(), "file not found");
}

TEST(PolarPngErrors, CorruptPng) {
  TempDir dir;
  const fs::path path = dir.file("corrupt.png");
  {
    std::ofstream out(path, std::ios::binary);
    const char signature[] = "\x89PNG\r\n\x1a\n";
    out.write(signature, 8);
    out << "this is not a PNG chunk stream at all";
  }
  expect_error([&] { read_polar_png(path, options(0.05)); }, path.string(), "could not decode");
}

TEST(PolarPngErrors, SixteenBitPng) {
  TempDir dir;
  const fs::path path = dir.file("sixteen.png");
  ASSERT_TRUE(cv::imwrite(path.string(), cv::Mat(400, 3371, CV_16UC1, cv::Scalar(1000))));
  expect_error([&] { read_polar_png(path, options(0.05)); }, path.string(), "16-bit");
}

TEST(PolarPngErrors, ColourPng) {
  TempDir dir;
  const fs::path path = dir.file("colour.png");
  ASSERT_TRUE(cv::imwrite(path.string(), cv::Mat(40, 100, CV_8UC3, cv::Scalar(1, 2, 3))));
  expect_error([&] { read_polar_png(path, options(0.05)); }, path.string(), "3 channels");
}

TEST(PolarPngErrors, TinyImage) {
  TempDir dir;
  const fs::path path = dir.file("tiny.png");
  // 8 wide x 4 high: azimuth rows by shape, but not even the 11 metadata bytes fit.
  ASSERT_TRUE(cv::imwrite(path.string(), cv::Mat(4, 8, CV_8UC1, cv::Scalar(0))));
  expect_error([&] { read_polar_png(path, options(0.05)); }, path.string(), "too small");
}

// A valid 8-bit PNG (range rows x azimuth columns) as bytes, for the header tests to damage.
std::string png_bytes(int rows, int columns) {
  std::vector<std::uint8_t> encoded;
  EXPECT_TRUE(cv::imencode(".png", cv::Mat(rows, columns, CV_8UC1, cv::Scalar(7)), encoded));
  return std::string(encoded.begin(), encoded.end());
}

void put_big_endian(std::string& bytes, std::size_t at, std::uint32_t value) {
  for (int i = 0; i < 4; ++i) bytes[at + i] = static_cast<char>(value >> (24 - 8 * i));
}

// Both the header check at open and the decode refuse, naming the file and the cause, before
// the decoder allocates what the header claims (it used to take 2.1 GB and 11-24 s, or end in
// an OpenCV assertion without the file name).
void expect_png_refused(const fs::path& path, const std::string& bytes,
                        const std::string& fragment) {
  std::ofstream(path, std::ios::binary) << bytes;
  expect_error([&] { read_png_header(path); }, path.string(), fragment);
  expect_error([&] { read_polar_png(path, options(0.05)); }, path.string(), fragment);
}

TEST(PolarPngErrors, AbsurdHeaderDimensionsAreRefusedBeforeDecoding) {
  TempDir dir;
  std::string bytes = png_bytes(500, 400);
  put_big_endian(bytes, 16, 100000);  // IHDR width
  put_big_endian(bytes, 20, 100000);  // IHDR height
  expect_png_refused(dir.file("huge.png"), bytes,
                     "declares 100000 x 100000 pixels; each side must be in [1, 32768]");
  put_big_endian(bytes, 16, 20000);
  put_big_endian(bytes, 20, 20000);
  expect_png_refused(dir.file("many.png"), bytes, "at most 33554432 are accepted");
  // Within the limits, but more than the file's bytes can hold.
  put_big_endian(bytes, 16, 30000);
  put_big_endian(bytes, 20, 1000);
  expect_png_refused(dir.file("small_file.png"), bytes, "more than its");
  put_big_endian(bytes, 16, 0);
  expect_png_refused(dir.file("empty.png"), bytes, "declares 0 x 1000 pixels");
}

TEST(PolarPngErrors, AChunkLongerThanTheFileIsRefusedBeforeDecoding) {
  TempDir dir;
  const std::string valid = png_bytes(500, 400);
  // An ancillary text chunk declaring 2 GiB, right after IHDR (at byte 8 + 25 = 33).
  std::string chunk(12 + 4, 'x');
  put_big_endian(chunk, 0, 0x8000'0000u);
  chunk.replace(4, 4, "tEXt");
  std::string bytes = valid.substr(0, 33) + chunk + valid.substr(33);
  expect_png_refused(dir.file("chunk.png"), bytes,
                     "its 'tEXt' chunk at byte 33 declares 2147483648 bytes");
  // An image data chunk that runs past the end: found when decoded.
  bytes = valid;
  const std::size_t idat = bytes.find("IDAT") - 4;
  put_big_endian(bytes, idat, 0x7fff'ffffu);
  const fs::path path = dir.file("idat.png");
  std::ofstream(path, std::ios::binary) << bytes;
  expect_error([&] { read_polar_png(path, options(0.05)); }, path.string(),
               "its 'IDAT' chunk at byte");
}

TEST(PolarPngErrors, DirectoryInsteadOfFile) {
  TempDir dir;
  const fs::path path = dir.file("a_directory.png");
  fs::create_directories(path);
  expect_error([&] { read_polar_png(path, options(0.05)); }, path.string(), "not a regular file");
}

TEST(PolarPng, RoundTripsThroughAPngFile) {
  TempDir dir;
  const fs::path path = dir.file("hand.png");
  const ByteImage written = oxford_image(1'600'000'000'000'000, 625);
  ASSERT_TRUE(cv::imwrite(path.string(), opencv_view(written)));
  const DecodedPolarPng d = read_polar_png(path, options(0.05));
  EXPECT_EQ(d.layout, PolarPngLayout::oxford);
  EXPECT_EQ(d.image.azimuth_times_ns[1], 1'600'000'000'000'625'000);
  EXPECT_EQ(d.image.power(1, 2), 12);
}

// ---- Real MulRan KAIST03 frames: the native image and its oxford-form copy. ----

class MulranKaist03 : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!fs::exists(real_data("referee_mulran_kaist03/native/000000.png"))) {
      GTEST_SKIP() << "real MulRan sample not found under ../shared/data/real/"
                      "referee_mulran_kaist03; skipping";
    }
  }
  static DecodedPolarPng read(const std::string& form, const std::string& frame) {
    return read_polar_png(real_data("referee_mulran_kaist03/" + form + "/" + frame + ".png"),
                          options(kMulranResolution));
  }
};

TEST_F(MulranKaist03, NativeEqualsOxfordFormPixelForPixel) {
  // Only 000000 and 000001: native/000010 and oxford_form/000010 come from different commits
  // and hold different frames (they differ in ~970k of 1.34M pixels).
  for (const std::string frame : {"000000", "000001"}) {
    const DecodedPolarPng native = read("native", frame);
    const DecodedPolarPng oxford = read("oxford_form", frame);
    EXPECT_EQ(native.layout, PolarPngLayout::mulran_native) << frame;
    EXPECT_EQ(oxford.layout, PolarPngLayout::oxford) << frame;
    // 3360 rows x 400 columns transposed; 3371 columns - 11 metadata.
    ASSERT_EQ(native.image.power.rows(), 400) << frame;
    ASSERT_EQ(native.image.power.cols(), 3360) << frame;
    EXPECT_TRUE(native.image.power == oxford.image.power) << frame;
    EXPECT_NE(native.image.power, ByteImage(400, 3360)) << frame;  // not two blank images
    EXPECT_FALSE(native.timestamp_ns.has_value());
    EXPECT_TRUE(native.image.azimuth_times_ns.empty());
  }
}

TEST_F(MulranKaist03, OxfordFormTimestampsAreSaneNanoseconds) {
  // 2019-01-01 = 1546300800 s, 2020-01-01 = 1577836800 s (KAIST03 was recorded 2019-09-02).
  constexpr std::int64_t kStart2019 = 1'546'300'800'000'000'000;
  constexpr std::int64_t kStart2020 = 1'577'836'800'000'000'000;
  std::int64_t previous_last = 0;
  for (const std::string frame : {"000000", "000001", "000010"}) {
    const DecodedPolarPng d = read("oxford_form", frame);
    const auto& times = d.image.azimuth_times_ns;
    ASSERT_EQ(times.size(), 400u);
    EXPECT_GE(times.front(), kStart2019);
    EXPECT_LT(times.back(), kStart2020);
    EXPECT_TRUE(std::is_sorted(times.begin(), times.end())) << frame;
    // One revolution at 4 Hz: 399/400 of 0.25 s between the first and last azimuth.
    EXPECT_NEAR(static_cast<double>(times.back() - times.front()) * 1e-9, 0.249, 0.01) << frame;
    ASSERT_TRUE(d.timestamp_ns.has_value());
    EXPECT_EQ(*d.timestamp_ns, times[200]);
    EXPECT_GT(times.front(), previous_last);  // scans follow each other
    previous_last = times.back();
  }
  // SOURCE.md: frame 000000's last azimuth is 1567410201812840960 ns (the MulRan file name,
  // up to MATLAB rounding).
  EXPECT_EQ(read("oxford_form", "000000").image.azimuth_times_ns.back(), 1'567'410'201'812'840'960);
}

TEST_F(MulranKaist03, OxfordFormAzimuthsStepByPoint9Degrees) {
  const DecodedPolarPng d = read("oxford_form", "000000");
  const auto& az = d.image.azimuths_rad;
  ASSERT_EQ(az.size(), 400u);
  for (std::size_t a = 0; a < az.size(); ++a) {
    EXPECT_GE(az[a], 0.0);
    EXPECT_LT(az[a], 2 * kPi);
    // 360 / 400 = 0.9 degrees = 14 encoder counts.
    if (a > 0) {
      EXPECT_NEAR((az[a] - az[a - 1]) * 180 / kPi, 0.9, 1e-9) << a;
    }
  }
  EXPECT_EQ(d.row_flags, std::vector<std::uint8_t>(400, 255));
}

// ---- Real Oxford Radar RobotCar frame: µs stamps, 3768 bins. ----

TEST(OxfordRobotCar, MicrosecondStampsBecomeNanoseconds) {
  const fs::path path =
      real_data("oxford_radar_robotcar_tiny_radarslampy/radar/1547131046353776.png");
  if (!fs::exists(path)) {
    GTEST_SKIP() << "real Oxford sample not found under ../shared/data/real/"
                    "oxford_radar_robotcar_tiny_radarslampy; skipping";
  }
  const DecodedPolarPng d = read_polar_png(path, options(kOxfordResolution));
  EXPECT_EQ(d.layout, PolarPngLayout::oxford);
  EXPECT_EQ(d.image.power.rows(), 400);
  EXPECT_EQ(d.image.power.cols(), 3768);  // 3779 - 11 columns
  EXPECT_EQ(d.image.range_resolution_m, kOxfordResolution);
  const auto& times = d.image.azimuth_times_ns;
  ASSERT_EQ(times.size(), 400u);
  // Oxford names a scan by its first azimuth's µs stamp: x 1000 in ns.
  EXPECT_EQ(times.front(), 1'547'131'046'353'776'000);
  for (const std::int64_t t : times) EXPECT_EQ(t % 1000, 0);  // came from µs
  EXPECT_TRUE(std::is_sorted(times.begin(), times.end()));
  EXPECT_NEAR(static_cast<double>(times.back() - times.front()) * 1e-9, 0.25, 0.01);
}

}  // namespace
}  // namespace radarpr
