// radarpr.load_results: a results folder as dicts and numpy columns.
#include <filesystem>
#include <limits>
#include <string>

#include <fmt/format.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "evaluation/results/results_reader.hpp"
#include "python/bindings.hpp"
#include "python/error_translation.hpp"
#include "python/json_values.hpp"

namespace radarpr::python {
namespace {

template <typename T, typename Field>
py::array_t<T> column_of(std::size_t size, Field field) {
  py::array_t<T> values(static_cast<py::ssize_t>(size));
  for (std::size_t i = 0; i < size; ++i) values.mutable_at(static_cast<py::ssize_t>(i)) = field(i);
  return values;
}

double or_nan(const std::optional<double>& value) {
  return value.value_or(std::numeric_limits<double>::quiet_NaN());
}

const ResultRow& row_of(const RunResults& results, const std::string& dataset,
                        const std::string& descriptor) {
  const ResultRow* row = results.find(dataset, descriptor);
  if (!row) {
    throw py::key_error(fmt::format("no row for dataset '{}' and descriptor '{}' in {}", dataset,
                                    descriptor, results.folder.string()));
  }
  return *row;
}

// One dataset's summary rows as columns: descriptor ids and labels as lists, every metric as a
// float64 column (NaN where undefined), recall@K as recall_at_<K>.
py::dict dataset_table(const RunResults& results, const std::string& dataset) {
  std::vector<const nlohmann::json*> rows;
  for (const auto& row : results.summary.at("rows")) {
    if (row.at("dataset") == dataset) rows.push_back(&row);
  }
  if (rows.empty()) {
    throw py::key_error(fmt::format("no dataset '{}' in {}", dataset, results.folder.string()));
  }
  py::dict table;
  py::list ids, labels;
  for (const auto* row : rows) {
    ids.append(row->at("descriptor").get<std::string>());
    labels.append(row->at("label").get<std::string>());
  }
  table["descriptor"] = ids;
  table["label"] = labels;
  auto number = [](const nlohmann::json& value) {
    return value.is_number() ? value.get<double>() : std::numeric_limits<double>::quiet_NaN();
  };
  for (const auto& [key, value] : rows.front()->items()) {
    if (value.is_number() || value.is_null()) {
      table[py::str(key)] = column_of<double>(rows.size(), [&](std::size_t i) {
        return number(rows[i]->contains(key) ? rows[i]->at(key) : nlohmann::json());
      });
    } else if (key == "recall_at_k" && value.is_object()) {
      for (const auto& [k, unused] : value.items()) {
        table[py::str("recall_at_" + k)] = column_of<double>(rows.size(), [&](std::size_t i) {
          const auto& recalls = rows[i]->at("recall_at_k");
          return number(recalls.contains(k) ? recalls.at(k) : nlohmann::json());
        });
      }
    }
  }
  return table;
}

}  // namespace

void bind_results(py::module_& module) {
  py::class_<RunResults>(module, "Results", R"(A results folder as ``radarpr run`` wrote it.

Attributes
----------
folder : pathlib.Path
experiment : str
datasets : list of str
    In run order.
descriptors : list of str
    Descriptor ids, in config order.
summary : dict
    summary.json as written (the config, the protocol and one row per dataset x descriptor).
timing : dict or None
    timing.json (run time, machine), None when there is none.
rows : list of dict
    summary.json's rows.
)")
      .def_readonly("folder", &RunResults::folder)
      .def_readonly("experiment", &RunResults::experiment)
      .def_readonly("datasets", &RunResults::datasets)
      .def_readonly("descriptors", &RunResults::descriptors)
      .def_property_readonly("summary",
                             [](const RunResults& r) { return python_from_json(r.summary); })
      .def_property_readonly("timing",
                             [](const RunResults& r) { return python_from_json(r.timing); })
      .def_property_readonly(
          "rows", [](const RunResults& r) { return python_from_json(r.summary.at("rows")); })
      .def("table", &dataset_table, py::arg("dataset"),
           R"(One dataset's summary as columns.

Parameters
----------
dataset : str

Returns
-------
dict
    ``descriptor`` and ``label`` (lists), and one float64 numpy column per metric and size
    (``roc_auc``, ``f1_max``, ``recall_at_1``, ``recall_at_5``, ``payload_bytes``, ...), NaN
    where a metric is undefined.
)")
      .def(
          "curve",
          [](const RunResults& r, const std::string& dataset, const std::string& descriptor) {
            const auto& curve = row_of(r, dataset, descriptor).curve;
            py::dict columns;
            const std::size_t n = curve.size();
            columns["threshold"] = column_of<double>(n, [&](auto i) { return curve[i].threshold; });
            columns["precision"] =
                column_of<double>(n, [&](auto i) { return or_nan(curve[i].precision); });
            columns["recall"] = column_of<double>(n, [&](auto i) { return curve[i].recall; });
            columns["fpr"] = column_of<double>(n, [&](auto i) { return curve[i].fpr; });
            columns["f1"] = column_of<double>(n, [&](auto i) { return or_nan(curve[i].f1); });
            return columns;
          },
          py::arg("dataset"), py::arg("descriptor"),
          R"(A descriptor's threshold sweep (curve.csv) as float64 columns.

Parameters
----------
dataset : str
descriptor : str
    The descriptor's id.

Returns
-------
dict of numpy.ndarray
    ``threshold``, ``precision``, ``recall``, ``fpr``, ``f1`` (NaN where undefined).
)")
      .def(
          "matching_graph",
          [](const RunResults& r, const std::string& dataset, const std::string& descriptor) {
            const auto& graph = row_of(r, dataset, descriptor).graph;
            py::dict columns;
            const std::size_t n = graph.size();
            columns["query"] = column_of<std::int64_t>(n, [&](auto i) { return graph[i].query; });
            columns["match"] = column_of<std::int64_t>(n, [&](auto i) { return graph[i].match; });
            py::list labels;
            for (const auto& edge : graph) labels.append(edge.label);
            columns["label"] = labels;
            return columns;
          },
          py::arg("dataset"), py::arg("descriptor"),
          R"(The matching graph at the F1-max threshold (matching_graph.csv).

Returns
-------
dict
    ``query`` and ``match`` (int64 numpy columns) and ``label`` (a list of 'tp', 'fp', 'fn').
)")
      .def("__repr__", [](const RunResults& r) {
        return fmt::format("<radarpr.Results {} ({} datasets x {} descriptors) at {}>",
                           r.experiment, r.datasets.size(), r.descriptors.size(),
                           r.folder.string());
      });

  module.def(
      "load_results",
      [](const std::filesystem::path& folder) {
        py::gil_scoped_release unlocked;
        return reading_files([&] { return read_run_results(folder); });
      },
      py::arg("folder"), R"(Read a results folder that ``radarpr run`` wrote.

Parameters
----------
folder : str or os.PathLike
    E.g. ``'results/quickstart'``.

Returns
-------
Results

Raises
------
OSError
    A missing, unreadable or malformed file; the message names it.
)");
}

}  // namespace radarpr::python
