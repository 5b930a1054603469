#include "datasets/npy_file.hpp"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <bit>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <optional>

#include <fmt/format.h>
#include <fmt/ranges.h>

namespace radarpr {

// The elements are handed out as stored; a big-endian host would need byte swapping.
static_assert(std::endian::native == std::endian::little,
              "radarpr's .npy I/O assumes little-endian");

namespace {

constexpr std::string_view kMagic = "\x93NUMPY";
constexpr std::size_t kPreambleV1 = 10;  // magic, 2 version bytes, uint16 header length
constexpr std::size_t kPreambleV2 = 12;  // ... uint32 header length
constexpr std::size_t kHeaderAlignment = 64;
constexpr std::size_t kShapeGrowthRoom = 21;  // numpy's GROWTH_AXIS_MAX_DIGITS

std::string quoted(const std::filesystem::path& path) {
  return path.string();
}

[[noreturn]] void fail(const std::filesystem::path& path, std::string_view what) {
  throw NpyError(fmt::format("{}: {}", quoted(path), what));
}

// numpy's type strings for the supported dtypes. uint8 has no byte order: numpy writes '|u1'.
struct DescrName {
  std::string_view descr;
  NpyDtype dtype;
};
constexpr DescrName kDescrs[] = {
    {"|u1", NpyDtype::uint8},   {"<u1", NpyDtype::uint8},   {"<f2", NpyDtype::float16},
    {"<f4", NpyDtype::float32}, {"<f8", NpyDtype::float64}, {"<i8", NpyDtype::int64},
};

std::string_view descr_of(NpyDtype dtype) {
  switch (dtype) {
    case NpyDtype::uint8:
      return "|u1";
    case NpyDtype::float16:
      return "<f2";
    case NpyDtype::float32:
      return "<f4";
    case NpyDtype::float64:
      return "<f8";
    case NpyDtype::int64:
      return "<i8";
  }
  return "?";
}

// A strict reader of the header's Python dict literal, e.g.
// {'descr': '<f4', 'fortran_order': False, 'shape': (3, 4), }
// Exactly the three keys, each once; a shape is a tuple of non-negative integers written as
// Python writes it ("()" , "(5,)", "(3, 4)").
class HeaderParser {
 public:
  HeaderParser(std::string_view text, const std::filesystem::path& path)
      : text_(text), path_(path) {}

  struct Header {
    NpyDtype dtype;
    std::vector<std::size_t> shape;
  };

  Header parse() {
    skip_spaces();
    expect('{');
    std::optional<std::string> descr;
    std::optional<bool> fortran_order;
    std::optional<std::vector<std::size_t>> shape;
    skip_spaces();
    while (peek() != '}') {
      const std::string key = string_literal();
      skip_spaces();
      expect(':');
      skip_spaces();
      if (key == "descr") {
        if (descr) bad("'descr' appears twice");
        descr = string_literal();
      } else if (key == "fortran_order") {
        if (fortran_order) bad("'fortran_order' appears twice");
        fortran_order = boolean();
      } else if (key == "shape") {
        if (shape) bad("'shape' appears twice");
        shape = tuple();
      } else {
        bad(fmt::format("unexpected key '{}' (expected descr, fortran_order, shape)", key));
      }
      skip_spaces();
      if (peek() == ',') {
        ++pos_;
        skip_spaces();
      } else if (peek() != '}') {
        bad("expected ',' or '}' after a value");
      }
    }
    ++pos_;
    skip_spaces();
    if (pos_ != text_.size()) bad("text after the closing '}'");
    if (!descr || !fortran_order || !shape) {
      bad("the header must name 'descr', 'fortran_order' and 'shape'");
    }
    if (*fortran_order) {
      fail(path_, "Fortran-order arrays are not supported (write np.ascontiguousarray(a))");
    }
    return {dtype_from(*descr), std::move(*shape)};
  }

