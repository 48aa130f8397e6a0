#pragma once
// Tuning options from a YAML file (DESIGN.md: options are YAML files parsed into plain option
// structs; unknown keys are errors): a flat map of key: value, each key naming one field of an
// options struct through a setter. A stage lists its setters; this file reads, checks and
// applies them the same way for every stage:
//   key_frame_translation_m: 0.5
//   normal_step_px: 2

#include <cmath>
#include <filesystem>
#include <functional>
#include <map>
#include <string>
#include <type_traits>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "core/error.hpp"
#include "core/yaml_fields.hpp"

namespace littermap {

template <typename Options>
using OptionSetter = std::function<void(const YAML::Node&, Options*)>;
template <typename Options>
using OptionSetters = std::map<std::string, OptionSetter<Options>>;

// The node's value; numbers must be finite (YAML reads .nan and .inf as numbers). Throws
// YAML::Exception for a value of another type, BadInputError for a non-finite number.
template <typename T>
T OptionValue(const YAML::Node& node) {
  const T value = node.as<T>();
  if constexpr (std::is_floating_point_v<T>) {
    if (!std::isfinite(value)) throw BadInputError("must be a finite number");
  } else if constexpr (std::is_same_v<T, std::vector<double>>) {
    for (const double element : value) {
      if (!std::isfinite(element)) throw BadInputError("must be finite numbers");
    }
  }
  return value;
}

// A setter of one field: `field` maps the options to a reference to it.
template <typename T, typename Options, typename Field>
OptionSetter<Options> SetOption(Field field) {
  return
      [field](const YAML::Node& node, Options* options) { field(*options) = OptionValue<T>(node); };
}

// The value a name stands for, or BadInputError listing the names it takes.
template <typename Enum>
Enum OptionChoice(const std::map<std::string, Enum>& names, const YAML::Node& node) {
  const auto found = names.find(node.as<std::string>());
  if (found == names.end()) {
    std::string known;
    for (const auto& [name, value] : names) known += (known.empty() ? "" : ", ") + name;
    throw BadInputError("must be one of " + known);
  }
  return found->second;
}

// A setter of a named choice.
template <typename Options, typename Enum, typename Field>
OptionSetter<Options> SetOptionChoice(std::map<std::string, Enum> names, Field field) {
  return [names, field](const YAML::Node& node, Options* options) {
    field(*options) = OptionChoice(names, node);
  };
}

template <typename Options>
std::vector<std::string> OptionKeys(const OptionSetters<Options>& setters) {
  std::vector<std::string> keys;
  for (const auto& [key, setter] : setters) keys.push_back(key);
  return keys;
}

// Applies the file's keys to options, then options->Validate(): values each valid alone may
// still not go together. Throws BadInputError naming the file (and the key where there is one)
// for an unreadable file, an unknown key, a value of the wrong type or options that fail
// validation.
template <typename Options>
void ApplyOptionsFile(const std::filesystem::path& path, const OptionSetters<Options>& setters,
                      Options* options) {
  const YAML::Node root = LoadYamlFile(path);
  if (root.IsNull()) return;
  if (!root.IsMap()) throw BadInputError(path.string() + ": expected a map of option: value");
  for (const auto& entry : root) {
    const std::string key = entry.first.as<std::string>();
    const auto setter = setters.find(key);
    if (setter == setters.end()) {
      throw BadInputError(path.string() + ": unknown option '" + key + "'");
    }
    try {
      setter->second(entry.second, options);
    } catch (const YAML::Exception&) {
      throw BadInputError(path.string() + ": option '" + key + "' has a value of the wrong type");
    } catch (const BadInputError& e) {
      throw BadInputError(path.string() + ": option '" + key + "' " + e.what());
    }
  }
  try {
    options->Validate();
  } catch (const UsageError& e) {
    throw BadInputError(path.string() + ": " + e.what());
  }
}

}  // namespace littermap
