#pragma once
// Reconstruction options from a YAML file (DESIGN.md: options are YAML files parsed into plain
// option structs; unknown keys are errors). A flat map of the tunable values, e.g.
//   key_frame_translation_m: 0.5
//   loop_min_matching_ratio: 0.6

#include <filesystem>
#include <string>
#include <vector>

#include "reconstruct/reconstruction.hpp"

namespace littermap::reconstruct {

// Applies the file's keys to options. Throws BadInputError naming the file and key for an
// unknown key or a value of the wrong type, UsageError if the file cannot be read.
void ApplyOptionsFile(const std::filesystem::path& path, ReconstructionOptions* options);

// The keys ApplyOptionsFile understands, for help texts.
std::vector<std::string> OptionsFileKeys();

}  // namespace littermap::reconstruct