 private:
  [[noreturn]] void bad(std::string_view what) const {
    fail(path_, fmt::format("malformed .npy header at character {}: {}", pos_, what));
  }
  char peek() const { return pos_ < text_.size() ? text_[pos_] : '\0'; }
  void skip_spaces() {
    while (pos_ < text_.size() && (text_[pos_] == ' ' || text_[pos_] == '\n')) ++pos_;
  }
  void expect(char c) {
    if (peek() != c) bad(fmt::format("expected '{}'", c));
    ++pos_;
  }
  std::string string_literal() {
    const char quote = peek();
    if (quote != '\'' && quote != '"') bad("expected a quoted string");
    const std::size_t end = text_.find(quote, pos_ + 1);
    if (end == std::string_view::npos) bad("unterminated string");
    std::string value(text_.substr(pos_ + 1, end - pos_ - 1));
    pos_ = end + 1;
    return value;
  }
  bool boolean() {
    if (text_.substr(pos_, 4) == "True") {
      pos_ += 4;
      return true;
    }
    if (text_.substr(pos_, 5) == "False") {
      pos_ += 5;
      return false;
    }
    bad("expected True or False");
  }
  std::size_t integer() {
    const std::size_t start = pos_;
    std::size_t value = 0;
    while (pos_ < text_.size() && text_[pos_] >= '0' && text_[pos_] <= '9') {
      const auto digit = static_cast<std::size_t>(text_[pos_] - '0');
      if (value > (std::numeric_limits<std::size_t>::max() - digit) / 10)
        bad("dimension too large");
      value = value * 10 + digit;
      ++pos_;
    }
    if (pos_ == start) bad("expected a non-negative integer dimension");
    return value;
  }
  std::vector<std::size_t> tuple() {
    expect('(');
    std::vector<std::size_t> dims;
    skip_spaces();
    bool trailing_comma = false;
    while (peek() != ')') {
      dims.push_back(integer());
      skip_spaces();
      trailing_comma = false;
      if (peek() == ',') {
        ++pos_;
        trailing_comma = true;
        skip_spaces();
      } else if (peek() != ')') {
        bad("expected ',' or ')' in the shape");
      }
    }
    // "(5)" is the integer 5 in Python, not a shape.
    if (dims.size() == 1 && !trailing_comma) bad("a one-dimensional shape is written (n,)");
    ++pos_;
    return dims;
  }
  NpyDtype dtype_from(const std::string& descr) const {
    for (const auto& known : kDescrs) {
      if (descr == known.descr) return known.dtype;
    }
    if (descr.size() == 3 && descr[0] == '>') {
      fail(path_, fmt::format("big-endian dtype '{}' is not supported (write a.astype('<{}'))",
                              descr, descr.substr(1)));
    }
    fail(path_, fmt::format("dtype '{}' is not supported (expected uint8, float16, float32 or "
                            "float64 or int64, little-endian)",
                            descr));
  }

