#include "core/failure.hpp"

#include <gtest/gtest.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <new>
#include <stdexcept>
#include <string>
#include <system_error>

namespace littermap {
namespace {

std::filesystem::filesystem_error FsError(int errno_value) {
  return {"status", "/some/path", std::error_code(errno_value, std::generic_category())};
}

TEST(Failure, OwnErrorsKeepTheirKind) {
  EXPECT_EQ(KindOf(UsageError("x")), ErrorKind::kUsage);
  EXPECT_EQ(KindOf(BadInputError("x")), ErrorKind::kBadInput);
  EXPECT_EQ(KindOf(InternalError("x")), ErrorKind::kInternal);
  EXPECT_EQ(KindOf(EnvironmentError("x")), ErrorKind::kEnvironment);
}

TEST(Failure, PathsAtFaultAreBadInput) {
  for (int e : {ELOOP, ENAMETOOLONG, ENOENT, ENOTDIR, EEXIST, EILSEQ}) {
    EXPECT_EQ(KindOf(FsError(e)), ErrorKind::kBadInput) << std::strerror(e);
  }
}

TEST(Failure, TheMachineAtFaultIsEnvironment) {
  for (int e : {ENOSPC, EDQUOT, EACCES, EPERM, EROFS, EIO, ENODEV}) {
    EXPECT_EQ(KindOf(FsError(e)), ErrorKind::kEnvironment) << std::strerror(e);
  }
  EXPECT_EQ(KindOf(std::system_error(ENOSPC, std::system_category())), ErrorKind::kEnvironment);
  EXPECT_EQ(KindOf(std::bad_alloc()), ErrorKind::kEnvironment);
}

TEST(Failure, AnythingElseIsInternal) {
  EXPECT_EQ(KindOf(std::logic_error("bug")), ErrorKind::kInternal);
  EXPECT_EQ(KindOf(std::out_of_range("bug")), ErrorKind::kInternal);
  EXPECT_EQ(KindOf(FsError(EDOM)), ErrorKind::kInternal);
}

TEST(Failure, FileFailureNamesTheFileAndTheCause) {
  const Error full = FileFailure("out/map.pgm", "cannot write", ENOSPC);
  EXPECT_EQ(full.kind(), ErrorKind::kEnvironment);
  EXPECT_EQ(std::string(full.what()), "out/map.pgm: cannot write: No space left on device");
  const Error unknown = FileFailure("out/map.pgm", "cannot write", 0);
  EXPECT_EQ(unknown.kind(), ErrorKind::kEnvironment);
  EXPECT_EQ(std::string(unknown.what()), "out/map.pgm: cannot write");
  EXPECT_EQ(FileFailure("out", "cannot create", ENOTDIR).kind(), ErrorKind::kBadInput);
}

}  // namespace
}  // namespace littermap
