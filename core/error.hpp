#pragma once
// The error type of every littermap library. Libraries never print or exit: they throw one of
// these with a message that names the file, field, line, topic or frame at fault, and the CLI
// maps the kind to an exit code (DESIGN.md: 1 usage, 2 bad input data, 3 internal, 4 environment).
// core/failure.hpp gives the kind of any other exception (a library's, the standard library's).

#include <stdexcept>
#include <string>

namespace littermap {

enum class ErrorKind {
  kUsage = 1,        // the caller asked for something impossible (bad option, missing argument)
  kBadInput = 2,     // a file or message is malformed; the message says which and where
  kInternal = 3,     // a bug: nothing the user or the machine did explains it
  kEnvironment = 4,  // the machine failed: disk full, permission denied, device gone, no memory
};

class Error : public std::runtime_error {
 public:
  Error(ErrorKind kind, const std::string& message) : std::runtime_error(message), kind_(kind) {}
  ErrorKind kind() const { return kind_; }

 private:
  ErrorKind kind_;
};

class UsageError : public Error {
 public:
  explicit UsageError(const std::string& message) : Error(ErrorKind::kUsage, message) {}
};

class BadInputError : public Error {
 public:
  explicit BadInputError(const std::string& message) : Error(ErrorKind::kBadInput, message) {}
};

class InternalError : public Error {
 public:
  explicit InternalError(const std::string& message) : Error(ErrorKind::kInternal, message) {}
};

class EnvironmentError : public Error {
 public:
  explicit EnvironmentError(const std::string& message) : Error(ErrorKind::kEnvironment, message) {}
};

// Throws UsageError "`stage`: `key` must be `rule`" unless ok: one line per option in Validate().
inline void RequireOption(bool ok, const char* stage, const char* key, const char* rule) {
  if (!ok) throw UsageError(std::string(stage) + ": " + key + " must be " + rule);
}

}  // namespace littermap
