#include "cli/progress_display.hpp"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <string>

namespace littermap::cli {
namespace {

constexpr auto kTerminalRedraw = std::chrono::milliseconds(100);
constexpr auto kLogInterval = std::chrono::seconds(5);
constexpr int kBarWidth = 30;

std::string Percent(const Progress& progress) {
  if (progress.total == 0) return std::to_string(progress.done);
  const double fraction = static_cast<double>(progress.done) / static_cast<double>(progress.total);
  char text[64];
  std::snprintf(text, sizeof(text), "%5.1f%% (%llu/%llu)", 100.0 * fraction,
                static_cast<unsigned long long>(progress.done),
                static_cast<unsigned long long>(progress.total));
  return text;
}

}  // namespace

ProgressDisplay::ProgressDisplay() : terminal_(isatty(STDERR_FILENO) == 1) {}

void ProgressDisplay::Update(const Progress& progress) {
  const auto now = std::chrono::steady_clock::now();
  // Each task is throttled on its own, so runs surveyed side by side, whose tasks take turns,
  // each show their progress every interval; a task seen for the first time starts a new line.
  last_task_ = std::string(progress.task);
  const auto drawn = last_draw_of_task_.find(last_task_);
  const bool new_task = drawn == last_draw_of_task_.end();
  const bool finished = progress.total != 0 && progress.done >= progress.total;
  const auto interval = terminal_ ? kTerminalRedraw : kLogInterval;
  if (!new_task && !finished && now - drawn->second < interval) return;
  if (new_task && bar_open_) Finish();
  last_draw_of_task_[last_task_] = now;
  last_draw_ = now;

  if (!terminal_) {
    std::fprintf(stderr, "%s: %s\n", last_task_.c_str(), Percent(progress).c_str());
    return;
  }
  std::string bar;
  if (progress.total != 0) {
    const auto filled =
        std::min<std::uint64_t>(kBarWidth * progress.done / progress.total, kBarWidth);
    bar.assign(kBarWidth + 3, ' ');
    bar.front() = '[';
    bar[kBarWidth + 1] = ']';
    std::fill_n(bar.begin() + 1, filled, '#');
  }
  std::fprintf(stderr, "\r\033[K%s: %s%s", last_task_.c_str(), bar.c_str(),
               Percent(progress).c_str());
  std::fflush(stderr);
  bar_open_ = true;
}

void ProgressDisplay::Status(const std::string& line) {
  const auto now = std::chrono::steady_clock::now();
  if (!terminal_) {
    if (last_draw_ != std::chrono::steady_clock::time_point{} && now - last_draw_ < kLogInterval) {
      return;
    }
    last_draw_ = now;
    std::fprintf(stderr, "%s\n", line.c_str());
    return;
  }
  last_draw_ = now;
  std::fprintf(stderr, "\r\033[K%s", line.c_str());
  std::fflush(stderr);
  bar_open_ = true;
}

void ProgressDisplay::Finish() {
  if (bar_open_) std::fputc('\n', stderr);
  bar_open_ = false;
}

}  // namespace littermap::cli
