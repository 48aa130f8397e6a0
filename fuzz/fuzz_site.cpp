// libFuzzer target: arbitrary bytes as a site database file. Opening it must either give a site
// whose records read, or end in a littermap::Error of kind bad input (not a GeoPackage, not a
// littermap site, damaged) or environment; a crash, a sanitizer report, another exception or
// an internal error is a bug.

#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <string>

#include "core/error.hpp"
#include "db/site_database.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::filesystem::path file = std::filesystem::temp_directory_path() /
                                     ("fuzz_site_" + std::to_string(::getpid()) + ".gpkg");
  std::filesystem::remove(file);
  for (const char* suffix : {"-wal", "-shm", "-journal"}) {
    std::filesystem::remove(file.string() + suffix);
  }
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
