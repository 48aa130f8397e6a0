#pragma once
// OpenCV's k-means (cv::kmeans, and GrabCut's colour models, which start from it) draws its
// k-means++ seeds from the calling thread's cv::theRNG(), one stream for every call before it: an
// object's segmentation would depend on how many others the thread refined earlier, and a trained
// model on what ran before the training. Within a SeededTheRng's scope the stream starts from a
// given seed; afterwards it goes on where it was.

#include <cstdint>

#include <opencv2/core.hpp>

namespace littermap::detect {

class SeededTheRng {
 public:
  explicit SeededTheRng(std::uint64_t seed) : saved_state_(cv::theRNG().state) {
    cv::theRNG() = cv::RNG(seed);
  }
  ~SeededTheRng() { cv::theRNG().state = saved_state_; }
  SeededTheRng(const SeededTheRng&) = delete;
  SeededTheRng& operator=(const SeededTheRng&) = delete;

 private:
  std::uint64_t saved_state_;
};

}  // namespace littermap::detect
