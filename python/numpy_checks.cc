// The numpy argument checks (numpy_checks.h).

#include "python/numpy_checks.h"

#include <cstdint>
#include <string>

namespace manyworlds::python {
namespace {

// Python's spelling of a shape: (4096, 2, 3), (4096,), ().
std::string ShapeText(const py::ssize_t* dims, std::size_t ndim) {
  std::string text = "(";
  for (std::size_t i = 0; i < ndim; ++i) {
    text += (i ? ", " : "") + std::to_string(dims[i]);
  }
  return text + (ndim == 1 ? ",)" : ")");
}

std::string TypeNameOf(py::handle value) {
  return std::string(py::str(py::type::handle_of(value).attr("__name__")));
}

// `value` as a numpy array whose dtype is one of `dtypes`, shape `shape`,
// C-contiguous and aligned for T. `expected` names the dtypes in messages,
// `numpy_dtype` is what to convert to (e.g. "np.float32").
template <class T>
py::array CheckedArray(py::handle value, const char* name, const Shape& shape,
                       std::initializer_list<py::dtype> dtypes, const char* expected,
                       const char* numpy_dtype) {
  if (!py::isinstance<py::array>(value)) {
    throw py::type_error(std::string(name) + ": expected a numpy array of " + expected + ", got " +
                         TypeNameOf(value) + " (use np.asarray(x, dtype=" + numpy_dtype + "))");
  }
  py::array array = py::reinterpret_borrow<py::array>(value);
  bool dtype_ok = false;
  for (const py::dtype& dtype : dtypes) {
    dtype_ok = dtype_ok || array.dtype().equal(dtype);
  }
  if (!dtype_ok) {
    throw py::type_error(std::string(name) + ": expected " + expected + ", got " +
                         std::string(py::str(array.dtype())) + " (use arr.astype(" + numpy_dtype +
                         "))");
  }
  const auto ndim = static_cast<std::size_t>(array.ndim());
  bool shape_ok = ndim == shape.size();
  for (std::size_t i = 0; shape_ok && i < ndim; ++i) shape_ok = array.shape(i) == shape[i];
  if (!shape_ok) {
    throw py::value_error(std::string(name) + ": expected shape " +
                          ShapeText(shape.data(), shape.size()) + ", got " +
                          ShapeText(array.shape(), ndim));
  }
  if (!(array.flags() & py::array::c_style)) {
    throw py::value_error(std::string(name) + ": must be C-contiguous; use np.ascontiguousarray");
  }
  if (reinterpret_cast<std::uintptr_t>(array.data()) % alignof(T) != 0) {
    throw py::value_error(std::string(name) + ": data is not aligned to " +
                          std::to_string(alignof(T)) + " bytes; use np.ascontiguousarray");
  }
  return array;
}

// Names for messages, constants: the checks run on every call of an RL
// loop, so nothing is built unless a check fails.
template <class T>
constexpr const char* kDtypeName = nullptr;
template <>
constexpr const char* kDtypeName<float> = "float32";
template <class T>
constexpr const char* kNumpyDtype = nullptr;
template <>
constexpr const char* kNumpyDtype<float> = "np.float32";

}  // namespace

template <class T>
std::span<const T> ArrayArgument(py::handle value, const char* name, const Shape& shape) {
  const py::array array =
      CheckedArray<T>(value, name, shape, {py::dtype::of<T>()}, kDtypeName<T>, kNumpyDtype<T>);
  return {static_cast<const T*>(array.data()), static_cast<std::size_t>(array.size())};
}

template <class T>
std::span<T> OutputArgument(py::handle value, const char* name, const Shape& shape) {
  py::array array =
      CheckedArray<T>(value, name, shape, {py::dtype::of<T>()}, kDtypeName<T>, kNumpyDtype<T>);
  if (!array.writeable()) {
    throw py::value_error(std::string(name) + ": array is read-only");
  }
  return {static_cast<T*>(array.mutable_data()), static_cast<std::size_t>(array.size())};
}

template std::span<const float> ArrayArgument<float>(py::handle, const char*, const Shape&);
template std::span<float> OutputArgument<float>(py::handle, const char*, const Shape&);

std::span<const std::uint8_t> MaskArgument(py::handle value, const char* name, std::size_t worlds) {
  if (value.is_none()) return {};
  // numpy's bool is one byte holding 0 or 1, so both read as uint8.
  const py::array array = CheckedArray<std::uint8_t>(
      value, name, {static_cast<py::ssize_t>(worlds)},
      {py::dtype::of<bool>(), py::dtype::of<std::uint8_t>()}, "bool or uint8", "bool");
  return {static_cast<const std::uint8_t*>(array.data()), worlds};
}

PerWorldFloats::PerWorldFloats(py::handle value, const char* name, std::size_t worlds,
                               std::size_t width)
    : worlds_(worlds), width_(width) {
  const auto w = static_cast<py::ssize_t>(worlds);
  if (py::isinstance<py::array>(value)) {
    const Shape shape = width == 1 ? Shape{w} : Shape{w, static_cast<py::ssize_t>(width)};
    data_ = ArrayArgument<float>(value, name, shape).data();
    stride_ = width;
    return;
  }
  const auto refuse = [&] {
    const std::string shape =
        width == 1 ? "(" + std::to_string(worlds) + ",)"
                   : "(" + std::to_string(worlds) + ", " + std::to_string(width) + ")";
    const std::string expected =
        (width == 1 ? std::string("a number")
                    : "a sequence of " + std::to_string(width) + " numbers") +
        " or a numpy array of float32, shape " + shape;
    std::string got = TypeNameOf(value);
    if (py::isinstance<py::sequence>(value) && !py::isinstance<py::str>(value)) {
      got += " of length " + std::to_string(py::len(value));
    }
    throw py::type_error(std::string(name) + ": expected " + expected + "; got " + got +
                         " (use np.asarray(x, dtype=np.float32))");
  };
  // PyNumber_Check: ints, floats, numpy scalars; not strings.
  const auto number = [&](py::handle item) {
    if (!PyNumber_Check(item.ptr())) refuse();
    return static_cast<float>(py::float_(py::reinterpret_borrow<py::object>(item)));
  };
  if (width == 1) {
    broadcast_.push_back(number(value));
  } else {
    if (py::isinstance<py::str>(value) || !py::isinstance<py::sequence>(value) ||
        py::len(value) != width) {
      refuse();
    }
    for (const py::handle item : value) broadcast_.push_back(number(item));
  }
  data_ = broadcast_.data();
  stride_ = 0;
}

std::span<const float> PerWorldFloats::Span() {
  if (stride_ == 0) {
    const std::vector<float> one(broadcast_.begin(), broadcast_.end());
    broadcast_.clear();
    for (std::size_t w = 0; w < worlds_; ++w) {
      broadcast_.insert(broadcast_.end(), one.begin(), one.end());
    }
    data_ = broadcast_.data();
    stride_ = width_;
  }
  return {data_, worlds_ * width_};
}

}  // namespace manyworlds::python
