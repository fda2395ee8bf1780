// A user's program against the installed package (tests/package): a
// reference scene stepped with its actions, a refused scene caught as
// SceneError, the SIMD target reported. Exits 1 when anything is off.
#include <cmath>
#include <cstdint>
#include <cstdio>

#include "manyworlds/batch.h"
#include "manyworlds/error.h"
#include "manyworlds/scenes.h"
#include "manyworlds/targets.h"

int main() {
  using namespace manyworlds;
  const std::size_t worlds = 100;  // not a multiple of 16: a padded block
  Batch batch(MakeReferenceScene("cartpole"), worlds);
  const SceneActions actions("cartpole");
  for (std::uint64_t step = 0; step < 60; ++step) {
    actions.Apply(batch, step, /*seed=*/1);
    batch.Step(StepSettings{});
  }
  float worst = 0.0f;
  for (std::size_t world = 0; world < worlds; ++world) {
    worst = std::fmax(worst, batch.MaxConstraintError(world));
  }
  if (batch.UnhealthyWorldCount() != 0 || !(worst < 0.05f)) {
    std::fprintf(stderr, "consumer: %zu unhealthy worlds, constraint error %g\n",
                 batch.UnhealthyWorldCount(), worst);
    return 1;
  }

  // An exception thrown inside the static library is caught by its type here.
  Scene bad;
  BodySettings body;
  body.mass = -1.0f;
  bad.AddBody(body);
  try {
    Batch refused(bad, 1);
    std::fprintf(stderr, "consumer: a body of mass -1 was accepted\n");
    return 1;
  } catch (const SceneError& error) {
    std::printf("consumer: refused as expected: %s\n", error.what());
  }

  std::printf("consumer: cartpole, %zu worlds, 60 steps on %s (%zu lanes; compiled: %zu targets), "
              "max constraint error %.3g\n",
              worlds, batch.SimdTarget(), batch.SimdLanes(), CompiledTargetNames().size(),
              static_cast<double>(worst));
  return 0;
}
