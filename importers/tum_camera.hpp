#pragma once
// The colour cameras of the TUM RGB-D benchmark (Sturm et al., IROS 2012), whose depth images
// are registered to colour: intrinsics and plumb_bob distortion (k1 k2 p1 p2 k3) as published on
// the benchmark's "file formats / intrinsic camera calibration" page. The freiburg3 images are
// already undistorted, so its distortion is zero and its intrinsics are the recommended ones.

#include <filesystem>
#include <optional>
#include <string_view>

#include "bag/ros_messages.hpp"

namespace littermap::importers {

enum class TumCamera { kFreiburg1, kFreiburg2, kFreiburg3 };

// "fr1", "freiburg1", ... (case-insensitive); nullopt for anything else.
std::optional<TumCamera> ParseTumCamera(std::string_view name);

// From a sequence directory's name ("rgbd_dataset_freiburg2_desk"); nullopt if the name names no
// camera, or more than one.
std::optional<TumCamera> TumCameraFromDirectory(const std::filesystem::path& directory);

const char* TumCameraName(TumCamera camera);  // "freiburg1", ...

// 640x480 CameraInfo with K, D, R = I and P = [K | 0].
msg::CameraInfo TumCameraInfo(TumCamera camera, const msg::Header& header);

}  // namespace littermap::importers
