#pragma once
// SCIP 2.0, the line protocol of Hokuyo URG/UTM laser scanners ("Communication Protocol
// Specification for SCIP2.0 Standard", Hokuyo C-42-03320B): pure functions, no I/O.
//
// A reply is LF-terminated lines ending in an empty line: the command echo, a status line, then
// data lines. Every line after the echo ends in a one-character sum: (sum of the preceding bytes
// & 0x3F) + 0x30 (§7). Data lines carry at most 64 data characters before the sum. Numbers are
// encoded 6 bits a character, each character being value + 0x30 (§6: "CB" = 1234, "1Dh" = 5432,
// "m2@0" = 16,000,000).
//
// Status lines (§7, §8): "00" is success, "99" marks a scan frame of MD/MS, anything else is an
// error code. Real devices also send:
//   "0"    a SCIP 1.1 device answering "SCIP2.0": it switched, 1.1 status lines have no sum;
//   "00"   without its sum (tolerated for every command);
//   "0E"   ("0Ee") to "SCIP2.0" from a device already in SCIP 2.0 mode, where "SCIP2.0" is an
//          undefined command (error 0E, §9) — success for that command only.
// Which codes mean success for which command: ScipStatusAccepted().

#include <cstddef>
#include <cstdint>
#include <map>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "core/laser_scan.hpp"
#include "core/time.hpp"

namespace littermap::capture {

inline constexpr std::size_t kScipMaxDataCharsPerLine = 64;

// The SCIP sum character of `bytes`.
char ScipChecksum(std::string_view bytes);

// Decodes 1..4 SCIP characters (6 bits each, most significant first). Throws BadInputError when
// a character is outside 0x30..0x6F.
std::uint32_t ScipDecode(std::string_view chars);

// Encodes `value` in `width` characters (the inverse of ScipDecode; used by emulators and tests).
std::string ScipEncode(std::uint32_t value, std::size_t width);

// `line` followed by its sum character.
std::string WithScipChecksum(std::string_view line);

// Splits one reply (up to and including its terminating empty line) into its lines, without the
// LFs and the final empty line. Throws BadInputError (naming `context`) when the text does not end
// in "\n\n".
std::vector<std::string> SplitScipReply(std::string_view reply, const std::string& context);

// The data characters of a data line (its text without the sum), after checking the sum and the
// length. Throws BadInputError quoting the line and naming `context`.
std::string_view ScipLineData(std::string_view line, const std::string& context);

struct ScipStatus {
  std::string code;           // "00", "99", "0E", "0" (SCIP 1.1), ...
  bool has_checksum = false;  // false for "0" and a bare "00"
};

// Parses and checks a status line. Throws BadInputError quoting it.
ScipStatus ParseScipStatus(std::string_view line, const std::string& context);

// Whether `status` means success for `command` ("SCIP2.0", "MD", "PP", ...; see the file comment).
bool ScipStatusAccepted(std::string_view command, std::string_view status);

// A reply split into echo, status and body (data lines, still with their sums).
struct ScipReply {
  std::string echo;
  ScipStatus status;
  std::vector<std::string> body;
};

// Splits the lines of one reply. Throws BadInputError when the echo does not start with
// `expected_echo_prefix`, or the status line is malformed.
ScipReply ParseScipReply(std::span<const std::string> lines, std::string_view expected_echo_prefix,
                         const std::string& context);

// PP (§8.12): the sensor's geometry. Steps are indices of measurement directions.
struct ScipSensorParameters {
  std::string model;             // MODL
  int min_distance_mm = 0;       // DMIN: readings below are error codes
  int max_distance_mm = 0;       // DMAX
  int steps_per_revolution = 0;  // ARES
  int first_step = 0;            // AMIN
  int last_step = 0;             // AMAX
  int front_step = 0;            // AFRT: the step along the laser's x axis
  int motor_speed_rpm = 0;       // SCAN

  double AngleOfStepRad(double step) const;
  double scan_period_s() const { return motor_speed_rpm > 0 ? 60.0 / motor_speed_rpm : 0.0; }
};

// Parses the body of a PP reply ("KEY:VALUE;S" lines). The sum of these lines covers the text
// before ';' in the specification and on UTM-30LX; some firmwares include the ';' — both are
// accepted. Throws BadInputError naming the line or the missing key.
ScipSensorParameters ParseScipParameters(std::span<const std::string> body,
                                         const std::string& context);

// Parses the body of a VV (or II) reply into key → value (VEND, PROD, FIRM, PROT, SERI).
std::map<std::string, std::string> ParseScipInfo(std::span<const std::string> body,
                                                 const std::string& context);

// One measurement frame of MD/MS/GD/GS.
struct ScipScanData {
  std::uint32_t timestamp_ms = 0;  // the sensor's 24-bit millisecond clock
  std::vector<std::uint32_t> ranges_mm;
};

// Decodes the body of a scan frame: the time stamp line (4 characters + sum), then data lines
// with `chars_per_range` characters a reading (3 for MD/GD, 2 for MS/GS). Throws BadInputError.
ScipScanData DecodeScipScanData(std::span<const std::string> body, std::size_t chars_per_range,
                                const std::string& context);

// The MD/GD range request a client sends; echoes of scan frames repeat it.
struct ScipRangeRequest {
  int first_step = 0;
  int last_step = 0;
  int cluster_count = 1;  // adjacent steps merged into one reading (1 = none)

  std::size_t reading_count() const;
};

// "MD" + start(4) + end(4) + cluster(2) + interval(1) + scans(2), without LF.
std::string ScipMdCommand(const ScipRangeRequest& request, int scan_interval, int scan_count);

// A decoded frame as a LaserScan in the laser's frame: beam k is the cluster of steps
// first_step + k·cluster .. + cluster − 1, at the angle of its centre, (step − AFRT)·2π/ARES
// (counter-clockwise, AFRT along x). Readings below DMIN are error codes and become +infinity
// ("no echo", REP 117, as everywhere in littermap); the others are converted to metres.
LaserScan ScipToLaserScan(const ScipSensorParameters& sensor, const ScipRangeRequest& request,
                          std::span<const std::uint32_t> ranges_mm, TimestampNs stamp_ns);

}  // namespace littermap::capture
