#pragma once
// Text from users (site, run and class names, file contents) is stored and shown as UTF-8: it
// is checked where it comes in and refused there, rather than failing later in a JSON writer or
// showing as mojibake in a GIS.

#include <string>
#include <string_view>

namespace littermap {

// Well-formed UTF-8 (RFC 3629): no overlong forms, no surrogates, nothing above U+10FFFF.
bool IsUtf8(std::string_view text);

// Throws BadInputError "WHAT is not valid UTF-8 (byte N)" for anything else.
void RequireUtf8(std::string_view text, const std::string& what);

}  // namespace littermap
