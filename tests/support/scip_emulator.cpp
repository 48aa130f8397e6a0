#include "support/scip_emulator.hpp"

#include <arpa/inet.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/ioctl.h>
#include <sys/socket.h>
#include <termios.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <stdexcept>
#include <utility>

#include "capture/scip_protocol.hpp"
#include "support/emulator_links.hpp"

namespace littermap::test {

namespace {

std::int64_t NowMs() {
  return std::chrono::duration_cast<std::chrono::milliseconds>(
             std::chrono::steady_clock::now().time_since_epoch())
      .count();
}

// "KEY:VALUE;S", the sum covering the ';' or not.
std::string InfoLine(const std::string& key, const std::string& value,
                     bool sum_includes_semicolon) {
  const std::string text = key + ":" + value;
  return text + ";" + capture::ScipChecksum(sum_includes_semicolon ? text + ";" : text) + "\n";
}

bool AllDigits(const std::string& s) {
  return std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; });
}

}  // namespace

std::uint32_t ScipEmulatorRangeMm(int step, int frame) {
  if (step % 100 == 7) return 1;
  return static_cast<std::uint32_t>(200 + 13 * step + 5 * frame);
}

ScipEmulator::ScipEmulator(Link link, const ScipEmulatorOptions& options)
    : link_(link), options_(options) {
  if (link_ == Link::kTcp) {
    const LoopbackListener listener = ListenOnLoopback("SCIP emulator");
    listen_fd_ = listener.fd;
    uri_ = "scip://127.0.0.1:" + std::to_string(listener.port);
  } else {
    const PseudoTerminal terminal = OpenPseudoTerminal("SCIP emulator");
    master_fd_ = terminal.master_fd;
    holder_fd_ = terminal.holder_fd;
    uri_ = "scip:" + terminal.device;
  }
  thread_ = std::thread([this] { Run(); });
}

ScipEmulator::~ScipEmulator() {
  stop_ = true;
  thread_.join();
  for (const int fd : {listen_fd_, master_fd_, holder_fd_}) {
    if (fd >= 0) ::close(fd);
  }
}

std::vector<std::string> ScipEmulator::commands() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return commands_;
}

void ScipEmulator::Run() {
  while (!stop_) {
    if (link_ == Link::kTcp) {
      pollfd p{listen_fd_, POLLIN, 0};
      if (::poll(&p, 1, 10) <= 0) continue;
      connection_fd_ = ::accept4(listen_fd_, nullptr, nullptr, SOCK_NONBLOCK | SOCK_CLOEXEC);
      if (connection_fd_ < 0) continue;
      Serve();
      ::close(connection_fd_);
    } else {
      if (master_fd_ < 0) return;  // hung up for good
      connection_fd_ = master_fd_;
      Serve();
      if (stop_) return;
      ::close(master_fd_);  // hangs up the client's side of the terminal
      ::close(holder_fd_);
      master_fd_ = holder_fd_ = -1;
    }
    connection_fd_ = -1;
  }
}

void ScipEmulator::Serve() {
  streaming_ = false;
  out_.clear();
  std::string in;
  while (!stop_) {
    const std::int64_t now = NowMs();
    int timeout_ms = 10;
    if (streaming_ && out_.empty()) {
      timeout_ms = static_cast<int>(std::clamp<std::int64_t>(next_frame_ms_ - now, 0, 10));
    }
    pollfd p{connection_fd_, static_cast<short>(POLLIN | (out_.empty() ? 0 : POLLOUT)), 0};
    ::poll(&p, 1, timeout_ms);
    if ((p.revents & POLLIN) != 0) {
      char chunk[1024];
      const ssize_t n = ::read(connection_fd_, chunk, sizeof chunk);
      if (n == 0 || (n < 0 && errno != EAGAIN && errno != EINTR)) return;  // client left
      if (n > 0) in.append(chunk, static_cast<std::size_t>(n));
      std::size_t end;
      while ((end = in.find_first_of("\r\n")) != std::string::npos) {
        const std::string command = in.substr(0, end);
        in.erase(0, end + 1);
        if (!command.empty()) Handle(command);
      }
    } else if ((p.revents & (POLLHUP | POLLERR)) != 0 && out_.empty()) {
      return;
    }
    if (!out_.empty()) {
      const ssize_t n = ::write(connection_fd_, out_.data(), out_.size());
      if (n > 0) out_.erase(0, static_cast<std::size_t>(n));
      if (n < 0 && errno != EAGAIN && errno != EINTR) return;
    }
    if (streaming_ && out_.empty() && NowMs() >= next_frame_ms_) {
      if (!disconnected_once_ && frames_sent_ == options_.disconnect_after_frames) {
        disconnected_once_ = true;
        WaitUntilDelivered();
        return;
      }
      QueueFrame();
      next_frame_ms_ += options_.scan_period_ms;
    }
  }
}

