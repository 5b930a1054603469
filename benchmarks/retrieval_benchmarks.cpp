#include "benchmarks/retrieval_benchmarks.hpp"

#include <flann/flann.hpp>

#include <Eigen/Core>

#include <stdlib.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>
#include <stdexcept>
#include <utility>

#include <fmt/format.h>

#include "benchmarks/drive_values.hpp"
#include "datasets/npy_file.hpp"
#include "datasets/real/mulran_dataset.hpp"
#include "descriptors/descriptor_registry.hpp"
#include "descriptors/precomputed/external_values.hpp"
#include "evaluation/mapped_value_matrix.hpp"
#include "evaluation/parallel.hpp"
#include "evaluation/retrieval/retrieval.hpp"

namespace radarpr::bench {
namespace {

using Values = std::vector<DescriptorValue>;

std::string_view method_name(RetrievalMethod method) {
  switch (method) {
    case RetrievalMethod::kdtree:
      return "kdtree";
    case RetrievalMethod::key_then_rerank:
      return "key_then_rerank";
    case RetrievalMethod::exhaustive:
      return "exhaustive";
    case RetrievalMethod::exhaustive_l2:
      return "exhaustive_l2";
  }
  return "unknown";
}

// The two sessions of one drive at one database size. Only the most recent pair is kept: the
// benchmarks of one size run one after another, and the largest take gigabytes.
struct Sessions {
  Values first;   // the database (and, single session, the queries)
  Values second;  // multi-session queries
};

std::string& cached_sessions_key() {
  static std::string key;
  return key;
}
std::shared_ptr<const Sessions>& cached_sessions() {
  static std::shared_ptr<const Sessions> sessions;
  return sessions;
}

std::shared_ptr<const Sessions> drive_sessions(const DescriptorShape& shape, std::size_t count) {
  std::string& cached_key = cached_sessions_key();
  std::shared_ptr<const Sessions>& cached = cached_sessions();
  const std::string key = fmt::format("{}x{}/{}", shape.rows, shape.cols, count);
  if (key == cached_key && cached) return cached;
  cached.reset();  // free the previous drive before building the next one
  DriveValuesSpec spec;
  spec.count = count;
  spec.rows = shape.rows;
  spec.cols = shape.cols;
  auto sessions = std::make_shared<Sessions>();
  sessions->first = drive_values(spec);
  spec.session = 1;
  sessions->second = drive_values(spec);
  cached_key = key;
  cached = sessions;
  return cached;
}

// The timed queries: all of them, or `sampled` spread evenly over the sequence.
std::vector<std::size_t> query_indices(std::size_t count, std::size_t sampled) {
  std::vector<std::size_t> indices;
  for (std::size_t k = 0; k < sampled; ++k) indices.push_back((2 * k + 1) * count / (2 * sampled));
  return indices;
}

std::size_t single_session_end(std::size_t query, std::size_t exclude) {
  return query >= exclude ? query - exclude + 1 : 0;
}

// The case's timed and total query counts and (query, database value) pairs: every query sees
// the whole database in a multi session, its prefix in a single one.
void count_queries_and_pairs(BenchCase& bench, std::size_t count, std::size_t queries, bool single,
                             std::size_t exclude) {
  bench.queries_timed = queries;
  bench.queries_total = count;
  for (const std::size_t q : query_indices(count, queries)) {
    bench.pairs_timed += single ? single_session_end(q, exclude) : count;
  }
  for (std::size_t q = 0; q < count; ++q) {
    bench.pairs_total += single ? single_session_end(q, exclude) : count;
  }
}

// How many queries one timed call searches.
std::size_t timed_queries(RetrievalMethod method, std::size_t count, std::size_t dimension,
                          const RetrievalBenchOptions& options) {
  double affordable = static_cast<double>(count);
  const double n = static_cast<double>(count);
  if (method == RetrievalMethod::key_then_rerank) {
    affordable = static_cast<double>(options.reranked_queries_per_call);
  }
  if (method == RetrievalMethod::exhaustive) affordable = options.exhaustive_pairs_per_call / n;
  if (method == RetrievalMethod::exhaustive_l2) {
    affordable = options.l2_multiply_adds_per_call / (n * static_cast<double>(dimension));
  }
  // Timing nearly all of them would save little and make the total an estimate.
  if (affordable >= 0.5 * n) return count;
  return static_cast<std::size_t>(std::max(16.0, std::floor(affordable)));
}

struct RetrievalCase {
  std::shared_ptr<const Descriptor> descriptor;
  DescriptorShape shape;
  std::size_t count = 0;
  std::size_t queries = 0;  // timed
  bool single_session = false;
  std::size_t exclude_recent = 50;
};

void run_retrieval(benchmark::State& state, const RetrievalCase& c) {
  const std::shared_ptr<const Sessions> sessions = drive_sessions(c.shape, c.count);
  const Values& database = sessions->first;
  const bool all = c.queries == c.count;
  Values sampled;
  std::vector<std::size_t> ends;
  for (const std::size_t q : query_indices(c.count, c.queries)) {
    if (!all) sampled.push_back(c.single_session ? database[q] : sessions->second[q]);
    ends.push_back(c.single_session ? single_session_end(q, c.exclude_recent) : c.count);
  }
  // A whole single session passes the database twice, as the evaluation does.
  const Values& queries = !all ? sampled : c.single_session ? database : sessions->second;
  for (auto _ : state) {
    auto neighbours = retrieve_nearest(*c.descriptor, database, queries, ends, 1);
    benchmark::DoNotOptimize(neighbours.data());
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(queries.size()));
}

// Removes a folder and everything in it when it goes out of scope, also on an exception.
class FolderRemoval {
 public:
  explicit FolderRemoval(std::filesystem::path folder) : folder_(std::move(folder)) {}
  FolderRemoval(const FolderRemoval&) = delete;
  FolderRemoval& operator=(const FolderRemoval&) = delete;
  ~FolderRemoval() {
    std::error_code ignored;
    std::filesystem::remove_all(folder_, ignored);
  }

