#pragma once

#include <cstddef>
#include <functional>
#include <vector>

#include "descriptors/descriptor.hpp"

namespace radarpr {

// Values of one length as rows of floats, read where they lie: one vector per value (in memory)
// or one contiguous row-major matrix (a memory-mapped .npy), so that the search never copies a
// whole session, only slices of a block of rows small enough to stay in cache.
class L2Rows {
 public:
  using Release = std::function<void(std::size_t begin, std::size_t end)>;

  // In-memory values of one length (common_dimension checked by the caller); not copied.
  explicit L2Rows(const std::vector<DescriptorValue>& values);
  // `count` values of rows x cols floats, one after another from `data` (row-major, float
  // aligned). `release(begin, end)`, when given, is told when the search has read values
  // [begin, end) for now, so that a memory map can let go of their pages.
  L2Rows(const float* data, std::size_t count, int rows, int cols, Release release = {});

  std::size_t size() const { return count_; }
  std::size_t dimension() const { return dimension_; }
  const float* row(std::size_t i) const {
    return data_ != nullptr ? data_ + i * dimension_ : (*values_)[i].values.data();
  }
  // The contiguous matrix, or nullptr for in-memory values.
  const float* contiguous_data() const { return data_; }
  // Value i as distance() takes it: the in-memory value itself, or a copy into `scratch`.
  const DescriptorValue& value(std::size_t i, DescriptorValue& scratch) const;
  void release(std::size_t begin, std::size_t end) const {
    if (release_) release_(begin, end);
  }
  // Whether both read the same values (a single session searches its own past).
  bool same_values(const L2Rows& other) const {
    return values_ == other.values_ && data_ == other.data_ && count_ == other.count_;
  }

 private:
  const std::vector<DescriptorValue>* values_ = nullptr;
  const float* data_ = nullptr;
  std::size_t count_ = 0;
  std::size_t dimension_ = 0;
  int rows_ = 0;
  int cols_ = 0;
  Release release_;
};

}  // namespace radarpr
