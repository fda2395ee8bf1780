// What the binding files of the Python module share: their entry points and
// the helpers that make a C++ settings struct feel like a Python object
// (keyword constructors, array fields read as tuples and written from any
// sequence, with errors that name the field).
#pragma once

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <type_traits>

namespace manyworlds {
class Batch;
}

namespace manyworlds::python {

namespace py = pybind11;

// One per binding file, called in this order by module.cc.
void BindSettings(py::module_& m);     // bind_settings.cc: enums, bodies, motors, step
void BindConstraints(py::module_& m);  // bind_constraints.cc: every constraint type
void BindScene(py::module_& m);        // bind_scene.cc: Scene, reference scenes
void BindBatch(py::module_& m);        // bind_batch.cc: Batch
void BindRecording(py::module_& m);    // bind_recording.cc: Recorder
// bind_step.cc: Batch.step with its actions, resets and outputs.
void BindStep(py::class_<Batch>& cls);
// bind_batch_parameters.cc: Batch's per-world parameters (masses, limits...).
void BindParameters(py::class_<Batch>& cls);

// `index` as an index into `count` items, or IndexError naming `what`
// ("body 5 out of range [0, 3)"); negative indices are refused too.
inline std::size_t CheckedIndex(std::int64_t index, std::size_t count, const char* what) {
  if (index < 0 || static_cast<std::uint64_t>(index) >= count) {
    throw py::index_error(std::string(what) + " " + std::to_string(index) + " out of range [0, " +
                          std::to_string(count) + ")");
  }
  return static_cast<std::size_t>(index);
}

// Sets the fields named by `kwargs` on `object` (a Python view of a settings
// struct) through its properties, so every field keeps its own conversion and
// error; an unknown name raises TypeError as Python's own constructors do.
void SetFieldsFromKeywords(py::handle object, const py::kwargs& kwargs);

// Constructors of a settings struct: T() with Jolt's defaults,
// T(field=value, ...) for any of its fields, and T(other, field=value, ...)
// a copy of `other` with those fields changed.
template <class T, class... Options>
void DefKeywordConstructors(py::class_<T, Options...>& cls) {
  const auto with_fields = [](T value, const py::kwargs& kwargs) {
    // A borrowed Python view of `value`: setting its properties writes into
    // `value`; the view dies before `value` is returned.
    SetFieldsFromKeywords(py::cast(&value, py::return_value_policy::reference), kwargs);
    return value;
  };
  cls.def(py::init([with_fields](const py::kwargs& kwargs) { return with_fields(T{}, kwargs); }))
      .def(py::init([with_fields](const T& other, const py::kwargs& kwargs) {
             return with_fields(other, kwargs);
           }),
           py::arg("other"));
}

// "a number" or the Python name of a bound type, for messages.
template <class T>
std::string TypeName() {
  if constexpr (std::is_arithmetic_v<T>) {
    return "a number";
  } else {
    return std::string(py::str(py::type::of<T>().attr("__name__")));
  }
}

// N values from a Python sequence (tuple, list, 1-d numpy array); `what`
// names the field in the TypeError for anything else.
template <class T, std::size_t N>
std::array<T, N> ArrayFrom(py::handle value, const std::string& what) {
  if (py::isinstance<py::str>(value) || !py::isinstance<py::sequence>(value) ||
      py::len(value) != N) {
    throw py::type_error(what + ": expected a sequence of " + std::to_string(N) + " values, got " +
                         std::string(py::repr(value)));
  }
  std::array<T, N> result;
  const py::sequence sequence = py::reinterpret_borrow<py::sequence>(value);
  for (std::size_t i = 0; i < N; ++i) {
    try {
      result[i] = sequence[i].template cast<T>();
    } catch (const py::cast_error&) {
      throw py::type_error(what + "[" + std::to_string(i) + "]: expected " + TypeName<T>() +
                           ", got " + std::string(py::repr(sequence[i])));
    }
  }
  return result;
}

// A std::array field as a Python property. Numbers and enums read as a tuple
// (immutable, so `body.position[0] = 1` fails loudly instead of changing a
// copy); structs (MotorSettings, SpringSettings) read as a tuple of live
// views, so `six_dof.motor[0].max_force_limit = 5` changes the setting.
// Assigning takes any sequence of N values.
template <class Owner, class T, std::size_t N, class... Options>
void DefArray(py::class_<Owner, Options...>& cls, const char* name, std::array<T, N> Owner::*member,
              const char* doc = "") {
  const std::string what = std::string(py::str(cls.attr("__name__"))) + "." + std::string(name);
  cls.def_property(
      name,
      [member](py::object self) {
        auto& values = self.cast<Owner&>().*member;
        py::tuple result(N);
        for (std::size_t i = 0; i < N; ++i) {
          if constexpr (std::is_class_v<T>) {
            result[i] = py::cast(&values[i], py::return_value_policy::reference_internal, self);
          } else {
            result[i] = py::cast(values[i]);
          }
        }
        return result;
      },
      [member, what](Owner& owner, py::handle value) {
        owner.*member = ArrayFrom<T, N>(value, what);
      },
      doc);
}

}  // namespace manyworlds::python
