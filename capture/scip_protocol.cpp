#include "capture/scip_protocol.hpp"

#include <cstdio>
#include <limits>
#include <numbers>
#include <set>

#include "core/error.hpp"

namespace littermap::capture {

namespace {

[[noreturn]] void Malformed(const std::string& context, const std::string& what,
                            std::string_view line) {
  throw BadInputError(context + ": " + what + " in line \"" + std::string(line) + "\"");
}

int ParseNonNegativeInt(std::string_view text, const std::string& context, std::string_view line) {
  if (text.empty() || text.size() > 9) Malformed(context, "bad number", line);
  int value = 0;
  for (const char c : text) {
    if (c < '0' || c > '9') Malformed(context, "bad number", line);
    value = value * 10 + (c - '0');
  }
  return value;
}

}  // namespace

char ScipChecksum(std::string_view bytes) {
  unsigned sum = 0;
  for (const char c : bytes) sum += static_cast<unsigned char>(c);
  return static_cast<char>((sum & 0x3Fu) + 0x30u);
}

std::uint32_t ScipDecode(std::string_view chars) {
  if (chars.empty() || chars.size() > 4) {
    throw BadInputError("SCIP value of " + std::to_string(chars.size()) + " characters");
  }
  std::uint32_t value = 0;
  for (const char c : chars) {
    if (c < 0x30 || c > 0x6F) {
      throw BadInputError("SCIP value \"" + std::string(chars) +
                          "\" has a character outside 0x30..0x6F");
    }
    value = (value << 6) | static_cast<std::uint32_t>(c - 0x30);
  }
  return value;
}

std::string ScipEncode(std::uint32_t value, std::size_t width) {
  if (width == 0 || width > 4 || (width < 4 && value >= (1u << (6 * width)))) {
    throw UsageError("SCIP value " + std::to_string(value) + " does not fit " +
                     std::to_string(width) + " characters");
  }
  std::string out(width, '0');
  for (std::size_t i = 0; i < width; ++i) {
    out[width - 1 - i] = static_cast<char>(0x30 + ((value >> (6 * i)) & 0x3Fu));
  }
  return out;
}

std::string WithScipChecksum(std::string_view line) {
  std::string out(line);
  out += ScipChecksum(line);
  return out;
}

std::vector<std::string> SplitScipReply(std::string_view reply, const std::string& context) {
  if (reply.size() < 2 || reply.substr(reply.size() - 2) != "\n\n") {
    throw BadInputError(context + ": reply does not end in an empty line");
  }
  std::vector<std::string> lines;
  std::size_t begin = 0;
  const std::size_t end = reply.size() - 1;  // the final LF closes the empty line
  while (begin < end) {
    const std::size_t lf = reply.find('\n', begin);
    lines.emplace_back(reply.substr(begin, lf - begin));
    begin = lf + 1;
  }
  return lines;
}

std::string_view ScipLineData(std::string_view line, const std::string& context) {
  if (line.empty()) Malformed(context, "empty data line", line);
  if (line.size() > kScipMaxDataCharsPerLine + 1) {
    Malformed(context, "data line longer than 64 characters + sum", line);
  }
  const std::string_view data = line.substr(0, line.size() - 1);
  if (ScipChecksum(data) != line.back()) Malformed(context, "checksum error", line);
  return data;
}

ScipStatus ParseScipStatus(std::string_view line, const std::string& context) {
  ScipStatus status;
  if (line.size() == 1 && line[0] == '0') {  // SCIP 1.1 status: no sum
    status.code = "0";
    return status;
  }
  if (line.size() != 2 && line.size() != 3) Malformed(context, "malformed status", line);
  for (std::size_t i = 0; i < 2; ++i) {
    const char c = line[i];
    if (!((c >= '0' && c <= '9') || (c >= 'A' && c <= 'Z'))) {
      Malformed(context, "malformed status", line);
    }
  }
  status.code = std::string(line.substr(0, 2));
  if (line.size() == 2) {
    // Only a bare "00" is tolerated without a sum: an error code must be verifiable.
    if (status.code != "00") Malformed(context, "status without checksum", line);
    return status;
  }
  if (ScipChecksum(status.code) != line[2]) Malformed(context, "checksum error", line);
  status.has_checksum = true;
  return status;
}

bool ScipStatusAccepted(std::string_view command, std::string_view status) {
  if (command == "SCIP2.0") return status == "0" || status == "00" || status == "0E";
  if (command == "MD" || command == "MS") return status == "00" || status == "99";
  if (command == "BM") return status == "00" || status == "02";  // 02: laser already on
  return status == "00";
}

ScipReply ParseScipReply(std::span<const std::string> lines, std::string_view expected_echo_prefix,
                         const std::string& context) {
  if (lines.size() < 2) {
    throw BadInputError(context + ": reply of " + std::to_string(lines.size()) +
                        " lines, expected an echo and a status");
  }
  if (lines[0].substr(0, expected_echo_prefix.size()) != expected_echo_prefix) {
    Malformed(context, "unexpected echo (expected \"" + std::string(expected_echo_prefix) + "\")",
              lines[0]);
  }
  ScipReply reply;
  reply.echo = lines[0];
  reply.status = ParseScipStatus(lines[1], context);
  reply.body.assign(lines.begin() + 2, lines.end());
  return reply;
}

double ScipSensorParameters::AngleOfStepRad(double step) const {
  return (step - front_step) * 2 * std::numbers::pi / steps_per_revolution;
}

namespace {

// "KEY:VALUE;S" with S the sum of "KEY:VALUE" (or of "KEY:VALUE;").
std::pair<std::string, std::string> ParseInfoLine(const std::string& line,
                                                  const std::string& context) {
  // The separator is the second-to-last character: the sum itself may be ';' (sum & 0x3F = 11).
  const std::size_t colon = line.find(':');
  if (line.size() < 3 || line[line.size() - 2] != ';' || colon == std::string::npos ||
      colon >= line.size() - 2) {
    Malformed(context, "malformed parameter", line);
  }
  const std::size_t semicolon = line.size() - 2;
  const std::string_view text(line.data(), semicolon);
  const char sum = line.back();
  if (ScipChecksum(text) != sum &&
      ScipChecksum(std::string_view(line.data(), semicolon + 1)) != sum) {
    Malformed(context, "checksum error", line);
  }
  return {line.substr(0, colon), line.substr(colon + 1, semicolon - colon - 1)};
}

}  // namespace

std::map<std::string, std::string> ParseScipInfo(std::span<const std::string> body,
                                                 const std::string& context) {
  std::map<std::string, std::string> info;
  for (const auto& line : body) info.insert(ParseInfoLine(line, context));
  return info;
}

ScipSensorParameters ParseScipParameters(std::span<const std::string> body,
                                         const std::string& context) {
  ScipSensorParameters p;
  std::set<std::string> seen;
  for (const auto& line : body) {
    auto [key, value] = ParseInfoLine(line, context);
    seen.insert(key);
    if (key == "MODL") {
      p.model = value;
      continue;
    }
    int* field = key == "DMIN"   ? &p.min_distance_mm
                 : key == "DMAX" ? &p.max_distance_mm
                 : key == "ARES" ? &p.steps_per_revolution
                 : key == "AMIN" ? &p.first_step
                 : key == "AMAX" ? &p.last_step
                 : key == "AFRT" ? &p.front_step
                 : key == "SCAN" ? &p.motor_speed_rpm
                                 : nullptr;
    if (field != nullptr) *field = ParseNonNegativeInt(value, context, line);
  }
  for (const char* key : {"DMIN", "DMAX", "ARES", "AMIN", "AMAX", "AFRT", "SCAN"}) {
    if (!seen.contains(key)) throw BadInputError(context + ": PP reply lacks " + key);
  }
  if (p.steps_per_revolution <= 0 || p.first_step > p.last_step ||
      p.last_step >= p.steps_per_revolution || p.min_distance_mm >= p.max_distance_mm ||
      p.motor_speed_rpm <= 0) {
    throw BadInputError(
        context + ": inconsistent PP parameters (ARES " + std::to_string(p.steps_per_revolution) +
        ", AMIN " + std::to_string(p.first_step) + ", AMAX " + std::to_string(p.last_step) +
        ", DMIN " + std::to_string(p.min_distance_mm) + ", DMAX " +
        std::to_string(p.max_distance_mm) + ", SCAN " + std::to_string(p.motor_speed_rpm) + ")");
  }
  return p;
}

ScipScanData DecodeScipScanData(std::span<const std::string> body, std::size_t chars_per_range,
                                const std::string& context) {
  if (chars_per_range != 2 && chars_per_range != 3) {
    throw UsageError("SCIP readings are 2 or 3 characters, not " + std::to_string(chars_per_range));
  }
  if (body.empty()) throw BadInputError(context + ": scan frame without a time stamp");
  ScipScanData scan;
  const std::string_view stamp = ScipLineData(body[0], context);
  if (stamp.size() != 4) Malformed(context, "time stamp is not 4 characters", body[0]);
  try {
    scan.timestamp_ms = ScipDecode(stamp);
  } catch (const BadInputError& e) {
    Malformed(context, e.what(), body[0]);
  }
  std::string data;
  for (std::size_t i = 1; i < body.size(); ++i) {
    // Readings may straddle lines, so join the data first (§8.1).
    data += ScipLineData(body[i], context);
  }
  if (data.size() % chars_per_range != 0) {
    Malformed(context,
              std::to_string(data.size()) + " data characters, not a multiple of " +
                  std::to_string(chars_per_range),
              body.back());
  }
  scan.ranges_mm.reserve(data.size() / chars_per_range);
  for (std::size_t i = 0; i < data.size(); i += chars_per_range) {
    const std::string_view chars = std::string_view(data).substr(i, chars_per_range);
    for (const char c : chars) {
      if (c < 0x30 || c > 0x6F) {
        throw BadInputError(context + ": reading " + std::to_string(i / chars_per_range) + " \"" +
                            std::string(chars) + "\" has a character outside 0x30..0x6F");
      }
    }
    scan.ranges_mm.push_back(ScipDecode(chars));
  }
  return scan;
}

std::size_t ScipRangeRequest::reading_count() const {
  if (cluster_count <= 0 || last_step < first_step) return 0;
  const int steps = last_step - first_step + 1;
  return static_cast<std::size_t>((steps + cluster_count - 1) / cluster_count);
}

std::string ScipMdCommand(const ScipRangeRequest& request, int scan_interval, int scan_count) {
  if (request.first_step < 0 || request.last_step > 9999 ||
      request.first_step > request.last_step || request.cluster_count < 0 ||
      request.cluster_count > 99 || scan_interval < 0 || scan_interval > 9 || scan_count < 0 ||
      scan_count > 99) {
    throw UsageError("SCIP MD parameters out of range");
  }
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "MD%04d%04d%02d%01d%02d", request.first_step,
                request.last_step, request.cluster_count, scan_interval, scan_count);
  return buffer;
}

LaserScan ScipToLaserScan(const ScipSensorParameters& sensor, const ScipRangeRequest& request,
                          std::span<const std::uint32_t> ranges_mm, TimestampNs stamp_ns) {
  const int cluster = std::max(request.cluster_count, 1);
  LaserScan scan;
  scan.stamp_ns = stamp_ns;
  scan.angle_min_rad = sensor.AngleOfStepRad(request.first_step + (cluster - 1) / 2.0);
  scan.angle_increment_rad = cluster * 2 * std::numbers::pi / sensor.steps_per_revolution;
  scan.range_min_m = sensor.min_distance_mm / 1000.0;
  scan.range_max_m = sensor.max_distance_mm / 1000.0;
  scan.scan_time_s = sensor.scan_period_s();
  scan.ranges_m.reserve(ranges_mm.size());
  for (const std::uint32_t mm : ranges_mm) {
    scan.ranges_m.push_back(static_cast<int>(mm) < sensor.min_distance_mm
                                ? std::numeric_limits<float>::infinity()
                                : static_cast<float>(mm / 1000.0));
  }
  return scan;
}

}  // namespace littermap::capture
