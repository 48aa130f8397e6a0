#pragma once
// Which topic of a bag fills which sensor role. littermap's own bags use the default names of
// bag/topics.hpp; a real robot publishes on /scan_front, /odometry/filtered,
// /camera/camera/color/image_raw... For each role the topic is, in this order:
//   1. the one the user named (`--topic ROLE=NAME`),
//   2. the default name, when the bag has it with the role's type,
//   3. the only topic of the role's message type (colour and depth images told apart by name:
//      a depth topic has "depth" in its name, a colour one and the colour camera's info have
//      not),
//   4. none — an error naming the candidates when there are several, so the user can choose.
// Roles: scan, odometry, imu, colour, depth, camera_info.

#include <map>
#include <string>
#include <vector>

#include "bag/bag_info.hpp"
#include "bag/topics.hpp"

namespace littermap::bag {

struct SensorRoles {
  RunTopics topics;
  // Role -> how its topic was found: "given", "default", "by type", "missing" or (from
  // FindSensorRoles only) "ambiguous". A missing role keeps its default name, and the stage that
  // needs it fails naming it.
  std::map<std::string, std::string> found;
  std::map<std::string, std::vector<std::string>> candidates;  // of the ambiguous roles
};

// The role names, in the order `info` lists them.
const std::vector<std::string>& SensorRoleNames();

// "ROLE=NAME" assignments -> role -> topic. Throws UsageError naming an unknown role or a
// malformed assignment.
std::map<std::string, std::string> ParseRoleAssignments(
    const std::vector<std::string>& assignments);

// Throws UsageError when a given topic is not in the bag or has the wrong type, BadInputError
// when a role has several candidates and none was given (naming them and the option).
SensorRoles ResolveSensorRoles(const BagInfo& info,
                               const std::map<std::string, std::string>& given = {},
                               const RunTopics& defaults = {});

// The same with the default names and nothing given, for showing (`info`): an ambiguous role
// is reported, not thrown.
SensorRoles FindSensorRoles(const BagInfo& info);

// The topic of a role ("scan", ...) in roles.topics.
const std::string& TopicOf(const SensorRoles& roles, const std::string& role);

// "ROLE: TOPIC (how)" for each role; an ambiguous one lists its candidates.
std::vector<std::string> DescribeSensorRoles(const SensorRoles& roles);

}  // namespace littermap::bag
