#include "capture/scip_client.hpp"

#include <algorithm>
#include <chrono>

namespace littermap::capture {

namespace {

constexpr std::size_t kMaxLineBytes = 1024;           // SCIP lines are at most 65 bytes (+ echo)
constexpr std::size_t kMaxReplyLines = 4096;          // a 1440-step MD frame has ~70 lines
constexpr std::uint32_t kSensorClockMask = 0xFFFFFF;  // 24-bit millisecond counter

}  // namespace

void ScipClientOptions::Validate() const {
  if (!(reply_timeout_s > 0) || !(scan_timeout_s > 0)) {
    throw UsageError("SCIP reply_timeout_s and scan_timeout_s must be positive");
  }
  if (cluster_count < 1 || cluster_count > 99) {
    throw UsageError("SCIP cluster_count must be 1..99, not " + std::to_string(cluster_count));
  }
  if (clock_offset_scans < 1) throw UsageError("SCIP clock_offset_scans must be at least 1");
}

ScipClient::ScipClient(const std::string& uri, const ScipClientOptions& options)
    : ScipClient(OpenByteStream(uri, {"laser", "scip://", "scip:"}, options.transport), options) {}

ScipClient::ScipClient(std::unique_ptr<ByteStream> transport, const ScipClientOptions& options)
    : transport_(std::move(transport)), options_(options), clock_(options.clock_offset_scans) {
  if (!transport_) throw UsageError("SCIP client without a transport");
  options_.Validate();
  Handshake();
}

ScipClient::~ScipClient() {
  if (!measuring_) return;
  try {
    Stop();
  } catch (const Error&) {
    // The sensor is gone or confused; nothing more to do on the way out.
  }
}

std::string ScipClient::Context(const std::string& command) const {
  return uri() + ": " + command + " reply";
}

std::string ScipClient::ReadLine(TimestampNs deadline_ns) {
  for (;;) {
    const std::size_t lf = buffer_.find('\n');
    if (lf != std::string::npos) {
      std::string line = buffer_.substr(0, lf);
      buffer_.erase(0, lf + 1);
      return line;
    }
    if (buffer_.size() > kMaxLineBytes) {
      throw BadInputError(uri() + ": line longer than " + std::to_string(kMaxLineBytes) +
                          " bytes: \"" + buffer_.substr(0, 80) + "...\"");
    }
    const TimestampNs now = HostNowNs();
    if (now >= deadline_ns) {
      throw SensorDisconnectedError(uri() + ": sensor stopped answering (timeout)");
    }
    char chunk[4096];
    const std::size_t n = transport_->Read(chunk, sizeof chunk, ToSeconds(deadline_ns - now));
    buffer_.append(chunk, n);
  }
}

std::vector<std::string> ScipClient::ReadReplyLines(double timeout_s, TimestampNs* first_line_ns) {
  const TimestampNs deadline = HostNowNs() + FromSeconds(timeout_s);
  std::vector<std::string> lines;
  for (;;) {
    std::string line = ReadLine(deadline);
    if (line.empty()) {
      if (lines.empty()) continue;  // a stray LF between replies
      return lines;
    }
    if (lines.empty() && first_line_ns != nullptr) *first_line_ns = HostNowNs();
    if (lines.size() >= kMaxReplyLines) {
      throw BadInputError(uri() + ": reply of more than " + std::to_string(kMaxReplyLines) +
                          " lines, starting \"" + lines.front() + "\"");
    }
    lines.push_back(std::move(line));
  }
}

ScipReply ScipClient::Transact(const std::string& command) {
  transport_->Write(command + "\n");
  const std::vector<std::string> lines = ReadReplyLines(options_.reply_timeout_s);
  const std::string name = command.substr(0, command.starts_with("SCIP") ? 7 : 2);
  ScipReply reply = ParseScipReply(lines, command, Context(name));
  if (!ScipStatusAccepted(name, reply.status.code)) {
    throw BadInputError(Context(name) + ": sensor reports error status " + reply.status.code +
                        " in line \"" + lines[1] + "\"");
  }
  return reply;
}

void ScipClient::ThrowIfQtIgnored(int frames_skipped) const {
  // Frames in flight when QT went out are a few; a sensor still streaming after this many
  // (5 s at 40 Hz) did not take the command.
  constexpr int kMaxFramesAfterQt = 200;
  if (frames_skipped >= kMaxFramesAfterQt) {
    throw SensorDisconnectedError(uri() + ": sensor keeps streaming and does not answer QT");
  }
}

void ScipClient::Handshake() {
  // A sensor left streaming by an earlier client keeps sending frames: stop it and skip
  // everything up to the QT reply.
  transport_->Write("QT\n");
  for (int skipped = 0;; ++skipped) {
    const std::vector<std::string> lines = ReadReplyLines(options_.reply_timeout_s);
    if (lines.front().starts_with("QT")) break;
    ThrowIfQtIgnored(skipped);
  }
  handshake_.scip2_status = Transact("SCIP2.0").status.code;
  handshake_.version = ParseScipInfo(Transact("VV").body, Context("VV"));
  handshake_.sensor = ParseScipParameters(Transact("PP").body, Context("PP"));
}

void ScipClient::StartMeasurement() {
  if (measuring_) return;
  const ScipSensorParameters& sensor = handshake_.sensor;
  request_ = {sensor.first_step, sensor.last_step, options_.cluster_count};
  const std::string command = ScipMdCommand(request_, 0, 0);  // every scan, until QT
  md_echo_prefix_ = command.substr(0, 13);
  const ScipReply reply = Transact(command);
  if (reply.status.code != "00") {
    throw BadInputError(Context("MD") + ": expected status 00 accepting the command, got \"" +
                        reply.status.code + "\"");
  }
  measuring_ = true;
}

ScipScan ScipClient::ReadScan() {
  if (!measuring_) throw UsageError(uri() + ": ReadScan before StartMeasurement");
  const std::string context = Context("MD");
  for (;;) {
    ScipScan out;
    const std::vector<std::string> lines = ReadReplyLines(options_.scan_timeout_s, &out.arrival_ns);
    const ScipReply reply = ParseScipReply(lines, md_echo_prefix_, context);
    if (reply.status.code == "98") continue;  // measurement resumed after a laser check (§8.1)
    if (reply.status.code != "99") {
      throw BadInputError(context + ": sensor reports error status " + reply.status.code +
                          " in line \"" + lines[1] + "\"");
    }
    const ScipScanData data = DecodeScipScanData(reply.body, 3, context);
    if (data.ranges_mm.size() != request_.reading_count()) {
      throw BadInputError(context + ": " + std::to_string(data.ranges_mm.size()) +
                          " readings, expected " + std::to_string(request_.reading_count()) +
                          " in frame \"" + reply.echo + "\"");
    }
    if (last_sensor_ms_) {
      std::uint32_t delta = (data.timestamp_ms - *last_sensor_ms_) & kSensorClockMask;
      // A step of more than half the range is the clock going backwards, not a wrap.
      unwrapped_sensor_ms_ += delta < (kSensorClockMask + 1) / 2
                                  ? static_cast<std::int64_t>(delta)
                                  : static_cast<std::int64_t>(delta) - (kSensorClockMask + 1);
    } else {
      unwrapped_sensor_ms_ = data.timestamp_ms;
    }
    last_sensor_ms_ = data.timestamp_ms;
    out.sensor_time_ms = data.timestamp_ms;
    out.sensor_time_unwrapped_ms = unwrapped_sensor_ms_;
    out.scan = ScipToLaserScan(handshake_.sensor, request_, data.ranges_mm,
                               clock_.ToHost(unwrapped_sensor_ms_ * 1'000'000, out.arrival_ns));
    return out;
  }
}

void ScipClient::Stop() {
  transport_->Write("QT\n");
  measuring_ = false;
  for (int skipped = 0;; ++skipped) {  // frames already sent come first
    const std::vector<std::string> lines = ReadReplyLines(options_.reply_timeout_s);
    if (!lines.front().starts_with("QT")) {
      ThrowIfQtIgnored(skipped);
      continue;
    }
    const ScipReply reply = ParseScipReply(lines, "QT", Context("QT"));
    if (!ScipStatusAccepted("QT", reply.status.code)) {
      throw BadInputError(Context("QT") + ": sensor reports error status " + reply.status.code +
                          " in line \"" + lines[1] + "\"");
    }
    return;
  }
}

}  // namespace littermap::capture
