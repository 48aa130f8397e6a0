#include "support/odometry_emulator.hpp"
#include "support/emulator_links.hpp"

#include <arpa/inet.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <termios.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <stdexcept>

namespace littermap::test {
namespace {

// Writes all of `text` to a non-blocking fd; false when the link is gone or the reader has not
// taken anything for 0.5 s.
bool WriteAll(int fd, bool socket, const std::string& text) {
  std::size_t done = 0;
  for (int stalls = 0; done < text.size();) {
    const ssize_t n = socket ? ::send(fd, text.data() + done, text.size() - done, MSG_NOSIGNAL)
                             : ::write(fd, text.data() + done, text.size() - done);
    if (n < 0 && (errno == EINTR || errno == EAGAIN)) {
      if (++stalls > 50) return false;
      pollfd p{fd, POLLOUT, 0};
      ::poll(&p, 1, 10);
      continue;
    }
    if (n <= 0) return false;
    done += static_cast<std::size_t>(n);
  }
  return true;
}

}  // namespace

capture::OdometryReading OdometryEmulatorReading(std::uint64_t k,
                                                 const OdometryEmulatorOptions& options) {
  capture::OdometryReading reading;
  const double t_s = static_cast<double>(k) / options.rate_hz;
  reading.time_ms = options.first_time_ms + static_cast<std::uint64_t>(std::llround(t_s * 1000));
  reading.T_odom_base = {0.5 * t_s, 0.02 * t_s, 0.05 * t_s};
  reading.linear_mps = 0.5;
  reading.angular_radps = 0.05;
  return reading;
}

OdometryEmulator::OdometryEmulator(Link link, const OdometryEmulatorOptions& options)
    : link_(link), options_(options) {
  if (link_ == Link::kTcp) {
    const LoopbackListener listener = ListenOnLoopback("odometry emulator");
    listen_fd_ = listener.fd;
    uri_ = "tcp://127.0.0.1:" + std::to_string(listener.port);
  } else {
    const PseudoTerminal terminal = OpenPseudoTerminal("odometry emulator");
    master_fd_ = terminal.master_fd;
    holder_fd_ = terminal.holder_fd;
    uri_ = "serial:" + terminal.device;
  }
  thread_ = std::thread([this] { Run(); });
}

OdometryEmulator::~OdometryEmulator() {
  stop_ = true;
  thread_.join();
  for (const int fd : {listen_fd_, master_fd_, holder_fd_}) {
    if (fd >= 0) ::close(fd);
  }
}

void OdometryEmulator::Run() {
  while (!stop_) {
    if (link_ == Link::kPseudoTerminal) {
      Stream(master_fd_);
      return;
    }
    pollfd p{listen_fd_, POLLIN, 0};
    if (::poll(&p, 1, 10) <= 0) continue;
    const int fd = ::accept4(listen_fd_, nullptr, nullptr, SOCK_NONBLOCK | SOCK_CLOEXEC);
    if (fd < 0) continue;
    Stream(fd);
    ::close(fd);
  }
}

void OdometryEmulator::Stream(int fd) {
  using Clock = std::chrono::steady_clock;
  const auto period = std::chrono::duration<double>(1.0 / options_.rate_hz);
  auto next = Clock::now();
  while (!stop_) {
    std::this_thread::sleep_until(next);
    next += std::chrono::duration_cast<Clock::duration>(period);
    const int k = readings_sent_.load();
    if (!disconnected_once_ && k == options_.disconnect_after_readings) {
      disconnected_once_ = true;
      return;
    }
    std::string line = capture::FormatOdometryLine(
        OdometryEmulatorReading(static_cast<std::uint64_t>(k), options_));
    if (options_.bad_checksum_every > 0 && k % options_.bad_checksum_every == 0) {
      line.back() = line.back() == '0' ? '1' : '0';
    }
    const std::string chatter = k % 10 == 0 ? "# battery 24.1 V\r\n" : "";
    // A pseudo-terminal without a reader fills up: readings are lost then, as on a serial line.
    if (!WriteAll(fd, link_ == Link::kTcp, chatter + line + "\r\n") && link_ == Link::kTcp) {
      return;
    }
    readings_sent_.fetch_add(1);
  }
}

}  // namespace littermap::test
