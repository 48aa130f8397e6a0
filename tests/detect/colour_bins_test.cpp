// The thesis's nine colour bins (3.2) at their edges, the grey rule, histograms of masked
// objects, and the naive Bayes classifier: known scores, red vs green objects, model files.

#include "detect/colour_bins.hpp"

#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include <opencv2/core.hpp>

#include "core/error.hpp"

namespace littermap::detect {
namespace {

// Fully saturated, fully bright: only the hue decides.
ColourBin Hue(double hue_deg) { return ColourBinOfHsv(hue_deg, 1.0, 1.0); }

ColourBin Bgr(int b, int g, int r) {
  const cv::Mat pixel(1, 1, CV_8UC3, cv::Scalar(b, g, r));
  return static_cast<ColourBin>(ColourBinImage(pixel).at<std::uint8_t>(0));
}

TEST(ColourBins, HueEdgesFollowTheThesisRangesInWholeDegrees) {
  EXPECT_EQ(Hue(0), ColourBin::kRed);
  EXPECT_EQ(Hue(10), ColourBin::kRed);
  EXPECT_EQ(Hue(10.99), ColourBin::kRed);
  EXPECT_EQ(Hue(11), ColourBin::kOrange);
  EXPECT_EQ(Hue(48.99), ColourBin::kOrange);
  EXPECT_EQ(Hue(49), ColourBin::kYellow);
  EXPECT_EQ(Hue(67), ColourBin::kYellow);
  EXPECT_EQ(Hue(68), ColourBin::kGreen);
  EXPECT_EQ(Hue(150), ColourBin::kGreen);
  EXPECT_EQ(Hue(151), ColourBin::kCyan);
  EXPECT_EQ(Hue(206), ColourBin::kCyan);
  EXPECT_EQ(Hue(207), ColourBin::kBlue);
  EXPECT_EQ(Hue(259), ColourBin::kBlue);
  EXPECT_EQ(Hue(260), ColourBin::kMagenta);
  EXPECT_EQ(Hue(334.99), ColourBin::kMagenta);
  EXPECT_EQ(Hue(335), ColourBin::kRed);
  EXPECT_EQ(Hue(359.99), ColourBin::kRed);
  EXPECT_EQ(Hue(360), ColourBin::kRed) << "wrapped";
  EXPECT_EQ(Hue(-30), ColourBin::kMagenta) << "wrapped to 330";
  EXPECT_EQ(Hue(420), ColourBin::kYellow) << "wrapped to 60";
}

TEST(ColourBins, ValueAndSaturationRules) {
  EXPECT_EQ(ColourBinOfHsv(120, 1.0, 0.19), ColourBin::kBlack) << "V 19 %: black whatever hue";
  EXPECT_EQ(ColourBinOfHsv(120, 1.0, 0.20), ColourBin::kGreen) << "V 20 %: chromatic";
  EXPECT_EQ(ColourBinOfHsv(120, 0.09, 0.91), ColourBin::kWhite) << "S 9 %, V 91 %";
  EXPECT_EQ(ColourBinOfHsv(120, 0.10, 0.91), ColourBin::kGreen) << "S 10 % is chromatic";
  EXPECT_EQ(ColourBinOfHsv(0, 0.0, 0.05), ColourBin::kBlack);
  EXPECT_EQ(ColourBinOfHsv(0, 0.0, 1.0), ColourBin::kWhite);
}

TEST(ColourBins, GreysSplitByValueNotByTheirMeaninglessHue) {
  EXPECT_EQ(ColourBinOfHsv(0, 0.05, 0.30), ColourBin::kBlack);
  EXPECT_EQ(ColourBinOfHsv(120, 0.09, 0.49), ColourBin::kBlack);
  EXPECT_EQ(ColourBinOfHsv(120, 0.09, 0.50), ColourBin::kWhite);
  EXPECT_EQ(ColourBinOfHsv(240, 0.0, 0.90), ColourBin::kWhite);
}

TEST(ColourBins, BgrPixelsThroughOpenCvHsv) {
  EXPECT_EQ(Bgr(0, 0, 255), ColourBin::kRed);
  EXPECT_EQ(Bgr(0, 128, 255), ColourBin::kOrange);  // hue 30
  EXPECT_EQ(Bgr(0, 255, 255), ColourBin::kYellow);  // hue 60
  EXPECT_EQ(Bgr(0, 255, 0), ColourBin::kGreen);
  EXPECT_EQ(Bgr(255, 255, 0), ColourBin::kCyan);
  EXPECT_EQ(Bgr(255, 0, 0), ColourBin::kBlue);
  EXPECT_EQ(Bgr(255, 0, 255), ColourBin::kMagenta);
  EXPECT_EQ(Bgr(0, 0, 48), ColourBin::kBlack) << "V = 48/255 = 18.8 %";
  EXPECT_EQ(Bgr(0, 0, 52), ColourBin::kRed) << "V = 52/255 = 20.4 %";
  EXPECT_EQ(Bgr(250, 250, 250), ColourBin::kWhite);
  EXPECT_EQ(Bgr(100, 100, 100), ColourBin::kBlack) << "grey, V 39 %";
  EXPECT_EQ(Bgr(180, 180, 180), ColourBin::kWhite) << "grey, V 71 %";
  // Hue 10.6 degrees is red, 11.3 orange: the float conversion keeps sub-degree hue.
  EXPECT_EQ(Bgr(0, 45, 255), ColourBin::kRed);
  EXPECT_EQ(Bgr(0, 48, 255), ColourBin::kOrange);
}

TEST(ColourBins, HistogramCountsOnlyMaskedPixels) {
  cv::Mat image(4, 4, CV_8UC3, cv::Scalar(0, 0, 255));       // red
  image(cv::Rect(2, 0, 2, 4)).setTo(cv::Scalar(0, 255, 0));  // right half green
  cv::Mat mask = cv::Mat::zeros(4, 4, CV_8U);
  mask(cv::Rect(0, 0, 3, 1)).setTo(255);  // red, red, green
  mask.at<std::uint8_t>(3, 3) = 1;        // green
  const ColourHistogram h = ComputeColourHistogram(image, mask);
  EXPECT_EQ(h[ColourBin::kRed], 2);
  EXPECT_EQ(h[ColourBin::kGreen], 2);
  EXPECT_EQ(h.Total(), 4);
  EXPECT_EQ(ComputeColourHistogram(image, cv::Mat()).Total(), 16) << "no mask: every pixel";
  EXPECT_EQ(ComputeColourHistogram(image, cv::Mat::zeros(4, 4, CV_8U)).Total(), 0);
  const ColourHistogram shares = h.Normalised();
  EXPECT_DOUBLE_EQ(shares[ColourBin::kRed], 0.5);
  EXPECT_THROW(ComputeColourHistogram(image, cv::Mat::zeros(3, 4, CV_8U)), UsageError);
  EXPECT_THROW(ComputeColourHistogram(cv::Mat(4, 4, CV_8UC1), cv::Mat()), UsageError);
  EXPECT_THROW(ColourHistogram().Normalised(), UsageError);
}

ColourHistogram Counts(ColourBin bin, double count, ColourHistogram h = {}) {
  h[bin] += count;
  return h;
}

TEST(ColourNaiveBayes, ScoreIsTheSmoothedLogLikelihoodOfTheObjectsPixels) {
  ColourNaiveBayes model;  // pseudo-count 1
  model.Train("a", Counts(ColourBin::kRed, 3));
  model.Train("b", Counts(ColourBin::kGreen, 1, Counts(ColourBin::kRed, 1)));
  const ColourHistogram object = Counts(ColourBin::kRed, 2, Counts(ColourBin::kBlue, 1));
  const std::vector<double> scores = model.Scores(object);
  ASSERT_EQ(scores.size(), 2u);
  // a: p(red) = (3 + 1) / (3 + 9), p(blue) = 1 / 12; b: p(red) = 2 / 11, p(blue) = 1 / 11.
  EXPECT_NEAR(scores[0], 2 * std::log(4.0 / 12) + std::log(1.0 / 12), 1e-12);
  EXPECT_NEAR(scores[1], 2 * std::log(2.0 / 11) + std::log(1.0 / 11), 1e-12);
  EXPECT_TRUE(std::isfinite(scores[0])) << "an unseen bin costs a finite penalty";
}

// A synthetic object: mostly one colour, with some dark and bright pixels (shadow, glint).
ColourHistogram SyntheticObject(const cv::Scalar& bgr, int pixels, int seed) {
  cv::Mat image(1, pixels, CV_8UC3, bgr);
  cv::RNG rng(static_cast<std::uint64_t>(seed));
  cv::Mat noise(1, pixels, CV_32FC3);
  rng.fill(noise, cv::RNG::NORMAL, 0, 12);
  cv::Mat noisy;
  image.convertTo(noisy, CV_32FC3);
  noisy += noise;
  noisy.convertTo(image, CV_8UC3);
  image(cv::Rect(0, 0, pixels / 10, 1)).setTo(cv::Scalar(10, 10, 10));
  image(cv::Rect(pixels / 10, 0, pixels / 20, 1)).setTo(cv::Scalar(250, 250, 250));
  return ComputeColourHistogram(image, cv::Mat());
}

TEST(ColourNaiveBayes, SeparatesRedFromGreenObjects) {
  ColourNaiveBayes model;
  for (int i = 0; i < 5; ++i) {
    model.Train("red can", SyntheticObject(cv::Scalar(40, 30, 200), 400 + 50 * i, i));
    model.Train("grass", SyntheticObject(cv::Scalar(40, 160, 60), 400 + 50 * i, 100 + i));
  }
  const ColourPrediction red = model.Predict(SyntheticObject(cv::Scalar(30, 40, 210), 300, 7));
  EXPECT_EQ(red.best_name, "red can");
  EXPECT_EQ(red.best_class, 0u);
  EXPECT_GT(red.scores[0], red.scores[1]);
  const ColourPrediction green = model.Predict(SyntheticObject(cv::Scalar(50, 150, 70), 300, 8));
  EXPECT_EQ(green.best_name, "grass");
  const ColourPrediction blue = model.Predict(SyntheticObject(cv::Scalar(200, 40, 40), 300, 9));
  for (double s : blue.scores) EXPECT_TRUE(std::isfinite(s)) << "blue was never trained";
}

TEST(ColourNaiveBayes, RejectsMisuse) {
  ColourNaiveBayes model;
  EXPECT_THROW(model.Predict(Counts(ColourBin::kRed, 1)), UsageError) << "no classes";
  EXPECT_THROW(model.Train("", Counts(ColourBin::kRed, 1)), UsageError);
  EXPECT_THROW(model.Train("a", ColourHistogram()), UsageError) << "empty object";
  EXPECT_THROW(model.Train("a", Counts(ColourBin::kRed, -1)), UsageError);
  model.Train("a", Counts(ColourBin::kRed, 1));
  EXPECT_THROW(model.Predict(ColourHistogram()), UsageError);
  ColourNaiveBayesOptions options;
  options.laplace_pseudocount = 0;
  EXPECT_THROW(ColourNaiveBayes{options}, UsageError);
}

ColourNaiveBayes TrainedModel() {
  ColourNaiveBayesOptions options;
  options.laplace_pseudocount = 0.5;
  ColourNaiveBayes model(options);
  model.Train("litter", Counts(ColourBin::kRed, 1234.5, Counts(ColourBin::kWhite, 17)));
  model.Train("natural", Counts(ColourBin::kGreen, 0.1 + 0.2, Counts(ColourBin::kBlack, 3)));
  return model;
}

class ColourNaiveBayesFile : public testing::TestWithParam<const char*> {};

TEST_P(ColourNaiveBayesFile, RoundTripsExactly) {
  const ColourNaiveBayes model = TrainedModel();
  cv::FileStorage out(GetParam(), cv::FileStorage::WRITE | cv::FileStorage::MEMORY);
  model.Write(out, "colour_naive_bayes");
  const std::string text = out.releaseAndGetString();
  cv::FileStorage in(text, cv::FileStorage::READ | cv::FileStorage::MEMORY);
  const ColourNaiveBayes read = ColourNaiveBayes::Read(in["colour_naive_bayes"]);
  EXPECT_EQ(read.class_names(), model.class_names());
  EXPECT_EQ(read.options().laplace_pseudocount, 0.5);
  for (std::size_t k = 0; k < model.class_count(); ++k) {
    EXPECT_EQ(read.class_counts(k).counts, model.class_counts(k).counts) << "class " << k;
  }
  const ColourHistogram object = Counts(ColourBin::kRed, 5, Counts(ColourBin::kGreen, 2));
  EXPECT_EQ(read.Scores(object), model.Scores(object));
}

INSTANTIATE_TEST_SUITE_P(Formats, ColourNaiveBayesFile, testing::Values(".yml", ".json", ".xml"));

TEST(ColourNaiveBayesFile, MalformedModelNamesTheField) {
  const std::string yaml =
      "%YAML:1.0\n---\nm:\n  bins: [black, white, red, orange, yellow, green, cyan, blue, "
      "magenta]\n  laplace_pseudocount: 1.\n  classes:\n    - { name: a, counts: [1, 2, 3] }\n";
  cv::FileStorage in(yaml, cv::FileStorage::READ | cv::FileStorage::MEMORY);
  try {
    ColourNaiveBayes::Read(in["m"]);
    FAIL() << "expected BadInputError";
  } catch (const BadInputError& e) {
    EXPECT_NE(std::string(e.what()).find("classes[0].counts"), std::string::npos) << e.what();
  }
  EXPECT_THROW(ColourNaiveBayes::Read(in["missing"]), BadInputError);
}

}  // namespace
}  // namespace littermap::detect
