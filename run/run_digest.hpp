#pragma once
// What identifies a run in a site: the digest of the files that make it up. Ingesting the same
// files twice changes nothing; other files under the same name are another run.

#include <filesystem>
#include <span>
#include <string>

namespace littermap::run {

// The files of a run directory that a site stores: the trajectory and the items, which are
// RUN_DIR/items.csv from `detect` or, in a simulator truth directory, litter.csv.
struct RunDirectoryFiles {
  std::filesystem::path trajectory;
  std::filesystem::path items;
  bool simulator_truth = false;  // items is litter.csv
};

// Throws BadInputError naming the directory when it has neither items.csv nor litter.csv.
RunDirectoryFiles FindRunDirectoryFiles(const std::filesystem::path& run_dir);

// The digest a run is stored under.
std::string RunDigest(const RunDirectoryFiles& files);

// A hex FNV-1a 64 digest of the files' bytes, in order. Throws BadInputError for a file that
// cannot be opened.
std::string DigestFiles(std::span<const std::filesystem::path> files);

}  // namespace littermap::run
