// Errors the library raises. Every message names the body, constraint or
// field at fault, so a bad scene can be fixed without a debugger.
#pragma once

#include <stdexcept>
#include <string>

namespace manyworlds {

// A scene (or a binding of parts to bodies) that cannot be simulated; raised
// when it is built, never in the middle of a step.
class SceneError : public std::invalid_argument {
 public:
  explicit SceneError(const std::string& message) : std::invalid_argument(message) {}
};

}  // namespace manyworlds
