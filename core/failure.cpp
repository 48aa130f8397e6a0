#include "core/failure.hpp"

#include <cerrno>
#include <cstring>
#include <new>
#include <string>
#include <system_error>

namespace littermap {

ErrorKind KindOfErrno(int errno_value) {
  switch (errno_value) {
    case ENOENT:
    case ENOTDIR:
    case EISDIR:
    case ELOOP:
    case ENAMETOOLONG:
    case EEXIST:
    case ENOTEMPTY:
    case EILSEQ:
    case EINVAL:
    case EXDEV:
      return ErrorKind::kBadInput;
    case 0:
    case ENOSPC:
    case EDQUOT:
    case EFBIG:
    case EACCES:
    case EPERM:
    case EROFS:
    case EIO:
    case ENODEV:
    case ENXIO:
    case ENOMEM:
    case EMFILE:
    case ENFILE:
    case EBUSY:
    case ETXTBSY:
    case EAGAIN:
    case ENOTCONN:
    case ECONNRESET:
    case EPIPE:
    case ESTALE:
      return ErrorKind::kEnvironment;
    default:
      return ErrorKind::kInternal;
  }
}

ErrorKind KindOf(const std::exception& failure) {
  if (const auto* error = dynamic_cast<const Error*>(&failure)) return error->kind();
  if (dynamic_cast<const std::bad_alloc*>(&failure) != nullptr) return ErrorKind::kEnvironment;
  if (const auto* system = dynamic_cast<const std::system_error*>(&failure)) {
    const std::error_code& code = system->code();
    if (code.category() == std::generic_category() || code.category() == std::system_category()) {
      return KindOfErrno(code.value());
    }
  }
  return ErrorKind::kInternal;
}

Error FileFailure(const std::filesystem::path& file, std::string_view doing, int errno_value) {
  std::string message = file.string() + ": " + std::string(doing);
  if (errno_value != 0) message += std::string(": ") + std::strerror(errno_value);
  return Error(KindOfErrno(errno_value), message);
}

}  // namespace littermap