 private:
  std::filesystem::path folder_;
};

// The first session of the drive of `count` values written as a count x rows x cols float32
// .npy into a new folder under `parent` a block at a time (never held whole), then mapped; the
// folder is removed before returning (also when writing fails): the map keeps the file's data
// until it is unmapped. Throws std::runtime_error when `parent` lacks the space or a write fails.
std::shared_ptr<const MappedValueMatrix> write_and_map_drive(const DescriptorShape& shape,
                                                             std::size_t count,
                                                             const std::filesystem::path& parent) {
  namespace fs = std::filesystem;
  DriveValuesSpec spec;
  spec.count = count;
  spec.rows = shape.rows;
  spec.cols = shape.cols;
  const DriveValueGenerator generator(spec);
  const std::size_t dimension = generator.dimension();
  const std::string header = npy_file_header(
      NpyDtype::float32,
      {count, static_cast<std::size_t>(shape.rows), static_cast<std::size_t>(shape.cols)});
  const std::uintmax_t bytes = header.size() + std::uintmax_t{count} * dimension * sizeof(float);
  constexpr std::uintmax_t kSpareBytes = std::uintmax_t{1} << 30;  // left to everyone else
  const fs::space_info space = fs::space(parent);
  if (space.available < bytes + kSpareBytes) {
    throw std::runtime_error(fmt::format(
        "the values ({:.1f} GB) need {:.1f} GB free in {}, {:.1f} GB are",
        static_cast<double>(bytes) / 1e9, static_cast<double>(bytes + kSpareBytes) / 1e9,
        parent.string(), static_cast<double>(space.available) / 1e9));
  }
  std::string pattern = (parent / "radarpr-bench-values-XXXXXX").string();
  if (::mkdtemp(pattern.data()) == nullptr) {
    throw std::runtime_error(fmt::format("cannot create a folder in {}", parent.string()));
  }
  const fs::path folder = pattern;
  const FolderRemoval removal(folder);
  const fs::path file = folder / "values.npy";
  std::ofstream out(file, std::ios::binary);
  out.write(header.data(), static_cast<std::streamsize>(header.size()));
  constexpr std::size_t kWriteBlock = 256;  // values generated in parallel, then written
  std::vector<float> block(kWriteBlock * dimension);
  for (std::size_t begin = 0; begin < count && out; begin += kWriteBlock) {
    const std::size_t values = std::min(kWriteBlock, count - begin);
    parallel_for(values, 0,
                 [&](std::size_t i) { generator.value(begin + i, block.data() + i * dimension); });
    out.write(reinterpret_cast<const char*>(block.data()),
              static_cast<std::streamsize>(values * dimension * sizeof(float)));
  }
  out.close();
  if (!out) throw std::runtime_error(fmt::format("writing {} failed", file.string()));
  return std::make_shared<const MappedValueMatrix>(MappedValueMatrix::open(file));
}

// The process's peak resident memory (VmHWM of /proc/self/status) in bytes; 0 where unknown.
double peak_resident_bytes() {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line)) {
    if (line.rfind("VmHWM:", 0) == 0) return std::stod(line.substr(6)) * 1024.0;  // kB
  }
  return 0.0;
}

