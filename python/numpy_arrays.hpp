#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <pybind11/numpy.h>

#include "datasets/byte_image.hpp"
#include "descriptors/descriptor.hpp"

namespace radarpr::python {

namespace py = pybind11;

// A 2-D uint8 numpy array as radarpr's polar image reads it (row = azimuth, column = range bin),
// taken apart while the GIL is held so that it can be turned into a ByteImage without it. The
// array object must outlive the view.
struct ImageView {
  const std::uint8_t* data = nullptr;
  int rows = 0;
  int cols = 0;
  std::ptrdiff_t row_stride = 0;  // bytes
  std::ptrdiff_t col_stride = 0;  // bytes
};

// Checks that `object` is a numpy uint8 array of rank 2 with both sides > 0; throws
// std::invalid_argument (ValueError) naming `what`, what was expected and what it got otherwise.
ImageView image_view(const py::handle& object, const std::string& what);

// The scans of `images`: a list (or any sequence) of 2-D uint8 arrays, or one 3-D uint8 array
// whose axis `scan_axis` counts the scans (0: N x A x R, as np.stack makes; 2: A x R x N).
// `keep` receives the arrays the views point into.
std::vector<ImageView> image_views(const py::handle& images, int scan_axis,
                                   std::vector<py::object>& keep);

// The view's pixels as a ByteImage: the array's own memory, borrowed, when it is C-ordered (rows
// contiguous and back to back, as a ByteImage lays them out), else one copy. The array is only
// read, and must outlive the image. Needs no GIL.
ByteImage image_bytes(const ImageView& view);

// An image handed over to numpy: a uint8 rows x cols array that owns it (no copy), read-only.
py::array image_array(ByteImage image);

// A read-only uint8 rows x cols array over `image`'s pixels (no copy) that keeps `owner`, the
// Python object holding the image, alive as long as the array lives.
py::array image_view_array(const ByteImage& image, py::handle owner);

// A descriptor value as a float32 rows x cols array that owns the value's memory (no copy).
py::array_t<float> value_array(DescriptorValue value);
// Values of one shape as a float32 N x rows x cols array.
py::array_t<float> value_stack(const std::vector<DescriptorValue>& values);

// A float32 array as a descriptor value: a 2-D array keeps its rows x cols, a 1-D array of D is
// D x 1 (the shape `precomputed` gives its rows). Throws std::invalid_argument (ValueError)
// naming `what` for another dtype or rank.
DescriptorValue value_from_array(const py::handle& object, const std::string& what);

// The values of N scans: an N x D array (each value D x 1, as `precomputed` reads rows) or an
// N x rows x cols array (as extract_many returns), float32 or float64 (rounded to float32, as
// radarpr stores every value). Throws std::invalid_argument (ValueError) naming `what`.
std::vector<DescriptorValue> values_from_rows(const py::handle& object, const std::string& what);

// An N x columns float64 array of any real or integer array with that many columns (positions).
// Throws std::invalid_argument (ValueError) naming `what` and `expected` (e.g. "N x 2 or N x 3").
py::array_t<double> real_matrix(const py::handle& object, const std::string& what,
                                std::size_t min_columns, std::size_t max_columns);

// "a 3-D float64 array of shape (2, 3, 4)", "a list": what `object` is, for error messages.
std::string describe_object(const py::handle& object);

}  // namespace radarpr::python
