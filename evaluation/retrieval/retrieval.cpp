#include "evaluation/retrieval/retrieval.hpp"

#include "evaluation/parallel.hpp"
#include "evaluation/retrieval/blocked_l2_search.hpp"
#include "evaluation/retrieval/candidate_set.hpp"
#include "evaluation/retrieval/neighbour_ranking.hpp"
#include "evaluation/retrieval/projected_key_scan.hpp"
#include "evaluation/retrieval/retrieval_declaration.hpp"
#include "evaluation/retrieval/screened_search.hpp"

#include <flann/flann.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>

namespace radarpr {
namespace {

using namespace retrieval_detail;

// The distance functor of the KD-trees (FLANN's distance concept). It counts its evaluations
// per thread so that the planner can tell how much of the database a tree search visits.
struct KeyDistance {
  using is_kdtree_distance = bool;
  using ElementType = float;
  using ResultType = float;

  static inline thread_local std::size_t evaluations = 0;

  float operator()(const float* a, const float* b, std::size_t size, float /*worst*/ = -1) const {
    ++evaluations;
    return squared_l2(a, b, size);
  }
  template <typename U, typename V>
  float accum_dist(const U& a, const V& b, int /*dimension*/) const {
    return (a - b) * (a - b);
  }
};
using KeyTree = flann::KDTreeSingleIndex<KeyDistance>;

// Measured on 30,000 frames of 50 floats (single session): the block size and leaf size change
// the search time by under 10%; trees keep pointers into the key matrix (no reordered copy) so
// memory stays at one copy of the keys whatever the number of trees.
constexpr std::size_t kBlockSize = 256;
constexpr int kLeafSize = 16;
constexpr bool kReorder = false;
// Planner (trees_pay_off): the queries it samples, and the largest share of the eligible keys
// a tree search may evaluate before the projected scan (ProjectedKeyScan) is cheaper. Measured
// on 10^5 single-session keys of 50 floats, top-1 and top-10, CPU seconds: a smooth
// low-dimensional drive with noise 0.001 (trees evaluate 0.24% of the eligible keys) trees 1.4,
// scan 2.7; with noise 0.01 (1.5%) trees 1.9-2.4, scan 2.3-2.9; ReFeree values of a synthetic
// drive (14%) trees 47, scan 4.8.
constexpr std::size_t kPlannerSamples = 32;
constexpr double kTreeVisitLimit = 0.015;
// Trees are built only when the queries would scan at least this many times the keys indexed.
constexpr double kTreeBuildCostInScans = 8.0;

// Search keys as the rows of one contiguous matrix (FLANN indexes matrix rows).
struct KeyMatrix {
  std::size_t rows = 0;
  std::size_t dimension = 0;
  std::vector<float> data;
  const float* row(std::size_t i) const { return data.data() + i * dimension; }
};

KeyMatrix search_keys(const Descriptor& descriptor, const std::vector<DescriptorValue>& values,
                      const char* role, std::size_t expected_dimension) {
  KeyMatrix keys;
  keys.rows = values.size();
  keys.dimension = expected_dimension;
  for (std::size_t i = 0; i < values.size(); ++i) {
    const std::vector<float> key = descriptor.search_key(values[i]);
    if (keys.dimension == 0) {
      if (key.empty()) {
        throw std::invalid_argument(std::string("retrieve_nearest: the search key of ") + role +
                                    " value " + std::to_string(i) + " is empty");
      }
      keys.dimension = key.size();
      keys.data.reserve(values.size() * keys.dimension);
    }
    if (key.size() != keys.dimension) {
      throw std::invalid_argument(
          std::string("retrieve_nearest: search keys must all have the same length, but ") + role +
          " value " + std::to_string(i) + " has " + std::to_string(key.size()) + " floats where " +
          std::to_string(keys.dimension) + " were expected");
    }
    for (const float element : key) {
      if (!std::isfinite(element)) {
        throw std::invalid_argument(std::string("retrieve_nearest: the search key of ") + role +
                                    " value " + std::to_string(i) + " has a non-finite element");
      }
    }
    keys.data.insert(keys.data.end(), key.begin(), key.end());
  }
  return keys;
}

float max_squared_norm(const KeyMatrix& keys) {
  float largest = 0.0f;
  for (std::size_t i = 0; i < keys.rows; ++i) {
    float norm = 0.0f;
    for (std::size_t d = 0; d < keys.dimension; ++d) norm += keys.row(i)[d] * keys.row(i)[d];
    largest = std::max(largest, norm);
  }
  return largest;
}

std::vector<std::vector<Neighbour>> retrieve_exhaustive(
    const Descriptor& descriptor, const std::vector<DescriptorValue>& database,
    const std::vector<DescriptorValue>& queries, const std::vector<std::size_t>& eligible_ends,
    std::size_t k) {
  const std::unique_ptr<PreparedDistances> prepared =
      descriptor.prepare_distances(queries, database);
  if (const auto* screen = dynamic_cast<const ScreenedDistances*>(prepared.get())) {
    return retrieve_screened(*prepared, *screen, queries.size(), eligible_ends, k);
  }
  std::vector<std::vector<Neighbour>> results(queries.size());
  parallel_for(queries.size(), 0, [&](std::size_t q) {
    std::vector<Neighbour> heap;  // max-heap (farthest on top) of the k nearest so far
    heap.reserve(k + 1);
    for (std::size_t j = 0; j < eligible_ends[q]; ++j) {
      const Neighbour candidate{j, checked_distance(prepared->distance(q, j), q, j)};
      if (heap.size() < k) {
        heap.push_back(candidate);
        std::push_heap(heap.begin(), heap.end(), nearer);
      } else if (nearer(candidate, heap.front())) {
        std::pop_heap(heap.begin(), heap.end(), nearer);
        heap.back() = candidate;
        std::push_heap(heap.begin(), heap.end(), nearer);
      }
    }
    std::sort_heap(heap.begin(), heap.end(), nearer);
    results[q] = std::move(heap);
  });
  return results;
}

// Whether KD-trees beat a plain scan of the keys: a tree search costs several times a scanned
// key per key it evaluates, so in high intrinsic dimension (where it evaluates most keys) the
// scan wins. Decided on a sample of queries; both paths give the same, exact, result.
template <typename TreeSearch>
bool trees_pay_off(std::size_t query_count, const std::vector<std::size_t>& eligible_ends,
                   TreeSearch&& tree_search) {
  std::vector<std::size_t> searched;
  for (std::size_t q = 0; q < query_count; ++q) {
    if (eligible_ends[q] > 0) searched.push_back(q);
  }
  const std::size_t samples = std::min(kPlannerSamples, searched.size());
  if (samples == 0) return true;
  std::size_t eligible = 0;
  KeyDistance::evaluations = 0;
  for (std::size_t s = 0; s < samples; ++s) {
    const std::size_t q = searched[s * searched.size() / samples];
    eligible += eligible_ends[q];
    tree_search(q);
  }
  return static_cast<double>(KeyDistance::evaluations) <
         kTreeVisitLimit * static_cast<double>(eligible);
}

// An exact KD-tree over the keys of database frames [begin, end).
struct KeyBlock {
  std::size_t begin = 0;
  std::size_t end = 0;
  std::unique_ptr<KeyTree> tree;
};

// The parts a query's eligible prefix [0, end) is searched in: KD-trees over aligned blocks
// plus a short tail searched by brute force.
struct PrefixPlan {
  std::vector<std::size_t> blocks;  // indices into the block list
  std::size_t tail_begin = 0;
};

// The rerank_count nearest database indices by key distance (ties: smaller index), among
// candidates that hold at least them.
std::vector<std::size_t> nearest_by_key(const KeyMatrix& database_keys, const float* query_key,
                                        std::vector<std::size_t> candidates,
                                        std::size_t rerank_count) {
  std::vector<std::pair<float, std::size_t>> by_key;
  by_key.reserve(candidates.size());
  for (const std::size_t j : candidates) {
    by_key.emplace_back(squared_l2(query_key, database_keys.row(j), database_keys.dimension), j);
  }
  const std::size_t kept = std::min(rerank_count, by_key.size());
  std::partial_sort(by_key.begin(), by_key.begin() + static_cast<std::ptrdiff_t>(kept),
                    by_key.end());
  candidates.clear();
  for (std::size_t i = 0; i < kept; ++i) candidates.push_back(by_key[i].second);
  return candidates;
}

// KD-trees over the search keys. rerank_count == 0: the keys order the database like distance()
// (RetrievalMethod::kdtree), so the k nearest keys, ties included, are ranked by distance().
// rerank_count > 0: the rerank_count nearest keys are the candidates re-ranked by distance()
// (RetrievalMethod::key_then_rerank).
std::vector<std::vector<Neighbour>> retrieve_kdtree(const Descriptor& descriptor,
                                                    const std::vector<DescriptorValue>& database,
                                                    const std::vector<DescriptorValue>& queries,
                                                    const std::vector<std::size_t>& eligible_ends,
                                                    std::size_t k, std::size_t rerank_count) {
  const std::size_t key_k = rerank_count == 0 ? k : rerank_count;
  const KeyMatrix database_keys = search_keys(descriptor, database, "database", 0);
  const bool same_values = &database == &queries;
  const KeyMatrix query_keys =
      same_values ? KeyMatrix{}
                  : search_keys(descriptor, queries, "query", database_keys.dimension);
  const KeyMatrix& queries_keys = same_values ? database_keys : query_keys;
  const std::size_t dimension = database_keys.dimension;
  const float scale =
      std::max(max_squared_norm(database_keys), same_values ? 0.0f : max_squared_norm(query_keys));
  // A squared key distance is at most 4x the largest squared norm; past float range it would be
  // infinite, fail every comparison and silently drop the query.
  if (!std::isfinite(4.0f * scale)) {
    throw std::invalid_argument(
        "retrieve_nearest: search keys are too large for float distances (squared norms overflow)");
  }
  const float absolute_band =
      std::max(scale * kAbsoluteBandPerSquaredNorm, std::numeric_limits<float>::min());

  // Plan every query's blocks, then build each distinct block once.
  std::map<std::pair<std::size_t, std::size_t>, std::size_t> block_ids;
  std::vector<KeyBlock> blocks;
  auto block_id = [&](std::size_t begin, std::size_t end) {
    const auto [it, inserted] = block_ids.try_emplace({begin, end}, blocks.size());
    if (inserted) blocks.push_back({begin, end, nullptr});
    return it->second;
  };
  std::vector<PrefixPlan> plans(queries.size());
  const bool one_prefix = std::adjacent_find(eligible_ends.begin(), eligible_ends.end(),
                                             std::not_equal_to<>()) == eligible_ends.end();
  for (std::size_t q = 0; q < queries.size(); ++q) {
    const std::size_t end = eligible_ends[q];
    PrefixPlan& plan = plans[q];
    if (one_prefix) {
      // Every query sees the same database (multi session): one tree over all of it.
      if (end > 0) plan.blocks.push_back(block_id(0, end));
      plan.tail_begin = end;
      continue;
    }
    const std::size_t full_blocks = end / kBlockSize;
    // The binary digits of the number of full blocks give aligned power-of-two runs of blocks,
    // largest first, so a query searches at most log2(end / block) trees.
    std::size_t begin = 0;
    for (int bit = std::numeric_limits<std::size_t>::digits - 1; bit >= 0; --bit) {
      const std::size_t run = std::size_t{1} << bit;
      if ((full_blocks & run) == 0) continue;
      plan.blocks.push_back(block_id(begin, begin + run * kBlockSize));
      begin += run * kBlockSize;
    }
    plan.tail_begin = begin;
  }
  const flann::SearchParams exact(flann::FLANN_CHECKS_UNLIMITED, 0.0f);
  // Key candidates of query q within database [0, end): through the trees or by a full scan.
  auto collect = [&](std::size_t q, bool through_trees) {
    const std::size_t end = eligible_ends[q];
    const float* query_key = queries_keys.row(q);
    CandidateSet candidates(key_k, absolute_band);
    std::size_t scan_begin = 0;
    if (through_trees) {
      for (const std::size_t b : plans[q].blocks) {
        candidates.set_offset(blocks[b].begin);
        blocks[b].tree->findNeighbors(candidates, query_key, exact);
      }
      candidates.set_offset(0);
      scan_begin = plans[q].tail_begin;
    }
    for (std::size_t j = scan_begin; j < end; ++j) {
      candidates.addPoint(squared_l2(query_key, database_keys.row(j), dimension), j);
    }
    return candidates.indices();
  };
  // Building a tree costs about as much as scanning its keys a few times: with few queries
  // (little scanning to save) the trees are not built at all.
  std::size_t indexed = 0;
  for (const KeyBlock& block : blocks) indexed += block.end - block.begin;
  std::size_t eligible = 0;
  for (const std::size_t end : eligible_ends) eligible += end;
  bool use_trees = !blocks.empty() && static_cast<double>(eligible) >=
                                          kTreeBuildCostInScans * static_cast<double>(indexed);
  if (use_trees) {
    parallel_for(blocks.size(), 0, [&](std::size_t b) {
      KeyBlock& block = blocks[b];
      const flann::Matrix<float> rows(const_cast<float*>(database_keys.row(block.begin)),
                                      block.end - block.begin, dimension);
      block.tree =
          std::make_unique<KeyTree>(rows, flann::KDTreeSingleIndexParams(kLeafSize, kReorder));
      block.tree->buildIndex();
    });
    use_trees =
        trees_pay_off(queries.size(), eligible_ends, [&](std::size_t q) { collect(q, true); });
  }

  std::vector<std::vector<Neighbour>> results(queries.size());
  auto finish = [&](std::size_t q, std::vector<std::size_t> candidates) {
    if (rerank_count > 0) {
      candidates =
          nearest_by_key(database_keys, queries_keys.row(q), std::move(candidates), rerank_count);
    }
    results[q] = rank_by_distance(descriptor, queries[q], database, candidates, k, q);
  };
  if (use_trees) {
    parallel_for(queries.size(), 0, [&](std::size_t q) {
      if (eligible_ends[q] == 0) return;
      finish(q, collect(q, true));
    });
    return results;
  }
  // Where trees would touch most keys anyway: every key, each rejected by a cheap bound where
  // it can be (ProjectedKeyScan), in blocks of queries that share the passes over the database.
  const ProjectedKeyScan scan(database_keys.data.data(), database_keys.rows, dimension);
  const std::vector<float> projected_query_rows =
      same_values ? std::vector<float>{} : scan.project(query_keys.data.data(), query_keys.rows);
  const float* projected_queries =
      same_values ? scan.projected_database().data() : projected_query_rows.data();
  float projected_scale = scan.max_squared_norm();
  for (std::size_t i = 0; i < (same_values ? 0 : queries.size()); ++i) {
    float norm = 0.0f;
    for (std::size_t d = 0; d < dimension; ++d) {
      norm += projected_queries[i * dimension + d] * projected_queries[i * dimension + d];
    }
    projected_scale = std::max(projected_scale, norm);
  }
  if (!std::isfinite(4.0f * projected_scale)) {
    throw std::invalid_argument(
        "retrieve_nearest: search keys are too large for float distances (squared norms overflow "
        "once centred)");
  }
  const float projected_band = std::max({projected_scale * kAbsoluteBandPerSquaredNorm,
                                         ProjectedKeyScan::projection_error(projected_scale),
                                         std::numeric_limits<float>::min()});
  constexpr std::size_t kQueriesPerTask = 256;
  const std::size_t tasks = (queries.size() + kQueriesPerTask - 1) / kQueriesPerTask;
  parallel_for(tasks, 0, [&](std::size_t task) {
    const std::size_t begin = task * kQueriesPerTask;
    const std::size_t end = std::min(queries.size(), begin + kQueriesPerTask);
    const std::vector<std::size_t> ends(eligible_ends.begin() + static_cast<std::ptrdiff_t>(begin),
                                        eligible_ends.begin() + static_cast<std::ptrdiff_t>(end));
    std::vector<CandidateSet> candidates(end - begin, CandidateSet(key_k, projected_band));
    scan.collect(projected_queries + begin * dimension, ends, candidates);
    for (std::size_t q = begin; q < end; ++q) {
      if (eligible_ends[q] == 0) continue;
      finish(q, candidates[q - begin].indices());
    }
  });
  return results;
}

// One eligible end per query, none beyond the database.
void check_eligible_ends(const std::vector<std::size_t>& eligible_ends, std::size_t query_count,
                         std::size_t database_size) {
  if (eligible_ends.size() != query_count) {
    throw std::invalid_argument("retrieve_nearest: " + std::to_string(query_count) +
                                " queries but " + std::to_string(eligible_ends.size()) +
                                " eligible ends");
  }
  for (std::size_t q = 0; q < eligible_ends.size(); ++q) {
    if (eligible_ends[q] > database_size) {
      throw std::invalid_argument("retrieve_nearest: the eligible end of query " +
                                  std::to_string(q) + " is " + std::to_string(eligible_ends[q]) +
                                  ", beyond the database's " + std::to_string(database_size) +
                                  " values");
    }
  }
}

}  // namespace

std::vector<std::vector<Neighbour>> retrieve_nearest_l2(
    const Descriptor& descriptor, const L2Rows& database, const L2Rows& queries,
    const std::vector<std::size_t>& eligible_ends, std::size_t k) {
  if (descriptor.retrieval_method() != RetrievalMethod::exhaustive_l2) {
    throw std::invalid_argument(
        "retrieve_nearest_l2: values read in place are searched by exhaustive_l2 only, and this "
        "descriptor declares another retrieval method");
  }
  check_eligible_ends(eligible_ends, queries.size(), database.size());
  if (k == 0 || database.size() == 0) return std::vector<std::vector<Neighbour>>(queries.size());
  if (database.dimension() == 0) {
    throw std::invalid_argument("retrieve_nearest: exhaustive_l2 values must not be empty");
  }
  if (queries.size() > 0 && queries.dimension() != database.dimension()) {
    throw std::invalid_argument(
        "retrieve_nearest: exhaustive_l2 values must all have the same length, but the queries "
        "have " +
        std::to_string(queries.dimension()) + " floats where " +
        std::to_string(database.dimension()) + " were expected");
  }
  check_exhaustive_l2_rows(descriptor, database, queries);
  return retrieve_exhaustive_l2(descriptor, database, queries, eligible_ends, k);
}

std::vector<std::vector<Neighbour>> retrieve_nearest(const Descriptor& descriptor,
                                                     const std::vector<DescriptorValue>& database,
                                                     const std::vector<DescriptorValue>& queries,
                                                     const std::vector<std::size_t>& eligible_ends,
                                                     std::size_t k) {
  check_eligible_ends(eligible_ends, queries.size(), database.size());
  if (k == 0 || database.empty()) return std::vector<std::vector<Neighbour>>(queries.size());
  check_retrieval_declaration(descriptor, database, queries);
  switch (descriptor.retrieval_method()) {
    case RetrievalMethod::kdtree:
      return retrieve_kdtree(descriptor, database, queries, eligible_ends, k, 0);
    case RetrievalMethod::key_then_rerank: {
      const std::size_t rerank_count = descriptor.rerank_candidates();
      if (rerank_count == 0) {
        throw std::invalid_argument(
            "retrieve_nearest: a key_then_rerank descriptor must re-rank at least one candidate");
      }
      return retrieve_kdtree(descriptor, database, queries, eligible_ends, k, rerank_count);
    }
    case RetrievalMethod::exhaustive:
      return retrieve_exhaustive(descriptor, database, queries, eligible_ends, k);
    case RetrievalMethod::exhaustive_l2:
      return retrieve_exhaustive_l2(descriptor, database, queries, eligible_ends, k);
  }
  throw std::logic_error("retrieve_nearest: unknown retrieval method");
}

}  // namespace radarpr
