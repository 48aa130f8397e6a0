#pragma once
// The sources of a capture, as the URIs `littermap capture` takes: a real sensor
// (capture/openni2_camera.hpp, capture/scip_laser_source.hpp, capture/odometry_source.hpp),
// "none" or nothing for no sensor, or "sim:WORLD.yaml" for the park simulator, which records
// every sensor of one world at once and so never records together with a real sensor.

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "capture/openni2_camera.hpp"
#include "capture/sensor_source.hpp"

namespace littermap::capture {

struct CaptureSources {
  std::string camera_uri;
  std::string laser_uri;
  std::string odometry_uri;
};

// The world file when the sources are simulated, nullopt when none is. Throws UsageError naming
// --camera, --laser or --odometry when a sim: source comes without --camera sim:WORLD.yaml, with
// a real sensor, without a laser, or with another world (the odometry may be left out).
std::optional<std::string> SimulatedWorld(const CaptureSources& sources);

// The real sensors given, camera first, then laser and odometry; nothing is connected yet.
// Throws UsageError for a URI of no known scheme and when no sensor is given.
std::vector<std::unique_ptr<SensorSource>> MakeSources(const CaptureSources& sources,
                                                       const Openni2CameraOptions& camera);

}  // namespace littermap::capture
