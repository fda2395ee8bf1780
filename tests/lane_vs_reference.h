// Comparing a batch lane with a reference body, shared by the tests that run
// the batch against reference::World step by step (scene_comparison_test.cc,
// allowed_dofs_test.cc, exact_solve_test.cc): deviations in units of
// FLT_EPSILON x max(1, |value|) (rotations: FLT_EPSILON, q and -q the same),
// syncing a reference world to a lane's state (bodies and solver state), and
// kicking every world differently.
#pragma once

#include <algorithm>
#include <array>
#include <cfloat>
#include <cmath>
#include <cstddef>
#include <vector>

#include "manyworlds/batch.h"
#include "reference/world.h"

namespace manyworlds {

struct Deviation {
  double position = 0, rotation = 0, velocity = 0;
  void Max(const Deviation& other) {
    position = std::max(position, other.position);
    rotation = std::max(rotation, other.rotation);
    velocity = std::max(velocity, other.velocity);
  }
};

// |got - want| in FLT_EPSILON x max(1, |want|).
inline double RelativeDeviation(double got, double want) {
  return std::abs(got - want) / (FLT_EPSILON * std::max(1.0, std::abs(want)));
}

// The lane's body state, relative to the reference body, in units of
// FLT_EPSILON * scale (see the top of this file).
template <class T>
Deviation Compare(const float* lane, const reference::Body<T>& body) {
  Deviation d;
  const auto relative = RelativeDeviation;
  for (int i = 0; i < 3; ++i) d.position = std::max(d.position, relative(lane[i], body.position[i]));
  const double q[4] = {double(body.rotation.x()), double(body.rotation.y()),
                       double(body.rotation.z()), double(body.rotation.w())};
  double dot = 0;
  for (int i = 0; i < 4; ++i) dot += q[i] * lane[3 + i];
  const double sign = dot < 0 ? -1.0 : 1.0;  // q and -q are the same rotation
  for (int i = 0; i < 4; ++i) {
    d.rotation = std::max(d.rotation, std::abs(lane[3 + i] - sign * q[i]) / FLT_EPSILON);
  }
  for (int i = 0; i < 3; ++i) {
    d.velocity = std::max(d.velocity, relative(lane[7 + i], body.linear_velocity[i]));
    d.velocity = std::max(d.velocity, relative(lane[10 + i], body.angular_velocity[i]));
  }
  return d;
}

// A reference body's state as the 13 floats of a state array.
template <class T>
std::array<float, kStateFloatsPerBody> FloatStateArray(const reference::Body<T>& body) {
  return {float(body.position.x()),         float(body.position.y()),
          float(body.position.z()),         float(body.rotation.x()),
          float(body.rotation.y()),         float(body.rotation.z()),
          float(body.rotation.w()),         float(body.linear_velocity.x()),
          float(body.linear_velocity.y()),  float(body.linear_velocity.z()),
          float(body.angular_velocity.x()), float(body.angular_velocity.y()),
          float(body.angular_velocity.z())};
}

template <class T>
void SetReferenceState(reference::World<T>& world, const float* lane_bodies) {
  for (std::size_t b = 0; b < world.body_count(); ++b) {
    const float* s = lane_bodies + b * kStateFloatsPerBody;
    reference::Body<T>& body = world.body(b);
    body.position = reference::Vec3<T>(s[0], s[1], s[2]);
    body.rotation = reference::Quat<T>(s[6], s[3], s[4], s[5]);
    body.linear_velocity = reference::Vec3<T>(s[7], s[8], s[9]);
    body.angular_velocity = reference::Vec3<T>(s[10], s[11], s[12]);
  }
}

// A reference world given everything lane `lane_world` of the batch steps
// from: its bodies (lane_bodies, that world's rows of GetState) and its solver
// state (accumulated impulses, hinge turns, remembered directions, the
// contacts' kept points; Batch::GetSolverState). One step of both then
// differs only by that step's rounding: no history the two built apart (a
// warm start, a contact point kept on one side only) carries into it.
template <class T>
void SyncReferenceWorld(reference::World<T>& world, const Batch& batch, std::size_t lane_world,
                        const float* lane_bodies) {
  SetReferenceState(world, lane_bodies);
  std::vector<float> solver_state(batch.SolverStateSize());
  batch.GetSolverState(lane_world, solver_state);
  world.SetSolverState(std::vector<T>(solver_state.begin(), solver_state.end()));
}

// Calls edit(world, body, its kStateFloatsPerBody floats) for every dynamic
// body of every world, then sets the edited state.
template <class Edit>
void EditEveryDynamicBody(Batch& batch, Edit&& edit) {
  const std::size_t per_world = batch.body_count() * kStateFloatsPerBody;
  std::vector<float> state(batch.world_count() * per_world);
  batch.GetState(state);
  for (std::size_t w = 0; w < batch.world_count(); ++w) {
    for (std::size_t b = 0; b < batch.body_count(); ++b) {
      if (batch.scene().bodies()[b].motion_type != MotionType::kDynamic) continue;
      edit(w, b, state.data() + w * per_world + b * kStateFloatsPerBody);
    }
  }
  batch.SetState(state);
}

// Per-world velocity kicks of up to 0.3 m/s and rad/s on every dynamic body,
// so that the worlds of a block differ and every per-lane decision (limit
// sides, slack or taut, deactivations, recomputes where an error is
// non-zero, Newton steps of the exact solve) is taken differently across the
// lanes of one vector.
inline void KickEveryWorldDifferently(Batch& batch) {
  EditEveryDynamicBody(batch, [](std::size_t w, std::size_t b, float* body) {
    for (int i = 7; i < 13; ++i) body[i] += 0.3f * std::sin(float(w * 13 + b * 7 + std::size_t(i)));
  });
}

}  // namespace manyworlds
