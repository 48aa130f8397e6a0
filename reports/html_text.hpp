#pragma once
// Text into HTML: escaping whatever people typed (site and run names, classes) and embedding
// binary files as data: URLs, so a report is one self-contained file.

#include <span>
#include <string>
#include <string_view>

namespace littermap::reports {

// & < > " ' as character references: safe in element content and quoted attributes.
std::string EscapeHtml(std::string_view text);

// RFC 4648 base64.
std::string Base64(std::span<const unsigned char> bytes);

// "12.3" with `decimals` digits after the point; thousands grouped with a thin space.
std::string FormatNumber(double value, int decimals);

// A fraction as a whole percentage: 0.184 -> "18 %".
std::string FormatPercent(double fraction);

}  // namespace littermap::reports
