// Hostile inputs at the door: each is refused before any work with the documented exit code
// (1 usage, 2 bad input, 4 environment; never 3, which is a bug) and a first line that names the
// option, file or field at fault.

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "core/sqlite_database.hpp"
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

// A depth image whose PNG data is damaged inside a bag that is otherwise sound: `detect` stops
// naming the bag, topic and message, with libpng's reason in littermap's words (nothing printed
// by libpng itself).
TEST(HostileInputsCli, AnImageThatDoesNotDecodeIsNamedByTopicAndMessage) {
  TempDir dir;
  const std::filesystem::path bag = dir / "bag";
  ASSERT_EQ(RunLittermap("-q simulate " + Quote(test::SampleWorld()) + " -o " + Quote(bag) +
                         " --truth " + Quote(dir / "truth") + " --duration 3")
                .exit_code,
            0);
  {
    // 64 zero bytes in the middle of the third depth message: inside its PNG's compressed data.
    SqliteDatabase database(bag / "bag_0.db3", SqliteDatabase::Mode::kReadWrite);
    database.Execute(
        "UPDATE messages SET data = substr(data, 1, length(data) / 2) || zeroblob(64) || "
        "substr(data, length(data) / 2 + 65) WHERE id = (SELECT m.id FROM messages m JOIN topics "
        "t ON m.topic_id = t.id WHERE t.name = '/camera/depth/image_raw/compressed' "
        "ORDER BY m.timestamp LIMIT 1 OFFSET 2)");
  }
  std::filesystem::create_directories(dir / "run");
  const test::CommandResult result =
      RunLittermap("-q detect " + Quote(bag) + " --run " + Quote(dir / "run") + " --trajectory " +
                   Quote(dir / "truth" / "trajectory.tum") + " --every 1");
  EXPECT_EQ(result.exit_code, 2) << result.output;
  EXPECT_NE(FirstLine(result.output)
                .find(bag.string() + ": topic '/camera/depth/image_raw/compressed' message #2"),
            std::string::npos)
      << result.output;
  EXPECT_NE(FirstLine(result.output).find("PNG does not decode: "), std::string::npos)
      << result.output;
  EXPECT_EQ(result.output.find("libpng"), std::string::npos) << result.output;
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

// Options that size a computation are bounded where they are read: a negative hotspot count was
// an internal error, a 1e12 m bandwidth a segmentation fault, --duration inf a run that never
// ended, a contact sheet of an unknown format an internal error after the whole simulation.
TEST(HostileInputsCli, OptionsThatSizeAComputationAreBounded) {
  TempDir dir;
  const std::string site = Quote(dir / "site.gpkg");
  ASSERT_EQ(RunLittermap("-q site init " + site + " --name p").exit_code, 0);
  for (const char* command : {"heatmap", "report"}) {
    const std::string out = " -o " + Quote(dir / command);
    ExpectRefused(std::string(command) + " " + site + out + " --hotspots -1", 1,
                  "--hotspots: Value -1 not in range 0 to 1000");
    ExpectRefused(std::string(command) + " " + site + out + " --bandwidth 1e12", 1,
                  "--bandwidth: must be a finite number from 0.1 to 100, not '1e12'");
    ExpectRefused(std::string(command) + " " + site + out + " --bandwidth nan", 1,
                  "--bandwidth: must be a finite number from 0.1 to 100, not 'nan'");
    ExpectRefused(std::string(command) + " " + site + out + " --cell-size 1e-6", 1,
                  "--cell-size: must be a finite number from 0.05 to 100, not '1e-6'");
  }
  const std::string simulate = "simulate " + Quote(test::SampleWorld()) + " -o " +
                               Quote(dir / "bag") + " --truth " + Quote(dir / "truth");
  ExpectRefused(simulate + " --duration inf", 1,
                "--duration: must be a finite number from 0.1 to 86400, not 'inf'");
  ExpectRefused(simulate + " --duration 2 --contact-sheet " + Quote(dir / "sheet.xyz"), 1,
                "must end in .png, .jpg");
  EXPECT_FALSE(std::filesystem::exists(dir / "bag"));
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
