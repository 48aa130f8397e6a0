#include "bag/sensor_roles.hpp"

#include <algorithm>

#include "bag/ros_codec.hpp"
#include "core/error.hpp"

namespace littermap::bag {
namespace {

struct Role {
  const char* name;
  std::string RunTopics::*topic;
  std::vector<std::string> types;
  int depth = 0;  // +1: "depth" in the name; -1: not; 0: either
};

const std::vector<Role>& Roles() {
  static const std::vector<Role> roles = {
      {"scan", &RunTopics::scan, {"sensor_msgs/msg/LaserScan"}},
      {"odometry", &RunTopics::odometry, {"nav_msgs/msg/Odometry"}},
      {"imu", &RunTopics::imu, {"sensor_msgs/msg/Imu"}},
      {"colour",
       &RunTopics::colour,
       {"sensor_msgs/msg/CompressedImage", "sensor_msgs/msg/Image"},
       -1},
      {"depth",
       &RunTopics::depth,
       {"sensor_msgs/msg/CompressedImage", "sensor_msgs/msg/Image"},
       +1},
      // The colour camera's: depth is registered to colour (bag/topics.hpp).
      {"camera_info", &RunTopics::camera_info, {"sensor_msgs/msg/CameraInfo"}, -1},
  };
  return roles;
}

bool Fits(const Role& role, const TopicInfo& topic) {
  if (std::find(role.types.begin(), role.types.end(), topic.type) == role.types.end()) {
    return false;
  }
  if (role.depth == 0) return true;
  const bool depth = topic.name.find("depth") != std::string::npos;
  return role.depth > 0 ? depth : !depth;
}

std::string Join(const std::vector<std::string>& names) {
  std::string text;
  for (const auto& name : names) text += (text.empty() ? "" : ", ") + name;
  return text;
}

}  // namespace

const std::vector<std::string>& SensorRoleNames() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> out;
    for (const Role& role : Roles()) out.push_back(role.name);
    return out;
  }();
  return names;
}

std::map<std::string, std::string> ParseRoleAssignments(
    const std::vector<std::string>& assignments) {
  std::map<std::string, std::string> given;
  for (const std::string& assignment : assignments) {
    const auto equals = assignment.find('=');
    const std::string role = assignment.substr(0, equals);
    if (equals == std::string::npos || equals + 1 == assignment.size()) {
      throw UsageError("--topic " + assignment + ": expected ROLE=TOPIC, e.g. scan=/scan_front");
    }
    const auto& names = SensorRoleNames();
    if (std::find(names.begin(), names.end(), role) == names.end()) {
      throw UsageError("--topic " + assignment + ": unknown role '" + role + "' (" + Join(names) +
                       ")");
    }
    given[role] = assignment.substr(equals + 1);
  }
  return given;
}

namespace {

SensorRoles Resolve(const BagInfo& info, const std::map<std::string, std::string>& given,
                    const RunTopics& defaults, bool strict) {
  SensorRoles roles;
  roles.topics = defaults;
  for (const Role& role : Roles()) {
    std::string& topic = roles.topics.*role.topic;
    if (auto it = given.find(role.name); it != given.end()) {
      const TopicInfo* named = info.FindTopic(it->second);
      if (named == nullptr) {
        throw UsageError("--topic " + std::string(role.name) + "=" + it->second +
                         ": the bag has no such topic");
      }
      if (std::find(role.types.begin(), role.types.end(), named->type) == role.types.end()) {
        throw UsageError("--topic " + std::string(role.name) + "=" + it->second + ": it has type " +
                         named->type + ", not " + Join(role.types));
      }
      topic = it->second;
      roles.found[role.name] = "given";
      continue;
    }
    const TopicInfo* default_topic = info.FindTopic(topic);
    if (default_topic != nullptr && Fits(role, *default_topic)) {
      roles.found[role.name] = "default";
      continue;
    }
    std::vector<std::string> candidates;
    for (const TopicInfo& candidate : info.topics) {
      if (Fits(role, candidate)) candidates.push_back(candidate.name);
    }
    if (candidates.size() > 1 && !strict) {
      roles.found[role.name] = "ambiguous";
      roles.candidates[role.name] = candidates;
      continue;
    }
    if (candidates.size() > 1) {
      throw BadInputError("the bag has " + std::to_string(candidates.size()) + " " + role.name +
                          " topics (" + Join(candidates) + "): choose one with --topic " +
                          role.name + "=TOPIC");
    }
    if (candidates.size() == 1) {
      topic = candidates.front();
      roles.found[role.name] = "by type";
    } else if (default_topic != nullptr && strict &&
               std::find(role.types.begin(), role.types.end(), default_topic->type) ==
                   role.types.end()) {
      // Read as the role's type, its messages would decode as garbage or not at all.
      throw BadInputError("topic '" + topic + "' has type " + default_topic->type + ", not " +
                          Join(role.types) + ": name the " + role.name + " topic with --topic " +
                          role.name + "=TOPIC");
    } else {
      roles.found[role.name] = "missing";
    }
  }
  return roles;
}

}  // namespace

SensorRoles ResolveSensorRoles(const BagInfo& info, const std::map<std::string, std::string>& given,
                               const RunTopics& defaults) {
  return Resolve(info, given, defaults, true);
}

SensorRoles FindSensorRoles(const BagInfo& info) { return Resolve(info, {}, RunTopics{}, false); }

const std::string& TopicOf(const SensorRoles& roles, const std::string& role) {
  for (const Role& r : Roles()) {
    if (role == r.name) return roles.topics.*r.topic;
  }
  throw UsageError("unknown sensor role '" + role + "'");
}

std::vector<std::string> DescribeSensorRoles(const SensorRoles& roles) {
  std::vector<std::string> lines;
  for (const std::string& role : SensorRoleNames()) {
    const std::string found = roles.found.count(role) ? roles.found.at(role) : "missing";
    if (found == "missing") {
      lines.push_back(role + ": none");
    } else if (found == "ambiguous") {
      lines.push_back(role + ": one of " + Join(roles.candidates.at(role)) + " (--topic " + role +
                      "=TOPIC)");
    } else {
      lines.push_back(role + ": " + TopicOf(roles, role) + " (" + found + ")");
    }
  }
  return lines;
}

}  // namespace littermap::bag
