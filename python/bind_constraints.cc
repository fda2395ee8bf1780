// Python bindings: the twelve constraint settings structs, every field
// read/write, with Jolt's defaults (include/manyworlds/scene.h documents
// each field; the Python docstrings repeat the units).

#include <string>
#include <vector>

#include "manyworlds/scene.h"
#include "python/bindings.h"

namespace manyworlds::python {
namespace {

// A constraint settings class with its keyword constructors and the fields
// every constraint has: name, the two bodies and how its points are given.
template <class T>
py::class_<T> ConstraintClass(py::module_& m, const char* name, const char* doc) {
  py::class_<T> cls(m, name, doc);
  DefKeywordConstructors(cls);
  cls.def_readwrite("name", &T::name)
      .def_readwrite("body1", &T::body1)
      .def_readwrite("body2", &T::body2)
      .def_readwrite("space", &T::space);
  return cls;
}

void BindSimpleJoints(py::module_& m) {
  auto point = ConstraintClass<PointConstraintSettings>(
      m, "PointConstraintSettings", "Ball joint: body 1's point1 and body 2's point2 coincide.");
  DefArray(point, "point1", &PointConstraintSettings::point1);
  DefArray(point, "point2", &PointConstraintSettings::point2);

  auto fixed = ConstraintClass<FixedConstraintSettings>(
      m, "FixedConstraintSettings", "Welds two bodies: relative rotation and anchor fixed.");
  fixed.def_readwrite("auto_detect_point", &FixedConstraintSettings::auto_detect_point);
  DefArray(fixed, "point1", &FixedConstraintSettings::point1);
  DefArray(fixed, "axis_x1", &FixedConstraintSettings::axis_x1);
  DefArray(fixed, "axis_y1", &FixedConstraintSettings::axis_y1);
  DefArray(fixed, "point2", &FixedConstraintSettings::point2);
  DefArray(fixed, "axis_x2", &FixedConstraintSettings::axis_x2);
  DefArray(fixed, "axis_y2", &FixedConstraintSettings::axis_y2);

  auto hinge = ConstraintClass<HingeConstraintSettings>(
      m, "HingeConstraintSettings",
      "One rotation about the hinge axis; limits within [-pi, 0] and [0, pi] (rad).");
  DefArray(hinge, "point1", &HingeConstraintSettings::point1);
  DefArray(hinge, "hinge_axis1", &HingeConstraintSettings::hinge_axis1);
  DefArray(hinge, "normal_axis1", &HingeConstraintSettings::normal_axis1);
  DefArray(hinge, "point2", &HingeConstraintSettings::point2);
  DefArray(hinge, "hinge_axis2", &HingeConstraintSettings::hinge_axis2);
  DefArray(hinge, "normal_axis2", &HingeConstraintSettings::normal_axis2);
  hinge.def_readwrite("limits_min", &HingeConstraintSettings::limits_min, "rad")
      .def_readwrite("limits_max", &HingeConstraintSettings::limits_max, "rad")
      .def_readwrite("limits_spring", &HingeConstraintSettings::limits_spring)
      .def_readwrite("max_friction_torque", &HingeConstraintSettings::max_friction_torque, "N m")
      .def_readwrite("motor", &HingeConstraintSettings::motor, "force limits are torques (N m)")
      .def_readwrite("motor_state", &HingeConstraintSettings::motor_state)
      .def_readwrite("target_angular_velocity", &HingeConstraintSettings::target_angular_velocity,
                     "rad/s")
      .def_readwrite("target_angle", &HingeConstraintSettings::target_angle, "rad");

  auto slider = ConstraintClass<SliderConstraintSettings>(
      m, "SliderConstraintSettings", "One translation along the slider axis; rotation fixed.");
  slider.def_readwrite("auto_detect_point", &SliderConstraintSettings::auto_detect_point);
  DefArray(slider, "point1", &SliderConstraintSettings::point1);
  DefArray(slider, "slider_axis1", &SliderConstraintSettings::slider_axis1);
  DefArray(slider, "normal_axis1", &SliderConstraintSettings::normal_axis1);
  DefArray(slider, "point2", &SliderConstraintSettings::point2);
  DefArray(slider, "slider_axis2", &SliderConstraintSettings::slider_axis2);
  DefArray(slider, "normal_axis2", &SliderConstraintSettings::normal_axis2);
  slider.def_readwrite("limits_min", &SliderConstraintSettings::limits_min, "m, <= 0")
      .def_readwrite("limits_max", &SliderConstraintSettings::limits_max, "m, >= 0")
      .def_readwrite("limits_spring", &SliderConstraintSettings::limits_spring)
      .def_readwrite("max_friction_force", &SliderConstraintSettings::max_friction_force, "N")
      .def_readwrite("motor", &SliderConstraintSettings::motor)
      .def_readwrite("motor_state", &SliderConstraintSettings::motor_state)
      .def_readwrite("target_velocity", &SliderConstraintSettings::target_velocity, "m/s")
      .def_readwrite("target_position", &SliderConstraintSettings::target_position, "m");
}

void BindCouplings(py::module_& m) {
  m.attr("NO_CONSTRAINT") = kNoConstraint;

  auto gear = ConstraintClass<GearConstraintSettings>(
      m, "GearConstraintSettings",
      "theta1 + ratio theta2 = 0; hinge1/hinge2 (NO_CONSTRAINT: none) give position correction.");
  DefArray(gear, "hinge_axis1", &GearConstraintSettings::hinge_axis1);
  DefArray(gear, "hinge_axis2", &GearConstraintSettings::hinge_axis2);
  gear.def_readwrite("ratio", &GearConstraintSettings::ratio)
      .def_readwrite("hinge1", &GearConstraintSettings::hinge1)
      .def_readwrite("hinge2", &GearConstraintSettings::hinge2);

  auto rack = ConstraintClass<RackAndPinionConstraintSettings>(
      m, "RackAndPinionConstraintSettings",
      "theta - ratio d = 0 (rad/m); hinge and slider give position correction.");
  DefArray(rack, "hinge_axis1", &RackAndPinionConstraintSettings::hinge_axis1);
  DefArray(rack, "slider_axis2", &RackAndPinionConstraintSettings::slider_axis2);
  rack.def_readwrite("ratio", &RackAndPinionConstraintSettings::ratio)
      .def_readwrite("hinge", &RackAndPinionConstraintSettings::hinge)
      .def_readwrite("slider", &RackAndPinionConstraintSettings::slider);

  auto distance = ConstraintClass<DistanceConstraintSettings>(
      m, "DistanceConstraintSettings",
      "Distance of the points within [min, max] (m): rod, rope or spring; negative: initial.");
  DefArray(distance, "point1", &DistanceConstraintSettings::point1);
  DefArray(distance, "point2", &DistanceConstraintSettings::point2);
  distance.def_readwrite("min_distance", &DistanceConstraintSettings::min_distance)
      .def_readwrite("max_distance", &DistanceConstraintSettings::max_distance)
      .def_readwrite("limits_spring", &DistanceConstraintSettings::limits_spring);

  auto pulley = ConstraintClass<PulleyConstraintSettings>(
      m, "PulleyConstraintSettings",
      "|p1 - f1| + ratio |p2 - f2| within [min_length, max_length] (m; negative: initial).");
  DefArray(pulley, "body_point1", &PulleyConstraintSettings::body_point1);
  DefArray(pulley, "fixed_point1", &PulleyConstraintSettings::fixed_point1, "world space");
  DefArray(pulley, "body_point2", &PulleyConstraintSettings::body_point2);
  DefArray(pulley, "fixed_point2", &PulleyConstraintSettings::fixed_point2, "world space");
  pulley.def_readwrite("ratio", &PulleyConstraintSettings::ratio)
      .def_readwrite("min_length", &PulleyConstraintSettings::min_length)
      .def_readwrite("max_length", &PulleyConstraintSettings::max_length);
}

void BindRagdollJoints(py::module_& m) {
  auto cone = ConstraintClass<ConeConstraintSettings>(
      m, "ConeConstraintSettings", "Ball joint whose twist axes part by at most half_cone_angle.");
  DefArray(cone, "point1", &ConeConstraintSettings::point1);
  DefArray(cone, "twist_axis1", &ConeConstraintSettings::twist_axis1);
  DefArray(cone, "point2", &ConeConstraintSettings::point2);
  DefArray(cone, "twist_axis2", &ConeConstraintSettings::twist_axis2);
  cone.def_readwrite("half_cone_angle", &ConeConstraintSettings::half_cone_angle, "rad, [0, pi]");

  using SwingTwist = SwingTwistConstraintSettings;
  auto swing = ConstraintClass<SwingTwist>(
      m, "SwingTwistConstraintSettings",
      "Ragdoll joint: swing cone or pyramid and twist range, swing and twist motors.");
  DefArray(swing, "point1", &SwingTwist::point1);
  DefArray(swing, "twist_axis1", &SwingTwist::twist_axis1);
  DefArray(swing, "plane_axis1", &SwingTwist::plane_axis1);
  DefArray(swing, "point2", &SwingTwist::point2);
  DefArray(swing, "twist_axis2", &SwingTwist::twist_axis2);
  DefArray(swing, "plane_axis2", &SwingTwist::plane_axis2);
  swing.def_readwrite("swing_type", &SwingTwist::swing_type)
      .def_readwrite("normal_half_cone_angle", &SwingTwist::normal_half_cone_angle, "rad")
      .def_readwrite("plane_half_cone_angle", &SwingTwist::plane_half_cone_angle, "rad")
      .def_readwrite("twist_min_angle", &SwingTwist::twist_min_angle, "rad")
      .def_readwrite("twist_max_angle", &SwingTwist::twist_max_angle, "rad")
      .def_readwrite("max_friction_torque", &SwingTwist::max_friction_torque, "N m")
      .def_readwrite("swing_motor", &SwingTwist::swing_motor)
      .def_readwrite("twist_motor", &SwingTwist::twist_motor)
      .def_readwrite("swing_motor_state", &SwingTwist::swing_motor_state)
      .def_readwrite("twist_motor_state", &SwingTwist::twist_motor_state);
  DefArray(swing, "target_angular_velocity", &SwingTwist::target_angular_velocity,
           "rad/s about body 2's frame X, Y, Z");
  DefArray(swing, "target_orientation", &SwingTwist::target_orientation,
           "body 2's frame in body 1's, quaternion (x, y, z, w)");

  using SixDof = SixDofConstraintSettings;
  auto six = ConstraintClass<SixDof>(
      m, "SixDofConstraintSettings",
      "Per axis (SixDofAxis) fixed, free or limited, with springs, motors and friction. "
      "Per-axis fields are 6-tuples (limits_spring: 3, translation axes).");
  DefArray(six, "position1", &SixDof::position1);
  DefArray(six, "axis_x1", &SixDof::axis_x1);
  DefArray(six, "axis_y1", &SixDof::axis_y1);
  DefArray(six, "position2", &SixDof::position2);
  DefArray(six, "axis_x2", &SixDof::axis_x2);
  DefArray(six, "axis_y2", &SixDof::axis_y2);
  six.def_readwrite("swing_type", &SixDof::swing_type);
  DefArray(six, "limit_min", &SixDof::limit_min);
  DefArray(six, "limit_max", &SixDof::limit_max);
  DefArray(six, "limits_spring", &SixDof::limits_spring);
  DefArray(six, "max_friction", &SixDof::max_friction, "N (translation), N m (rotation)");
  DefArray(six, "motor", &SixDof::motor);
  DefArray(six, "motor_state", &SixDof::motor_state);
  DefArray(six, "target_velocity", &SixDof::target_velocity, "m/s, body 1's frame");
  DefArray(six, "target_angular_velocity", &SixDof::target_angular_velocity,
           "rad/s, body 2's frame");
  DefArray(six, "target_position", &SixDof::target_position, "m, body 1's frame");
  DefArray(six, "target_orientation", &SixDof::target_orientation,
           "body 2's frame in body 1's, quaternion (x, y, z, w)");
  six.def("make_fixed_axis", &SixDof::MakeFixedAxis, py::arg("axis"))
      .def("make_free_axis", &SixDof::MakeFreeAxis, py::arg("axis"))
      .def("set_limited_axis", &SixDof::SetLimitedAxis, py::arg("axis"), py::arg("min"),
           py::arg("max"));
}

void BindPath(py::module_& m) {
  auto path = ConstraintClass<PathConstraintSettings>(
      m, "PathConstraintSettings",
      "Body 2 slides along a Hermite path fixed to body 1. `path` reads as a tuple of copies: "
      "assign a new sequence of PathPoint to change it.");
  DefArray(path, "path_position", &PathConstraintSettings::path_position);
  DefArray(path, "path_rotation", &PathConstraintSettings::path_rotation);
  path.def_property(
      "path",
      [](const PathConstraintSettings& settings) {
        py::tuple points(settings.path.size());
        for (std::size_t i = 0; i < settings.path.size(); ++i) points[i] = settings.path[i];
        return points;
      },
      [](PathConstraintSettings& settings, const py::sequence& points) {
        std::vector<PathPoint> path;
        for (const py::handle point : points) {
          if (!py::isinstance<PathPoint>(point)) {
            throw py::type_error("PathConstraintSettings.path: expected PathPoint items, got " +
                                 std::string(py::repr(point)));
          }
          path.push_back(point.cast<PathPoint>());
        }
        settings.path = std::move(path);
      },
      "control points (at least 2)");
  path.def_readwrite("looping", &PathConstraintSettings::looping)
      .def_readwrite("path_fraction", &PathConstraintSettings::path_fraction)
      .def_readwrite("rotation", &PathConstraintSettings::rotation)
      .def_readwrite("max_friction_force", &PathConstraintSettings::max_friction_force, "N")
      .def_readwrite("motor", &PathConstraintSettings::motor)
      .def_readwrite("motor_state", &PathConstraintSettings::motor_state)
      .def_readwrite("target_velocity", &PathConstraintSettings::target_velocity, "m/s")
      .def_readwrite("target_path_fraction", &PathConstraintSettings::target_path_fraction);
}

}  // namespace

void BindConstraints(py::module_& m) {
  BindSimpleJoints(m);
  BindCouplings(m);
  BindRagdollJoints(m);
  BindPath(m);
}

}  // namespace manyworlds::python