  std::string_view text_;
  const std::filesystem::path& path_;
  std::size_t pos_ = 0;
};

std::size_t checked_product(const std::vector<std::size_t>& dims, std::size_t item,
                            const std::filesystem::path& path) {
  std::size_t product = item;
  for (const std::size_t dim : dims) {
    if (dim != 0 && product > std::numeric_limits<std::size_t>::max() / dim) {
      fail(path, "the shape's size overflows");
    }
    product *= dim;
  }
  return product;
}

std::string shape_text(const std::vector<std::size_t>& shape) {
  if (shape.size() == 1) return fmt::format("({},)", shape[0]);
  return fmt::format("({})", fmt::join(shape, ", "));
}

std::uint32_t read_le(const std::byte* bytes, std::size_t count) {
  std::uint32_t value = 0;
  for (std::size_t i = 0; i < count; ++i) {
    value |= static_cast<std::uint32_t>(bytes[i]) << (8 * i);
  }
  return value;
}

template <typename T>
T load(const std::byte* bytes) {
  T value;
  std::memcpy(&value, bytes, sizeof(T));
  return value;
}

}  // namespace

struct NpyFile::Mapping {
  const std::byte* data = nullptr;
  std::size_t size = 0;
  Mapping(const Mapping&) = delete;
  Mapping& operator=(const Mapping&) = delete;
  Mapping(const std::byte* d, std::size_t s) : data(d), size(s) {}
  ~Mapping() {
    if (data != nullptr) munmap(const_cast<std::byte*>(data), size);
  }
};

std::string_view to_string(NpyDtype dtype) {
  switch (dtype) {
    case NpyDtype::uint8:
      return "uint8";
    case NpyDtype::float16:
      return "float16";
    case NpyDtype::float32:
      return "float32";
    case NpyDtype::float64:
      return "float64";
    case NpyDtype::int64:
      return "int64";
  }
  return "unknown";
}

std::size_t item_size(NpyDtype dtype) {
  switch (dtype) {
    case NpyDtype::uint8:
      return 1;
    case NpyDtype::float16:
      return 2;
    case NpyDtype::float32:
      return 4;
    case NpyDtype::float64:
    case NpyDtype::int64:
      return 8;
  }
  return 1;
}

NpyFile NpyFile::open(const std::filesystem::path& path) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) fail(path, fmt::format("cannot open: {}", std::strerror(errno)));
  struct stat info {};
  if (fstat(fd, &info) != 0 || !S_ISREG(info.st_mode)) {
    ::close(fd);
    fail(path, "not a regular file");
  }
  const auto size = static_cast<std::size_t>(info.st_size);
  if (size < kPreambleV1) {
    ::close(fd);
    fail(path, fmt::format("not a .npy file ({} bytes, shorter than the format's preamble)", size));
  }
  void* address = mmap(nullptr, size, PROT_READ, MAP_PRIVATE, fd, 0);
  ::close(fd);  // the mapping keeps the file's pages reachable
  if (address == MAP_FAILED) fail(path, fmt::format("cannot map: {}", std::strerror(errno)));
  auto mapping = std::make_shared<const Mapping>(static_cast<const std::byte*>(address), size);
  const std::byte* bytes = mapping->data;

  if (std::memcmp(bytes, kMagic.data(), kMagic.size()) != 0) {
    fail(path, "not a .npy file (no \\x93NUMPY magic)");
  }
  const auto major = static_cast<int>(bytes[6]);
  const auto minor = static_cast<int>(bytes[7]);
  if ((major != 1 && major != 2) || minor != 0) {
    fail(path, fmt::format(".npy format version {}.{} is not supported (expected 1.0 or 2.0)",
                           major, minor));
  }
  const std::size_t preamble = major == 1 ? kPreambleV1 : kPreambleV2;
  if (size < preamble) fail(path, "truncated .npy preamble");
  const std::size_t header_length = read_le(bytes + 8, major == 1 ? 2 : 4);
  if (header_length > size - preamble) {
    fail(path, fmt::format("truncated .npy header ({} bytes announced, {} present)", header_length,
                           size - preamble));
  }
  const std::string_view header(reinterpret_cast<const char*>(bytes + preamble), header_length);
  if (header.empty() || header.back() != '\n') fail(path, "the .npy header does not end in '\\n'");
  auto parsed = HeaderParser(header, path).parse();

  NpyFile file;
  file.path_ = path;
  file.dtype_ = parsed.dtype;
  file.shape_ = std::move(parsed.shape);
  file.data_offset_ = preamble + header_length;
  const std::size_t data_bytes = checked_product(file.shape_, item_size(file.dtype_), path);
  const std::size_t present = size - file.data_offset_;
  if (present != data_bytes) {
    fail(path, fmt::format("{} {} array needs {} data bytes, the file has {} ({})",
                           shape_text(file.shape_), to_string(file.dtype_), data_bytes, present,
                           present < data_bytes ? "truncated" : "trailing bytes"));
  }
  file.mapping_ = std::move(mapping);
  return file;
}

std::size_t NpyFile::element_count() const {
  std::size_t count = 1;
  for (const std::size_t dim : shape_) count *= dim;
  return count;
}

std::span<const std::byte> NpyFile::bytes() const {
  if (!mapping_) return {};
  return {mapping_->data + data_offset_, data_bytes()};
}

