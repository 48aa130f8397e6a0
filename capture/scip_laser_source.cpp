#include "capture/scip_laser_source.hpp"

#include "bag/sensor_messages.hpp"

namespace littermap::capture {

ScipLaserSource::ScipLaserSource(std::string uri, const ScipClientOptions& options)
    : uri_(std::move(uri)), options_(options) {
  options_.Validate();
}

void ScipLaserSource::Connect() {
  Disconnect();
  client_ = std::make_unique<ScipClient>(uri_, options_);
  client_->StartMeasurement();
}

std::optional<SensorSample> ScipLaserSource::Read(double /*timeout_s*/) {
  // The client waits at most options.scan_timeout_s for a frame and reports a silent sensor as
  // disconnected: a laser streams at 10–40 Hz, so a missing frame is never just a quiet moment.
  if (!client_) throw SensorDisconnectedError(uri_ + ": not connected");
  const ScipScan scan = client_->ReadScan();
  return bag::sensor_messages::Scan(scan.scan.stamp_ns, scan.scan);
}

void ScipLaserSource::Disconnect() {
  if (!client_) return;
  try {
    client_->Stop();
  } catch (const std::exception&) {  // the sensor may already be gone
  }
  client_.reset();
}

}  // namespace littermap::capture
