#pragma once
// The pictures of a site report: the site map (occupancy map, litter density, items by class,
// numbered hotspots, scale bar, north arrow; north up) and a close-up of each hotspot cut from
// it.

#include <vector>

#include <opencv2/core.hpp>

#include "reports/site_report.hpp"

namespace littermap::reports {

struct SiteMapFigureOptions {
  int max_size_px = 1100;          // the longer side of the site map
  double close_up_radius_m = 5.0;  // a hotspot close-up shows this far around it
  int close_up_size_px = 220;
};

struct SiteMapFigure {
  cv::Mat map;                     // BGR
  std::vector<cv::Mat> close_ups;  // one per hotspot, in rank order
  double metres_per_pixel = 0.0;
  float peak_density_per_100m2 = 0.0f;  // the top of the colour scale
  // Where each hotspot's number was put on the map, in rank order: none covers another, the
  // north arrow or the scale bar while the map has room for them (a leader line joins a number
  // set apart to its outline).
  std::vector<cv::Rect> label_boxes;
};

SiteMapFigure DrawSiteMap(const SiteReport& report, const SiteMapFigureOptions& options);

// PNG bytes of an image. Throws InternalError when OpenCV cannot encode it.
std::vector<unsigned char> EncodePng(const cv::Mat& image);

}  // namespace littermap::reports
