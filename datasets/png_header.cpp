#include "datasets/png_header.hpp"

#include <array>
#include <cstring>
#include <stdexcept>
#include <string>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <fmt/format.h>

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

}  // namespace

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
  if (std::memcmp(head.data(), kSignature.data(), kSignature.size()) != 0) {
    throw std::runtime_error(
        fmt::format("{}: not a PNG (the file does not start with the PNG signature)", name));
  }
  if (big_endian(head.data() + 8) != 13 || std::memcmp(head.data() + 12, "IHDR", 4) != 0) {
    throw std::runtime_error(
        fmt::format("{}: corrupt PNG, expected the IHDR chunk right after the signature", name));
  }
  if (std::memcmp(tail.data(), kIendChunk.data(), kIendChunk.size()) != 0) {
    throw std::runtime_error(
        fmt::format("{}: the PNG does not end with an IEND chunk ({} bytes): truncated, or still "
                    "being copied",
                    name, size));
  }
  PngHeader header;
  header.width = static_cast<int>(big_endian(head.data() + 16) & 0x7FFF'FFFFu);
  header.height = static_cast<int>(big_endian(head.data() + 20) & 0x7FFF'FFFFu);
  header.bit_depth = head[24];
  header.colour_type = head[25];
  return header;
}

}  // namespace radarpr
