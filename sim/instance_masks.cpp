#include "sim/instance_masks.hpp"

#include <cstdio>
#include <map>

#include <opencv2/imgcodecs.hpp>

#include "bag/image_codec.hpp"
#include "core/error.hpp"
#include "core/failure.hpp"

namespace littermap::sim {
namespace {

std::filesystem::path CreatedFolder(const std::filesystem::path& folder) {
  std::error_code error;
  std::filesystem::create_directories(folder, error);
  if (error) throw FileFailure(folder, "cannot create", error.value());
  return folder;
}

}  // namespace

cv::Mat InstanceIdsToMask(const cv::Mat& instance_ids) {
  if (instance_ids.type() != CV_32SC1) throw InternalError("instance ids are not CV_32SC1");
  cv::Mat mask(instance_ids.size(), CV_16UC1);
  for (int row = 0; row < instance_ids.rows; ++row) {
    const auto* in = instance_ids.ptr<std::int32_t>(row);
    auto* out = mask.ptr<std::uint16_t>(row);
    for (int col = 0; col < instance_ids.cols; ++col) {
      const std::int32_t id = in[col];
      if (id >= kMaskSky) throw InternalError("instance id does not fit a 16-bit mask");
      out[col] = id < 0 ? kMaskSky : static_cast<std::uint16_t>(id);
    }
  }
  return mask;
}

InstanceMaskWriter::InstanceMaskWriter(const std::filesystem::path& truth_dir)
    : directory_(CreatedFolder(truth_dir / "masks")),
      index_(directory_ / "index.csv"),
      visible_(directory_ / "visible.csv") {
  index_.stream() << "frame,stamp_ns,file\n";
  visible_.stream() << "frame,object_id,pixels,depth_pixels\n";
}

void InstanceMaskWriter::Write(std::size_t frame, TimestampNs stamp_ns, const cv::Mat& instance_ids,
                               const cv::Mat& depth_mm) {
  char name[32];
  std::snprintf(name, sizeof name, "frame_%06zu.png", frame);
  const std::filesystem::path path = directory_ / name;
  const cv::Mat mask = InstanceIdsToMask(instance_ids);
  std::map<std::uint16_t, std::pair<std::size_t, std::size_t>> pixels;  // all, with depth
  for (int row = 0; row < mask.rows; ++row) {
    const auto* value = mask.ptr<std::uint16_t>(row);
    const auto* depth = depth_mm.ptr<std::uint16_t>(row);
    for (int col = 0; col < mask.cols; ++col) {
      if (value[col] == kMaskGround || value[col] == kMaskSky) continue;
      auto& [all, with_depth] = pixels[value[col]];
      ++all;
      with_depth += depth[col] > 0 ? 1 : 0;
    }
  }
  for (const auto& [value, count] : pixels) {
    visible_.stream() << frame << ',' << value - 1 << ',' << count.first << ',' << count.second
                      << '\n';
  }
  bag::WriteImageFile(path, mask, {cv::IMWRITE_PNG_COMPRESSION, 3});
  index_.stream() << frame << ',' << stamp_ns << ",masks/" << name << '\n';
  ++written_;
}

void InstanceMaskWriter::Close() {
  index_.Commit();
  visible_.Commit();
}

}  // namespace littermap::sim
