#pragma once
// The byte stream a sensor talks over: TCP (e.g. "scip://HOST:PORT" for an Ethernet laser) or a
// serial/USB-ACM device ("scip:/dev/ttyACM0", also any pseudo-terminal), opened in raw mode.

#include <cstddef>
#include <memory>
#include <string>
#include <string_view>

#include "capture/sensor_disconnected.hpp"
#include "core/error.hpp"

namespace littermap::capture {

class ByteStream {
 public:
  virtual ~ByteStream() = default;
  // Writes all of `bytes`. Throws SensorDisconnectedError.
  virtual void Write(std::string_view bytes) = 0;
  // Reads what is available, up to `size` bytes, waiting at most `timeout_s`. Returns 0 on
  // timeout; throws SensorDisconnectedError when the stream has ended or failed.
  virtual std::size_t Read(char* buffer, std::size_t size, double timeout_s) = 0;
  virtual const std::string& uri() const = 0;
};

struct ByteStreamOptions {
  double connect_timeout_s = 2.0;
  int serial_baud_rate = 115200;  // ignored by USB-ACM devices and pseudo-terminals
};

// The URI schemes of one kind of sensor, e.g. {"laser", "scip://", "scip:"}.
struct ByteStreamSchemes {
  std::string_view device;  // named in errors
  std::string_view tcp;     // followed by HOST:PORT
  std::string_view serial;  // followed by an absolute device path
};

// Opens TCP for schemes.tcp + "HOST:PORT", a serial device for schemes.serial + "/PATH". Throws
// UsageError for a URI of another form, SensorDisconnectedError when the sensor cannot be
// reached.
std::unique_ptr<ByteStream> OpenByteStream(const std::string& uri, const ByteStreamSchemes& schemes,
                                           const ByteStreamOptions& options = {});

}  // namespace littermap::capture
