#include "bag/tum_trajectory.hpp"

#include <array>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "core/error.hpp"
#include "core/output_file.hpp"
#include "core/text_lines.hpp"

namespace littermap::bag {
namespace {

constexpr TimestampNs kMaxSeconds = 9'000'000'000;  // keeps nanoseconds within int64

bool IsDigit(char c) { return c >= '0' && c <= '9'; }

bool ParseDouble(std::string_view token, double* value) {
  if (token.size() > 1 && token[0] == '+') token.remove_prefix(1);
  const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), *value);
  return error == std::errc() && end == token.data() + token.size() && std::isfinite(*value);
}

// Splits on blanks (and commas, which some TUM-style files use).
std::vector<std::string_view> SplitFields(std::string_view line) {
  std::vector<std::string_view> fields;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == ',')) ++i;
    const std::size_t begin = i;
    while (i < line.size() && line[i] != ' ' && line[i] != '\t' && line[i] != ',') ++i;
    if (i > begin) fields.push_back(line.substr(begin, i - begin));
  }
  return fields;
}

}  // namespace

std::string FormatTumStamp(TimestampNs stamp_ns) {
  const bool negative = stamp_ns < 0;
  const auto magnitude = static_cast<unsigned long long>(negative ? -stamp_ns : stamp_ns);
  char text[48];
  std::snprintf(text, sizeof text, "%s%llu.%09llu", negative ? "-" : "",
                magnitude / 1'000'000'000ULL, magnitude % 1'000'000'000ULL);
  return text;
}

bool ParseTumStamp(std::string_view text, TimestampNs* stamp_ns) {
  if (text.find_first_of("eEnNiI") != std::string_view::npos) {  // exponent, nan or inf
    double seconds = 0;
    if (!ParseDouble(text, &seconds) || std::abs(seconds) > static_cast<double>(kMaxSeconds)) {
      return false;
    }
    *stamp_ns = FromSeconds(seconds);
    return true;
  }
  const bool negative = !text.empty() && text[0] == '-';
  if (!text.empty() && (text[0] == '-' || text[0] == '+')) text.remove_prefix(1);
  const std::size_t dot = text.find('.');
  const std::string_view whole = text.substr(0, dot);
  const std::string_view fraction = dot == std::string_view::npos ? "" : text.substr(dot + 1);
  if (whole.empty() && fraction.empty()) return false;
  TimestampNs seconds = 0;
  for (const char c : whole) {
    if (!IsDigit(c) || seconds > kMaxSeconds) return false;
    seconds = seconds * 10 + (c - '0');
  }
  if (seconds > kMaxSeconds) return false;
  TimestampNs nanoseconds = 0;
  for (std::size_t i = 0; i < fraction.size(); ++i) {
    if (!IsDigit(fraction[i])) return false;
    if (i < 9) nanoseconds = nanoseconds * 10 + (fraction[i] - '0');
    if (i == 9 && fraction[i] >= '5') ++nanoseconds;  // round half up at the 10th digit
  }
  for (std::size_t i = fraction.size(); i < 9; ++i) nanoseconds *= 10;
  const TimestampNs total = seconds * kNanosecondsPerSecond + nanoseconds;
  *stamp_ns = negative ? -total : total;
  return true;
}

namespace {

StampedPose ParseTumLine(const std::vector<std::string_view>& fields) {
  static constexpr std::array<const char*, 8> kNames = {"timestamp", "tx", "ty", "tz",
                                                        "qx",        "qy", "qz", "qw"};
  if (fields.size() != kNames.size()) {
    throw BadInputError("expected 8 fields (timestamp tx ty tz qx qy qz qw), found " +
                        std::to_string(fields.size()));
  }
  StampedPose pose;
  if (!ParseTumStamp(fields[0], &pose.stamp_ns)) {
    throw BadInputError("field 'timestamp': '" + std::string(fields[0]) + "' is not a time");
  }
  std::array<double, 7> values{};
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (!ParseDouble(fields[i + 1], &values[i])) {
      throw BadInputError("field '" + std::string(kNames[i + 1]) + "': '" +
                          std::string(fields[i + 1]) + "' is not a finite number");
    }
  }
  pose.position_m = {values[0], values[1], values[2]};
  pose.orientation = Eigen::Quaterniond(values[6], values[3], values[4], values[5]);
  const double norm = pose.orientation.norm();
  if (std::abs(norm - 1.0) > 0.01) {
    throw BadInputError("quaternion (qx qy qz qw) has norm " + std::to_string(norm) + ", not 1");
  }
  pose.orientation.normalize();
  return pose;
}

}  // namespace

std::vector<StampedPose> ReadTumTrajectory(const std::filesystem::path& path) {
  TextLineReader reader(path);
  std::vector<StampedPose> poses;
  std::string_view line;
  while (reader.Next(&line)) {
    const std::vector<std::string_view> fields = SplitFields(line);
    if (fields.empty() || fields[0][0] == '#') continue;
    try {
      poses.push_back(ParseTumLine(fields));
    } catch (const BadInputError& error) {
      throw BadInputError(path.string() + ":" + std::to_string(reader.line_number()) + ": " +
                          error.what());
    }
  }
  return poses;
}

void WriteTumTrajectory(const std::filesystem::path& path, std::span<const StampedPose> poses) {
  OutputFile file(path);
  file.stream() << "# timestamp tx ty tz qx qy qz qw\n";
  char line[256];
  for (const StampedPose& pose : poses) {
    // "+ 0.0" turns -0 into 0, so that files do not show "-0.000000".
    const Eigen::Vector4d q = pose.orientation.coeffs() + Eigen::Vector4d::Zero();
    std::snprintf(line, sizeof line, "%s %.6f %.6f %.6f %.9f %.9f %.9f %.9f\n",
                  FormatTumStamp(pose.stamp_ns).c_str(), pose.position_m.x() + 0.0,
                  pose.position_m.y() + 0.0, pose.position_m.z() + 0.0, q.x(), q.y(), q.z(), q.w());
    file.stream() << line;
  }
  file.Commit();
}

}  // namespace littermap::bag
