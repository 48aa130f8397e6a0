#pragma once
// A fake SCIP 2.0 laser (UTM-30LX-like by default) served over loopback TCP or a pseudo-terminal,
// for testing the SCIP client. It answers QT, SCIP2.0, VV, PP and MD (continuous, any step range
// and cluster count) and streams frames of known readings (ScipEmulatorRangeMm) at a fixed
// period, stamping frame k with first_timestamp_ms + k·scan_period_ms (mod 2^24). It can
// misbehave on request. VV lines carry the sum including the ';', PP lines the sum of the text
// before it, so clients are exercised with both variants seen on real devices.

#include <atomic>
#include <cstdint>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace littermap::test {

struct ScipEmulatorOptions {
  std::string scip2_status_line = "00P";  // the status line answering SCIP2.0, sent verbatim
  std::string model = "UTM-30LX(Hokuyo Automatic Co.,Ltd.)";
  int min_distance_mm = 23;
  int max_distance_mm = 60000;
  int steps_per_revolution = 1440;
  int first_step = 0;
  int last_step = 1080;
  int front_step = 540;
  int motor_speed_rpm = 2400;  // 40 Hz
  int scan_period_ms = 10;     // real time and sensor time between frames (faster than 40 Hz)
  std::uint32_t first_timestamp_ms = 1000;

  // Misbehaviour (frame indices count from 0 over the emulator's life; -1: never).
  int disconnect_after_frames = -1;  // close the connection once, after this many frames
  int bad_checksum_frame = -1;       // a wrong sum on the second data line of this frame
  int long_line_frame = -1;          // a data line of 70 characters (valid sum) in this frame
  int error_status_frame = -1;       // this frame is status 50 (hardware trouble) only
  bool bad_checksum_pp = false;      // a wrong sum on PP's DMAX line
  bool ignores_qt = false;           // while streaming, QT is not answered and frames go on
};

// The reading (mm) the emulator reports for `step` in frame `frame`: every step ≡ 7 (mod 100)
// is error code 1 (below DMIN, no echo), the others 200 + 13·step + 5·frame.
std::uint32_t ScipEmulatorRangeMm(int step, int frame);

class ScipEmulator {
 public:
  enum class Link { kTcp, kPseudoTerminal };

  ScipEmulator(Link link, const ScipEmulatorOptions& options = {});
  ~ScipEmulator();
  ScipEmulator(const ScipEmulator&) = delete;
  ScipEmulator& operator=(const ScipEmulator&) = delete;

  // "scip://127.0.0.1:PORT" or "scip:/dev/pts/N".
  const std::string& uri() const { return uri_; }
  int frames_sent() const { return frames_sent_.load(); }
  std::vector<std::string> commands() const;  // received so far, without LF

 private:
  void Run();
  void Serve();  // one connection until it ends or the emulator stops
  void Handle(const std::string& command);
  void WaitUntilDelivered();
  void QueueFrame();
  std::string PpReply() const;
  std::string VvReply() const;

  Link link_;
  ScipEmulatorOptions options_;
  std::string uri_;
  int listen_fd_ = -1;  // TCP
  int master_fd_ = -1;  // pseudo-terminal master
  int holder_fd_ = -1;  // a slave fd kept open so the master does not see a hang-up early
  int connection_fd_ = -1;
  bool disconnected_once_ = false;

  // Streaming state (thread only).
  bool streaming_ = false;
  std::string md_params_;  // echo text after "MD", without the scan count
  int md_first_ = 0, md_last_ = 0, md_cluster_ = 1;
  std::int64_t next_frame_ms_ = 0;
  std::string out_;

  std::atomic<bool> stop_{false};
  std::atomic<int> frames_sent_{0};
  mutable std::mutex mutex_;
  std::vector<std::string> commands_;
  std::thread thread_;
};

}  // namespace littermap::test
