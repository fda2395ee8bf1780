// Batch: one world's solver state as plain floats (GetSolverState /
// SetSolverState), what its constraints and contact slots carry from one
// step to the next besides the bodies. The layout is listed in
// docs/stepping.md ("Solver state of one world"); reference::World::SolverState writes the
// same values in the same order (reference/solver_state.h), so a test can
// step a reference world from exactly the state a lane steps from.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <span>
#include <stdexcept>
#include <string>

#include "batch/batch_impl.h"
#include "batch/constraint_block.h"
#include "batch/constraint_state.h"
#include "kernels/contact.h"
#include "manyworlds/batch.h"

namespace manyworlds {
namespace {

// A contact slot's values: its friction impulses (t1, t2, angular), then
// kMaxContactPoints times a point's kept flag (1 or 0), its local points on
// body 1 and 2 and its normal impulse. Kept points come first, in slot order,
// then zeros: the batch keeps a point in the slot of the candidate it came
// from, the reference compacts them, and the next setup's matching takes the
// first old point within 1 cm in either order, so the two are the same state.
constexpr std::size_t kContactPointValues = 8;
constexpr std::size_t kContactValues = 3 + kMaxContactPoints * kContactPointValues;

void ReadContactState(const ContactPlan& c, const std::byte* block, std::size_t lane,
                      float* out) {
  const ContactLanes& manifold = At<ContactLanes>(block, c.offset);
  out[0] = manifold.tangent1_lambda[lane];
  out[1] = manifold.tangent2_lambda[lane];
  out[2] = manifold.angular_lambda[lane];
  std::fill(out + 3, out + kContactValues, 0.0f);
  const ContactPointLanes* points = &At<ContactPointLanes>(block, c.points_offset);
  float* kept = out + 3;
  for (std::size_t i = 0; i < c.point_count; ++i) {
    const ContactPointLanes& point = points[i];
    if (point.present[lane] == 0.0f) continue;
    *kept++ = 1.0f;
    for (const Vec3Lanes* local : {&point.local_point1, &point.local_point2}) {
      *kept++ = local->x[lane];
      *kept++ = local->y[lane];
      *kept++ = local->z[lane];
    }
    *kept++ = point.normal_lambda[lane];
  }
}

// Why the slot's values cannot be written, or nullptr.
const char* ContactStateRefusal(const ContactPlan& c, const float* values,
                                std::size_t* bad_value) {
  std::size_t kept = 0;
  for (std::size_t i = 0; i < kContactValues; ++i) {
    *bad_value = i;
    if (!std::isfinite(values[i])) return "is not finite";
  }
  for (std::size_t p = 0; p < kMaxContactPoints; ++p) {
    const float* point = values + 3 + p * kContactPointValues;
    *bad_value = 3 + p * kContactPointValues;
    if (point[0] != 0.0f && point[0] != 1.0f) return "is a point's kept flag: must be 0 or 1";
    if (point[0] == 0.0f) {
      for (std::size_t i = 1; i < kContactPointValues; ++i) {
        *bad_value = 3 + p * kContactPointValues + i;
        if (point[i] != 0.0f) return "belongs to a point not kept: must be 0";
      }
      continue;
    }
    if (kept != p) return "is a point kept after one that is not: kept points come first";
    if (++kept > c.point_count) return "keeps more points than the pair can make";
  }
  return nullptr;
}

void WriteContactState(const ContactPlan& c, std::byte* block, std::size_t lane,
                       const float* values) {
  ContactLanes& manifold = At<ContactLanes>(block, c.offset);
  manifold.tangent1_lambda[lane] = values[0];
  manifold.tangent2_lambda[lane] = values[1];
  manifold.angular_lambda[lane] = values[2];
  ContactPointLanes* points = &At<ContactPointLanes>(block, c.points_offset);
  float any_kept = 0.0f;
  for (std::size_t i = 0; i < c.point_count; ++i) {
    const float* point = values + 3 + i * kContactPointValues;
    ContactPointLanes& lanes = points[i];
    lanes.present[lane] = point[0];
    lanes.local_point1.x[lane] = point[1];
    lanes.local_point1.y[lane] = point[2];
    lanes.local_point1.z[lane] = point[3];
    lanes.local_point2.x[lane] = point[4];
    lanes.local_point2.y[lane] = point[5];
    lanes.local_point2.z[lane] = point[6];
    lanes.normal_lambda[lane] = point[7];
    any_kept = std::max(any_kept, point[0]);
  }
  // The manifold existed where a point was kept (the next setup carries the
  // friction impulses over only then).
  manifold.present[lane] = any_kept;
}

std::size_t ConstraintValueCount(const StepPlan& plan, std::byte* block) {
  std::size_t count = 0;
  for (std::size_t k = 0; k < plan.constraints.size(); ++k) {
    VisitConstraintState(ConstraintInBlock(plan, k, block),
                         [&](LaneArray*, const char*) { ++count; });
  }
  return count;
}

// The visitors above serve reads and writes alike; the reads never write
// through them.
std::byte* Writable(const std::byte* block) { return const_cast<std::byte*>(block); }

}  // namespace

std::size_t Batch::SolverStateSize() const {
  const Impl& batch = impl();
  return ConstraintValueCount(batch.plan_, Writable(batch.Block(0))) +
         batch.plan_.contacts.size() * kContactValues;
}

void Batch::GetSolverState(std::size_t world, std::span<float> out) const {
  const Impl& batch = impl();
  batch.CheckWorld(world);
  batch.CheckSize(out.size(), SolverStateSize(), "GetSolverState");
  const std::size_t lane = Impl::Lane(world);
  std::byte* block = Writable(batch.Block(world / kLaneWidth));
  std::size_t i = 0;
  for (std::size_t k = 0; k < batch.plan_.constraints.size(); ++k) {
    VisitConstraintState(ConstraintInBlock(batch.plan_, k, block),
                         [&](LaneArray* array, const char*) {
                           out[i++] = array != nullptr ? (*array)[lane] : 0.0f;
                         });
  }
  for (const ContactPlan& c : batch.plan_.contacts) {
    ReadContactState(c, block, lane, &out[i]);
    i += kContactValues;
  }
}

void Batch::SetSolverState(std::size_t world, std::span<const float> in) {
  Impl& batch = impl();
  batch.CheckWorld(world);
  batch.CheckSize(in.size(), SolverStateSize(), "SetSolverState");
  const std::size_t lane = Impl::Lane(world);
  std::byte* block = batch.Block(world / kLaneWidth);
  const auto refuse = [&](const std::string& label, const char* what, std::size_t index,
                          const char* why) {
    throw std::invalid_argument("SetSolverState: " + batch.InWorld(label, world) + ": " + what +
                                " (value " + std::to_string(index) + ", " +
                                std::to_string(in[index]) + ") " + why);
  };
  // Every value is checked before any is written.
  std::size_t i = 0;
  for (std::size_t k = 0; k < batch.plan_.constraints.size(); ++k) {
    const std::string& label = batch.plan_.constraints[k].label;
    VisitConstraintState(ConstraintInBlock(batch.plan_, k, block),
                         [&](LaneArray* array, const char* what) {
                           const float value = in[i++];
                           if (!std::isfinite(value)) refuse(label, what, i - 1, "is not finite");
                           if (array == nullptr && value != 0.0f) {
                             refuse(label, what, i - 1, "must be 0: the constraint has no such row");
                           }
                         });
  }
  const std::size_t contacts_start = i;
  for (const ContactPlan& c : batch.plan_.contacts) {
    std::size_t bad = 0;
    if (const char* why = ContactStateRefusal(c, &in[i], &bad)) {
      refuse(c.label, "contact value", i + bad, why);
    }
    i += kContactValues;
  }
  i = 0;
  for (std::size_t k = 0; k < batch.plan_.constraints.size(); ++k) {
    VisitConstraintState(ConstraintInBlock(batch.plan_, k, block),
                         [&](LaneArray* array, const char*) {
                           const float value = in[i++];
                           if (array != nullptr) (*array)[lane] = value;
                         });
  }
  i = contacts_start;
  for (const ContactPlan& c : batch.plan_.contacts) {
    WriteContactState(c, block, lane, &in[i]);
    i += kContactValues;
  }
}

}  // namespace manyworlds
