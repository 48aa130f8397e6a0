#pragma once
// A run's name in a site: what staff read in the report and GIS users in the layers. Given with
// --name or taken from the folder the run came from.

#include <filesystem>
#include <string>

namespace littermap::run {

// The name of the run in dir when none is given: the folder's own name ("week1" for "week1",
// "week1/" and "/data/week1/."); a folder called just "run" or "bag" is named after the folder
// holding it ("week1/bag": "week1"), that of a survey without its suffix ("week1-survey/run").
// Throws UsageError when the path names no folder ("/", "") and BadInputError when the name is not
// UTF-8.
std::string RunNameFromPath(const std::filesystem::path& dir);

// Throws UsageError (empty, or longer than kMaxRunNameBytes) or BadInputError (not UTF-8) naming
// `what`, the option or file it came from.
constexpr std::size_t kMaxRunNameBytes = 200;
void CheckRunName(const std::string& name, const std::string& what);

// The run's name: `given` (--name) checked, or when empty the name of `dir`.
std::string RunName(const std::string& given, const std::filesystem::path& dir);

}  // namespace littermap::run
