#pragma once
// Trajectories in the TUM RGB-D benchmark's text format, which evo and the TUM scripts read:
// one pose a line, "timestamp tx ty tz qx qy qz qw" (seconds, metres, unit quaternion of
// T_world_body), '#' lines are comments (Sturm et al., IROS 2012; vision.in.tum.de file formats).
//
// Time stamps are written as seconds with 9 decimals, printed from the integer nanoseconds, and
// read back exactly from their decimal digits, so a stamp survives a round trip unchanged and
// matches the bag's message stamps for association. Positions are written with 6 decimals (1 µm)
// and quaternion components with 9.

#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "core/stamped_pose.hpp"
#include "core/time.hpp"

namespace littermap::bag {

// Reads a TUM trajectory. Throws BadInputError "FILE:LINE: ..." naming the field for a malformed
// line, a quaternion whose norm is not 1 within 1 %, or a file that cannot be opened.
// Quaternions are normalised on reading.
std::vector<StampedPose> ReadTumTrajectory(const std::filesystem::path& path);

// Writes a TUM trajectory with a "# timestamp tx ty tz qx qy qz qw" header line. Throws
// UsageError if the file cannot be created, InternalError if writing fails.
void WriteTumTrajectory(const std::filesystem::path& path, std::span<const StampedPose> poses);

// "1305031102.175304000" from nanoseconds, and back; parsing returns false for a malformed
// number. Exposed for other text formats with TUM-style stamps.
std::string FormatTumStamp(TimestampNs stamp_ns);
bool ParseTumStamp(std::string_view text, TimestampNs* stamp_ns);

}  // namespace littermap::bag
