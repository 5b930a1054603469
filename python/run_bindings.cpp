// radarpr.run: an experiment config run as `radarpr run` runs it, in this process.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "evaluation/config/experiment_config.hpp"
#include "evaluation/experiment_runner.hpp"
#include "evaluation/parallel.hpp"
#include "evaluation/report/report.hpp"
#include "evaluation/results/results_reader.hpp"
#include "evaluation/results/results_writer.hpp"
#include "python/bindings.hpp"
#include "python/error_translation.hpp"
#include "python/json_values.hpp"

namespace radarpr::python {
namespace {

// The overrides as the command line's --set assignments: a dict {"protocol.revisit_radius_m": 10}
// (values as JSON) or a list of "key=value" strings.
std::vector<std::string> assignments(const py::object& overrides) {
  std::vector<std::string> result;
  if (overrides.is_none()) return result;
  if (py::isinstance<py::dict>(overrides)) {
    for (const auto& [key, value] : py::reinterpret_borrow<py::dict>(overrides)) {
      const std::string name = py::str(key).cast<std::string>();
      result.push_back(name + "=" + json_from_python(value, "overrides." + name).dump());
    }
    return result;
  }
  for (const auto& item : overrides) {
    if (!py::isinstance<py::str>(item)) {
      throw std::invalid_argument(
          "overrides: expected a dict of key paths to values, or a list of 'key=value' strings");
    }
    result.push_back(item.cast<std::string>());
  }
  return result;
}

ExperimentConfig experiment_config(const py::object& config,
                                   const std::vector<std::string>& overrides) {
  if (py::isinstance<py::dict>(config)) {
    return parse_with_overrides(json_from_python(config, "config"), overrides, "config");
  }
  if (!py::isinstance<py::str>(config) && !py::hasattr(config, "__fspath__")) {
    throw std::invalid_argument("config: expected the path of a config file or a config as a dict");
  }
  const std::filesystem::path path = json_from_python(config, "config").get<std::string>();
  return reading_files([&] { return load_experiment_config(path, overrides); });
}

RunResults run(const py::object& config, const py::object& out, const py::object& overrides,
               std::optional<int> threads, bool quiet, bool report) {
  ExperimentConfig experiment = experiment_config(config, assignments(overrides));
  if (threads) {
    if (*threads < 0 || *threads > kMaxThreads) {
      throw std::invalid_argument(
          fmt::format("threads: expected 0 (all processors) to {}, got {}", kMaxThreads, *threads));
    }
    experiment.threads = *threads;
  }
  const std::filesystem::path folder =
      out.is_none() ? std::filesystem::path("results") / experiment.name
                    : std::filesystem::path(json_from_python(out, "out").get<std::string>());
  ReportOutcome outcome;
  RunResults results;
  {
    py::gil_scoped_release unlocked;
    // A bad folder is refused before the run, as the command line does.
    reading_files([&] { return resolve_results_folder(folder); });
    const ExperimentRun run = run_experiment(experiment, !quiet);
    reading_files([&] { write_results(folder, experiment, run); });
    if (report) outcome = reading_files([&] { return write_report(folder, ReportOptions{}); });
    results = reading_files([&] { return read_run_results(folder); });
  }
  for (const std::string& warning : outcome.warnings) {
    if (PyErr_WarnEx(PyExc_RuntimeWarning, warning.c_str(), 1) != 0) throw py::error_already_set();
  }
  return results;
}

}  // namespace

void bind_run(py::module_& module) {
  module.def("run", &run, py::arg("config"), py::arg("out") = py::none(),
             py::arg("overrides") = py::none(), py::arg("threads") = py::none(),
             py::arg("quiet") = true, py::arg("report") = true,
             R"(Run an experiment as ``radarpr run`` does, in this process.

Descriptors registered with ``radarpr.register_descriptor`` may be named in the config.

Parameters
----------
config : str, os.PathLike or dict
    A config file (docs/configs.md) or the config itself.
out : str or os.PathLike, optional
    The results folder; ``results/<experiment>`` by default. Only the files a run writes are
    replaced.
overrides : dict or list of str, optional
    ``{"protocol.revisit_radius_m": 10}`` or ``["protocol.revisit_radius_m=10"]``, as
    ``--set`` applies them.
threads : int, optional
    Extraction threads (0: every processor); the config's ``threads`` by default.
quiet : bool
    No progress on stderr.
report : bool
    Also write the report (figures, tables, index.html); a missing gnuplot is a RuntimeWarning.

Returns
-------
Results
    The folder as ``load_results`` reads it.

Raises
------
radarpr.ConfigError
    A config problem; the message names the file (or the override) and the key.
OSError
    A dataset file or the results folder cannot be read or written.

Notes
-----
The GIL is released while the experiment runs.
)");
}

}  // namespace radarpr::python
