#include "sim/footprint.hpp"

#include <cmath>
#include <numbers>
#include <opencv2/imgproc.hpp>
#include <vector>

#include "core/pose3.hpp"

namespace littermap::sim {

Footprint FootprintOf(const WorldObject& object) {
  const Eigen::Matrix3d R = RotationFromRpy(object.orientation);
  const double yaw = object.orientation.yaw_rad;
  const Eigen::Vector3d along(std::cos(yaw), std::sin(yaw), 0), across(-along.y(), along.x(), 0);
  Footprint footprint;
  footprint.center_m = object.center_m.head<2>();
  footprint.yaw_rad = yaw;
  // The extent of the oriented box along each horizontal axis: every local axis contributes
  // the share of its length that points that way.
  for (int i = 0; i < 3; ++i) {
    footprint.size_m.x() += std::abs(R.col(i).dot(along)) * object.size_m[i];
    footprint.size_m.y() += std::abs(R.col(i).dot(across)) * object.size_m[i];
  }
  return footprint;
}

bool FootprintsOverlap(const Footprint& a, const Footprint& b, double gap_m) {
  // In a's frame: single precision holds millimetres there, anywhere in a park.
  const auto rect = [&a, gap_m](const Footprint& f) {
    const Eigen::Vector2d c = f.center_m - a.center_m;
    return cv::RotatedRect(cv::Point2f(float(c.x()), float(c.y())),
                           cv::Size2f(float(f.size_m.x() + gap_m), float(f.size_m.y() + gap_m)),
                           float(f.yaw_rad * 180 / std::numbers::pi));
  };
  // Far apart for certain: the rectangles' circumscribed circles do not meet.
  const double reach = 0.5 * ((a.size_m.array() + gap_m).matrix().norm() +
                              (b.size_m.array() + gap_m).matrix().norm());
  if ((a.center_m - b.center_m).squaredNorm() >= reach * reach) return false;
  std::vector<cv::Point2f> intersection;
  return cv::rotatedRectangleIntersection(rect(a), rect(b), intersection) != cv::INTERSECT_NONE;
}

}  // namespace littermap::sim
