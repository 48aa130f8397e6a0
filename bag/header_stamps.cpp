#include "bag/header_stamps.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

#include "core/error.hpp"

namespace littermap::bag {
namespace {

constexpr std::size_t kStampOffset = 4;  // after the CDR encapsulation header
constexpr TimestampNs kToleranceNs = kNanosecondsPerSecond;

bool HasLeadingHeader(const std::string& type) {
  static const std::array<const char*, 7> kTypes = {
      "sensor_msgs/msg/LaserScan",       "nav_msgs/msg/Odometry",      "sensor_msgs/msg/Image",
      "sensor_msgs/msg/CompressedImage", "sensor_msgs/msg/CameraInfo", "sensor_msgs/msg/Imu",
      "sensor_msgs/msg/NavSatFix"};
  return std::find(kTypes.begin(), kTypes.end(), type) != kTypes.end();
}

bool BigEndian(std::span<const std::uint8_t> serialized) {
  return serialized[1] == 0x00 || serialized[1] == 0x02;  // CDR_BE, PL_CDR_BE
}

std::uint32_t Read32(std::span<const std::uint8_t> bytes, std::size_t at, bool big) {
  std::uint32_t value = 0;
  for (int i = 0; i < 4; ++i) {
    value |= std::uint32_t{bytes[at + (big ? 3 - i : i)]} << (8 * i);
  }
  return value;
}

void Write32(std::vector<std::uint8_t>& bytes, std::size_t at, std::uint32_t value, bool big) {
  for (int i = 0; i < 4; ++i) {
    bytes[at + (big ? 3 - i : i)] = static_cast<std::uint8_t>(value >> (8 * i));
  }
}

}  // namespace

StampSource ParseStampSource(const std::string& name) {
  if (name == "header") return StampSource::kHeader;
  if (name == "recorded") return StampSource::kRecorded;
  throw UsageError("--stamps " + name + ": expected header or recorded");
}

std::optional<TimestampNs> HeaderStamp(const std::string& type,
                                       std::span<const std::uint8_t> serialized) {
  if (!HasLeadingHeader(type) || serialized.size() < kStampOffset + 8) return std::nullopt;
  const bool big = BigEndian(serialized);
  const auto sec = static_cast<std::int32_t>(Read32(serialized, kStampOffset, big));
  const std::uint32_t nanosec = Read32(serialized, kStampOffset + 4, big);
  return TimestampNs{sec} * kNanosecondsPerSecond + TimestampNs{nanosec};
}

bool SetHeaderStamp(const std::string& type, std::vector<std::uint8_t>& serialized,
                    TimestampNs stamp_ns) {
  if (!HeaderStamp(type, serialized)) return false;
  const bool big = BigEndian(serialized);
  TimestampNs sec = stamp_ns / kNanosecondsPerSecond;
  TimestampNs nanosec = stamp_ns % kNanosecondsPerSecond;
  if (nanosec < 0) --sec, nanosec += kNanosecondsPerSecond;
  Write32(serialized, kStampOffset, static_cast<std::uint32_t>(static_cast<std::int32_t>(sec)),
          big);
  Write32(serialized, kStampOffset + 4, static_cast<std::uint32_t>(nanosec), big);
  return true;
}

std::string StampAgreement::Observe(const std::string& topic, TimestampNs header_ns,
                                    TimestampNs recorded_ns, StampSource source) {
  if (judged_[topic]) return {};
  std::vector<TimestampNs>& offsets = offsets_[topic];
  offsets.push_back(SaturatingDifference(header_ns, recorded_ns));
  if (offsets.size() < kSamples) return {};
  judged_[topic] = true;
  std::nth_element(offsets.begin(), offsets.begin() + kSamples / 2, offsets.end());
  const TimestampNs median = offsets[kSamples / 2];
  offsets_.erase(topic);
  if (median >= -kToleranceNs && median <= kToleranceNs) return {};
  char seconds[32];
  std::snprintf(seconds, sizeof(seconds), "%.1f", std::fabs(ToSeconds(median)));
  return topic + ": header stamps are " + seconds + " s " + (median < 0 ? "behind" : "ahead of") +
         " the recording stamps (median of the first " + std::to_string(kSamples) + " messages); " +
         (source == StampSource::kHeader
              ? "header stamps are used (--stamps recorded uses the recording stamps instead)"
              : "the recording stamps are used (--stamps recorded)");
}

}  // namespace littermap::bag
