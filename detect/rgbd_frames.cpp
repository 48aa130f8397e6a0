#include "detect/rgbd_frames.hpp"

#include <cmath>
#include <cstdlib>
#include <utility>

#include "capture/bag_reader.hpp"
#include "capture/image_codec.hpp"
#include "capture/message_header.hpp"
#include "capture/message_stream.hpp"
#include "core/error.hpp"

namespace littermap::detect {
namespace {

void RequireTopic(const BagReader& reader, const std::string& topic, const std::string& role,
                  std::uint64_t* count = nullptr) {
  for (const auto& info : reader.info().topics) {
    if (info.name != topic) continue;
    if (count != nullptr) *count = info.message_count;
    return;
  }
  throw BadInputError(reader.directory().string() + ": no " + role + " topic " + topic);
}

struct Pending {
  msg::CompressedImage image;
  TimestampNs stamp_ns = 0;
};

}  // namespace

RgbdFrameReader::RgbdFrameReader(std::filesystem::path bag, RgbdTopics topics)
    : bag_(std::move(bag)), topics_(std::move(topics)) {
  BagReader reader(bag_);
  RequireTopic(reader, topics_.colour, "colour image", &colour_count_);
  RequireTopic(reader, topics_.depth, "depth image");
  RequireTopic(reader, topics_.camera_info, "camera info");
  RequireTopic(reader, topics_.tf_static, "static transform");
  bool have_info = false, have_tf = false;
  reader.SetTopicFilter({topics_.camera_info, topics_.tf_static});
  MessageStream stream(reader);
  while ((!have_info || !have_tf)) {
    const auto message = stream.Next();
    if (!message) break;
    if (const auto* info = std::get_if<msg::CameraInfo>(&message->message); info && !have_info) {
      intrinsics_ = IntrinsicsFromCameraInfo(*info, bag_.string() + ": " + topics_.camera_info);
      have_info = true;
    }
    if (const auto* tf = std::get_if<msg::TFMessage>(&message->message)) {
      for (const auto& transform : tf->transforms) {
        if (transform.child_frame_id != topics_.camera_frame) continue;
        T_base_camera_ = ToIsometry(transform.transform);
        have_tf = true;
      }
    }
  }
  if (!have_info) throw BadInputError(bag_.string() + ": no message on " + topics_.camera_info);
  if (!have_tf) {
    throw BadInputError(bag_.string() + ": no " + frames::kBase + " -> " + topics_.camera_frame +
                        " transform on " + topics_.tf_static);
  }
}

void RgbdFrameReader::ForEach(std::size_t every,
                              const std::function<void(const RgbdFrame&)>& visit) const {
  if (every == 0) throw UsageError("detect: --every must be >= 1");
  BagReader reader(bag_);
  reader.SetTopicFilter({topics_.colour, topics_.depth, topics_.imu});
  const auto max_gap = static_cast<TimestampNs>(topics_.max_pair_gap_s * 1e9);
  const auto max_imu_age = static_cast<TimestampNs>(topics_.max_imu_age_s * 1e9);
  std::optional<Pending> colour, depth;
  std::optional<std::pair<TimestampNs, RollPitchYaw>> tilt;
  std::size_t colour_index = 0, wanted_index = 0;
  while (auto raw = reader.Next()) {
    const std::string& topic = raw->topic->name;
    if (topic == topics_.imu) {
      const auto imu = DecodeBagMessage<msg::Imu>(reader, *raw);
      RollPitchYaw rpy = RpyFromRotation(ToEigen(imu.orientation).normalized().toRotationMatrix());
      rpy.yaw_rad = 0;
      tilt.emplace(StampOf(imu.header), rpy);
      continue;
    }
    const bool is_colour = topic == topics_.colour;
    if (is_colour) {
      wanted_index = colour_index++;
      if (wanted_index % every != 0) {
        colour.reset();
        continue;
      }
    }
    auto image = DecodeBagMessage<msg::CompressedImage>(reader, *raw);
    const TimestampNs stamp_ns = StampOf(image.header);
    Pending pending{std::move(image), stamp_ns};
    (is_colour ? colour : depth) = std::move(pending);
    if (!colour || !depth || std::llabs(colour->stamp_ns - depth->stamp_ns) > max_gap) continue;
    RgbdFrame frame;
    frame.index = wanted_index;
    frame.stamp_ns = colour->stamp_ns;
    frame.colour_bgr = DecodeColor(colour->image);
    frame.depth_mm = DecodeDepthMm(depth->image);
    if (tilt && std::llabs(frame.stamp_ns - tilt->first) <= max_imu_age) frame.tilt = tilt->second;
    colour.reset();
    depth.reset();
    visit(frame);
  }
}

Eigen::Isometry3f LevelledCamera(const Eigen::Isometry3d& T_base_camera,
                                 const std::optional<RollPitchYaw>& tilt) {
  Eigen::Isometry3d T_level_base = Eigen::Isometry3d::Identity();
  if (tilt) T_level_base.linear() = RotationFromRpy(*tilt);
  return (T_level_base * T_base_camera).cast<float>();
}

}  // namespace littermap::detect
