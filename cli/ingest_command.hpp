#pragma once
// What `littermap ingest` and `littermap survey` share: which files of a run directory make up
// the run, and the digest that identifies the run in a site.

#include <filesystem>
#include <string>

namespace littermap::cli {

struct RunDirectoryFiles {
  std::filesystem::path trajectory;  // RUN_DIR/trajectory.tum
  std::filesystem::path items;       // RUN_DIR/items.csv, or a truth directory's litter.csv
  bool simulator_truth = false;      // items is litter.csv
};

// Throws BadInputError naming the directory when it has neither items.csv nor litter.csv.
RunDirectoryFiles FindRunDirectoryFiles(const std::filesystem::path& run_dir);

// The digest a run is stored under: ingesting the same files twice changes nothing.
std::string RunDigest(const RunDirectoryFiles& files);

}  // namespace littermap::cli
