#pragma once
// Shows Progress reports on stderr: a redrawn bar on a terminal, otherwise a plain line at most
// every few seconds (and at each new task), so logs of long runs stay readable.

#include <chrono>
#include <map>
#include <string>

#include "core/progress.hpp"

namespace littermap::cli {

class ProgressDisplay {
 public:
  ProgressDisplay();
  void Update(const Progress& progress);
  // A status line of a long open-ended task: redrawn in place on a terminal, otherwise printed at
  // most every few seconds.
  void Status(const std::string& line);
  void Finish();  // ends a bar line so later output starts on a fresh line

 private:
  bool terminal_;
  bool bar_open_ = false;
  std::string last_task_;
  std::map<std::string, std::chrono::steady_clock::time_point> last_draw_of_task_;
  std::chrono::steady_clock::time_point last_draw_{};
};

}  // namespace littermap::cli
