#pragma once

#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "datasets/polar_image.hpp"

namespace radarpr {

// A descriptor's value: `rows` x `cols` floats, row-major. Every descriptor stores float32.
struct DescriptorValue {
  int rows = 0;
  int cols = 0;
  std::vector<float> values;

  std::size_t element_count() const { return values.size(); }
  std::size_t payload_bytes() const { return values.size() * sizeof(float); }
};

// The element type of every DescriptorValue, as reported in listings and result rows.
inline constexpr std::string_view kDescriptorElementType = "float32";

// The size facts of a scan that a descriptor's shape may depend on (R-ReFeree's chunk count
// follows the range bin count, RaPlace's Cartesian extent the range resolution).
struct ScanGeometry {
  int azimuths = 400;
  int range_bins = 3360;
  double range_resolution_m = 0.0595238;
};
ScanGeometry geometry_of(const PolarImage& scan);

struct DescriptorShape {
  int rows = 0;
  int cols = 0;
  std::size_t element_count() const {
    return static_cast<std::size_t>(rows) * static_cast<std::size_t>(cols);
  }
  std::size_t payload_bytes() const { return element_count() * sizeof(float); }
  // A float64 numpy file of the elements: the convention behind the ReFeree paper's size table
  // (descriptors.md §7).
  std::size_t paper_bytes() const { return element_count() * 8 + 128; }
  friend bool operator==(const DescriptorShape&, const DescriptorShape&) = default;
};

// How the evaluation engine searches a database of this descriptor's values. The strategies are
// implemented once in evaluation/retrieval/retrieval.cpp; a descriptor only picks one. The default,
// exhaustive, is correct for any distance(); the others are fast paths a descriptor opts into by
// declaring what they rely on, and the evaluation checks that declaration on a sample of the
// values before trusting it (evaluation/retrieval/retrieval_declaration.hpp).
enum class RetrievalMethod {
  // search_key() vectors in a KD-tree: their L2 distance orders the database exactly as
  // distance() does, so the KD-tree nearest neighbour is the descriptor's nearest neighbour.
  // Declared by overriding retrieval_method(); checked: distance() must not decrease as the keys'
  // L2 distance grows.
  kdtree,
  // A pre-search: the rerank_candidates() database values whose search_key() is L2-nearest to the
  // query's (exact KD-tree search), re-ranked by distance(). Scan Context's ring key scheme; an
  // approximation by design, so only a descriptor that states it uses it.
  key_then_rerank,
  // distance() against every eligible database value, through prepare_distances() so that
  // per-value work (a spectrum) is done once per value rather than once per pair. The default.
  exhaustive,
  // distance() is the L2 distance between the values themselves: computed in blocks of matrix
  // products (high-dimensional values such as VLAD vectors), the nearest re-checked exactly.
  // Checked: distance() must equal the values' L2 distance.
  exhaustive_l2,
};

// Distances between a fixed set of queries and a fixed database, prepared once (see
// Descriptor::prepare_distances). Must be safe to call from several threads at once.
class PreparedDistances {
 public:
  virtual ~PreparedDistances() = default;
  // Equals descriptor.distance(queries[query], database[database_index]).
  virtual double distance(std::size_t query, std::size_t database_index) const = 0;
};

// The scans a trainable descriptor learns from (faiss's train step). They are loaded on demand so
// that a descriptor may subsample them without holding a whole sequence in memory.
class TrainingScans {
 public:
  virtual ~TrainingScans() = default;
  virtual std::size_t size() const = 0;
  virtual PolarImage load(std::size_t index) const = 0;  // thread-safe
  virtual std::string description() const = 0;           // e.g. the sequence's name, for errors
};

// The plugin interface every place-recognition descriptor implements (architecture.md). An
// instance is immutable once constructed (and, for a trainable descriptor, trained) and is then
// used from several threads at once.
class Descriptor {
 public:
  virtual ~Descriptor() = default;

  virtual DescriptorValue extract(const PolarImage& scan) const = 0;
  // Smaller = more similar; descriptors built on a similarity expose 1 - similarity or the like.
  virtual double distance(const DescriptorValue& a, const DescriptorValue& b) const = 0;
  virtual bool rotation_invariant() const = 0;
  // The shape extract() returns for scans of this geometry.
  virtual DescriptorShape shape(const ScanGeometry& geometry) const = 0;

  // Exhaustive unless a descriptor declares a fast path whose premise its distance() meets.
  virtual RetrievalMethod retrieval_method() const { return RetrievalMethod::exhaustive; }
  // The KD-tree key of a value (kdtree, key_then_rerank); the value itself by default.
  virtual std::vector<float> search_key(const DescriptorValue& value) const { return value.values; }
  // How many key neighbours key_then_rerank re-ranks.
  virtual std::size_t rerank_candidates() const { return 1; }
  // For exhaustive retrieval. `queries` and `database` may be the same vector (single session).
  // The default calls distance() per pair; override to precompute per-value work.
  virtual std::unique_ptr<PreparedDistances> prepare_distances(
      const std::vector<DescriptorValue>& queries,
      const std::vector<DescriptorValue>& database) const;
  // Heading of scan `query` relative to scan `database` in radians, (-pi, pi], for descriptors
  // that can estimate it.
  virtual std::optional<double> estimate_yaw(const DescriptorValue& /*query*/,
                                             const DescriptorValue& /*database*/) const {
    return std::nullopt;
  }

  // Trainable descriptors (a codebook) return true from trainable(), false from is_trained()
  // until train() has run, and refuse to extract before that with an error that says so.
  virtual bool trainable() const { return false; }
  virtual bool is_trained() const { return true; }
  // Throws std::invalid_argument for too few or unusable scans; std::logic_error when the
  // descriptor is not trainable.
  virtual void train(const TrainingScans& scans);
};

}  // namespace radarpr
