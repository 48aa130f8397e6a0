// libFuzzer target: arbitrary text through the CARMEN line parser, line by line, and every laser
// record it accepts through the LaserScan conversion. Malformed input must end in a
// littermap::BadInputError naming the field; anything else (a crash, a sanitizer report, another
// exception, a huge allocation from a corrupt count) is a bug.

#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>
#include <variant>

#include "core/error.hpp"
#include "importers/carmen_laser.hpp"
#include "importers/carmen_log.hpp"

namespace {

void ParseOneLine(std::string_view line) {
  try {
    const littermap::importers::CarmenRecord record = littermap::importers::ParseCarmenLine(line);
    if (const auto* laser = std::get_if<littermap::importers::CarmenLaserRecord>(&record)) {
      if (laser->ranges_m.empty()) __builtin_trap();  // the parser promises at least one beam
      const std::span<const littermap::importers::CarmenLaserRecord> scans(laser, 1);
      const littermap::importers::CarmenRangeLimits limits =
          littermap::importers::CarmenRanges(scans);
      const auto scan = littermap::importers::ToLaserScan(*laser, {}, limits);
      if (scan.ranges.size() != laser->ranges_m.size()) __builtin_trap();
    }
  } catch (const littermap::BadInputError&) {
    // Expected for malformed lines.
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::string_view text(reinterpret_cast<const char*>(data), size);
  while (!text.empty()) {
    const std::size_t newline = text.find('\n');
    ParseOneLine(text.substr(0, newline));
    if (newline == std::string_view::npos) break;
    text.remove_prefix(newline + 1);
  }
  return 0;
}