// Sets the peak resident memory back to the current one (Linux: "5" to clear_refs), so that
// peak_resident_bytes() then covers what follows; false where the kernel refuses.
bool reset_peak_resident() {
  std::ofstream clear("/proc/self/clear_refs");
  clear << "5";
  clear.close();
  return static_cast<bool>(clear);
}

// A single session whose values exceed the memory budget: written to a .npy, mapped, and the
// sampled queries searched against their whole prefixes streamed from the map.
void run_mapped_retrieval(benchmark::State& state, const RetrievalCase& c,
                          const std::string& folder) {
  static std::string cached_key;
  static std::shared_ptr<const MappedValueMatrix> cached;
  try {
    // The in-memory drives of the smaller sizes are not needed any more.
    cached_sessions().reset();
    cached_sessions_key().clear();
    const std::string key = fmt::format("{}x{}/{}", c.shape.rows, c.shape.cols, c.count);
    if (key != cached_key || !cached) {
      cached.reset();
      cached = write_and_map_drive(
          c.shape, c.count,
          folder.empty() ? std::filesystem::temp_directory_path() : std::filesystem::path(folder));
      cached_key = key;
    }
    const MappedValueMatrix& matrix = *cached;
    const L2Rows database = matrix.l2_rows();
    std::vector<DescriptorValue> queries;
    std::vector<std::size_t> ends;
    for (const std::size_t q : query_indices(c.count, c.queries)) {
      DescriptorValue value;
      value.rows = matrix.rows();
      value.cols = matrix.cols();
      value.values.assign(matrix.data() + q * matrix.dimension(),
                          matrix.data() + (q + 1) * matrix.dimension());
      queries.push_back(std::move(value));
      ends.push_back(single_session_end(q, c.exclude_recent));
    }
    matrix.release(0, matrix.size());
    const bool reset = reset_peak_resident();
    for (auto _ : state) {
      auto neighbours = retrieve_nearest_l2(*c.descriptor, database, L2Rows(queries), ends, 1);
      benchmark::DoNotOptimize(neighbours.data());
    }
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(queries.size()));
    state.counters["peak_rss_bytes"] = peak_resident_bytes();
    state.counters["peak_rss_since_search"] = reset ? 1.0 : 0.0;
    state.counters["values_bytes"] =
        static_cast<double>(matrix.size() * matrix.dimension() * sizeof(float));
  } catch (const std::exception& failure) {
    state.SkipWithError(failure.what());
  }
}

void build_key_tree(benchmark::State& state, const Descriptor& descriptor,
                    const DescriptorShape& shape, std::size_t count) {
  const std::shared_ptr<const Sessions> sessions = drive_sessions(shape, count);
  for (auto _ : state) {
    std::vector<float> keys;
    std::size_t dimension = 0;
    for (const DescriptorValue& value : sessions->first) {
      const std::vector<float> key = descriptor.search_key(value);
      dimension = key.size();
      keys.insert(keys.end(), key.begin(), key.end());
    }
    const flann::Matrix<float> rows(keys.data(), count, dimension);
    flann::KDTreeSingleIndex<flann::L2<float>> tree(rows,
                                                    flann::KDTreeSingleIndexParams(16, false));
    tree.buildIndex();
    benchmark::DoNotOptimize(tree.size());
  }
}

void prepare_database(benchmark::State& state, const Descriptor& descriptor,
                      const DescriptorShape& shape, std::size_t count) {
  const std::shared_ptr<const Sessions> sessions = drive_sessions(shape, count);
  const Values one_query{sessions->second.front()};
  for (auto _ : state) {
    auto prepared = descriptor.prepare_distances(one_query, sessions->first);
    benchmark::DoNotOptimize(prepared.get());
  }
}

