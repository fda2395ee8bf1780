// Storage of the rotation-quaternion part (three angular rows that fix the
// relative rotation of two bodies, exact quaternion Jacobian) for one block
// of worlds. The maths is in rotation_quat-inl.h.
#pragma once

#include "kernels/body_lanes.h"
#include "kernels/kernel_table.h"
#include "manyworlds/lanes.h"

namespace manyworlds {

// Everything the part caches between its verbs. Only `persistent` survives
// from one step to the next; the rest is recomputed in CalculateProperties.
struct RotationQuatLanes {
  Mat33Lanes inv_i1_jp_transposed;  // I1^-1 JP^T; zero unless body 1 is dynamic
  Mat33Lanes inv_i2_jp_transposed;  // I2^-1 JP^T; zero unless body 2 is dynamic
  Sym33Lanes effective_mass;        // K^-1; zero when deactivated
  Mat33Lanes effective_mass_jp;     // K^-1 JP; zero when deactivated

  struct Persistent {
    Vec3Lanes total_lambda;  // accumulated impulse of the three rows
  } persistent;
};

// The part's kernels on one target; each call processes one block.
// `inv_initial_orientation` is r0^-1 per world (q2 = q1 r0 at rest), as
// computed by RotationEulerKernels' inverse_initial_orientation_* kernels.
struct RotationQuatKernels {
  TargetInfo target;
  // The Jacobian depends on the current error, so it needs r0^-1 too.
  void (*calculate_properties)(const BodyPair&, const QuatLanes& inv_initial_orientation,
                               RotationQuatLanes&);
  void (*warm_start)(const BodyPair&, RotationQuatLanes&, float warm_start_ratio);
  // Solves return true if any lane applied a non-zero impulse / correction.
  bool (*solve_velocity)(const BodyPair&, RotationQuatLanes&);
  // C = xyz(q1* q2 r0^-1) from the current rotations, with the Jacobian and
  // K^-1 of the last calculate_properties.
  bool (*solve_position)(const BodyPair&, const QuatLanes& inv_initial_orientation,
                         const RotationQuatLanes&, float baumgarte);
  void (*deactivate)(RotationQuatLanes&, const LaneFlags& lanes);
  void (*is_active)(const RotationQuatLanes&, LaneFlags& active);
};

MANYWORLDS_DECLARE_KERNEL_TABLE(RotationQuatKernels)

}  // namespace manyworlds
