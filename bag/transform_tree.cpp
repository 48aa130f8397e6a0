#include "bag/transform_tree.hpp"

#include "bag/bag_reader.hpp"
#include "bag/message_header.hpp"
#include "bag/message_stream.hpp"

namespace littermap::bag {
namespace {

constexpr double kFixedTranslationM = 1e-3;
constexpr double kFixedRotationRad = 0.1 * 3.14159265358979323846 / 180.0;
constexpr int kMaxDepth = 64;  // deeper is a cycle

bool Same(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b) {
  const Eigen::Isometry3d delta = a.inverse() * b;
  return delta.translation().norm() <= kFixedTranslationM &&
         Eigen::AngleAxisd(delta.linear()).angle() <= kFixedRotationRad;
}

}  // namespace

void TransformTree::Add(const msg::TFMessage& message, bool from_tf_static) {
  for (const msg::TransformStamped& transform : message.transforms) {
    const Eigen::Isometry3d T = ToIsometry(transform.transform);
    const Edge added{transform.header.frame_id, transform.transform, T, false};
    auto [it, inserted] = edges_.try_emplace(transform.child_frame_id, added);
    Edge& edge = it->second;
    if (inserted) continue;
    if (from_tf_static) {  // the latest static transform wins, as tf2 has it
      edge = added;
    } else if (edge.parent != transform.header.frame_id || !Same(edge.T_parent_child, T)) {
      edge.moves = true;
    }
  }
}

std::pair<std::string, Eigen::Isometry3d> TransformTree::FromRoot(const std::string& frame) const {
  Eigen::Isometry3d T_root_frame = Eigen::Isometry3d::Identity();
  std::string root = frame;
  for (int depth = 0; depth < kMaxDepth; ++depth) {
    const auto edge = edges_.find(root);
    if (edge == edges_.end() || edge->second.moves) break;
    T_root_frame = edge->second.T_parent_child * T_root_frame;
    root = edge->second.parent;
  }
  return {root, T_root_frame};
}

std::optional<Eigen::Isometry3d> TransformTree::Lookup(const std::string& parent,
                                                       const std::string& child) const {
  const auto [parent_root, T_root_parent] = FromRoot(parent);
  const auto [child_root, T_root_child] = FromRoot(child);
  if (parent_root != child_root) return std::nullopt;
  return T_root_parent.inverse() * T_root_child;
}

std::optional<msg::Transform> TransformTree::LookupTransform(const std::string& parent,
                                                             const std::string& child) const {
  if (const auto edge = edges_.find(child);
      edge != edges_.end() && edge->second.parent == parent && !edge->second.moves) {
    return edge->second.transform;
  }
  const auto T = Lookup(parent, child);
  if (!T) return std::nullopt;
  const Eigen::Quaterniond q(T->linear());
  msg::Transform transform;
  transform.translation = {T->translation().x(), T->translation().y(), T->translation().z()};
  transform.rotation = {q.x(), q.y(), q.z(), q.w()};
  return transform;
}

TransformTree ReadTransformTree(BagReader& reader, const RunTopics& topics) {
  TransformTree tree;
  const std::string tf = "/tf";
  std::vector<std::string> wanted;
  for (const std::string& topic : {topics.tf_static, tf}) {
    const TopicInfo* info = reader.info().FindTopic(topic);
    if (info != nullptr && info->type == MessageTraits<msg::TFMessage>::kTypeName) {
      wanted.push_back(topic);
    }
  }
  if (wanted.empty()) return tree;
  reader.SetTopicFilter(wanted);
  MessageStream stream(reader);
  while (auto message = stream.Next()) {
    if (const auto* transforms = std::get_if<msg::TFMessage>(&message->message)) {
      tree.Add(*transforms, message->topic->name == topics.tf_static);
    }
  }
  return tree;
}

}  // namespace littermap::bag
