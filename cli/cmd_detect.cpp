// littermap detect BAG --run RUN_DIR [-o DIR] [--model MODEL] [--every N]
// Segments every n-th RGB-D frame, classifies the objects, places them with the run's
// trajectory and fuses the sightings into litter items: DIR/detections.csv and DIR/items.csv.

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>

#include "bag/tum_trajectory.hpp"
#include "cli/cli_context.hpp"
#include "cli/debug_frames.hpp"
#include "core/error.hpp"
#include "detect/item_fusion.hpp"
#include "detect/litter_classifier.hpp"
#include "detect/run_objects.hpp"

namespace littermap::cli {
namespace {

struct DetectArguments {
  std::string bag;
  std::string run_dir;
  std::string output;
  std::string trajectory;
  std::string model = LITTERMAP_DEFAULT_MODEL;
  std::string debug_frames;
  detect::RunObjectsOptions options;
  detect::FusionOptions fusion;
};

std::ofstream OpenCsv(const std::filesystem::path& file, const char* header) {
  std::ofstream out(file);
  if (!out) throw UsageError(file.string() + ": cannot create");
  out << header << '\n';
  return out;
}

void WriteItems(const std::filesystem::path& file, const std::vector<detect::LitterItem>& items,
                const detect::LitterClassifier& classifier, std::size_t clutter) {
  auto out = OpenCsv(file,
                     "id,class,x,y,z,size_m,confidence,views,litter,litter_probability,"
                     "first_seen_ns,last_seen_ns");
  for (auto item : items) {
    item.best_class = classifier.Decide(item.class_probabilities);
    item.confidence = item.class_probabilities[item.best_class];
    if (item.best_class == clutter) continue;
    double litter_probability = 0;
    for (std::size_t k = 0; k < item.class_probabilities.size(); ++k) {
      if (classifier.is_litter(k)) litter_probability += item.class_probabilities[k];
    }
    char line[320];
    std::snprintf(line, sizeof line, "%d,%s,%.3f,%.3f,%.3f,%.3f,%.3f,%d,%d,%.3f,%lld,%lld", item.id,
                  classifier.classes()[item.best_class].c_str(), item.position_world_m.x(),
                  item.position_world_m.y(), item.position_world_m.z(), item.size_m,
                  item.confidence, item.views, classifier.is_litter(item.best_class) ? 1 : 0,
                  litter_probability, static_cast<long long>(item.first_seen_ns),
                  static_cast<long long>(item.last_seen_ns));
    out << line << '\n';
  }
  if (!out.flush()) throw InternalError(file.string() + ": write failed");
}

void RunDetect(const DetectArguments& arguments, CliContext& context) {
  const std::filesystem::path run_dir = arguments.run_dir;
  const std::filesystem::path out_dir =
      arguments.output.empty() ? run_dir : std::filesystem::path(arguments.output);
  const auto trajectory_file = arguments.trajectory.empty()
                                   ? run_dir / "trajectory.tum"
                                   : std::filesystem::path(arguments.trajectory);
  const auto trajectory = bag::ReadTumTrajectory(trajectory_file);
  const auto classifier = detect::LitterClassifier::Load(arguments.model);
  const std::size_t clutter = classifier.ClassIndex("clutter");
  std::filesystem::create_directories(out_dir);
  if (!arguments.debug_frames.empty()) std::filesystem::create_directories(arguments.debug_frames);
  auto detections = OpenCsv(out_dir / "detections.csv",
                            "frame,stamp_ns,u,v,width_px,height_px,x,y,z,size_m,height_m,range_m,"
                            "class,confidence,litter_probability,item");
  detect::ItemFusion fusion(arguments.fusion, classifier.classes().size());
  std::vector<std::size_t> track_of_line;
  const auto result = detect::ForEachRunObject(
      arguments.bag, trajectory, arguments.options, context.Progress(),
      [&](const detect::PlacedObject& placed) {
        const detect::Classification c = classifier.Classify(placed.sample);
        long track = -1;
        if (c.best != clutter) {
          detect::Sighting sighting{placed.frame->index,     placed.frame->stamp_ns,
                                    placed.position_world_m, placed.object->size_m,
                                    placed.object->range_m,  c.probabilities};
          track = static_cast<long>(fusion.Add(sighting));
        }
        const cv::Rect& box = placed.object->box;
        char line[400];
        std::snprintf(line, sizeof line,
                      "%zu,%lld,%d,%d,%d,%d,%.3f,%.3f,%.3f,%.3f,%.3f,%.2f,%s,%.3f,%.3f,%ld",
                      placed.frame->index, static_cast<long long>(placed.frame->stamp_ns), box.x,
                      box.y, box.width, box.height, placed.position_world_m.x(),
                      placed.position_world_m.y(), placed.position_world_m.z(),
                      placed.object->size_m, placed.object->height_m, placed.object->range_m,
                      classifier.classes()[c.best].c_str(), c.probabilities[c.best],
                      c.litter_probability, track);
        detections << line << '\n';
      },
      [&](const detect::RgbdFrame& frame, const detect::FrameSegmentation& segmentation) {
        if (!arguments.debug_frames.empty())
          WriteDebugFrame(arguments.debug_frames, frame, segmentation);
      });
  context.FinishProgress();
  if (!detections.flush())
    throw InternalError((out_dir / "detections.csv").string() + ": write failed");
  const auto items = fusion.Items();
  WriteItems(out_dir / "items.csv", items, classifier, clutter);
  std::size_t litter = 0, natural = 0;
  for (const auto& item : items) {
    const std::size_t best = classifier.Decide(item.class_probabilities);
    if (best == clutter) continue;
    (classifier.is_litter(best) ? litter : natural) += 1;
  }
  if (result.frames_without_pose > 0) {
    context.Warn(std::to_string(result.frames_without_pose) +
                 " frames lay outside the trajectory and were skipped");
  }
  std::printf(
      "wrote %s: %zu frames, %zu objects, %zu litter items and %zu natural objects seen in >= %d "
      "views\n%s\n",
      out_dir.c_str(), result.frames, result.objects, litter, natural, arguments.fusion.min_views,
      SegmentationTimeLine(result).c_str());
}

}  // namespace

void RegisterDetectCommand(CLI::App& app, CliContext& context) {
  auto arguments = std::make_shared<DetectArguments>();
  CLI::App* command = context.AddCommand(
      app, "detect",
      "Detect and classify litter in a run's RGB-D frames: RUN_DIR/detections.csv (per frame) "
      "and RUN_DIR/items.csv (fused items)");
  command->add_option("BAG", arguments->bag, "Run bag directory")
      ->required()
      ->check(CLI::ExistingPath);
  command->add_option("--run", arguments->run_dir, "Run directory of `littermap reconstruct`")
      ->required()
      ->check(CLI::ExistingDirectory);
  command->add_option("-o,--output", arguments->output,
                      "Where to write (default: the run directory)");
  command
      ->add_option("--trajectory", arguments->trajectory,
                   "TUM trajectory to place objects with (default RUN_DIR/trajectory.tum; "
                   "e.g. the simulator's truth)")
      ->check(CLI::ExistingFile);
  command->add_option("--model", arguments->model, "Classifier model of `littermap train`")
      ->capture_default_str()
      ->check(CLI::ExistingFile);
  command->add_option("--every", arguments->options.every, "Process every n-th frame")
      ->capture_default_str();
  command
      ->add_option("--min-views", arguments->fusion.min_views,
                   "Frames an item must be seen in to be kept")
      ->capture_default_str();
  command
      ->add_option("--association-radius", arguments->fusion.association_radius_m,
                   "Sightings this close (m) are one item")
      ->capture_default_str();
  command->add_option("--debug-frames", arguments->debug_frames,
                      "Write a segmentation picture of every processed frame here");
  command->callback([arguments, &context] {
    context.run = [arguments, &context] { RunDetect(*arguments, context); };
  });
}

}  // namespace littermap::cli
