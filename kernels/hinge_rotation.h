// Storage of the hinge-rotation part (two angular rows that keep the hinge
// axes of both bodies aligned) for one block of worlds. The maths is in
// hinge_rotation-inl.h.
#pragma once

#include "kernels/body_lanes.h"
#include "kernels/kernel_table.h"
#include "manyworlds/lanes.h"

namespace manyworlds {

// Per-step inputs the owning constraint computes before CalculateProperties:
// each body's hinge axis in world space (unit).
struct HingeRotationGeometry {
  Vec3Lanes hinge_axis1;  // a1
  Vec3Lanes hinge_axis2;  // a2; repaired inside the part when >= 90 deg from a1
};

// Everything the part caches between its verbs. Only `persistent` survives
// from one step to the next; the rest is recomputed in CalculateProperties.
struct HingeRotationLanes {
  Vec3Lanes a1;      // body 1's hinge axis, for the position error
  Vec3Lanes b2, c2;  // unit perpendiculars of the (repaired) a2: a2 = b2 x c2
  Vec3Lanes b2_x_a1, c2_x_a1;                // angular Jacobian rows
  Vec3Lanes inv_i1_b2_x_a1, inv_i1_c2_x_a1;  // zero unless body 1 is dynamic
  Vec3Lanes inv_i2_b2_x_a1, inv_i2_c2_x_a1;  // zero unless body 2 is dynamic
  Sym22Lanes effective_mass;                 // K^-1; zero when deactivated

  struct Persistent {
    Vec2Lanes total_lambda;  // accumulated angular impulse per row
  } persistent;
};

// The part's kernels on one target; each call processes one block.
struct HingeRotationKernels {
  TargetInfo target;
  void (*calculate_properties)(const BodyPair&, const HingeRotationGeometry&,
                               HingeRotationLanes&);
  void (*warm_start)(const BodyPair&, HingeRotationLanes&, float warm_start_ratio);
  // Solves return true if any lane applied a non-zero impulse / correction.
  bool (*solve_velocity)(const BodyPair&, HingeRotationLanes&);
  // C = (a1.b2, a1.c2) from the cached axes (callers recompute them first).
  bool (*solve_position)(const BodyPair&, const HingeRotationLanes&, float baumgarte);
  void (*deactivate)(HingeRotationLanes&, const LaneFlags& lanes);
  void (*is_active)(const HingeRotationLanes&, LaneFlags& active);
};

MANYWORLDS_DECLARE_KERNEL_TABLE(HingeRotationKernels)

}  // namespace manyworlds
