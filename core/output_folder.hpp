#pragma once
// The folder a command writes its outputs into (-o), checked before any work is done, so that a
// mistyped -o (the home folder, "/", a file) neither fails after an hour's reconstruction nor
// mixes littermap's files into someone else's.

#include <filesystem>
#include <string>
#include <vector>

namespace littermap {

struct OutputFolderCheck {
  std::string option = "-o";     // how the user named the folder, for the messages
  std::vector<std::string> own;  // the names littermap writes there (files and folders)
  bool force = false;            // write among other files all the same
};

// Creates `folder` when missing. Throws UsageError when it is a file, or holds names other than
// `check.own` (and the *.tmp files of an interrupted write) unless check.force, naming a few of
// them; throws FileFailure (environment, or bad input for a path that cannot be a folder) when
// it cannot be created or written.
void PrepareOutputFolder(const std::filesystem::path& folder, const OutputFolderCheck& check);

}  // namespace littermap
