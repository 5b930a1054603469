#include "evaluation/retrieval/blocked_l2_search.hpp"

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>

#include "evaluation/parallel.hpp"
#include "evaluation/retrieval/candidate_set.hpp"
#include "evaluation/retrieval/column_distances.hpp"
#include "evaluation/retrieval/neighbour_ranking.hpp"

namespace radarpr::retrieval_detail {
namespace {

using RowMatrix = Eigen::Matrix<float, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
using ConstRowMap = Eigen::Map<const RowMatrix, Eigen::Unaligned, Eigen::OuterStride<>>;

// A query block holds kQueryBlock values as rows (32 MB for 32,768-float VLAD vectors); a few
// are searched at once, each against database blocks of kDatabaseBlock values. The database is
// never copied whole: each product reads a slice of kDatabaseBlock x kFloatDepth floats (2 MB),
// in place when the values are one contiguous matrix, else copied into a buffer that stays in
// cache for the product that reads it next. Copying whole 64 MB database blocks instead moved
// every database value through memory twice more than the product itself does.
constexpr std::size_t kQueryBlock = 256;
constexpr std::size_t kDatabaseBlock = 512;
constexpr std::size_t kQueryMemoryBudget = std::size_t{1} << 30;
// Dot products are summed in float over at most this many elements, then in double: the float
// rounding error is then at most gamma(1024) |q| |d| whatever order the matrix product sums in
// (Higham, Accuracy and Stability, 3.1), 32 times tighter than one float sum over 32,768 VLAD
// elements, so the band of values re-checked with distance() stays narrow. The double sums cost
// one addition per 2 x 1024 flops of the product; at 256 elements the partial products' traffic
// made the search 1.5 times slower than the plain product.
constexpr Eigen::Index kFloatDepth = 1024;
// Prefetching of in-memory database slices: rows ahead, floats per 64-byte line.
constexpr Eigen::Index kPrefetchAhead = 2;
constexpr Eigen::Index kFloatsPerCacheLine = 16;
// Rows whose squared norms one task sums (and then lets go of, for a memory map).
constexpr std::size_t kNormBlock = 128;

double squared_norm(const float* elements, std::size_t size) {
  // Eight independent sums (vectorised; one chain of 32,768 dependent additions would cost as
  // much as a sample of queries' products): the order differs from a plain loop by far less
  // than the 1e-9 relative the error bound allows for the double sums.
  double lanes[8] = {};
  std::size_t j = 0;
  for (; j + 8 <= size; j += 8) {
    for (std::size_t lane = 0; lane < 8; ++lane) {
      lanes[lane] += double(elements[j + lane]) * elements[j + lane];
    }
  }
  double sum = ((lanes[0] + lanes[4]) + (lanes[1] + lanes[5])) +
               ((lanes[2] + lanes[6]) + (lanes[3] + lanes[7]));
  for (; j < size; ++j) sum += double(elements[j]) * elements[j];
  return sum;
}

std::vector<double> squared_norms(const L2Rows& values, const char* role) {
  std::vector<double> norms(values.size());
  const std::size_t blocks = (values.size() + kNormBlock - 1) / kNormBlock;
  parallel_for(blocks, 0, [&](std::size_t block) {
    const std::size_t begin = block * kNormBlock;
    const std::size_t end = std::min(values.size(), begin + kNormBlock);
    for (std::size_t i = begin; i < end; ++i) {
      norms[i] = squared_norm(values.row(i), values.dimension());
    }
    values.release(begin, end);
  });
  // Checked in order, so that the error names the first offending value.
  for (std::size_t i = 0; i < norms.size(); ++i) {
    const double sum = norms[i];
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

// One query block: its values as rows, a candidate set per query (filled by several threads,
// under `mutex`), and the database values it may see.
struct QueryBlock {
  std::size_t begin = 0;
  std::size_t end = 0;
  std::size_t database_end = 0;
  bool ends_grow = false;
  RowMatrix rows;
  std::vector<CandidateSet> candidates;
  std::mutex mutex;
};

// One thread's working memory, reused between tiles.
struct Scratch {
  std::vector<float> slice;  // kDatabaseBlock x kFloatDepth, in-memory database values
  Eigen::MatrixXf partial;
  Eigen::MatrixXd dots;
  std::vector<float> keys;        // one database value's distances to the active queries
  std::vector<float> thresholds;  // each active query's CandidateSet::worstDist()
};

// Offers one database value (a column of the products, `dots`, one per active query) to the
// candidate sets of the active queries `first_row` onwards. Candidate sets admit only distances
// below their worstDist(), which never rises: the distances are computed and compared with it in
// one vectorised pass over the column, and addPoint() runs only for the few that pass, in the
// order one call per pair would make (at 10^5 640-float values one call per pair took 7 % of the
// search).
template <typename Dot>
void offer_column(const Dot* dots, const double* query_norms, double database_norm,
                  std::size_t first_row, std::size_t rows, std::size_t index,
                  CandidateSet* candidates, Scratch& scratch) {
  float* keys = scratch.keys.data();
  float* thresholds = scratch.thresholds.data();
  if (!column_distances(dots, query_norms, database_norm, first_row, rows, thresholds, keys)) {
    return;
  }
  for (std::size_t r = first_row; r < rows; ++r) {
    if (keys[r] < thresholds[r]) {
      candidates[r].addPoint(keys[r], index);
      thresholds[r] = candidates[r].worstDist();
    }
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
  static_cast<void>(common_dimension(database, queries));
  const L2Rows database_rows(database);
  if (&queries == &database) {
    return retrieve_exhaustive_l2(descriptor, database_rows, database_rows, eligible_ends, k);
  }
  return retrieve_exhaustive_l2(descriptor, database_rows, L2Rows(queries), eligible_ends, k);
}

std::vector<std::vector<Neighbour>> retrieve_exhaustive_l2(
    const Descriptor& descriptor, const L2Rows& database, const L2Rows& queries,
    const std::vector<std::size_t>& eligible_ends, std::size_t k) {
  const std::size_t dimension = database.dimension();
  const std::vector<double> database_norms = squared_norms(database, "database");
  const std::vector<double> query_norms =
      queries.same_values(database) ? database_norms : squared_norms(queries, "query");
  const double scale = std::max(
      database_norms.empty() ? 0.0
                             : *std::max_element(database_norms.begin(), database_norms.end()),
      query_norms.empty() ? 0.0 : *std::max_element(query_norms.begin(), query_norms.end()));
  // Each computed distance is within `error` of the true one, so every value truly nearer than
  // the k-th lies within 2 error of the computed k-th: that band is kept, and the exact
  // distance() orders the few values inside it.
  const float error = distance_error_bound(dimension, scale);
  const float absolute_band = std::max(2.5f * error, std::numeric_limits<float>::min());

  std::vector<std::vector<Neighbour>> results(queries.size());
  const std::size_t query_blocks = (queries.size() + kQueryBlock - 1) / kQueryBlock;
  const int threads = default_thread_count();
  // Query blocks searched at once: one per thread, within the memory budget. Their tiles (a
  // query block against a database block) are handed out together, so that the threads stay
  // busy to the end even when the blocks' work differs (a single session's later queries see
  // longer prefixes) or a query block spans fewer database blocks than there are threads.
  const std::size_t window =
      std::clamp<std::size_t>(kQueryMemoryBudget / (kQueryBlock * dimension * sizeof(float)), 1,
                              static_cast<std::size_t>(threads));
  const auto depth = static_cast<Eigen::Index>(dimension);

  auto open_block = [&](std::size_t block, QueryBlock& q) {
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
    q.rows.resize(0, depth);
    q.candidates.clear();
    if (q.database_end == 0) return;
    q.rows.resize(static_cast<Eigen::Index>(q.end - q.begin), depth);
    for (std::size_t i = q.begin; i < q.end; ++i) {
      std::copy(queries.row(i), queries.row(i) + dimension,
                q.rows.row(static_cast<Eigen::Index>(i - q.begin)).data());
    }
    queries.release(q.begin, q.end);
    q.candidates.assign(q.end - q.begin, CandidateSet(k, absolute_band, /*relative_band=*/0.0f));
  };

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

  // The products of query block `q` with database values [begin, begin + kDatabaseBlock) and the
  // computed distances of its eligible pairs into its candidate sets.
  auto search_tile = [&](QueryBlock& q, std::size_t begin, Scratch& scratch) {
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
    const auto rows = static_cast<Eigen::Index>(end - begin);
    // Values of at most kFloatDepth floats need no double sums: their one float product is read.
    const bool one_slice = depth <= kFloatDepth;
    if (!one_slice) scratch.dots.setZero(active, rows);
    for (Eigen::Index first = 0; first < depth; first += kFloatDepth) {
      const Eigen::Index width = std::min(kFloatDepth, depth - first);
      const float* slice = nullptr;
      Eigen::Index stride = depth;
      if (const float* data = database.contiguous_data()) {
        slice = data + begin * dimension + static_cast<std::size_t>(first);
      } else {
        scratch.slice.resize(kDatabaseBlock * static_cast<std::size_t>(kFloatDepth));
        for (Eigen::Index r = 0; r < rows; ++r) {
          const float* source = database.row(begin + static_cast<std::size_t>(r)) + first;
          // Each row's slice starts a new page, where the hardware prefetchers start cold: the
          // slice a few rows ahead is asked for now (copying 30 to 40 % faster).
          if (r + kPrefetchAhead < rows) {
            const float* ahead =
                database.row(begin + static_cast<std::size_t>(r + kPrefetchAhead)) + first;
            for (Eigen::Index i = 0; i < width; i += kFloatsPerCacheLine) {
              __builtin_prefetch(ahead + i);
            }
          }
          std::copy(source, source + width, scratch.slice.data() + r * width);
        }
        slice = scratch.slice.data();
        stride = width;
      }
      const ConstRowMap database_slice(slice, rows, width, Eigen::OuterStride<>(stride));
      scratch.partial.noalias() =
          q.rows.bottomRows(active).middleCols(first, width) * database_slice.transpose();
      if (!one_slice) scratch.dots += scratch.partial.cast<double>();
    }
    database.release(begin, end);
    const std::lock_guard lock(q.mutex);
    CandidateSet* candidates = q.candidates.data() + (first_active - q.begin);
    if (!q.ends_grow) {
      for (std::size_t query = first_active; query < q.end; ++query) {
        const auto row = static_cast<Eigen::Index>(query - first_active);
        const std::size_t last = std::min(end, eligible_ends[query]);
        for (std::size_t j = begin; j < last; ++j) {
          const auto column = static_cast<Eigen::Index>(j - begin);
          const double dot = one_slice ? static_cast<double>(scratch.partial(row, column))
                                       : scratch.dots(row, column);
          const double squared = query_norms[query] + database_norms[j] - 2.0 * dot;
          candidates[row].addPoint(static_cast<float>(std::max(squared, 0.0)), j);
        }
      }
      return;
    }
    // Growing ends (every multi session, a single session's queries in order): the queries that
    // see database value j are the active ones from the first whose end lies beyond j, so the
    // products' columns (contiguous, one per database value) are offered whole from that row.
    const auto active_rows = static_cast<std::size_t>(active);
    scratch.keys.resize(active_rows);
    scratch.thresholds.resize(active_rows);
    for (std::size_t r = 0; r < active_rows; ++r) {
      scratch.thresholds[r] = candidates[r].worstDist();
    }
    const std::size_t* ends = eligible_ends.data() + first_active;
    std::size_t first_row = 0;
    for (std::size_t j = begin; j < end; ++j) {
      while (first_row < active_rows && ends[first_row] <= j) ++first_row;
      if (first_row == active_rows) break;
      const auto column = static_cast<Eigen::Index>(j - begin);
      if (one_slice) {
        offer_column(&scratch.partial(0, column), query_norms.data() + first_active,
                     database_norms[j], first_row, active_rows, j, candidates, scratch);
      } else {
        offer_column(&scratch.dots(0, column), query_norms.data() + first_active, database_norms[j],
                     first_row, active_rows, j, candidates, scratch);
      }
    }
  };

  // The final order by distance() among each query's candidates.
  auto finish = [&](QueryBlock& q) {
    const std::size_t count = q.candidates.empty() ? 0 : q.end - q.begin;
    parallel_for(count, threads, [&](std::size_t offset) {
      const std::size_t query = q.begin + offset;
      if (eligible_ends[query] == 0) return;
      DescriptorValue query_copy;
      DescriptorValue database_copy;
      const DescriptorValue& query_value = queries.value(query, query_copy);
      std::vector<std::size_t> candidates = q.candidates[offset].indices();
      std::sort(candidates.begin(), candidates.end());
      std::vector<Neighbour> ranked;
      std::size_t run_begin = 0;  // the run of consecutive candidates read since
      for (std::size_t c = 0; c < candidates.size(); ++c) {
        const std::size_t index = candidates[c];
        const double distance =
            descriptor.distance(query_value, database.value(index, database_copy));
        ranked.push_back({index, checked_distance(distance, query, index)});
        // A drive's candidates are often dozens of consecutive frames near the nearest: each run
        // of them is let go of once read (a memory map's pages), so that the ranking of a
        // window of queries does not hold thousands of values.
        if (c + 1 == candidates.size() || candidates[c + 1] != index + 1) {
          database.release(candidates[run_begin], index + 1);
          run_begin = c + 1;
        }
      }
      const std::size_t kept = std::min(k, ranked.size());
      std::partial_sort(ranked.begin(), ranked.begin() + static_cast<std::ptrdiff_t>(kept),
                        ranked.end(), nearer);
      ranked.resize(kept);
      results[query] = std::move(ranked);
    });
  };

  std::vector<QueryBlock> open(window);
  for (std::size_t first_block = 0; first_block < query_blocks; first_block += window) {
    const std::size_t in_window = std::min(window, query_blocks - first_block);
    std::size_t database_blocks = 0;
    for (std::size_t w = 0; w < in_window; ++w) {
      open_block(first_block + w, open[w]);
      database_blocks =
          std::max(database_blocks, (open[w].database_end + kDatabaseBlock - 1) / kDatabaseBlock);
    }
    // Database block major: the query blocks of the window read a database block at about the
    // same time, and the last tiles handed out are the smallest.
    std::vector<std::pair<std::size_t, std::size_t>> tiles;  // (window slot, database block)
    for (std::size_t b = 0; b < database_blocks; ++b) {
      for (std::size_t w = 0; w < in_window; ++w) {
        if (b * kDatabaseBlock < open[w].database_end) tiles.emplace_back(w, b);
      }
    }
    parallel_for(tiles.size(), threads, [&](std::size_t t) {
      std::unique_ptr<Scratch> scratch = borrow();
      search_tile(open[tiles[t].first], tiles[t].second * kDatabaseBlock, *scratch);
      give_back(std::move(scratch));
    });
    for (std::size_t w = 0; w < in_window; ++w) finish(open[w]);
    // The candidates' values read by distance() (in a drive, the frames along the route near
    // the nearest: dozens a query) are let go of too.
    database.release(0, database.size());
  }
  return results;
}

}  // namespace radarpr::retrieval_detail
