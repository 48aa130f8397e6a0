// littermap eval segmentation BAG TRUTH_DIR [--min-pixels N] [--json]
// Segmentation IoU on the simulator's instance masks: every masked frame is segmented as
// `detect` does, and every litter and natural object it shows (with at least N pixels within
// the depth range) is scored by the IoU of the best-overlapping detected object.

#include <charconv>
#include <cstdio>
#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>

#include "cli/cli_context.hpp"
#include "core/csv_table.hpp"
#include "core/error.hpp"
#include "detect/frame_segmenter.hpp"
#include "detect/rgbd_frames.hpp"
#include "detect/segmentation_score.hpp"
#include "eval/detection_metrics.hpp"

namespace littermap::cli {
namespace {

struct SegmentationArguments {
  std::string bag;
  std::string truth_dir;
  int min_pixels = 100;
  bool json = false;
};

struct ClassScore {
  std::size_t objects = 0;
  double iou_sum = 0;
  std::size_t found = 0;  // IoU >= 0.5
};

void RunEvalSegmentation(const SegmentationArguments& arguments, CliContext& context) {
  const std::filesystem::path truth = arguments.truth_dir;
  std::map<int, std::string> class_of;
  for (const eval::TruthObject& object : eval::ReadTruthDirectory(truth)) {
    int id = 0;
    const auto [end, error] =
        std::from_chars(object.id.data(), object.id.data() + object.id.size(), id);
    if (error != std::errc() || end != object.id.data() + object.id.size()) {
      throw BadInputError(truth.string() + ": object id '" + object.id + "' is not an integer");
    }
    class_of[id] = object.litter ? object.class_name : std::string("natural");
  }
  std::map<std::size_t, std::filesystem::path> masks;
  ReadCsv(truth / "masks" / "index.csv", {"frame", "file"}, [&](const CsvRow& row) {
    masks[static_cast<std::size_t>(row.Number("frame"))] = truth / row.Text("file");
  });
  if (masks.size() < 2)
    throw BadInputError((truth / "masks/index.csv").string() + ": fewer than two masks");
  const std::size_t every = std::next(masks.begin())->first - masks.begin()->first;
  std::vector<int> ids;
  for (const auto& [id, name] : class_of) ids.push_back(id);

  const detect::RgbdFrameReader reader(arguments.bag, detect::RgbdFrameOptions{});
  detect::FrameSegmenter segmenter(detect::SegmentationOptions{});
  std::map<std::string, ClassScore> scores;
  std::uint64_t done = 0;
  const auto progress = context.Progress();
  reader.ForEach(every, [&](const detect::RgbdFrame& frame) {
    ReportProgress(progress, {"segmenting masked frames", ++done, masks.size()});
    const auto mask_file = masks.find(frame.index);
    if (mask_file == masks.end()) return;
    const cv::Mat mask = cv::imread(mask_file->second.string(), cv::IMREAD_UNCHANGED);
    if (mask.empty()) throw BadInputError(mask_file->second.string() + ": cannot read the mask");
    const auto segmentation =
        segmenter.Segment(frame.colour_bgr, frame.depth_mm, reader.intrinsics(),
                          detect::LevelledCamera(reader.T_base_camera(), frame.tilt));
    for (const auto& score :
         detect::ScoreSegmentation(segmentation, mask, frame.depth_mm, ids, arguments.min_pixels)) {
      for (const std::string& key : {class_of[score.object_id], std::string("all")}) {
        ClassScore& s = scores[key];
        ++s.objects;
        s.iou_sum += score.iou;
        s.found += score.iou >= 0.5 ? 1 : 0;
      }
    }
  });
  context.FinishProgress();
  nlohmann::ordered_json json;
  if (!arguments.json)
    std::printf("%-16s %8s %9s %13s\n", "class", "objects", "mean IoU", "IoU >= 0.5");
  for (const auto& [name, s] : scores) {
    const double mean = s.objects ? s.iou_sum / double(s.objects) : 0.0;
    const double share = s.objects ? double(s.found) / double(s.objects) : 0.0;
    json[name] = {{"objects", s.objects}, {"mean_iou", mean}, {"found_share", share}};
    if (!arguments.json)
      std::printf("%-16s %8zu %9.3f %13.3f\n", name.c_str(), s.objects, mean, share);
  }
  if (arguments.json) std::printf("%s\n", json.dump(2).c_str());
}

}  // namespace

void RegisterEvalSegmentationCommand(CLI::App& app, CliContext& context) {
  CLI::App* eval_command = app.get_subcommand("eval");
  auto arguments = std::make_shared<SegmentationArguments>();
  CLI::App* command = context.AddCommand(
      *eval_command, "segmentation",
      "Segmentation IoU of litter and natural objects on a simulated run's instance masks "
      "(objects in view and within the depth range; 'objects' counts object-frame pairs)");
  command->add_option("BAG", arguments->bag, "Run bag of `littermap simulate`")
      ->required()
      ->check(CLI::ExistingPath);
  command->add_option("TRUTH_DIR", arguments->truth_dir, "Its ground truth")
      ->required()
      ->check(CLI::ExistingDirectory);
  command
      ->add_option("--min-pixels", arguments->min_pixels,
                   "Score objects showing at least this many pixels with depth")
      ->capture_default_str();
  command->add_flag("--json", arguments->json,
                    "JSON: {CLASS: {objects, mean_iou, found_share}}, CLASS 'all' too");
  command->callback([arguments, &context] {
    context.run = [arguments, &context] { RunEvalSegmentation(*arguments, context); };
  });
}

}  // namespace littermap::cli
