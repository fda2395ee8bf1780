// What batch/scenes.cc and batch/stress_scenes.cc share about scene ids: the
// one message for an unknown id, which lists every valid id grouped, so that
// MakeScene, SceneStepSettings and SceneDescription all say the same.
#pragma once

#include <string_view>

namespace manyworlds::scene_ids {

// Throws std::invalid_argument "unknown scene 'ID'; valid ids: reference
// scenes a, b, ...; stress scenes c, d, ..." (defined in batch/scenes.cc).
[[noreturn]] void ThrowUnknownScene(std::string_view id);

// What the stress scene `id` tests; "" for an id that is not a stress scene
// (defined in batch/stress_scenes.cc).
std::string_view StressSceneDescription(std::string_view id);
// The same for the contact scenes (defined in batch/contact_scenes.cc).
std::string_view ContactSceneDescription(std::string_view id);

}  // namespace manyworlds::scene_ids
