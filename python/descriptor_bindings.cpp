// radarpr.descriptors() and radarpr.Descriptor: extraction and distances over numpy arrays.
#include <chrono>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <nlohmann/json.hpp>

#include "datasets/polar_png.hpp"
#include "descriptors/descriptor_registry.hpp"
#include "evaluation/parallel.hpp"
#include "python/bindings.hpp"
#include "python/descriptor_object.hpp"
#include "python/numpy_arrays.hpp"

namespace radarpr::python {
namespace {

// How the scans of one call are turned into PolarImages (outside the GIL).
struct ScanSettings {
  std::optional<double> range_resolution;  // none: known from the bin count
  std::optional<std::vector<double>> azimuths;
};

double checked_resolution(const ScanSettings& settings, int range_bins) {
  if (settings.range_resolution) return *settings.range_resolution;
  const auto known = known_range_resolution(range_bins);
  if (!known) {
    throw std::invalid_argument(
        fmt::format("{} range bins match no known sensor; pass range_resolution= (metres per bin)",
                    range_bins));
  }
  return *known;
}

PolarImage polar_image(const ImageView& view, const ScanSettings& settings) {
  PolarImage image;
  image.range_resolution_m = checked_resolution(settings, view.cols);
  image.power = image_bytes(view);
  if (settings.azimuths) {
    if (settings.azimuths->size() != static_cast<std::size_t>(view.rows)) {
      throw std::invalid_argument(
          fmt::format("azimuths: expected one angle per image row ({}), got {}", view.rows,
                      settings.azimuths->size()));
    }
    image.azimuths_rad = *settings.azimuths;
  } else {
    image.azimuths_rad = uniform_azimuths(view.rows);
  }
  return image;
}

ScanSettings scan_settings(std::optional<double> range_resolution,
                           std::optional<std::vector<double>> azimuths) {
  if (range_resolution && !(std::isfinite(*range_resolution) && *range_resolution > 0)) {
    throw std::invalid_argument(fmt::format(
        "range_resolution: expected metres per range bin > 0, got {}", *range_resolution));
  }
  return {range_resolution, std::move(azimuths)};
}

}  // namespace

DescriptorInstance descriptor_from_id(const std::string& id) {
  try {
    return DescriptorRegistry::global().create_from_id(id);
  } catch (const ParameterError&) {
    throw;
  } catch (const std::invalid_argument& error) {
    // An unknown name or a malformed id: a config problem like a bad parameter.
    throw ParameterError("id", error.what());
  }
}

const DescriptorInstance* descriptor_of(const py::handle& object) {
  if (!py::isinstance<PythonDescriptor>(object)) return nullptr;
  return &object.cast<const PythonDescriptor&>().instance();
}

PythonDescriptor::PythonDescriptor(const std::string& id) : instance_(descriptor_from_id(id)) {}

py::array_t<float> PythonDescriptor::extract(const py::object& scan,
                                             std::optional<double> range_resolution,
                                             std::optional<std::vector<double>> azimuths) const {
  ScanSettings settings = scan_settings(range_resolution, std::move(azimuths));
  py::object image = scan;
  if (py::isinstance<DecodedPolarPng>(scan)) {
    // A PolarScan brings its own resolution and encoder angles unless they are overridden.
    const auto& decoded = scan.cast<const DecodedPolarPng&>();
    if (!settings.range_resolution) settings.range_resolution = decoded.image.range_resolution_m;
    if (!settings.azimuths) settings.azimuths = decoded.image.azimuths_rad;
    image = scan.attr("image");
  }
  const ImageView view = image_view(image, "image");
  DescriptorValue value;
  {
    py::gil_scoped_release unlocked;
    value = instance_.descriptor->extract(polar_image(view, settings));
  }
  return value_array(std::move(value));
}

py::array_t<float> PythonDescriptor::extract_many(const py::object& images,
                                                  std::optional<double> range_resolution,
                                                  int num_threads, int scan_axis) const {
  if (num_threads < 0 || num_threads > kMaxThreads) {
    throw std::invalid_argument(fmt::format(
        "num_threads: expected 0 (all processors) to {}, got {}", kMaxThreads, num_threads));
  }
  const ScanSettings settings = scan_settings(range_resolution, std::nullopt);
  std::vector<py::object> keep;
  const std::vector<ImageView> views = image_views(images, scan_axis, keep);
  std::vector<DescriptorValue> values(views.size());
  {
    py::gil_scoped_release unlocked;
    parallel_for(views.size(), num_threads, [&](std::size_t i) {
      values[i] = instance_.descriptor->extract(polar_image(views[i], settings));
    });
  }
  return value_stack(values);
}

double PythonDescriptor::distance(const py::object& a, const py::object& b) const {
  const DescriptorValue first = value_from_array(a, "a");
  const DescriptorValue second = value_from_array(b, "b");
  py::gil_scoped_release unlocked;
  return instance_.descriptor->distance(first, second);
}

double PythonDescriptor::time_extract(const py::object& image,
                                      std::optional<double> range_resolution, int repeats) const {
  if (repeats < 1 || repeats > 1'000'000) {
    throw std::invalid_argument(fmt::format("repeats: expected 1 to 1000000, got {}", repeats));
  }
  const ScanSettings settings = scan_settings(range_resolution, std::nullopt);
  const ImageView view = image_view(image, "image");
  py::gil_scoped_release unlocked;
  const PolarImage scan = polar_image(view, settings);
  double checksum = 0.0;  // uses every value, so no extraction can be left out
  const auto start = std::chrono::steady_clock::now();
  for (int r = 0; r < repeats; ++r) checksum += instance_.descriptor->extract(scan).values[0];
  const std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - start;
  if (!std::isfinite(checksum)) throw std::runtime_error("time_extract: a value was not finite");
  return elapsed.count() / repeats;
}

py::tuple PythonDescriptor::shape(int azimuths, int range_bins, double range_resolution) const {
  const DescriptorShape shape =
      instance_.descriptor->shape(ScanGeometry{azimuths, range_bins, range_resolution});
  return py::make_tuple(shape.rows, shape.cols);
}

namespace {

py::dict parameter_dict(const ParameterSpec& spec) {
  py::dict parameter;
  parameter["name"] = spec.name;
  parameter["kind"] = std::string(to_string(spec.kind));
  parameter["default"] = spec.default_value;
  parameter["description"] = spec.description;
  parameter["choices"] = spec.choices;
  parameter["minimum"] = spec.minimum;
  parameter["maximum"] = spec.maximum;
  return parameter;
}

py::list descriptor_list() {
  py::list list;
  for (const DescriptorInfo* info : DescriptorRegistry::global().all()) {
    py::dict entry;
    entry["name"] = info->name;
    entry["summary"] = info->summary;
    entry["origin"] = origin_of(*info);
    py::list parameters;
    for (const ParameterSpec& spec : info->parameters) parameters.append(parameter_dict(spec));
    entry["parameters"] = parameters;
    // Shape and flags of the default configuration on a 400 x 3360 scan; None where the defaults
    // cannot tell (precomputed learns its shape from its values file).
    entry["shape"] = py::none();
    entry["rotation_invariant"] = py::none();
    entry["trainable"] = py::none();
    try {
      const DescriptorInstance instance =
          DescriptorRegistry::global().create(info->name, nlohmann::json::object());
      const DescriptorShape shape = instance.descriptor->shape(ScanGeometry{});
      if (shape.element_count() > 0) entry["shape"] = py::make_tuple(shape.rows, shape.cols);
      entry["rotation_invariant"] = instance.descriptor->rotation_invariant();
      entry["trainable"] = instance.descriptor->trainable();
    } catch (const std::exception&) {
    }
    list.append(entry);
  }
  return list;
}

}  // namespace

void bind_descriptors(py::module_& module) {
  module.def("descriptors", &descriptor_list, R"(The registered descriptors.

Returns
-------
list of dict
    One dict per descriptor, sorted by name: ``name``, ``summary``, ``origin`` ('built-in' or
    the plugin's path), ``parameters`` (a list of dicts: ``name``, ``kind``, ``default``,
    ``description``, ``choices``, ``minimum``, ``maximum``), and for the default configuration
    on a 400 x 3360 scan ``shape`` (rows, cols), ``rotation_invariant`` and ``trainable`` (None
    for a descriptor whose defaults cannot stand alone, such as ``precomputed``).
)");

  py::class_<PythonDescriptor>(module, "Descriptor", R"(A configured descriptor.

Parameters
----------
id : str
    A descriptor name or id with parameters, e.g. ``'referee_r:kernel=box,z_q=3'`` (see
    ``radarpr.descriptors()`` and ``radarpr list``).

Raises
------
radarpr.ConfigError
    An unknown descriptor, parameter or value; the message lists what is known.
)")
      .def(py::init<const std::string&>(), py::arg("id"))
      .def_property_readonly(
          "id", [](const PythonDescriptor& d) { return d.instance().id; },
          "The canonical id: the name and the non-default parameters.")
      .def_property_readonly("name", [](const PythonDescriptor& d) { return d.instance().name; })
      .def_property_readonly(
          "parameters", [](const PythonDescriptor& d) { return d.instance().parameters.all(); },
          "Every parameter's value, defaults included.")
      .def_property_readonly(
          "rotation_invariant",
          [](const PythonDescriptor& d) { return d.instance().descriptor->rotation_invariant(); })
      .def("shape", &PythonDescriptor::shape, py::arg("azimuths") = 400,
           py::arg("range_bins") = 3360, py::arg("range_resolution") = 200.0 / 3360.0,
           R"(The (rows, cols) of the value extracted from a scan of this geometry.)")
      .def("extract", &PythonDescriptor::extract, py::arg("image"),
           py::arg("range_resolution") = py::none(), py::arg("azimuths") = py::none(),
           R"(Extract the descriptor value of one scan, as ``radarpr extract`` does.

Parameters
----------
image : numpy.ndarray or PolarScan
    uint8, azimuths x range bins (row = azimuth). A C-ordered array (or one whose rows are each
    contiguous, such as a slice of columns) is read in place; any other layout is copied once.
    A PolarScan brings its own range resolution and azimuth angles.
range_resolution : float, optional
    Metres per range bin; needed unless the bin count names the sensor (3360: MulRan, 3768:
    Oxford).
azimuths : array_like of float, optional
    One angle per row in radians (RaPlace reads them); uniform 2*pi*a/A by default.

Returns
-------
numpy.ndarray
    float32, rows x cols.

Raises
------
ValueError
    The image is not a 2-D uint8 array, or the range resolution is unknown or not positive.

Notes
-----
The GIL is released during the extraction.
)")
      .def("extract_many", &PythonDescriptor::extract_many, py::arg("images"),
           py::arg("range_resolution") = py::none(), py::arg("num_threads") = 0,
           py::arg("scan_axis") = 0,
           R"(Extract the values of many scans in parallel.

Parameters
----------
images : list of numpy.ndarray or numpy.ndarray
    2-D uint8 scans (azimuths x range bins), or one 3-D uint8 array of them.
range_resolution : float, optional
    Metres per range bin, as for ``extract``.
num_threads : int
    Threads to extract on; 0 uses every processor this process may run on.
scan_axis : {0, 2}
    Which axis of a 3-D array counts the scans: 0 (N x A x R, as ``numpy.stack`` makes) or 2
    (A x R x N; each scan is then copied once, as its rows are not contiguous).

Returns
-------
numpy.ndarray
    float32, N x rows x cols, in the order of the scans; equal to ``extract`` on each.

Raises
------
ValueError
    A scan that is not a 2-D uint8 array (its index is named), or scans of different shapes.

Notes
-----
The GIL is released during the extraction; other Python threads keep running.
)")
      .def("distance", &PythonDescriptor::distance, py::arg("a"), py::arg("b"),
           R"(The descriptor's distance between two values (smaller = more similar).

Parameters
----------
a, b : numpy.ndarray
    float32 values as ``extract`` returns them (rows x cols; a 1-D array of D is D x 1).

Returns
-------
float
)")
      .def("time_extract", &PythonDescriptor::time_extract, py::arg("image"),
           py::arg("range_resolution") = py::none(), py::arg("repeats") = 100,
           R"(Seconds per extraction of one scan, timed in a C++ loop.

The reference the cost of calling ``extract`` from Python is measured against
(benchmarks/python/extract_speed.py).

Parameters
----------
image : numpy.ndarray
    uint8, azimuths x range bins.
range_resolution : float, optional
    As for ``extract``.
repeats : int
    Extractions timed.

Returns
-------
float
)")
      .def("__repr__", [](const PythonDescriptor& d) {
        return fmt::format("radarpr.Descriptor('{}')", d.instance().id);
      });
}

}  // namespace radarpr::python