// Q x D times D x N in blocks of database rows (the result of one block only), on every core.
// Single session: the same sampled queries and ends as the search (`ends` from
// single_session_end), and per database block only the queries whose prefix reaches into it,
// against the rows up to the largest prefix: the shapes the blocked search multiplies.
void eigen_product(benchmark::State& state, const DescriptorShape& shape, std::size_t count,
                   std::size_t queries, bool single_session, std::size_t exclude) {
  using Matrix = Eigen::Matrix<float, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
  constexpr std::size_t kBlock = 512;  // database rows per product: many blocks for the threads
  const auto dimension = static_cast<Eigen::Index>(shape.element_count());
  const std::shared_ptr<const Sessions> sessions = drive_sessions(shape, count);
  Matrix query_rows(static_cast<Eigen::Index>(queries), dimension);
  const std::vector<std::size_t> indices = query_indices(count, queries);
  std::vector<std::size_t> ends;
  for (std::size_t k = 0; k < queries; ++k) {
    const Values& source = single_session ? sessions->first : sessions->second;
    const auto& v = source[indices[k]].values;
    std::copy(v.begin(), v.end(), query_rows.row(static_cast<Eigen::Index>(k)).data());
    ends.push_back(single_session ? single_session_end(indices[k], exclude) : count);
  }
  const std::size_t rows_used = *std::max_element(ends.begin(), ends.end());
  Matrix database_rows(static_cast<Eigen::Index>(count), dimension);
  for (std::size_t j = 0; j < count; ++j) {
    const auto& v = sessions->first[j].values;
    std::copy(v.begin(), v.end(), database_rows.row(static_cast<Eigen::Index>(j)).data());
  }
  const std::size_t blocks = (rows_used + kBlock - 1) / kBlock;
  for (auto _ : state) {
    parallel_for(blocks, 0, [&](std::size_t b) {
      const auto begin = static_cast<Eigen::Index>(b * kBlock);
      const auto rows = std::min<Eigen::Index>(static_cast<Eigen::Index>(kBlock),
                                               static_cast<Eigen::Index>(rows_used) - begin);
      // The sampled queries' ends grow with their index: the first active one onwards.
      const auto first_active = static_cast<Eigen::Index>(
          std::partition_point(ends.begin(), ends.end(),
                               [&](std::size_t e) { return e <= b * kBlock; }) -
          ends.begin());
      const Eigen::Index active = static_cast<Eigen::Index>(queries) - first_active;
      Eigen::MatrixXf products =
          query_rows.bottomRows(active) * database_rows.middleRows(begin, rows).transpose();
      benchmark::DoNotOptimize(products.data());
    });
  }
}

BenchCase retrieval_case(std::string name, CaseKind kind, const std::string& id,
                         RetrievalMethod method, std::size_t count, std::size_t dimension) {
  BenchCase bench;
  bench.name = std::move(name);
  bench.kind = kind;
  bench.descriptor = id;
  bench.strategy = std::string(method_name(method));
  bench.database_size = count;
  bench.dimension = dimension;
  return bench;
}

}  // namespace

std::vector<std::string> default_retrieval_descriptor_ids() {
  std::vector<std::string> ids;
  std::vector<RetrievalMethod> covered;
  const DescriptorRegistry& registry = DescriptorRegistry::global();
  for (const DescriptorInfo* info : registry.all()) {
    // Built-ins only: a loaded plugin, sorting among them by name, must not change what the
    // default run measures.
    if (!info->plugin_path.empty()) continue;
    const DescriptorInstance instance = registry.create_from_id(info->name);
    // Values read from files (precomputed) have no shape until they are read.
    if (external_values_of(*instance.descriptor)) continue;
    const RetrievalMethod method = instance.descriptor->retrieval_method();
    if (std::find(covered.begin(), covered.end(), method) != covered.end()) continue;
    covered.push_back(method);
    ids.push_back(info->name);
  }
  if (registry.contains("open_radvlad")) ids.push_back("open_radvlad:bin_dim=10");
  return ids;
}

std::vector<std::string> retrieval_descriptor_ids(const std::vector<std::string>& named_ids) {
  std::vector<std::string> ids = default_retrieval_descriptor_ids();
  const DescriptorRegistry& registry = DescriptorRegistry::global();
  for (const std::string& id : named_ids) {
    const DescriptorInstance instance = registry.create_from_id(id);
    if (registry.info(instance.name).plugin_path.empty()) continue;
    if (std::find(ids.begin(), ids.end(), instance.id) == ids.end()) ids.push_back(instance.id);
  }
  return ids;
}

