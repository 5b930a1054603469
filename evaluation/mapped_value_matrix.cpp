#include "evaluation/mapped_value_matrix.hpp"

#include <sys/mman.h>
#include <unistd.h>

#include <cstdint>
#include <limits>
#include <string>

#include <fmt/format.h>

namespace radarpr {
namespace {

std::uintptr_t page_size() {
  static const auto size = static_cast<std::uintptr_t>(sysconf(_SC_PAGESIZE));
  return size;
}

}  // namespace

void release_mapped_range(const std::byte* begin, const std::byte* end,
                          const std::byte* mapping_end) {
  if (begin >= end) return;
  const std::uintptr_t page = page_size();
  const auto first = (reinterpret_cast<std::uintptr_t>(begin) + page - 1) / page * page;
  // The last page: whole when the range runs to the end of the map, else the whole pages only
  // (a page shared with the next values would drop bytes the caller still reads).
  const auto stop = reinterpret_cast<std::uintptr_t>(end);
  const std::uintptr_t last =
      end >= mapping_end ? (stop + page - 1) / page * page : stop / page * page;
  if (last <= first) return;
  // A private read-only map never written: the pages go, the file's bytes stay.
  ::madvise(reinterpret_cast<void*>(first), last - first, MADV_DONTNEED);
}

MappedValueMatrix MappedValueMatrix::open(const std::filesystem::path& path) {
  MappedValueMatrix matrix;
  matrix.file_ = NpyFile::open(path);
  const NpyFile& file = matrix.file_;
  auto refuse = [&](const std::string& why) {
    throw NpyError(fmt::format("{}: {}", path.string(), why));
  };
  if (file.dtype() != NpyDtype::float32) {
    refuse(fmt::format("descriptor values must be float32, this array is {}",
                       to_string(file.dtype())));
  }
  const std::vector<std::size_t>& shape = file.shape();
  if (shape.size() != 2 && shape.size() != 3) {
    refuse(
        fmt::format("descriptor values must be a count x floats or count x rows x cols "
                    "array, this one has {} dimensions",
                    shape.size()));
  }
  const std::size_t rows = shape[1];
  const std::size_t cols = shape.size() == 3 ? shape[2] : 1;
  if (shape[0] == 0 || rows == 0 || cols == 0) {
    refuse(fmt::format("no values to search (shape {})", fmt::join(shape, " x ")));
  }
  const auto most = static_cast<std::size_t>(std::numeric_limits<int>::max());
  if (rows > most || cols > most) {
    refuse(fmt::format("a value of {} x {} floats is larger than a descriptor value can be", rows,
                       cols));
  }
  const std::byte* bytes = file.bytes().data();
  // numpy and radarpr pad the header so that the elements start 64-byte aligned; a file that
  // does not is refused rather than read through misaligned floats.
  if (reinterpret_cast<std::uintptr_t>(bytes) % alignof(float) != 0) {
    refuse(
        "the values do not start at a multiple of 4 bytes into the file (a .npy header of "
        "unusual length); rewrite it with numpy.save");
  }
  matrix.data_ = reinterpret_cast<const float*>(bytes);
  matrix.count_ = shape[0];
  matrix.rows_ = static_cast<int>(rows);
  matrix.cols_ = static_cast<int>(cols);
  return matrix;
}

void MappedValueMatrix::release(std::size_t begin, std::size_t end) const {
  const auto* start = reinterpret_cast<const std::byte*>(data_ + begin * dimension());
  const auto* stop = reinterpret_cast<const std::byte*>(data_ + end * dimension());
  const std::span<const std::byte> bytes = file_.bytes();
  release_mapped_range(start, stop, bytes.data() + bytes.size());
}

L2Rows MappedValueMatrix::l2_rows() const {
  return L2Rows(data_, count_, rows_, cols_,
                [this](std::size_t begin, std::size_t end) { release(begin, end); });
}

}  // namespace radarpr
