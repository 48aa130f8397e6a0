#include "capture/odometry_source.hpp"

#include "bag/sensor_messages.hpp"
#include "capture/odometry_protocol.hpp"
#include "core/error.hpp"

namespace littermap::capture {
namespace {

constexpr std::size_t kMaxLineBytes = 512;  // a $ODOM line is under 100 bytes
constexpr const ByteStreamSchemes kSchemes{"odometry", "tcp://", "serial:"};

}  // namespace

OdometrySource::OdometrySource(std::string uri, const OdometrySourceOptions& options)
    : uri_(std::move(uri)), options_(options), clock_(options.clock_offset_readings) {
  if (options_.clock_offset_readings < 1) {
    throw UsageError("odometry clock_offset_readings must be at least 1");
  }
  if (!uri_.starts_with(kSchemes.tcp) && !uri_.starts_with(kSchemes.serial)) {
    throw UsageError("odometry URI " + uri_ + " is neither tcp://HOST:PORT nor serial:/DEVICE");
  }
}

void OdometrySource::Connect() {
  stream_ = OpenByteStream(uri_, kSchemes, options_.stream);
  buffer_.clear();
}

std::optional<SensorSample> OdometrySource::Read(double timeout_s) {
  if (!stream_) throw SensorDisconnectedError(uri_ + ": not connected");
  const TimestampNs deadline_ns = HostNowNs() + FromSeconds(timeout_s);
  for (;;) {
    for (std::size_t newline; (newline = buffer_.find('\n')) != std::string::npos;) {
      const std::string line = buffer_.substr(0, newline);
      buffer_.erase(0, newline + 1);
      const TimestampNs arrival_ns = HostNowNs();
      const std::optional<OdometryReading> reading = ParseOdometryLine(line, uri_);
      if (!reading) continue;
      const TimestampNs stamp_ns =
          clock_.ToHost(static_cast<TimestampNs>(reading->time_ms) * 1'000'000, arrival_ns);
      return bag::sensor_messages::Odometry(stamp_ns, reading->T_odom_base, reading->linear_mps,
                                            reading->angular_radps);
    }
    if (buffer_.size() > kMaxLineBytes) {
      const std::string garbage = buffer_.substr(0, 40);
      buffer_.clear();
      throw BadInputError(uri_ + ": no line end within " + std::to_string(kMaxLineBytes) +
                          " bytes (starting '" + garbage + "')");
    }
    const double left_s = ToSeconds(deadline_ns - HostNowNs());
    if (left_s <= 0) return std::nullopt;
    char chunk[1024];
    const std::size_t n = stream_->Read(chunk, sizeof chunk, left_s);
    if (n == 0) return std::nullopt;
    buffer_.append(chunk, n);
  }
}

void OdometrySource::Disconnect() { stream_.reset(); }

}  // namespace littermap::capture
