#pragma once
// Detection options from a YAML file (core/options_file.hpp: a flat map of key: value, unknown
// keys are errors), e.g.
//   normal_step_px: 1
//   max_size_m: 0.5
//   min_views: 4
// README's `littermap detect` section lists every key with its default and meaning.

#include <filesystem>
#include <string>
#include <vector>

#include "detect/item_fusion.hpp"
#include "detect/run_objects.hpp"

namespace littermap::detect {

// Applies the file's keys to the options of segmentation and sightings (objects) and of their
// fusion into items. Throws BadInputError naming the file and key for an unreadable file, an
// unknown key, a value of the wrong type or options that do not go together.
void ApplyOptionsFile(const std::filesystem::path& path, RunObjectsOptions* objects,
                      FusionOptions* fusion);

// The keys ApplyOptionsFile understands, for help texts and documentation tests.
std::vector<std::string> OptionsFileKeys();

}  // namespace littermap::detect
