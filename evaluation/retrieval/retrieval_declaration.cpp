#include "evaluation/retrieval/retrieval_declaration.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <utility>

#include <fmt/format.h>

#include "evaluation/parallel.hpp"
#include "evaluation/retrieval/blocked_l2_search.hpp"

namespace radarpr {
namespace {

// Enough pairs to catch a distance that orders values differently from L2 (a Hellinger distance
// over 64 database values disagrees with L2 within a few queries), few enough to cost nothing
// beside the search itself.
constexpr std::size_t kSampleQueries = 16;
constexpr std::size_t kSampleDatabase = 64;
// The exhaustive_l2 check compares values, not orders: a distance other than L2 differs from it on
// nearly every pair. Long values take fewer database values per query, at most kSampleElements
// floats of queries' pairs in all but at least kMinimumSampleDatabase a query: a distance() of
// 32,768 floats (Open-RadVLAD's, one chain of dependent additions) costs as much as some 30 of the
// search's product pairs, and 16 x 64 of them took 3.6 % of a multi-session search of 91 queries
// against 10^4 such values (perf record), about twice that share of a single-session one.
constexpr std::size_t kSampleElements = std::size_t{1} << 22;
constexpr std::size_t kMinimumSampleDatabase = 8;
// Float keys and double distances: agreement is up to rounding, relative to the largest distance.
constexpr double kRelativeTolerance = 1e-5;

std::vector<std::size_t> spread_indices(std::size_t size, std::size_t count) {
  std::vector<std::size_t> indices;
  const std::size_t taken = std::min(size, count);
  for (std::size_t i = 0; i < taken; ++i) indices.push_back(i * size / taken);
  return indices;
}

double key_distance(const std::vector<float>& a, const std::vector<float>& b) {
  if (a.size() != b.size()) {
    throw std::invalid_argument(fmt::format(
        "retrieval: search keys of {} and {} elements cannot be compared", a.size(), b.size()));
  }
  double sum = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const double difference = static_cast<double>(a[i]) - static_cast<double>(b[i]);
    sum += difference * difference;
  }
  return std::sqrt(sum);
}

// The L2 distance in eight independent double sums (one chain of 32,768 dependent additions
// costs as much as the rest of the check): the order moves it by far less than the tolerance.
double lane_l2(const float* a, const float* b, std::size_t size) {
  double lanes[8] = {};
  std::size_t i = 0;
  for (; i + 8 <= size; i += 8) {
    for (std::size_t lane = 0; lane < 8; ++lane) {
      const double difference = static_cast<double>(a[i + lane]) - b[i + lane];
      lanes[lane] += difference * difference;
    }
  }
  double sum = ((lanes[0] + lanes[4]) + (lanes[1] + lanes[5])) +
               ((lanes[2] + lanes[6]) + (lanes[3] + lanes[7]));
  for (; i < size; ++i) {
    const double difference = static_cast<double>(a[i]) - b[i];
    sum += difference * difference;
  }
  return std::sqrt(sum);
}

struct SampledPair {
  std::size_t database_index;
  double key;
  double own;
};

void check_kdtree(const Descriptor& descriptor, const std::vector<DescriptorValue>& database,
                  const std::vector<DescriptorValue>& queries) {
  const std::vector<std::size_t> sampled_database =
      spread_indices(database.size(), kSampleDatabase);
  std::vector<std::vector<float>> database_keys;
  for (const std::size_t i : sampled_database) {
    database_keys.push_back(descriptor.search_key(database[i]));
  }
  for (const std::size_t q : spread_indices(queries.size(), kSampleQueries)) {
    const std::vector<float> query_key = descriptor.search_key(queries[q]);
    std::vector<SampledPair> pairs;
    double largest_key = 0.0;
    double largest_own = 0.0;
    for (std::size_t j = 0; j < sampled_database.size(); ++j) {
      const std::size_t d = sampled_database[j];
      const SampledPair pair{d, key_distance(query_key, database_keys[j]),
                             descriptor.distance(queries[q], database[d])};
      largest_key = std::max(largest_key, pair.key);
      largest_own = std::max(largest_own, std::abs(pair.own));
      pairs.push_back(pair);
    }
    std::sort(pairs.begin(), pairs.end(),
              [](const SampledPair& a, const SampledPair& b) { return a.key < b.key; });
    const double key_tolerance = kRelativeTolerance * largest_key;
    const double own_tolerance = kRelativeTolerance * largest_own;
    // Walking outwards by key distance, distance() may not fall below what a key-closer value
    // already had: the KD-tree would then return the key-closer value as the nearest.
    std::size_t highest = 0;
    for (std::size_t i = 1; i < pairs.size(); ++i) {
      if (pairs[i].own < pairs[highest].own - own_tolerance &&
          pairs[i].key > pairs[highest].key + key_tolerance) {
        throw std::invalid_argument(fmt::format(
            "retrieval: the descriptor declares kdtree retrieval, but its distance() does not "
            "order values as the L2 distance of their search keys: query {} is nearer to database "
            "value {} by distance() ({:.9g} < {:.9g}) yet farther by key ({:.9g} > {:.9g}) than "
            "to value {}; use the default (exhaustive) retrieval or a key whose L2 distance "
            "orders values as distance() does",
            q, pairs[i].database_index, pairs[i].own, pairs[highest].own, pairs[i].key,
            pairs[highest].key, pairs[highest].database_index));
      }
      if (pairs[i].own > pairs[highest].own) highest = i;
    }
  }
}

void check_exhaustive_l2(const Descriptor& descriptor, const std::vector<DescriptorValue>& database,
                         const std::vector<DescriptorValue>& queries) {
  // Lengths first: the descriptor's distance() may take equal lengths for granted.
  if (database.empty()) return;
  static_cast<void>(retrieval_detail::common_dimension(database, queries));
  const L2Rows database_rows(database);
  check_exhaustive_l2_rows(descriptor, database_rows,
                           &queries == &database ? database_rows : L2Rows(queries));
}

}  // namespace