std::vector<double> NpyFile::as_doubles() const {
  const std::size_t count = element_count();
  const std::byte* data = bytes().data();
  std::vector<double> values(count);
  const std::size_t item = item_size(dtype_);
  for (std::size_t i = 0; i < count; ++i) {
    const std::byte* element = data + i * item;
    switch (dtype_) {
      case NpyDtype::uint8:
        values[i] = static_cast<double>(load<std::uint8_t>(element));
        break;
      case NpyDtype::float16:
        values[i] = half_to_float(load<std::uint16_t>(element));
        break;
      case NpyDtype::float32:
        values[i] = load<float>(element);
        break;
      case NpyDtype::float64:
        values[i] = load<double>(element);
        break;
      case NpyDtype::int64:
        values[i] = static_cast<double>(load<std::int64_t>(element));
        break;
    }
  }
  return values;
}

std::vector<std::int64_t> NpyFile::as_int64s() const {
  if (dtype_ != NpyDtype::int64 && dtype_ != NpyDtype::uint8) {
    fail(path_, fmt::format("expected integers (int64), got {}", to_string(dtype_)));
  }
  const std::size_t count = element_count();
  const std::byte* data = bytes().data();
  std::vector<std::int64_t> values(count);
  for (std::size_t i = 0; i < count; ++i) {
    values[i] = dtype_ == NpyDtype::int64 ? load<std::int64_t>(data + 8 * i)
                                          : static_cast<std::int64_t>(load<std::uint8_t>(data + i));
  }
  return values;
}

std::vector<float> NpyFile::as_floats() const {
  if (dtype_ == NpyDtype::float32) {
    std::vector<float> values(element_count());
    if (!values.empty()) std::memcpy(values.data(), bytes().data(), data_bytes());
    return values;
  }
  const std::vector<double> wide = as_doubles();
  std::vector<float> values(wide.size());
  for (std::size_t i = 0; i < wide.size(); ++i) {
    if (std::isfinite(wide[i]) && std::abs(wide[i]) > std::numeric_limits<float>::max()) {
      fail(path_, fmt::format("element {} ({}) does not fit in float32", i, wide[i]));
    }
    values[i] = static_cast<float>(wide[i]);
  }
  return values;
}

std::string npy_file_header(NpyDtype dtype, const std::vector<std::size_t>& shape) {
  std::string header = fmt::format("{{'descr': '{}', 'fortran_order': False, 'shape': {}, }}",
                                   descr_of(dtype), shape_text(shape));
  // As numpy writes it (byte for byte, so that files are identical to np.save's): room for the
  // shape to grow in place, then spaces so that the data start is aligned to 64 bytes (for a
  // memory-mapped array of any element type), then '\n'. Version 1.0 unless the header does not
  // fit its 16-bit length.
  header.append(kShapeGrowthRoom, ' ');
  const auto padded_length = [&](std::size_t preamble) {
    return header.size() + 1 + kHeaderAlignment - (preamble + header.size() + 1) % kHeaderAlignment;
  };
  const std::size_t preamble = padded_length(kPreambleV1) <= 65535 ? kPreambleV1 : kPreambleV2;
  header.append(padded_length(preamble) - header.size() - 1, ' ');
  header.push_back('\n');

  std::string bytes(kMagic);
  bytes.push_back(static_cast<char>(preamble == kPreambleV1 ? 1 : 2));
  bytes.push_back('\0');
  const std::size_t length_bytes = preamble == kPreambleV1 ? 2 : 4;
  for (std::size_t i = 0; i < length_bytes; ++i) {
    bytes.push_back(static_cast<char>((header.size() >> (8 * i)) & 0xff));
  }
  bytes += header;
  return bytes;
}

