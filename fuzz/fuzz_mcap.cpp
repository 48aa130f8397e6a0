// libFuzzer target: reads the input as a one-file MCAP bag through BagReader, every message of
// every topic. Malformed input must end in a littermap::Error or in warnings (a damaged chunk
// is skipped); anything else (a crash, a sanitizer report, another exception, an out-of-memory,
// a hang) is a bug.

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>

#include "bag/bag_reader.hpp"
#include "bag/mcap_records.hpp"
#include "core/error.hpp"
#include "fuzz/scratch_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  // Other inputs would open as sqlite3 storage: fuzz the MCAP reader only.
  namespace mcap = littermap::bag::mcap;
  if (size < mcap::kMagic.size() || !std::equal(mcap::kMagic.begin(), mcap::kMagic.end(), data)) {
    return 0;
  }
  static const littermap::fuzz::ScratchFile scratch("fuzz_mcap", ".mcap");
  const std::filesystem::path& file = scratch.path();
  std::ofstream(file, std::ios::binary | std::ios::trunc)
      .write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  try {
    littermap::bag::BagReader reader(file);
    std::uint64_t count = 0;
    while (auto message = reader.Next()) ++count;
    if (count > reader.info().message_count + size) __builtin_trap();
  } catch (const littermap::Error&) {
    // Expected for malformed input.
  }
  return 0;
}
