#include "run/run_digest.hpp"

#include <cstdint>
#include <cstdio>
#include <fstream>

#include "core/error.hpp"
#include "run/run_files.hpp"

namespace littermap::run {

RunDirectoryFiles FindRunDirectoryFiles(const std::filesystem::path& run_dir) {
  const RunFiles run(run_dir);
  RunDirectoryFiles files{run.trajectory(), run.items(), false};
  if (!std::filesystem::exists(files.items) && std::filesystem::exists(run_dir / "litter.csv")) {
    files.items = run_dir / "litter.csv";
    files.simulator_truth = true;
  }
  if (!std::filesystem::exists(files.items)) {
    throw BadInputError(run_dir.string() + ": no items.csv (run 'littermap detect' first)");
  }
  return files;
}

std::string RunDigest(const RunDirectoryFiles& files) {
  const std::filesystem::path digested[] = {files.trajectory, files.items};
  return DigestFiles(digested);
}

std::string DigestFiles(std::span<const std::filesystem::path> files) {
  std::uint64_t hash = 1469598103934665603ull;  // FNV-1a 64 offset basis
  for (const auto& file : files) {
    std::ifstream in(file, std::ios::binary);
    if (!in) throw BadInputError(file.string() + ": cannot open");
    char buffer[65536];
    while (in.read(buffer, sizeof(buffer)) || in.gcount() > 0) {
      for (std::streamsize i = 0; i < in.gcount(); ++i) {
        hash ^= static_cast<unsigned char>(buffer[i]);
        hash *= 1099511628211ull;  // FNV prime
      }
    }
    hash ^= 0xff;  // file separator
    hash *= 1099511628211ull;
  }
  char text[17];
  std::snprintf(text, sizeof(text), "%016llx", static_cast<unsigned long long>(hash));
  return text;
}

}  // namespace littermap::run
