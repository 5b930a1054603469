// radarpr.evaluate: radarpr's retrieval, ground truth and metrics on values held in numpy.
#include <limits>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "descriptors/descriptor_registry.hpp"
#include "descriptors/precomputed/precomputed.hpp"
#include "evaluation/config/experiment_config.hpp"
#include "evaluation/descriptor_evaluation.hpp"
#include "evaluation/results/results_writer.hpp"
#include "python/bindings.hpp"
#include "python/descriptor_object.hpp"
#include "python/json_values.hpp"
#include "python/numpy_arrays.hpp"

namespace radarpr::python {
namespace {

// What evaluate() returns: plain Python data, built once.
struct Evaluation {
  py::dict metrics;
  py::dict curve;
  py::dict matches;
  py::dict matching_graph;
  py::dict protocol;
};

// The distance evaluate() ranks by: "l2" and "cosine" are `precomputed`'s (and so rank exactly
// as a config evaluating the same values through `precomputed` does); a Descriptor or an id
// uses that descriptor's distance and retrieval.
std::shared_ptr<const Descriptor> ranking_descriptor(const py::handle& distance) {
  if (py::isinstance<py::str>(distance)) {
    const std::string name = distance.cast<std::string>();
    if (name == "l2" || name == "cosine") {
      PrecomputedParams params;
      params.distance = name == "l2" ? PrecomputedDistance::l2 : PrecomputedDistance::cosine;
      return std::make_shared<PrecomputedDescriptor>(params);
    }
    return descriptor_from_id(name).descriptor;
  }
  if (const auto* descriptor = descriptor_of(distance)) return descriptor->descriptor;
  throw std::invalid_argument(fmt::format(
      "distance: expected 'l2', 'cosine', a descriptor id or a radarpr.Descriptor, got {}",
      describe_object(distance)));
}

// With protocol.revisit_max_yaw_deg a revisit also needs a close heading: positions without a
// yaw column would make every heading 0 and so every heading close, a silently wrong answer.
std::vector<ScanRecord> scan_records(const py::handle& positions, const py::handle& timestamps,
                                     std::size_t count, const std::string& what, bool needs_yaw) {
  const auto poses = real_matrix(positions, what + "positions", 2, 3);
  if (static_cast<std::size_t>(poses.shape(0)) != count) {
    throw std::invalid_argument(
        fmt::format("{}positions: {} rows for {} values", what, poses.shape(0), count));
  }
  if (needs_yaw && poses.shape(1) != 3) {
    throw std::invalid_argument(fmt::format(
        "{}positions: protocol.revisit_max_yaw_deg needs N x 3 positions (x, y, yaw in radians), "
        "got N x {}",
        what, poses.shape(1)));
  }
  std::vector<ScanRecord> records(count);
  const auto view = poses.unchecked<2>();
  for (std::size_t i = 0; i < count; ++i) {
    const auto row = static_cast<py::ssize_t>(i);
    records[i].pose = {view(row, 0), view(row, 1), poses.shape(1) == 3 ? view(row, 2) : 0.0};
    // Without times, frame i is at i ns: only the frame order matters then.
    records[i].timestamp_ns = static_cast<std::int64_t>(i);
  }
  if (!timestamps.is_none()) {
    const bool is_array = py::isinstance<py::array>(timestamps);
    const auto array = is_array ? py::reinterpret_borrow<py::array>(timestamps) : py::array();
    if (!is_array || array.ndim() != 1 || static_cast<std::size_t>(array.shape(0)) != count ||
        array.dtype().kind() != 'i') {
      throw std::invalid_argument(
          fmt::format("{}timestamps: expected {} int64 times in ns (one per value), got {}", what,
                      count, describe_object(timestamps)));
    }
    const auto times =
        py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>::ensure(array);
    for (std::size_t i = 0; i < count; ++i) {
      records[i].timestamp_ns = times.at(static_cast<py::ssize_t>(i));
      if (i > 0 && records[i].timestamp_ns <= records[i - 1].timestamp_ns) {
        throw std::invalid_argument(
            fmt::format("{}timestamps: must increase, but [{}] = {} follows [{}] = {}", what, i,
                        records[i].timestamp_ns, i - 1, records[i - 1].timestamp_ns));
      }
    }
  }
  return records;
}

template <typename T, typename Field>
py::array_t<T> column(std::size_t size, Field field) {
  py::array_t<T> values(static_cast<py::ssize_t>(size));
  auto out = values.template mutable_unchecked<1>();
  for (std::size_t i = 0; i < size; ++i) out(static_cast<py::ssize_t>(i)) = field(i);
  return values;
}

double or_nan(const std::optional<double>& value) {
  return value.value_or(std::numeric_limits<double>::quiet_NaN());
}

Evaluation to_python(const DescriptorEvaluation& evaluation, const Protocol& protocol) {
  Evaluation result;
  result.metrics = python_from_json(metrics_to_json(evaluation.metrics));
  result.protocol = python_from_json(protocol_to_json(protocol));
  const auto& curve = evaluation.curve;
  const std::size_t n = curve.size();
  result.curve["threshold"] = column<double>(n, [&](auto i) { return curve[i].threshold; });
  result.curve["tp"] = column<std::int64_t>(n, [&](auto i) { return curve[i].counts.tp; });
  result.curve["fp"] = column<std::int64_t>(n, [&](auto i) { return curve[i].counts.fp; });
  result.curve["fn"] = column<std::int64_t>(n, [&](auto i) { return curve[i].counts.fn; });
  result.curve["tn"] = column<std::int64_t>(n, [&](auto i) { return curve[i].counts.tn; });
  result.curve["precision"] = column<double>(n, [&](auto i) { return or_nan(curve[i].precision); });
  result.curve["recall"] = column<double>(n, [&](auto i) { return or_nan(curve[i].recall); });
  result.curve["f1"] = column<double>(n, [&](auto i) { return or_nan(curve[i].f1); });
  result.curve["fpr"] = column<double>(n, [&](auto i) { return or_nan(curve[i].fpr); });
  const auto& rows = evaluation.results;
  const std::size_t m = rows.size();
  result.matches["query"] = column<std::int64_t>(m, [&](auto i) { return rows[i].query; });
  result.matches["match"] = column<std::int64_t>(m, [&](auto i) { return rows[i].match; });
  result.matches["distance"] = column<double>(m, [&](auto i) { return rows[i].distance; });
  result.matches["correct"] = column<bool>(m, [&](auto i) { return rows[i].correct; });
  result.matches["revisit"] = column<bool>(m, [&](auto i) { return rows[i].revisit; });
  result.matches["first_correct_rank"] =
      column<std::int64_t>(m, [&](auto i) { return rows[i].first_correct_rank; });
  const auto& graph = evaluation.matching_graph;
  const std::size_t g = graph.size();
  result.matching_graph["query"] = column<std::int64_t>(g, [&](auto i) { return graph[i].query; });
  result.matching_graph["match"] = column<std::int64_t>(g, [&](auto i) { return graph[i].match; });
  result.matching_graph["distance"] = column<double>(g, [&](auto i) { return graph[i].distance; });
  py::list labels;
  for (const auto& edge : graph) labels.append(std::string(to_string(edge.label)));
  result.matching_graph["label"] = labels;
  return result;
}

Evaluation evaluate(const py::object& values, const py::object& positions,
                    const py::object& protocol, const py::object& distance,
                    const py::object& timestamps, const py::object& database_values,
                    const py::object& database_positions, const py::object& database_timestamps) {
  const Protocol parsed = protocol.is_none()
                              ? Protocol{}
                              : parse_protocol_object(json_from_python(protocol, "protocol"));
  const bool needs_yaw = parsed.revisit_max_yaw_deg.has_value();
  const std::shared_ptr<const Descriptor> descriptor = ranking_descriptor(distance);
  const std::vector<DescriptorValue> queries = values_from_rows(values, "values");
  const std::vector<ScanRecord> query_records =
      scan_records(positions, timestamps, queries.size(), "", needs_yaw);
  std::optional<std::vector<DescriptorValue>> database;
  std::vector<ScanRecord> database_records;
  if (!database_values.is_none()) {
    database = values_from_rows(database_values, "database_values");
    database_records = scan_records(database_positions, database_timestamps, database->size(),
                                    "database_", needs_yaw);
    if (database->size() > 0 && queries.size() > 0 &&
        (database->front().rows != queries.front().rows ||
         database->front().cols != queries.front().cols)) {
      throw std::invalid_argument("database_values: rows of another shape than the values'");
    }
  } else if (!database_positions.is_none() || !database_timestamps.is_none()) {
    throw std::invalid_argument(
        "database_positions/database_timestamps given without database_values");
  }
  if (parsed.exclude_recent_seconds && !database && timestamps.is_none()) {
    throw std::invalid_argument(
        "protocol.exclude_recent_seconds needs timestamps= (int64 ns, one per value)");
  }
  DescriptorEvaluation evaluation;
  {
    py::gil_scoped_release unlocked;
    evaluation =
        evaluate_descriptor(*descriptor, queries, query_records, database ? &*database : nullptr,
                            database ? &database_records : nullptr, parsed);
  }
  return to_python(evaluation, parsed);
}

}  // namespace

void bind_evaluation(py::module_& module) {
  py::class_<Evaluation>(module, "Evaluation", R"(What ``radarpr.evaluate`` measured.

Attributes
----------
metrics : dict
    The scalar metrics under the names of metrics.json (docs/protocols.md): ``queries``,
    ``revisits``, ``correct_top1``, ``roc_auc``, ``f1_max``, ``f1_max_threshold``,
    ``pr_auc_trapezoid``, ``average_precision``, ``pr_auc_mulran``, ``recall_at_1``,
    ``recall_at_k`` and ``recall_at_k_all_queries`` (dicts keyed by K as str),
    ``recall_at_100_precision``, ``extended_precision``. Undefined ones are None.
curve : dict of numpy.ndarray
    One column per quantity, one row per threshold of the sweep: ``threshold``, ``tp``, ``fp``,
    ``fn``, ``tn``, ``precision``, ``recall``, ``f1``, ``fpr`` (NaN where undefined).
matches : dict of numpy.ndarray
    One row per evaluated query: ``query``, ``match`` (top-1 database index), ``distance``,
    ``correct``, ``revisit``, ``first_correct_rank`` (0: none within the top K).
matching_graph : dict
    The accepted queries and missed revisits at the F1-max threshold: ``query``, ``match``,
    ``distance`` (numpy) and ``label`` (a list of 'tp', 'fp', 'fn').
protocol : dict
    The protocol as result files record it.
)")
      .def_readonly("metrics", &Evaluation::metrics)
      .def_readonly("curve", &Evaluation::curve)
      .def_readonly("matches", &Evaluation::matches)
      .def_readonly("matching_graph", &Evaluation::matching_graph)
      .def_readonly("protocol", &Evaluation::protocol)
      .def("__repr__", [](const Evaluation& e) {
        return fmt::format("<radarpr.Evaluation {}>", py::repr(e.metrics).cast<std::string>());
      });

  module.def("evaluate", &evaluate, py::arg("values"), py::arg("positions"),
             py::arg("protocol") = py::none(), py::arg("distance") = "l2",
             py::arg("timestamps") = py::none(), py::arg("database_values") = py::none(),
             py::arg("database_positions") = py::none(),
             py::arg("database_timestamps") = py::none(),
             R"(Evaluate descriptor values under radarpr's protocol, as ``radarpr run`` does.

Single session (the default): each query is searched against the frames before it, less the
excluded recent ones. Multi session: with ``database_values``, every query against every
database frame.

Parameters
----------
values : numpy.ndarray
    float32 or float64, N x D (or N x rows x cols as ``Descriptor.extract_many`` returns), one
    row per scan in time order.
positions : numpy.ndarray
    N x 2 (x, y in metres) or N x 3 (x, y, yaw in radians); revisits are scans within the
    radius. ``protocol.revisit_max_yaw_deg`` (a revisit also needs a close heading) needs N x 3.
protocol : dict, optional
    The config's "protocol" object (docs/protocols.md), e.g.
    ``{"revisit_radius_m": 20, "exclude_recent_frames": 50}``; radarpr's default otherwise.
distance : str or Descriptor
    'l2' or 'cosine' (as the ``precomputed`` descriptor ranks), or a descriptor id or
    ``radarpr.Descriptor`` whose distance and retrieval are used (values it extracted).
timestamps : numpy.ndarray, optional
    N int64 times in ns, increasing; needed by ``exclude_recent_seconds``.
database_values, database_positions, database_timestamps : numpy.ndarray, optional
    The database session of a multi-session evaluation.

Returns
-------
Evaluation

Raises
------
radarpr.ConfigError
    A bad protocol key or value, or an unknown descriptor id.
ValueError
    Arrays of the wrong dtype, rank or length, or values that are not finite.

Notes
-----
The GIL is released during retrieval and scoring.
)");
}

}  // namespace radarpr::python
