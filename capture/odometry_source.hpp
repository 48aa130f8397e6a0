#pragma once
// Wheel odometry from the robot base over the line protocol of capture/odometry_protocol.hpp,
// on TCP ("tcp://HOST:PORT") or a serial device ("serial:/dev/ttyUSB0"), as a recorder source:
// each reading becomes an Odometry odom -> base_link stamped in host time.

#include <memory>
#include <string>

#include "capture/byte_stream.hpp"
#include "capture/clock_offset.hpp"
#include "capture/sensor_source.hpp"

namespace littermap::capture {

struct OdometrySourceOptions {
  int clock_offset_readings = 50;  // readings over which the base's clock offset is estimated
  ByteStreamOptions stream;
};

class OdometrySource : public SensorSource {
 public:
  OdometrySource(std::string uri, const OdometrySourceOptions& options = {});

  SensorKind kind() const override { return SensorKind::kOdometry; }
  const std::string& uri() const override { return uri_; }
  void Connect() override;
  std::optional<SensorSample> Read(double timeout_s) override;
  void Disconnect() override;

 private:
  std::string uri_;
  OdometrySourceOptions options_;
  std::unique_ptr<ByteStream> stream_;
  std::string buffer_;
  ClockOffset clock_;
};

}  // namespace littermap::capture
