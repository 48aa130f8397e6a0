#pragma once
// A TUM RGB-D sequence directory (Sturm et al., IROS 2012): rgb.txt and depth.txt list the
// frames as "timestamp filename" lines ('#' comments), filenames relative to the directory
// (rgb/*.png, depth/*.png); groundtruth.txt, when present, holds the camera poses in TUM
// trajectory format. Colour and depth frames are taken at slightly different times and are
// paired the way the benchmark's associate.py does it.

#include <cstdint>
#include <filesystem>
#include <vector>

#include "core/time.hpp"

namespace littermap::importers {

struct TumFrameEntry {
  TimestampNs stamp_ns = 0;
  std::filesystem::path file;  // as listed, relative to the sequence directory
};

// Reads rgb.txt / depth.txt. Throws BadInputError "FILE:LINE: ..." for a malformed line and
// "FILE: cannot open file" when missing. Entries come sorted by time.
std::vector<TumFrameEntry> ReadTumFrameList(const std::filesystem::path& path);

struct TumFramePair {
  std::size_t colour_index = 0;  // into the colour list
  std::size_t depth_index = 0;   // into the depth list
};

// associate.py: among all (colour, depth) pairs closer than max_gap_s, repeatedly take the
// closest pair whose frames are both still unused. Pairs come sorted by colour time.
std::vector<TumFramePair> AssociateTumFrames(const std::vector<TumFrameEntry>& colour,
                                             const std::vector<TumFrameEntry>& depth,
                                             double max_gap_s = 0.02);

}  // namespace littermap::importers
