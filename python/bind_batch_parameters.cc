// Python bindings: Batch's per-world parameters (domain randomisation),
// vectorised over worlds. Each takes, per value, one number for every world
// or a float32 array [world] (inertia: 3 numbers or [world, 3]), and an
// optional world mask, and loops in C++ over the C++ per-world setter.
//
// All or nothing: the C++ setters refuse a bad value (NaN mass, inverted
// limits, ...) before writing its world, but the worlds before it would
// already hold their new values. So the loop runs after a snapshot of the
// batch and restores it, every byte, when a setter refuses: a bad value in
// world 9 raises ValueError naming world 9 and leaves every world as it was.
// The snapshot costs a copy of the batch (bytes_per_world * num_worlds) per
// call: cheap next to a step, but meant for resets, not every step.

#include <algorithm>
#include <cstdint>
#include <span>
#include <string>

#include "manyworlds/batch.h"
#include "python/bindings.h"
#include "python/numpy_checks.h"

namespace manyworlds::python {
namespace {

// Calls set_world(world) for every world `mask` selects (empty: all),
// restoring the batch if one of them throws.
template <class SetWorld>
void ForSelectedWorlds(Batch& batch, std::span<const std::uint8_t> mask, SetWorld set_world) {
  if (!mask.empty() && std::all_of(mask.begin(), mask.end(), [](auto m) { return m == 0; })) {
    return;  // no world selected: nothing to write, no snapshot to pay for
  }
  const BatchSnapshot before = batch.Snapshot();
  try {
    for (std::size_t w = 0; w < batch.world_count(); ++w) {
      if (mask.empty() || mask[w] != 0) set_world(w);
    }
  } catch (...) {
    batch.Restore(before);
    throw;
  }
}

// The many setters of the form Set(world, index, a, b).
using TwoFloatSetter = void (Batch::*)(std::size_t, std::size_t, float, float);
using OneFloatSetter = void (Batch::*)(std::size_t, std::size_t, float);

// Binds `name`(index, a, b, mask=None) over a two-float setter; `index` is a
// body or a constraint (`index_name`), `a` and `b` the argument names.
void DefTwoFloats(py::class_<Batch>& cls, const char* name, TwoFloatSetter set,
                  const char* index_name, const char* a, const char* b, const char* doc) {
  const bool of_body = std::string(index_name) == "body";
  cls.def(
      name,
      [set, index_name, a, b, of_body](Batch& batch, std::int64_t index, py::handle a_values,
                                       py::handle b_values, py::handle mask) {
        const std::size_t i = CheckedIndex(
            index, of_body ? batch.body_count() : batch.constraint_count(), index_name);
        const std::size_t worlds = batch.world_count();
        const PerWorldFloats first(a_values, a, worlds), second(b_values, b, worlds);
        const auto selected = MaskArgument(mask, "mask", worlds);
        ForSelectedWorlds(batch, selected,
                          [&](std::size_t w) { (batch.*set)(w, i, first[w][0], second[w][0]); });
      },
      py::arg(index_name), py::arg(a), py::arg(b), py::arg("mask") = py::none(), doc);
}

void DefOneFloat(py::class_<Batch>& cls, const char* name, OneFloatSetter set,
                 const char* index_name, const char* a, const char* doc) {
  const bool of_body = std::string(index_name) == "body";
  cls.def(
      name,
      [set, index_name, a, of_body](Batch& batch, std::int64_t index, py::handle values,
                                    py::handle mask) {
        const std::size_t i = CheckedIndex(
            index, of_body ? batch.body_count() : batch.constraint_count(), index_name);
        const std::size_t worlds = batch.world_count();
        const PerWorldFloats per_world(values, a, worlds);
        const auto selected = MaskArgument(mask, "mask", worlds);
        ForSelectedWorlds(batch, selected,
                          [&](std::size_t w) { (batch.*set)(w, i, per_world[w][0]); });
      },
      py::arg(index_name), py::arg(a), py::arg("mask") = py::none(), doc);
}

}  // namespace

void BindParameters(py::class_<Batch>& cls) {
  cls.def(
      "set_mass_properties",
      [](Batch& batch, std::int64_t body, py::handle mass, py::handle inertia, py::handle mask) {
        const std::size_t b = CheckedIndex(body, batch.body_count(), "body");
        const std::size_t worlds = batch.world_count();
        const PerWorldFloats masses(mass, "mass", worlds);
        const PerWorldFloats inertias(inertia, "inertia", worlds, 3);
        const auto selected = MaskArgument(mask, "mask", worlds);
        ForSelectedWorlds(batch, selected, [&](std::size_t w) {
          const float* i = inertias[w];
          batch.SetMassProperties(w, b, masses[w][0], {i[0], i[1], i[2]});
        });
      },
      py::arg("body"), py::arg("mass"), py::arg("inertia"), py::arg("mask") = py::none(),
      "Mass (kg) and principal inertia (kg m^2) of a dynamic body per world: mass a "
      "number or float32 [world], inertia 3 numbers or float32 [world, 3].");
  DefTwoFloats(cls, "set_damping", &Batch::SetDamping, "body", "linear", "angular",
               "Linear and angular damping (1/s) of a body per world.");
  DefOneFloat(cls, "set_gravity_factor", &Batch::SetGravityFactor, "body", "factor",
              "Gravity factor of a body per world.");
  DefTwoFloats(cls, "set_limits", &Batch::SetLimits, "constraint", "min", "max",
               "Limits of a hinge (rad), slider (m) or distance (m) constraint per world "
               "(a rigid distance stays a rod: min == max).");
  DefTwoFloats(cls, "set_limits_spring", &Batch::SetLimitsSpring, "constraint",
               "frequency_or_stiffness", "damping",
               "The limits spring per world (soft limits stay soft, hard stay hard).");
  DefTwoFloats(cls, "set_motor_spring", &Batch::SetMotorSpring, "constraint",
               "frequency_or_stiffness", "damping", "The motor's position spring per world.");
  DefTwoFloats(cls, "set_motor_limits", &Batch::SetMotorLimits, "constraint", "min", "max",
               "The motor's force (N) or torque (N m) limits per world.");
  DefOneFloat(cls, "set_max_friction", &Batch::SetMaxFriction, "constraint", "max_friction",
              "Friction force (N) or torque (N m) when the motor is off, per world.");
  DefOneFloat(cls, "set_ratio", &Batch::SetRatio, "constraint", "ratio",
              "Ratio of a gear, rack-and-pinion or pulley per world.");
}

}  // namespace manyworlds::python