void write_npy(const std::filesystem::path& path, NpyDtype dtype,
               const std::vector<std::size_t>& shape, std::span<const std::byte> bytes) {
  const std::size_t expected = checked_product(shape, item_size(dtype), path);
  if (bytes.size() != expected) {
    throw std::invalid_argument(fmt::format("{}: {} {} array needs {} bytes, {} given",
                                            quoted(path), shape_text(shape), to_string(dtype),
                                            expected, bytes.size()));
  }
  const std::string header = npy_file_header(dtype, shape);

  // A unique temporary name in the same folder (rename is atomic only within a file system).
  static std::atomic<unsigned> counter{0};
  std::filesystem::path temporary = path;
  temporary += fmt::format(".tmp.{}.{}", ::getpid(), counter++);
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    if (!out) fail(path, fmt::format("cannot write (temporary file {})", temporary.string()));
    out.write(header.data(), static_cast<std::streamsize>(header.size()));
    if (!bytes.empty()) {
      out.write(reinterpret_cast<const char*>(bytes.data()),
                static_cast<std::streamsize>(bytes.size()));
    }
    out.close();
    if (!out) {
      std::error_code ignored;
      std::filesystem::remove(temporary, ignored);
      fail(path, "cannot write (disk full or I/O error)");
    }
  }
  std::error_code error;
  std::filesystem::rename(temporary, path, error);
  if (error) {
    std::error_code ignored;
    std::filesystem::remove(temporary, ignored);
    fail(path, fmt::format("cannot replace: {}", error.message()));
  }
}

void write_npy(const std::filesystem::path& path, const std::vector<std::size_t>& shape,
               std::span<const float> values) {
  write_npy(path, NpyDtype::float32, shape, std::as_bytes(values));
}

void write_npy(const std::filesystem::path& path, const std::vector<std::size_t>& shape,
               std::span<const double> values) {
  write_npy(path, NpyDtype::float64, shape, std::as_bytes(values));
}

void write_npy(const std::filesystem::path& path, const std::vector<std::size_t>& shape,
               std::span<const std::uint8_t> values) {
  write_npy(path, NpyDtype::uint8, shape, std::as_bytes(values));
}

void write_npy(const std::filesystem::path& path, const std::vector<std::size_t>& shape,
               std::span<const std::int64_t> values) {
  write_npy(path, NpyDtype::int64, shape, std::as_bytes(values));
}

float half_to_float(std::uint16_t half) {
  const std::uint32_t sign = static_cast<std::uint32_t>(half & 0x8000u) << 16;
  const std::uint32_t exponent = (half >> 10) & 0x1fu;
  const std::uint32_t mantissa = half & 0x3ffu;
  if (exponent == 0) {  // zero or subnormal: mantissa x 2^-24
    const float magnitude = std::ldexp(static_cast<float>(mantissa), -24);
    return sign != 0 ? -magnitude : magnitude;
  }
  if (exponent == 31) return std::bit_cast<float>(sign | 0x7f800000u | (mantissa << 13));
  return std::bit_cast<float>(sign | ((exponent + 112) << 23) | (mantissa << 13));
}

std::uint16_t float_to_half(float value) {
  std::uint32_t bits = std::bit_cast<std::uint32_t>(value);
  const std::uint32_t sign = (bits >> 16) & 0x8000u;
  bits &= 0x7fffffffu;
  std::uint32_t half = 0;
  if (bits >= 0x47800000u) {  // >= 65536 (rounds to infinity), infinity or NaN
    half = bits > 0x7f800000u ? 0x7e00u : 0x7c00u;
  } else if (bits < 0x38800000u) {  // below 2^-14: a subnormal half or zero
    // Adding 0.5 puts the value's 2^-24 units into the low mantissa bits, rounded to nearest even
    // by the float addition itself.
    const float shifted = std::bit_cast<float>(bits) + 0.5f;
    half = std::bit_cast<std::uint32_t>(shifted) - 0x3f000000u;
  } else {
    const std::uint32_t odd = (bits >> 13) & 1u;
    bits += 0xc8000fffu + odd;  // rebias the exponent (127 -> 15) and round to nearest even
    half = bits >> 13;
  }
  return static_cast<std::uint16_t>(half | sign);
}

}  // namespace radarpr
