// Python bindings: every enum of the public API, and the settings structs
// that are not constraints (bodies, springs, motors, step, batch options).
// Enum values use Python's UPPER_CASE spelling of the C++ names
// (MotionType::kDynamic is MotionType.DYNAMIC).

#include <string>

#include "manyworlds/batch.h"
#include "manyworlds/scene.h"
#include "manyworlds/spring_settings.h"
#include "python/bindings.h"

namespace manyworlds::python {

void SetFieldsFromKeywords(py::handle object, const py::kwargs& kwargs) {
  const py::handle type = py::type::handle_of(object);
  const py::handle property = reinterpret_cast<PyObject*>(&PyProperty_Type);
  for (const auto& [key, value] : kwargs) {
    // Only properties are fields: methods and dunders are not keywords.
    if (!py::isinstance(py::getattr(type, key, py::none()), property)) {
      throw py::type_error(std::string(py::str(type.attr("__name__"))) +
                           "() got an unexpected keyword argument '" + std::string(py::str(key)) +
                           "'");
    }
    py::setattr(object, key, value);
  }
}

namespace {

void BindEnums(py::module_& m) {
  py::enum_<MotionType>(m, "MotionType", "How a body moves (the same in every world).")
      .value("STATIC", MotionType::kStatic, "never moves")
      .value("KINEMATIC", MotionType::kKinematic, "moved by its velocities only")
      .value("DYNAMIC", MotionType::kDynamic, "moved by forces and constraints");

  // Bit flags: AllowedDofs.TRANSLATION_X | AllowedDofs.ROTATION_Z is an
  // AllowedDofs again (pybind11's arithmetic enums would give a plain int).
  py::enum_<AllowedDofs> dofs(m, "AllowedDofs",
                              "World axes a body may translate along and rotate about "
                              "(flags, combine with |).");
  dofs.value("NONE", AllowedDofs::kNone)
      .value("TRANSLATION_X", AllowedDofs::kTranslationX)
      .value("TRANSLATION_Y", AllowedDofs::kTranslationY)
      .value("TRANSLATION_Z", AllowedDofs::kTranslationZ)
      .value("ROTATION_X", AllowedDofs::kRotationX)
      .value("ROTATION_Y", AllowedDofs::kRotationY)
      .value("ROTATION_Z", AllowedDofs::kRotationZ)
      .value("ALL", AllowedDofs::kAll)
      .value("PLANE_2D", AllowedDofs::kPlane2D)
      .def("__or__", [](AllowedDofs a, AllowedDofs b) { return a | b; })
      .def("__and__", [](AllowedDofs a, AllowedDofs b) { return a & b; })
      .def("__bool__", [](AllowedDofs a) { return a != AllowedDofs::kNone; });
  // Replaces pybind11's repr, which prints "???" for combinations of flags.
  const py::cpp_function dofs_repr(
      [](AllowedDofs a) {
        static constexpr const char* kNames[] = {"TRANSLATION_X", "TRANSLATION_Y", "TRANSLATION_Z",
                                                 "ROTATION_X",    "ROTATION_Y",    "ROTATION_Z"};
        std::string names;
        for (int bit = 0; bit < 6; ++bit) {
          if ((static_cast<int>(a) >> bit) & 1) {
            names += (names.empty() ? "" : "|") + std::string(kNames[bit]);
          }
        }
        return "AllowedDofs." + (names.empty() ? std::string("NONE") : names);
      },
      py::name("__repr__"), py::is_method(dofs));
  dofs.attr("__repr__") = dofs_repr;
  dofs.attr("__str__") = dofs_repr;
  py::implicitly_convertible<py::int_, AllowedDofs>();

  py::enum_<MotorState>(m, "MotorState", "Jolt's EMotorState.")
      .value("OFF", MotorState::kOff)
      .value("VELOCITY", MotorState::kVelocity)
      .value("POSITION", MotorState::kPosition)
      .value("POSITION_AND_VELOCITY", MotorState::kPositionAndVelocity);

  py::enum_<SpringMode>(m, "SpringMode",
                        "How a spring's two numbers are read (Jolt's ESpringMode).")
      .value("FREQUENCY_AND_DAMPING", SpringMode::kFrequencyAndDamping)
      .value("STIFFNESS_AND_DAMPING", SpringMode::kStiffnessAndDamping)
      .value("MASS_NORMALIZED_STIFFNESS_AND_DAMPING",
             SpringMode::kMassNormalizedStiffnessAndDamping);

  py::enum_<SwingType>(m, "SwingType", "Swing limit shape of swing-twist and six-DOF joints.")
      .value("CONE", SwingType::kCone)
      .value("PYRAMID", SwingType::kPyramid);

  py::enum_<ConstraintSpace>(m, "ConstraintSpace", "How a constraint's points and axes are given.")
      .value("WORLD_SPACE", ConstraintSpace::kWorldSpace)
      .value("LOCAL_TO_BODY_COM", ConstraintSpace::kLocalToBodyCOM);

  py::enum_<PathRotation>(m, "PathRotation", "How a path constraint holds body 2's rotation.")
      .value("FREE", PathRotation::kFree)
      .value("CONSTRAIN_AROUND_TANGENT", PathRotation::kConstrainAroundTangent)
      .value("CONSTRAIN_AROUND_NORMAL", PathRotation::kConstrainAroundNormal)
      .value("CONSTRAIN_AROUND_BINORMAL", PathRotation::kConstrainAroundBinormal)
      .value("CONSTRAIN_TO_PATH", PathRotation::kConstrainToPath)
      .value("FULLY_CONSTRAINED", PathRotation::kFullyConstrained);

  py::enum_<SixDofAxis>(m, "SixDofAxis", "The six axes of a six-DOF constraint's frame.")
      .value("TRANSLATION_X", SixDofAxis::kTranslationX)
      .value("TRANSLATION_Y", SixDofAxis::kTranslationY)
      .value("TRANSLATION_Z", SixDofAxis::kTranslationZ)
      .value("ROTATION_X", SixDofAxis::kRotationX)
      .value("ROTATION_Y", SixDofAxis::kRotationY)
      .value("ROTATION_Z", SixDofAxis::kRotationZ);

  py::enum_<JointSolver>(m, "JointSolver", "How a step solves the scene's joints.")
      .value("GAUSS_SEIDEL", JointSolver::kGaussSeidel, "Jolt's iterations (the default)")
      .value("EXACT", JointSolver::kExact,
             "all equality rows at once, Newton position steps (docs/stepping.md)");
  py::enum_<ShapeType>(m, "ShapeType", "A body's collision shape (docs/contacts.md).")
      .value("NONE", ShapeType::kNone, "collides with nothing")
      .value("SPHERE", ShapeType::kSphere, "radius")
      .value("CAPSULE", ShapeType::kCapsule, "radius, half_height along the shape's Y")
      .value("BOX", ShapeType::kBox, "half_extents")
      .value("PLANE", ShapeType::kPlane, "half-space below the shape's XZ plane; static only");
  py::enum_<UnhealthyWorlds>(m, "UnhealthyWorlds", "What a step does with the worlds it flags.")
      .value("KEEP", UnhealthyWorlds::kKeep, "leave them flagged until reset")
      .value("RESET", UnhealthyWorlds::kReset, "reset them to the scene's initial state");

  py::enum_<StateField>(m, "StateField", "One part of a body's 13 state floats.")
      .value("POSITION", StateField::kPosition, "3 floats at offset 0")
      .value("ROTATION", StateField::kRotation, "4 floats (x, y, z, w) at offset 3")
      .value("LINEAR_VELOCITY", StateField::kLinearVelocity, "3 floats at offset 7")
      .value("ANGULAR_VELOCITY", StateField::kAngularVelocity, "3 floats at offset 10");
  m.def("state_field_offset", &StateFieldOffset, py::arg("field"),
        "Offset of the field among a body's 13 state floats.");
  m.def("state_field_size", &StateFieldSize, py::arg("field"), "Floats of the field.");

  // WorldHealthBits: plain ints (the package wraps them in an IntFlag), so
  // `health & manyworlds.NON_FINITE_STATE` works on numpy arrays.
  m.attr("NON_FINITE_STATE") = int(kNonFiniteState);
  m.attr("VELOCITY_OVERFLOW") = int(kVelocityOverflow);
  m.attr("POSITION_OUT_OF_RANGE") = int(kPositionOutOfRange);
  m.attr("NON_FINITE_INPUT") = int(kNonFiniteInput);
  m.attr("NOT_STEPPED") = int(kNotStepped);
}

void BindSpringAndMotor(py::module_& m) {
  py::class_<SpringSettings> spring(m, "SpringSettings",
                                    "Jolt's SpringSettings: frequency (Hz) or stiffness by mode, "
                                    "and damping. frequency_or_stiffness <= 0 on a limit: hard.");
  DefKeywordConstructors(spring);
  spring.def_readwrite("mode", &SpringSettings::mode)
      .def_readwrite("frequency_or_stiffness", &SpringSettings::frequency_or_stiffness)
      .def_readwrite("damping", &SpringSettings::damping);

  py::class_<MotorSettings> motor(m, "MotorSettings",
                                  "Jolt's MotorSettings: the spring of position drives and the "
                                  "force (N) or torque (N m) limits.");
  DefKeywordConstructors(motor);
  motor.def_readwrite("spring", &MotorSettings::spring)
      .def_readwrite("min_force_limit", &MotorSettings::min_force_limit)
      .def_readwrite("max_force_limit", &MotorSettings::max_force_limit);
}

void BindBody(py::module_& m) {
  py::class_<ShapeSettings> shape(m, "ShapeSettings",
                                  "A body's collision shape in its body frame, with friction, "
                                  "restitution and collision filter (docs/contacts.md).");
  DefKeywordConstructors(shape);
  shape.def_readwrite("type", &ShapeSettings::type)
      .def_readwrite("radius", &ShapeSettings::radius, "m: sphere, capsule")
      .def_readwrite("half_height", &ShapeSettings::half_height,
                     "m: capsule, half its core segment (along the shape's Y)");
  DefArray(shape, "half_extents", &ShapeSettings::half_extents, "m: box");
  DefArray(shape, "position", &ShapeSettings::position,
           "shape centre in the body frame, relative to the centre of mass (m)");
  DefArray(shape, "rotation", &ShapeSettings::rotation,
           "shape frame in the body frame, quaternion (x, y, z, w)");
  shape.def_readwrite("friction", &ShapeSettings::friction, "combined as sqrt(f1 f2)")
      .def_readwrite("restitution", &ShapeSettings::restitution, "[0, 1], combined as max")
      .def_readwrite("collision_group", &ShapeSettings::collision_group)
      .def_readwrite("collision_mask", &ShapeSettings::collision_mask,
                     "two shapes meet when (group1 & mask2) and (group2 & mask1)")
      .def_readwrite("collide_with_joined", &ShapeSettings::collide_with_joined,
                     "also collide with bodies a constraint joins");

  py::class_<BodySettings> body(m, "BodySettings",
                                "One body of a scene (Jolt's BodyCreationSettings and defaults). "
                                "Vectors are tuples; assign any sequence or numpy array.");
  DefKeywordConstructors(body);
  body.def_readwrite("name", &BodySettings::name)
      .def_readwrite("motion_type", &BodySettings::motion_type)
      .def_readwrite("mass", &BodySettings::mass, "kg; dynamic bodies only");
  DefArray(body, "inertia_diagonal", &BodySettings::inertia_diagonal,
           "principal moments (kg m^2), body frame");
  DefArray(body, "inertia_rotation", &BodySettings::inertia_rotation,
           "principal axes in the body frame, quaternion (x, y, z, w)");
  DefArray(body, "position", &BodySettings::position, "centre of mass, world (m)");
  DefArray(body, "rotation", &BodySettings::rotation, "quaternion (x, y, z, w)");
  DefArray(body, "linear_velocity", &BodySettings::linear_velocity, "m/s");
  DefArray(body, "angular_velocity", &BodySettings::angular_velocity, "rad/s");
  body.def_readwrite("linear_damping", &BodySettings::linear_damping, "1/s")
      .def_readwrite("angular_damping", &BodySettings::angular_damping, "1/s")
      .def_readwrite("max_linear_velocity", &BodySettings::max_linear_velocity, "m/s")
      .def_readwrite("max_angular_velocity", &BodySettings::max_angular_velocity, "rad/s")
      .def_readwrite("gravity_factor", &BodySettings::gravity_factor)
      .def_readwrite("allowed_dofs", &BodySettings::allowed_dofs)
      .def_readwrite("shape", &BodySettings::shape, "collision shape (ShapeSettings)");

  py::class_<PathPoint> point(m, "PathPoint",
                              "A control point of a Hermite path: position, tangent, normal.");
  DefKeywordConstructors(point);
  DefArray(point, "position", &PathPoint::position);
  DefArray(point, "tangent", &PathPoint::tangent);
  DefArray(point, "normal", &PathPoint::normal);
}

void BindStepAndBatchOptions(py::module_& m) {
  py::class_<StepSettings> step(m, "StepSettings",
                                "Jolt's PhysicsSettings that matter here (defaults: dt 1/60 s, "
                                "1 substep, 10 velocity and 2 position iterations).");
  DefKeywordConstructors(step);
  step.def_readwrite("delta_time", &StepSettings::delta_time, "s, of the whole step")
      .def_readwrite("substeps", &StepSettings::substeps)
      .def_readwrite("velocity_iterations", &StepSettings::velocity_iterations)
      .def_readwrite("velocity_tolerance", &StepSettings::velocity_tolerance,
                     "0 (default): every velocity iteration, as Jolt. > 0: a world stops its "
                     "velocity iterations after the first pass that changed no velocity "
                     "component of its dynamic bodies by more than this (m/s, rad/s); with "
                     "JointSolver.EXACT, of the passes around its joints")
      .def_readwrite("position_iterations", &StepSettings::position_iterations)
      .def_readwrite("baumgarte", &StepSettings::baumgarte)
      .def_readwrite("warm_start", &StepSettings::warm_start);
  DefArray(step, "gravity", &StepSettings::gravity, "m/s^2");
  step.def_readwrite("unhealthy_worlds", &StepSettings::unhealthy_worlds)
      .def_readwrite("gyroscopic", &StepSettings::gyroscopic,
                     "opt-in implicit gyroscopic term (off: Jolt's integration)")
      .def_readwrite("solver", &StepSettings::solver,
                     "GAUSS_SEIDEL (Jolt's) or EXACT (position_iterations: most Newton steps)")
      .def_readwrite("exact_tolerance", &StepSettings::exact_tolerance,
                     "m or rad: EXACT's Newton steps stop at this error of every row group")
      .def_readwrite("exact_geometric_stiffness", &StepSettings::exact_geometric_stiffness,
                     "EXACT: implicit geometric stiffness, x the backward-Euler amount (0: off)")
      .def_readwrite("exact_curvature_velocity", &StepSettings::exact_curvature_velocity,
                     "EXACT, scenes whose joints are all equalities: add the normal velocity "
                     "the joints' curvature needs over a step (off loses energy at first order)")
      .def_readwrite("speculative_contact_distance", &StepSettings::speculative_contact_distance,
                     "m: shapes closer than this make contact points")
      .def_readwrite("penetration_slop", &StepSettings::penetration_slop,
                     "m: penetration left alone by the position phase")
      .def_readwrite("max_penetration_distance", &StepSettings::max_penetration_distance,
                     "m: most penetration one position step corrects")
      .def_readwrite("min_velocity_for_restitution", &StepSettings::min_velocity_for_restitution,
                     "m/s: slower approaches do not bounce")
      .def_readwrite("speculative_contacts_from_velocity",
                     &StepSettings::speculative_contacts_from_velocity,
                     "grow each contact's speculative distance by its approach in a substep "
                     "(off: Jolt's fixed distance)");

  py::class_<BatchOptions> options(m, "BatchOptions", "How a Batch runs its worlds.");
  DefKeywordConstructors(options);
  options.def_readwrite("threads", &BatchOptions::threads, "0: every core")
      .def_readwrite("blocks_per_task", &BatchOptions::blocks_per_task, "0: automatic")
      .def_readwrite("target", &BatchOptions::target,
                     "Highway target bit to force (0: the best this CPU supports)")
      .def_readwrite("profile_phases", &BatchOptions::profile_phases,
                     "time every phase of every block's step (Batch.phase_profile())");

  m.attr("MIN_SUBSTEP_DELTA_TIME") = kMinSubstepDeltaTime;
  m.attr("MAX_SUBSTEP_DELTA_TIME") = kMaxSubstepDeltaTime;
  m.attr("MAX_SUBSTEPS") = kMaxSubsteps;
  m.attr("MAX_ITERATIONS") = kMaxIterations;
  m.attr("MAX_THREADS") = kMaxThreads;
  m.attr("MAX_HEALTHY_COORDINATE") = kMaxHealthyCoordinate;
  m.attr("STATE_FLOATS_PER_BODY") = kStateFloatsPerBody;
}

}  // namespace

void BindSettings(py::module_& m) {
  BindEnums(m);
  BindSpringAndMotor(m);
  BindBody(m);
  BindStepAndBatchOptions(m);
}

}  // namespace manyworlds::python
