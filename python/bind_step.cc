// Python bindings: Batch.step, with the keywords of an RL loop's one call
// per step (C++: Batch::Step(settings, StepIo), batch.h): the actions
// written into each block just before it steps, the resets of done worlds
// after it, and the observations read from it, all in the step's own pass
// over the worlds and with the same bits as the separate calls.
//
// Every argument is checked, and refused by name (TypeError, ValueError,
// IndexError, or SceneError from the C++ checks), before anything is
// written or stepped.

#include <cstdint>
#include <deque>
#include <string>
#include <vector>

#include "manyworlds/batch.h"
#include "python/bindings.h"
#include "python/numpy_checks.h"

namespace manyworlds::python {
namespace {

// The action keywords' arrays as StepActions, and the numbers broadcast to
// every world that some of them point into (a deque: its elements never
// move while more are added).
struct StepActions {
  // A reference to every array: the step runs without the GIL, and another
  // Python thread could meanwhile drop the caller's dict entries.
  std::vector<py::object> keep_alive;
  std::deque<PerWorldFloats> per_world_numbers;
  std::vector<StepAction> actions;
};

// One keyword, a dict {index: values} (or None): a body's [world, 3]
// float32 forces or torques, or a constraint's motor targets as float32
// [world] or one number for every world; added in the dict's order.
void AddActions(StepActions& out, const Batch& batch, py::handle keyword, const char* name,
                ActionKind kind) {
  if (keyword.is_none()) return;
  const bool of_body = kind == ActionKind::kForce || kind == ActionKind::kTorque;
  const bool one_per_world =
      kind == ActionKind::kTargetVelocity || kind == ActionKind::kTargetPosition;
  const py::ssize_t width = kind == ActionKind::kTargetOrientation ? 4 : 3;
  if (!py::isinstance<py::dict>(keyword)) {
    throw py::type_error(std::string(name) + ": expected a dict {" +
                         (of_body         ? std::string("body: float32 array [world, 3]")
                          : one_per_world ? std::string("constraint: float32 array [world] or a number")
                                          : "constraint: float32 array [world, " +
                                                std::to_string(width) + "]") +
                         "}, got " + std::string(py::str(py::type::handle_of(keyword).attr("__name__"))));
  }
  for (const auto& [key, values] : py::reinterpret_borrow<py::dict>(keyword)) {
    // Any integer (int, numpy integers: whatever has __index__), as indices are.
    if (!PyIndex_Check(key.ptr())) {
      throw py::type_error(std::string(name) + ": keys are " +
                           (of_body ? "body" : "constraint") + " indices (int), got " +
                           std::string(py::repr(key)));
    }
    const std::int64_t key_value = PyNumber_AsSsize_t(key.ptr(), nullptr);
    if (key_value == -1 && PyErr_Occurred()) throw py::error_already_set();
    const std::size_t index =
        of_body ? CheckedIndex(key_value, batch.body_count(), "body")
                : CheckedIndex(key_value, batch.constraint_count(), "constraint");
    // "body_forces[1]": only the checks below use it (in their messages).
    const std::string what = std::string(name) + "[" + std::to_string(index) + "]";
    std::span<const float> per_world;
    if (one_per_world) {
      per_world =
          out.per_world_numbers.emplace_back(values, what.c_str(), batch.world_count()).Span();
    } else {
      per_world = ArrayArgument<float>(
          values, what.c_str(), {static_cast<py::ssize_t>(batch.world_count()), width});
    }
    out.keep_alive.push_back(py::reinterpret_borrow<py::object>(values));
    out.actions.push_back({kind, index, per_world});
  }
}

// step(...) and check_step(...): the arguments checked and turned into a
// StepIo, then the step, or (check_only) only Batch::CheckStep.
void StepOrCheck(Batch& batch, const StepSettings& settings, py::handle body_forces,
                 py::handle body_torques, py::handle target_velocities,
                 py::handle target_positions, py::handle target_orientations,
                 py::handle target_angular_velocities, py::handle target_translations,
                 py::handle target_linear_velocities, py::handle reset_mask,
                 py::handle reset_states, py::handle state_out, py::handle joints_out,
                 bool check_only) {
  // A copy: another Python thread may change the settings object
  // while this one steps without the GIL.
  const StepSettings copy = settings;
  const auto worlds = static_cast<py::ssize_t>(batch.world_count());
  const auto bodies = static_cast<py::ssize_t>(batch.body_count());
  // Every argument checked (and refused by name) before the step;
  // the C++ call checks the actions against the scene (a static
  // body, a constraint without a motor) before writing any.
  StepActions actions;
  const struct {
    py::handle values;
    const char* name;
    ActionKind kind;
  } keywords[] = {
      {body_forces, "body_forces", ActionKind::kForce},
      {body_torques, "body_torques", ActionKind::kTorque},
      {target_velocities, "target_velocities", ActionKind::kTargetVelocity},
      {target_positions, "target_positions", ActionKind::kTargetPosition},
      {target_orientations, "target_orientations", ActionKind::kTargetOrientation},
      {target_angular_velocities, "target_angular_velocities",
       ActionKind::kTargetAngularVelocity},
      {target_translations, "target_translations", ActionKind::kTargetTranslation},
      {target_linear_velocities, "target_linear_velocities",
       ActionKind::kTargetLinearVelocity},
  };
  for (const auto& keyword : keywords) {
    AddActions(actions, batch, keyword.values, keyword.name, keyword.kind);
  }
  StepIo io;
  io.actions = actions.actions;
  io.reset_mask = MaskArgument(reset_mask, "reset_mask", batch.world_count());
  const Shape state_shape{worlds, bodies, kStateFloatsPerBody};
  if (!reset_states.is_none()) {
    io.reset_states = ArrayArgument<float>(reset_states, "reset_states", state_shape);
  }
  if (!state_out.is_none()) {
    io.state_out = OutputArgument<float>(state_out, "state_out", state_shape);
  }
  if (!joints_out.is_none()) {
    io.joints_out = OutputArgument<float>(
        joints_out, "joints_out",
        {worlds, static_cast<py::ssize_t>(batch.JointCoordinatesPerWorld())});
  }
  if (check_only) {
    batch.CheckStep(copy, io);
    return;
  }
  // The step runs on TBB's threads without the GIL: other Python
  // threads go on meanwhile (a call on this same Batch from one of
  // them raises RuntimeError: a Batch is one thread at a time).
  py::gil_scoped_release release;
  batch.Step(copy, io);
}

// Binds `name` with step's keywords (the same for step and check_step).
template <class Fn>
void DefWithStepKeywords(py::class_<Batch>& cls, const char* name, Fn fn, const char* doc) {
  cls.def(name, fn, py::arg_v("settings", StepSettings{}, "StepSettings()"), py::kw_only(),
          py::arg("body_forces") = py::none(), py::arg("body_torques") = py::none(),
          py::arg("target_velocities") = py::none(), py::arg("target_positions") = py::none(),
          py::arg("target_orientations") = py::none(),
          py::arg("target_angular_velocities") = py::none(),
          py::arg("target_translations") = py::none(),
          py::arg("target_linear_velocities") = py::none(), py::arg("reset_mask") = py::none(),
          py::arg("reset_states") = py::none(), py::arg("state_out") = py::none(),
          py::arg("joints_out") = py::none(), doc);
}

// step and check_step take the same arguments: one function type for both.
template <bool kCheckOnly>
void StepBinding(Batch& batch, const StepSettings& settings, py::handle body_forces,
                 py::handle body_torques, py::handle target_velocities,
                 py::handle target_positions, py::handle target_orientations,
                 py::handle target_angular_velocities, py::handle target_translations,
                 py::handle target_linear_velocities, py::handle reset_mask,
                 py::handle reset_states, py::handle state_out, py::handle joints_out) {
  StepOrCheck(batch, settings, body_forces, body_torques, target_velocities, target_positions,
              target_orientations, target_angular_velocities, target_translations,
              target_linear_velocities, reset_mask, reset_states, state_out, joints_out,
              kCheckOnly);
}

}  // namespace

void BindStep(py::class_<Batch>& cls) {
  DefWithStepKeywords(
      cls, "step", &StepBinding<false>,
      "Steps every world by settings.delta_time (the GIL is released meanwhile). The "
      "keywords do an RL loop's actions, resets and observation reads inside the step's "
      "pass over each block of 16 worlds (cheaper than separate calls, same bits). Before "
      "a block steps, its actions are written: body_forces and body_torques, dicts {body: "
      "float32 [world, 3]}, as set_body_forces / set_body_torques; target_velocities and "
      "target_positions, dicts {constraint: float32 [world] or a number}, as "
      "set_target_velocities / set_target_positions; the drives of swing-twist and six-DOF "
      "constraints, target_orientations (float32 [world, 4]), target_angular_velocities, "
      "target_translations and target_linear_velocities (float32 [world, 3]), dicts "
      "{constraint: array}, as the set_target_* of the same names (all in this order, each "
      "dict in its order). After it steps, the worlds where reset_mask != 0 (bool or uint8 [world]) go "
      "back to the scene's initial state, as reset(mask), or with reset_states (float32 "
      "[world, body, 13]) as reset_to(mask, reset_states); then state_out (float32 [world, "
      "body, 13]) is filled as get_state(out=) and joints_out (float32 [world, "
      "joint_coordinates_per_world]) as get_joint_coordinates(out=). For autoreset, pass "
      "the worlds done after the previous step: their observation is then their new "
      "episode's first. Every argument is checked before anything is written.");
  DefWithStepKeywords(
      cls, "check_step", &StepBinding<true>,
      "Raises exactly what step(...) with the same arguments would raise, and steps and "
      "writes nothing (manyworlds.sharding checks every MPI rank's step this way before "
      "any rank steps).");
}

}  // namespace manyworlds::python
