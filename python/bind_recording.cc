// Python bindings: Recorder, the NPZ recording of chosen worlds
// (include/manyworlds/recording.h, docs/recording.md). The Python side
// (python/manyworlds/recording.py) adds the context manager and
// load_recording.

#include <pybind11/stl.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "manyworlds/batch.h"
#include "manyworlds/recording.h"
#include "python/bindings.h"

namespace manyworlds::python {

void BindRecording(py::module_& m) {
  py::class_<Recorder>(m, "Recorder",
                       "Streams chosen worlds of a Batch, one frame per capture(), into an NPZ "
                       "file (docs/recording.md). Use it as a context manager: the file "
                       "appears at the end of the with-block, whole, and not at all after "
                       "an exception.")
      .def(py::init([](const Batch& batch, const std::string& path,
                       const std::vector<std::int64_t>& worlds, const std::string& scene,
                       bool overwrite) {
             std::vector<std::size_t> indices;
             for (const std::int64_t w : worlds) {
               indices.push_back(CheckedIndex(w, batch.world_count(), "world"));
             }
             return Recorder(batch, path, indices,
                             RecorderOptions{.scene = scene, .overwrite = overwrite});
           }),
           py::arg("batch"), py::arg("path"), py::arg("worlds") = std::vector<std::int64_t>{0},
           py::kw_only(), py::arg("scene") = "", py::arg("overwrite") = false,
           "Records `worlds` of `batch` to `path` (str); an existing file is refused unless "
           "overwrite=True.")
      .def(
          "capture",
          [](Recorder& self, const Batch& batch, double time, std::int64_t step) {
            py::gil_scoped_release release;
            self.Capture(batch, time, step);
          },
          py::arg("batch"), py::arg("time"), py::arg("step"),
          "One frame: the recorded worlds of `batch` now, at simulated `time` (s) after "
          "`step` steps.")
      .def("close", &Recorder::Close, py::call_guard<py::gil_scoped_release>(),
           "Writes the file (under a temporary name, then renamed).")
      .def("discard", &Recorder::Discard,
           "Removes the partial file without writing it (the with-block does on an exception).")
      .def_property_readonly("closed", &Recorder::closed)
      .def_property_readonly("frame_count", &Recorder::frame_count)
      .def_property_readonly("path", &Recorder::path);
}

}  // namespace manyworlds::python