void add_retrieval_benchmarks(BenchPlan& plan, const RetrievalBenchOptions& options) {
  const std::vector<std::string> ids =
      options.descriptor_ids.empty() ? default_retrieval_descriptor_ids() : options.descriptor_ids;
  const ScanGeometry geometry{400, 3360, kMulranRangeResolution};
  for (const std::string& id : ids) {
    const DescriptorInstance instance = DescriptorRegistry::global().create_from_id(id);
    const std::shared_ptr<const Descriptor> descriptor = instance.descriptor;
    const RetrievalMethod method = descriptor->retrieval_method();
    const DescriptorShape shape = descriptor->shape(geometry);
    const std::size_t dimension = shape.element_count();
    const std::string method_id = std::string(method_name(method));
    for (const std::size_t count : options.database_sizes) {
      const std::string suffix = fmt::format("{}/{}", instance.id, count);
      const std::string retrieval_prefix = "retrieval/" + method_id + "/" + suffix;
      const std::size_t bytes = 2 * count * dimension * sizeof(float);
      if (bytes > options.memory_budget_bytes) {
        const std::string reason = fmt::format(
            "{} x {} floats per session ({:.1f} GiB for both) exceed the memory budget of "
            "{:.1f} GiB",
            count, dimension, static_cast<double>(bytes) / (1 << 30),
            static_cast<double>(options.memory_budget_bytes) / (1 << 30));
        plan.skip(retrieval_prefix + "/multi", reason);
        if (method != RetrievalMethod::exhaustive_l2) {
          plan.skip(retrieval_prefix + "/single", reason);
          continue;
        }
        // One session's values memory-mapped from a file, the search streamed.
        BenchCase bench = retrieval_case(retrieval_prefix + "/single", CaseKind::retrieval, id,
                                         method, count, dimension);
        bench.session = "single";
        const std::size_t queries =
            std::min(count, std::max<std::size_t>(1, options.mapped_queries));
        count_queries_and_pairs(bench, count, queries, true, options.exclude_recent);
        const RetrievalCase c{descriptor, shape, count, queries, true, options.exclude_recent};
        const std::string folder = options.mapped_folder;
        plan.add(
            bench, [c, folder](benchmark::State& state) { run_mapped_retrieval(state, c, folder); },
            true, false, 1);
        continue;
      }
      if (method == RetrievalMethod::kdtree || method == RetrievalMethod::key_then_rerank) {
        plan.add(
            retrieval_case("index_build/" + method_id + "/" + suffix + "/database",
                           CaseKind::index_build, id, method, count, dimension),
            [descriptor, shape, count](benchmark::State& state) {
              build_key_tree(state, *descriptor, shape, count);
            },
            true);
      } else if (method == RetrievalMethod::exhaustive) {
        plan.add(
            retrieval_case("index_build/" + method_id + "/" + suffix + "/database",
                           CaseKind::index_build, id, method, count, dimension),
            [descriptor, shape, count](benchmark::State& state) {
              prepare_database(state, *descriptor, shape, count);
            },
            true);
      }
      const std::size_t queries = timed_queries(method, count, dimension, options);
      for (const bool single : {false, true}) {
        BenchCase bench = retrieval_case(retrieval_prefix + (single ? "/single" : "/multi"),
                                         CaseKind::retrieval, id, method, count, dimension);
        bench.session = single ? "single" : "multi";
        count_queries_and_pairs(bench, count, queries, single, options.exclude_recent);
        const RetrievalCase c{descriptor, shape, count, queries, single, options.exclude_recent};
        plan.add(
            bench, [c](benchmark::State& state) { run_retrieval(state, c); }, true);
      }
      if (method == RetrievalMethod::exhaustive_l2) {
        for (const bool single : {false, true}) {
          const std::string session = single ? "single" : "multi";
          BenchCase bench = retrieval_case("eigen_product/" + suffix + "/" + session,
                                           CaseKind::matrix_product, id, method, count, dimension);
          bench.session = session;
          count_queries_and_pairs(bench, count, queries, single, options.exclude_recent);
          const std::size_t exclude = options.exclude_recent;
          plan.add(
              bench,
              [shape, count, queries, single, exclude](benchmark::State& state) {
                eigen_product(state, shape, count, queries, single, exclude);
              },
              true);
        }
      }
    }
  }
}

}  // namespace radarpr::bench
