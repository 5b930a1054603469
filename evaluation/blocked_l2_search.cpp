#include "evaluation/blocked_l2_search.hpp"

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <thread>

#include "evaluation/candidate_set.hpp"
#include "evaluation/neighbour_ranking.hpp"
#include "evaluation/parallel.hpp"

namespace radarpr::retrieval_detail {
namespace {

using RowMatrix = Eigen::Matrix<float, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

// Per thread a block holds kQueryBlock + kDatabaseBlock values: 96 MB for 32,768-float VLAD
// vectors. Each query block copies the database once, so larger query blocks copy less. The
// threads together stay within kBlockMemoryBudget whatever the core count.
constexpr std::size_t kQueryBlock = 256;
constexpr std::size_t kDatabaseBlock = 512;
constexpr std::size_t kBlockMemoryBudget = std::size_t{1} << 30;

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

std::vector<float> squared_norms(const std::vector<DescriptorValue>& values, const char* role) {
  std::vector<float> norms(values.size());
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
    norms[i] = static_cast<float>(sum);
  }
  return norms;
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

std::vector<std::vector<Neighbor>> retrieve_exhaustive_l2(
    const Descriptor& descriptor, const std::vector<DescriptorValue>& database,
    const std::vector<DescriptorValue>& queries, const std::vector<std::size_t>& eligible_ends,
    std::size_t k) {
  const std::size_t dimension = common_dimension(database, queries);
  const std::vector<float> database_norms = squared_norms(database, "database");
  const std::vector<float> query_norms =
      &queries == &database ? database_norms : squared_norms(queries, "query");
  const float scale =
      std::max(*std::max_element(database_norms.begin(), database_norms.end()),
               queries.empty() ? 0.0f : *std::max_element(query_norms.begin(), query_norms.end()));
  // A float dot product of n terms is off by at most about n * 2^-24 * |q| |d| (sequential
  // summation); the band around the k-th nearest covers that bound, and the exact distance()
  // then orders the few values inside it.
  const float absolute_band =
      std::max(4.0f * static_cast<float>(dimension) * std::numeric_limits<float>::epsilon() * scale,
               std::numeric_limits<float>::min());

  std::vector<std::vector<Neighbor>> results(queries.size());
  const std::size_t query_blocks = (queries.size() + kQueryBlock - 1) / kQueryBlock;
  const std::size_t bytes_per_thread = (kQueryBlock + kDatabaseBlock) * dimension * sizeof(float);
  const int threads = static_cast<int>(std::clamp<std::size_t>(
      kBlockMemoryBudget / bytes_per_thread, 1, std::max(1u, std::thread::hardware_concurrency())));
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
    Eigen::MatrixXf dots;
    std::vector<CandidateSet> candidates(query_end - query_begin, CandidateSet(k, absolute_band));
    for (std::size_t begin = 0; begin < database_end; begin += kDatabaseBlock) {
      const std::size_t end = std::min(database_end, begin + kDatabaseBlock);
      pack(database, begin, end, database_rows);
      dots.noalias() = query_rows * database_rows.transpose();
      for (std::size_t q = query_begin; q < query_end; ++q) {
        const auto row = static_cast<Eigen::Index>(q - query_begin);
        for (std::size_t j = begin; j < std::min(end, eligible_ends[q]); ++j) {
          const float squared = query_norms[q] + database_norms[j] -
                                2.0f * dots(row, static_cast<Eigen::Index>(j - begin));
          candidates[q - query_begin].addPoint(std::max(squared, 0.0f), j);
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
