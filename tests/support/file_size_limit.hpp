#pragma once
// A full disk, made on demand: runs a function in a child process whose files may not grow past
// a size, with SIGXFSZ ignored (as littermap does), so a write past it fails with EFBIG as a full
// disk fails with ENOSPC.

#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <functional>

namespace littermap::test {

// The function's return value is the child's exit code; -1 when the child could not be started
// or did not exit by itself. The function must catch what it throws.
inline int RunWithFileSizeLimit(rlim_t limit_bytes, const std::function<int()>& function) {
  const pid_t child = fork();
  if (child < 0) return -1;
  if (child == 0) {
    signal(SIGXFSZ, SIG_IGN);
    const rlimit limit{limit_bytes, limit_bytes};
    setrlimit(RLIMIT_FSIZE, &limit);
    _exit(function());
  }
  int status = 0;
  if (waitpid(child, &status, 0) != child || !WIFEXITED(status)) return -1;
  return WEXITSTATUS(status);
}

}  // namespace littermap::test
