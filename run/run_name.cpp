#include "run/run_name.hpp"

#include "core/error.hpp"
#include "core/utf8.hpp"

namespace littermap::run {

std::string RunNameFromPath(const std::filesystem::path& dir) {
  std::filesystem::path folder = std::filesystem::absolute(dir).lexically_normal();
  if (!folder.has_filename()) folder = folder.parent_path();  // "week1/" normalises to "week1/"
  std::string name = folder.filename().string();
  static constexpr std::string_view kSurveySuffix = "-survey";
  if (name == "run" || name == "bag") {  // the layouts of survey (NAME-survey/run) and the demo
    std::string parent = folder.parent_path().filename().string();
    if (parent.size() > kSurveySuffix.size() && parent.ends_with(kSurveySuffix)) {
      parent.resize(parent.size() - kSurveySuffix.size());
    }
    if (!parent.empty()) name = parent;
  }
  if (name.empty() || name == "/") {
    throw UsageError(dir.string() + ": the run has no folder name to be called by; give --name");
  }
  CheckRunName(name, dir.string() + ": the folder name");
  return name;
}

std::string RunName(const std::string& given, const std::filesystem::path& dir) {
  if (given.empty()) return RunNameFromPath(dir);
  CheckRunName(given, "--name");
  return given;
}

void CheckRunName(const std::string& name, const std::string& what) {
  if (name.empty()) throw UsageError(what + ": a run name must not be empty");
  if (name.size() > kMaxRunNameBytes) {
    throw UsageError(what + ": a run name has at most " + std::to_string(kMaxRunNameBytes) +
                     " bytes, not " + std::to_string(name.size()));
  }
  RequireUtf8(name, what);
}

}  // namespace littermap::run
