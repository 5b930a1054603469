#include "datasets/png_header.hpp"

#include <algorithm>
#include <array>
#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <string>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <fmt/format.h>
#include <libdeflate.h>

namespace radarpr {
namespace {

constexpr std::array<std::uint8_t, 8> kSignature = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
// Length 0, type "IEND", CRC of "IEND": the same 12 bytes end every complete PNG.
constexpr std::array<std::uint8_t, 12> kIendChunk = {0,   0,   0,    0,    'I',  'E',
                                                     'N', 'D', 0xAE, 0x42, 0x60, 0x82};
// Signature (8), IHDR length and type (8), width, height (8), bit depth, colour type (2).
constexpr std::size_t kHeadBytes = 26;
constexpr std::size_t kSmallestPng = 8 + 25 + 12;  // signature, IHDR chunk, IEND chunk

std::uint32_t big_endian(const std::uint8_t* bytes) {
  return (std::uint32_t{bytes[0]} << 24) | (std::uint32_t{bytes[1]} << 16) |
         (std::uint32_t{bytes[2]} << 8) | std::uint32_t{bytes[3]};
}

// Closes the descriptor however the reading ends.
class File {
 public:
  explicit File(const std::string& path) : fd_(::open(path.c_str(), O_RDONLY | O_CLOEXEC)) {}
  ~File() {
    if (fd_ >= 0) ::close(fd_);
  }
  File(const File&) = delete;
  File& operator=(const File&) = delete;
  int fd() const { return fd_; }

