#pragma once
// SIGINT and SIGTERM as a request to stop: while a StopOnSignals lives, either sets its flag;
// the first one resets the handler, so a second signal ends a program that does not stop.

#include <signal.h>

#include <atomic>

namespace littermap::cli {

inline std::atomic<bool> g_stop_requested{false};

extern "C" inline void RequestStop(int) { g_stop_requested.store(true); }

class StopOnSignals {
 public:
  StopOnSignals() {
    g_stop_requested.store(false);
    struct sigaction action {};
    action.sa_handler = RequestStop;
    action.sa_flags = SA_RESETHAND;
    sigemptyset(&action.sa_mask);
    sigaction(SIGINT, &action, &old_int_);
    sigaction(SIGTERM, &action, &old_term_);
  }
  ~StopOnSignals() {
    sigaction(SIGINT, &old_int_, nullptr);
    sigaction(SIGTERM, &old_term_, nullptr);
  }
  StopOnSignals(const StopOnSignals&) = delete;
  StopOnSignals& operator=(const StopOnSignals&) = delete;

  const std::atomic<bool>& stop_requested() const { return g_stop_requested; }

 private:
  struct sigaction old_int_ {};
  struct sigaction old_term_ {};
};

}  // namespace littermap::cli
