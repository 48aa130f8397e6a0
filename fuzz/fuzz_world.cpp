// libFuzzer target: arbitrary text as a world file (the simulator's YAML). Anything malformed,
// out of bounds or too large must end in a littermap::BadInputError naming the field; anything
// else (a crash, a sanitizer report, another exception, a runaway allocation) is a bug.

#include <cstddef>
#include <cstdint>
#include <string>

#include "core/error.hpp"
#include "sim/world_spec.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const littermap::sim::WorldSpec spec = littermap::sim::ParseWorldSpec(text, "fuzz.yaml");
    (void)spec.DrivenRoute();
  } catch (const littermap::BadInputError&) {
    // Expected for malformed worlds.
  }
  return 0;
}
