#pragma once
// A SCIP 2.0 laser (capture/scip_client.hpp) as a recorder source: connects, handshakes and
// starts continuous measurement; each scan becomes a LaserScan in frame `laser`.

#include <memory>
#include <string>

#include "capture/scip_client.hpp"
#include "capture/sensor_source.hpp"

namespace littermap::capture {

class ScipLaserSource : public SensorSource {
 public:
  // uri: "scip://HOST:PORT" or "scip:/DEVICE".
  ScipLaserSource(std::string uri, const ScipClientOptions& options = {});

  SensorKind kind() const override { return SensorKind::kLaser; }
  const std::string& uri() const override { return uri_; }
  void Connect() override;
  std::optional<SensorSample> Read(double timeout_s) override;
  void Disconnect() override;

 private:
  std::string uri_;
  ScipClientOptions options_;
  std::unique_ptr<ScipClient> client_;
};

}  // namespace littermap::capture
