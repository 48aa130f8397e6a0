#pragma once
// Progress reporting from libraries without printing: long operations take a callback and the
// CLI decides how to show it (a bar on a terminal, plain lines otherwise, nothing with --quiet).

#include <cstdint>
#include <functional>
#include <string>
#include <string_view>

namespace littermap {

struct Progress {
  std::string_view task;  // what is being done, e.g. "importing intel-corrected.log.gz"
  std::uint64_t done = 0;
  std::uint64_t total = 0;  // 0 when unknown
};

using ProgressCallback = std::function<void(const Progress&)>;

// Something the user should know that does not stop the work (a damaged chunk read past, a
// missing sensor mounting), passed on as it happens so it reaches the user in order.
using WarningCallback = std::function<void(const std::string& warning)>;

// A callback that does nothing, for callers that do not care.
inline void ReportProgress(const ProgressCallback& callback, const Progress& progress) {
  if (callback) callback(progress);
}

}  // namespace littermap
