#include "tools/record_option.h"

#include <charconv>
#include <stdexcept>

namespace manyworlds::tools {

std::vector<std::size_t> ParseRecordWorlds(const std::string& text, std::size_t world_count) {
  const std::string option = std::string(kRecordWorldsOption) + " = '" + text + "'";
  std::vector<std::size_t> worlds;
  std::size_t start = 0;
  while (true) {
    const std::size_t end = std::min(text.find(',', start), text.size());
    const std::string item = text.substr(start, end - start);
    std::size_t world = 0;
    const auto [parsed_end, error] = std::from_chars(item.data(), item.data() + item.size(), world);
    if (item.empty() || error != std::errc() || parsed_end != item.data() + item.size()) {
      throw UsageError(option + ": '" + item + "' is not a world index (a list like 0,1,7)");
    }
    if (world >= world_count) {
      throw UsageError(option + ": world " + item + " out of range [0, " +
                       std::to_string(world_count) + ") (--worlds)");
    }
    for (const std::size_t earlier : worlds) {
      if (earlier == world) throw UsageError(option + ": world " + item + " given twice");
    }
    worlds.push_back(world);
    if (end == text.size()) break;
    start = end + 1;
  }
  return worlds;
}

RunRecording::RunRecording(const Options& options, const Batch& batch,
                           const std::string& scene_id, double delta_time)
    : delta_time_(delta_time) {
  if (!options.Has(kRecordOption)) {
    if (options.Has(kRecordWorldsOption)) {
      throw UsageError(std::string(kRecordWorldsOption) + " needs " + kRecordOption + " FILE");
    }
    return;
  }
  worlds_ = ParseRecordWorlds(options.Text(kRecordWorldsOption, "0"), batch.world_count());
  const std::string path = options.Text(kRecordOption);
  try {
    recorder_.emplace(batch, path, worlds_, RecorderOptions{.scene = scene_id});
  } catch (const std::runtime_error& e) {
    throw std::runtime_error(std::string(kRecordOption) + ": " + e.what());
  }
}

void RunRecording::Capture(const Batch& batch, std::uint64_t step) {
  if (recorder_) recorder_->Capture(batch, double(step) * delta_time_, std::int64_t(step));
}

void RunRecording::Close() {
  if (recorder_) recorder_->Close();
}

std::string RunRecording::Describe() const {
  if (!recorder_) return "off";
  std::string worlds;
  for (const std::size_t w : worlds_) {
    if (!worlds.empty()) worlds += ',';
    worlds += std::to_string(w);
  }
  return recorder_->path() + ", worlds " + worlds + ", " +
         std::to_string(recorder_->frame_count()) +
         " frames (captured every step, inside the timed loop)";
}

}  // namespace manyworlds::tools
