#include "bag/contact_sheet.hpp"

#include <cmath>
#include <cstdio>
#include <map>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include <opencv2/imgproc.hpp>

#include "bag/image_codec.hpp"
#include "bag/message_stream.hpp"
#include "bag/topics.hpp"
#include "core/error.hpp"
#include "core/failure.hpp"

namespace littermap::bag {
namespace {

struct SheetRow {
  TimestampNs stamp_ns = 0;
  cv::Mat colour, depth;
  std::optional<msg::LaserScan> scan;
};

cv::Mat Fit(const cv::Mat& image, int width) {
  cv::Mat out;
  const double scale = static_cast<double>(width) / image.cols;
  cv::resize(image, out, {}, scale, scale, scale < 1 ? cv::INTER_AREA : cv::INTER_NEAREST);
  return out;
}

cv::Mat DepthPanel(const cv::Mat& depth_mm, int width, double depth_max_m) {
  cv::Mat scaled, colour;
  depth_mm.convertTo(scaled, CV_8U, 255.0 / (depth_max_m * 1000));
  cv::applyColorMap(scaled, colour, cv::COLORMAP_TURBO);
  colour.setTo(cv::Scalar(0, 0, 0), depth_mm == 0);
  return Fit(colour, width);
}

cv::Mat LaserPanel(const std::optional<msg::LaserScan>& scan, cv::Size size,
                   const ContactSheetOptions& options) {
  cv::Mat panel(size, CV_8UC3, cv::Scalar(30, 30, 30));
  const cv::Point2d centre(size.width / 2.0, size.height / 2.0);
  const double px_per_m = size.height / (2 * options.laser_extent_m);
  for (int ring = 1; ring <= static_cast<int>(options.laser_extent_m); ++ring) {
    cv::circle(panel, centre, static_cast<int>(ring * px_per_m), cv::Scalar(70, 70, 70), 1,
               cv::LINE_AA);
  }
  const double half_fov = options.camera_hfov_deg * std::numbers::pi / 360;
  for (const double side : {-1.0, 1.0}) {  // forward is up, left is left
    const cv::Point2d end = centre + cv::Point2d(-side * std::sin(half_fov), -std::cos(half_fov)) *
                                         (options.laser_extent_m * px_per_m);
    cv::line(panel, centre, end, cv::Scalar(0, 160, 220), 1, cv::LINE_AA);
  }
  cv::circle(panel, centre, 3, cv::Scalar(0, 0, 255), cv::FILLED);
  if (!scan) return panel;
  for (std::size_t i = 0; i < scan->ranges.size(); ++i) {
    const double r = scan->ranges[i];
    if (!std::isfinite(r) || r < scan->range_min || r > scan->range_max) continue;
    const double a = scan->angle_min + static_cast<double>(i) * scan->angle_increment;
    const cv::Point2d p = centre + cv::Point2d(-r * std::sin(a), -r * std::cos(a)) * px_per_m;
    cv::circle(panel, p, 1, cv::Scalar(255, 255, 255), cv::FILLED);
  }
  return panel;
}

void Label(cv::Mat& image, const std::string& text) {
  cv::putText(image, text, {6, 18}, cv::FONT_HERSHEY_SIMPLEX, 0.5, cv::Scalar(0, 0, 0), 3,
              cv::LINE_AA);
  cv::putText(image, text, {6, 18}, cv::FONT_HERSHEY_SIMPLEX, 0.5, cv::Scalar(255, 255, 255), 1,
              cv::LINE_AA);
}

std::map<std::uint64_t, SheetRow> ReadRows(BagReader& reader, const ContactSheetOptions& options) {
  const TopicInfo* colour_topic = reader.info().FindTopic(topics::kColor);
  if (colour_topic == nullptr || colour_topic->message_count == 0) {
    throw BadInputError(reader.directory().string() + ": no colour frames on " +
                        std::string(topics::kColor));
  }
  const std::uint64_t n = colour_topic->message_count;
  const std::uint64_t rows = std::min<std::uint64_t>(n, static_cast<std::uint64_t>(options.rows));
  std::map<std::uint64_t, SheetRow> chosen;
  for (std::uint64_t r = 0; r < rows; ++r) chosen[rows > 1 ? r * (n - 1) / (rows - 1) : 0];
  reader.SetTopicFilter({topics::kColor, topics::kDepth, topics::kScan});
  std::optional<BagMessage> last_scan;
  while (std::optional<BagMessage> message = reader.Next()) {
    const std::string& topic = message->topic->name;
    if (topic == topics::kScan) {
      last_scan = std::move(message);
      continue;
    }
    const auto row = chosen.find(message->index);
    if (row == chosen.end()) continue;
    const auto image = DecodeBagMessage<msg::CompressedImage>(reader, *message);
    if (topic == topics::kColor) {
      row->second.stamp_ns = message->timestamp_ns;
      row->second.colour = DecodeColor(image);
      if (last_scan) row->second.scan = DecodeBagMessage<msg::LaserScan>(reader, *last_scan);
    } else {
      row->second.depth = DecodeDepthMm(image);
    }
  }
  return chosen;
}

}  // namespace

ContactSheetResult WriteContactSheet(const std::filesystem::path& bag,
                                     const std::filesystem::path& png,
                                     const ContactSheetOptions& options) {
  BagReader reader(bag);
  const std::map<std::uint64_t, SheetRow> rows = ReadRows(reader, options);
  const TimestampNs start_ns = reader.info().starting_time_ns;
  const int width = options.tile_width_px;
  std::vector<cv::Mat> lines;
  for (const auto& [index, row] : rows) {
    cv::Mat colour = Fit(row.colour, width);
    char label[64];
    std::snprintf(label, sizeof label, "frame %llu  t = %.1f s",
                  static_cast<unsigned long long>(index), ToSeconds(row.stamp_ns - start_ns));
    Label(colour, label);
    const cv::Mat depth = row.depth.empty() ? cv::Mat(colour.size(), CV_8UC3, cv::Scalar::all(0))
                                            : DepthPanel(row.depth, width, options.depth_max_m);
    cv::Mat line;
    cv::hconcat(std::vector<cv::Mat>{colour, depth, LaserPanel(row.scan, colour.size(), options)},
                line);
    lines.push_back(line);
  }
  cv::Mat sheet;
  cv::vconcat(lines, sheet);
  WriteImageFile(png, sheet);
  return {static_cast<int>(rows.size()), sheet.cols, sheet.rows};
}

}  // namespace littermap::bag
