#pragma once
// The byte stream a SCIP 2.0 laser talks over: TCP (Ethernet models, "scip://HOST:PORT") or a
// serial/USB-ACM device ("scip:/dev/ttyACM0", also any pseudo-terminal), opened in raw mode.

#include <cstddef>
#include <memory>
#include <string>
#include <string_view>

#include "core/error.hpp"

namespace littermap {

// The sensor went away (connection closed, device unplugged, I/O error) or stopped answering:
// a recorder can catch this, reopen the URI and carry on.
class ScipDisconnectedError : public InternalError {
 public:
  explicit ScipDisconnectedError(const std::string& message) : InternalError(message) {}
};

class ScipTransport {
 public:
  virtual ~ScipTransport() = default;
  // Writes all of `bytes`. Throws ScipDisconnectedError.
  virtual void Write(std::string_view bytes) = 0;
  // Reads what is available, up to `size` bytes, waiting at most `timeout_s`. Returns 0 on
  // timeout; throws ScipDisconnectedError when the stream has ended or failed.
  virtual std::size_t Read(char* buffer, std::size_t size, double timeout_s) = 0;
  virtual const std::string& uri() const = 0;
};

struct ScipTransportOptions {
  double connect_timeout_s = 2.0;
  int serial_baud_rate = 115200;  // ignored by USB-ACM devices and pseudo-terminals
};

// Opens "scip://HOST:PORT" (TCP) or "scip:/PATH" (serial device). Throws UsageError for a URI of
// another form, ScipDisconnectedError when the sensor cannot be reached.
std::unique_ptr<ScipTransport> OpenScipTransport(const std::string& uri,
                                                 const ScipTransportOptions& options = {});

}  // namespace littermap
