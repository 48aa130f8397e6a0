#include "core/output_folder.hpp"

#include <algorithm>
#include <cerrno>
#include <fstream>
#include <system_error>

#include "core/error.hpp"
#include "core/failure.hpp"
#include "core/utf8.hpp"

namespace littermap {
namespace {

constexpr std::size_t kNamesShown = 3;

bool Own(const std::string& name, const std::vector<std::string>& own) {
  return name.ends_with(".tmp") || std::find(own.begin(), own.end(), name) != own.end();
}

}  // namespace

void PrepareOutputFolder(const std::filesystem::path& folder, const OutputFolderCheck& check) {
  RequireUtf8(folder.string(), check.option);
  const std::string where = check.option + " " + folder.string();
  std::error_code error;
  const std::filesystem::file_status status = std::filesystem::status(folder, error);
  if (std::filesystem::exists(status) && !std::filesystem::is_directory(status)) {
    throw UsageError(where + ": is a file, not a folder");
  }
  if (std::filesystem::is_directory(status) && !check.force) {
    std::vector<std::string> others;
    std::size_t count = 0;
    for (const auto& entry : std::filesystem::directory_iterator(folder, error)) {
      const std::string name = entry.path().filename().string();
      if (Own(name, check.own)) continue;
      if (others.size() < kNamesShown) others.push_back(name);
      ++count;
    }
    if (error) throw FileFailure(folder, "cannot list the folder", error.value());
    if (count > 0) {
      std::string names;
      for (const std::string& name : others) names += (names.empty() ? "" : ", ") + name;
      if (count > others.size()) names += ", …";
      throw UsageError(where + ": holds " + std::to_string(count) +
                       (count == 1 ? " file" : " files") + " littermap does not write there (" +
                       names + "); choose a new or empty folder, or give --force");
    }
  }
  if (!std::filesystem::create_directories(folder, error) && error) {
    throw FileFailure(folder, "cannot create the folder", error.value());
  }
  // Writable? A small file created and removed now, rather than a failure after the work.
  const std::filesystem::path probe = folder / ".littermap-write-test.tmp";
  {
    std::ofstream out(probe);
    if (!out) throw FileFailure(folder, "cannot write into the folder", errno);
  }
  std::filesystem::remove(probe, error);
}

}  // namespace littermap
