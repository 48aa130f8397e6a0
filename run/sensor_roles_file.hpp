#pragma once
// Which bag topic filled which sensor role in a run (bag/sensor_roles.hpp), resolved once per
// stage and written to RUN_DIR/sensor_roles.json, so a run says what it was made from:
//   {"scan": {"topic": "/scan_front", "found": "by type"}, ...}

#include <filesystem>
#include <map>
#include <string>

#include "bag/sensor_roles.hpp"

namespace littermap::run {

// The bag's roles: `given` (--topic ROLE=NAME) over `defaults`. Throws as ResolveSensorRoles.
bag::SensorRoles ResolveBagRoles(const std::filesystem::path& bag,
                                 const std::map<std::string, std::string>& given,
                                 const bag::RunTopics& defaults);

void WriteSensorRoles(const std::filesystem::path& file, const bag::SensorRoles& roles);

}  // namespace littermap::run
