#include "evaluation/retrieval/blocked_l2_search.hpp"

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "evaluation/parallel.hpp"
#include "evaluation/retrieval/candidate_set.hpp"
#include "evaluation/retrieval/neighbour_ranking.hpp"

namespace radarpr::retrieval_detail {
namespace {

using RowMatrix = Eigen::Matrix<float, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

// Per thread a block holds kQueryBlock + kDatabaseBlock values: 96 MB for 32,768-float VLAD
// vectors. Each query block copies the database once, so larger query blocks copy less. The
// threads together stay within kBlockMemoryBudget whatever the core count.
constexpr std::size_t kQueryBlock = 256;
constexpr std::size_t kDatabaseBlock = 512;
constexpr std::size_t kBlockMemoryBudget = std::size_t{1} << 30;
// Dot products are summed in float over at most this many elements, then in double: the float
// rounding error is then at most gamma(256) |q| |d| whatever order the matrix product sums in
// (Higham, Accuracy and Stability, 3.1), 128 times tighter than one float sum over 32,768 VLAD
// elements, so the band of values re-checked with distance() stays narrow. The double sums cost
// one addition per 2 x 256 flops of the product.
constexpr Eigen::Index kFloatDepth = 256;

std::vector<double> squared_norms(const std::vector<DescriptorValue>& values, const char* role) {
  std::vector<double> norms(values.size());
  for (std::size_t i = 0; i < values.size(); ++i) {
    double sum = 0.0;
    for (const float element : values[i].values) sum += double(element) * element;
    if (!std::isfinite(sum)) {
      throw std::invalid_argument(std::string("retrieve_nearest: ") + role + " value " +
                                  std::to_string(i) + " has a NaN or infinite element");
    }
    if (sum > std::numeric_limits<float>::max() / 4) {
      throw std::invalid_argument(std::string("retrieve_nearest: ") + role + " value " +
                                  std::to_string(i) + " has a squared norm of " +
                                  std::to_string(sum) +
                                  ", too large for float distances (at most " +
                                  std::to_string(std::numeric_limits<float>::max() / 4) + ")");
    }
    norms[i] = sum;
  }
  return norms;
}

// The largest error of a computed squared distance |q|^2 + |d|^2 - 2 q.d, for values whose
// squared norms are at most `scale`: the float dot product over kFloatDepth elements (gamma
// |q| |d|, doubled by the factor 2), the final rounding to float (the distance is at most
// 4 scale) and, generously, the double sums.
float distance_error_bound(std::size_t dimension, double scale) {
  const double unit_roundoff = std::numeric_limits<float>::epsilon() / 2.0;
  const double depth = static_cast<double>(std::min<std::size_t>(dimension, kFloatDepth));
  const double gamma = depth * unit_roundoff / (1.0 - depth * unit_roundoff);
  return static_cast<float>((2.0 * gamma + 4.0 * unit_roundoff + 1e-9) * scale);
}

// Copies values [begin, end) into the rows of `block`.
void pack(const std::vector<DescriptorValue>& values, std::size_t begin, std::size_t end,
          RowMatrix& block) {
  block.resize(static_cast<Eigen::Index>(end - begin), block.cols());
  for (std::size_t i = begin; i < end; ++i) {
    std::copy(values[i].values.begin(), values[i].values.end(),
              block.row(static_cast<Eigen::Index>(i - begin)).data());
  }
}

}  // namespace

std::size_t common_dimension(const std::vector<DescriptorValue>& database,
                             const std::vector<DescriptorValue>& queries) {
  const std::size_t dimension = database.front().values.size();
  if (dimension == 0) {
    throw std::invalid_argument("retrieve_nearest: exhaustive_l2 values must not be empty");
  }
  for (const auto* values : {&database, &queries}) {
    for (std::size_t i = 0; i < values->size(); ++i) {
      if ((*values)[i].values.size() != dimension) {
        throw std::invalid_argument(
            "retrieve_nearest: exhaustive_l2 values must all have the same length, but " +
            std::string(values == &database ? "database" : "query") + " value " +
            std::to_string(i) + " has " + std::to_string((*values)[i].values.size()) +
            " floats where " + std::to_string(dimension) + " were expected");
      }
    }
  }
  return dimension;
}

std::vector<std::vector<Neighbour>> retrieve_exhaustive_l2(
    const Descriptor& descriptor, const std::vector<DescriptorValue>& database,
    const std::vector<DescriptorValue>& queries, const std::vector<std::size_t>& eligible_ends,
    std::size_t k) {
  const std::size_t dimension = common_dimension(database, queries);
  const std::vector<double> database_norms = squared_norms(database, "database");
  const std::vector<double> query_norms =
      &queries == &database ? database_norms : squared_norms(queries, "query");
  const double scale =
      std::max(*std::max_element(database_norms.begin(), database_norms.end()),
               queries.empty() ? 0.0 : *std::max_element(query_norms.begin(), query_norms.end()));
  // Each computed distance is within `error` of the true one, so every value truly nearer than
  // the k-th lies within 2 error of the computed k-th: that band is kept, and the exact
  // distance() orders the few values inside it.
  const float error = distance_error_bound(dimension, scale);
  const float absolute_band = std::max(2.5f * error, std::numeric_limits<float>::min());

  std::vector<std::vector<Neighbour>> results(queries.size());
  const std::size_t query_blocks = (queries.size() + kQueryBlock - 1) / kQueryBlock;
  const std::size_t bytes_per_thread = (kQueryBlock + kDatabaseBlock) * dimension * sizeof(float);
  const int threads = static_cast<int>(std::clamp<std::size_t>(
      kBlockMemoryBudget / bytes_per_thread, 1, static_cast<std::size_t>(default_thread_count())));
  parallel_for(query_blocks, threads, [&](std::size_t block) {
    const std::size_t query_begin = block * kQueryBlock;
    const std::size_t query_end = std::min(queries.size(), query_begin + kQueryBlock);
    const std::size_t database_end =
        *std::max_element(eligible_ends.begin() + static_cast<std::ptrdiff_t>(query_begin),
                          eligible_ends.begin() + static_cast<std::ptrdiff_t>(query_end));
    if (database_end == 0) return;

    RowMatrix query_rows(static_cast<Eigen::Index>(query_end - query_begin),
                         static_cast<Eigen::Index>(dimension));
    pack(queries, query_begin, query_end, query_rows);
    RowMatrix database_rows(0, static_cast<Eigen::Index>(dimension));
    Eigen::MatrixXf partial;
    Eigen::MatrixXd dots;
    std::vector<CandidateSet> candidates(query_end - query_begin,
                                         CandidateSet(k, absolute_band, /*relative_band=*/0.0f));
    const auto depth = static_cast<Eigen::Index>(dimension);
    // A single session's queries come in order, their eligible prefixes growing: a database
    // block then concerns only the block's later queries, and the products skip the others
    // (without this, a block of queries spread over a session would multiply against the
    // prefix of its last query for every one of them).
    const bool ends_grow =
        std::is_sorted(eligible_ends.begin() + static_cast<std::ptrdiff_t>(query_begin),
                       eligible_ends.begin() + static_cast<std::ptrdiff_t>(query_end));
    std::size_t first_active = query_begin;  // queries before it have nothing in this block
    for (std::size_t begin = 0; begin < database_end; begin += kDatabaseBlock) {
      const std::size_t end = std::min(database_end, begin + kDatabaseBlock);
      while (ends_grow && eligible_ends[first_active] <= begin) ++first_active;
      const auto skipped = static_cast<Eigen::Index>(first_active - query_begin);
      const Eigen::Index active = query_rows.rows() - skipped;
      pack(database, begin, end, database_rows);
      dots.setZero(active, database_rows.rows());
      for (Eigen::Index first = 0; first < depth; first += kFloatDepth) {
        const Eigen::Index width = std::min(kFloatDepth, depth - first);
        partial.noalias() = query_rows.bottomRows(active).middleCols(first, width) *
                            database_rows.middleCols(first, width).transpose();
        dots += partial.cast<double>();
      }
      for (std::size_t q = first_active; q < query_end; ++q) {
        const auto row = static_cast<Eigen::Index>(q - first_active);
        for (std::size_t j = begin; j < std::min(end, eligible_ends[q]); ++j) {
          const double squared = query_norms[q] + database_norms[j] -
                                 2.0 * dots(row, static_cast<Eigen::Index>(j - begin));
          candidates[q - query_begin].addPoint(static_cast<float>(std::max(squared, 0.0)), j);
        }
      }
    }
    for (std::size_t q = query_begin; q < query_end; ++q) {
      if (eligible_ends[q] == 0) continue;
      results[q] = rank_by_distance(descriptor, queries[q], database,
                                    candidates[q - query_begin].indices(), k, q);
    }
  });
  return results;
}

}  // namespace radarpr::retrieval_detail
