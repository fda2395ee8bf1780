// Batch snapshots: every byte of every world's block lanes, its health and
// pending-input notes, and the previous step size, so that a restored world
// continues bit for bit (batch.h, BatchSnapshot).
//
// Layout of the bytes: a Header, then the blocks (block_count * block_bytes),
// then health [world], then pending input notes [world].

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>

#include "batch/batch_impl.h"
#include "manyworlds/batch.h"

namespace manyworlds {
namespace {

// "MWSNAP" and a layout version: bumped whenever what a block holds changes.
constexpr std::uint64_t kMagic = 0x31'30'50'41'4E'53'57'4DULL;  // "MWSNAP01"

struct Header {
  std::uint64_t magic;
  std::uint64_t world_count;
  std::uint64_t block_bytes;
  std::uint64_t scene_fingerprint;
  float previous_substep_dt;
  std::uint32_t padding;
};
static_assert(sizeof(Header) == 40);

// FNV-1a over the scene's initial block: two batches of different scenes
// (or of a scene changed by LimitMassRange) differ in it.
std::uint64_t Fingerprint(const std::vector<LaneArray>& initial) {
  std::uint64_t hash = 14695981039346656037ULL;
  const auto* bytes = reinterpret_cast<const unsigned char*>(initial.data());
  for (std::size_t i = 0; i < initial.size() * sizeof(LaneArray); ++i) {
    hash = (hash ^ bytes[i]) * 1099511628211ULL;
  }
  return hash;
}

std::size_t SnapshotBytes(std::uint64_t world_count, std::uint64_t block_bytes) {
  const std::uint64_t blocks = (world_count + kLaneWidth - 1) / kLaneWidth;
  return sizeof(Header) + blocks * block_bytes + 2 * world_count;
}

Header HeaderOf(std::span<const std::byte> data) {
  Header header;
  std::memcpy(&header, data.data(), sizeof header);
  return header;
}

}  // namespace

std::size_t BatchSnapshot::world_count() const {
  return empty() ? 0 : HeaderOf(data_).world_count;
}

BatchSnapshot BatchSnapshot::FromBytes(std::span<const std::byte> bytes) {
  if (bytes.size() < sizeof(Header)) {
    throw std::invalid_argument("BatchSnapshot::FromBytes: " + std::to_string(bytes.size()) +
                                " bytes is shorter than a snapshot's header");
  }
  const Header header = HeaderOf(bytes);
  if (header.magic != kMagic) {
    throw std::invalid_argument(
        "BatchSnapshot::FromBytes: not a manyworlds snapshot of this version (bad magic)");
  }
  if (header.world_count == 0 || header.block_bytes % sizeof(LaneArray) != 0 ||
      header.world_count > (1ULL << 40) || header.block_bytes > (1ULL << 40) ||
      bytes.size() != SnapshotBytes(header.world_count, header.block_bytes)) {
    throw std::invalid_argument("BatchSnapshot::FromBytes: " + std::to_string(bytes.size()) +
                                " bytes do not match the sizes in the header");
  }
  BatchSnapshot snapshot;
  snapshot.data_.assign(bytes.begin(), bytes.end());
  return snapshot;
}

BatchSnapshot Batch::Snapshot() const {
  const Impl& batch = impl();
  const Impl::Exclusive exclusive(batch, "Snapshot");
  const Header header{kMagic,
                      batch.world_count_,
                      batch.plan_.block_bytes,
                      Fingerprint(batch.initial_),
                      batch.previous_substep_dt_,
                      0};
  BatchSnapshot snapshot;
  snapshot.data_.resize(SnapshotBytes(batch.world_count_, batch.plan_.block_bytes));
  std::byte* out = snapshot.data_.data();
  std::memcpy(out, &header, sizeof header);
  out += sizeof header;
  const std::size_t block_bytes = batch.storage_.size() * sizeof(LaneArray);
  std::memcpy(out, batch.storage_.data(), block_bytes);
  out += block_bytes;
  std::memcpy(out, batch.health_.data(), batch.world_count_);
  std::memcpy(out + batch.world_count_, batch.pending_input_.data(), batch.world_count_);
  return snapshot;
}

void Batch::Restore(const BatchSnapshot& snapshot, std::span<const std::uint8_t> world_mask) {
  Impl& batch = impl();
  const Impl::Exclusive exclusive(batch, "Restore");
  if (snapshot.empty()) throw std::invalid_argument("Restore: the snapshot is empty");
  const Header header = HeaderOf(snapshot.data_);
  const auto refuse = [](const std::string& what, std::uint64_t got, std::uint64_t want) {
    throw std::invalid_argument("Restore: the snapshot's " + what + " is " +
                                std::to_string(got) + ", this batch's " + std::to_string(want) +
                                " (nothing was restored)");
  };
  if (header.world_count != batch.world_count_) {
    refuse("world count", header.world_count, batch.world_count_);
  }
  if (header.block_bytes != batch.plan_.block_bytes) {
    refuse("block size in bytes", header.block_bytes, batch.plan_.block_bytes);
  }
  if (header.scene_fingerprint != Fingerprint(batch.initial_)) {
    throw std::invalid_argument(
        "Restore: the snapshot was taken of another scene (its initial state differs; "
        "nothing was restored)");
  }
  if (!world_mask.empty()) batch.CheckSize(world_mask.size(), batch.world_count_, "Restore mask");

  // The blocks follow the 40-byte header, so they are not LaneArray-aligned
  // in the snapshot's bytes: copied with memcpy, never read as LaneArrays.
  const std::byte* blocks = snapshot.data_.data() + sizeof(Header);
  const std::uint8_t* health = reinterpret_cast<const std::uint8_t*>(
      blocks + batch.storage_.size() * sizeof(LaneArray));
  const std::uint8_t* pending = health + batch.world_count_;
  if (world_mask.empty()) {
    std::memcpy(batch.storage_.data(), blocks, batch.storage_.size() * sizeof(LaneArray));
    std::copy_n(health, batch.world_count_, batch.health_.begin());
    std::copy_n(pending, batch.world_count_, batch.pending_input_.begin());
    batch.previous_substep_dt_ = header.previous_substep_dt;
    return;
  }
  for (std::size_t world = 0; world < batch.world_count_; ++world) {
    if (world_mask[world] == 0) continue;
    const std::size_t first = (world / kLaneWidth) * batch.arrays_per_block_;
    const std::size_t l = Impl::Lane(world);
    for (std::size_t i = first; i < first + batch.arrays_per_block_; ++i) {
      std::memcpy(&batch.storage_[i][l], blocks + i * sizeof(LaneArray) + l * sizeof(float),
                  sizeof(float));
    }
    batch.health_[world] = health[world];
    batch.pending_input_[world] = pending[world];
  }
}

}  // namespace manyworlds
