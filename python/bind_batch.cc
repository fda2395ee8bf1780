// Python bindings: Batch (construction, state, actions, resets,
// snapshots, health, reports). Step is in bind_step.cc, per-world
// parameters in bind_batch_parameters.cc.
//
// Arrays are world-major, [world, ...], float32, and never converted: every
// numpy argument goes through numpy_checks.h and is refused, by name, before
// anything is written. Actions (forces, torques, motor targets) are never
// refused for NaN or infinity: the world is flagged NON_FINITE_INPUT at the
// next step instead (batch.h, WorldHealthBits), as in C++.

#include <algorithm>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "manyworlds/batch.h"
#include "python/bindings.h"
#include "python/numpy_checks.h"

namespace manyworlds::python {
namespace {

py::ssize_t Worlds(const Batch& batch) { return static_cast<py::ssize_t>(batch.world_count()); }
py::ssize_t Bodies(const Batch& batch) { return static_cast<py::ssize_t>(batch.body_count()); }

// A new float32 array of `shape` for a result, unless the caller passed one
// (`out`) to fill without allocating; either way checked like any argument.
py::array OutputArray(py::object out, const Shape& shape) {
  if (out.is_none()) return py::array_t<float>(shape);
  return py::reinterpret_borrow<py::array>(out);
}

// The mask the C++ Reset takes: None means every world.
std::vector<std::uint8_t> EveryWorld(const Batch& batch) {
  return std::vector<std::uint8_t>(batch.world_count(), 1);
}

void BindConstruction(py::class_<Batch>& cls) {
  cls.def(py::init([](const Scene& scene, std::size_t num_worlds, int threads, std::int64_t target,
                      std::size_t blocks_per_task, bool profile_phases) {
            BatchOptions options;
            options.threads = threads;
            options.target = target;
            options.blocks_per_task = blocks_per_task;
            options.profile_phases = profile_phases;
            return Batch(scene, num_worlds, options);
          }),
          py::arg("scene"), py::arg("num_worlds"), py::arg("threads") = 0, py::arg("target") = 0,
          py::arg("blocks_per_task") = 0, py::arg("profile_phases") = false,
          "num_worlds copies of `scene`. threads 0: every core; target 0: the best SIMD "
          "target of this CPU. Raises SceneError (a ValueError) naming the body or "
          "constraint and field of a bad scene.")
      .def(py::init([](const Scene& scene, std::size_t num_worlds, const BatchOptions& options) {
             return Batch(scene, num_worlds, options);
           }),
           py::arg("scene"), py::arg("num_worlds"), py::arg("options"))
      .def_property_readonly("num_worlds", &Batch::world_count)
      .def_property_readonly("num_bodies", &Batch::body_count)
      .def_property_readonly("num_constraints", &Batch::constraint_count)
      .def_property_readonly(
          "scene", [](const Batch& batch) { return Scene(batch.scene()); }, "A copy of the scene.")
      .def_property_readonly("threads", &Batch::threads)
      .def_property_readonly("simd_target", &Batch::SimdTarget, "e.g. 'AVX3'")
      .def_property_readonly("simd_lanes", &Batch::SimdLanes, "floats per vector")
      .def_property_readonly("bytes_per_world", &Batch::BytesPerWorld)
      .def("__repr__", [](const Batch& batch) {
        return "Batch(" + std::to_string(batch.world_count()) + " worlds, " +
               std::to_string(batch.body_count()) + " bodies, " +
               std::to_string(batch.constraint_count()) + " constraints, " + batch.SimdTarget() +
               ")";
      });
}

void BindState(py::class_<Batch>& cls) {
  cls.def(
          "get_state",
          [](const Batch& batch, py::object out) {
            const Shape shape{Worlds(batch), Bodies(batch), kStateFloatsPerBody};
            py::array result = OutputArray(out, shape);
            batch.GetState(OutputArgument<float>(result, "out", shape));
            return result;
          },
          py::arg("out") = py::none(),
          "Every body of every world: float32 [world, body, 13] = position (3), rotation "
          "quaternion x, y, z, w (4), linear velocity (3), angular velocity (3). With out=, "
          "fills that array instead of allocating one.")
      .def(
          "set_state",
          [](Batch& batch, py::handle state, py::handle mask) {
            batch.SetState(ArrayArgument<float>(
                               state, "state", {Worlds(batch), Bodies(batch), kStateFloatsPerBody}),
                           MaskArgument(mask, "mask", batch.world_count()));
          },
          py::arg("state"), py::arg("mask") = py::none(),
          "Writes float32 [world, body, 13] into every world, or those where mask != 0. "
          "Solver warm-start impulses are kept (snapshots carry everything).")
      .def(
          "get_field",
          [](const Batch& batch, StateField field, py::object out) {
            const Shape shape{Worlds(batch), Bodies(batch),
                              static_cast<py::ssize_t>(StateFieldSize(field))};
            py::array result = OutputArray(out, shape);
            batch.GetField(field, OutputArgument<float>(result, "out", shape));
            return result;
          },
          py::arg("field"), py::arg("out") = py::none(),
          "One StateField of every body: float32 [world, body, state_field_size(field)].")
      .def(
          "set_field",
          [](Batch& batch, StateField field, py::handle values) {
            batch.SetField(field,
                           ArrayArgument<float>(values, "values",
                                                {Worlds(batch), Bodies(batch),
                                                 static_cast<py::ssize_t>(StateFieldSize(field))}));
          },
          py::arg("field"), py::arg("values"))
      .def_property_readonly("solver_state_size", &Batch::SolverStateSize,
                             "Floats of one world's solver state.")
      .def(
          "get_solver_state",
          [](const Batch& batch, std::int64_t world, py::object out) {
            const std::size_t w = CheckedIndex(world, batch.world_count(), "world");
            const Shape shape{static_cast<py::ssize_t>(batch.SolverStateSize())};
            py::array result = OutputArray(out, shape);
            batch.GetSolverState(w, OutputArgument<float>(result, "out", shape));
            return result;
          },
          py::arg("world"), py::arg("out") = py::none(),
          "What one world's constraints and contacts carry from one step to the next besides "
          "its bodies: float32 [solver_state_size] of accumulated impulses, hinge turns, "
          "remembered directions and kept contact points (layout: docs/stepping.md, "
          "\"Solver state of one world\").")
      .def(
          "set_solver_state",
          [](Batch& batch, std::int64_t world, py::handle values) {
            const std::size_t w = CheckedIndex(world, batch.world_count(), "world");
            batch.SetSolverState(
                w, ArrayArgument<float>(values, "values",
                                        {static_cast<py::ssize_t>(batch.SolverStateSize())}));
          },
          py::arg("world"), py::arg("values"),
          "Writes one world's solver state (as get_solver_state gives it); ValueError naming "
          "the constraint or contact, writing nothing, for a value that is not finite, a row "
          "the constraint does not have or a bad contact point. With set_state, a world "
          "continues exactly as the world the two came from.");
}

void BindJointCoordinates(py::class_<Batch>& cls) {
  cls.def(
         "joint_coordinate_count",
         [](const Batch& batch, std::int64_t constraint) {
           return batch.JointCoordinateCount(
               CheckedIndex(constraint, batch.constraint_count(), "constraint"));
         },
         py::arg("constraint"), "Coordinates per world of a constraint (0 for some types).")
      .def(
          "joint_coordinate_names",
          [](const Batch& batch, std::int64_t constraint) {
            return batch.JointCoordinateNames(
                CheckedIndex(constraint, batch.constraint_count(), "constraint"));
          },
          py::arg("constraint"),
          "Names of a constraint's coordinates, e.g. ['angle', 'unwrapped_angle', "
          "'angular_velocity'] for a hinge.")
      .def_property_readonly("joint_coordinates_per_world", &Batch::JointCoordinatesPerWorld,
                             "Coordinates of every constraint of a world, together.")
      .def(
          "get_joint_coordinates",
          [](const Batch& batch, std::optional<std::int64_t> constraint, py::object out) {
            if (!constraint) {
              const Shape shape{Worlds(batch),
                                static_cast<py::ssize_t>(batch.JointCoordinatesPerWorld())};
              py::array result = OutputArray(out, shape);
              batch.GetJointCoordinates(OutputArgument<float>(result, "out", shape));
              return result;
            }
            const std::size_t c = CheckedIndex(*constraint, batch.constraint_count(), "constraint");
            const Shape shape{Worlds(batch),
                              static_cast<py::ssize_t>(batch.JointCoordinateCount(c))};
            py::array result = OutputArray(out, shape);
            batch.GetJointCoordinates(c, OutputArgument<float>(result, "out", shape));
            return result;
          },
          py::arg("constraint") = py::none(), py::arg("out") = py::none(),
          "Joint coordinates from the bodies as they are: float32 [world, "
          "joint_coordinate_count(constraint)] in the order of joint_coordinate_names, or "
          "with constraint None every constraint's, in scene order: [world, "
          "joint_coordinates_per_world]. With out=, fills that array.")
      .def(
          "motor_force_count",
          [](const Batch& batch, std::int64_t constraint) {
            return batch.MotorForceCount(
                CheckedIndex(constraint, batch.constraint_count(), "constraint"));
          },
          py::arg("constraint"),
          "1 for a hinge, slider or path drive, 3 for swing-twist, 6 for six-DOF, else 0.")
      .def(
          "get_motor_forces",
          [](const Batch& batch, std::int64_t constraint, py::object out) {
            const std::size_t c = CheckedIndex(constraint, batch.constraint_count(), "constraint");
            const Shape shape{Worlds(batch), static_cast<py::ssize_t>(batch.MotorForceCount(c))};
            py::array result = OutputArray(out, shape);
            batch.GetMotorForces(c, OutputArgument<float>(result, "out", shape));
            return result;
          },
          py::arg("constraint"), py::arg("out") = py::none(),
          "The force (N) or torque (N m) of each motor or friction row in the last substep "
          "of the last step: float32 [world, motor_force_count(constraint)].")
      .def_property_readonly("num_contact_slots", &Batch::ContactSlotCount,
                             "Pairs of shapes that may touch (docs/contacts.md).")
      .def(
          "contact_slot",
          [](const Batch& batch, std::int64_t slot) {
            const Batch::ContactSlot s =
                batch.GetContactSlot(CheckedIndex(slot, batch.ContactSlotCount(), "contact slot"));
            return py::make_tuple(s.body1, s.body2, s.max_points);
          },
          py::arg("slot"), "(body1, body2, max_points) of a contact slot, body1 < body2.")
      .def(
          "get_contacts",
          [](const Batch& batch, py::object out) {
            const Shape shape{Worlds(batch), static_cast<py::ssize_t>(batch.ContactSlotCount()),
                              static_cast<py::ssize_t>(Batch::kContactFloats)};
            py::array result = OutputArray(out, shape);
            batch.GetContacts(OutputArgument<float>(result, "out", shape));
            return result;
          },
          py::arg("out") = py::none(),
          "Per world and contact slot, from the last substep: points kept, normal force (N), "
          "force on body 2 (N, xyz), normal from body 1 to body 2 (xyz): float32 "
          "[world, num_contact_slots, 8]; zeros where the shapes do not touch.");
}

// A drive target of every world, float32 [world, width], through the C++
// array setter `set` (which refuses a zero quaternion in any world, naming
// it, before writing any).
void SetEveryWorld(Batch& batch, std::int64_t constraint, py::handle values, const char* name,
                   py::ssize_t width,
                   void (Batch::*set)(std::size_t, std::span<const float>)) {
  const std::size_t c = CheckedIndex(constraint, batch.constraint_count(), "constraint");
  (batch.*set)(c, ArrayArgument<float>(values, name, {Worlds(batch), width}));
}

void BindRotationAndTranslationTargets(py::class_<Batch>& cls) {
  cls.def(
         "set_target_orientations",
         [](Batch& batch, std::int64_t constraint, py::handle orientations) {
           SetEveryWorld(batch, constraint, orientations, "orientations", 4,
                         &Batch::SetTargetOrientations);
         },
         py::arg("constraint"), py::arg("orientations"),
         "Rotation drive targets of a swing-twist or six-DOF constraint: body 2's frame in "
         "body 1's, float32 [world, 4] quaternions (x, y, z, w), normalised; a zero "
         "quaternion is refused.")
      .def(
          "set_target_angular_velocities",
          [](Batch& batch, std::int64_t constraint, py::handle velocities) {
            SetEveryWorld(batch, constraint, velocities, "velocities", 3,
                          &Batch::SetTargetAngularVelocities);
          },
          py::arg("constraint"), py::arg("velocities"),
          "Swing-twist or six-DOF: rad/s about body 2's frame axes, float32 [world, 3].")
      .def(
          "set_target_translations",
          [](Batch& batch, std::int64_t constraint, py::handle translations) {
            SetEveryWorld(batch, constraint, translations, "translations", 3,
                          &Batch::SetTargetTranslations);
          },
          py::arg("constraint"), py::arg("translations"),
          "Six-DOF: target displacement (m) in body 1's frame, float32 [world, 3].")
      .def(
          "set_target_linear_velocities",
          [](Batch& batch, std::int64_t constraint, py::handle velocities) {
            SetEveryWorld(batch, constraint, velocities, "velocities", 3,
                          &Batch::SetTargetLinearVelocities);
          },
          py::arg("constraint"), py::arg("velocities"),
          "Six-DOF: target velocity (m/s) in body 1's frame, float32 [world, 3].");
}

void BindActions(py::class_<Batch>& cls) {
  cls.def(
         "set_forces",
         [](Batch& batch, py::handle forces) {
           batch.SetForces(
               ArrayArgument<float>(forces, "forces", {Worlds(batch), Bodies(batch), 3}));
         },
         py::arg("forces"),
         "Forces (N, world space, through the centre of mass) for the next step: float32 "
         "[world, body, 3]; static bodies' entries are ignored. Cleared by the step.")
      .def(
          "set_torques",
          [](Batch& batch, py::handle torques) {
            batch.SetTorques(
                ArrayArgument<float>(torques, "torques", {Worlds(batch), Bodies(batch), 3}));
          },
          py::arg("torques"), "Torques (N m) for the next step: float32 [world, body, 3].")
      .def(
          "set_body_forces",
          [](Batch& batch, std::int64_t body, py::handle forces) {
            const std::size_t b = CheckedIndex(body, batch.body_count(), "body");
            batch.SetForces(b, ArrayArgument<float>(forces, "forces", {Worlds(batch), 3}));
          },
          py::arg("body"), py::arg("forces"),
          "The force on one body of every world for the next step: float32 [world, 3]. "
          "The fast path for RL actions.")
      .def(
          "set_body_torques",
          [](Batch& batch, std::int64_t body, py::handle torques) {
            const std::size_t b = CheckedIndex(body, batch.body_count(), "body");
            batch.SetTorques(b, ArrayArgument<float>(torques, "torques", {Worlds(batch), 3}));
          },
          py::arg("body"), py::arg("torques"), "float32 [world, 3].")
      .def(
          "set_target_velocities",
          [](Batch& batch, std::int64_t constraint, py::handle velocities) {
            const std::size_t c = CheckedIndex(constraint, batch.constraint_count(), "constraint");
            batch.SetTargetVelocities(
                c, PerWorldFloats(velocities, "velocities", batch.world_count()).Span());
          },
          py::arg("constraint"), py::arg("velocities"),
          "Motor target velocity of a hinge (rad/s), slider (m/s) or path (m/s) per world: "
          "float32 [world] or one number for every world.")
      .def(
          "set_target_positions",
          [](Batch& batch, std::int64_t constraint, py::handle positions) {
            const std::size_t c = CheckedIndex(constraint, batch.constraint_count(), "constraint");
            batch.SetTargetPositions(
                c, PerWorldFloats(positions, "positions", batch.world_count()).Span());
          },
          py::arg("constraint"), py::arg("positions"),
          "Motor target position of a hinge (rad), slider (m) or path (fraction) per world, "
          "clamped into the limits: float32 [world] or one number.");
  BindRotationAndTranslationTargets(cls);
}

void BindResetsAndSnapshots(py::class_<Batch>& cls) {
  cls.def(
         "reset",
         [](Batch& batch, py::handle mask) {
           const auto selected = MaskArgument(mask, "mask", batch.world_count());
           if (selected.empty()) {
             batch.Reset(EveryWorld(batch));
           } else {
             batch.Reset(selected);
           }
         },
         py::arg("mask") = py::none(),
         "Puts the worlds where mask != 0 (None: every world) back to the scene's initial "
         "state: state, warm-start impulses, motor targets and per-world parameters.")
      .def(
          "reset_to",
          [](Batch& batch, py::handle mask, py::handle state) {
            const auto selected = MaskArgument(mask, "mask", batch.world_count());
            const auto states = ArrayArgument<float>(
                state, "state", {Worlds(batch), Bodies(batch), kStateFloatsPerBody});
            if (selected.empty()) {
              batch.ResetTo(EveryWorld(batch), states);
            } else {
              batch.ResetTo(selected, states);
            }
          },
          py::arg("mask"), py::arg("state"),
          "reset(mask), then the masked worlds' rows of state (float32 [world, body, 13]).");

  py::class_<BatchSnapshot>(cls, "Snapshot",
                            "Every world of a Batch exactly as it was (Batch.snapshot()). Its "
                            "bytes fit only a Batch of the same scene, world count and build.")
      .def(py::init<>())
      .def_property_readonly("num_worlds", &BatchSnapshot::world_count)
      .def_property_readonly("empty", &BatchSnapshot::empty)
      .def(
          "bytes",
          [](const BatchSnapshot& snapshot) {
            const auto data = snapshot.bytes();
            return py::bytes(reinterpret_cast<const char*>(data.data()), data.size());
          },
          "The snapshot as bytes (to store; read back with Snapshot.from_bytes).")
      .def_static(
          "from_bytes",
          [](const py::buffer& data) {
            const py::buffer_info info = data.request();
            if (info.ndim != 1 || info.itemsize != 1 || info.strides[0] != 1) {
              throw py::type_error("data: expected bytes or a contiguous byte buffer");
            }
            return BatchSnapshot::FromBytes(std::span<const std::byte>(
                static_cast<const std::byte*>(info.ptr), static_cast<std::size_t>(info.size)));
          },
          py::arg("data"), "A snapshot from bytes(); ValueError unless they are a whole one.")
      .def(py::pickle(
          [](const BatchSnapshot& snapshot) {
            const auto data = snapshot.bytes();
            return py::make_tuple(
                py::bytes(reinterpret_cast<const char*>(data.data()), data.size()));
          },
          [](const py::tuple& state) {
            const std::string data = state[0].cast<std::string>();
            return BatchSnapshot::FromBytes(std::span<const std::byte>(
                reinterpret_cast<const std::byte*>(data.data()), data.size()));
          }));

  cls.def("snapshot", &Batch::Snapshot, "Every world, bit for bit (a Batch.Snapshot).")
      .def(
          "restore",
          [](Batch& batch, const BatchSnapshot& snapshot, py::handle mask) {
            batch.Restore(snapshot, MaskArgument(mask, "mask", batch.world_count()));
          },
          py::arg("snapshot"), py::arg("mask") = py::none(),
          "Every world (mask None) or those where mask != 0 back to the snapshot, bit for "
          "bit; ValueError, changing nothing, for a snapshot of another batch layout.");
}

void BindReports(py::class_<Batch>& cls) {
  cls.def_property_readonly(
         "health",
         [](const Batch& batch) {
           const auto health = batch.WorldHealth();
           py::array_t<std::uint8_t> result(static_cast<py::ssize_t>(health.size()));
           std::copy(health.begin(), health.end(), result.mutable_data());
           return result;
         },
         "uint8 [world]: 0 when healthy, else an OR of WorldHealthBits (a copy, after the "
         "last step).")
      .def_property_readonly("unhealthy_world_count", &Batch::UnhealthyWorldCount)
      .def(
          "phase_profile",
          [](const Batch& batch) {
            const PhaseProfile profile = batch.GetPhaseProfile();
            py::dict seconds;
            for (std::size_t p = 0; p < kStepPhaseCount; ++p) {
              seconds[StepPhaseName(StepPhase(p))] = profile.seconds[p];
            }
            py::dict result;
            result["seconds"] = seconds;
            result["block_steps"] = profile.block_steps;
            result["world_steps"] = profile.world_steps;
            return result;
          },
          "With profile_phases=True: {'seconds': {phase: thread seconds}, 'block_steps', "
          "'world_steps'} summed since the batch was made or reset_phase_profile(); phases "
          "in step order: forces, setup, warm_start, velocity, integration, position, "
          "finish. Zeros without profiling.")
      .def("reset_phase_profile", &Batch::ResetPhaseProfile)
      .def(
          "plan",
          [](const Batch& batch, std::optional<StepSettings> settings) {
            return settings ? batch.Plan(*settings) : batch.Plan();
          },
          py::arg("settings") = py::none(),
          "What one step runs, per constraint (for `settings`, default those of the last "
          "step).")
      .def(
          "max_constraint_error",
          [](const Batch& batch, std::int64_t world) {
            return batch.MaxConstraintError(CheckedIndex(world, batch.world_count(), "world"));
          },
          py::arg("world"), "Largest position error of any constraint (m or rad).")
      .def(
          "max_constraint_errors",
          [](const Batch& batch) {
            py::array_t<float> result(Worlds(batch));
            float* out = result.mutable_data();
            for (std::size_t w = 0; w < batch.world_count(); ++w) {
              out[w] = batch.MaxConstraintError(w);
            }
            return result;
          },
          "max_constraint_error of every world: float32 [world].")
      .def(
          "max_constraint_error_split",
          [](const Batch& batch, std::int64_t world) {
            const ConstraintErrorSplit split = batch.MaxConstraintErrorSplit(
                CheckedIndex(world, batch.world_count(), "world"));
            return py::make_tuple(split.linear, split.angular);
          },
          py::arg("world"),
          "(linear m, angular rad): the largest position error of the world's linear rows and "
          "of its angular rows, apart (max_constraint_error is the larger).")
      .def(
          "constraint_error",
          [](const Batch& batch, std::int64_t world, std::int64_t constraint) {
            return batch.ConstraintError(
                CheckedIndex(world, batch.world_count(), "world"),
                CheckedIndex(constraint, batch.constraint_count(), "constraint"));
          },
          py::arg("world"), py::arg("constraint"), "Position error of one constraint.")
      .def(
          "constraint_velocity_error",
          [](const Batch& batch, std::int64_t world, std::int64_t constraint) {
            return batch.ConstraintVelocityError(
                CheckedIndex(world, batch.world_count(), "world"),
                CheckedIndex(constraint, batch.constraint_count(), "constraint"));
          },
          py::arg("world"), py::arg("constraint"), "|J v| of its equality rows.");
}

}  // namespace

void BindBatch(py::module_& m) {
  py::class_<Batch> cls(m, "Batch",
                        "N copies of a scene, stepped together, one SIMD lane per world. Not "
                        "thread-safe: call a Batch from one thread at a time (concurrent use "
                        "raises RuntimeError).");
  BindConstruction(cls);
  BindStep(cls);  // bind_step.cc
  BindState(cls);
  BindJointCoordinates(cls);
  BindActions(cls);
  BindResetsAndSnapshots(cls);
  BindReports(cls);
  BindParameters(cls);
}

}  // namespace manyworlds::python