void ScipEmulator::WaitUntilDelivered() {
  // Closing a pseudo-terminal master discards what the client has not read yet (a TCP close does
  // not), so wait, a bounded time, until the client's input queue has stayed empty for a while.
  if (link_ != Link::kPseudoTerminal) return;
  int quiet_checks = 0;
  for (int i = 0; i < 200 && quiet_checks < 4 && !stop_; ++i) {
    int pending = 0;
    ::ioctl(holder_fd_, FIONREAD, &pending);
    quiet_checks = pending == 0 ? quiet_checks + 1 : 0;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
}

void ScipEmulator::Handle(const std::string& command) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    commands_.push_back(command);
  }
  if (command == "QT" && options_.ignores_qt && streaming_) {
    return;
  } else if (command == "QT") {
    streaming_ = false;
    out_ += "QT\n00P\n\n";
  } else if (command == "SCIP2.0") {
    out_ += "SCIP2.0\n" + options_.scip2_status_line + "\n\n";
  } else if (command == "VV") {
    out_ += VvReply();
  } else if (command == "PP") {
    out_ += PpReply();
  } else if (command.starts_with("MD") && command.size() == 15 && AllDigits(command.substr(2))) {
    const int first = std::atoi(command.substr(2, 4).c_str());
    const int last = std::atoi(command.substr(6, 4).c_str());
    const int cluster = std::max(std::atoi(command.substr(10, 2).c_str()), 1);
    if (first > last || last > options_.last_step || first < options_.first_step) {
      out_ += command + "\n" + capture::WithScipChecksum("04") + "\n\n";  // end step out of range
      return;
    }
    out_ += command + "\n00P\n\n";
    md_params_ = command.substr(2, 11);
    md_first_ = first;
    md_last_ = last;
    md_cluster_ = cluster;
    streaming_ = true;
    next_frame_ms_ = NowMs() + options_.scan_period_ms;
  } else {
    out_ += command + "\n" + capture::WithScipChecksum("0E") + "\n\n";  // undefined command
  }
}

std::string ScipEmulator::VvReply() const {
  return "VV\n00P\n" + InfoLine("VEND", "Hokuyo Automatic Co.,Ltd.", true) +
         InfoLine("PROD", "SOKUIKI Sensor TOP-URG UTM-30LX", true) +
         InfoLine("FIRM", "1.1.0(04/Feb./2010)", true) + InfoLine("PROT", "SCIP 2.0", true) +
         InfoLine("SERI", "H0000001", true) + "\n";
}

std::string ScipEmulator::PpReply() const {
  std::string dmax = InfoLine("DMAX", std::to_string(options_.max_distance_mm), false);
  if (options_.bad_checksum_pp) {
    char& sum = dmax[dmax.size() - 2];
    sum = static_cast<char>(0x30 + ((sum - 0x30 + 1) & 0x3F));
  }
  return "PP\n00P\n" + InfoLine("MODL", options_.model, false) +
         InfoLine("DMIN", std::to_string(options_.min_distance_mm), false) + dmax +
         InfoLine("ARES", std::to_string(options_.steps_per_revolution), false) +
         InfoLine("AMIN", std::to_string(options_.first_step), false) +
         InfoLine("AMAX", std::to_string(options_.last_step), false) +
         InfoLine("AFRT", std::to_string(options_.front_step), false) +
         InfoLine("SCAN", std::to_string(options_.motor_speed_rpm), false) + "\n";
}

void ScipEmulator::QueueFrame() {
  const int frame = frames_sent_;
  const std::string echo = "MD" + md_params_ + "00";  // remaining scans: 00 = unlimited
  ++frames_sent_;
  if (frame == options_.error_status_frame) {
    out_ += echo + "\n" + capture::WithScipChecksum("50") + "\n\n";
    return;
  }
  const std::uint32_t stamp =
      (options_.first_timestamp_ms + static_cast<std::uint32_t>(frame * options_.scan_period_ms)) &
      0xFFFFFFu;
  out_ += echo + "\n99b\n" + capture::WithScipChecksum(capture::ScipEncode(stamp, 4)) + "\n";
  std::string data;
  for (int step = md_first_; step <= md_last_; step += md_cluster_) {
    // A cluster reports its smallest valid reading (§8.1).
    std::uint32_t value = ScipEmulatorRangeMm(step, frame);
    for (int s = step + 1; s < std::min(step + md_cluster_, md_last_ + 1); ++s) {
      const std::uint32_t r = ScipEmulatorRangeMm(s, frame);
      if (value < static_cast<std::uint32_t>(options_.min_distance_mm) ||
          (r >= static_cast<std::uint32_t>(options_.min_distance_mm) && r < value)) {
        value = r;
      }
    }
    data += capture::ScipEncode(value, 3);
  }
  int line = 0;
  for (std::size_t i = 0; i < data.size(); ++line) {
    const std::size_t length = (frame == options_.long_line_frame && line == 0) ? 70 : 64;
    std::string text = capture::WithScipChecksum(data.substr(i, length));
    i += length;
    if (frame == options_.bad_checksum_frame && line == 1) {
      text.back() = static_cast<char>(0x30 + ((text.back() - 0x30 + 1) & 0x3F));
    }
    out_ += text + "\n";
  }
  out_ += "\n";
}

}  // namespace littermap::test
