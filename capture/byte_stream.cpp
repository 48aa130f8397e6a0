#include "capture/byte_stream.hpp"

#include <fcntl.h>
#include <netdb.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <sys/socket.h>
#include <termios.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstring>

namespace littermap::capture {

namespace {

int TimeoutMs(double timeout_s) {
  if (!(timeout_s > 0)) return 0;
  return static_cast<int>(std::min(std::ceil(timeout_s * 1000.0), 2'000'000'000.0));
}

std::string Errno() { return std::strerror(errno); }

// A file descriptor driven with poll(): a TCP socket or a serial/pseudo-terminal device.
class FdTransport : public ByteStream {
 public:
  FdTransport(int fd, bool is_socket, std::string uri)
      : fd_(fd), is_socket_(is_socket), uri_(std::move(uri)) {}
  ~FdTransport() override { ::close(fd_); }
  FdTransport(const FdTransport&) = delete;
  FdTransport& operator=(const FdTransport&) = delete;

  void Write(std::string_view bytes) override {
    while (!bytes.empty()) {
      const ssize_t n = is_socket_ ? ::send(fd_, bytes.data(), bytes.size(), MSG_NOSIGNAL)
                                   : ::write(fd_, bytes.data(), bytes.size());
      if (n < 0 && errno == EINTR) continue;
      if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) {
        pollfd p{fd_, POLLOUT, 0};
        if (::poll(&p, 1, 1000) <= 0 || (p.revents & (POLLERR | POLLHUP)) != 0) {
          throw SensorDisconnectedError(uri_ + ": sensor does not accept data");
        }
        continue;
      }
      if (n <= 0) throw SensorDisconnectedError(uri_ + ": write failed: " + Errno());
      bytes.remove_prefix(static_cast<std::size_t>(n));
    }
  }

  std::size_t Read(char* buffer, std::size_t size, double timeout_s) override {
    for (;;) {
      pollfd p{fd_, POLLIN, 0};
      const int ready = ::poll(&p, 1, TimeoutMs(timeout_s));
      if (ready < 0 && errno == EINTR) continue;
      if (ready < 0) throw SensorDisconnectedError(uri_ + ": poll failed: " + Errno());
      if (ready == 0) return 0;
      const ssize_t n = ::read(fd_, buffer, size);
      if (n < 0 && (errno == EINTR || errno == EAGAIN)) continue;
      // A pseudo-terminal whose other side closed reads EIO; a socket reads 0.
      if (n < 0) throw SensorDisconnectedError(uri_ + ": connection lost: " + Errno());
      if (n == 0) throw SensorDisconnectedError(uri_ + ": connection closed by the sensor");
      return static_cast<std::size_t>(n);
    }
  }

  const std::string& uri() const override { return uri_; }

 private:
  int fd_;
  bool is_socket_;
  std::string uri_;
};

int ConnectTcp(const std::string& host, const std::string& port, const std::string& uri,
               double timeout_s) {
  addrinfo hints{};
  hints.ai_family = AF_UNSPEC;
  hints.ai_socktype = SOCK_STREAM;
  addrinfo* found = nullptr;
  if (const int rc = ::getaddrinfo(host.c_str(), port.c_str(), &hints, &found); rc != 0) {
    throw SensorDisconnectedError(uri + ": cannot resolve host: " + ::gai_strerror(rc));
  }
  std::string failure = "no address";
  for (addrinfo* a = found; a != nullptr; a = a->ai_next) {
    const int fd =
        ::socket(a->ai_family, a->ai_socktype | SOCK_NONBLOCK | SOCK_CLOEXEC, a->ai_protocol);
    if (fd < 0) continue;
    int rc = ::connect(fd, a->ai_addr, a->ai_addrlen);
    if (rc < 0 && errno == EINPROGRESS) {
      pollfd p{fd, POLLOUT, 0};
      rc = ::poll(&p, 1, TimeoutMs(timeout_s)) == 1 ? 0 : -1;
      int error = rc == 0 ? 0 : ETIMEDOUT;
      socklen_t length = sizeof error;
      if (rc == 0) ::getsockopt(fd, SOL_SOCKET, SO_ERROR, &error, &length);
      errno = error;
      rc = error == 0 ? 0 : -1;
    }
    if (rc == 0) {
      const int one = 1;
      ::setsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);
      ::freeaddrinfo(found);
      return fd;
    }
    failure = Errno();
    ::close(fd);
  }
  ::freeaddrinfo(found);
  throw SensorDisconnectedError(uri + ": cannot connect: " + failure);
}

speed_t BaudConstant(int baud, const std::string& uri) {
  switch (baud) {
    case 19200:
      return B19200;
    case 38400:
      return B38400;
    case 57600:
      return B57600;
    case 115200:
      return B115200;
    case 230400:
      return B230400;
    case 500000:
      return B500000;
    default:
      throw UsageError(uri + ": unsupported serial baud rate " + std::to_string(baud));
  }
}

int OpenSerial(const std::string& path, const std::string& uri, int baud) {
  const speed_t speed = BaudConstant(baud, uri);
  const int fd = ::open(path.c_str(), O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) throw SensorDisconnectedError(uri + ": cannot open: " + Errno());
  termios tio{};
  if (::tcgetattr(fd, &tio) != 0) {
    const std::string why = Errno();
    ::close(fd);
    throw UsageError(uri + ": not a serial device: " + why);
  }
  ::cfmakeraw(&tio);  // no echo, no line editing, no CR/LF translation
  tio.c_cflag |= CLOCAL | CREAD;
  tio.c_cc[VMIN] = 0;
  tio.c_cc[VTIME] = 0;
  ::cfsetispeed(&tio, speed);
  ::cfsetospeed(&tio, speed);
  if (::tcsetattr(fd, TCSANOW, &tio) != 0) {
    const std::string why = Errno();
    ::close(fd);
    throw SensorDisconnectedError(uri + ": cannot set raw mode: " + why);
  }
  ::tcflush(fd, TCIFLUSH);
  return fd;
}

}  // namespace

std::unique_ptr<ByteStream> OpenByteStream(const std::string& uri, const ByteStreamSchemes& schemes,
                                           const ByteStreamOptions& options) {
  if (uri.starts_with(schemes.tcp)) {
    const std::string address = uri.substr(schemes.tcp.size());
    const std::size_t colon = address.rfind(':');
    if (colon == std::string::npos || colon == 0 || colon + 1 == address.size()) {
      throw UsageError(std::string(schemes.device) + " URI " + uri + " lacks HOST:PORT");
    }
    std::string host = address.substr(0, colon);
    if (host.size() > 2 && host.front() == '[' && host.back() == ']') {
      host = host.substr(1, host.size() - 2);  // [IPv6]
    }
    const int fd = ConnectTcp(host, address.substr(colon + 1), uri, options.connect_timeout_s);
    return std::make_unique<FdTransport>(fd, true, uri);
  }
  if (uri.starts_with(schemes.serial) && uri.size() > schemes.serial.size() &&
      uri[schemes.serial.size()] == '/') {
    const std::string path = uri.substr(schemes.serial.size());
    return std::make_unique<FdTransport>(OpenSerial(path, uri, options.serial_baud_rate), false,
                                         uri);
  }
  throw UsageError(std::string(schemes.device) + " URI " + uri + " is neither " +
                   std::string(schemes.tcp) + "HOST:PORT nor " + std::string(schemes.serial) +
                   "/DEVICE");
}

}  // namespace littermap::capture
