#include "run/sensor_roles_file.hpp"

#include <nlohmann/json.hpp>

#include "bag/bag_reader.hpp"
#include "core/error.hpp"
#include "core/failure.hpp"
#include "core/output_file.hpp"

namespace littermap::run {

bag::SensorRoles ResolveBagRoles(const std::filesystem::path& bag,
                                 const std::map<std::string, std::string>& given,
                                 const bag::RunTopics& defaults) {
  const bag::BagReader reader(bag);
  try {
    return bag::ResolveSensorRoles(reader.info(), given, defaults);
  } catch (const BadInputError& e) {
    throw BadInputError(bag.string() + ": " + e.what());
  }
}

void WriteSensorRoles(const std::filesystem::path& file, const bag::SensorRoles& roles) {
  nlohmann::ordered_json json = nlohmann::ordered_json::object();
  for (const std::string& role : bag::SensorRoleNames()) {
    const auto found = roles.found.find(role);
    json[role] = {{"topic", bag::TopicOf(roles, role)},
                  {"found", found == roles.found.end() ? "missing" : found->second}};
  }
  WriteFileAtomically(file,
                      json.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n");
}

}  // namespace littermap::run
