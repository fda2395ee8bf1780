// A reference world's solver state as plain numbers: what its constraints and
// contact slots carry from one step to the next besides the bodies (Jolt's
// SaveState / RestoreState, spec 4.4: the accumulated impulses that warm-start
// the next step, and the directions some constraints remember). The order is
// the batch's (Batch::GetSolverState, docs/stepping.md "Solver state of one world"), so a
// test can give a reference world exactly the state a lane steps from.
#pragma once

#include <cstddef>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "reference/math.h"

namespace manyworlds::reference {

// Appends values in order.
template <class T>
class SolverStateWriter {
 public:
  explicit SolverStateWriter(std::vector<T>& out) : out_(out) {}
  void operator()(T value) { out_.push_back(value); }
  void operator()(const Vec2<T>& v) { out_.insert(out_.end(), {v.x(), v.y()}); }
  void operator()(const Vec3<T>& v) { out_.insert(out_.end(), {v.x(), v.y(), v.z()}); }

 private:
  std::vector<T>& out_;
};

// Reads values in the order a SolverStateWriter wrote them.
template <class T>
class SolverStateReader {
 public:
  explicit SolverStateReader(std::span<const T> in) : in_(in) {}
  T Scalar() { return Next(); }
  Vec2<T> Vector2() {
    const T x = Next();
    return Vec2<T>(x, Next());
  }
  Vec3<T> Vector3() {
    const T x = Next();
    const T y = Next();
    return Vec3<T>(x, y, Next());
  }

 private:
  T Next() {
    if (at_ >= in_.size()) {
      throw std::invalid_argument("reference::World::SetSolverState: " +
                                  std::to_string(in_.size()) + " values are too few");
    }
    return in_[at_++];
  }
  std::span<const T> in_;
  std::size_t at_ = 0;
};

}  // namespace manyworlds::reference
