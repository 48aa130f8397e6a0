#pragma once
// Reads the keys of one YAML mapping into option fields, remembering which keys were read so
// that Finish() can reject the unknown ones. Every error names the file and the dotted key.

#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>
#include <Eigen/Core>

namespace littermap {

// A YAML file (core/text_file.hpp's limits). Throws BadInputError "FILE: line N: not valid YAML:
// ..." or the file's read failure.
YAML::Node LoadYamlFile(const std::filesystem::path& path);

class YamlFields {
 public:
  // `node` must be a mapping (or null: no keys); `prefix` is its dotted key ("robot.laser").
  YamlFields(const YAML::Node& node, const std::filesystem::path& file, std::string prefix);

  void Read(const char* key, double& value);
  void Read(const char* key, bool& value);
  void Read(const char* key, int& value);
  void Read(const char* key, std::uint64_t& value);
  void Read(const char* key, std::string& value);
  void Read(const char* key, std::vector<Eigen::Vector2d>& points);  // [[x, y], ...]
  void Read(const char* key, std::map<std::string, double>& weights,
            const std::set<std::string>& allowed);
  // A nested mapping; Finish() of the returned fields must be called by the caller.
  YamlFields Child(const char* key);
  // The items of a sequence of mappings.
  std::vector<YamlFields> Children(const char* key);

  // Throws BadInputError for the first key that was never read.
  void Finish() const;
  // An error about `key` of this mapping.
  [[noreturn]] void Fail(const std::string& key, const std::string& what) const;
  std::string Name(const std::string& key) const;

 private:
  YAML::Node Get(const char* key);

  YAML::Node node_;
  std::filesystem::path file_;
  std::string prefix_;
  std::set<std::string> read_;
};

}  // namespace littermap
