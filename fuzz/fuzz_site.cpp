// libFuzzer target: arbitrary bytes as a site database file. Opening it must either give a site
// whose records read, or end in a littermap::Error of kind bad input (not a GeoPackage, not a
// littermap site, damaged) or environment; a crash, a sanitizer report, another exception or
// an internal error is a bug.

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <filesystem>

#include "core/error.hpp"
#include "db/site_database.hpp"
#include "fuzz/scratch_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const littermap::fuzz::ScratchFile scratch("fuzz_site", ".gpkg");
  const std::filesystem::path& file = scratch.path();
  scratch.Remove();  // the last input's database must not be read as this one's
  if (std::FILE* out = std::fopen(file.c_str(), "wb")) {
    std::fwrite(data, 1, size, out);
    std::fclose(out);
  }
  try {
    littermap::db::SiteDatabase site = littermap::db::SiteDatabase::Open(file);
    (void)site.site();
    (void)site.Runs();
    (void)site.SiteMap();
  } catch (const littermap::Error& e) {
    if (e.kind() == littermap::ErrorKind::kInternal || e.kind() == littermap::ErrorKind::kUsage) {
      std::fprintf(stderr, "%s\n", e.what());
      __builtin_trap();
    }
  }
  return 0;
}
