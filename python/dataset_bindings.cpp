// radarpr.open_dataset: a config's sequence as a stream of scans (image, time, pose).
#include <memory>
#include <stdexcept>
#include <string>

#include <fmt/format.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "evaluation/config/config_reader.hpp"
#include "evaluation/config/sequence_config.hpp"
#include "python/bindings.hpp"
#include "python/error_translation.hpp"
#include "python/json_values.hpp"
#include "python/numpy_arrays.hpp"

namespace radarpr::python {
namespace {

struct Scan {
  std::size_t index = 0;
  ScanRecord record;
  PolarImage image;
};

class Dataset {
 public:
  explicit Dataset(const py::object& spec) {
    const nlohmann::json json = json_from_python(spec, "dataset");
    const SequenceConfig config = parse_sequence_config(ConfigReader(json, "dataset"));
    py::gil_scoped_release unlocked;
    sequence_ = reading_files([&] { return open_sequence(config); });
  }

  std::size_t size() const { return sequence_->size(); }
  const ScanSequence& sequence() const { return *sequence_; }

  Scan scan(std::ptrdiff_t index) const {
    const auto count = static_cast<std::ptrdiff_t>(size());
    if (index < 0) index += count;
    if (index < 0 || index >= count) {
      throw py::index_error(fmt::format("scan {} of a sequence of {}", index, count));
    }
    Scan scan{static_cast<std::size_t>(index), sequence_->records()[index], {}};
    py::gil_scoped_release unlocked;
    scan.image = reading_files([&] { return sequence_->load_image(scan.index); });
    return scan;
  }

 private:
  std::unique_ptr<ScanSequence> sequence_;
};

// Iterates a Dataset scan by scan: one image decoded at a time.
struct ScanIterator {
  py::object dataset;  // keeps the Dataset alive
  std::size_t next = 0;
};

}  // namespace

void bind_datasets(py::module_& module) {
  py::class_<Scan>(module, "Scan", R"(One scan of a dataset.

Attributes
----------
index : int
    Its position in the sequence.
image : numpy.ndarray
    uint8, azimuths x range bins, read-only.
timestamp_ns : int
pose : tuple of float
    (x, y, yaw) in metres and radians, in the dataset's frame.
range_resolution : float
    Metres per range bin.
azimuths : numpy.ndarray
    float64, one angle per row in radians.
source : str
    The file it was read from, or what generated it.
)")
      .def_readonly("index", &Scan::index)
      // A view that keeps the Scan alive: no copy of its pixels.
      .def_property_readonly("image",
                             [](py::object self) {
                               return image_view_array(self.cast<const Scan&>().image.power, self);
                             })
      .def_property_readonly("timestamp_ns", [](const Scan& s) { return s.record.timestamp_ns; })
      .def_property_readonly("pose",
                             [](const Scan& s) {
                               return py::make_tuple(s.record.pose.x, s.record.pose.y,
                                                     s.record.pose.yaw);
                             })
      .def_property_readonly("range_resolution",
                             [](const Scan& s) { return s.image.range_resolution_m; })
      .def_property_readonly("azimuths",
                             [](const Scan& s) {
                               return py::array_t<double>(
                                   static_cast<py::ssize_t>(s.image.azimuths_rad.size()),
                                   s.image.azimuths_rad.data());
                             })
      .def_property_readonly("source", [](const Scan& s) { return s.record.source; })
      .def("__repr__", [](const Scan& s) {
        return fmt::format("<radarpr.Scan {} t={} ns {}x{}>", s.index, s.record.timestamp_ns,
                           s.image.azimuth_count(), s.image.range_bin_count());
      });

  py::class_<ScanIterator>(module, "ScanIterator")
      .def("__iter__", [](py::object self) { return self; })
      .def("__next__", [](ScanIterator& it) {
        const auto& dataset = it.dataset.cast<const Dataset&>();
        if (it.next >= dataset.size()) throw py::stop_iteration();
        return dataset.scan(static_cast<std::ptrdiff_t>(it.next++));
      });

  py::class_<Dataset>(module, "Dataset", R"(A sequence of scans, opened by ``open_dataset``.

``len(d)`` scans; ``d[i]`` decodes scan i; iterating decodes one scan at a time (a sequence is
never held in memory). ``timestamps_ns`` and ``positions`` describe every scan without decoding
any.
)")
      .def("__len__", &Dataset::size)
      .def("__getitem__", &Dataset::scan, py::arg("index"))
      .def("__iter__",
           [](py::object self) {
             return ScanIterator{std::move(self), 0};
           })
      .def_property_readonly("name", [](const Dataset& d) { return d.sequence().name(); })
      .def_property_readonly("fingerprint",
                             [](const Dataset& d) { return d.sequence().fingerprint(); })
      .def_property_readonly(
          "timestamps_ns",
          [](const Dataset& d) {
            const auto& records = d.sequence().records();
            py::array_t<std::int64_t> times(static_cast<py::ssize_t>(records.size()));
            for (std::size_t i = 0; i < records.size(); ++i) {
              times.mutable_at(static_cast<py::ssize_t>(i)) = records[i].timestamp_ns;
            }
            return times;
          })
      .def_property_readonly(
          "positions",
          [](const Dataset& d) {
            const auto& records = d.sequence().records();
            py::array_t<double> poses({static_cast<py::ssize_t>(records.size()), py::ssize_t{3}});
            auto out = poses.mutable_unchecked<2>();
            for (std::size_t i = 0; i < records.size(); ++i) {
              const auto row = static_cast<py::ssize_t>(i);
              out(row, 0) = records[i].pose.x;
              out(row, 1) = records[i].pose.y;
              out(row, 2) = records[i].pose.yaw;
            }
            return poses;
          },
          "N x 3 float64: x, y (metres), yaw (radians) of every scan.")
      .def("__repr__", [](const Dataset& d) {
        return fmt::format("<radarpr.Dataset {} ({} scans)>", d.sequence().name(), d.size());
      });

  module.def(
      "open_dataset", [](const py::object& spec) { return Dataset(spec); }, py::arg("spec"),
      R"(Open a sequence as a config's "query" or "database" entry names it.

Parameters
----------
spec : dict
    ``{"type": ..., <that type's keys>}`` (docs/datasets.md), e.g. ``{"type": "mulran",
    "root": "/data/MulRan", "sequence": "KAIST03"}`` or ``{"type": "synthetic", "seed": 7,
    "session": 0, "scans": 600}``.

Returns
-------
Dataset
    Scans are decoded (or rendered) one at a time as they are read.

Raises
------
radarpr.ConfigError
    An unknown type, key or value.
OSError
    Files that are missing or malformed.
)");
}

}  // namespace radarpr::python
