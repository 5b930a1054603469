#include "python/numpy_arrays.hpp"

#include <climits>
#include <cmath>
#include <cstring>
#include <stdexcept>

#include <fmt/format.h>

namespace radarpr::python {
namespace {

bool has_dtype(const py::array& array, char kind, py::ssize_t itemsize) {
  return array.dtype().kind() == kind && array.dtype().itemsize() == itemsize;
}

int side(py::ssize_t length, const std::string& what) {
  if (length <= 0) throw std::invalid_argument(what + ": the array is empty");
  if (length > INT_MAX) throw std::invalid_argument(what + ": the array is too large");
  return static_cast<int>(length);
}

ImageView view_of(const std::uint8_t* data, py::ssize_t rows, py::ssize_t cols,
                  py::ssize_t row_stride, py::ssize_t col_stride, const std::string& what) {
  return {data, side(rows, what), side(cols, what), row_stride, col_stride};
}

}  // namespace

std::string describe_object(const py::handle& object) {
  if (!py::isinstance<py::array>(object)) {
    return "a " + py::str(py::type::handle_of(object).attr("__name__")).cast<std::string>();
  }
  const auto array = py::reinterpret_borrow<py::array>(object);
  std::string shape;
  for (py::ssize_t axis = 0; axis < array.ndim(); ++axis) {
    shape += (axis ? ", " : "") + std::to_string(array.shape(axis));
  }
  if (array.ndim() == 1) shape += ",";
  return fmt::format("a {}-D {} array of shape ({})", array.ndim(),
                     py::str(array.dtype()).cast<std::string>(), shape);
}

ImageView image_view(const py::handle& object, const std::string& what) {
  const bool is_array = py::isinstance<py::array>(object);
  if (!is_array || py::reinterpret_borrow<py::array>(object).ndim() != 2 ||
      !has_dtype(py::reinterpret_borrow<py::array>(object), 'u', 1)) {
    throw std::invalid_argument(
        fmt::format("{}: expected a 2-D numpy uint8 array (azimuths x range bins), got {}", what,
                    describe_object(object)));
  }
  const auto array = py::reinterpret_borrow<py::array>(object);
  return view_of(static_cast<const std::uint8_t*>(array.data()), array.shape(0), array.shape(1),
                 array.strides(0), array.strides(1), what);
}

std::vector<ImageView> image_views(const py::handle& images, int scan_axis,
                                   std::vector<py::object>& keep) {
  std::vector<ImageView> views;
  if (py::isinstance<py::array>(images)) {
    const auto array = py::reinterpret_borrow<py::array>(images);
    if (array.ndim() != 3 || !has_dtype(array, 'u', 1)) {
      throw std::invalid_argument(
          fmt::format("images: expected a list of 2-D uint8 arrays or one 3-D uint8 array, got {}",
                      describe_object(images)));
    }
    if (scan_axis != 0 && scan_axis != 2) {
      throw std::invalid_argument(fmt::format(
          "scan_axis: expected 0 (N x azimuths x range bins) or 2 (azimuths x range bins x N), "
          "got {}",
          scan_axis));
    }
    keep.push_back(array);
    const auto* data = static_cast<const std::uint8_t*>(array.data());
    const py::ssize_t count = array.shape(scan_axis);
    for (py::ssize_t i = 0; i < count; ++i) {
      const std::string what = fmt::format("images[{}]", i);
      if (scan_axis == 0) {
        views.push_back(view_of(data + i * array.strides(0), array.shape(1), array.shape(2),
                                array.strides(1), array.strides(2), what));
      } else {
        views.push_back(view_of(data + i * array.strides(2), array.shape(0), array.shape(1),
                                array.strides(0), array.strides(1), what));
      }
    }
    return views;
  }
  if (!py::isinstance<py::sequence>(images) || py::isinstance<py::str>(images)) {
    throw std::invalid_argument(
        fmt::format("images: expected a list of 2-D uint8 arrays or one 3-D uint8 array, got {}",
                    describe_object(images)));
  }
  const auto sequence = py::reinterpret_borrow<py::sequence>(images);
  for (std::size_t i = 0; i < sequence.size(); ++i) {
    py::object item = sequence[i];
    views.push_back(image_view(item, fmt::format("images[{}]", i)));
    keep.push_back(std::move(item));
  }
  return views;
}

ByteImage image_bytes(const ImageView& view) {
  // Descriptors read the scan through a const PolarImage&: the array is never written.
  if (view.col_stride == 1 && view.row_stride == view.cols) {
    return ByteImage::borrow(view.data, view.rows, view.cols);
  }
  // Every pixel is written below.
  ByteImage image = ByteImage::uninitialised(view.rows, view.cols);
  for (int r = 0; r < view.rows; ++r) {
    const std::uint8_t* row = view.data + r * view.row_stride;
    std::uint8_t* out = image.row(r);
    if (view.col_stride == 1) {
      std::memcpy(out, row, static_cast<std::size_t>(view.cols));
    } else {
      for (int c = 0; c < view.cols; ++c) out[c] = row[c * view.col_stride];
    }
  }
  return image;
}

py::array image_array(ByteImage image) {
  auto* owned = new ByteImage(std::move(image));
  py::capsule release(owned, [](void* p) { delete static_cast<ByteImage*>(p); });
  return image_view_array(*owned, release);
}

py::array image_view_array(const ByteImage& image, py::handle owner) {
  // numpy's constructor takes a mutable pointer; the array is made read-only before anyone sees
  // it, so the image is never written through it.
  py::array array(py::dtype::of<std::uint8_t>(), {image.rows(), image.cols()},
                  {static_cast<py::ssize_t>(image.cols()), py::ssize_t{1}},
                  const_cast<std::uint8_t*>(image.data()), owner);
  array.attr("setflags")(py::arg("write") = false);
  return array;
}

py::array_t<float> value_array(DescriptorValue value) {
  auto* owned = new std::vector<float>(std::move(value.values));
  py::capsule free_when_done(owned, [](void* p) { delete static_cast<std::vector<float>*>(p); });
  return py::array_t<float>(
      {static_cast<py::ssize_t>(value.rows), static_cast<py::ssize_t>(value.cols)}, owned->data(),
      free_when_done);
}

py::array_t<float> value_stack(const std::vector<DescriptorValue>& values) {
  const int rows = values.empty() ? 0 : values.front().rows;
  const int cols = values.empty() ? 0 : values.front().cols;
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (values[i].rows != rows || values[i].cols != cols) {
      throw std::invalid_argument(fmt::format(
          "images[{}] gives a {}x{} value, images[0] a {}x{} one: pass scans of one geometry "
          "(or call extract per scan)",
          i, values[i].rows, values[i].cols, rows, cols));
    }
  }
  py::array_t<float> stack({static_cast<py::ssize_t>(values.size()), static_cast<py::ssize_t>(rows),
                            static_cast<py::ssize_t>(cols)});
  float* out = stack.mutable_data();
  for (const DescriptorValue& value : values) {
    std::memcpy(out, value.values.data(), value.payload_bytes());
    out += value.values.size();
  }
  return stack;
}

