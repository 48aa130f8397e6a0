// Small text files read whole: a folder, a device or a file beyond the size limit is refused
// naming the file, before any memory is taken for it.

#include "core/text_file.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "core/error.hpp"
#include "support/temp_dir.hpp"

namespace littermap {
namespace {

using namespace std::string_literals;

void ExpectRefused(const std::filesystem::path& path, std::uintmax_t max_bytes,
                   const std::string& says) {
  try {
    ReadTextFile(path, max_bytes);
    ADD_FAILURE() << path << " was read";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::kBadInput) << e.what();
    EXPECT_EQ(std::string(e.what()), path.string() + ": " + says);
  }
}

TEST(TextFile, ReadsARegularFileWhole) {
  test::TempDir dir;
  const std::string text = "name: park\nseed: 7\n\0binary too"s;
  std::ofstream(dir / "w.yaml", std::ios::binary) << text;
  EXPECT_EQ(ReadTextFile(dir / "w.yaml"), text);
  std::ofstream(dir / "empty.yaml");
  EXPECT_EQ(ReadTextFile(dir / "empty.yaml"), "");
}

TEST(TextFile, RefusesWhatIsNotASmallRegularFile) {
  test::TempDir dir;
  ExpectRefused(dir.path(), kMaxTextFileBytes, "not a regular file (a folder)");
  ExpectRefused("/dev/zero", kMaxTextFileBytes, "not a regular file (a device or pipe)");
  std::ofstream(dir / "big.yaml") << std::string(1001, 'x');
  ExpectRefused(dir / "big.yaml", 1000,
                "1001 bytes, more than the 1000 a text file of this kind may have");
  ExpectRefused(dir / "missing.yaml", kMaxTextFileBytes, "cannot read: No such file or directory");
}

}  // namespace
}  // namespace littermap
