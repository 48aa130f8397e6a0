// Outputs written under FILE.tmp and renamed when complete: FILE is the old version or the
// whole new one, and a failed write (here a file size limit, as on a full disk) leaves neither a
// truncated FILE nor the temporary.

#include "core/output_file.hpp"

#include <gtest/gtest.h>

#include <string>

#include "core/error.hpp"
#include "support/file_size_limit.hpp"
#include "support/temp_dir.hpp"
#include "support/test_files.hpp"

namespace littermap {
namespace {

namespace fs = std::filesystem;
using test::Slurp;

TEST(OutputFile, CommitReplacesTheFileWhole) {
  test::TempDir dir;
  const fs::path file = dir / "out.csv";
  WriteFileAtomically(file, "old\n");
  {
    OutputFile out(file);
    out.stream() << "new,";
    EXPECT_TRUE(fs::exists(out.temporary()));
    EXPECT_EQ(Slurp(file), "old\n");  // readers see the old file until the commit
    out.stream() << "whole\n";
    out.Commit();
  }
  EXPECT_EQ(Slurp(file), "new,whole\n");
  EXPECT_FALSE(fs::exists(file.string() + ".tmp"));
}

TEST(OutputFile, AnOutputNotCommittedLeavesTheOldFileAndNoTemporary) {
  test::TempDir dir;
  const fs::path file = dir / "map.pgm";
  WriteFileAtomically(file, "old");
  try {
    OutputFile out(file);
    out.stream() << "half of it";
    throw std::runtime_error("the work failed half-way");
  } catch (const std::runtime_error&) {
  }
  EXPECT_EQ(Slurp(file), "old");
  EXPECT_FALSE(fs::exists(file.string() + ".tmp"));
  // A library writing by name (libtiff) writes the temporary; nothing is opened for it.
  {
    OutputFile out = OutputFile::ByName(dir / "density.tif");
    EXPECT_FALSE(fs::exists(out.temporary()));
  }
}

TEST(OutputFile, AFullDiskIsAnEnvironmentErrorNamingTheFile) {
  test::TempDir dir;
  const fs::path file = dir / "trajectory.tum";
  WriteFileAtomically(file, "old");
  // Writing 64 kB with a 4 kB file size limit.
  const int exit_code = test::RunWithFileSizeLimit(4096, [&] {
    try {
      WriteFileAtomically(file, std::string(65536, 'x'));
      return 10;
    } catch (const Error& error) {
      const bool named = std::string(error.what()).starts_with(file.string() + ": cannot write");
      return error.kind() == ErrorKind::kEnvironment && named ? 0 : 11;
    } catch (...) {
      return 12;
    }
  });
  EXPECT_EQ(exit_code, 0) << "10: no error, 11: wrong kind or file, 12: another error";
  EXPECT_EQ(Slurp(file), "old");
  EXPECT_FALSE(fs::exists(file.string() + ".tmp"));
}

TEST(OutputFile, AFileThatCannotBeCreatedIsNamed) {
  test::TempDir dir;
  try {
    OutputFile out(dir / "no" / "such" / "folder.csv");
    ADD_FAILURE() << "no error";
  } catch (const Error& error) {
    EXPECT_EQ(error.kind(), ErrorKind::kBadInput);
    EXPECT_EQ(std::string(error.what()), (dir / "no" / "such" / "folder.csv").string() +
                                             ": cannot create: No such file or directory");
  }
}

// A folder (or ".") named where a file belongs fails before anything is written, as bad input,
// instead of at the final rename (EBUSY for ".", an environment fault).
TEST(OutputFile, AFolderCannotBecomeAFile) {
  test::TempDir dir;
  for (const fs::path& folder : {dir.path(), fs::path(".")}) {
    try {
      OutputFile out(folder);
      ADD_FAILURE() << folder << ": no error";
    } catch (const Error& error) {
      EXPECT_EQ(error.kind(), ErrorKind::kBadInput) << error.what();
      EXPECT_EQ(std::string(error.what()),
                folder.string() + ": cannot write a file: Is a directory");
    }
  }
  try {
    OutputFile::ByName(dir.path());
    ADD_FAILURE() << "ByName: no error";
  } catch (const Error& error) {
    EXPECT_EQ(error.kind(), ErrorKind::kBadInput) << error.what();
  }
}

}  // namespace
}  // namespace littermap
