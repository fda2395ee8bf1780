// `manyworlds run --record FILE [--record-worlds 0,1,7]`: the recording of a
// run (docs/recording.md), kept out of Run() so that its options, checks and
// report line live in one place.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "manyworlds/batch.h"
#include "manyworlds/recording.h"
#include "tools/options.h"

namespace manyworlds::tools {

// The option names, for Options' list of known options.
inline constexpr const char* kRecordOption = "--record";
inline constexpr const char* kRecordWorldsOption = "--record-worlds";

// "0,1,7" as world indices below `world_count`: a UsageError naming the
// value for an empty list or item, a non-number, a world out of range or a
// world given twice.
std::vector<std::size_t> ParseRecordWorlds(const std::string& text, std::size_t world_count);

class RunRecording {
 public:
  // Off without --record (and --record-worlds alone is a UsageError). With
  // it, checks --record-worlds (default "0") and creates the file's
  // temporary (an existing FILE or a folder that refuses it throws
  // std::runtime_error naming FILE), before any step is taken.
  RunRecording(const Options& options, const Batch& batch, const std::string& scene_id,
               double delta_time);

  // A frame after `step` steps (0: before the first); nothing when off.
  void Capture(const Batch& batch, std::uint64_t step);
  // Writes FILE; nothing when off.
  void Close();
  // For the run's report: "off", or the file, worlds and frames.
  std::string Describe() const;

 private:
  std::optional<Recorder> recorder_;
  std::vector<std::size_t> worlds_;
  double delta_time_ = 0.0;
};

}  // namespace manyworlds::tools
