#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "benchmarks/bench_plan.hpp"

namespace radarpr::bench {

struct RetrievalBenchOptions {
  std::vector<std::string> descriptor_ids;  // empty = default_retrieval_descriptor_ids()
  std::vector<std::size_t> database_sizes = {1'000, 10'000, 100'000};
  // Single session: query i searches frames 0..i-E (the paper protocol's 50 frames).
  std::size_t exclude_recent = 50;
  // Database sizes whose values (both sessions) would take more memory are skipped.
  std::size_t memory_budget_bytes = std::size_t{3} << 30;
  // Above these amounts of work per timed call, a sample of the queries is timed and the total
  // extrapolated: queries for `key_then_rerank` (each re-ranks its candidates at a cost that
  // hardly depends on N), pairs of values for `exhaustive`, multiply-adds for `exhaustive_l2`.
  // `kdtree` always times every query.
  std::size_t reranked_queries_per_call = 10'000;
  double exhaustive_pairs_per_call = 2e8;
  double l2_multiply_adds_per_call = 3e10;
  // exhaustive_l2 single sessions over the memory budget: the values are written to a .npy in
  // `mapped_folder` (empty: the system's temporary folder), memory-mapped and the search
  // streamed from the map, timing this many queries spread over the session (once: the file
  // alone takes a minute to write) and extrapolating the total.
  std::size_t mapped_queries = 256;
  std::string mapped_folder;
};

// Per retrieval method, the first built-in descriptor (by name, at its defaults) that uses it,
// plus open_radvlad:bin_dim=10 (RadVLAD-DS, 640 floats) when open_radvlad is registered. Plugin
// descriptors never: loading a plugin does not change what the default run measures.
std::vector<std::string> default_retrieval_descriptor_ids();

// The defaults, plus each of `named_ids` (`radarpr bench --descriptor`) whose descriptor comes
// from a plugin: the built-ins' retrieval methods are covered by the defaults already.
std::vector<std::string> retrieval_descriptor_ids(const std::vector<std::string>& named_ids);

// For every descriptor and database size, on synthetic drive values (drive_values.hpp) of the
// descriptor's shape on a 400 x 3360 scan:
// - retrieval/<method>/<id>/<N>/multi: N queries of a second session against N values;
// - retrieval/<method>/<id>/<N>/single: query i of one session against its frames 0..i-E;
// - index_build/<method>/<id>/<N>/database: the part that does not depend on the queries - the
// search
//   keys and a KD-tree over them (kdtree, key_then_rerank; FLANN, leaf size 16), or
//   prepare_distances over the database (exhaustive); exhaustive_l2 has none;
// - eigen_product/<id>/<N>/<session> (exhaustive_l2): the float products of the same shapes, in
//   blocks of database rows on every core (single session: per block, the sampled queries whose
//   prefix reaches into it).
// - retrieval/exhaustive_l2/<id>/<N>/single over the memory budget: the values written to a
//   temporary .npy (its folder removed once mapped, or on failure), memory-mapped and searched
//   streamed from the map; counters peak_rss_bytes (the process's peak resident memory during
//   the search) and values_bytes (the file's size).
// Retrieval runs on every core and is timed by wall clock, k = 1.
void add_retrieval_benchmarks(BenchPlan& plan, const RetrievalBenchOptions& options);

}  // namespace radarpr::bench
