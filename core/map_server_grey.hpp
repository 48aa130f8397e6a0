#pragma once
// Grey levels of an occupancy map image in the ROS map_server convention, as littermap writes
// them (map.pgm, the site map): a trinary image of occupied, free and unknown cells.

#include <cstdint>

namespace littermap::map_grey {

constexpr std::uint8_t kOccupied = 0;
constexpr std::uint8_t kFree = 254;
constexpr std::uint8_t kUnknown = 205;

}  // namespace littermap::map_grey
