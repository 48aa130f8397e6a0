// Training from sample directories and the thesis's classifiers scored on held-out samples:
// the model is saved, the summary counts what was used, every method is scored in order.

#include "detect/classifier_training.hpp"

#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "core/error.hpp"
#include "support/temp_dir.hpp"

namespace littermap::detect {
namespace {

// Red boxes (cans), yellow discs (natural) and brown blobs (clutter), with colour noise.
ObjectSample MakeTrainingSample(const std::string& label, std::mt19937& random) {
  std::normal_distribution<double> noise(0.0, 8.0);
  std::uniform_int_distribution<int> extra(0, 12);
  const int size = 24 + extra(random);
  ObjectSample s;
  s.label = label;
  s.colour_bgr = cv::Mat(size, size, CV_8UC3, cv::Scalar(50, 130, 60));
  s.mask = cv::Mat::zeros(s.colour_bgr.size(), CV_8U);
  cv::Scalar colour;
  if (label == "can") {
    cv::rectangle(s.mask, cv::Rect(3, size / 3, size - 6, size / 3), 255, cv::FILLED);
    colour = cv::Scalar(30, 30, 200), s.size_m = 0.12, s.height_m = 0.07;
  } else if (label == "natural") {
    cv::circle(s.mask, {size / 2, size / 2}, size / 4, 255, cv::FILLED);
    colour = cv::Scalar(20, 210, 230), s.size_m = 0.04, s.height_m = 0.13;
  } else {
    cv::circle(s.mask, {size / 3, size / 2}, size / 5, 255, cv::FILLED);
    cv::circle(s.mask, {2 * size / 3, size / 2}, size / 5, 255, cv::FILLED);
    colour = cv::Scalar(40, 90, 110), s.size_m = 0.15, s.height_m = 0.02;
  }
  s.width_m = 0.5 * s.size_m, s.range_m = 2;
  for (int v = 0; v < size; ++v) {
    for (int u = 0; u < size; ++u) {
      if (!s.mask.at<std::uint8_t>(v, u)) continue;
      for (int c = 0; c < 3; ++c) {
        s.colour_bgr.at<cv::Vec3b>(v, u)[c] =
            cv::saturate_cast<std::uint8_t>(colour[c] + noise(random));
      }
    }
  }
  return s;
}

std::vector<ObjectSample> MakeTrainingSamples(int per_class, unsigned seed) {
  std::mt19937 random(seed);
  std::vector<ObjectSample> samples;
  for (int i = 0; i < per_class; ++i) {
    for (const char* label : {"can", "natural", "clutter"})
      samples.push_back(MakeTrainingSample(label, random));
  }
  return samples;
}

TEST(ClassifierTraining, TrainsOnEveryDirectoryAndSavesTheModel) {
  test::TempDir dir;
  WriteSamples(dir / "a", MakeTrainingSamples(10, 1));
  WriteSamples(dir / "b", MakeTrainingSamples(5, 2));
  ClassifierOptions options;
  options.trees = 20;
  const ClassifierTraining training =
      TrainClassifier({(dir / "a").string(), (dir / "b").string()}, dir / "model.yml.gz", options);
  EXPECT_EQ(training.samples, 45u);
  ASSERT_EQ(training.summary.samples_per_class.size(), 3u);
  EXPECT_TRUE(std::filesystem::exists(dir / "model.yml.gz"));
  EXPECT_EQ(LitterClassifier::Load(dir / "model.yml.gz").classes(), training.classifier.classes());

  const std::string text = TrainingSummaryText(training, dir / "model.yml.gz");
  char first[512];
  std::snprintf(first, sizeof first, "wrote %s: 3 classes from 45 samples (training accuracy %.3f)",
                (dir / "model.yml.gz").c_str(), training.summary.training_accuracy);
  EXPECT_EQ(text.substr(0, text.find('\n')), first);
  const auto& [label, count] = training.summary.samples_per_class.front();
  char line[64];
  std::snprintf(line, sizeof line, "\n  %-16s %zu samples used", label.c_str(), count);
  EXPECT_NE(text.find(line), std::string::npos) << text;
  EXPECT_NE(text.back(), '\n');
}

TEST(ClassifierTraining, ScoresEveryMethodOnHeldOutSamples) {
  test::TempDir dir;
  WriteSamples(dir / "a", MakeTrainingSamples(15, 3));
  ClassifierOptions options;
  options.trees = 20;
  const ClassifierTraining training =
      TrainClassifier({(dir / "a").string()}, dir / "m.yml.gz", options);
  const ClassifierValidation validation =
      ValidateClassifier(training.classifier, MakeTrainingSamples(10, 4));
  EXPECT_EQ(validation.samples, 30u);
  ASSERT_EQ(validation.methods.size(), 5u);
  EXPECT_EQ(validation.methods.front().method, ClassifierMethod::kNaiveBayes);
  EXPECT_EQ(validation.methods.back().method, ClassifierMethod::kCombined);
  // Colour, shape and size all separate these classes: the combination gets nearly all right.
  EXPECT_GE(validation.methods.back().class_accuracy, 0.9);
  EXPECT_GE(validation.methods.back().litter_natural_accuracy, 0.9);
  for (const MethodAccuracy& m : validation.methods) {
    EXPECT_GE(m.class_accuracy, 0.0);
    EXPECT_LE(m.class_accuracy, 1.0);
  }
  // No held-out sample: ratios over nothing are 0.
  const ClassifierValidation none = ValidateClassifier(training.classifier, {});
  EXPECT_EQ(none.samples, 0u);
  EXPECT_EQ(none.methods.back().class_accuracy, 0.0);
}

TEST(ClassifierTraining, RefusesWhatItCannotTrainOn) {
  test::TempDir dir;
  EXPECT_THROW(TrainClassifier({(dir / "missing").string()}, dir / "m.yml.gz", {}), BadInputError);
  auto samples = MakeTrainingSamples(3, 5);
  for (auto& sample : samples) sample.label = "can";
  WriteSamples(dir / "one", samples);
  EXPECT_THROW(TrainClassifier({(dir / "one").string()}, dir / "m.yml.gz", {}), UsageError);
  EXPECT_FALSE(std::filesystem::exists(dir / "m.yml.gz"));
}

}  // namespace
}  // namespace littermap::detect
