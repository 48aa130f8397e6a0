#pragma once
// The litter classifier trained from sample directories and saved (`littermap train`), and every
// classifier of the thesis, alone and combined, scored on held-out samples.

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "detect/litter_classifier.hpp"
#include "detect/object_sample.hpp"

namespace littermap::detect {

struct ClassifierTraining {
  LitterClassifier classifier;
  TrainingSummary summary;
  std::size_t samples = 0;  // read from the directories
};

// Reads the samples of every directory (ReadSamples), trains on all of them and saves the model
// to `model`. Throws BadInputError for a sample directory at fault, UsageError for fewer than
// two classes.
ClassifierTraining TrainClassifier(const std::vector<std::string>& sample_dirs,
                                   const std::filesystem::path& model,
                                   const ClassifierOptions& options);

// What the training came to: "wrote MODEL: N classes from M samples (training accuracy A)" and a
// line per class with the samples used.
std::string TrainingSummaryText(const ClassifierTraining& training,
                                const std::filesystem::path& model);

struct MethodAccuracy {
  ClassifierMethod method = ClassifierMethod::kCombined;
  double class_accuracy = 0;           // over all samples
  double litter_natural_accuracy = 0;  // litter vs natural, over the samples of either kind
};

struct ClassifierValidation {
  std::size_t samples = 0;
  std::vector<MethodAccuracy> methods;  // naive Bayes, GMM energy, EMD, Hu, combined
};

// A ratio over no samples counts as 0.
ClassifierValidation ValidateClassifier(const LitterClassifier& classifier,
                                        const std::vector<ObjectSample>& samples);

}  // namespace littermap::detect
