#pragma once
// Writes a TUM RGB-D benchmark sequence directory (rgb.txt, depth.txt, rgb/*.png, depth/*.png
// at 5000 units per metre, groundtruth.txt of the optical frame) from the park simulator: the
// camera along the first seconds of a world's route, rendered with the freiburg3 intrinsics so
// `littermap import tum --camera fr3` reads it with the right calibration.

#include <cstddef>
#include <filesystem>

namespace littermap::test {

struct SimTumSequenceOptions {
  double duration_s = 20;
  double rate_hz = 15;
};

// Returns the number of frames written. Throws on a bad world or an unwritable directory.
std::size_t WriteSimTumSequence(const std::filesystem::path& world_yaml,
                                const std::filesystem::path& directory,
                                const SimTumSequenceOptions& options = {});

}  // namespace littermap::test
