#pragma once
// Where the tests find their inputs (the sample worlds, the real data sets) and how they read a
// whole file back.

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace littermap::test {

inline const std::filesystem::path kDatasets{LITTERMAP_DATASETS_DIR};

inline std::filesystem::path SampleWorld(const char* name = "park_small.yaml") {
  return std::filesystem::path(LITTERMAP_SOURCE_DIR) / "samples" / "worlds" / name;
}

// The file's bytes; empty when it cannot be read (the assertions on its content then fail).
inline std::string Slurp(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace littermap::test
