#include "importers/tum_camera.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <string>
#include <system_error>

namespace littermap::importers {
namespace {

struct Calibration {
  double fx, fy, cx, cy;
  std::array<double, 5> distortion;  // k1 k2 p1 p2 k3
};

// vision.in.tum.de/data/datasets/rgbd-dataset/file_formats, "Intrinsic Camera Calibration of the
// Kinect" (colour camera; depth is registered to it).
Calibration CalibrationOf(TumCamera camera) {
  switch (camera) {
    case TumCamera::kFreiburg1:
      return {517.306408,
              516.469215,
              318.643040,
              255.313989,
              {0.262383, -0.953104, -0.005358, 0.002628, 1.163314}};
    case TumCamera::kFreiburg2:
      return {520.908620,
              521.007327,
              325.141442,
              249.701764,
              {0.231222, -0.784899, -0.003257, -0.000105, 0.917205}};
    case TumCamera::kFreiburg3:
      break;
  }
  return {535.4, 539.2, 320.1, 247.6, {0, 0, 0, 0, 0}};
}

std::string Lower(std::string_view text) {
  std::string lower(text);
  std::transform(lower.begin(), lower.end(), lower.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return lower;
}

}  // namespace

std::optional<TumCamera> ParseTumCamera(std::string_view name) {
  const std::string lower = Lower(name);
  if (lower == "fr1" || lower == "freiburg1") return TumCamera::kFreiburg1;
  if (lower == "fr2" || lower == "freiburg2") return TumCamera::kFreiburg2;
  if (lower == "fr3" || lower == "freiburg3") return TumCamera::kFreiburg3;
  return std::nullopt;
}

std::optional<TumCamera> TumCameraFromDirectory(const std::filesystem::path& directory) {
  // Canonical, so that "." and "seq/" name the directory itself.
  std::error_code error;
  std::filesystem::path resolved = std::filesystem::weakly_canonical(directory, error);
  if (error) resolved = directory;
  std::filesystem::path name = resolved.filename();
  if (name.empty()) name = resolved.parent_path().filename();
  const std::string lower = Lower(name.string());
  std::optional<TumCamera> found;
  for (const TumCamera camera :
       {TumCamera::kFreiburg1, TumCamera::kFreiburg2, TumCamera::kFreiburg3}) {
    if (lower.find(TumCameraName(camera)) == std::string::npos) continue;
    if (found) return std::nullopt;  // ambiguous
    found = camera;
  }
  return found;
}

const char* TumCameraName(TumCamera camera) {
  switch (camera) {
    case TumCamera::kFreiburg1:
      return "freiburg1";
    case TumCamera::kFreiburg2:
      return "freiburg2";
    case TumCamera::kFreiburg3:
      break;
  }
  return "freiburg3";
}

msg::CameraInfo TumCameraInfo(TumCamera camera, const msg::Header& header) {
  const Calibration c = CalibrationOf(camera);
  msg::CameraInfo info;
  info.header = header;
  info.width = 640;
  info.height = 480;
  info.distortion_model = "plumb_bob";
  info.d.assign(c.distortion.begin(), c.distortion.end());
  info.k = {c.fx, 0, c.cx, 0, c.fy, c.cy, 0, 0, 1};
  info.r = {1, 0, 0, 0, 1, 0, 0, 0, 1};
  info.p = {c.fx, 0, c.cx, 0, 0, c.fy, c.cy, 0, 0, 0, 1, 0};
  return info;
}

}  // namespace littermap::importers
