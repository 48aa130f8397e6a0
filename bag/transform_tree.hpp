#pragma once
// The fixed transforms of a robot as its bag records them: every transform on /tf_static, and
// every transform on /tf that never changes (many robots publish base_link -> laser there, with
// the moving odom -> base_link). Sensors hang off base_link through any chain of frames
// (base_link -> mast -> laser_front); Lookup composes the chain.

#include <map>
#include <optional>
#include <string>

#include <Eigen/Geometry>

#include "bag/ros_messages.hpp"
#include "bag/topics.hpp"

namespace littermap::bag {

class BagReader;

class TransformTree {
 public:
  // A transform that moves by more than 1 mm or 0.1° between two messages on /tf is not fixed:
  // it is left out (odom -> base_link).
  void Add(const msg::TFMessage& message, bool from_tf_static);

  // T_parent_child through the tree; nullopt when the two frames are not connected by fixed
  // transforms.
  std::optional<Eigen::Isometry3d> Lookup(const std::string& parent,
                                          const std::string& child) const;
  // The same as a message transform: the recorded one, bit for bit, when child hangs directly
  // off parent; the composed chain otherwise.
  std::optional<msg::Transform> LookupTransform(const std::string& parent,
                                                const std::string& child) const;

 private:
  struct Edge {
    std::string parent;
    msg::Transform transform;
    Eigen::Isometry3d T_parent_child;
    bool moves = false;  // seen to change on /tf
  };
  // T_root_frame and the root, walking up from frame.
  std::pair<std::string, Eigen::Isometry3d> FromRoot(const std::string& frame) const;

  std::map<std::string, Edge> edges_;  // by child frame: a tree has one parent per frame
};

// Every message on the bag's /tf_static and /tf (topics.tf_static, "/tf" beside it).
TransformTree ReadTransformTree(BagReader& reader, const RunTopics& topics);

}  // namespace littermap::bag
