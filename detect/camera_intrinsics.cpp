#include "detect/camera_intrinsics.hpp"

#include "core/error.hpp"

namespace littermap::detect {

CameraIntrinsics IntrinsicsFromCameraInfo(const msg::CameraInfo& info, const std::string& source) {
  if (!(info.k[0] > 0) || !(info.k[4] > 0)) {
    throw BadInputError(source +
                        ": CameraInfo field k has no focal length (k[0], k[4] must be > 0)");
  }
  if (info.width == 0 || info.height == 0) {
    throw BadInputError(source + ": CameraInfo fields width/height are zero");
  }
  CameraIntrinsics intrinsics;
  intrinsics.fx = info.k[0];
  intrinsics.fy = info.k[4];
  intrinsics.cx = info.k[2];
  intrinsics.cy = info.k[5];
  intrinsics.width = static_cast<int>(info.width);
  intrinsics.height = static_cast<int>(info.height);
  return intrinsics;
}

}  // namespace littermap::detect
