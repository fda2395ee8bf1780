// Python bindings: Scene, the reference and stress scenes with their actions
// and step settings, LimitMassRange, and the SIMD target queries.

#include <cstdint>
#include <string>

#include "manyworlds/mass_range.h"
#include "manyworlds/scene.h"
#include "manyworlds/scenes.h"
#include "manyworlds/shard.h"
#include "manyworlds/targets.h"
#include "python/bindings.h"

namespace manyworlds::python {
namespace {

void BindSceneClass(py::module_& m) {
  py::class_<Scene>(m, "Scene",
                    "The bodies and constraints of one world, which a Batch copies into N "
                    "worlds. Plain data: nothing is checked until a Batch is built from it. "
                    "`bodies` and `constraints` read as tuples of copies: change one with "
                    "set_body / set_constraint.")
      .def(py::init<>())
      .def(py::init<const Scene&>(), py::arg("other"))
      .def("add_body", &Scene::AddBody, py::arg("body"), "Adds a body; returns its index.")
      .def("add_constraint", &Scene::AddConstraint, py::arg("constraint"),
           "Adds any XxxConstraintSettings; returns its index. Constraints are solved in "
           "the order they were added.")
      .def_property_readonly("bodies",
                             [](const Scene& scene) { return py::tuple(py::cast(scene.bodies())); })
      .def_property_readonly(
          "constraints",
          [](const Scene& scene) { return py::tuple(py::cast(scene.constraints())); })
      .def_property_readonly("num_bodies", [](const Scene& scene) { return scene.bodies().size(); })
      .def_property_readonly("num_constraints",
                             [](const Scene& scene) { return scene.constraints().size(); })
      .def(
          "set_body",
          [](Scene& scene, std::int64_t index, const BodySettings& body) {
            scene.bodies()[CheckedIndex(index, scene.bodies().size(), "body")] = body;
          },
          py::arg("index"), py::arg("body"), "Replaces body `index`.")
      .def(
          "set_constraint",
          [](Scene& scene, std::int64_t index, const ConstraintSettings& constraint) {
            scene.constraints()[CheckedIndex(index, scene.constraints().size(), "constraint")] =
                constraint;
          },
          py::arg("index"), py::arg("constraint"), "Replaces constraint `index`.")
      .def(
          "body_label",
          [](const Scene& scene, std::int64_t index) {
            return BodyLabel(scene, CheckedIndex(index, scene.bodies().size(), "body"));
          },
          py::arg("index"), "The body's name, or a label, as error messages print it.")
      .def(
          "constraint_label",
          [](const Scene& scene, std::int64_t index) {
            return ConstraintLabel(scene,
                                   CheckedIndex(index, scene.constraints().size(), "constraint"));
          },
          py::arg("index"), "The constraint's name, or '<type> #index'.")
      .def("__repr__", [](const Scene& scene) {
        return "Scene(" + std::to_string(scene.bodies().size()) + " bodies, " +
               std::to_string(scene.constraints().size()) + " constraints)";
      });
}

void BindSceneCatalogue(py::module_& m) {
  m.def("reference_scene_ids", &ReferenceSceneIds, "Ids of the reference scenes.");
  m.def("stress_scene_ids", &StressSceneIds, "Ids of the stress scenes.");
  m.def("contact_scene_ids", &ContactSceneIds, "Ids of the contact scenes (docs/contacts.md).");
  m.def("all_scene_ids", &AllSceneIds, "Every scene id, reference then stress then contact.");
  m.def(
      "make_scene", [](const std::string& id) { return MakeScene(id); }, py::arg("id"),
      "The reference or stress scene `id`; ValueError lists the valid ids.");
  m.def("make_chain", &MakeChain, py::arg("links"), py::arg("last_link_scale"),
        "chain16's chain at any length and mass ratio: `links` ball-jointed rods 0.5 m long "
        "released from horizontal, the last one's mass and inertia times `last_link_scale` "
        "(make_chain(16, 100) is chain16-r100); ValueError names a bad argument.");
  m.def(
      "scene_step_settings", [](const std::string& id) { return SceneStepSettings(id); },
      py::arg("id"), "The StepSettings scene `id` is meant to be stepped with.");
  m.def(
      "scene_description", [](const std::string& id) { return SceneDescription(id); },
      py::arg("id"), "What scene `id` is and what it tests, one line (as `manyworlds scenes`).");

  py::class_<MassRaise>(m, "MassRaise", "A body whose mass limit_mass_range raised.")
      .def_readonly("body", &MassRaise::body)
      .def_readonly("factor", &MassRaise::factor, "new mass / old mass (inertia too)")
      .def("__repr__", [](const MassRaise& raise) {
        return "MassRaise(body=" + std::to_string(raise.body) +
               ", factor=" + std::string(py::repr(py::float_(raise.factor))) + ")";
      });
  m.def("limit_mass_range", &LimitMassRange, py::arg("scene"), py::arg("max_ratio"),
        "Raises the masses (and inertias) of bodies lighter than the heaviest of their "
        "joined group / max_ratio, in place; returns the raised bodies.");

  py::class_<BodyForce>(m, "BodyForce", "A force (N, world) on one body for the next step.")
      .def_readonly("body", &BodyForce::body)
      .def_property_readonly("force",
                             [](const BodyForce& f) { return py::tuple(py::cast(f.force)); });
  py::class_<MotorTarget>(m, "MotorTarget", "A motor position target for the next step.")
      .def_readonly("constraint", &MotorTarget::constraint)
      .def_readonly("position", &MotorTarget::position);
  py::class_<SceneActions>(m, "SceneActions",
                           "The per-step actions of a reference scene, a function of "
                           "(seed, world, step) only.")
      .def(py::init([](const std::string& id) { return SceneActions(id); }), py::arg("id"))
      .def_property_readonly("empty", &SceneActions::empty)
      .def_property_readonly("forces_per_world", &SceneActions::forces_per_world)
      .def_property_readonly("targets_per_world", &SceneActions::targets_per_world)
      .def("force", &SceneActions::Force, py::arg("i"), py::arg("world"), py::arg("step"),
           py::arg("seed"))
      .def("target", &SceneActions::Target, py::arg("i"), py::arg("world"), py::arg("step"),
           py::arg("seed"))
      .def("apply", &SceneActions::Apply, py::arg("batch"), py::arg("step"), py::arg("seed"),
           py::arg("first_world") = 0,
           "Sets the forces and targets of every world of `batch` for its next step; "
           "local world i gets world first_world + i's (a shard of a larger batch).");
  m.def(
      "shard_of_worlds",
      [](std::size_t total_worlds, int rank, int ranks) {
        const WorldShard shard = ShardOfWorlds(total_worlds, rank, ranks);
        return py::make_tuple(shard.first, shard.count);
      },
      py::arg("total_worlds"), py::arg("rank"), py::arg("ranks"),
      "(first, count): the global worlds rank `rank` of `ranks` owns (C++ ShardOfWorlds, "
      "docs/scale-out.md): contiguous, balanced to whole blocks of 16 worlds. ValueError "
      "when total_worlds < ranks.");
  m.def("cartpole_force", &CartpoleForce, py::arg("seed"), py::arg("world"), py::arg("step"),
        "The reference cartpole's cart force (N) of a world at a step.");

  // Indices of the reference scenes' bodies and constraints.
  py::module_ ids = m.def_submodule("reference_scene", "Body and constraint indices.");
  ids.attr("WORLD") = reference_scene::kWorld;
  ids.attr("CART") = reference_scene::kCart;
  ids.attr("POLE") = reference_scene::kPole;
  ids.attr("RAIL") = reference_scene::kRail;
  ids.attr("POLE_HINGE") = reference_scene::kPoleHinge;
  ids.attr("PINION") = reference_scene::kPinion;
  ids.attr("RACK") = reference_scene::kRack;
  ids.attr("PINION_HINGE") = reference_scene::kPinionHinge;
  ids.attr("RACK_SLIDER") = reference_scene::kRackSlider;
  ids.attr("RACK_AND_PINION") = reference_scene::kRackAndPinion;
  ids.attr("GEAR1") = reference_scene::kGear1;
  ids.attr("GEAR2") = reference_scene::kGear2;
  ids.attr("GEAR1_HINGE") = reference_scene::kGear1Hinge;
  ids.attr("GEAR2_HINGE") = reference_scene::kGear2Hinge;
  ids.attr("GEAR") = reference_scene::kGear;
  ids.attr("PELVIS") = reference_scene::kPelvis;
  ids.attr("LEFT_ELBOW") = reference_scene::kLeftElbow;
  ids.attr("LEFT_KNEE") = reference_scene::kLeftKnee;
  ids.attr("RIGHT_ELBOW") = reference_scene::kRightElbow;
  ids.attr("RIGHT_KNEE") = reference_scene::kRightKnee;
}

void BindTargets(py::module_& m) {
  m.def("dispatched_target", &DispatchedTargetName,
        "Highway's name of the SIMD target this CPU dispatches to, e.g. 'AVX3'.");
  m.def("dispatched_vector_lanes", &DispatchedVectorLanes, "Floats per vector on it.");
  m.def("compiled_targets", &CompiledTargetNames, "Targets compiled in, best first.");
  m.def("supported_targets", &SupportedTargetNames, "Compiled targets this CPU runs.");
}

}  // namespace

void BindScene(py::module_& m) {
  BindSceneClass(m);
  BindSceneCatalogue(m);
  BindTargets(m);
}

}  // namespace manyworlds::python
