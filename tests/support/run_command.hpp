#pragma once
// Runs the littermap executable in a shell and captures its exit code and output.

#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>

namespace littermap::test {

struct CommandResult {
  int exit_code = -1;
  std::string output;  // stdout and stderr together
};

// A path as one shell word (test paths hold no single quote).
inline std::string Quote(const std::filesystem::path& path) { return "'" + path.string() + "'"; }

// A shell command line, its stderr joined to its stdout.
inline CommandResult RunCommand(const std::string& command_line) {
  const std::string command = command_line + " 2>&1";
  CommandResult result;
  FILE* pipe = popen(command.c_str(), "r");
  if (pipe == nullptr) return result;
  std::array<char, 4096> buffer;
  std::size_t read = 0;
  while ((read = fread(buffer.data(), 1, buffer.size(), pipe)) > 0) {
    result.output.append(buffer.data(), read);
  }
  const int status = pclose(pipe);
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return result;
}

// With a file size limit (ulimit -f, in 512-byte blocks), writes beyond it fail as on a full disk.
inline CommandResult RunLittermap(const std::string& arguments,
                                  std::optional<int> file_size_limit_blocks = std::nullopt) {
  const std::string command = std::string(LITTERMAP_EXECUTABLE) + " " + arguments;
  if (!file_size_limit_blocks) return RunCommand(command);
  return RunCommand("ulimit -f " + std::to_string(*file_size_limit_blocks) + " && " + command);
}

}  // namespace littermap::test
