#include "detect/classifier_training.hpp"

#include <algorithm>
#include <iterator>
#include <utility>

#include "core/object_classes.hpp"
#include "eval/text_format.hpp"

namespace littermap::detect {

ClassifierTraining TrainClassifier(const std::vector<std::string>& sample_dirs,
                                   const std::filesystem::path& model,
                                   const ClassifierOptions& options) {
  std::vector<ObjectSample> samples;
  for (const auto& directory : sample_dirs) {
    auto more = ReadSamples(directory);
    samples.insert(samples.end(), std::make_move_iterator(more.begin()),
                   std::make_move_iterator(more.end()));
  }
  TrainingSummary summary;
  LitterClassifier classifier = LitterClassifier::Train(samples, options, &summary);
  classifier.Save(model);
  return {std::move(classifier), std::move(summary), samples.size()};
}

std::string TrainingSummaryText(const ClassifierTraining& training,
                                const std::filesystem::path& model) {
  std::string text;
  eval::AppendFormat(text, "wrote %s: %zu classes from %zu samples (training accuracy %.3f)",
                     model.c_str(), training.summary.samples_per_class.size(), training.samples,
                     training.summary.training_accuracy);
  for (const auto& [label, count] : training.summary.samples_per_class) {
    eval::AppendFormat(text, "\n  %-16s %zu samples used", label.c_str(), count);
  }
  return text;
}

ClassifierValidation ValidateClassifier(const LitterClassifier& classifier,
                                        const std::vector<ObjectSample>& samples) {
  ClassifierValidation validation;
  validation.samples = samples.size();
  for (const auto method :
       {ClassifierMethod::kNaiveBayes, ClassifierMethod::kGmmEnergy, ClassifierMethod::kEmd,
        ClassifierMethod::kHu, ClassifierMethod::kCombined}) {
    std::size_t correct = 0, split_correct = 0, split_total = 0;
    for (const auto& sample : samples) {
      const std::size_t predicted = classifier.Predict(sample, method);
      correct += predicted == classifier.ClassIndex(sample.label);
      if (sample.label == "clutter") continue;  // litter vs natural: objects of either kind
      ++split_total;
      split_correct += classifier.is_litter(predicted) == IsLitterClass(sample.label);
    }
    validation.methods.push_back(
        {method, double(correct) / double(std::max<std::size_t>(1, samples.size())),
         double(split_correct) / double(std::max<std::size_t>(1, split_total))});
  }
  return validation;
}

}  // namespace littermap::detect
