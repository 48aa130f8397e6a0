#include "support/emulator_links.hpp"

#include <arpa/inet.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <termios.h>
#include <unistd.h>

#include <cstdlib>
#include <stdexcept>

namespace littermap::test {
namespace {

void Check(bool ok, const std::string& emulator, const char* what) {
  if (!ok) throw std::runtime_error(emulator + ": " + what + " failed");
}

}  // namespace

LoopbackListener ListenOnLoopback(const std::string& emulator) {
  LoopbackListener out;
  out.fd = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
  Check(out.fd >= 0, emulator, "socket");
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  address.sin_port = 0;
  Check(::bind(out.fd, reinterpret_cast<sockaddr*>(&address), sizeof address) == 0, emulator,
        "bind");
  Check(::listen(out.fd, 4) == 0, emulator, "listen");
  socklen_t length = sizeof address;
  Check(::getsockname(out.fd, reinterpret_cast<sockaddr*>(&address), &length) == 0, emulator,
        "getsockname");
  out.port = ntohs(address.sin_port);
  return out;
}

PseudoTerminal OpenPseudoTerminal(const std::string& emulator) {
  PseudoTerminal out;
  out.master_fd = ::posix_openpt(O_RDWR | O_NOCTTY | O_CLOEXEC);
  Check(out.master_fd >= 0, emulator, "posix_openpt");
  Check(::grantpt(out.master_fd) == 0 && ::unlockpt(out.master_fd) == 0, emulator,
        "grantpt/unlockpt");
  char name[256];
  Check(::ptsname_r(out.master_fd, name, sizeof name) == 0, emulator, "ptsname_r");
  out.device = name;
  out.holder_fd = ::open(name, O_RDWR | O_NOCTTY | O_CLOEXEC);
  Check(out.holder_fd >= 0, emulator, "open pty slave");
  termios tio{};
  Check(::tcgetattr(out.holder_fd, &tio) == 0, emulator, "tcgetattr");
  ::cfmakeraw(&tio);  // no echo of what the emulator writes before the client opens the device
  Check(::tcsetattr(out.holder_fd, TCSANOW, &tio) == 0, emulator, "tcsetattr");
  Check(::fcntl(out.master_fd, F_SETFL, O_NONBLOCK) == 0, emulator, "fcntl");
  return out;
}

}  // namespace littermap::test
