#include "bag/camera_setup.hpp"

#include "bag/bag_reader.hpp"
#include "bag/message_header.hpp"
#include "bag/message_stream.hpp"
#include "core/error.hpp"

namespace littermap::bag {

CameraSetup ReadCameraSetup(const std::filesystem::path& bag, const RunTopics& topics,
                            Extrinsic extrinsic) {
  BagReader reader(bag);
  reader.RequireTopic(topics.camera_info, "camera info");
  const bool need_tf = extrinsic == Extrinsic::kRequired;
  if (need_tf) reader.RequireTopic(topics.tf_static, "static transform");
  const bool has_tf = reader.info().FindTopic(topics.tf_static) != nullptr;
  CameraSetup setup;
  bool have_info = false, have_tf = false;
  reader.SetTopicFilter({topics.camera_info, topics.tf_static});
  MessageStream stream(reader);
  while (!have_info || (!have_tf && has_tf)) {
    const auto message = stream.Next();
    if (!message) break;
    if (const auto* info = std::get_if<msg::CameraInfo>(&message->message); info && !have_info) {
      setup.info = *info;
      have_info = true;
    }
    if (const auto* tf = std::get_if<msg::TFMessage>(&message->message)) {
      for (const auto& transform : tf->transforms) {
        if (transform.child_frame_id != topics.camera_frame) continue;
        setup.T_base_camera = ToIsometry(transform.transform);
        have_tf = true;
      }
    }
  }
  if (!have_info) throw BadInputError(bag.string() + ": no message on " + topics.camera_info);
  if (!have_tf && need_tf) {
    throw BadInputError(bag.string() + ": no " + frames::kBase + " -> " + topics.camera_frame +
                        " transform on " + topics.tf_static);
  }
  return setup;
}

}  // namespace littermap::bag
