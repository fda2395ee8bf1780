// A streaming writer of NPZ files (what numpy.savez writes: a ZIP of stored,
// uncompressed members "<name>.npy" in NPY format 1.0, little-endian), for
// recordings that must not sit in memory (docs/recording.md).
//
// Arrays known up front are kept in memory; growing arrays (one frame per
// Append) go to unlinked temporary files next to the output, so a crash
// leaves no litter beside the one temporary ZIP. Close writes the ZIP into a
// temporary name next to `path` (NPY shapes now known, CRC-32 computed while
// copying) and renames it over `path`. Destroying an unclosed writer, or
// any error, removes the temporary file: `path` only ever appears whole.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

namespace manyworlds::npz {

// When the ZIP64 extensions are written: only where a size or offset needs
// them (as Python's zipfile), or for every member and the end record (for
// tests of the ZIP64 path without writing 4 GiB).
enum class Zip64 : std::uint8_t { kWhenNeeded, kAlways };

// One NPY header: "{'descr': ..., 'fortran_order': False, 'shape': (...), }"
// padded with spaces to a multiple of 64 bytes, as numpy writes it.
std::string NpyHeader(const std::string& descr, std::span<const std::uint64_t> shape);

// UTF-8 text as numpy's '<U' item of `width` code points: UTF-32LE,
// zero-padded. Throws std::invalid_argument for invalid UTF-8.
std::vector<std::uint32_t> Utf32(const std::string& utf8);

// CRC-32 (ZIP's polynomial 0xEDB88320) of `bytes`, continuing `crc`.
std::uint32_t Crc32(std::span<const std::byte> bytes, std::uint32_t crc = 0);

class StreamingNpzWriter {
 public:
  // Creates the temporary ZIP next to `path` now, so an unwritable folder
  // fails before any work. Throws std::runtime_error naming the path; an
  // existing `path` is refused unless `overwrite`.
  StreamingNpzWriter(std::string path, bool overwrite, Zip64 zip64 = Zip64::kWhenNeeded);
  ~StreamingNpzWriter();
  StreamingNpzWriter(const StreamingNpzWriter&) = delete;
  StreamingNpzWriter& operator=(const StreamingNpzWriter&) = delete;

  // A whole array: `data` holds the product of `shape` items of `descr`
  // (e.g. "<f4", "<U7"), C order. Members appear in the ZIP in the order
  // they were added.
  void AddArray(const std::string& name, const std::string& descr,
                std::vector<std::uint64_t> shape, std::span<const std::byte> data);
  // An array that grows along a first axis by one `frame_shape` per Append;
  // returns its handle for Append.
  std::size_t AddGrowingArray(const std::string& name, const std::string& descr,
                              std::size_t item_bytes, std::vector<std::uint64_t> frame_shape);
  // One frame of a growing array: exactly product(frame_shape) items.
  void Append(std::size_t growing_array, std::span<const std::byte> frame);

  // Writes the ZIP and renames it to `path`. After an exception the
  // temporary file is gone and the writer is closed.
  void Close();
  // Removes the temporary file without writing `path`; the writer is closed.
  void Discard();
  bool closed() const;
  const std::string& path() const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace manyworlds::npz
