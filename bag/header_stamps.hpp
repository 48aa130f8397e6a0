#pragma once
// Header stamps against recording stamps. A sensor message carries two times: its header stamp
// (when the sensor measured, by the robot's clock) and the time the recorder received it. They
// can disagree: a simulated robot's header time in a bag recorded with wall-clock time, a robot
// without a synchronised clock. littermap uses header stamps by default; with
// `--stamps recorded` the recording stamps replace them.
//
// Both work on the serialized (CDR) message: every type littermap reads that carries a header
// starts with it, so its stamp is the int32 sec + uint32 nanosec after the 4-byte CDR
// encapsulation header.

#include <cstdint>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "core/time.hpp"

namespace littermap::bag {

enum class StampSource { kHeader, kRecorded };

// "header" | "recorded"; UsageError otherwise.
StampSource ParseStampSource(const std::string& name);

// The header stamp of a message of this type; nullopt for a type without a leading header or a
// message too short to hold one.
std::optional<TimestampNs> HeaderStamp(const std::string& type,
                                       std::span<const std::uint8_t> serialized);
// Writes stamp_ns into the header; false (nothing written) when HeaderStamp would be nullopt.
bool SetHeaderStamp(const std::string& type, std::vector<std::uint8_t>& serialized,
                    TimestampNs stamp_ns);

// Watches each topic's first messages; a topic whose header stamps are more than a second off
// its recording stamps (median of its first 16 messages) gets one warning.
class StampAgreement {
 public:
  // Returns the warning for this topic once its median is known and off; empty otherwise.
  std::string Observe(const std::string& topic, TimestampNs header_ns, TimestampNs recorded_ns,
                      StampSource source);

 private:
  static constexpr std::size_t kSamples = 16;
  std::map<std::string, std::vector<TimestampNs>> offsets_;  // cleared once judged
  std::map<std::string, bool> judged_;
};

}  // namespace littermap::bag
