#include "detect/litter_classifier.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <random>

#include <opencv2/imgproc.hpp>

#include "core/error.hpp"
#include "support/temp_dir.hpp"

namespace littermap::detect {
namespace {

// Red cans (boxes), small yellow flowers (discs) and green-brown clutter (blotches), with
// colour noise, random size and rotation: separable by colour, shape and size together.
ObjectSample MakeSample(const std::string& label, std::mt19937& random) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::normal_distribution<double> noise(0.0, 10.0);
  ObjectSample s;
  s.label = label;
  const int size = 20 + static_cast<int>(20 * unit(random));
  s.colour_bgr = cv::Mat(size + 8, size + 8, CV_8UC3, cv::Scalar(50, 130, 60));
  s.mask = cv::Mat::zeros(s.colour_bgr.size(), CV_8U);
  const cv::Point2f centre(0.5f * float(s.mask.cols), 0.5f * float(s.mask.rows));
  cv::Scalar colour;
  if (label == "can") {
    const cv::RotatedRect box(centre, cv::Size2f(0.9f * float(size), 0.45f * float(size)),
                              float(180 * unit(random)));
    cv::Point2f corners[4];
    box.points(corners);
    std::vector<cv::Point> polygon(corners, corners + 4);
    cv::fillConvexPoly(s.mask, polygon, 255);
    colour = cv::Scalar(30, 30, 200);
    s.size_m = 0.12, s.width_m = 0.066, s.height_m = 0.066;
  } else if (label == "natural") {
    cv::circle(s.mask, centre, size / 4, 255, cv::FILLED);
    colour = cv::Scalar(20, 210, 230);
    s.size_m = 0.04, s.width_m = 0.04, s.height_m = 0.13;
  } else {
    for (int k = 0; k < 4; ++k) {
      cv::circle(s.mask,
                 centre + cv::Point2f(float(size * (unit(random) - 0.5) / 2),
                                      float(size * (unit(random) - 0.5) / 2)),
                 size / 6, 255, cv::FILLED);
    }
    colour = cv::Scalar(40, 90, 110);
    s.size_m = 0.15, s.width_m = 0.08, s.height_m = 0.02;
  }
  s.size_m *= 0.8 + 0.4 * unit(random);
  s.range_m = 1 + 3 * unit(random);
  for (int v = 0; v < s.mask.rows; ++v) {
    for (int u = 0; u < s.mask.cols; ++u) {
      if (!s.mask.at<std::uint8_t>(v, u)) continue;
      auto& p = s.colour_bgr.at<cv::Vec3b>(v, u);
      for (int c = 0; c < 3; ++c) p[c] = cv::saturate_cast<std::uint8_t>(colour[c] + noise(random));
    }
  }
  return s;
}

std::vector<ObjectSample> MakeSamples(int per_class, unsigned seed) {
  std::mt19937 random(seed);
  std::vector<ObjectSample> samples;
  for (int i = 0; i < per_class; ++i) {
    for (const char* label : {"can", "natural", "clutter"})
      samples.push_back(MakeSample(label, random));
  }
  return samples;
}

ClassifierOptions SmallForest() {
  ClassifierOptions options;
  options.trees = 30;
  return options;
}

TEST(LitterClassifier, LearnsSeparableClassesAndGeneralisesToNewSamples) {
  TrainingSummary summary;
  const auto classifier = LitterClassifier::Train(MakeSamples(30, 1), SmallForest(), &summary);
  ASSERT_EQ(classifier.classes().size(), 3u);
  EXPECT_TRUE(classifier.is_litter(classifier.ClassIndex("can")));
  EXPECT_FALSE(classifier.is_litter(classifier.ClassIndex("natural")));
  EXPECT_GE(summary.training_accuracy, 0.95);
  int correct = 0;
  const auto held_out = MakeSamples(20, 2);
  for (const auto& sample : held_out) {
    const Classification c = classifier.Classify(sample);
    correct += classifier.classes()[c.best] == sample.label;
    double total = 0;
    for (double p : c.probabilities) total += p;
    EXPECT_NEAR(total, 1.0, 1e-9);
  }
  // The classes differ in colour, shape and size at once: expect nearly all right.
  EXPECT_GE(correct, static_cast<int>(0.95 * double(held_out.size())));
  // Each thesis feature alone separates these colours too.
  for (const auto method :
       {ClassifierMethod::kNaiveBayes, ClassifierMethod::kGmmEnergy, ClassifierMethod::kEmd}) {
    int right = 0;
    for (const auto& sample : held_out)
      right += classifier.classes()[classifier.Predict(sample, method)] == sample.label;
    EXPECT_GE(right, static_cast<int>(0.9 * double(held_out.size())))
        << ClassifierMethodName(method);
  }
}

TEST(LitterClassifier, DecidesLitterWhenItIsMoreLikelyThanNot) {
  auto samples = MakeSamples(4, 6);
  for (int i = 0; i < 4; ++i) {  // a second litter class: "cup", relabelled cans
    ObjectSample cup = samples[static_cast<std::size_t>(3 * i)];
    cup.label = "cup";
    samples.push_back(cup);
  }
  const auto classifier = LitterClassifier::Train(samples, SmallForest(), nullptr);
  const auto& classes = classifier.classes();
  const auto index = [&](const std::string& name) {
    return static_cast<std::size_t>(std::find(classes.begin(), classes.end(), name) -
                                    classes.begin());
  };
  ASSERT_EQ(classes.size(), 4u);
  const auto decide = [&](double can, double cup, double natural, double clutter,
                          double min_litter_probability = 0.5) {
    std::vector<double> p(4);
    p[index("can")] = can, p[index("cup")] = cup, p[index("natural")] = natural;
    p[index("clutter")] = clutter;
    return classes[classifier.Decide(p, min_litter_probability)];
  };
  // Two litter classes sharing 0.55 beat a natural class of 0.45: the likelier litter class.
  EXPECT_EQ(decide(0.30, 0.25, 0.45, 0.0), "can");
  // 0.45 litter is less likely than not, though it beats natural (0.30) and clutter (0.25) alone.
  EXPECT_EQ(decide(0.25, 0.20, 0.30, 0.25), "natural");
  EXPECT_EQ(decide(0.25, 0.20, 0.20, 0.35), "clutter");
  EXPECT_EQ(decide(0.20, 0.30, 0.25, 0.25), "cup");  // a tie counts as litter
  // An item may ask for more than even odds: 0.55 litter is not enough for 0.6.
  EXPECT_EQ(decide(0.30, 0.25, 0.45, 0.0, 0.6), "natural");
  EXPECT_EQ(decide(0.35, 0.25, 0.40, 0.0, 0.6), "can");
}

TEST(LitterClassifier, SavedModelClassifiesExactlyAsTheTrainedOne) {
  test::TempDir dir;
  const auto classifier = LitterClassifier::Train(MakeSamples(15, 3), SmallForest(), nullptr);
  classifier.Save(dir / "model.yml.gz");
  const auto loaded = LitterClassifier::Load(dir / "model.yml.gz");
  EXPECT_EQ(loaded.classes(), classifier.classes());
  for (const auto& sample : MakeSamples(5, 4)) {
    EXPECT_EQ(loaded.Classify(sample).probabilities, classifier.Classify(sample).probabilities);
  }
}

TEST(LitterClassifier, RefusesOneClassAndForeignFiles) {
  auto samples = MakeSamples(2, 5);
  EXPECT_NO_THROW(LitterClassifier::Train(samples, SmallForest(), nullptr));  // K = 2 here
  for (auto& sample : samples) sample.label = "can";
  EXPECT_THROW(LitterClassifier::Train(samples, SmallForest(), nullptr), UsageError);
  test::TempDir dir;
  std::ofstream(dir / "model.yml") << "%YAML:1.0\nformat: something else\n";
  try {
    LitterClassifier::Load(dir / "model.yml");
    FAIL();
  } catch (const BadInputError& e) {
    EXPECT_NE(std::string(e.what()).find("format"), std::string::npos) << e.what();
  }
  EXPECT_THROW(LitterClassifier::Load(dir / "missing.yml"), BadInputError);
}

TEST(ObjectSamples, RoundTripThroughTheSampleDirectoryAndNameBadColumns) {
  test::TempDir dir;
  const auto samples = MakeSamples(2, 6);
  WriteSamples(dir / "s", samples);
  const auto read = ReadSamples(dir / "s");
  ASSERT_EQ(read.size(), samples.size());
  EXPECT_EQ(read[1].label, samples[1].label);
  EXPECT_NEAR(read[1].size_m, samples[1].size_m, 1e-4);
  EXPECT_EQ(cv::norm(read[1].colour_bgr, samples[1].colour_bgr, cv::NORM_INF), 0.0);  // PNG
  std::ofstream(dir / "s" / "labels.csv", std::ios::app)
      << "crop_000000.png,mask_000000.png,can,big,0,0,1\n";
  try {
    ReadSamples(dir / "s");
    FAIL();
  } catch (const BadInputError& e) {
    EXPECT_NE(std::string(e.what()).find("labels.csv:8: column 'size_m'"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace littermap::detect
