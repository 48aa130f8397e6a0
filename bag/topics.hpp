#pragma once
// Default topic and frame names of a littermap run bag. Bags from other robots can use other
// topic names; every stage that reads a bag takes them as a RunTopics defaulting to these.

#include <string>

namespace littermap::topics {

inline constexpr const char* kScan = "/scan";                                // LaserScan
inline constexpr const char* kOdometry = "/odom";                            // Odometry
inline constexpr const char* kColor = "/camera/color/image_raw/compressed";  // JPEG
inline constexpr const char* kDepth = "/camera/depth/image_raw/compressed";  // 16-bit PNG, mm
inline constexpr const char* kCameraInfo = "/camera/color/camera_info";      // CameraInfo
// Depth is registered to colour (same optical frame and intrinsics), as the Kinect drivers'
// depth_registered output; its CameraInfo repeats the colour one on the depth stamps.
inline constexpr const char* kDepthCameraInfo = "/camera/depth/camera_info";  // CameraInfo
inline constexpr const char* kImu = "/imu";                                   // Imu
inline constexpr const char* kGps = "/gps/fix";                               // NavSatFix
inline constexpr const char* kTfStatic = "/tf_static";                        // TFMessage

}  // namespace littermap::topics

namespace littermap::frames {

inline constexpr const char* kOdom = "odom";
inline constexpr const char* kBase = "base_link";
inline constexpr const char* kLaser = "laser";
inline constexpr const char* kCamera = "camera_color_optical_frame";

}  // namespace littermap::frames

namespace littermap::bag {

// Where a run's streams are in its bag: one set of names for every stage that reads a run.
struct RunTopics {
  std::string scan = topics::kScan;
  std::string odometry = topics::kOdometry;
  std::string imu = topics::kImu;  // tilt and yaw rate, if recorded
  std::string tf_static = topics::kTfStatic;
  std::string colour = topics::kColor;
  std::string depth = topics::kDepth;
  std::string camera_info = topics::kCameraInfo;
  std::string camera_frame = frames::kCamera;  // the colour optical frame's child_frame_id
};

}  // namespace littermap::bag
