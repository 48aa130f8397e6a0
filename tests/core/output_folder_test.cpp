#include "core/output_folder.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "core/error.hpp"
#include "support/temp_dir.hpp"

namespace littermap {
namespace {

using test::TempDir;

std::string Refusal(const std::filesystem::path& folder, const OutputFolderCheck& check) {
  try {
    PrepareOutputFolder(folder, check);
    return "";
  } catch (const UsageError& e) {
    return e.what();
  }
}

TEST(OutputFolder, CreatesAMissingFolderAndAcceptsOneHoldingItsOwnFiles) {
  TempDir dir;
  const OutputFolderCheck check{"-o", {"index.html", "report.json"}, false};
  EXPECT_EQ(Refusal(dir / "new" / "report", check), "");
  EXPECT_TRUE(std::filesystem::is_directory(dir / "new" / "report"));
  std::ofstream(dir / "new" / "report" / "index.html") << "old";
  std::ofstream(dir / "new" / "report" / "report.json.tmp") << "interrupted";
  EXPECT_EQ(Refusal(dir / "new" / "report", check), "");
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir / "new" / "report"), {}), 2)
      << "the write probe is removed";
}

TEST(OutputFolder, RefusesOtherFilesUnlessForcedAndAFile) {
  TempDir dir;
  for (const char* name : {"thesis.pdf", "photos", "index.html", "notes.txt", "x"}) {
    std::ofstream(dir / name) << "mine";
  }
  OutputFolderCheck check{"-o", {"index.html"}, false};
  const std::string refusal = Refusal(dir.path(), check);
  const std::string head =
      "-o " + dir.path().string() + ": holds 4 files littermap does not write there (";
  EXPECT_EQ(refusal.substr(0, head.size()), head) << refusal;
  EXPECT_TRUE(refusal.ends_with(", …); choose a new or empty folder, or give --force")) << refusal;
  EXPECT_EQ(refusal.find("index.html"), std::string::npos) << refusal;
  check.force = true;
  EXPECT_EQ(Refusal(dir.path(), check), "");
  EXPECT_EQ(Refusal(dir / "x", check), "-o " + (dir / "x").string() + ": is a file, not a folder");
}

TEST(OutputFolder, APathThatCannotBeAFolderIsBadInput) {
  TempDir dir;
  std::ofstream(dir / "file") << "x";
  try {
    PrepareOutputFolder(dir / "file" / "below", {"-o", {}, false});
    ADD_FAILURE() << "a folder below a file was accepted";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::kBadInput) << e.what();
  }
}

// Its name goes into run names, site records and JSON: not UTF-8, it is refused at the door.
TEST(OutputFolder, ANameThatIsNotUtf8IsBadInput) {
  TempDir dir;
  try {
    PrepareOutputFolder(dir / "run\xff", {"-o", {}, false});
    ADD_FAILURE() << "accepted";
  } catch (const BadInputError& e) {
    EXPECT_NE(std::string(e.what()).find("-o is not valid UTF-8"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(std::filesystem::exists(dir / "run\xff"));
}

}  // namespace
}  // namespace littermap
