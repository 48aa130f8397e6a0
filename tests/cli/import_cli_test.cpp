// `littermap import carmen|tum`: exit codes (0 success, 1 usage, 2 bad input), the summary line
// on stdout and the warnings on stderr.

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>

#include "bag/bag_reader.hpp"
#include "support/run_command.hpp"
#include "support/temp_dir.hpp"
#include "support/test_files.hpp"

namespace littermap {
namespace {

using test::RunLittermap;

using test::kDatasets;

using test::Quote;

TEST(ImportCli, CarmenSucceedsWithSummaryAndWarning) {
  const auto log = kDatasets / "carmen" / "orebro-corrected.log.gz";
  ASSERT_TRUE(std::filesystem::exists(log)) << "missing data set " << log;
  test::TempDir dir;
  const auto result =
      RunLittermap("import carmen " + Quote(log) + " -o " + Quote(dir / "bag") + " --reference " +
                   Quote(dir / "ref.tum") + " --odometry-noise 3");
  ASSERT_EQ(result.exit_code, 0) << result.output;
  EXPECT_NE(result.output.find("237 scans (181 beams), 237 odometry (noisy, seed 3)"),
            std::string::npos)
      << result.output;
  // orebro has no time stamps: the user is told they were synthesised.
  EXPECT_NE(result.output.find("warning: orebro-corrected.log.gz"), std::string::npos)
      << result.output;
  EXPECT_TRUE(std::filesystem::exists(dir / "ref.tum"));
  EXPECT_EQ(bag::BagReader(dir / "bag").info().message_count, 237u * 2 + 1);
}

TEST(ImportCli, QuietSilencesWarningsButNotTheSummary) {
  const auto log = kDatasets / "carmen" / "orebro-corrected.log.gz";
  ASSERT_TRUE(std::filesystem::exists(log)) << "missing data set " << log;
  test::TempDir dir;
  const auto result = RunLittermap("import carmen -q " + Quote(log) + " -o " + Quote(dir / "bag"));
  ASSERT_EQ(result.exit_code, 0) << result.output;
  EXPECT_EQ(result.output.find("warning"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("wrote "), std::string::npos) << result.output;
}

TEST(ImportCli, MalformedLogExitsTwoNamingFileAndLine) {
  test::TempDir dir;
  std::ofstream(dir / "bad.log") << "# fine\nFLASER 2 1.0 2.0 0 0 0 0 0\n";
  const auto result =
      RunLittermap("import carmen " + Quote(dir / "bad.log") + " -o " + Quote(dir / "bag"));
  EXPECT_EQ(result.exit_code, 2) << result.output;
  EXPECT_NE(result.output.find("bad.log:2: FLASER field 'odom_theta'"), std::string::npos)
      << result.output;
  EXPECT_FALSE(std::filesystem::exists(dir / "bag"));
}

TEST(ImportCli, TruncatedGzipExitsTwo) {
  const auto log = kDatasets / "carmen" / "intel-corrected.log.gz";
  ASSERT_TRUE(std::filesystem::exists(log)) << "missing data set " << log;
  test::TempDir dir;
  std::ifstream in(log, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::ofstream(dir / "cut.log.gz", std::ios::binary) << bytes.substr(0, bytes.size() / 2);
  const auto result =
      RunLittermap("import carmen " + Quote(dir / "cut.log.gz") + " -o " + Quote(dir / "bag"));
  EXPECT_EQ(result.exit_code, 2) << result.output;
  EXPECT_NE(result.output.find("truncated"), std::string::npos) << result.output;
}

TEST(ImportCli, UsageErrorsExitOne) {
  test::TempDir dir;
  const auto log = kDatasets / "carmen" / "orebro-corrected.log.gz";
  EXPECT_EQ(RunLittermap("import carmen " + Quote(log)).exit_code, 1) << "no -o";
  EXPECT_EQ(RunLittermap("import carmen " + Quote(dir / "nope.log") + " -o x").exit_code, 2)
      << "a missing input is bad input, as everywhere";
  EXPECT_EQ(RunLittermap("import carmen " + Quote(log) + " -o " + Quote(dir / "bag") +
                         " --odometry-noise banana")
                .exit_code,
            1);
  EXPECT_EQ(RunLittermap("import").exit_code, 1) << "no importer named";
  EXPECT_EQ(RunLittermap("import shapefile x -o y").exit_code, 1);
  std::filesystem::create_directories(dir / "full");
  std::ofstream(dir / "full" / "something") << "x";
  EXPECT_EQ(RunLittermap("import carmen " + Quote(log) + " -o " + Quote(dir / "full")).exit_code, 1)
      << "refuses to write into a non-empty directory";
  EXPECT_TRUE(std::filesystem::exists(dir / "full" / "something"));
}

TEST(ImportCli, HelpDescribesBothImporters) {
  const auto result = RunLittermap("import --help");
  EXPECT_EQ(result.exit_code, 0);
  EXPECT_NE(result.output.find("carmen"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("tum"), std::string::npos) << result.output;
  const auto carmen = RunLittermap("import carmen --help");
  EXPECT_NE(carmen.output.find("--odometry-noise"), std::string::npos) << carmen.output;
  EXPECT_NE(carmen.output.find("--reference"), std::string::npos) << carmen.output;
}

TEST(ImportCli, TumNeedsAKnownCamera) {
  const auto pair = kDatasets / "tum_pair";
  ASSERT_TRUE(std::filesystem::exists(pair / "1.png")) << "missing data set " << pair;
  test::TempDir dir;
  const auto sequence = dir / "desk";
  std::filesystem::create_directories(sequence / "rgb");
  std::filesystem::create_directories(sequence / "depth");
  std::filesystem::copy_file(pair / "1.png", sequence / "rgb" / "1.png");
  std::filesystem::copy_file(pair / "1_depth.png", sequence / "depth" / "1.png");
  std::ofstream(sequence / "rgb.txt") << "1311868164.363181 rgb/1.png\n";
  std::ofstream(sequence / "depth.txt") << "1311868164.373557 depth/1.png\n";

  const auto unknown = RunLittermap("import tum " + Quote(sequence) + " -o " + Quote(dir / "a"));
  EXPECT_EQ(unknown.exit_code, 1) << unknown.output;
  EXPECT_NE(unknown.output.find("--camera"), std::string::npos) << unknown.output;
  const auto bad =
      RunLittermap("import tum " + Quote(sequence) + " -o " + Quote(dir / "b") + " --camera fr9");
  EXPECT_EQ(bad.exit_code, 1) << bad.output;
  const auto good =
      RunLittermap("import tum " + Quote(sequence) + " -o " + Quote(dir / "c") + " --camera fr2");
  EXPECT_EQ(good.exit_code, 0) << good.output;
  EXPECT_NE(good.output.find("1 colour, 1 depth, 1 camera_info (freiburg2)"), std::string::npos)
      << good.output;
  const auto no_truth = RunLittermap("import tum " + Quote(sequence) + " -o " + Quote(dir / "d") +
                                     " --camera fr2 --reference " + Quote(dir / "ref.tum"));
  EXPECT_EQ(no_truth.exit_code, 2) << "groundtruth.txt is missing: " << no_truth.output;
}

}  // namespace
}  // namespace littermap
