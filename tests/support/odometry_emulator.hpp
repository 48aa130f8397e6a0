#pragma once
// A fake robot base streaming wheel odometry in the $ODOM line protocol
// (capture/odometry_protocol.hpp) over loopback TCP or a pseudo-terminal, for testing the
// odometry source and the recorder. Reading k carries time_ms = first_time_ms + k·period and the
// pose OdometryEmulatorPose(k); between readings it prints other lines a base might send.

#include <atomic>
#include <cstdint>
#include <string>
#include <thread>

#include "capture/odometry_protocol.hpp"

namespace littermap::test {

struct OdometryEmulatorOptions {
  double rate_hz = 50;
  std::uint64_t first_time_ms = 5000;
  int disconnect_after_readings = -1;  // close the connection once, after this many readings
  int bad_checksum_every = 0;          // every Nth reading (N > 0) has a wrong checksum
};

capture::OdometryReading OdometryEmulatorReading(std::uint64_t k,
                                                 const OdometryEmulatorOptions& options);

class OdometryEmulator {
 public:
  enum class Link { kTcp, kPseudoTerminal };

  explicit OdometryEmulator(Link link, const OdometryEmulatorOptions& options = {});
  ~OdometryEmulator();
  OdometryEmulator(const OdometryEmulator&) = delete;
  OdometryEmulator& operator=(const OdometryEmulator&) = delete;

  // "tcp://127.0.0.1:PORT" or "serial:/dev/pts/N".
  const std::string& uri() const { return uri_; }
  int readings_sent() const { return readings_sent_.load(); }

 private:
  void Run();
  // Streams to `fd` until the link fails, the emulator stops or it is time to disconnect.
  void Stream(int fd);

  Link link_;
  OdometryEmulatorOptions options_;
  std::string uri_;
  int listen_fd_ = -1;
  int master_fd_ = -1;
  int holder_fd_ = -1;
  bool disconnected_once_ = false;
  std::atomic<bool> stop_{false};
  std::atomic<int> readings_sent_{0};
  std::thread thread_;
};

}  // namespace littermap::test
