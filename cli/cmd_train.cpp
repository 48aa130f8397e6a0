// littermap samples (detect/sample_collection.hpp), train (detect/classifier_training.hpp)

#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "cli/cli_context.hpp"
#include "cli/option_checks.hpp"
#include "detect/classifier_training.hpp"
#include "detect/options_file.hpp"
#include "detect/sample_collection.hpp"
#include "run/detect_run.hpp"

namespace littermap::cli {
namespace {

struct SamplesArguments {
  std::string bag;
  std::string truth_dir;
  std::string output;
  std::string options_file;
  detect::SampleCollectionOptions options;
};

void RunSamples(const SamplesArguments& arguments, CliContext& context) {
  const detect::SampleCollection collection = detect::CollectSamples(
      arguments.bag, arguments.truth_dir, arguments.output, arguments.options, context.Progress());
  context.FinishProgress();
  std::printf("%s\n%s\n", detect::CollectionSummary(collection, arguments.output).c_str(),
              run::SegmentationTimeLine(collection.objects).c_str());
}

struct TrainArguments {
  std::vector<std::string> samples;
  std::string output;
  std::string validate;
  detect::ClassifierOptions options;
};

void RunTrain(const TrainArguments& arguments) {
  const detect::ClassifierTraining training =
      detect::TrainClassifier(arguments.samples, arguments.output, arguments.options);
  std::printf("%s\n", detect::TrainingSummaryText(training, arguments.output).c_str());
  if (arguments.validate.empty()) return;
  const detect::ClassifierValidation validation =
      detect::ValidateClassifier(training.classifier, detect::ReadSamples(arguments.validate));
  std::printf("\nheld-out samples: %zu\n%-30s %10s %16s\n", validation.samples, "method",
              "class acc.", "litter/natural acc.");
  for (const detect::MethodAccuracy& m : validation.methods) {
    std::printf("%-30s %10.3f %16.3f\n", detect::ClassifierMethodName(m.method), m.class_accuracy,
                m.litter_natural_accuracy);
  }
}

}  // namespace

void RegisterTrainCommands(CLI::App& app, CliContext& context) {
  auto samples = std::make_shared<SamplesArguments>();
  CLI::App* command = context.AddCommand(
      app, "samples",
      "Cut labelled object crops for training from a simulated run (labels from its truth)");
  command->add_option("BAG", samples->bag, "Run bag of `littermap simulate`")
      ->required()
      ->check(ExistingInput(InputKind::kFileOrFolder));
  command->add_option("--truth", samples->truth_dir, "The run's TRUTH_DIR")
      ->required()
      ->check(ExistingInput(InputKind::kFolder));
  command->add_option("-o,--output", samples->output, "Sample directory to write")->required();
  command->add_option("--every", samples->options.objects.every, "Process every n-th frame")
      ->capture_default_str()
      ->check(WholeNumber<std::size_t>(1, kMaxFrameStep));
  command->add_option("--debug-frames", samples->options.debug_frames,
                      "Write a segmentation picture of every processed frame here");
  command
      ->add_option("--options", samples->options_file,
                   "detect's YAML options file: its segmentation and frame keys cut the objects "
                   "(item keys do not apply; --every overrides it)")
      ->check(ExistingInput(InputKind::kFile));
  command
      ->add_option("--label-radius", samples->options.label_radius_m,
                   "An object within this distance (m) of a truth object takes its class")
      ->capture_default_str()
      ->check(FiniteRange(0.01, 10));
  command->callback([samples, command, &context] {
    if (!samples->options_file.empty()) {
      const std::size_t every = samples->options.objects.every;
      detect::FusionOptions unused;
      detect::ApplyOptionsFile(samples->options_file, &samples->options.objects, &unused);
      if (command->count("--every") > 0) samples->options.objects.every = every;
    }
    context.run = [samples, &context] { RunSamples(*samples, context); };
  });

  auto train = std::make_shared<TrainArguments>();
  command =
      context.AddCommand(app, "train", "Train the litter classifier from labelled object samples");
  command->add_option("SAMPLES", train->samples, "Sample directories (labels.csv + crops)")
      ->required()
      ->check(ExistingInput(InputKind::kFolder));
  command->add_option("-o,--output", train->output, "Model file to write (.yml.gz)")->required();
  command
      ->add_option("--validate", train->validate,
                   "Score every classifier of the thesis, alone and combined, on these samples")
      ->check(ExistingInput(InputKind::kFolder));
  command->add_option("--trees", train->options.trees, "Random forest size")
      ->capture_default_str()
      ->check(WholeNumber(1, 10000));
  command->add_option("--clusters", train->options.clusters_per_class, "K clusters per class")
      ->capture_default_str()
      ->check(WholeNumber(1, 100));
  command->add_option("--seed", train->options.seed, "Random seed")
      ->capture_default_str()
      ->check(Seed());
  command->callback([train, &context] { context.run = [train] { RunTrain(*train); }; });
}

}  // namespace littermap::cli
