// The extension module manyworlds._core: the whole C++ API of manyworlds for
// Python (the package python/manyworlds/ re-exports it).
//
// Exceptions: SceneError (a bad scene, setting or per-world value) is
// manyworlds.SceneError, a ValueError; std::invalid_argument -> ValueError,
// std::out_of_range -> IndexError, std::logic_error (a Batch used from two
// threads at once) -> RuntimeError (pybind11's translations).

#include "manyworlds/error.h"
#include "python/bindings.h"

#ifndef MANYWORLDS_VERSION
#define MANYWORLDS_VERSION "unknown"
#endif

PYBIND11_MODULE(_core, m) {
  namespace py = pybind11;
  namespace mw = manyworlds::python;
  m.doc() = "manyworlds: step thousands of independent rigid-body worlds per call.";
  m.attr("__version__") = MANYWORLDS_VERSION;
  py::register_exception<manyworlds::SceneError>(m, "SceneError", PyExc_ValueError);
  mw::BindSettings(m);
  mw::BindConstraints(m);
  mw::BindScene(m);
  mw::BindBatch(m);
  mw::BindRecording(m);
}
