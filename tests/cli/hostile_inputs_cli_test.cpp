// Hostile inputs at the door: each is refused before any work with the documented exit code
// (1 usage, 2 bad input, 4 environment; never 3, which is a bug) and a first line that names the
// option, file or field at fault.

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "support/run_command.hpp"
#include "support/temp_dir.hpp"
#include "support/test_files.hpp"

namespace littermap {
namespace {

using test::Quote;
using test::RunLittermap;
using test::TempDir;

std::string FirstLine(const std::string& text) { return text.substr(0, text.find('\n')); }

// Runs littermap and checks the exit code and that the first line of the output holds `says`.
void ExpectRefused(const std::string& arguments, int exit_code, const std::string& says) {
  const test::CommandResult result = RunLittermap("-q " + arguments);
  EXPECT_EQ(result.exit_code, exit_code) << arguments << "\n" << result.output;
  EXPECT_NE(FirstLine(result.output).find(says), std::string::npos) << arguments << "\n"
                                                                    << result.output;
}

TEST(HostileInputsCli, SiteOriginsMustBeFiniteAndInTheirCrsArea) {
  TempDir dir;
  ExpectRefused("site init " + Quote(dir / "a.gpkg") +
                    " --name p --crs EPSG:32632 --origin 999999999 999999999",
                1,
                "littermap: error: --origin 999999999 999999999: outside the area EPSG:32632 is");
  ExpectRefused(
      "site init " + Quote(dir / "b.gpkg") + " --name p --crs EPSG:32632 --origin nan inf", 1,
      "must be finite numbers of metres in EPSG:32632");
  ExpectRefused("site init " + Quote(dir / "c.gpkg") +
                    " --name p --crs EPSG:32632 --origin 691000 5334000 --rotation inf",
                1, "--rotation must be a number of degrees from -360 to 360");
  EXPECT_FALSE(std::filesystem::exists(dir / "a.gpkg"));
  EXPECT_EQ(RunLittermap("site init " + Quote(dir / "d.gpkg") +
                         " --name p --crs EPSG:32632 --origin 691000 5334000")
                .exit_code,
            0);
}

TEST(HostileInputsCli, NamesMustBeUtf8) {
  TempDir dir;
  ExpectRefused("site init " + Quote(dir / "a.gpkg") + " --name \"$(printf 'North \\377 park')\"",
                2, "site init: --name is not valid UTF-8 (byte 7 of 12)");
  EXPECT_FALSE(std::filesystem::exists(dir / "a.gpkg"));
}

TEST(HostileInputsCli, StartTimesOutsideTheBagsStampsAreRefused) {
  TempDir dir;
  for (const char* date : {"9999-12-31T23:59:59", "1900-01-01"}) {
    ExpectRefused("simulate " + Quote(test::SampleWorld()) + " -o " + Quote(dir / "bag") +
                      " --truth " + Quote(dir / "truth") + " --duration 1 --start-time " + date,
                  1, "a run starts from 1970-01-01 to 2033-05-18 UTC");
    EXPECT_FALSE(std::filesystem::exists(dir / "bag"));
  }
}

TEST(HostileInputsCli, PathsAtFaultAreBadInputNotInternalErrors) {
  TempDir dir;
  std::filesystem::create_directory_symlink(dir / "loop", dir / "loop");
  ExpectRefused("info " + Quote(dir / "loop"), 2, (dir / "loop").string());
  ExpectRefused("info " + Quote(dir / "loop" / "x"), 2, (dir / "loop").string());
  ExpectRefused("info " + Quote(dir / std::string(300, 'n')), 2, std::string(300, 'n'));
}

}  // namespace
}  // namespace littermap
