#include "datasets/npy_file.hpp"

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "tests/datasets/dataset_tree.hpp"

namespace radarpr {
namespace {

using test::TempTree;
namespace fs = std::filesystem;

// A .npy file written byte by byte: preamble for `major`, then `header` as given (no padding
// added), then `data`.
void write_raw(const fs::path& path, int major, const std::string& header,
               const std::string& data = "") {
  std::string bytes = "\x93NUMPY";
  bytes.push_back(static_cast<char>(major));
  bytes.push_back('\0');
  const int length_bytes = major == 1 ? 2 : 4;
  for (int i = 0; i < length_bytes; ++i) {
    bytes.push_back(static_cast<char>((header.size() >> (8 * i)) & 0xff));
  }
  std::ofstream(path, std::ios::binary) << bytes << header << data;
}

std::string float_bytes(const std::vector<float>& values) {
  return {reinterpret_cast<const char*>(values.data()), values.size() * sizeof(float)};
}

std::string error_of(const fs::path& path) {
  try {
    NpyFile::open(path);
  } catch (const NpyError& error) {
    return error.what();
  }
  return "no error";
}

std::string read_all(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

TEST(NpyFile, WritesExactlyWhatNumpySaveWrites) {
  // np.save(f, np.arange(6, dtype='<f4').reshape(2, 3)) with numpy 1.24: a 128-byte header whose
  // padding leaves room for the shape to grow.
  const TempTree tree;
  const std::vector<float> values{0, 1, 2, 3, 4, 5};
  write_npy(tree.path("a.npy"), {2, 3}, std::span<const float>(values));
  const std::string header = "{'descr': '<f4', 'fortran_order': False, 'shape': (2, 3), }";
  const std::string expected = std::string("\x93NUMPY\x01\x00v\x00", 10) + header +
                               std::string(128 - 10 - header.size() - 1, ' ') + "\n" +
                               float_bytes(values);
  EXPECT_EQ(read_all(tree.path("a.npy")), expected);
}

TEST(NpyFile, RoundTripsEveryDtypeAndShape) {
  const TempTree tree;
  const std::vector<double> doubles{1.5, -2.25, 1e300, 0.0};
  write_npy(tree.path("d.npy"), {4}, std::span<const double>(doubles));
  const NpyFile d = NpyFile::open(tree.path("d.npy"));
  EXPECT_EQ(d.dtype(), NpyDtype::float64);
  EXPECT_EQ(d.shape(), (std::vector<std::size_t>{4}));
  EXPECT_EQ(d.as_doubles(), doubles);

  const std::vector<std::uint8_t> bytes{0, 7, 255, 128, 1, 2};
  write_npy(tree.path("u.npy"), {1, 2, 3}, std::span<const std::uint8_t>(bytes));
  const NpyFile u = NpyFile::open(tree.path("u.npy"));
  EXPECT_EQ(u.dtype(), NpyDtype::uint8);
  EXPECT_EQ(u.shape(), (std::vector<std::size_t>{1, 2, 3}));
  EXPECT_EQ(u.as_floats(), (std::vector<float>{0, 7, 255, 128, 1, 2}));
  EXPECT_EQ(u.bytes().size(), 6u);
  // The data start is 64-byte aligned in the mapping, as numpy aligns it.
  EXPECT_EQ(reinterpret_cast<std::uintptr_t>(u.bytes().data()) % 64, 0u);

  const std::vector<std::uint16_t> halves{float_to_half(1.0f), float_to_half(-0.5f),
                                          float_to_half(65504.0f)};
  write_npy(tree.path("h.npy"), NpyDtype::float16, {3}, std::as_bytes(std::span(halves)));
  const NpyFile h = NpyFile::open(tree.path("h.npy"));
  EXPECT_EQ(h.dtype(), NpyDtype::float16);
  EXPECT_EQ(h.as_floats(), (std::vector<float>{1.0f, -0.5f, 65504.0f}));

  const std::vector<std::int64_t> times{1574859771744660272, -5};
  write_npy(tree.path("t.npy"), {2}, std::span<const std::int64_t>(times));
  const NpyFile t = NpyFile::open(tree.path("t.npy"));
  EXPECT_EQ(t.dtype(), NpyDtype::int64);
  EXPECT_EQ(t.as_int64s(), times);
  EXPECT_THROW(d.as_int64s(), NpyError);  // floats are not silently truncated

  write_npy(tree.path("scalar.npy"), {}, std::span<const float>(std::vector<float>{3.5f}));
  const NpyFile scalar = NpyFile::open(tree.path("scalar.npy"));
  EXPECT_TRUE(scalar.shape().empty());
  EXPECT_EQ(scalar.as_floats(), std::vector<float>{3.5f});

  write_npy(tree.path("empty.npy"), {0, 5}, std::span<const float>());
  const NpyFile empty = NpyFile::open(tree.path("empty.npy"));
  EXPECT_EQ(empty.shape(), (std::vector<std::size_t>{0, 5}));
  EXPECT_EQ(empty.element_count(), 0u);
  EXPECT_TRUE(empty.as_floats().empty());
}

TEST(NpyFile, ReadsVersion2AndHandWrittenHeaders) {
  const TempTree tree;
  // Version 2.0 (32-bit header length), double quotes, keys in another order, no trailing comma.
  write_raw(tree.path("v2.npy"), 2,
            "{\"shape\": (2,), \"fortran_order\": False, \"descr\": \"<f4\"}    \n",
            float_bytes({1.0f, 2.0f}));
  const NpyFile file = NpyFile::open(tree.path("v2.npy"));
  EXPECT_EQ(file.shape(), (std::vector<std::size_t>{2}));
  EXPECT_EQ(file.as_floats(), (std::vector<float>{1.0f, 2.0f}));
}

TEST(NpyFile, WritesVersion2WhenTheHeaderOutgrowsVersion1) {
  const TempTree tree;
  std::vector<std::size_t> shape(30000, 1);  // "1, " x 30000: a header beyond 64 KiB
  write_npy(tree.path("big.npy"), shape, std::span<const float>(std::vector<float>{9.0f}));
  EXPECT_EQ(read_all(tree.path("big.npy"))[6], '\x02');
  const NpyFile file = NpyFile::open(tree.path("big.npy"));
  EXPECT_EQ(file.shape().size(), 30000u);
  EXPECT_EQ(file.as_floats(), std::vector<float>{9.0f});
}

TEST(NpyFile, RefusesWhatItDoesNotSupportNamingTheFile) {
  const TempTree tree;
  const auto header = [](const std::string& dict) { return dict + "\n"; };
  struct Case {
    std::string name;
    int major;
    std::string header;
    std::string data;
    std::string expected;
  };
  const std::string ok_data = float_bytes({1, 2});
  const std::vector<Case> cases{
      {"big_endian", 1, header("{'descr': '>f4', 'fortran_order': False, 'shape': (2,), }"),
       ok_data, "big-endian dtype '>f4'"},
      {"int32", 1, header("{'descr': '<i4', 'fortran_order': False, 'shape': (2,), }"), ok_data,
       "dtype '<i4' is not supported"},
      {"object", 1, header("{'descr': '|O', 'fortran_order': False, 'shape': (2,), }"), ok_data,
       "dtype '|O' is not supported"},
      {"fortran", 1, header("{'descr': '<f4', 'fortran_order': True, 'shape': (2,), }"), ok_data,
       "Fortran-order"},
      {"truncated", 1, header("{'descr': '<f4', 'fortran_order': False, 'shape': (3,), }"), ok_data,
       "needs 12 data bytes, the file has 8 (truncated)"},
      {"trailing", 1, header("{'descr': '<f4', 'fortran_order': False, 'shape': (1,), }"), ok_data,
       "trailing bytes"},
      {"not_a_tuple", 1, header("{'descr': '<f4', 'fortran_order': False, 'shape': (2), }"),
       ok_data, "one-dimensional shape is written (n,)"},
      {"negative", 1, header("{'descr': '<f4', 'fortran_order': False, 'shape': (-2,), }"), ok_data,
       "non-negative integer"},
      {"extra_key", 1, header("{'descr': '<f4', 'fortran_order': False, 'shape': (2,), 'x': 1, }"),
       ok_data, "unexpected key 'x'"},
      {"missing_key", 1, header("{'descr': '<f4', 'shape': (2,), }"), ok_data,
       "must name 'descr', 'fortran_order' and 'shape'"},
      {"duplicate_key", 1,
       header("{'descr': '<f4', 'descr': '<f4', 'fortran_order': False, 'shape': (2,), }"), ok_data,
       "'descr' appears twice"},
      {"no_newline", 1, "{'descr': '<f4', 'fortran_order': False, 'shape': (2,), }", ok_data,
       "does not end in"},
      {"version3", 3, header("{'descr': '<f4', 'fortran_order': False, 'shape': (2,), }"), ok_data,
       "version 3.0 is not supported"},
      {"overflow", 1,
       header("{'descr': '<f4', 'fortran_order': False, 'shape': (99999999999, 99999999999), }"),
       ok_data, "overflows"},
  };
  for (const Case& c : cases) {
    const fs::path path = tree.path(c.name + ".npy");
    write_raw(path, c.major, c.header, c.data);
    const std::string error = error_of(path);
    EXPECT_NE(error.find(path.string()), std::string::npos) << c.name << ": " << error;
    EXPECT_NE(error.find(c.expected), std::string::npos) << c.name << ": " << error;
  }

  std::ofstream(tree.path("text.npy")) << "hello, this is not numpy";
  EXPECT_NE(error_of(tree.path("text.npy")).find("no \\x93NUMPY magic"), std::string::npos);
  std::ofstream(tree.path("short.npy")) << "\x93NUM";
  EXPECT_NE(error_of(tree.path("short.npy")).find("shorter than the format's preamble"),
            std::string::npos);
  write_raw(tree.path("cut_header.npy"), 1, "");
  std::ofstream(tree.path("cut_header.npy"), std::ios::app) << "{'de";
  EXPECT_NE(error_of(tree.path("cut_header.npy")).find("does not end in"), std::string::npos);
  EXPECT_NE(error_of(tree.path("absent.npy")).find("absent.npy: cannot open"), std::string::npos);
  EXPECT_NE(error_of(tree.root()).find("not a regular file"), std::string::npos);
}

TEST(NpyFile, FloatConversionRefusesValuesOutsideFloat32) {
  const TempTree tree;
  write_npy(tree.path("huge.npy"), {2}, std::span<const double>(std::vector<double>{1.0, 1e300}));
  const NpyFile file = NpyFile::open(tree.path("huge.npy"));
  EXPECT_THROW(file.as_floats(), NpyError);
  EXPECT_EQ(file.as_doubles()[1], 1e300);
}

TEST(NpyFile, WriteIsAtomicAndLeavesAnOpenMappingIntact) {
  const TempTree tree;
  const fs::path path = tree.path("values.npy");
  write_npy(path, {2}, std::span<const float>(std::vector<float>{1, 2}));
  const NpyFile before = NpyFile::open(path);
  write_npy(path, {3}, std::span<const float>(std::vector<float>{7, 8, 9}));
  // The old mapping still reads the old file; a new open reads the new one.
  EXPECT_EQ(before.as_floats(), (std::vector<float>{1, 2}));
  EXPECT_EQ(NpyFile::open(path).as_floats(), (std::vector<float>{7, 8, 9}));
  // No temporary file stays behind.
  int files = 0;
  for ([[maybe_unused]] const auto& entry : fs::directory_iterator(tree.root())) ++files;
  EXPECT_EQ(files, 1);

  // Wrong byte count: refused before anything is written.
  const std::vector<float> three{1, 2, 3};
  EXPECT_THROW(write_npy(tree.path("bad.npy"), {2, 2}, std::span<const float>(three)),
               std::invalid_argument);
  EXPECT_FALSE(fs::exists(tree.path("bad.npy")));
  // An unwritable place: an error naming the file, nothing left behind.
  try {
    write_npy(tree.path("no/such/dir/x.npy"), {3}, std::span<const float>(three));
    ADD_FAILURE() << "expected NpyError";
  } catch (const NpyError& error) {
    EXPECT_NE(std::string(error.what()).find("x.npy"), std::string::npos) << error.what();
  }
}

TEST(NpyFile, HalfPrecisionConversionRoundTripsEveryHalfAndRoundsToNearestEven) {
  for (std::uint32_t bits = 0; bits <= 0xffff; ++bits) {
    const auto half = static_cast<std::uint16_t>(bits);
    const float value = half_to_float(half);
    if (std::isnan(value)) {
      EXPECT_TRUE(std::isnan(half_to_float(float_to_half(value))));
      continue;
    }
    ASSERT_EQ(float_to_half(value), half) << "half bits " << bits;
  }
  EXPECT_EQ(half_to_float(0x3c00), 1.0f);
  EXPECT_EQ(half_to_float(0x0001), std::ldexp(1.0f, -24));  // smallest subnormal
  EXPECT_EQ(float_to_half(65519.0f), 0x7bff);               // rounds down to the largest half
  EXPECT_EQ(float_to_half(65520.0f), 0x7c00);               // rounds up to infinity
  EXPECT_EQ(float_to_half(1.0f + std::ldexp(1.0f, -11)), 0x3c00);      // tie: to even (1.0)
  EXPECT_EQ(float_to_half(1.0f + 3 * std::ldexp(1.0f, -11)), 0x3c02);  // tie: to even (up)
  EXPECT_EQ(float_to_half(std::ldexp(1.0f, -26)), 0x0000);  // below half the smallest: zero
  EXPECT_EQ(float_to_half(-std::numeric_limits<float>::infinity()), 0xfc00);
}

}  // namespace
}  // namespace radarpr
