#pragma once
// The two links a fake sensor serves on: a TCP socket listening on loopback, and a
// pseudo-terminal standing in for a serial device. Both throw std::runtime_error naming the
// emulator and the call that failed.

#include <string>

namespace littermap::test {

struct LoopbackListener {
  int fd = -1;  // listening socket
  int port = 0;
};
LoopbackListener ListenOnLoopback(const std::string& emulator);

struct PseudoTerminal {
  int master_fd = -1;  // non-blocking; the emulator's side
  int holder_fd = -1;  // a raw-mode slave fd kept open so the master sees no hang-up early
  std::string device;  // "/dev/pts/N", for the client to open
};
PseudoTerminal OpenPseudoTerminal(const std::string& emulator);

}  // namespace littermap::test
