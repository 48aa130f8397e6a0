#pragma once
// When a run started: the stamp of the first pose of its trajectory, in Unix seconds. What
// orders runs in a site (ingest sets the run's start_time_s from the same pose).

#include <filesystem>

namespace littermap::run {

// Throws BadInputError naming the file when the run directory has no trajectory or an empty
// one.
double RunStartTimeS(const std::filesystem::path& run_dir);

}  // namespace littermap::run
