// StepSettings::velocity_tolerance: each world of a block stops its velocity
// passes (Gauss-Seidel's, or the exact solve's around its joints from the
// second on) after the first pass that changed no velocity component of its
// dynamic bodies by more than the tolerance,
//
//   converged after pass k  <=>  max over dynamic bodies and components of
//                                |v_k - v_(k-1)| <= tolerance
//
// (m/s and rad/s alike, |v_k - v_(k-1)| rounded to float; v_(k-1) is the
// velocity before the pass). A NaN change never converges: such a world runs
// every pass and the health check flags it.
//
// Every lane of a block runs the same instructions, so a world that has
// converged still runs the block's later passes. What it keeps is what it had
// after its converging pass: that pass copies, for the worlds that converged
// in it, every array a pass may write (its bodies' velocities and every
// accumulated impulse, StepPlan::velocity_pass_arrays) into a snapshot, and
// Finish puts the snapshot back (a pass after which every world has
// converged ends the block's passes, so its worlds need no snapshot). So a
// world's result has the same bits whatever its neighbours need, and the
// block's passes end as soon as every world in it has converged (the padding
// lanes, whose bodies never move, in their first pass). That early end is
// where the time is saved; the checks cost two loads and a store per
// velocity array and chunk each pass, the copies a few per array and chunk in
// the passes where some world converges.

#if defined(MANYWORLDS_BATCH_VELOCITY_CONVERGENCE_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef MANYWORLDS_BATCH_VELOCITY_CONVERGENCE_INL_H_
#undef MANYWORLDS_BATCH_VELOCITY_CONVERGENCE_INL_H_
#else
#define MANYWORLDS_BATCH_VELOCITY_CONVERGENCE_INL_H_
#endif

#include <cstddef>
#include <vector>

#include "batch/constraint_block.h"
#include "batch/plan.h"
#include "hwy/highway.h"
#include "kernels/lane_math-inl.h"

HWY_BEFORE_NAMESPACE();
namespace manyworlds {
namespace HWY_NAMESPACE {

// Per thread, sized for the plan being stepped.
struct VelocityConvergenceScratch {
  std::vector<LaneArray*> arrays;   // the block's pass arrays (plan order)
  std::vector<LaneArray> before;    // the bodies' velocities before the pass
  std::vector<LaneArray> snapshot;  // every pass array, in converged lanes
};

// One block's velocity passes of one substep.
class VelocityConvergence {
 public:
  VelocityConvergence(const StepPlan& plan, std::byte* block, float tolerance,
                      VelocityConvergenceScratch& scratch)
      : velocity_arrays_(plan.body_velocity_arrays),
        tolerance_(tolerance),
        arrays_(scratch.arrays),
        before_(scratch.before),
        snapshot_(scratch.snapshot) {
    arrays_.clear();
    for (const std::size_t offset : plan.velocity_pass_arrays) {
      arrays_.push_back(&At<LaneArray>(block, offset));
    }
    before_.resize(velocity_arrays_);
    snapshot_.resize(arrays_.size());
  }

  void BeforePass() {
    // A world that converged in an earlier pass is about to be changed:
    // Finish must put its snapshot back.
    restore_ = restore_ || any_converged_;
    // Later passes start from what AfterPass left in before_.
    if (!started_) {
      for (std::size_t i = 0; i < velocity_arrays_; ++i) before_[i] = *arrays_[i];
      started_ = true;
    }
  }

  // After a pass: marks the worlds that converged in it and, unless that
  // ends the block's passes (then they keep what they have), keeps their
  // arrays. True once every world of the block has converged.
  bool AfterPass() {
    const LaneVec tolerance = Splat(tolerance_);
    bool all = true, any_new = false;
    ForEachChunk([&](std::size_t offset) {
      LaneVec change = Zero();
      for (std::size_t i = 0; i < velocity_arrays_; ++i) {
        const LaneVec now = Load(*arrays_[i], offset);
        change = hn::Max(change, hn::Abs(hn::Sub(now, Load(before_[i], offset))));
        Store(now, before_[i], offset);
      }
      const LaneMask was = LoadFlags(converged_, offset);
      // Le is false for a NaN change.
      const LaneMask now = hn::Or(was, hn::Le(change, tolerance));
      const LaneMask newly = hn::AndNot(was, now);
      any_new = any_new || AnyLane(newly);
      StoreFlags(newly, newly_, offset);
      StoreFlags(now, converged_, offset);
      all = all && hn::AllTrue(LaneTag(), now);
    });
    any_converged_ = any_converged_ || any_new;
    if (all || !any_new) return all;
    ForEachChunk([&](std::size_t offset) {
      const LaneMask newly = LoadFlags(newly_, offset);
      if (!AnyLane(newly)) return;
      for (std::size_t i = 0; i < arrays_.size(); ++i) {
        Store(hn::IfThenElse(newly, Load(*arrays_[i], offset), Load(snapshot_[i], offset)),
              snapshot_[i], offset);
      }
    });
    return false;
  }

  // After the last pass: every world that converged before it gets back what
  // it had then.
  void Finish() {
    if (!restore_) return;
    ForEachChunk([&](std::size_t offset) {
      // Lanes that converged in the last pass took no snapshot: the newly_
      // mask of that pass leaves them as they are.
      const LaneMask restore =
          hn::AndNot(LoadFlags(newly_, offset), LoadFlags(converged_, offset));
      if (!AnyLane(restore)) return;
      for (std::size_t i = 0; i < arrays_.size(); ++i) {
        Store(hn::IfThenElse(restore, Load(snapshot_[i], offset), Load(*arrays_[i], offset)),
              *arrays_[i], offset);
      }
    });
  }

 private:
  std::size_t velocity_arrays_;
  float tolerance_;
  std::vector<LaneArray*>& arrays_;
  std::vector<LaneArray>& before_;
  std::vector<LaneArray>& snapshot_;
  LaneFlags converged_{};  // the lanes that have converged
  LaneFlags newly_{};      // the lanes that converged in the last pass
  bool started_ = false;
  bool any_converged_ = false;
  bool restore_ = false;
};

}  // namespace HWY_NAMESPACE
}  // namespace manyworlds
HWY_AFTER_NAMESPACE();

#endif  // MANYWORLDS_BATCH_VELOCITY_CONVERGENCE_INL_H_
