#pragma once
// A SCIP 2.0 client for Hokuyo URG/UTM lasers: handshake (SCIP2.0, VV, PP), continuous
// measurement with MD over the full step range, scans one by one as LaserScan stamped in host
// time, and QT to stop.
//
// Errors: BadInputError for malformed replies and checksum errors (the message names the URI and
// quotes the line), SensorDisconnectedError (capture/byte_stream.hpp) when the sensor goes away
// or stops answering, so a recorder can reconnect. A sensor that reports an error status
// (hardware trouble, rejected command) raises BadInputError quoting the status.
//
// Time: the sensor stamps each scan with a 24-bit millisecond counter that wraps every
// 4.66 hours. The client unwraps it and maps it to host time with an offset, the smallest
// (arrival time − sensor time) over the first scans (options.clock_offset_scans): arrival is
// always later than the measurement, so the least delayed scan gives the tightest offset. The
// offset is then held, so stamps stay as regular as the sensor's clock.

#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "capture/byte_stream.hpp"
#include "capture/clock_offset.hpp"
#include "capture/scip_protocol.hpp"
#include "core/laser_scan.hpp"
#include "core/time.hpp"

namespace littermap::capture {

struct ScipClientOptions {
  double reply_timeout_s = 1.0;  // for command replies (SCIP2.0, VV, PP, MD, QT)
  double scan_timeout_s = 1.0;   // longest wait for the next scan frame
  int cluster_count = 1;         // adjacent steps merged into one reading
  int clock_offset_scans = 20;   // scans over which the host–sensor clock offset is estimated
  ByteStreamOptions transport;

  void Validate() const;
};

struct ScipHandshake {
  std::string scip2_status;  // the SCIP2.0 reply's status: "0" (was SCIP 1.1), "00", "0E"
  std::map<std::string, std::string> version;  // VV: VEND, PROD, FIRM, PROT, SERI
  ScipSensorParameters sensor;                 // PP
};

struct ScipScan {
  LaserScan scan;                             // stamp_ns in host time (Unix epoch)
  std::uint32_t sensor_time_ms = 0;           // the raw 24-bit time stamp
  std::int64_t sensor_time_unwrapped_ms = 0;  // monotonic across 24-bit wraps
  TimestampNs arrival_ns = 0;                 // host time the frame's first line arrived
};

class ScipClient {
 public:
  // Opens `uri`, "scip://HOST:PORT" or "scip:/DEVICE" (see OpenByteStream), and performs the
  // handshake.
  explicit ScipClient(const std::string& uri, const ScipClientOptions& options = {});
  // Uses an already open transport and performs the handshake.
  ScipClient(std::unique_ptr<ByteStream> transport, const ScipClientOptions& options = {});
  ~ScipClient();
  ScipClient(const ScipClient&) = delete;
  ScipClient& operator=(const ScipClient&) = delete;

  const ScipHandshake& handshake() const { return handshake_; }
  const std::string& uri() const { return transport_->uri(); }

  // Sends MD over AMIN..AMAX, every scan, until stopped, and checks the sensor accepted it.
  void StartMeasurement();
  // The next scan frame; waits up to options.scan_timeout_s.
  ScipScan ReadScan();
  // Sends QT, skipping scan frames still on their way, and waits for its reply.
  void Stop();

  std::optional<TimestampNs> clock_offset_ns() const {
    return clock_.known() ? std::optional(clock_.offset_ns()) : std::nullopt;
  }

 private:
  void Handshake();
  // Throws SensorDisconnectedError once too many frames came after a QT.
  void ThrowIfQtIgnored(int frames_skipped) const;
  // Sends `command` + LF and returns the checked reply.
  ScipReply Transact(const std::string& command);
  // One reply's lines (without LFs and the closing empty line); `first_line_ns` gets the host
  // time its first line arrived.
  std::vector<std::string> ReadReplyLines(double timeout_s, TimestampNs* first_line_ns = nullptr);
  std::string ReadLine(TimestampNs deadline_ns);
  std::string Context(const std::string& command) const;

  std::unique_ptr<ByteStream> transport_;
  ScipClientOptions options_;
  ScipHandshake handshake_;
  ScipRangeRequest request_;
  std::string md_echo_prefix_;  // MD + steps + cluster + interval, the part every frame echoes
  bool measuring_ = false;
  std::string buffer_;  // bytes received but not yet consumed
  std::optional<std::uint32_t> last_sensor_ms_;
  std::int64_t unwrapped_sensor_ms_ = 0;
  ClockOffset clock_;
};

}  // namespace littermap::capture
