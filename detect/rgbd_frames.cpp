#include "detect/rgbd_frames.hpp"

#include <cmath>
#include <cstdlib>
#include <utility>

#include "bag/bag_reader.hpp"
#include "bag/camera_image.hpp"
#include "bag/camera_setup.hpp"
#include "bag/image_codec.hpp"
#include "bag/message_header.hpp"
#include "bag/message_stream.hpp"
#include "bag/rgbd_pairing.hpp"
#include "core/error.hpp"

namespace littermap::detect {

RgbdFrameReader::RgbdFrameReader(std::filesystem::path bag, RgbdFrameOptions options)
    : bag_(std::move(bag)), options_(std::move(options)) {
  {
    const bag::BagReader reader(bag_);
    colour_count_ = reader.RequireTopic(options_.topics.colour, "colour image").message_count;
    reader.RequireTopic(options_.topics.depth, "depth image");
  }
  const bag::CameraSetup setup = bag::ReadCameraSetup(bag_, options_.topics);
  intrinsics_ =
      IntrinsicsFromCameraInfo(setup.info, bag_.string() + ": " + options_.topics.camera_info);
  T_base_camera_ = setup.T_base_camera;
}

void RgbdFrameReader::ForEach(std::size_t every,
                              const std::function<void(const RgbdFrame&)>& visit) const {
  if (every == 0) throw UsageError("detect: --every must be >= 1");
  bag::BagReader reader(bag_);
  reader.SetStampSource(options_.stamps);
  reader.SetTopicFilter({options_.topics.colour, options_.topics.depth, options_.topics.imu});
  const auto max_imu_age = static_cast<TimestampNs>(options_.max_imu_age_s * 1e9);
  bag::RgbdPairing pairing(options_.max_pair_gap_s);
  std::optional<std::pair<TimestampNs, RollPitchYaw>> tilt;
  std::size_t colour_index = 0, wanted_index = 0;
  while (auto raw = reader.Next()) {
    const std::string& topic = raw->topic->name;
    if (topic == options_.topics.imu) {
      const auto imu = bag::DecodeBagMessage<msg::Imu>(reader, *raw);
      RollPitchYaw rpy =
          RpyFromRotation(bag::ToEigen(imu.orientation).normalized().toRotationMatrix());
      rpy.yaw_rad = 0;
      tilt.emplace(bag::StampOf(imu.header), rpy);
      continue;
    }
    const bool is_colour = topic == options_.topics.colour;
    if (is_colour) {
      wanted_index = colour_index++;
      if (wanted_index % every != 0) {
        pairing.Reset();
        continue;
      }
    }
    auto image = bag::DecodeCameraImage(reader, *raw);
    std::string origin = bag::MessageOrigin(reader, *raw);
    const std::optional<bag::CompressedRgbd> pair =
        is_colour ? pairing.AddColour(std::move(image), std::move(origin))
                  : pairing.AddDepth(std::move(image), std::move(origin));
    if (!pair) continue;
    RgbdFrame frame;
    frame.index = wanted_index;
    frame.stamp_ns = pair->stamp_ns;
    frame.colour_bgr = bag::DecodeColor(*pair);
    frame.depth_mm = bag::DecodeDepthMm(*pair);
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
