#include "run/stage_marker.hpp"

#include <algorithm>

namespace littermap::run {

namespace fs = std::filesystem;

bool StageUpToDate(const StageFiles& stage, const fs::path& marker) {
  if (stage.outputs.empty() || !fs::exists(marker)) return false;
  const auto finished = fs::last_write_time(marker);
  for (const fs::path& output : stage.outputs) {
    if (!fs::exists(output) || fs::last_write_time(output) > finished) return false;
  }
  return std::all_of(stage.inputs.begin(), stage.inputs.end(), [&](const fs::path& input) {
    return fs::exists(input) && fs::last_write_time(input) <= finished;
  });
}

std::vector<fs::path> FilesIn(const fs::path& dir) {
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(dir)) {
    if (entry.is_regular_file()) files.push_back(entry.path());
  }
  return files;
}

}  // namespace littermap::run
