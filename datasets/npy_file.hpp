#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace radarpr {

// numpy's .npy format (format versions 1.0 and 2.0): the exchange format for descriptor values,
// codebooks and anything else a Python user should open with np.load. Only what radarpr writes and
// reads is supported: little-endian uint8, float16, float32, float64 and int64 arrays in C order.
// Anything else (big-endian, Fortran order, object or structured dtypes, format 3.0) is refused
// with an error naming the file, never reinterpreted.

// int64: times in ns (precomputed descriptors' timestamps).
enum class NpyDtype { uint8, float16, float32, float64, int64 };

std::string_view to_string(NpyDtype dtype);  // "uint8", "float16", ...
std::size_t item_size(NpyDtype dtype);       // bytes per element

// A malformed, unsupported or unreadable .npy file; the message starts with the file's path.
class NpyError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A .npy file opened read-only and memory-mapped: the elements are read from the page cache on
// demand, so a large array costs no RAM up front. Copies share the mapping; it stays valid as long
// as one copy lives (replacing the file by rename, as write_npy does, does not disturb it).
class NpyFile {
 public:
  // Throws NpyError (missing file, bad magic, bad or unsupported header, size mismatch).
  static NpyFile open(const std::filesystem::path& path);

  const std::filesystem::path& path() const { return path_; }
  NpyDtype dtype() const { return dtype_; }
  // Dimensions, outermost first; empty for a 0-d (scalar) array.
  const std::vector<std::size_t>& shape() const { return shape_; }
  std::size_t element_count() const;
  std::size_t data_bytes() const { return element_count() * item_size(dtype_); }
  // The raw little-endian elements, C order. Empty span for an empty array.
  std::span<const std::byte> bytes() const;

  // The elements converted to float / double (any dtype). Throws NpyError for a float64 value
  // outside float's range in as_floats(), so that no value silently becomes infinity.
  std::vector<float> as_floats() const;
  std::vector<double> as_doubles() const;
  // The elements as int64: int64 and uint8 arrays only (a float array throws NpyError), so that
  // no time is rounded on the way.
  std::vector<std::int64_t> as_int64s() const;

 private:
  struct Mapping;
  std::filesystem::path path_;
  NpyDtype dtype_ = NpyDtype::float32;
  std::vector<std::size_t> shape_;
  std::shared_ptr<const Mapping> mapping_;
  std::size_t data_offset_ = 0;
};

// The bytes a .npy file of `dtype` and `shape` starts with (magic, version, header length and the
// header, padded so that the elements start 64-byte aligned), exactly as write_npy and numpy write
// them: a writer streaming its elements after them writes a file np.load opens.
std::string npy_file_header(NpyDtype dtype, const std::vector<std::size_t>& shape);

// Writes `bytes` (little-endian, C order) as a .npy array of `dtype` and `shape`. Atomic: the file
// is written beside `path` under a temporary name and renamed over it, so readers see the old file
// or the whole new one, never a half-written array. Throws std::invalid_argument when
// bytes.size() does not match dtype and shape, NpyError for I/O failures (naming the file).
void write_npy(const std::filesystem::path& path, NpyDtype dtype,
               const std::vector<std::size_t>& shape, std::span<const std::byte> bytes);

// Conveniences for the common element types.
void write_npy(const std::filesystem::path& path, const std::vector<std::size_t>& shape,
               std::span<const float> values);
void write_npy(const std::filesystem::path& path, const std::vector<std::size_t>& shape,
               std::span<const double> values);
void write_npy(const std::filesystem::path& path, const std::vector<std::size_t>& shape,
               std::span<const std::uint8_t> values);
void write_npy(const std::filesystem::path& path, const std::vector<std::size_t>& shape,
               std::span<const std::int64_t> values);

// IEEE 754 binary16 <-> binary32 conversion (float16 arrays). float_to_half rounds to nearest even
// and saturates to infinity, as numpy's astype(np.float16) does.
float half_to_float(std::uint16_t half);
std::uint16_t float_to_half(float value);

}  // namespace radarpr
