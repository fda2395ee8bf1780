// Batch: reading the contacts of every world (GetContacts), from the impulses
// the last substep's velocity iterations accumulated in each contact slot.

#include <cstddef>
#include <span>
#include <stdexcept>
#include <string>

#include "batch/batch_impl.h"
#include "batch/constraint_block.h"
#include "kernels/contact.h"
#include "manyworlds/batch.h"

namespace manyworlds {
namespace {

// One world's row of a slot: points kept, normal force, force on body 2, normal.
void ContactOfLane(const ContactPlan& slot, const std::byte* block, std::size_t lane,
                   float substep_dt, float* out) {
  const auto& manifold = At<ContactLanes>(block, slot.offset);
  const ContactPointLanes* points = &At<ContactPointLanes>(block, slot.points_offset);
  for (std::size_t i = 0; i < Batch::kContactFloats; ++i) out[i] = 0.0f;
  if (manifold.present.lanes[lane] == 0.0f || !(substep_dt > 0.0f)) return;
  const auto at = [&](const Vec3Lanes& v) {
    return Float3{v.x.lanes[lane], v.y.lanes[lane], v.z.lanes[lane]};
  };
  const Float3 n = at(manifold.normal), t1 = at(manifold.tangent1), t2 = at(manifold.tangent2);
  float count = 0.0f, normal_impulse = 0.0f;
  for (std::size_t i = 0; i < slot.point_count; ++i) {
    count += points[i].present.lanes[lane];
    normal_impulse += points[i].normal_lambda.lanes[lane];
  }
  const float f1 = manifold.tangent1_lambda.lanes[lane];
  const float f2 = manifold.tangent2_lambda.lanes[lane];
  out[0] = count;
  out[1] = normal_impulse / substep_dt;
  for (int k = 0; k < 3; ++k) {
    out[2 + k] = (normal_impulse * n[k] + f1 * t1[k] + f2 * t2[k]) / substep_dt;
    out[5 + k] = n[k];
  }
}

}  // namespace

std::size_t Batch::ContactSlotCount() const { return impl().plan_.contacts.size(); }

Batch::ContactSlot Batch::GetContactSlot(std::size_t slot) const {
  const auto& contacts = impl().plan_.contacts;
  if (slot >= contacts.size()) {
    throw std::out_of_range("GetContactSlot: slot " + std::to_string(slot) + ", but the scene has " +
                            std::to_string(contacts.size()) + " contact slots");
  }
  return {contacts[slot].body1, contacts[slot].body2, contacts[slot].point_count};
}

void Batch::GetContacts(std::span<float> out) const {
  const Impl& batch = impl();
  const auto& contacts = batch.plan_.contacts;
  const std::size_t per_world = contacts.size() * kContactFloats;
  batch.CheckSize(out.size(), batch.world_count_ * per_world, "GetContacts");
  batch.ForEachBlock([&](std::size_t block) {
    for (auto [world, end] = batch.WorldsOf(block); world < end; ++world) {
      for (std::size_t slot = 0; slot < contacts.size(); ++slot) {
        ContactOfLane(contacts[slot], batch.Block(block), Impl::Lane(world),
                      batch.previous_substep_dt_,
                      out.data() + world * per_world + slot * kContactFloats);
      }
    }
  });
}

}  // namespace manyworlds
