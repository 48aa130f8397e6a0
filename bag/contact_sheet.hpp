#pragma once
// A contact sheet of a run bag for a person to look at: one row per sampled RGB-D frame with the
// colour image, the depth image colour-mapped (turbo, near blue to far red, black = no reading)
// and the laser scan nearest before it drawn top-down (laser at the centre, forward up, rings
// every metre, the camera's horizontal field of view as two lines).

#include <filesystem>

#include "bag/bag_reader.hpp"

namespace littermap::bag {

struct ContactSheetOptions {
  int rows = 6;                   // frames, spread evenly over the run (first and last included)
  int tile_width_px = 320;        // each panel; height follows the image aspect ratio
  double depth_max_m = 4.5;       // end of the depth colour map
  double laser_extent_m = 6;      // half-width of the laser panel
  double camera_hfov_deg = 62.7;  // drawn on the laser panel (Kinect: 2 atan(320 / 525))
};

struct ContactSheetResult {
  int rows = 0;
  int width_px = 0;
  int height_px = 0;
};

// Throws BadInputError when the bag has no colour frames, InternalError if the PNG cannot be
// written.
ContactSheetResult WriteContactSheet(const std::filesystem::path& bag,
                                     const std::filesystem::path& png,
                                     const ContactSheetOptions& options = {});

}  // namespace littermap::bag
