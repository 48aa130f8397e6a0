#pragma once
// --topic ROLE=TOPIC and --stamps header|recorded, for every command that reads sensors
// (bag/sensor_roles.hpp, bag/header_stamps.hpp).

#include <map>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "bag/header_stamps.hpp"
#include "bag/sensor_roles.hpp"

namespace littermap::cli {

struct SensorArguments {
  std::vector<std::string> topics;  // ROLE=TOPIC
  std::string stamps = "header";

  std::map<std::string, std::string> Roles() const { return bag::ParseRoleAssignments(topics); }
  bag::StampSource Stamps() const { return bag::ParseStampSource(stamps); }
};

inline void AddSensorOptions(CLI::App* command, SensorArguments& arguments) {
  command->add_option("--topic", arguments.topics,
                      "The topic of a sensor role, ROLE=TOPIC (roles: scan, odometry, imu, "
                      "colour, depth, camera_info); needed only when the bag has several "
                      "topics of the role's type. Repeatable");
  command
      ->add_option("--stamps", arguments.stamps,
                   "Which time a message has: its header stamp, or when it was recorded (for a "
                   "robot whose clock was wrong)")
      ->check(CLI::IsMember({"header", "recorded"}))
      ->capture_default_str();
}

}  // namespace littermap::cli
