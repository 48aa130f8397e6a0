#include "detect/segmentation_evaluation.hpp"

#include <charconv>
#include <iterator>
#include <vector>

#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>

#include "core/csv_table.hpp"
#include "core/error.hpp"
#include "detect/frame_segmenter.hpp"
#include "detect/rgbd_frames.hpp"
#include "detect/segmentation_score.hpp"
#include "eval/detection_metrics.hpp"
#include "eval/text_format.hpp"

namespace littermap::detect {
namespace {

struct ClassSums {
  std::size_t objects = 0;
  double iou_sum = 0;
  std::size_t found = 0;  // IoU >= 0.5
};

// The class of every truth object by its (integer) id, "natural" for the natural ones.
std::map<int, std::string> ClassesById(const std::filesystem::path& truth_dir) {
  std::map<int, std::string> class_of;
  for (const eval::TruthObject& object : eval::ReadTruthDirectory(truth_dir)) {
    int id = 0;
    const auto [end, error] =
        std::from_chars(object.id.data(), object.id.data() + object.id.size(), id);
    if (error != std::errc() || end != object.id.data() + object.id.size()) {
      throw BadInputError(truth_dir.string() + ": object id '" + object.id + "' is not an integer");
    }
    class_of[id] = object.litter ? object.class_name : std::string("natural");
  }
  return class_of;
}

}  // namespace

SegmentationEvaluation EvaluateSegmentation(const std::filesystem::path& bag,
                                            const std::filesystem::path& truth_dir,
                                            const SegmentationEvaluationOptions& options,
                                            const ProgressCallback& progress) {
  std::map<int, std::string> class_of = ClassesById(truth_dir);
  std::map<std::size_t, std::filesystem::path> masks;
  ReadCsv(truth_dir / "masks" / "index.csv", {"frame", "file"}, [&](const CsvRow& row) {
    masks[static_cast<std::size_t>(row.Number("frame"))] = truth_dir / row.Text("file");
  });
  if (masks.size() < 2)
    throw BadInputError((truth_dir / "masks/index.csv").string() + ": fewer than two masks");
  const std::size_t every = std::next(masks.begin())->first - masks.begin()->first;
  std::vector<int> ids;
  for (const auto& [id, name] : class_of) ids.push_back(id);

  const RgbdFrameReader reader(bag, RgbdFrameOptions{});
  FrameSegmenter segmenter(options.segmentation);
  std::map<std::string, ClassSums> sums;
  std::uint64_t done = 0;
  reader.ForEach(every, [&](const RgbdFrame& frame) {
    ReportProgress(progress, {"segmenting masked frames", ++done, masks.size()});
    const auto mask_file = masks.find(frame.index);
    if (mask_file == masks.end()) return;
    const cv::Mat mask = cv::imread(mask_file->second.string(), cv::IMREAD_UNCHANGED);
    if (mask.empty()) throw BadInputError(mask_file->second.string() + ": cannot read the mask");
    const auto segmentation =
        segmenter.Segment(frame.colour_bgr, frame.depth_mm, reader.intrinsics(),
                          LevelledCamera(reader.T_base_camera(), frame.tilt));
    for (const auto& score :
         ScoreSegmentation(segmentation, mask, frame.depth_mm, ids, options.min_depth_pixels)) {
      for (const std::string& key : {class_of[score.object_id], std::string("all")}) {
        ClassSums& s = sums[key];
        ++s.objects;
        s.iou_sum += score.iou;
        s.found += score.iou >= 0.5 ? 1 : 0;
      }
    }
  });
  SegmentationEvaluation evaluation;
  for (const auto& [name, s] : sums) {
    evaluation.classes[name] = {s.objects, s.objects ? s.iou_sum / double(s.objects) : 0.0,
                                s.objects ? double(s.found) / double(s.objects) : 0.0};
  }
  return evaluation;
}

std::string ToJson(const SegmentationEvaluation& evaluation) {
  nlohmann::ordered_json json;
  for (const auto& [name, c] : evaluation.classes) {
    json[name] = {{"objects", c.objects}, {"mean_iou", c.mean_iou}, {"found_share", c.found_share}};
  }
  return json.dump(2, ' ', false, nlohmann::json::error_handler_t::replace);
}

std::string ToText(const SegmentationEvaluation& evaluation) {
  std::string text;
  eval::AppendFormat(text, "%-16s %8s %9s %13s\n", "class", "objects", "mean IoU", "IoU >= 0.5");
  for (const auto& [name, c] : evaluation.classes) {
    eval::AppendFormat(text, "%-16s %8zu %9.3f %13.3f\n", name.c_str(), c.objects, c.mean_iou,
                       c.found_share);
  }
  text.pop_back();  // the caller ends the last line, as after ToJson
  return text;
}

}  // namespace littermap::detect
