// Storage of the point part (three linear rows; ball joint) for one block of
// worlds. The maths is in point-inl.h.
#pragma once

#include "kernels/body_lanes.h"
#include "kernels/kernel_table.h"
#include "manyworlds/lanes.h"

namespace manyworlds {

// Per-step inputs from the owning constraint: the anchor of each body relative
// to its centre of mass, in body space. CalculateProperties rotates them by the
// bodies' current rotations.
struct PointGeometry {
  Vec3Lanes r1_local;
  Vec3Lanes r2_local;
};

// Everything the part caches between its verbs. Only `persistent` survives
// from one step to the next; the rest is recomputed in CalculateProperties.
struct PointLanes {
  Vec3Lanes r1, r2;                 // world lever arms p1 - x1, p2 - x2
  Mat33Lanes inv_i1_r1_cross;       // I1^-1 [r1]x; zero unless body 1 is dynamic
  Mat33Lanes inv_i2_r2_cross;       // I2^-1 [r2]x; zero unless body 2 is dynamic
  Sym33Lanes effective_mass;        // K^-1; zero when deactivated

  struct Persistent {
    Vec3Lanes total_lambda;  // accumulated impulse (world, linear)
  } persistent;
};

// The part's kernels on one target; each call processes one block.
struct PointKernels {
  TargetInfo target;
  void (*calculate_properties)(const BodyPair&, const PointGeometry&, PointLanes&);
  void (*warm_start)(const BodyPair&, PointLanes&, float warm_start_ratio);
  // Solves return true if any lane applied a non-zero impulse / correction.
  bool (*solve_velocity)(const BodyPair&, PointLanes&);
  // C from the current centres of mass and the lever arms of the last
  // calculate_properties (callers recompute them first).
  bool (*solve_position)(const BodyPair&, const PointLanes&, float baumgarte);
  // The position phase's verb: calculate_properties + solve_position, except
  // that a lane whose C is exactly zero is left exactly as it is.
  bool (*recompute_and_solve_position)(const BodyPair&, const PointGeometry&, PointLanes&,
                                       float baumgarte);
  void (*deactivate)(PointLanes&, const LaneFlags& lanes);
  void (*is_active)(const PointLanes&, LaneFlags& active);
};

MANYWORLDS_DECLARE_KERNEL_TABLE(PointKernels)

}  // namespace manyworlds