void check_exhaustive_l2_rows(const Descriptor& descriptor, const L2Rows& database,
                              const L2Rows& queries) {
  const std::vector<std::size_t> sampled_queries = spread_indices(queries.size(), kSampleQueries);
  const std::size_t affordable =
      kSampleElements / (kSampleQueries * std::max<std::size_t>(1, database.dimension()));
  const std::vector<std::size_t> sampled_database = spread_indices(
      database.size(), std::clamp(affordable, kMinimumSampleDatabase, kSampleDatabase));
  const std::size_t per_query = sampled_database.size();
  // Both distances of every sampled pair, in parallel (a pair of 32,768-float values costs as
  // much as some 30 pairs of the search's products), then checked in order, so that the
  // error names the first offending pair whatever the thread count.
  std::vector<std::pair<double, double>> distances(sampled_queries.size() * per_query);
  parallel_for(sampled_queries.size(), 0, [&](std::size_t i) {
    DescriptorValue query_copy;
    DescriptorValue database_copy;
    const DescriptorValue& query = queries.value(sampled_queries[i], query_copy);
    for (std::size_t j = 0; j < per_query; ++j) {
      const DescriptorValue& value = database.value(sampled_database[j], database_copy);
      distances[i * per_query + j] = {
          descriptor.distance(query, value),
          lane_l2(query.values.data(), value.values.data(), database.dimension())};
    }
  });
  database.release(0, database.size());
  queries.release(0, queries.size());
  for (std::size_t i = 0; i < sampled_queries.size(); ++i) {
    for (std::size_t j = 0; j < per_query; ++j) {
      const auto [own, l2] = distances[i * per_query + j];
      if (std::abs(own - l2) > kRelativeTolerance * std::max({1e-12, std::abs(own), l2})) {
        throw std::invalid_argument(fmt::format(
            "retrieval: the descriptor declares exhaustive_l2 retrieval, but its distance() is "
            "not the L2 distance of the values: query {} to database value {} is {:.9g} by "
            "distance(), {:.9g} by L2; use the default (exhaustive) retrieval",
            sampled_queries[i], sampled_database[j], own, l2));
      }
    }
  }
}

void check_retrieval_declaration(const Descriptor& descriptor,
                                 const std::vector<DescriptorValue>& database,
                                 const std::vector<DescriptorValue>& queries) {
  switch (descriptor.retrieval_method()) {
    case RetrievalMethod::kdtree:
      check_kdtree(descriptor, database, queries);
      return;
    case RetrievalMethod::exhaustive_l2:
      check_exhaustive_l2(descriptor, database, queries);
      return;
    case RetrievalMethod::key_then_rerank:
    case RetrievalMethod::exhaustive:
      return;
  }
}

}  // namespace radarpr
