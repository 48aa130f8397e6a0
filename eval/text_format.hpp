#pragma once
// printf-style appending, for the text reports of the metrics (ToText): their column widths and
// decimals are part of the output that scripts and people read. A ToText report is lines like
// a ToJson object: without a newline after the last.

#include <string>

namespace littermap::eval {

void AppendFormat(std::string& text, const char* format, ...) __attribute__((format(printf, 2, 3)));

}  // namespace littermap::eval
