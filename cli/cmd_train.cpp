// littermap samples BAG --truth TRUTH_DIR -o SAMPLES [--every N]
//   object crops of a simulated run, labelled from its ground truth (detect/object_sample.hpp)
// littermap train SAMPLES... -o MODEL [--validate SAMPLES]
//   the litter classifier (detect/litter_classifier.hpp), optionally scored on held-out samples

#include <cstdio>
#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "bag/tum_trajectory.hpp"
#include "cli/cli_context.hpp"
#include "cli/debug_frames.hpp"
#include "core/error.hpp"
#include "detect/litter_classifier.hpp"
#include "detect/run_objects.hpp"
#include "eval/detection_metrics.hpp"

namespace littermap::cli {
namespace {

struct SamplesArguments {
  std::string bag;
  std::string truth_dir;
  std::string output;
  std::string debug_frames;
  double label_radius_m = 0.2;
  detect::RunObjectsOptions options;
};

// The label of an object at xy: the class of the truth object within the radius, "clutter" when
// none is within twice the radius, empty (ambiguous: not a sample) in between.
std::string LabelAt(const std::vector<eval::TruthObject>& truth, const Eigen::Vector2d& xy,
                    double radius) {
  double best = 1e9;
  const eval::TruthObject* nearest = nullptr;
  for (const auto& object : truth) {
    const double d = (object.position_m - xy).norm();
    if (d < best) best = d, nearest = &object;
  }
  if (nearest != nullptr && best <= radius) {
    return nearest->litter ? nearest->class_name : std::string("natural");
  }
  return best > 2 * radius ? "clutter" : "";
}

void RunSamples(const SamplesArguments& arguments, CliContext& context) {
  const std::filesystem::path truth_dir = arguments.truth_dir;
  const auto truth = eval::ReadTruthDirectory(truth_dir);
  const auto trajectory = bag::ReadTumTrajectory(truth_dir / "trajectory.tum");
  std::vector<detect::ObjectSample> samples;
  std::map<std::string, int> counts;
  const std::string source = std::filesystem::path(arguments.bag).filename().string();
  if (!arguments.debug_frames.empty()) std::filesystem::create_directories(arguments.debug_frames);
  const auto result = detect::ForEachRunObject(
      arguments.bag, trajectory, arguments.options, context.Progress(),
      [&](const detect::PlacedObject& placed) {
        std::string label =
            LabelAt(truth, placed.position_world_m.head<2>(), arguments.label_radius_m);
        if (label.empty()) return;
        detect::ObjectSample sample = placed.sample;
        sample.label = label;
        sample.source = source + ":" + std::to_string(placed.frame->index);
        ++counts[label];
        samples.push_back(std::move(sample));
      },
      [&](const detect::RgbdFrame& frame, const detect::FrameSegmentation& segmentation) {
        if (!arguments.debug_frames.empty())
          WriteDebugFrame(arguments.debug_frames, frame, segmentation);
      });
  context.FinishProgress();
  detect::WriteSamples(arguments.output, samples);
  std::printf("wrote %s: %zu samples (", arguments.output.c_str(), samples.size());
  const char* separator = "";
  for (const auto& [label, count] : counts) {
    std::printf("%s%s %d", separator, label.c_str(), count);
    separator = ", ";
  }
  std::printf(")\n%s\n", SegmentationTimeLine(result).c_str());
}

struct TrainArguments {
  std::vector<std::string> samples;
  std::string output;
  std::string validate;
  detect::ClassifierOptions options;
};

void PrintValidation(const detect::LitterClassifier& classifier,
                     const std::vector<detect::ObjectSample>& validation) {
  using detect::ClassifierMethod;
  std::printf("\nheld-out samples: %zu\n%-30s %10s %16s\n", validation.size(), "method",
              "class acc.", "litter/natural acc.");
  for (const auto method :
       {ClassifierMethod::kNaiveBayes, ClassifierMethod::kGmmEnergy, ClassifierMethod::kEmd,
        ClassifierMethod::kHu, ClassifierMethod::kCombined}) {
    std::size_t correct = 0, split_correct = 0, split_total = 0;
    for (const auto& sample : validation) {
      const std::size_t predicted = classifier.Predict(sample, method);
      const std::size_t truth = classifier.ClassIndex(sample.label);
      correct += predicted == truth;
      if (sample.label == "clutter") continue;  // litter vs natural: objects of either kind
      ++split_total;
      split_correct += classifier.is_litter(predicted) == IsLitterClass(sample.label);
    }
    std::printf("%-30s %10.3f %16.3f\n", detect::ClassifierMethodName(method),
                double(correct) / double(std::max<std::size_t>(1, validation.size())),
                double(split_correct) / double(std::max<std::size_t>(1, split_total)));
  }
}

void RunTrain(const TrainArguments& arguments) {
  std::vector<detect::ObjectSample> samples;
  for (const auto& directory : arguments.samples) {
    auto more = detect::ReadSamples(directory);
    samples.insert(samples.end(), std::make_move_iterator(more.begin()),
                   std::make_move_iterator(more.end()));
  }
  detect::TrainingSummary summary;
  const auto classifier = detect::LitterClassifier::Train(samples, arguments.options, &summary);
  classifier.Save(arguments.output);
  std::printf("wrote %s: %zu classes from %zu samples (training accuracy %.3f)\n",
              arguments.output.c_str(), summary.samples_per_class.size(), samples.size(),
              summary.training_accuracy);
  for (const auto& [label, count] : summary.samples_per_class) {
    std::printf("  %-16s %zu samples used\n", label.c_str(), count);
  }
  if (!arguments.validate.empty())
    PrintValidation(classifier, detect::ReadSamples(arguments.validate));
}

}  // namespace

void RegisterTrainCommands(CLI::App& app, CliContext& context) {
  auto samples = std::make_shared<SamplesArguments>();
  CLI::App* command = context.AddCommand(
      app, "samples",
      "Cut labelled object crops for training from a simulated run (labels from its truth)");
  command->add_option("BAG", samples->bag, "Run bag of `littermap simulate`")
      ->required()
      ->check(CLI::ExistingPath);
  command->add_option("--truth", samples->truth_dir, "The run's TRUTH_DIR")
      ->required()
      ->check(CLI::ExistingDirectory);
  command->add_option("-o,--output", samples->output, "Sample directory to write")->required();
  command->add_option("--every", samples->options.every, "Process every n-th frame")
      ->capture_default_str();
  command->add_option("--debug-frames", samples->debug_frames,
                      "Write a segmentation picture of every processed frame here");
  command
      ->add_option("--label-radius", samples->label_radius_m,
                   "An object within this distance (m) of a truth object takes its class")
      ->capture_default_str();
  command->callback([samples, &context] {
    context.run = [samples, &context] { RunSamples(*samples, context); };
  });

  auto train = std::make_shared<TrainArguments>();
  command =
      context.AddCommand(app, "train", "Train the litter classifier from labelled object samples");
  command->add_option("SAMPLES", train->samples, "Sample directories (labels.csv + crops)")
      ->required()
      ->check(CLI::ExistingDirectory);
  command->add_option("-o,--output", train->output, "Model file to write (.yml.gz)")->required();
  command
      ->add_option("--validate", train->validate,
                   "Score every classifier of the thesis, alone and combined, on these samples")
      ->check(CLI::ExistingDirectory);
  command->add_option("--trees", train->options.trees, "Random forest size")->capture_default_str();
  command->add_option("--clusters", train->options.clusters_per_class, "K clusters per class")
      ->capture_default_str();
  command->add_option("--seed", train->options.seed, "Random seed")
      ->capture_default_str()
      ->check(CLI::NonNegativeNumber);
  command->callback([train, &context] { context.run = [train] { RunTrain(*train); }; });
}

}  // namespace littermap::cli
