// Storage of the dual-axis part (two linear rows) for one block of worlds.
// The maths is in dual_axis-inl.h.
#pragma once

#include "kernels/body_lanes.h"
#include "kernels/kernel_table.h"
#include "manyworlds/lanes.h"

namespace manyworlds {

// Per-step inputs the owning constraint computes before CalculateProperties:
// lever arms (world) and the two unit axes n1 _|_ n2.
struct DualAxisGeometry {
  Vec3Lanes r1_plus_u;  // p2 - x1: body 1's lever arm reaches body 2's anchor
  Vec3Lanes r2;         // p2 - x2
  Vec3Lanes n1, n2;
};

// Everything the part caches between its verbs. Only `persistent` survives
// from one step to the next; the rest is recomputed in CalculateProperties.
struct DualAxisLanes {
  Vec3Lanes r1_plus_u_x_n1, r1_plus_u_x_n2;  // angular Jacobian rows, body 1
  Vec3Lanes r2_x_n1, r2_x_n2;                // angular Jacobian rows, body 2
  Vec3Lanes inv_i1_r1_plus_u_x_n1, inv_i1_r1_plus_u_x_n2;  // zero unless dynamic
  Vec3Lanes inv_i2_r2_x_n1, inv_i2_r2_x_n2;                // zero unless dynamic
  Sym22Lanes effective_mass;  // K^-1; zero when deactivated

  struct Persistent {
    Vec2Lanes total_lambda;  // accumulated impulse per row
  } persistent;
};

// The part's kernels on one target; each call processes one block.
struct DualAxisKernels {
  TargetInfo target;
  void (*calculate_properties)(const BodyPair&, const DualAxisGeometry&, DualAxisLanes&);
  void (*warm_start)(const BodyPair&, const DualAxisGeometry&, DualAxisLanes&,
                     float warm_start_ratio);
  // Solves return true if any lane applied a non-zero impulse / correction.
  bool (*solve_velocity)(const BodyPair&, const DualAxisGeometry&, DualAxisLanes&);
  bool (*solve_position)(const BodyPair&, const DualAxisGeometry&,
                         const Vec3Lanes& separation, const DualAxisLanes&,
                         float baumgarte);
  // The position phase's verb: calculate_properties + solve_position, except
  // that a lane whose C is exactly zero is left exactly as it is.
  bool (*recompute_and_solve_position)(const BodyPair&, const DualAxisGeometry&,
                                       const Vec3Lanes& separation, DualAxisLanes&,
                                       float baumgarte);
  void (*deactivate)(DualAxisLanes&, const LaneFlags& lanes);
  void (*is_active)(const DualAxisLanes&, LaneFlags& active);
};

MANYWORLDS_DECLARE_KERNEL_TABLE(DualAxisKernels)

}  // namespace manyworlds
