// The OpenNI2 source through the real OpenNI2 library and its DummyDevice driver (Debian's
// libopenni2-0 ships it): 320x240 depth and colour at 30 Hz, the first pixel 2000 mm and pure
// blue, with no field of view, no registration and no other mode.

#include "capture/openni2_camera.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/error.hpp"

namespace littermap::capture {
namespace {

std::vector<RgbdFrame> ReadFrames(Openni2Camera& camera, int count) {
  std::vector<RgbdFrame> frames;
  for (int tries = 0; frames.size() < static_cast<std::size_t>(count) && tries < 200; ++tries) {
    if (auto sample = camera.Read(0.2)) frames.push_back(std::get<RgbdFrame>(std::move(*sample)));
  }
  return frames;
}

TEST(Openni2Camera, ReadsPairedFramesFromTheDummyDevice) {
  Openni2Camera camera("openni2:Dummy");
  camera.Connect();
  const std::vector<std::string> notes = camera.TakeNotes();
  const std::vector<RgbdFrame> frames = ReadFrames(camera, 15);
  ASSERT_EQ(frames.size(), 15u);
  for (const RgbdFrame& frame : frames) {
    ASSERT_EQ(frame.colour_bgr.type(), CV_8UC3);
    ASSERT_EQ(frame.depth_mm.type(), CV_16UC1);
    EXPECT_EQ(frame.colour_bgr.size(), cv::Size(320, 240));
    EXPECT_EQ(frame.depth_mm.size(), cv::Size(320, 240));
    // The driver's colour is pure blue in RGB order: BGR (255, 0, 0) once converted.
    EXPECT_EQ(frame.colour_bgr.at<cv::Vec3b>(0, 0), cv::Vec3b(255, 0, 0));
    EXPECT_EQ(frame.depth_mm.at<std::uint16_t>(0, 0), 2000);
  }
  // 30 Hz device clock mapped to host time: mostly 33 ms apart (the dummy driver skips now and
  // then), never closer, and recent.
  std::vector<double> dt_ms;
  for (std::size_t i = 1; i < frames.size(); ++i) {
    dt_ms.push_back(ToSeconds(frames[i].stamp_ns - frames[i - 1].stamp_ns) * 1000);
    EXPECT_GT(dt_ms.back(), 30.0);
  }
  std::nth_element(dt_ms.begin(), dt_ms.begin() + dt_ms.size() / 2, dt_ms.end());
  EXPECT_NEAR(dt_ms[dt_ms.size() / 2], 33.0, 1.5);
  EXPECT_LT(std::abs(ToSeconds(HostNowNs() - frames.back().stamp_ns)), 1.0);

  // No field of view from the device: the PrimeSense nominal 58° × 45°, and a note saying so.
  const msg::CameraInfo& info = frames.front().camera_info;
  EXPECT_EQ(info.width, 320u);
  EXPECT_EQ(info.height, 240u);
  const double fx = 160 / std::tan(58.0 / 2 * std::numbers::pi / 180);
  EXPECT_NEAR(info.k[0], fx, 1e-9);
  EXPECT_NEAR(info.k[2], 159.5, 1e-9);
  EXPECT_NEAR(info.k[5], 119.5, 1e-9);
  bool fov_note = false, mode_note = false;
  for (const std::string& note : notes) {
    fov_note |= note.find("no field of view") != std::string::npos;
    mode_note |= note.find("640x480@30 not available; recording 320x240@30") != std::string::npos;
  }
  EXPECT_TRUE(fov_note);
  EXPECT_TRUE(mode_note);
  EXPECT_TRUE(camera.TakeNotes().empty());

  // Disconnect and connect again, as after an unplug.
  camera.Disconnect();
  EXPECT_THROW(camera.Read(0.1), SensorDisconnectedError);
  camera.Connect();
  EXPECT_EQ(ReadFrames(camera, 3).size(), 3u);
  camera.Disconnect();
}

TEST(Openni2Camera, NamesTheUriWhenNoDeviceAnswers) {
  Openni2Camera camera("openni2:/dev/no-such-device");
  try {
    camera.Connect();
    FAIL() << "opened a device that does not exist";
  } catch (const SensorDisconnectedError& error) {
    EXPECT_NE(std::string(error.what()).find("openni2:/dev/no-such-device: cannot open"),
              std::string::npos)
        << error.what();
  }
  EXPECT_THROW(Openni2Camera("kinect"), UsageError);
  EXPECT_THROW(Openni2Camera("openni2:"), UsageError);
  Openni2CameraOptions zero_fps;
  zero_fps.fps = 0;
  EXPECT_THROW(Openni2Camera("openni2", zero_fps), UsageError);
}

}  // namespace
}  // namespace littermap::capture
