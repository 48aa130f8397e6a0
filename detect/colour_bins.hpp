#pragma once
// The thesis's nine colour bins and the naive Bayes colour classifier built on them (thesis 3.2,
// "Naive Bayes on 9 colour bins"). A pixel is converted to HSV and binned:
//   V < 20 %                      -> black
//   S < 10 % and V > 90 %         -> white
//   S < 10 %, 20 % <= V <= 90 %   -> black below V = 50 %, white from it (grey, see below)
//   otherwise by hue              -> red 335-10, orange 11-48, yellow 49-67, green 68-150,
//                                    cyan 151-206, blue 207-259, magenta 260-334 degrees.
// The thesis's ranges are inclusive whole degrees; a real-valued hue h falls in [lo, hi + 1), so
// 10.5 degrees is red and 11.0 orange, and every hue has exactly one bin.
//
// Greys: the thesis leaves unsaturated pixels of medium value to their hue. A grey's hue is the
// angle of a near-zero chroma vector: sensor and JPEG noise decide it, and an exact grey has hue 0
// (red) in OpenCV. Asphalt paths, concrete, gravel and shadows would then vote for arbitrary
// hues, mostly red. We split them by value instead, at the middle of the value range (a grey at
// least half as bright as white counts as white), which keeps the nine bins of the thesis and
// keeps achromatic pixels together with the achromatic bins they resemble.

#include <array>
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include <opencv2/core.hpp>

namespace littermap::detect {

enum class ColourBin : int {
  kBlack = 0,
  kWhite,
  kRed,
  kOrange,
  kYellow,
  kGreen,
  kCyan,
  kBlue,
  kMagenta,
};
inline constexpr int kColourBinCount = 9;

inline constexpr double kBlackBelowValue = 0.20;      // V < 20 %: black
inline constexpr double kGreyBelowSaturation = 0.10;  // S < 10 %: achromatic
inline constexpr double kGreySplitValue = 0.50;       // greys: black below, white from here
// The thesis's white rule (S < 10 % and V > 90 %); the grey split implies it.
inline constexpr double kWhiteAboveValue = 0.90;

// Lower-case English name ("black", ..., "magenta"); used in model files.
std::string_view ColourBinName(ColourBin bin);

// A chromatic bin's hue interval [begin_deg, end_deg) on the unwrapped circle: red is
// [335, 371). Throws UsageError for black and white.
struct HueInterval {
  double begin_deg = 0;
  double end_deg = 0;
};
HueInterval ColourBinHueInterval(ColourBin bin);

// hue_deg: any angle (wrapped to [0, 360)); saturation and value in [0, 1] as in OpenCV's HSV.
ColourBin ColourBinOfHsv(double hue_deg, double saturation, double value);

// Per-pixel bin index (CV_8U, values 0..8 = ColourBin) of a CV_8UC3 BGR image. HSV comes from
// cv::cvtColor on the image scaled to float [0, 1]: the 8-bit conversion quantises hue to 2
// degrees, too coarse for the one-degree bin edges. Throws UsageError for another type.
cv::Mat ColourBinImage(const cv::Mat& image_bgr);

// Pixel counts per bin (index = ColourBin), or shares after Normalised().
struct ColourHistogram {
  std::array<double, kColourBinCount> counts{};

  double& operator[](ColourBin bin) { return counts[static_cast<std::size_t>(bin)]; }
  double operator[](ColourBin bin) const { return counts[static_cast<std::size_t>(bin)]; }
  double Total() const;
  // Shares summing to one. Throws UsageError when the histogram is empty.
  ColourHistogram Normalised() const;
  // Throws UsageError naming `what` when a count is negative or not finite.
  void Validate(std::string_view what) const;
};

// Histogram of the object pixels of a CV_8UC3 BGR image: mask is CV_8U of the image's size,
// non-zero = object pixel; an empty mask (cv::Mat()) takes every pixel, an all-zero mask gives an
// empty histogram. Throws UsageError for wrong types or sizes.
ColourHistogram ComputeColourHistogram(const cv::Mat& image_bgr, const cv::Mat& mask);

struct ColourNaiveBayesOptions {
  // Laplace smoothing: pseudo-count added to every bin of every class model, in pixels. One
  // pixel keeps a bin no training object showed finite (log(1 / (S_k + 9)), about -14 for a
  // class of a million pixels: a strong but not infinite penalty) while barely moving bins that
  // were seen. Train with pixel counts, not shares, or the pseudo-count dominates.
  double laplace_pseudocount = 1.0;
  void Validate() const;
};

struct ColourPrediction {
  std::size_t best_class = 0;  // index into ColourNaiveBayes::class_names()
  std::string best_name;
  std::vector<double> scores;  // D_k per class, in class order; larger is more likely
};

// Naive Bayes over the nine bins (thesis 3.2): a class model is the summed bin counts v_ki of its
// training objects, S_k their total, and an object with bin counts v_i scores
//   D_k = sum_i v_i * log((v_ki + a) / (S_k + 9 a)),   a = laplace_pseudocount,
// the log-likelihood of its pixels under the class's bin distribution; the largest D_k wins.
// Equal priors, as in the thesis. Classes are named by strings ("litter", "natural", ...) so a
// model file says what it classifies; the index is the order in which classes were first trained.
class ColourNaiveBayes {
 public:
  explicit ColourNaiveBayes(const ColourNaiveBayesOptions& options = {});

  // Adds a training object's bin counts to class `class_name`, creating the class on first use.
  // Throws UsageError for an empty name or an empty or invalid histogram.
  void Train(const std::string& class_name, const ColourHistogram& object);

  std::size_t class_count() const { return names_.size(); }
  const std::vector<std::string>& class_names() const { return names_; }
  const ColourHistogram& class_counts(std::size_t k) const { return counts_.at(k); }
  const ColourNaiveBayesOptions& options() const { return options_; }

  // D_k for every class. Throws UsageError without classes or for an empty object histogram.
  std::vector<double> Scores(const ColourHistogram& object) const;
  ColourPrediction Predict(const ColourHistogram& object) const;

  // Writes the model as map `key` of an open cv::FileStorage (YAML, JSON or XML).
  void Write(cv::FileStorage& fs, const std::string& key) const;
  // Reads a map written by Write. Throws BadInputError naming the field that is missing or wrong.
  static ColourNaiveBayes Read(const cv::FileNode& node);

 private:
  ColourNaiveBayesOptions options_;
  std::vector<std::string> names_;
  std::vector<ColourHistogram> counts_;
};

}  // namespace littermap::detect
