#pragma once
// The error every live sensor source raises when its sensor is gone.

#include <string>

#include "core/error.hpp"

namespace littermap::capture {

// The sensor went away (connection closed, device unplugged, I/O error) or stopped answering:
// a recorder can catch this, reopen the URI and carry on.
class SensorDisconnectedError : public EnvironmentError {
 public:
  explicit SensorDisconnectedError(const std::string& message) : EnvironmentError(message) {}
};

}  // namespace littermap::capture
