// The accuracy metrics of `manyworlds sweep` that are not the library's own
// constraint errors (Batch::ConstraintError, Batch::ConstraintVelocityError):
// mechanical energy of a world, pose error against a reference world, and
// which constraints and scenes they apply to. Plain functions of a scene and
// one world's state ([body][13] floats, StateField order), so they can be
// tested on states written by hand.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "manyworlds/scene.h"
#include "manyworlds/scenes.h"

namespace manyworlds::tools {

// Kinetic plus gravitational potential energy of one world (J), from its
// state: sum over dynamic bodies of 1/2 m |v|^2 + 1/2 w_p . (I_p w_p)
// - m g_factor (g . x), w_p the angular velocity in the body's principal
// frame. Zero potential at the origin. Static and kinematic bodies carry none
// (a static body does not move; a scene with kinematic bodies is not
// energy-conserving, see EnergyIsConserved).
double MechanicalEnergy(const Scene& scene, std::span<const float> world_state, Float3 gravity);

// Whether the scene's mechanical energy is a conserved quantity of the exact
// dynamics, so its drift measures the solver: no actions, no body damping,
// no kinematic bodies, no motors or friction (hinge, slider, swing-twist,
// six-DOF), no springs (their potential energy is not counted). Of the
// reference scenes: the four chains and the linkage.
bool EnergyIsConserved(const Scene& scene, const SceneActions& actions);

// The gear and rack-and-pinion constraints whose hinges (and slider) the scene
// names: their position error (Batch::ConstraintError) is the coupling error
// |theta1 + r theta2| or |theta1 - r d2| (rad).
std::vector<std::size_t> CouplingConstraints(const Scene& scene);

// How far one world's bodies are from a reference pose: the largest position
// distance (m) and rotation angle (rad, in [0, pi]) over the non-static bodies.
struct PoseError {
  double position = 0.0;
  double rotation = 0.0;
};
// Both states are [body][13] (StateField order); `reference` in double.
PoseError BodyPoseError(const Scene& scene, std::span<const float> world_state,
                        std::span<const double> reference_state);

}  // namespace manyworlds::tools
