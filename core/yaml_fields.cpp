#include "core/yaml_fields.hpp"

#include <cmath>

#include "core/error.hpp"
#include "core/text_file.hpp"
#include "core/utf8.hpp"

namespace littermap {

YAML::Node LoadYamlFile(const std::filesystem::path& path) {
  const std::string text = ReadTextFile(path);
  try {
    return YAML::Load(text);
  } catch (const YAML::Exception& e) {
    throw BadInputError(path.string() + ": line " + std::to_string(e.mark.line + 1) +
                        ": not valid YAML: " + e.msg);
  }
}

YamlFields::YamlFields(const YAML::Node& node, const std::filesystem::path& file,
                       std::string prefix)
    : node_(node), file_(file), prefix_(std::move(prefix)) {
  if (node_ && !node_.IsNull() && !node_.IsMap()) {
    throw BadInputError(file_.string() + ": " + (prefix_.empty() ? "document" : prefix_) +
                        ": expected a mapping of keys");
  }
}

std::string YamlFields::Name(const std::string& key) const {
  return prefix_.empty() ? key : prefix_ + "." + key;
}

void YamlFields::Fail(const std::string& key, const std::string& what) const {
  throw BadInputError(file_.string() + ": " + Name(key) + ": " + what);
}

YAML::Node YamlFields::Get(const char* key) {
  read_.insert(key);
  // A key given without a value (null) counts as absent; const access never inserts keys.
  const YAML::Node& node = node_;
  if (!node || !node.IsMap()) return YAML::Node(YAML::NodeType::Undefined);
  YAML::Node value = node[key];
  if (!value || value.IsNull()) return YAML::Node(YAML::NodeType::Undefined);
  return value;
}

void YamlFields::Read(const char* key, double& value) {
  const YAML::Node node = Get(key);
  if (!node) return;
  try {
    value = node.as<double>();
  } catch (const YAML::Exception&) {
    Fail(key, "expected a number");
  }
  if (!std::isfinite(value)) Fail(key, "must be finite");
}

void YamlFields::Read(const char* key, bool& value) {
  const YAML::Node node = Get(key);
  if (!node) return;
  try {
    value = node.as<bool>();
  } catch (const YAML::Exception&) {
    Fail(key, "expected true or false");
  }
}

void YamlFields::Read(const char* key, int& value) {
  const YAML::Node node = Get(key);
  if (!node) return;
  try {
    value = node.as<int>();
  } catch (const YAML::Exception&) {
    Fail(key, "expected an integer");
  }
  if (value < 0) Fail(key, "must not be negative");
}

void YamlFields::Read(const char* key, std::uint64_t& value) {
  const YAML::Node node = Get(key);
  if (!node) return;
  try {
    value = node.as<std::uint64_t>();
  } catch (const YAML::Exception&) {
    Fail(key, "expected a non-negative integer");
  }
}

void YamlFields::Read(const char* key, std::string& value) {
  const YAML::Node node = Get(key);
  if (!node) return;
  if (!node.IsScalar()) Fail(key, "expected a string");
  value = node.as<std::string>();
  if (!IsUtf8(value)) Fail(key, "is not valid UTF-8");
}

void YamlFields::Read(const char* key, std::vector<Eigen::Vector2d>& points) {
  const YAML::Node node = Get(key);
  if (!node) return;
  if (!node.IsSequence()) Fail(key, "expected a list of [x, y] points");
  points.clear();
  for (std::size_t i = 0; i < node.size(); ++i) {
    const YAML::Node point = node[i];
    const std::string item = key + ("[" + std::to_string(i) + "]");
    if (!point.IsSequence() || point.size() != 2) Fail(item, "expected [x, y]");
    try {
      points.emplace_back(point[0].as<double>(), point[1].as<double>());
    } catch (const YAML::Exception&) {
      Fail(item, "expected two numbers");
    }
    if (!points.back().allFinite()) Fail(item, "must be finite");
  }
}

void YamlFields::Read(const char* key, std::map<std::string, double>& weights,
                      const std::set<std::string>& allowed) {
  const YAML::Node node = Get(key);
  if (!node) return;
  if (!node.IsMap()) Fail(key, "expected a mapping of class: weight");
  weights.clear();
  for (const auto& entry : node) {
    const std::string name = entry.first.as<std::string>();
    if (allowed.count(name) == 0) Fail(std::string(key) + "." + name, "unknown class");
    double weight = 0;
    try {
      weight = entry.second.as<double>();
    } catch (const YAML::Exception&) {
      Fail(std::string(key) + "." + name, "expected a number");
    }
    if (!(weight >= 0) || !std::isfinite(weight)) {
      Fail(std::string(key) + "." + name, "must be finite and not negative");
    }
    weights[name] = weight;
  }
}

YamlFields YamlFields::Child(const char* key) { return YamlFields(Get(key), file_, Name(key)); }

std::vector<YamlFields> YamlFields::Children(const char* key) {
  const YAML::Node node = Get(key);
  std::vector<YamlFields> children;
  if (!node) return children;
  if (!node.IsSequence()) Fail(key, "expected a list");
  for (std::size_t i = 0; i < node.size(); ++i) {
    children.emplace_back(node[i], file_, Name(key) + "[" + std::to_string(i) + "]");
  }
  return children;
}

void YamlFields::Finish() const {
  if (!node_ || !node_.IsMap()) return;
  for (const auto& entry : node_) {
    if (!entry.first.IsScalar()) {
      const std::string where = prefix_.empty() ? std::string("the top level") : prefix_;
      throw BadInputError(file_.string() + ": " + where + ": a key at line " +
                          std::to_string(entry.first.Mark().line + 1) +
                          " is not a plain name (a list or a map used as a key)");
    }
    const std::string key = entry.first.as<std::string>();
    if (read_.count(key) == 0) Fail(key, "unknown key");
  }
}

}  // namespace littermap
