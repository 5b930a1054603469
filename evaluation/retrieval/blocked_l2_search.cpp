#include "evaluation/retrieval/blocked_l2_search.hpp"

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <memory>
#include <mutex>
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
// rounding error is then at most gamma(1024) |q| |d| whatever order the matrix product sums in
// (Higham, Accuracy and Stability, 3.1), 32 times tighter than one float sum over 32,768 VLAD
// elements, so the band of values re-checked with distance() stays narrow. The double sums cost
// one addition per 2 x 1024 flops of the product; at 256 elements the partial products' traffic
// made the search 1.5 times slower than the plain product.
constexpr Eigen::Index kFloatDepth = 1024;

std::vector<double> squared_norms(const std::vector<DescriptorValue>& values, const char* role) {
  std::vector<double> norms(values.size());
  for (std::size_t i = 0; i < values.size(); ++i) {
    // Eight independent sums (vectorised; one chain of 32,768 dependent additions would cost as
    // much as a sample of queries' products): the order differs from a plain loop by far less
    // than the 1e-9 relative the error bound allows for the double sums.
    const std::vector<float>& elements = values[i].values;
    double lanes[8] = {};
    std::size_t j = 0;
    for (; j + 8 <= elements.size(); j += 8) {
      for (std::size_t lane = 0; lane < 8; ++lane) {
        lanes[lane] += double(elements[j + lane]) * elements[j + lane];
      }
    }
    double sum = ((lanes[0] + lanes[4]) + (lanes[1] + lanes[5])) +
                 ((lanes[2] + lanes[6]) + (lanes[3] + lanes[7]));
    for (; j < elements.size(); ++j) sum += double(elements[j]) * elements[j];
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
  const auto depth = static_cast<Eigen::Index>(dimension);

  // One query block: its values as rows, a candidate set per query, and the database values it
  // may see.
  struct QueryBlock {
    std::size_t begin = 0;
    std::size_t end = 0;
    std::size_t database_end = 0;
    bool ends_grow = false;
    RowMatrix rows;
    std::vector<CandidateSet> candidates;
  };
  auto open_block = [&](std::size_t block) {
    QueryBlock q;
    q.begin = block * kQueryBlock;
    q.end = std::min(queries.size(), q.begin + kQueryBlock);
    const auto first = eligible_ends.begin() + static_cast<std::ptrdiff_t>(q.begin);
    const auto last = eligible_ends.begin() + static_cast<std::ptrdiff_t>(q.end);
    q.database_end = *std::max_element(first, last);
    // A single session's queries come in order, their eligible prefixes growing: a database
    // block then concerns only the block's later queries, and the products skip the others
    // (without this, a block of queries spread over a session would multiply against the
    // prefix of its last query for every one of them).
    q.ends_grow = std::is_sorted(first, last);
    if (q.database_end == 0) return q;
    q.rows.resize(static_cast<Eigen::Index>(q.end - q.begin), depth);
    pack(queries, q.begin, q.end, q.rows);
    q.candidates.assign(q.end - q.begin, CandidateSet(k, absolute_band, /*relative_band=*/0.0f));
    return q;
  };
  // The products of a query block with database values [begin, end) and the computed distances
  // of the eligible pairs, handed to `add` (query, distances of [begin, end) in a row of `dots`).
  struct Scratch {
    RowMatrix database_rows;
    Eigen::MatrixXf partial;
    Eigen::MatrixXd dots;
  };
  // Scratch matrices are reused between blocks: a database block of 32,768-float values is
  // 64 MB, and allocating it afresh costs page faults comparable to its product.
  std::vector<std::unique_ptr<Scratch>> spare;
  std::mutex spare_mutex;
  auto borrow = [&] {
    const std::lock_guard lock(spare_mutex);
    if (spare.empty()) return std::make_unique<Scratch>();
    std::unique_ptr<Scratch> scratch = std::move(spare.back());
    spare.pop_back();
    return scratch;
  };
  auto give_back = [&](std::unique_ptr<Scratch> scratch) {
    const std::lock_guard lock(spare_mutex);
    spare.push_back(std::move(scratch));
  };
  auto multiply = [&](const QueryBlock& q, std::size_t begin, Scratch& scratch,
                      const std::function<void(std::size_t, Eigen::Index)>& add) {
    const std::size_t end = std::min(q.database_end, begin + kDatabaseBlock);
    std::size_t first_active = q.begin;  // queries before it have nothing in this block
    if (q.ends_grow) {
      first_active = static_cast<std::size_t>(
          std::partition_point(eligible_ends.begin() + static_cast<std::ptrdiff_t>(q.begin),
                               eligible_ends.begin() + static_cast<std::ptrdiff_t>(q.end),
                               [&](std::size_t e) { return e <= begin; }) -
          eligible_ends.begin());
    }
    if (first_active == q.end) return;
    const auto skipped = static_cast<Eigen::Index>(first_active - q.begin);
    const Eigen::Index active = q.rows.rows() - skipped;
    if (scratch.database_rows.cols() != depth) scratch.database_rows.resize(0, depth);
    pack(database, begin, end, scratch.database_rows);
    scratch.dots.setZero(active, scratch.database_rows.rows());
    for (Eigen::Index first = 0; first < depth; first += kFloatDepth) {
      const Eigen::Index width = std::min(kFloatDepth, depth - first);
      scratch.partial.noalias() = q.rows.bottomRows(active).middleCols(first, width) *
                                  scratch.database_rows.middleCols(first, width).transpose();
      scratch.dots += scratch.partial.cast<double>();
    }
    for (std::size_t query = first_active; query < q.end; ++query) {
      add(query, static_cast<Eigen::Index>(query - first_active));
    }
  };
  auto add_distances = [&](QueryBlock& q, std::size_t begin, const Eigen::MatrixXd& dots,
                           std::size_t query, Eigen::Index row) {
    const std::size_t end =
        std::min({q.database_end, begin + kDatabaseBlock, eligible_ends[query]});
    CandidateSet& candidates = q.candidates[query - q.begin];
    for (std::size_t j = begin; j < end; ++j) {
      const double squared = query_norms[query] + database_norms[j] -
                             2.0 * dots(row, static_cast<Eigen::Index>(j - begin));
      candidates.addPoint(static_cast<float>(std::max(squared, 0.0)), j);
    }
  };
  auto finish = [&](QueryBlock& q) {
    for (std::size_t query = q.begin; query < q.end; ++query) {
      if (eligible_ends[query] == 0) continue;
      results[query] = rank_by_distance(descriptor, queries[query], database,
                                        q.candidates[query - q.begin].indices(), k, query);
    }
  };

  if (query_blocks >= static_cast<std::size_t>(threads)) {
    // Enough query blocks for every thread: each thread takes whole query blocks.
    parallel_for(query_blocks, threads, [&](std::size_t block) {
      QueryBlock q = open_block(block);
      if (q.database_end == 0) return;
      std::unique_ptr<Scratch> scratch = borrow();
      for (std::size_t begin = 0; begin < q.database_end; begin += kDatabaseBlock) {
        multiply(q, begin, *scratch, [&](std::size_t query, Eigen::Index row) {
          add_distances(q, begin, scratch->dots, query, row);
        });
      }
      give_back(std::move(scratch));
      finish(q);
    });
    return results;
  }
  // Fewer query blocks than threads (a few hundred queries, or a sample of them as the
  // benchmarks time): the threads share each query block's database blocks instead, so every
  // core multiplies and each database block is packed once. The candidate sets take the
  // distances under a lock: one comparison per pair against a product of `dimension` terms.
  std::mutex candidates_mutex;
  for (std::size_t block = 0; block < query_blocks; ++block) {
    QueryBlock q = open_block(block);
    if (q.database_end == 0) continue;
    const std::size_t database_blocks = (q.database_end + kDatabaseBlock - 1) / kDatabaseBlock;
    parallel_for(database_blocks, threads, [&](std::size_t database_block) {
      std::unique_ptr<Scratch> scratch = borrow();
      const std::size_t begin = database_block * kDatabaseBlock;
      std::vector<std::pair<std::size_t, Eigen::Index>> rows;
      multiply(q, begin, *scratch,
               [&](std::size_t query, Eigen::Index row) { rows.emplace_back(query, row); });
      {
        const std::lock_guard lock(candidates_mutex);
        for (const auto& [query, row] : rows) add_distances(q, begin, scratch->dots, query, row);
      }
      give_back(std::move(scratch));
    });
    finish(q);
  }
  return results;
}

}  // namespace radarpr::retrieval_detail
