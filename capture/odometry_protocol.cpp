#include "capture/odometry_protocol.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <vector>

#include "core/error.hpp"

namespace littermap::capture {
namespace {

constexpr std::string_view kPrefix = "$ODOM,";
constexpr std::size_t kFieldCount = 6;

unsigned Checksum(std::string_view body) {
  unsigned sum = 0;
  for (const char c : body) sum ^= static_cast<unsigned char>(c);
  return sum;
}

std::string Quote(std::string_view line) {
  constexpr std::size_t kMaxShown = 120;
  return "'" + std::string(line.substr(0, kMaxShown)) + (line.size() > kMaxShown ? "...'" : "'");
}

}  // namespace

std::optional<OdometryReading> ParseOdometryLine(std::string_view line,
                                                 const std::string& context) {
  if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
  if (!line.starts_with(kPrefix)) return std::nullopt;
  const auto fail = [&](const std::string& why) -> BadInputError {
    return BadInputError(context + ": odometry line " + Quote(line) + ": " + why);
  };
  const std::size_t star = line.rfind('*');
  if (star == std::string_view::npos || star + 3 != line.size()) {
    throw fail("no '*HH' checksum at the end");
  }
  unsigned expected = 0;
  const auto [end, error] =
      std::from_chars(line.data() + star + 1, line.data() + line.size(), expected, 16);
  if (error != std::errc() || end != line.data() + line.size()) {
    throw fail("checksum is not two hex digits");
  }
  const std::string_view body = line.substr(1, star - 1);
  if (Checksum(body) != expected) {
    char computed[8];
    std::snprintf(computed, sizeof computed, "%02X", Checksum(body));
    throw fail(std::string("checksum mismatch (computed ") + computed + ")");
  }

  std::vector<std::string_view> fields;
  std::string_view rest = line.substr(kPrefix.size(), star - kPrefix.size());
  for (;;) {
    const std::size_t comma = rest.find(',');
    fields.push_back(rest.substr(0, comma));
    if (comma == std::string_view::npos) break;
    rest.remove_prefix(comma + 1);
  }
  if (fields.size() != kFieldCount) {
    throw fail("expected " + std::to_string(kFieldCount) + " fields, found " +
               std::to_string(fields.size()));
  }
  OdometryReading reading;
  {
    const auto [p, e] =
        std::from_chars(fields[0].data(), fields[0].data() + fields[0].size(), reading.time_ms);
    if (e != std::errc() || p != fields[0].data() + fields[0].size() || fields[0].empty()) {
      throw fail("time_ms is not an unsigned integer");
    }
  }
  static constexpr const char* kNames[] = {"x_m", "y_m", "theta_rad", "v_mps", "omega_radps"};
  double values[5];
  for (std::size_t i = 0; i < 5; ++i) {
    const std::string_view field = fields[i + 1];
    const auto [p, e] = std::from_chars(field.data(), field.data() + field.size(), values[i]);
    if (e != std::errc() || p != field.data() + field.size() || field.empty() ||
        !std::isfinite(values[i])) {
      throw fail(std::string(kNames[i]) + " is not a finite number");
    }
  }
  reading.T_odom_base = {values[0], values[1], values[2]};
  reading.linear_mps = values[3];
  reading.angular_radps = values[4];
  return reading;
}

std::string FormatOdometryLine(const OdometryReading& reading) {
  char body[256];
  std::snprintf(body, sizeof body, "ODOM,%llu,%.4f,%.4f,%.6f,%.4f,%.5f",
                static_cast<unsigned long long>(reading.time_ms), reading.T_odom_base.x_m,
                reading.T_odom_base.y_m, reading.T_odom_base.theta_rad, reading.linear_mps,
                reading.angular_radps);
  char line[300];
  std::snprintf(line, sizeof line, "$%s*%02X", body, Checksum(body));
  return line;
}

}  // namespace littermap::capture
