#pragma once
// The real RGB-D frame pair of ../shared/datasets/tum_pair (TUM RGB-D freiburg2 desk, 14 cm
// apart), for the RGB-D alignment tests.

#include <filesystem>
#include <string>
#include <utility>

#include <opencv2/imgcodecs.hpp>

#include "reconstruct/rgbd_aligner.hpp"

namespace littermap::reconstruct {

// The TUM freiburg2 desk pair (depth 5000 units per metre, registered to colour).
struct TumPair {
  RgbdImage first, second;
  RgbdCameraModel camera{520.909, 521.007, 325.141, 249.702, {}};
};

inline TumPair LoadTumPair() {
  const std::filesystem::path dir = std::filesystem::path(LITTERMAP_DATASETS_DIR) / "tum_pair";
  TumPair pair;
  for (auto [image, name] : {std::pair{&pair.first, "1"}, std::pair{&pair.second, "2"}}) {
    image->colour_bgr = cv::imread((dir / (std::string(name) + ".png")).string(), cv::IMREAD_COLOR);
    image->depth =
        cv::imread((dir / (std::string(name) + "_depth.png")).string(), cv::IMREAD_UNCHANGED);
    image->depth_unit_m = 1.0 / 5000;
  }
  return pair;
}

}  // namespace littermap::reconstruct
