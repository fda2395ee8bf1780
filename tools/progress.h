// The run command's live feedback on a terminal: a progress line on stderr,
// and Ctrl-C (SIGINT) turned into a request to stop at the next step
// boundary (docs/scenes.md, "Running a scene").
#pragma once

#include <chrono>
#include <cstddef>
#include <cstdint>

namespace manyworlds::tools {

// One line on stderr: steps done / total, world-steps/s and the time left,
// redrawn a few times a second once the run has lasted about a second, and
// erased by Erase() (or the destructor). When stderr is not a terminal it
// writes nothing at all and Update() does not even read the clock, so piped
// or redirected output is exactly what it would be without it.
class ProgressLine {
 public:
  // wanted = false: never drawn (the ranks of a sharded run but rank 0).
  ProgressLine(std::uint64_t total_steps, std::size_t worlds, bool wanted = true);
  ~ProgressLine() { Erase(); }
  ProgressLine(const ProgressLine&) = delete;
  ProgressLine& operator=(const ProgressLine&) = delete;

  // After every step: `steps_done` of the total so far.
  void Update(std::uint64_t steps_done) {
    if (enabled_) Draw(steps_done);
  }
  // Removes the line (if it was drawn) so that nothing of it is left on the
  // terminal; idempotent.
  void Erase();

 private:
  using Clock = std::chrono::steady_clock;
  void Draw(std::uint64_t steps_done);

  bool enabled_;
  bool shown_ = false;
  std::uint64_t total_steps_;
  double worlds_;
  Clock::time_point start_;
  Clock::time_point next_draw_;
};

// While alive, SIGINT (or `signal`) only sets a flag (requested()) that the
// run loop checks between steps; the handler is installed with
// SA_RESETHAND, so a second one gets the default action and kills the
// program as usual. The previous action is restored on destruction. One at
// a time. (Under mpirun the signal is SIGUSR1, which OpenMPI's mpirun
// forwards to every rank; Ctrl-C makes mpirun end the job.)
class SigintStop {
 public:
  explicit SigintStop(int signal = 2 /* SIGINT */);
  ~SigintStop();
  SigintStop(const SigintStop&) = delete;
  SigintStop& operator=(const SigintStop&) = delete;

  bool requested() const;

 private:
  int signal_;
};

}  // namespace manyworlds::tools
