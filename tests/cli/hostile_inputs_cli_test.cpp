// Hostile inputs at the door: each is refused before any work with the documented exit code
// (1 usage, 2 bad input, 4 environment; never 3, which is a bug) and a first line that names the
// option, file or field at fault.

#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
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

// A short run of the sample park simulated into DIR/bag.
std::filesystem::path SimulatedBag(const TempDir& dir, const char* duration_s) {
  const std::filesystem::path bag = dir / "bag";
  EXPECT_EQ(RunLittermap("-q simulate " + Quote(test::SampleWorld()) + " -o " + Quote(bag) +
                         " --truth " + Quote(dir / "truth") + " --duration " + duration_s)
                .exit_code,
            0);
  return bag;
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
  const std::filesystem::path bag = SimulatedBag(dir, "3");
  ASSERT_TRUE(std::filesystem::exists(bag / "bag_0.db3"));
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

// Numbers from options are checked where they are read, with the range in the message: 2^64 was
// clamped into a seed, -1 wrapped into a frame step, NaN reached the registration, 30 February
// became 2 March.
TEST(HostileInputsCli, NumbersAreCheckedWhereTheyAreRead) {
  TempDir dir;
  const std::string simulate = "simulate " + Quote(test::SampleWorld()) + " -o " +
                               Quote(dir / "bag") + " --truth " + Quote(dir / "truth");
  ExpectRefused(simulate + " --seed 18446744073709551616", 1,
                "--seed: must be a whole number from 0 to 18446744073709551615, not "
                "'18446744073709551616'");
  ExpectRefused(simulate + " --run-seed 1e3", 1, "--run-seed: must be a whole number");
  ExpectRefused(simulate + " --start-time 2026-02-30", 1,
                "--start-time 2026-02-30: the month has no such day");
  ExpectRefused("detect " + Quote(dir.path()) + " --run " + Quote(dir.path()) + " --every -1", 1,
                "--every: must be a whole number from 1 to 100000, not '-1'");
  ExpectRefused("train " + Quote(dir.path()) + " -o m.yml.gz --trees 0", 1,
                "--trees: must be a whole number from 1 to 10000, not '0'");
  const std::string ingest = "ingest " + Quote(dir / "s.gpkg") + " " + Quote(dir / "run");
  ExpectRefused(ingest + " --initial nan nan nan", 1,
                "--initial: must be a finite number from -100000 to 100000, not 'nan'");
  ExpectRefused(ingest + " --transform inf 0 0", 1, "--transform: must be a finite number");
  ExpectRefused(ingest + " --search-window nan", 1, "--search-window: must be a finite number");
  ExpectRefused(ingest + " --min-matching-ratio 2", 1,
                "--min-matching-ratio: must be a finite number from 0 to 1, not '2'");
  ExpectRefused(ingest + " --coverage-cell 1e-6", 1, "--coverage-cell: must be a finite number");
  ExpectRefused(ingest + " --camera-hfov 0", 1, "--camera-hfov: must be a finite number");
  ExpectRefused("eval trajectory " + Quote(test::SampleWorld()) + " " + Quote(test::SampleWorld()) +
                    " --rpe-delta 1e-300",
                1, "--rpe-delta: must be a finite number");
  EXPECT_FALSE(std::filesystem::exists(dir / "bag"));
  EXPECT_FALSE(std::filesystem::exists(dir / "s.gpkg"));
}

// A path that names something else than the file it should (a device, a folder, a file of
// another unit) is refused naming it, instead of reading until memory runs out.
TEST(HostileInputsCli, FilesAreWhatTheirNamesSay) {
  TempDir dir;
  ExpectRefused("simulate /dev/zero -o " + Quote(dir / "bag") + " --truth " + Quote(dir / "t"), 2,
                "littermap: error: /dev/zero: not a regular file (a device or pipe)");
  std::filesystem::create_directories(dir / "bag" / "metadata.yaml");
  ExpectRefused("info " + Quote(dir / "bag"), 2,
                (dir / "bag" / "metadata.yaml").string() + ": not a regular file (a folder)");
  { std::ofstream(dir / "o.yaml") << "max_correction_m: .nan\n"; }
  ExpectRefused("reconstruct " + Quote(dir / "bag") + " -o " + Quote(dir / "r") + " --options " +
                    Quote(dir / "o.yaml"),
                2,
                (dir / "o.yaml").string() + ": option 'max_correction_m' must be a finite number");
  ExpectRefused("import carmen " + Quote(test::kDatasets / "carmen" / "orebro-corrected.log.gz") +
                    " -o " + Quote(dir / "imported") + " --reference " + Quote(dir.path()),
                2, dir.path().string() + ": cannot write a file: Is a directory");
  EXPECT_FALSE(std::filesystem::exists(dir / "imported"));

  // A run whose trajectory is not in metres, and runs whose map image is not a map.
  const std::filesystem::path run = dir / "run";
  std::filesystem::create_directories(run);
  std::ofstream(run / "trajectory.tum") << "1700000000.0 0 0 0 0 0 0 1\n"
                                           "1700000004.0 1e15 -1e15 0 0 0 0 1\n";
  std::ofstream(run / "items.csv") << "id,class,x,y,z,size_m\n";
  std::ofstream(run / "map.yaml") << "image: map.pgm\nresolution: 0.05\norigin: [0, 0, 0]\n"
                                     "negate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n";
  std::ofstream(run / "map.pgm", std::ios::binary) << "P5\n100000 100000\n255\n"
                                                   << std::string(100, '\xfe');
  ASSERT_EQ(RunLittermap("-q site init " + Quote(dir / "site.gpkg") + " --name p").exit_code, 0);
  const std::string ingest = "ingest " + Quote(dir / "site.gpkg") + " " + Quote(run);
  ExpectRefused(ingest, 2,
                (run / "trajectory.tum").string() +
                    ": a position at (1e+15, -1e+15) m lies more than 20 km from the run's start");
  std::ofstream(run / "trajectory.tum") << "1700000000.0 0 0 0 0 0 0 1\n"
                                           "1700000004.0 1 0 0 0 0 0 1\n";
  ExpectRefused(ingest, 2,
                (run / "map.pgm").string() +
                    ": truncated (the header says 100000x100000 pixels, "
                    "the file has 121 bytes)");
  std::ofstream(run / "map.yaml") << "image: /dev/zero\nresolution: 0.05\norigin: [0, 0, 0]\n";
  ExpectRefused(ingest, 2,
                "/dev/zero: the map image named by " + (run / "map.yaml").string() +
                    " is not a regular file");
}

// Outputs: ground truth is not written among someone else's files without --force, and names
// that go into bags, sites and reports must be UTF-8.
TEST(HostileInputsCli, OutputsGoWhereTheyBelong) {
  TempDir dir;
  std::filesystem::create_directories(dir / "truth");
  std::ofstream(dir / "truth" / "thesis.tex") << "precious";
  const std::string simulate =
      "simulate " + Quote(test::SampleWorld()) + " --duration 0.5 --truth " + Quote(dir / "truth");
  ExpectRefused(simulate + " -o " + Quote(dir / "bag"), 1,
                "--truth " + (dir / "truth").string() +
                    ": holds 1 file littermap does not write there (thesis.tex)");
  EXPECT_FALSE(std::filesystem::exists(dir / "bag"));
  EXPECT_EQ(RunLittermap("-q " + simulate + " -o " + Quote(dir / "bag") + " --force").exit_code, 0);
  EXPECT_EQ(test::Slurp(dir / "truth" / "thesis.tex"), "precious");
  EXPECT_TRUE(std::filesystem::exists(dir / "truth" / "litter.csv"));

  ExpectRefused("simulate " + Quote(test::SampleWorld()) + " --duration 0.5 -o " +
                    Quote(dir / "b\xff") + " --truth " + Quote(dir / "t2"),
                2, "the bag folder's name is not valid UTF-8");
  ExpectRefused("reconstruct " + Quote(dir / "bag") + " -o " + Quote(dir / "r\xff"), 2,
                "-o is not valid UTF-8");
  ExpectRefused("site init " + Quote(dir / "s\xff.gpkg") + " --name p", 2,
                "site init: SITE is not valid UTF-8");
  { std::ofstream(dir / "w.yaml") << "name: park_\xff\xfe\n"; }
  ExpectRefused("simulate " + Quote(dir / "w.yaml") + " -o " + Quote(dir / "b3") + " --truth " +
                    Quote(dir / "t3"),
                2, (dir / "w.yaml").string() + ": name: is not valid UTF-8");
}

// A bag whose /scan topic is of another type: read as laser scans it decoded to nothing and
// reconstructed zero poses with exit 0.
TEST(HostileInputsCli, ATopicOfTheWrongTypeIsNamed) {
  TempDir dir;
  const std::filesystem::path bag = SimulatedBag(dir, "0.5");
  ASSERT_TRUE(std::filesystem::exists(bag / "bag_0.db3"));
  {
    SqliteDatabase database(bag / "bag_0.db3", SqliteDatabase::Mode::kReadWrite);
    database.Execute("UPDATE topics SET type = 'sensor_msgs/msg/Imu' WHERE name = '/scan'");
  }
  std::filesystem::remove(bag / "metadata.yaml");
  ExpectRefused("reconstruct " + Quote(bag) + " -o " + Quote(dir / "run"), 2,
                bag.string() +
                    ": topic '/scan' has type sensor_msgs/msg/Imu, not "
                    "sensor_msgs/msg/LaserScan: name the scan topic with --topic "
                    "scan=TOPIC");
}

// Environment faults are told from bad input: a site that cannot be created in a folder the
// user may not write is the machine's answer (4), not a bad path (2).
TEST(HostileInputsCli, ASiteInAFolderThatCannotBeWrittenIsAnEnvironmentFault) {
  TempDir dir;
  std::filesystem::create_directories(dir / "locked");
  std::filesystem::permissions(dir / "locked", std::filesystem::perms::owner_read |
                                                   std::filesystem::perms::owner_exec |
                                                   std::filesystem::perms::others_read |
                                                   std::filesystem::perms::others_exec);
  std::filesystem::permissions(dir.path(), std::filesystem::perms::all);
  const std::string as_user =
      geteuid() == 0 ? "setpriv --reuid=65534 --regid=65534 --clear-groups " : "";
  const test::CommandResult result =
      test::RunCommand(as_user + LITTERMAP_EXECUTABLE + " -q site init " +
                       Quote(dir / "locked" / "s.gpkg") + " --name p");
  EXPECT_EQ(result.exit_code, 4) << result.output;
  EXPECT_NE(FirstLine(result.output)
                .find((dir / "locked" / "s.gpkg").string() +
                      ": cannot open database: unable to open database file (Permission denied)"),
            std::string::npos)
      << result.output;
}

}  // namespace
}  // namespace littermap