DescriptorValue value_from_array(const py::handle& object, const std::string& what) {
  const bool is_array = py::isinstance<py::array>(object);
  const auto array = is_array ? py::reinterpret_borrow<py::array>(object) : py::array();
  if (!is_array || (array.ndim() != 1 && array.ndim() != 2) || !has_dtype(array, 'f', 4)) {
    throw std::invalid_argument(
        fmt::format("{}: expected a 1-D or 2-D numpy float32 array (a descriptor value), got {}",
                    what, describe_object(object)));
  }
  DescriptorValue value;
  value.rows = side(array.shape(0), what);
  value.cols = array.ndim() == 2 ? side(array.shape(1), what) : 1;
  value.values.resize(static_cast<std::size_t>(value.rows) * value.cols);
  const auto* data = static_cast<const char*>(array.data());
  const py::ssize_t col_stride = array.ndim() == 2 ? array.strides(1) : 0;
  for (int r = 0; r < value.rows; ++r) {
    for (int c = 0; c < value.cols; ++c) {
      std::memcpy(&value.values[static_cast<std::size_t>(r) * value.cols + c],
                  data + r * array.strides(0) + c * col_stride, sizeof(float));
    }
  }
  return value;
}

std::vector<DescriptorValue> values_from_rows(const py::handle& object, const std::string& what) {
  const bool is_array = py::isinstance<py::array>(object);
  const auto array = is_array ? py::reinterpret_borrow<py::array>(object) : py::array();
  if (!is_array || (array.ndim() != 2 && array.ndim() != 3) ||
      !(has_dtype(array, 'f', 4) || has_dtype(array, 'f', 8))) {
    throw std::invalid_argument(fmt::format(
        "{}: expected an N x D (or N x rows x cols) numpy float32 or float64 array, got {}", what,
        describe_object(object)));
  }
  // One conversion to a C-ordered float32 array (none when it already is one).
  const auto rows32 = py::array_t<float, py::array::c_style | py::array::forcecast>::ensure(array);
  const py::ssize_t count = array.shape(0);
  const int rows = side(array.shape(1), what);
  const int cols = array.ndim() == 3 ? side(array.shape(2), what) : 1;
  const std::size_t size = static_cast<std::size_t>(rows) * cols;
  std::vector<DescriptorValue> values(static_cast<std::size_t>(count));
  const float* data = rows32.data();
  for (py::ssize_t i = 0; i < count; ++i) {
    DescriptorValue& value = values[static_cast<std::size_t>(i)];
    value.rows = rows;
    value.cols = cols;
    value.values.assign(data + i * size, data + (i + 1) * size);
    for (float element : value.values) {
      if (!std::isfinite(element)) {
        throw std::invalid_argument(
            fmt::format("{}: row {} holds a value that is not finite ({})", what, i, element));
      }
    }
  }
  return values;
}

py::array_t<double> real_matrix(const py::handle& object, const std::string& what,
                                std::size_t min_columns, std::size_t max_columns) {
  const bool is_array = py::isinstance<py::array>(object);
  const auto array = is_array ? py::reinterpret_borrow<py::array>(object) : py::array();
  const char kind = is_array ? array.dtype().kind() : '?';
  const std::size_t columns = is_array && array.ndim() == 2 ? array.shape(1) : 0;
  if (!is_array || array.ndim() != 2 || (kind != 'f' && kind != 'i' && kind != 'u') ||
      columns < min_columns || columns > max_columns) {
    const std::string expected = min_columns == max_columns
                                     ? fmt::format("N x {}", min_columns)
                                     : fmt::format("N x {} to N x {}", min_columns, max_columns);
    throw std::invalid_argument(fmt::format("{}: expected an {} numeric numpy array, got {}", what,
                                            expected, describe_object(object)));
  }
  return py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(array);
}

}  // namespace radarpr::python
