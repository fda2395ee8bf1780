// Python bindings: joint coordinates and motor forces (batch.h), the numbers
// RL observations and energy rewards are made of, as float32 arrays
// [world, n]. Outputs go through numpy_checks.h like every other array: an
// `out=` of the wrong dtype, shape or layout is refused by name before
// anything is written.

#include <cstdint>
#include <string>
#include <vector>

#include "manyworlds/batch.h"
#include "python/bindings.h"
#include "python/numpy_checks.h"

namespace manyworlds::python {
namespace {

py::ssize_t Worlds(const Batch& batch) { return static_cast<py::ssize_t>(batch.world_count()); }

// A new float32 array of `shape`, or the caller's `out` (checked by the caller).
py::array Output(py::object out, const Shape& shape) {
  if (out.is_none()) return py::array_t<float>(shape);
  return py::reinterpret_borrow<py::array>(out);
}

std::size_t Constraint(const Batch& batch, std::int64_t constraint) {
  return CheckedIndex(constraint, batch.constraint_count(), "constraint");
}

}  // namespace

void BindJoints(py::module_& m) {
  // Methods added to the Batch class BindBatch made.
  auto cls = py::reinterpret_borrow<py::class_<Batch>>(m.attr("Batch"));
  cls.def(
         "joint_coordinate_count",
         [](const Batch& batch, std::int64_t constraint) {
           return batch.JointCoordinateCount(Constraint(batch, constraint));
         },
         py::arg("constraint"), "How many joint coordinates the constraint has (0 for some types).")
      .def(
          "joint_coordinate_names",
          [](const Batch& batch, std::int64_t constraint) {
            return batch.JointCoordinateNames(Constraint(batch, constraint));
          },
          py::arg("constraint"),
          "Names of the constraint's joint coordinates, in array order: hinge angle, "
          "unwrapped_angle, angular_velocity; slider position, velocity; ... "
          "(batch/joint_coordinates.h).")
      .def_property_readonly("joint_coordinates_per_world", &Batch::JointCoordinatesPerWorld,
                             "Joint coordinates of every constraint of one world, summed.")
      .def(
          "get_joint_coordinates",
          [](const Batch& batch, std::int64_t constraint, py::object out) {
            const std::size_t c = Constraint(batch, constraint);
            const Shape shape{Worlds(batch),
                              static_cast<py::ssize_t>(batch.JointCoordinateCount(c))};
            py::array result = Output(out, shape);
            batch.GetJointCoordinates(c, OutputArgument<float>(result, "out", shape));
            return result;
          },
          py::arg("constraint"), py::arg("out") = py::none(),
          "The constraint's joint coordinates in every world, from the bodies as they are now: "
          "float32 [world, joint_coordinate_count(constraint)], in the order of "
          "joint_coordinate_names(constraint). With out=, fills that array.")
      .def(
          "get_all_joint_coordinates",
          [](const Batch& batch, py::object out) {
            const Shape shape{Worlds(batch),
                              static_cast<py::ssize_t>(batch.JointCoordinatesPerWorld())};
            py::array result = Output(out, shape);
            batch.GetJointCoordinates(OutputArgument<float>(result, "out", shape));
            return result;
          },
          py::arg("out") = py::none(),
          "Every constraint's joint coordinates, constraints in scene order: float32 "
          "[world, joint_coordinates_per_world].")
      .def(
          "motor_force_count",
          [](const Batch& batch, std::int64_t constraint) {
            return batch.MotorForceCount(Constraint(batch, constraint));
          },
          py::arg("constraint"),
          "Motor or friction rows of the constraint: 1 hinge/slider/path, 3 swing-twist, "
          "6 six-DOF, else 0.")
      .def(
          "get_motor_forces",
          [](const Batch& batch, std::int64_t constraint, py::object out) {
            const std::size_t c = Constraint(batch, constraint);
            const Shape shape{Worlds(batch), static_cast<py::ssize_t>(batch.MotorForceCount(c))};
            py::array result = Output(out, shape);
            batch.GetMotorForces(c, OutputArgument<float>(result, "out", shape));
            return result;
          },
          py::arg("constraint"), py::arg("out") = py::none(),
          "Force (N) or torque (N m) each motor or friction row applied in the last substep "
          "of the last step: float32 [world, motor_force_count(constraint)] (zeros before the "
          "first step).");
}

}  // namespace manyworlds::python
