// Batch: reading the state of every world (GetState, GetField, and the
// fused step's state_out through ReadStateOfBlock), block by block.

#if defined(__SSE2__)
#include <immintrin.h>
#endif

#include <cstddef>
#include <span>

#include "batch/batch_impl.h"
#include "manyworlds/batch.h"

namespace manyworlds {
namespace {

// A body's 13 state columns (StateField order) are 13 consecutive LaneArrays
// of its BodyLanes: a [13][16] float matrix whose transpose is the rows of
// the block's worlds.
static_assert(offsetof(BodyLanes, rotation) == 3 * sizeof(LaneArray) &&
              offsetof(BodyLanes, linear_velocity) == 7 * sizeof(LaneArray) &&
              offsetof(BodyLanes, angular_velocity) == 10 * sizeof(LaneArray));

// out[l * out_stride + c] = columns[c * kLaneWidth + l] for c < kCount and
// l < lanes: moves only, so every bit (NaN payloads included) is copied.
// With SSE2 (every x86-64) 4x4 blocks move as four loads, a transpose by
// shuffles and four stores: GetState of 4096 cartpoles on one thread took
// 56-60 us a float at a time, 40 us this way (bench_step_loop.py breakdown).
template <std::size_t kCount>
void TransposeColumns(const float* columns, std::size_t lanes, float* out,
                      std::size_t out_stride) {
  std::size_t l = 0;
#if defined(__SSE2__)
  for (; l + 4 <= lanes; l += 4) {
    std::size_t c = 0;
    for (; c + 4 <= kCount; c += 4) {
      __m128 r0 = _mm_load_ps(columns + (c + 0) * kLaneWidth + l);
      __m128 r1 = _mm_load_ps(columns + (c + 1) * kLaneWidth + l);
      __m128 r2 = _mm_load_ps(columns + (c + 2) * kLaneWidth + l);
      __m128 r3 = _mm_load_ps(columns + (c + 3) * kLaneWidth + l);
      _MM_TRANSPOSE4_PS(r0, r1, r2, r3);
      _mm_storeu_ps(out + (l + 0) * out_stride + c, r0);
      _mm_storeu_ps(out + (l + 1) * out_stride + c, r1);
      _mm_storeu_ps(out + (l + 2) * out_stride + c, r2);
      _mm_storeu_ps(out + (l + 3) * out_stride + c, r3);
    }
    for (; c < kCount; ++c) {
      for (std::size_t k = 0; k < 4; ++k) {
        out[(l + k) * out_stride + c] = columns[c * kLaneWidth + l + k];
      }
    }
  }
#endif
  for (; l < lanes; ++l) {
    for (std::size_t c = 0; c < kCount; ++c) out[l * out_stride + c] = columns[c * kLaneWidth + l];
  }
}

// Columns [first, first + kCount) of every body's 13-float state row (in
// StateField order), into out[world][body][kCount], for one block's real
// worlds. Reading observations every step is part of an RL loop's cost next
// to Step (python/tests/bench_step_loop.py): world by world and body by
// body, a GetState of 4096 cartpoles took a sixth of their Step (110 us of
// 680); block by block and body by body, 50 us on one thread; transposed
// four by four, less again.
template <std::size_t kCount>
void ReadStateColumnsOfBlock(const Batch::Impl& batch, std::size_t block, std::size_t first,
                             float* out) {
  const std::size_t bodies = batch.plan_.bodies.size();
  const auto [block_first, block_end] = batch.WorldsOf(block);
  for (std::size_t b = 0; b < bodies; ++b) {
    const BodyLanes& body = batch.In<BodyLanes>(block_first, batch.plan_.bodies[b].offset);
    // The body's 13 columns as one float run (the static_assert above): the
    // pointer comes from the whole BodyLanes, not from its first LaneArray's
    // 16 floats, past whose end `first * 16` may point (undefined behaviour
    // that UBSan reports, which the fuzzer found through GetField).
    const float* columns = reinterpret_cast<const float*>(&body) + first * kLaneWidth;
    TransposeColumns<kCount>(columns, block_end - block_first,
                             out + (block_first * bodies + b) * kCount, bodies * kCount);
  }
}

template <std::size_t kCount>
void ReadStateColumns(const Batch::Impl& batch, std::size_t first, float* out) {
  batch.ForEachBlock(
      [&](std::size_t block) { ReadStateColumnsOfBlock<kCount>(batch, block, first, out); });
}

}  // namespace

void Batch::Impl::ReadStateOfBlock(std::size_t block, float* out) const {
  ReadStateColumnsOfBlock<kStateFloatsPerBody>(*this, block, 0, out);
}

void Batch::GetState(std::span<float> out) const {
  const Impl& batch = impl();
  batch.CheckSize(out.size(), batch.world_count_ * batch.plan_.bodies.size() * kStateFloatsPerBody,
                  "GetState");
  ReadStateColumns<kStateFloatsPerBody>(batch, 0, out.data());
}

void Batch::GetWorldState(std::size_t world, std::span<float> out) const {
  const Impl& batch = impl();
  batch.CheckWorld(world);
  const std::size_t bodies = batch.plan_.bodies.size();
  batch.CheckSize(out.size(), bodies * kStateFloatsPerBody, "GetWorldState");
  for (std::size_t b = 0; b < bodies; ++b) batch.ReadState(world, b, &out[b * kStateFloatsPerBody]);
}

void Batch::GetField(StateField field, std::span<float> out) const {
  const Impl& batch = impl();
  const std::size_t size = StateFieldSize(field);
  batch.CheckSize(out.size(), batch.world_count_ * batch.plan_.bodies.size() * size, "GetField");
  if (size == 4) {
    ReadStateColumns<4>(batch, StateFieldOffset(field), out.data());
  } else {
    ReadStateColumns<3>(batch, StateFieldOffset(field), out.data());
  }
}

}  // namespace manyworlds
