// The run command's progress line and SIGINT stop (tools/progress.h).

#include "tools/progress.h"

#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

namespace manyworlds::tools {
namespace {

// A quiet start: runs shorter than this never show a line, and the first
// rate shown is already averaged over this much.
constexpr std::chrono::milliseconds kFirstDraw{1000};
// A few redraws a second: readable, and negligible next to a step.
constexpr std::chrono::milliseconds kRedraw{250};

// "\r" back to the start of the line, ESC [K erases to its end: the line is
// redrawn in place and leaves nothing behind when erased.
constexpr const char* kEraseLine = "\r\033[K";

// Set by the handler, read between steps. A lock-free atomic is
// async-signal-safe; the handler does nothing else.
std::atomic<bool> sigint_received{false};
static_assert(std::atomic<bool>::is_always_lock_free);

extern "C" void OnSigint(int) { sigint_received.store(true, std::memory_order_relaxed); }

struct sigaction previous_action;
int installed_signal = 0;  // 0: none installed

// The time left as people read it: "42 s", "7 min 05 s", "3 h 20 min".
std::string Duration(double seconds) {
  const auto whole = static_cast<unsigned long long>(std::max(0.0, std::round(seconds)));
  char text[48];
  if (whole < 60) {
    std::snprintf(text, sizeof text, "%llu s", whole);
  } else if (whole < 3600) {
    std::snprintf(text, sizeof text, "%llu min %02llu s", whole / 60, whole % 60);
  } else {
    std::snprintf(text, sizeof text, "%llu h %02llu min", whole / 3600, whole / 60 % 60);
  }
  return text;
}

}  // namespace

ProgressLine::ProgressLine(std::uint64_t total_steps, std::size_t worlds, bool wanted)
    : enabled_(wanted && isatty(STDERR_FILENO) == 1), total_steps_(total_steps), worlds_(double(worlds)) {
  if (!enabled_) return;
  start_ = Clock::now();
  next_draw_ = start_ + kFirstDraw;
}

void ProgressLine::Draw(std::uint64_t steps_done) {
  const Clock::time_point now = Clock::now();
  if (now < next_draw_) return;
  next_draw_ = now + kRedraw;
  const double seconds = std::chrono::duration<double>(now - start_).count();
  const double steps_per_second = double(steps_done) / seconds;
  const double left = steps_per_second > 0
                          ? double(total_steps_ - steps_done) / steps_per_second
                          : 0.0;
  std::fprintf(stderr, "%sstep %llu / %llu (%.0f%%), %.3g world-steps/s, %s left", kEraseLine,
               static_cast<unsigned long long>(steps_done),
               static_cast<unsigned long long>(total_steps_),
               100.0 * double(steps_done) / double(total_steps_),
               steps_per_second * worlds_, Duration(left).c_str());
  std::fflush(stderr);
  shown_ = true;
}

void ProgressLine::Erase() {
  if (!shown_) return;
  std::fputs(kEraseLine, stderr);
  std::fflush(stderr);
  shown_ = false;
}

SigintStop::SigintStop(int signal) : signal_(signal) {
  if (installed_signal != 0) throw std::logic_error("SigintStop: one at a time");
  sigint_received.store(false);
  struct sigaction action = {};
  action.sa_handler = OnSigint;
  sigemptyset(&action.sa_mask);
  // SA_RESETHAND: the first SIGINT puts the default action back, so the
  // second one kills. No SA_RESTART: the loop's only blocking calls are
  // MPI's (a sharded run), which retry after a signal themselves.
  action.sa_flags = SA_RESETHAND;
  sigaction(signal_, &action, &previous_action);
  installed_signal = signal_;
}

SigintStop::~SigintStop() {
  sigaction(signal_, &previous_action, nullptr);
  installed_signal = 0;
}

bool SigintStop::requested() const { return sigint_received.load(std::memory_order_relaxed); }

}  // namespace manyworlds::tools
