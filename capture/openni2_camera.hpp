#pragma once
// An OpenNI2 RGB-D camera (Kinect, Xtion, PrimeSense Carmine class) as a recorder source:
// "openni2" opens the first device, "openni2:URI" the one OpenNI2 lists under URI (a USB path,
// or "Dummy" for OpenNI2's test driver). Depth in millimetres and RGB colour streams in the mode
// closest to the one asked for, depth registered to colour and frame sync on
// when the device can; a colour frame and the depth frame nearest in device time make one
// RgbdFrame, stamped in host time through the device clock (capture/clock_offset.hpp).
//
// Intrinsics: from the colour stream's field of view (the PrimeSense firmware does not expose a
// calibration), principal point at the image centre, no distortion. A device that reports no
// field of view gets options.fallback_*_fov_deg and a note saying so.

#include <memory>
#include <string>
#include <vector>

#include "capture/sensor_source.hpp"

namespace littermap::capture {

struct Openni2CameraOptions {
  int width = 640;  // the supported mode nearest to this size and rate is used
  int height = 480;
  int fps = 30;
  int clock_offset_frames = 30;  // frames over which the device clock offset is estimated
  double fallback_horizontal_fov_deg = 58.0;  // PrimeSense nominal
  double fallback_vertical_fov_deg = 45.0;

  void Validate() const;
};

// "WIDTHxHEIGHT@FPS" (e.g. 640x480@30) as camera options. Throws UsageError naming
// --camera-mode for other text or a mode out of range.
Openni2CameraOptions ParseCameraMode(const std::string& text);

class Openni2Camera : public SensorSource {
 public:
  // uri: "openni2" or "openni2:DEVICE_URI".
  Openni2Camera(std::string uri, const Openni2CameraOptions& options = {});
  ~Openni2Camera() override;

  SensorKind kind() const override { return SensorKind::kCamera; }
  const std::string& uri() const override { return uri_; }
  void Connect() override;
  std::optional<SensorSample> Read(double timeout_s) override;
  void Disconnect() override;
  std::vector<std::string> TakeNotes() override;

  // The devices OpenNI2 finds, as "URI (vendor name)".
  static std::vector<std::string> ListDevices();

 private:
  struct Device;
  std::string uri_;
  Openni2CameraOptions options_;
  std::unique_ptr<Device> device_;
  std::vector<std::string> notes_;
};

}  // namespace littermap::capture
