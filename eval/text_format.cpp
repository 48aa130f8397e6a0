#include "eval/text_format.hpp"

#include <cstdarg>
#include <cstdio>

namespace littermap::eval {

void AppendFormat(std::string& text, const char* format, ...) {
  std::va_list arguments;
  va_start(arguments, format);
  std::va_list copy;
  va_copy(copy, arguments);
  const int length = std::vsnprintf(nullptr, 0, format, copy);
  va_end(copy);
  if (length > 0) {
    const std::size_t start = text.size();
    text.resize(start + static_cast<std::size_t>(length) + 1);
    std::vsnprintf(text.data() + start, static_cast<std::size_t>(length) + 1, format, arguments);
    text.resize(start + static_cast<std::size_t>(length));
  }
  va_end(arguments);
}

}  // namespace littermap::eval
