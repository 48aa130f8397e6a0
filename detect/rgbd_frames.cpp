#include "detect/rgbd_frames.hpp"

#include <cmath>
#include <cstdlib>
#include <utility>

#include "capture/bag_reader.hpp"
#include "capture/camera_setup.hpp"
#include "capture/image_codec.hpp"
#include "capture/message_header.hpp"
#include "capture/message_stream.hpp"
#include "capture/rgbd_pairing.hpp"
#include "core/error.hpp"

namespace littermap::detect {

RgbdFrameReader::RgbdFrameReader(std::filesystem::path bag, RgbdTopics topics)
    : bag_(std::move(bag)), topics_(std::move(topics)) {
  {
    const BagReader reader(bag_);
    colour_count_ = reader.RequireTopic(topics_.colour, "colour image").message_count;
    reader.RequireTopic(topics_.depth, "depth image");
  }
  const CameraSetup setup =
      ReadCameraSetup(bag_, {topics_.camera_info, topics_.tf_static, topics_.camera_frame});
  intrinsics_ = IntrinsicsFromCameraInfo(setup.info, bag_.string() + ": " + topics_.camera_info);
  T_base_camera_ = setup.T_base_camera;
}

void RgbdFrameReader::ForEach(std::size_t every,
                              const std::function<void(const RgbdFrame&)>& visit) const {
  if (every == 0) throw UsageError("detect: --every must be >= 1");
  BagReader reader(bag_);
  reader.SetTopicFilter({topics_.colour, topics_.depth, topics_.imu});
  const auto max_imu_age = static_cast<TimestampNs>(topics_.max_imu_age_s * 1e9);
  RgbdPairing pairing(topics_.max_pair_gap_s);
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
        pairing.Reset();
        continue;
      }
    }
    auto image = DecodeBagMessage<msg::CompressedImage>(reader, *raw);
    const std::optional<CompressedRgbd> pair =
        is_colour ? pairing.AddColour(std::move(image)) : pairing.AddDepth(std::move(image));
    if (!pair) continue;
    RgbdFrame frame;
    frame.index = wanted_index;
    frame.stamp_ns = pair->stamp_ns;
    frame.colour_bgr = DecodeColor(pair->colour);
    frame.depth_mm = DecodeDepthMm(pair->depth);
    if (tilt && std::llabs(frame.stamp_ns - tilt->first) <= max_imu_age) frame.tilt = tilt->second;
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
