#include "detect/colour_bins.hpp"

#include <algorithm>
#include <cmath>

#include <opencv2/imgproc.hpp>

#include "core/error.hpp"

namespace littermap::detect {
namespace {

constexpr std::array<std::string_view, kColourBinCount> kNames = {
    "black", "white", "red", "orange", "yellow", "green", "cyan", "blue", "magenta"};

// Chromatic bins in ColourBin order from kRed, [begin, end) in degrees (thesis 3.2, whole-degree
// ranges closed on the right by one degree). Red wraps through 0.
constexpr std::array<HueInterval, 7> kHues = {
    {{335, 371}, {11, 49}, {49, 68}, {68, 151}, {151, 207}, {207, 260}, {260, 335}}};

void CheckImage(const cv::Mat& image_bgr, const char* what) {
  if (image_bgr.empty() || image_bgr.type() != CV_8UC3) {
    throw UsageError(std::string(what) + ": image must be a non-empty CV_8UC3 BGR image");
  }
}

// Bins of a CV_8UC3 image of any shape, written to a CV_8U image of the same shape.
void BinPixels(const cv::Mat& pixels_bgr, cv::Mat* bins) {
  cv::Mat scaled, hsv;
  pixels_bgr.convertTo(scaled, CV_32FC3, 1.0 / 255.0);
  cv::cvtColor(scaled, hsv, cv::COLOR_BGR2HSV);  // float: H in [0, 360), S and V in [0, 1]
  bins->create(pixels_bgr.size(), CV_8U);
  for (int r = 0; r < hsv.rows; ++r) {
    const auto* in = hsv.ptr<cv::Vec3f>(r);
    auto* out = bins->ptr<std::uint8_t>(r);
    for (int c = 0; c < hsv.cols; ++c) {
      out[c] = static_cast<std::uint8_t>(ColourBinOfHsv(in[c][0], in[c][1], in[c][2]));
    }
  }
}

// The masked pixels as one row of CV_8UC3.
cv::Mat MaskedRow(const cv::Mat& image_bgr, const cv::Mat& mask) {
  cv::Mat row(1, cv::countNonZero(mask), CV_8UC3);
  auto* out = row.ptr<cv::Vec3b>(0);
  for (int r = 0; r < image_bgr.rows; ++r) {
    const auto* in = image_bgr.ptr<cv::Vec3b>(r);
    const auto* m = mask.ptr<std::uint8_t>(r);
    for (int c = 0; c < image_bgr.cols; ++c) {
      if (m[c] != 0) *out++ = in[c];
    }
  }
  return row;
}

std::string Field(const std::string& field) { return "colour naive Bayes model: " + field; }

double ReadNumber(const cv::FileNode& node, const std::string& field) {
  if (!node.isReal() && !node.isInt()) throw BadInputError(Field(field + " must be a number"));
  const double value = static_cast<double>(node);
  if (!std::isfinite(value)) throw BadInputError(Field(field + " is not finite"));
  return value;
}

ColourHistogram ReadCounts(const cv::FileNode& node, const std::string& field) {
  if (!node.isSeq() || node.size() != static_cast<std::size_t>(kColourBinCount)) {
    throw BadInputError(
        Field(field + " must be a list of " + std::to_string(kColourBinCount) + " counts"));
  }
  ColourHistogram histogram;
  for (int i = 0; i < kColourBinCount; ++i) {
    const std::string item = field + "[" + std::to_string(i) + "]";
    histogram.counts[static_cast<std::size_t>(i)] = ReadNumber(node[i], item);
    if (histogram.counts[static_cast<std::size_t>(i)] < 0) {
      throw BadInputError(Field(item + " is negative"));
    }
  }
  return histogram;
}

}  // namespace

std::string_view ColourBinName(ColourBin bin) { return kNames.at(static_cast<std::size_t>(bin)); }

HueInterval ColourBinHueInterval(ColourBin bin) {
  if (bin == ColourBin::kBlack || bin == ColourBin::kWhite) {
    throw UsageError("colour bins: " + std::string(ColourBinName(bin)) + " has no hue interval");
  }
  return kHues.at(static_cast<std::size_t>(bin) - static_cast<std::size_t>(ColourBin::kRed));
}

ColourBin ColourBinOfHsv(double hue_deg, double saturation, double value) {
  if (value < kBlackBelowValue) return ColourBin::kBlack;
  if (saturation < kGreyBelowSaturation) {
    // White by the thesis when V > 90 %; other greys split by value (see the header).
    return value < kGreySplitValue ? ColourBin::kBlack : ColourBin::kWhite;
  }
  double h = std::fmod(hue_deg, 360.0);
  if (h < 0) h += 360.0;
  if (h < kHues[0].end_deg - 360.0) return ColourBin::kRed;  // the wrapped part of red
  for (std::size_t i = 0; i < kHues.size(); ++i) {
    if (h >= kHues[i].begin_deg && h < kHues[i].end_deg) {
      return static_cast<ColourBin>(static_cast<int>(ColourBin::kRed) + static_cast<int>(i));
    }
  }
  return ColourBin::kRed;  // not reached: the intervals cover [0, 360)
}

cv::Mat ColourBinImage(const cv::Mat& image_bgr) {
  CheckImage(image_bgr, "colour bins");
  cv::Mat bins;
  BinPixels(image_bgr, &bins);
  return bins;
}

double ColourHistogram::Total() const {
  double total = 0;
  for (double c : counts) total += c;
  return total;
}

ColourHistogram ColourHistogram::Normalised() const {
  Validate("colour histogram");
  const double total = Total();
  if (!(total > 0)) throw UsageError("colour histogram: cannot normalise an empty histogram");
  ColourHistogram shares;
  for (std::size_t i = 0; i < counts.size(); ++i) shares.counts[i] = counts[i] / total;
  return shares;
}

void ColourHistogram::Validate(std::string_view what) const {
  for (std::size_t i = 0; i < counts.size(); ++i) {
    if (!std::isfinite(counts[i]) || counts[i] < 0) {
      throw UsageError(std::string(what) + ": count of bin " + std::string(kNames[i]) +
                       " is negative or not finite");
    }
  }
}

ColourHistogram ComputeColourHistogram(const cv::Mat& image_bgr, const cv::Mat& mask) {
  CheckImage(image_bgr, "colour histogram");
  if (!mask.empty() && (mask.type() != CV_8UC1 || mask.size() != image_bgr.size())) {
    throw UsageError("colour histogram: mask must be CV_8UC1 of the image's size");
  }
  ColourHistogram histogram;
  if (!mask.empty() && cv::countNonZero(mask) == 0) return histogram;  // cvtColor rejects 0 px
  cv::Mat bins;
  BinPixels(mask.empty() ? image_bgr : MaskedRow(image_bgr, mask), &bins);
  for (int r = 0; r < bins.rows; ++r) {
    const auto* row = bins.ptr<std::uint8_t>(r);
    for (int c = 0; c < bins.cols; ++c) histogram.counts[row[c]] += 1.0;
  }
  return histogram;
}

void ColourNaiveBayesOptions::Validate() const {
  if (!(laplace_pseudocount > 0) || !std::isfinite(laplace_pseudocount)) {
    throw UsageError("colour naive Bayes: laplace_pseudocount must be > 0 and finite");
  }
}

ColourNaiveBayes::ColourNaiveBayes(const ColourNaiveBayesOptions& options) : options_(options) {
  options_.Validate();
}

void ColourNaiveBayes::Train(const std::string& class_name, const ColourHistogram& object) {
  if (class_name.empty()) throw UsageError("colour naive Bayes: empty class name");
  object.Validate("colour naive Bayes training object of class " + class_name);
  if (!(object.Total() > 0)) {
    throw UsageError("colour naive Bayes: empty training object for class " + class_name);
  }
  const auto it = std::find(names_.begin(), names_.end(), class_name);
  const auto k = static_cast<std::size_t>(it - names_.begin());
  if (it == names_.end()) {
    names_.push_back(class_name);
    counts_.emplace_back();
  }
  for (std::size_t i = 0; i < object.counts.size(); ++i) counts_[k].counts[i] += object.counts[i];
}

std::vector<double> ColourNaiveBayes::Scores(const ColourHistogram& object) const {
  if (names_.empty()) throw UsageError("colour naive Bayes: the model has no classes");
  object.Validate("colour naive Bayes object");
  if (!(object.Total() > 0)) throw UsageError("colour naive Bayes: empty object histogram");
  const double a = options_.laplace_pseudocount;
  std::vector<double> scores(names_.size(), 0.0);
  for (std::size_t k = 0; k < names_.size(); ++k) {
    const double log_total = std::log(counts_[k].Total() + kColourBinCount * a);
    for (std::size_t i = 0; i < object.counts.size(); ++i) {
      if (object.counts[i] == 0) continue;
      scores[k] += object.counts[i] * (std::log(counts_[k].counts[i] + a) - log_total);
    }
  }
  return scores;
}

ColourPrediction ColourNaiveBayes::Predict(const ColourHistogram& object) const {
  ColourPrediction prediction;
  prediction.scores = Scores(object);
  const auto best = std::max_element(prediction.scores.begin(), prediction.scores.end());
  prediction.best_class = static_cast<std::size_t>(best - prediction.scores.begin());
  prediction.best_name = names_[prediction.best_class];
  return prediction;
}

void ColourNaiveBayes::Write(cv::FileStorage& fs, const std::string& key) const {
  if (!fs.isOpened()) throw UsageError("colour naive Bayes: the file storage is not open");
  fs << key << "{";
  fs << "bins"
     << "[";
  for (std::string_view name : kNames) fs << std::string(name);
  fs << "]";
  fs << "laplace_pseudocount" << options_.laplace_pseudocount;
  fs << "classes"
     << "[";
  for (std::size_t k = 0; k < names_.size(); ++k) {
    fs << "{"
       << "name" << names_[k] << "counts"
       << "[:";
    for (double c : counts_[k].counts) fs << c;
    fs << "]"
       << "}";
  }
  fs << "]"
     << "}";
}

ColourNaiveBayes ColourNaiveBayes::Read(const cv::FileNode& node) {
  if (!node.isMap()) throw BadInputError(Field("expected a map"));
  const cv::FileNode bins = node["bins"];
  if (!bins.isSeq() || bins.size() != kNames.size()) {
    throw BadInputError(Field("bins must list the " + std::to_string(kColourBinCount) + " bins"));
  }
  for (int i = 0; i < kColourBinCount; ++i) {
    if (!bins[i].isString() ||
        static_cast<std::string>(bins[i]) != kNames[static_cast<std::size_t>(i)]) {
      throw BadInputError(Field("bins[" + std::to_string(i) + "] must be " +
                                std::string(kNames[static_cast<std::size_t>(i)])));
    }
  }
  ColourNaiveBayesOptions options;
  options.laplace_pseudocount = ReadNumber(node["laplace_pseudocount"], "laplace_pseudocount");
  if (!(options.laplace_pseudocount > 0)) {
    throw BadInputError(Field("laplace_pseudocount must be > 0"));
  }
  ColourNaiveBayes model(options);
  const cv::FileNode classes = node["classes"];
  if (!classes.isSeq()) throw BadInputError(Field("classes must be a list"));
  for (int k = 0; k < static_cast<int>(classes.size()); ++k) {
    const std::string field = "classes[" + std::to_string(k) + "]";
    const cv::FileNode name = classes[k]["name"];
    if (!name.isString() || static_cast<std::string>(name).empty()) {
      throw BadInputError(Field(field + ".name must be a non-empty string"));
    }
    const std::string class_name = static_cast<std::string>(name);
    if (std::find(model.names_.begin(), model.names_.end(), class_name) != model.names_.end()) {
      throw BadInputError(Field(field + ".name repeats class " + class_name));
    }
    model.names_.push_back(class_name);
    model.counts_.push_back(ReadCounts(classes[k]["counts"], field + ".counts"));
  }
  return model;
}

}  // namespace littermap::detect
