// The initial block of a scene: every world of the block holds the scene's
// initial state and parameters. World-space settings are converted once to
// body space (anchors, axes, the rest orientation r0^-1 of Fixed, Hinge and
// Slider), hinge and slider targets are clamped into their limits (spec 3).
// Batches start from copies of it and Reset copies a world's lanes back.
#pragma once

#include <cstddef>

#include "batch/plan.h"
#include "manyworlds/scene.h"

namespace manyworlds {

// `block` holds plan.block_bytes bytes, 64-byte aligned, zeroed.
void WriteInitialBlock(const Scene& scene, const StepPlan& plan, std::byte* block);

// A body's inverse mass and inverse principal inertia as a block holds them
// for the given mass properties (Jolt's SetMassProperties): 0 for a
// non-dynamic body, and without any allowed translation (rotation). Shared by
// the scene and Batch::SetMassProperties, so that one mass gives the same
// bits either way.
struct InverseMassProperties {
  float inv_mass;
  Float3 inv_inertia_diagonal;
};
InverseMassProperties InverseMassPropertiesOf(const BodySettings& body, float mass,
                                              const Float3& inertia_diagonal);

}  // namespace manyworlds
