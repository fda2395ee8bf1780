// Storage of the rotation-Euler part (three angular rows that fix the relative
// rotation of two bodies) for one block of worlds. The maths is in
// rotation_euler-inl.h.
#pragma once

#include "kernels/body_lanes.h"
#include "kernels/kernel_table.h"
#include "manyworlds/lanes.h"

namespace manyworlds {

// Everything the part caches between its verbs. Only `persistent` survives
// from one step to the next; the rest is recomputed in CalculateProperties.
struct RotationEulerLanes {
  Sym33Lanes inv_i1;          // world inverse inertia; zero unless body 1 is dynamic
  Sym33Lanes inv_i2;          // world inverse inertia; zero unless body 2 is dynamic
  Sym33Lanes effective_mass;  // K^-1 after the zero-column fix; zero when deactivated

  struct Persistent {
    Vec3Lanes total_lambda;  // accumulated angular impulse (world)
  } persistent;
};

// The part's kernels on one target; each call processes one block.
//
// The position step needs r0^-1, the inverse of the rotation from body 1 to
// body 2 at rest (q2 = q1 r0), per world; the owning constraint computes it
// once with one of the inverse_initial_orientation_* kernels.
struct RotationEulerKernels {
  TargetInfo target;
  void (*calculate_properties)(const BodyPair&, RotationEulerLanes&);
  void (*warm_start)(const BodyPair&, RotationEulerLanes&, float warm_start_ratio);
  // Solves return true if any lane applied a non-zero impulse / correction.
  bool (*solve_velocity)(const BodyPair&, RotationEulerLanes&);
  // C = 2 xyz(q2 r0^-1 q1*) (w >= 0) from the current rotations, with the
  // inertias and K^-1 of the last calculate_properties.
  bool (*solve_position)(const BodyPair&, const QuatLanes& inv_initial_orientation,
                         const RotationEulerLanes&, float baumgarte);
  void (*deactivate)(RotationEulerLanes&, const LaneFlags& lanes);
  void (*is_active)(const RotationEulerLanes&, LaneFlags& active);

  // r0^-1 = q2* q1: the bodies' current relative rotation becomes the rest one.
  void (*inverse_initial_orientation_from_bodies)(const BodyPair&,
                                                  QuatLanes& inv_initial_orientation);
  // r0^-1 = quat(C2) quat(C1)* from constraint frames given in body space by
  // two unit axes per body, C = (X, Y, X x Y); identity where both frames are
  // equal.
  void (*inverse_initial_orientation_from_frames_xy)(
      const Vec3Lanes& axis_x1, const Vec3Lanes& axis_y1, const Vec3Lanes& axis_x2,
      const Vec3Lanes& axis_y2, QuatLanes& inv_initial_orientation);
  // The same with X and Z axes, C = (X, Z x X, Z).
  void (*inverse_initial_orientation_from_frames_xz)(
      const Vec3Lanes& axis_x1, const Vec3Lanes& axis_z1, const Vec3Lanes& axis_x2,
      const Vec3Lanes& axis_z2, QuatLanes& inv_initial_orientation);
  // Frames given in world space at the bodies' initial rotations q10, q20
  // (the current ones): r0^-1 <- q20* r0^-1 q10.
  void (*inverse_initial_orientation_world_to_local)(const BodyPair&,
                                                     QuatLanes& inv_initial_orientation);
};

MANYWORLDS_DECLARE_KERNEL_TABLE(RotationEulerKernels)

}  // namespace manyworlds