 private:
  int fd_;
};

bool read_at(int fd, std::uint8_t* out, std::size_t count, off_t offset) {
  std::size_t done = 0;
  while (done < count) {
    const ssize_t got = ::pread(fd, out + done, count - done, offset + static_cast<off_t>(done));
    if (got <= 0) return false;
    done += static_cast<std::size_t>(got);
  }
  return true;
}

// Bytes per pixel sample, in bits, for an IHDR colour type (0 when the type is not valid).
int samples_per_pixel(int colour_type) {
  switch (colour_type) {
    case 0:
      return 1;  // grayscale
    case 2:
      return 3;  // RGB
    case 3:
      return 1;  // palette
    case 4:
      return 2;  // grayscale + alpha
    case 6:
      return 4;  // RGBA
    default:
      return 0;
  }
}

PngHeader parse_ihdr(const std::uint8_t* head, const std::string& name) {
  if (std::memcmp(head, kSignature.data(), kSignature.size()) != 0) {
    throw std::runtime_error(
        fmt::format("{}: not a PNG (the file does not start with the PNG signature)", name));
  }
  if (big_endian(head + 8) != 13 || std::memcmp(head + 12, "IHDR", 4) != 0) {
    throw std::runtime_error(
        fmt::format("{}: corrupt PNG, expected the IHDR chunk right after the signature", name));
  }
  const std::uint32_t width = big_endian(head + 16), height = big_endian(head + 20);
  if (width == 0 || height == 0 || width > kMaxPngSide || height > kMaxPngSide) {
    throw std::runtime_error(fmt::format(
        "{}: the PNG header declares {} x {} pixels; each side must be in [1, {}] (corrupt "
        "header?)",
        name, width, height, kMaxPngSide));
  }
  PngHeader header;
  header.width = static_cast<int>(width);
  header.height = static_cast<int>(height);
  header.bit_depth = head[24];
  header.colour_type = head[25];
  return header;
}

// A chunk type for a message: its four letters, anything else as '?'.
std::string chunk_name(const char* type) {
  std::string text(type, 4);
  for (char& c : text) {
    if (!((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'))) c = '?';
  }
  return text;
}

// The chunk after the one at `offset` (its length checked against the file), or throws.
std::uint64_t next_chunk(std::uint32_t length, std::uint64_t offset, std::uint64_t size,
                         const char* type, const std::string& name) {
  const std::uint64_t end = offset + 12 + std::uint64_t{length};  // length, type, data, CRC
  if (end > size) {
    throw std::runtime_error(fmt::format(
        "{}: corrupt PNG, its '{}' chunk at byte {} declares {} bytes but the file ends {} "
        "bytes later",
        name, chunk_name(type), offset, length, size - offset));
  }
  return end;
}

}  // namespace

void check_png_geometry(const PngHeader& header, std::uint64_t file_size, const std::string& name) {
  const auto width = static_cast<std::uint64_t>(header.width);
  const auto height = static_cast<std::uint64_t>(header.height);
  if (width * height > kMaxPngPixels) {
    throw std::runtime_error(fmt::format(
        "{}: the PNG header declares {} x {} = {} pixels; at most {} are accepted (no radar "
        "scan is that large: corrupt header?)",
        name, width, height, width * height, kMaxPngPixels));
  }
  const int samples = samples_per_pixel(header.colour_type);
  const int depth = header.bit_depth;
  if (samples == 0 || !(depth == 1 || depth == 2 || depth == 4 || depth == 8 || depth == 16)) {
    throw std::runtime_error(fmt::format("{}: corrupt PNG header (bit depth {}, colour type {})",
                                         name, depth, header.colour_type));
  }
  // One filter byte per row, then the packed samples.
  const std::uint64_t raw =
      height * (1 + (width * static_cast<std::uint64_t>(samples * depth) + 7) / 8);
  constexpr std::uint64_t kDeflateRatio = 1032;
  if (raw > kDeflateRatio * file_size + 65536) {
    throw std::runtime_error(fmt::format(
        "{}: the PNG header declares {} x {} pixels ({} bytes decoded), more than its {} bytes "
        "can hold (corrupt header?)",
        name, width, height, raw, file_size));
  }
}

PngHeader read_png_header(const std::filesystem::path& path) {
  const std::string name = path.string();
  const File file(name);
  struct stat info {};
  if (file.fd() < 0 || ::fstat(file.fd(), &info) != 0 || !S_ISREG(info.st_mode)) {
    throw std::runtime_error(fmt::format("{}: cannot be read ({}), expected a PNG file", name,
                                         file.fd() < 0 ? std::strerror(errno) : "not a file"));
  }
  const auto size = static_cast<std::size_t>(info.st_size);
  if (size < kSmallestPng) {
    throw std::runtime_error(
        fmt::format("{}: {} bytes, too short for a PNG (at least {}): truncated or empty", name,
                    size, kSmallestPng));
  }
  std::array<std::uint8_t, kHeadBytes> head{};
  std::array<std::uint8_t, kIendChunk.size()> tail{};
  if (!read_at(file.fd(), head.data(), head.size(), 0) ||
      !read_at(file.fd(), tail.data(), tail.size(), static_cast<off_t>(size - kIendChunk.size()))) {
    throw std::runtime_error(fmt::format("{}: could not read its {} bytes", name, size));
  }
  const PngHeader header = parse_ihdr(head.data(), name);
  if (std::memcmp(tail.data(), kIendChunk.data(), kIendChunk.size()) != 0) {
    throw std::runtime_error(
        fmt::format("{}: the PNG does not end with an IEND chunk ({} bytes): truncated, or still "
                    "being copied",
                    name, size));
  }
  check_png_geometry(header, size, name);
  // The chunks before the image data (ancillary ones, where a huge declared length made the
  // decoder allocate gigabytes): a few reads. The data chunks are checked when decoded.
  std::uint64_t offset = 8;
  for (int chunks = 0; chunks < 64 && offset + 12 <= size; ++chunks) {
    std::array<std::uint8_t, 8> chunk{};
    if (!read_at(file.fd(), chunk.data(), chunk.size(), static_cast<off_t>(offset))) break;
    const char* type = reinterpret_cast<const char*>(chunk.data() + 4);
    if (std::memcmp(type, "IDAT", 4) == 0) break;
    offset = next_chunk(big_endian(chunk.data()), offset, size, type, name);
  }
  return header;
}

namespace {

// 128 KiB: libpng asks for image data 8 KiB at a time, and the chunks of common writers (libpng
// and OpenCV: 8 KiB, Pillow: 64 KiB) fit whole, so each is checked in the buffer and handed on
// from it. A larger chunk is read twice: once for its CRC, once to hand it on.
constexpr std::size_t kCheckedReadBuffer = std::size_t{128} << 10;

std::vector<std::uint8_t>& thread_read_buffer() {
  thread_local std::vector<std::uint8_t> buffer;
  if (buffer.size() != kCheckedReadBuffer) buffer.resize(kCheckedReadBuffer);
  return buffer;
}

}  // namespace

CheckedPngFile::CheckedPngFile(const std::filesystem::path& path)
    : name_(path.string()), buffer_(thread_read_buffer()) {
  fd_ = ::open(name_.c_str(), O_RDONLY | O_CLOEXEC);
  struct stat info {};
  if (fd_ < 0 || ::fstat(fd_, &info) != 0 || !S_ISREG(info.st_mode)) {
    const std::string why = fd_ < 0 ? std::strerror(errno) : "not a file";
    if (fd_ >= 0) ::close(fd_);
    throw std::runtime_error(
        fmt::format("{}: cannot be read ({}), expected a PNG file", name_, why));
  }
  size_ = static_cast<std::uint64_t>(info.st_size);
  try {
    if (size_ < kSmallestPng) {
      throw std::runtime_error(
          fmt::format("{}: {} bytes, too short for a PNG (at least {}): truncated or empty", name_,
                      size_, kSmallestPng));
    }
    buffer_range(0, kHeadBytes);
    header_ = parse_ihdr(buffer_.data(), name_);
    check_png_geometry(header_, size_, name_);
  } catch (...) {
    ::close(fd_);
    throw;
  }
  checked_until_ = kSignature.size();
}

CheckedPngFile::~CheckedPngFile() {
  ::close(fd_);
}

void CheckedPngFile::read(std::uint8_t* out, std::size_t count) {
  while (count > 0) {
    if (handed_on_ == checked_until_) check_next_chunk();
    const auto part = static_cast<std::size_t>(
        std::min<std::uint64_t>({count, checked_until_ - handed_on_, buffer_.size()}));
    buffer_range(handed_on_, part);
    std::memcpy(out, buffer_.data() + (handed_on_ - buffer_begin_), part);
    handed_on_ += part;
    out += part;
    count -= part;
  }
}

void CheckedPngFile::check_next_chunk() {
  const std::uint64_t offset = checked_until_;
  if (ended_) {
    throw std::runtime_error(
        fmt::format("{}: corrupt PNG, the decoder asks for bytes after its IEND chunk", name_));
  }
  if (offset + 12 > size_) {
    throw std::runtime_error(
        fmt::format("{}: the PNG has no IEND chunk ({} bytes): truncated, or still being copied",
                    name_, size_));
  }
  buffer_range(offset, 8);
  const std::uint8_t* head = buffer_.data() + (offset - buffer_begin_);
  const std::uint32_t length = big_endian(head);
  char type[4];
  std::memcpy(type, head + 4, 4);
  const std::uint64_t end = next_chunk(length, offset, size_, type, name_);
  // The CRC covers the type and the data. libdeflate's folds with carry-less multiplication where
  // the processor has it: zlib's crc32_z took about 0.2 ms of the 0.9 ms a 1.35 MB MulRan scan
  // took to decode in a running process (`radarpr bench`, png_decode).
  std::uint32_t crc = 0;
  for (std::uint64_t at = offset + 4; at < end - 4;) {
    const auto part =
        static_cast<std::size_t>(std::min<std::uint64_t>(end - 4 - at, buffer_.size()));
    buffer_range(at, part);
    crc = libdeflate_crc32(crc, buffer_.data() + (at - buffer_begin_), part);
    at += part;
  }
  buffer_range(end - 4, 4);
  if (crc != big_endian(buffer_.data() + (end - 4 - buffer_begin_))) {
    throw std::runtime_error(
        fmt::format("{}: corrupt PNG, its '{}' chunk at byte {} fails its CRC check (damaged file)",
                    name_, chunk_name(type), offset));
  }
  ended_ = std::memcmp(type, "IEND", 4) == 0;
  checked_until_ = end;
}

// Makes the file's bytes [from, from + count) present in the buffer (count at most its size),
// keeping those already there from `from` on and reading as many after them as fit.
void CheckedPngFile::buffer_range(std::uint64_t from, std::size_t count) {
  if (from >= buffer_begin_ && from + count <= buffer_end_) return;
  std::size_t kept = 0;
  if (from >= buffer_begin_ && from < buffer_end_) {
    kept = static_cast<std::size_t>(buffer_end_ - from);
    std::memmove(buffer_.data(), buffer_.data() + (from - buffer_begin_), kept);
  }
  buffer_begin_ = from;
  buffer_end_ = from + kept;
  const auto wanted =
      static_cast<std::size_t>(std::min<std::uint64_t>(buffer_.size(), size_ - from)) - kept;
  if (from + count > size_ ||
      !read_at(fd_, buffer_.data() + kept, wanted, static_cast<off_t>(buffer_end_))) {
    throw std::runtime_error(
        fmt::format("{}: could not read its {} bytes (cut short while being read?)", name_, size_));
  }
  buffer_end_ += wanted;
}

}  // namespace radarpr
