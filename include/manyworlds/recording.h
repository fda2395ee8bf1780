// Recording: chosen worlds' body poses, joint coordinates and health, one
// frame per Capture, streamed into an NPZ file that numpy.load reads without
// manyworlds, after the scene's description (bodies with their mass
// properties and collision shapes, constraints; docs/recording.md has the
// arrays; viewer/ plays it in 3D).
//
//   Batch batch(scene, 4096);
//   Recorder recorder(batch, "run.npz", {0, 1, 7}, {.scene = "ragdoll"});
//   recorder.Capture(batch, 0.0, 0);            // frame 0: before the first step
//   for (std::int64_t step = 1; step <= 600; ++step) {
//     batch.Step(settings);
//     recorder.Capture(batch, step * settings.delta_time, step);
//   }
//   recorder.Close();                           // now run.npz exists, whole
//
// Frames are appended to temporary files, so a long recording does not sit in
// memory; Close assembles the ZIP (ZIP64 where a member or the file passes
// 4 GiB) under a temporary name next to the file and renames it. A Recorder
// destroyed without Close, or any error, leaves no file behind.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <string>

#include "manyworlds/batch.h"

namespace manyworlds {

inline constexpr std::int32_t kRecordingFormatVersion = 1;

struct RecorderOptions {
  std::string scene;       // the scene's id or name, stored as `scene`
  bool overwrite = false;  // an existing file is refused unless set
  // Test hook: write ZIP64 records for every member even when small.
  bool force_zip64 = false;
};

class Recorder {
 public:
  // Records `worlds` (indices into `batch`, each once, at least one) of
  // batch's scene to `path`. Throws std::invalid_argument naming a bad world
  // index (out of range, repeated) or an empty list, and std::runtime_error
  // naming `path` when it exists (and !overwrite) or its folder refuses a
  // new file; nothing is written then.
  Recorder(const Batch& batch, const std::string& path, std::span<const std::size_t> worlds,
           const RecorderOptions& options = {});
  ~Recorder();
  Recorder(Recorder&&) noexcept;
  Recorder& operator=(Recorder&&) noexcept;

  // One frame: the recorded worlds of `batch` as they are now (a batch of
  // the same scene with at least as many worlds), at simulated `time` (s)
  // after `step` steps. Throws std::invalid_argument for another scene's
  // batch; std::runtime_error when the disk refuses (the partial file is
  // removed and the recorder closed).
  void Capture(const Batch& batch, double time, std::int64_t step);

  // Writes the file. Capture and Close throw std::logic_error afterwards.
  void Close();
  // Gives up: removes the partial file now (as destruction does) and closes.
  void Discard();
  bool closed() const;
  std::size_t frame_count() const;
  const std::string& path() const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace manyworlds
