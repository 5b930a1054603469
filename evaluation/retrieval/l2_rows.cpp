#include "evaluation/retrieval/l2_rows.hpp"

#include <utility>

namespace radarpr {

L2Rows::L2Rows(const std::vector<DescriptorValue>& values)
    : values_(&values),
      count_(values.size()),
      dimension_(values.empty() ? 0 : values.front().values.size()) {
  if (!values.empty()) {
    rows_ = values.front().rows;
    cols_ = values.front().cols;
  }
}

L2Rows::L2Rows(const float* data, std::size_t count, int rows, int cols, Release release)
    : data_(data),
      count_(count),
      dimension_(static_cast<std::size_t>(rows) * static_cast<std::size_t>(cols)),
      rows_(rows),
      cols_(cols),
      release_(std::move(release)) {}

const DescriptorValue& L2Rows::value(std::size_t i, DescriptorValue& scratch) const {
  if (values_ != nullptr) return (*values_)[i];
  scratch.rows = rows_;
  scratch.cols = cols_;
  scratch.values.assign(row(i), row(i) + dimension_);
  return scratch;
}

}  // namespace radarpr
