#pragma once
// Resuming a chain of stages over a run: a stage that finished leaves a marker file, and is up to
// date while the marker is there, every output exists and is no newer than the marker, and no
// input changed since. A stage cut short leaves no marker, so it is redone.

#include <filesystem>
#include <vector>

namespace littermap::run {

struct StageFiles {
  std::vector<std::filesystem::path> inputs;
  std::vector<std::filesystem::path> outputs;  // empty: the stage always runs
};

bool StageUpToDate(const StageFiles& stage, const std::filesystem::path& marker);

// The regular files directly in `dir` (a bag's files, as a stage's inputs).
std::vector<std::filesystem::path> FilesIn(const std::filesystem::path& dir);

}  // namespace littermap::run
