#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace radarpr {

// What a PNG file says about itself without being decoded: its IHDR chunk.
struct PngHeader {
  int width = 0;
  int height = 0;
  int bit_depth = 0;    // bits per sample: 8 for the radar PNGs
  int colour_type = 0;  // 0 = grayscale
};

// The largest radar PNG accepted: no sensor comes near (Navtech scans are at most a few thousand
// range bins by a few thousand azimuths), and a header claiming more is corrupt or hostile. A
// decode is thereby bounded (2^25 pixels of at most 8 bytes: 256 MiB) by these limits, never by
// what a header claims.
inline constexpr std::uint32_t kMaxPngSide = 32768;
inline constexpr std::uint64_t kMaxPngPixels = std::uint64_t{1} << 25;

// Checks a header against the limits above and against the file's size (deflate compresses at
// most 1032:1, so a small file cannot hold a huge image). Throws std::runtime_error naming
// `name` and the limit.
void check_png_geometry(const PngHeader& header, std::uint64_t file_size, const std::string& name);

// Reads the first 26 bytes (signature, IHDR) and the last 12 (the IEND chunk) of a PNG: a cheap
// check of every scan when a sequence opens, so a truncated or wrong-size file is found before
// hours of extraction rather than during them. Throws std::runtime_error naming the file when it
// cannot be read, is not a PNG, has no IHDR chunk first, or does not end with an IEND chunk
// (truncated, or still being copied); or when its geometry or the length of a chunk before the
// image data fails the checks above.
PngHeader read_png_header(const std::filesystem::path& path);

// A PNG file read front to back through a small buffer, checked as it goes: the signature and
// IHDR (geometry as above, against the file's size) when it opens, and every chunk's length
// (against the bytes left) and CRC before any byte of that chunk is handed on, up to an IEND. So
// a decoder fed from it never sees a byte of a damaged or truncated chunk, nor a header the file
// cannot back, without the whole file in memory: reading a 1.35 MB scan whole into a buffer
// took ~330 fresh pages in every `radarpr extract`. Not copyable; one reader per thread.
class CheckedPngFile {
 public:
  // Opens the file and checks its signature and IHDR chunk. Throws std::runtime_error naming
  // `path` when it cannot be read or fails a check.
  explicit CheckedPngFile(const std::filesystem::path& path);
  ~CheckedPngFile();
  CheckedPngFile(const CheckedPngFile&) = delete;
  CheckedPngFile& operator=(const CheckedPngFile&) = delete;

  const PngHeader& header() const { return header_; }
  std::uint64_t size() const { return size_; }

  // The next `count` bytes of the file into `out`. Throws std::runtime_error naming the file
  // when a chunk they belong to fails its checks, the file ends without an IEND chunk, or a
  // read fails (a file cut short while read included: no signal, an error).
  void read(std::uint8_t* out, std::size_t count);

 private:
  void check_next_chunk();
  void buffer_range(std::uint64_t from, std::size_t count);

  std::string name_;
  int fd_ = -1;
  std::uint64_t size_ = 0;
  PngHeader header_;
  std::vector<std::uint8_t>& buffer_;  // the thread's, reused from one file to the next
  std::uint64_t buffer_begin_ = 0;     // file offset of buffer_[0]
  std::uint64_t buffer_end_ = 0;       // file offset past the last byte buffered
  std::uint64_t handed_on_ = 0;        // file offset of the next byte read() gives
  std::uint64_t checked_until_ = 0;    // bytes before this offset belong to checked chunks
  bool ended_ = false;                 // the IEND chunk is checked
};

}  // namespace radarpr
