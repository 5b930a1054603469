#pragma once

#include <cstddef>
#include <filesystem>

#include "datasets/npy_file.hpp"
#include "evaluation/retrieval/l2_rows.hpp"

namespace radarpr {

// Descriptor values in a .npy file (float32, C order; count x floats or count x rows x cols, as
// the descriptor cache and `radarpr export` write them) memory-mapped as one row-major matrix:
// the blocked L2 search reads it in place and lets go of each block of rows it has read, so a
// session larger than memory can be searched (rows()).
class MappedValueMatrix {
 public:
  // Throws NpyError naming `path` when the file is missing, not a .npy file, truncated or longer
  // than its header says (NpyFile::open), or not a float32 array of at least one value of at
  // least one float with two or three dimensions.
  static MappedValueMatrix open(const std::filesystem::path& path);

  const std::filesystem::path& path() const { return file_.path(); }
  std::size_t size() const { return count_; }
  int rows() const { return rows_; }
  int cols() const { return cols_; }
  std::size_t dimension() const { return static_cast<std::size_t>(rows_) * cols_; }
  // The first value's first float; value i starts dimension() floats further on each.
  const float* data() const { return data_; }

  // Lets go of the pages holding only values [begin, end): reading them again reads the file
  // (or the page cache) again.
  void release(std::size_t begin, std::size_t end) const;
  // The values as the search reads them, released block by block. Valid while this lives.
  L2Rows l2_rows() const;

 private:
  NpyFile file_;
  const float* data_ = nullptr;
  std::size_t count_ = 0;
  int rows_ = 0;
  int cols_ = 0;
};

// Lets go of the whole pages inside [begin, end) of a read-only memory map whose pages end at
// `mapping_end` (rounded up to a page: the map covers the file's last partial page). A hint:
// the bytes stay in the file and the page cache.
void release_mapped_range(const std::byte* begin, const std::byte* end,
                          const std::byte* mapping_end);

}  // namespace radarpr
