// The checks every numpy argument of a Batch method goes through, in one
// place so that each argument is refused the same way, by name, before
// anything is written:
//   not a numpy array or the wrong dtype  -> TypeError
//   the wrong shape, not C-contiguous,
//   misaligned, read-only (outputs)       -> ValueError
// Nothing is converted: a float64 array is refused, not copied, so a loop
// that passes the wrong dtype is told so instead of silently paying for a
// conversion every step.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace manyworlds::python {

namespace py = pybind11;

using Shape = std::vector<py::ssize_t>;

// The data of `value`, a C-contiguous numpy array of dtype T and exactly
// `shape`, or the exception above naming `name`. The span lives as long as
// the caller's reference to `value`.
template <class T>
std::span<const T> ArrayArgument(py::handle value, const char* name, const Shape& shape);

// The same for an array the call writes into (`out=`): also refuses a
// read-only array.
template <class T>
std::span<T> OutputArgument(py::handle value, const char* name, const Shape& shape);

// A world mask: None (every world: an empty span, as the C++ API takes it),
// or a bool or uint8 array of shape (worlds,); a world is selected when its
// entry is not 0.
std::span<const std::uint8_t> MaskArgument(py::handle value, const char* name, std::size_t worlds);

// One float per world: a number (the same for every world) or a float32
// array of shape (worlds,). With width 3, three floats per world: a sequence
// of 3 numbers or a float32 array of shape (worlds, 3).
class PerWorldFloats {
 public:
  PerWorldFloats(py::handle value, const char* name, std::size_t worlds, std::size_t width = 1);
  // The `width` floats of `world`.
  const float* operator[](std::size_t world) const { return data_ + world * stride_; }
  // Every world's floats, contiguous (a broadcast number is repeated).
  std::span<const float> Span();

 private:
  std::vector<float> broadcast_;  // the value given for every world
  const float* data_ = nullptr;
  std::size_t stride_ = 0;  // 0 when broadcast
  std::size_t worlds_ = 0, width_ = 1;
};

}  // namespace manyworlds::python
