// radarpr.read_polar_png and the PolarScan it returns.
#include <cmath>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>

#include <fmt/format.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "datasets/polar_png.hpp"
#include "python/bindings.hpp"
#include "python/error_translation.hpp"
#include "python/numpy_arrays.hpp"

namespace radarpr::python {
namespace {

PolarPngOptions png_options(std::optional<double> range_resolution, const std::string& layout,
                            bool use_row_metadata) {
  PolarPngOptions options;
  if (range_resolution && !(std::isfinite(*range_resolution) && *range_resolution > 0)) {
    throw std::invalid_argument(fmt::format(
        "range_resolution: expected metres per range bin > 0, got {}", *range_resolution));
  }
  // Decoded first with a provisional resolution when none is given: it only scales metres and
  // never changes the pixels (as `radarpr extract` does).
  options.range_resolution_m = range_resolution.value_or(1.0);
  if (layout == "oxford") {
    options.layout = PolarPngLayout::oxford;
  } else if (layout == "mulran_native") {
    options.layout = PolarPngLayout::mulran_native;
  } else if (layout != "auto") {
    throw std::invalid_argument(
        fmt::format("layout: expected 'auto', 'oxford' or 'mulran_native', got '{}'", layout));
  }
  options.use_row_metadata = use_row_metadata;
  return options;
}

DecodedPolarPng read_scan(const std::filesystem::path& path, std::optional<double> range_resolution,
                          const std::string& layout, bool use_row_metadata) {
  const PolarPngOptions options = png_options(range_resolution, layout, use_row_metadata);
  py::gil_scoped_release unlocked;
  DecodedPolarPng decoded = reading_files([&] { return read_polar_png(path, options); });
  if (!range_resolution) {
    const auto known = known_range_resolution(decoded.image.range_bin_count());
    if (!known) {
      throw std::invalid_argument(fmt::format(
          "{}: {} range bins match no known sensor; pass range_resolution=", path.string(),
          decoded.image.range_bin_count()));
    }
    decoded.image.range_resolution_m = *known;
  }
  return decoded;
}

template <typename T>
py::array_t<T> array_copy(const std::vector<T>& values) {
  return py::array_t<T>(static_cast<py::ssize_t>(values.size()), values.data());
}

}  // namespace

void bind_scans(py::module_& module) {
  py::class_<DecodedPolarPng>(module, "PolarScan", R"(One decoded polar radar scan.

Attributes
----------
image : numpy.ndarray
    uint8, azimuths x range bins (row = azimuth), metadata columns stripped. A read-only view of
    the scan's memory (no copy); ``image.copy()`` to modify it.
azimuths : numpy.ndarray
    float64, one angle per row in radians (encoder values, or uniform when the file has none).
azimuth_times_ns : numpy.ndarray
    int64, one time per row in ns; empty when the file has none.
timestamp_ns : int or None
    The scan's time (Oxford layout: the middle azimuth's time); None for the native layout.
layout : str
    ``'oxford'`` or ``'mulran_native'``.
range_resolution : float
    Metres per range bin.
row_flags : numpy.ndarray
    uint8, byte 10 of every row of the Oxford layout (255 = a real azimuth); empty otherwise.
)")
      .def_property_readonly("image",
                             [](py::object self) {
                               return image_view_array(
                                   self.cast<const DecodedPolarPng&>().image.power, self);
                             })
      .def_property_readonly(
          "azimuths",
          [](const DecodedPolarPng& scan) { return array_copy(scan.image.azimuths_rad); })
      .def_property_readonly(
          "azimuth_times_ns",
          [](const DecodedPolarPng& scan) { return array_copy(scan.image.azimuth_times_ns); })
      .def_readonly("timestamp_ns", &DecodedPolarPng::timestamp_ns)
      .def_property_readonly(
          "layout", [](const DecodedPolarPng& scan) { return std::string(to_string(scan.layout)); })
      .def_property_readonly(
          "range_resolution",
          [](const DecodedPolarPng& scan) { return scan.image.range_resolution_m; })
      .def_property_readonly("row_flags",
                             [](const DecodedPolarPng& scan) { return array_copy(scan.row_flags); })
      .def("__repr__", [](const DecodedPolarPng& scan) {
        return fmt::format("<radarpr.PolarScan {}x{} {} range_resolution={}>",
                           scan.image.azimuth_count(), scan.image.range_bin_count(),
                           to_string(scan.layout), scan.image.range_resolution_m);
      });

  module.def("read_polar_png", &read_scan, py::arg("path"),
             py::arg("range_resolution") = py::none(), py::arg("layout") = "auto",
             py::arg("use_row_metadata") = true,
             R"(Read and decode one polar radar PNG, as ``radarpr extract`` does.

Parameters
----------
path : str or os.PathLike
    The PNG: the Oxford layout (11 metadata columns, one row per azimuth) or MulRan's native
    layout (one row per range bin).
range_resolution : float, optional
    Metres per range bin. Needed unless the bin count names the sensor: 3360 bins (MulRan,
    0.0595238) or 3768 (Oxford, 0.0432).
layout : {'auto', 'oxford', 'mulran_native'}
    'auto' tells the layout from the image's shape.
use_row_metadata : bool
    Oxford layout: read the per-row times and encoder angles (off for sources whose metadata
    bytes are unreliable, such as OORD).

Returns
-------
PolarScan

Raises
------
OSError
    The file is missing, undecodable, or not a polar scan of the expected layout.
ValueError
    A bad option, or an unknown sensor without ``range_resolution``.
)");
}

}  // namespace radarpr::python
