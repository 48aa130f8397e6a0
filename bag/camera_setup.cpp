#include "bag/camera_setup.hpp"

#include "bag/bag_reader.hpp"
#include "bag/message_header.hpp"
#include "bag/message_stream.hpp"
#include "bag/transform_tree.hpp"
#include "core/error.hpp"

namespace littermap::bag {

CameraSetup ReadCameraSetup(const std::filesystem::path& bag, const RunTopics& topics,
                            Extrinsic extrinsic) {
  BagReader reader(bag);
  reader.RequireTopic(topics.camera_info, "camera info");
  CameraSetup setup;
  bool have_info = false;
  reader.SetTopicFilter({topics.camera_info});
  MessageStream stream(reader);
  while (auto message = stream.Next()) {
    if (const auto* info = std::get_if<msg::CameraInfo>(&message->message)) {
      setup.info = *info;
      have_info = true;
      break;
    }
  }
  if (!have_info) throw BadInputError(bag.string() + ": no message on " + topics.camera_info);

  // The optical frame is the configured one, or else the one the camera info names.
  const TransformTree tree = ReadTransformTree(reader, topics);
  auto T_base_camera = tree.LookupTransform(frames::kBase, topics.camera_frame);
  if (!T_base_camera && !setup.info.header.frame_id.empty()) {
    T_base_camera = tree.LookupTransform(frames::kBase, setup.info.header.frame_id);
  }
  if (T_base_camera) {
    setup.T_base_camera = ToIsometry(*T_base_camera);
  } else if (extrinsic == Extrinsic::kRequired) {
    throw BadInputError(
        bag.string() + ": no " + frames::kBase + " -> " + topics.camera_frame +
        (setup.info.header.frame_id.empty() || setup.info.header.frame_id == topics.camera_frame
             ? ""
             : " (or " + setup.info.header.frame_id + ")") +
        " transform on " + topics.tf_static + " or /tf");
  }
  return setup;
}

}  // namespace littermap::bag
