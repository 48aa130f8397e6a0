// The command line's rough edges, each with its message and exit code: a mistyped command is
// named with the closest one, a missing input is bad input (2) in every command, a bag's .db3
// file is read as its bag, and stamps are printed to the nanosecond.

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "bag/bag_writer.hpp"
#include "support/run_command.hpp"
#include "support/temp_dir.hpp"
#include "support/test_files.hpp"

namespace littermap {
namespace {

using test::Quote;
using test::RunLittermap;

std::string FirstLine(const std::string& text) { return text.substr(0, text.find('\n')); }

TEST(CommandLineCli, AMistypedCommandIsNamedWithTheClosestOne) {
  const test::CommandResult info = RunLittermap("infoo bag");
  EXPECT_EQ(info.exit_code, 1);
  EXPECT_EQ(FirstLine(info.output),
            "littermap: error: unknown command 'infoo' (did you mean 'info'?); 'littermap "
            "--help' lists the commands");
  const test::CommandResult eval = RunLittermap("eval trajectry a.tum b.tum");
  EXPECT_EQ(eval.exit_code, 1);
  EXPECT_EQ(FirstLine(eval.output),
            "littermap: error: unknown command 'eval trajectry' (did you mean 'eval "
            "trajectory'?); 'littermap eval --help' lists the commands");
  const test::CommandResult far = RunLittermap("-q frobnicate");
  EXPECT_EQ(far.exit_code, 1);
  EXPECT_EQ(FirstLine(far.output),
            "littermap: error: unknown command 'frobnicate'; 'littermap --help' lists the "
            "commands");
}

TEST(CommandLineCli, AMissingInputIsBadInputInEveryCommand) {
  test::TempDir dir;
  const std::string missing = Quote(dir / "missing");
  ASSERT_EQ(RunLittermap("-q site init " + Quote(dir / "s.gpkg") + " --name p").exit_code, 0);
  for (const std::string& command :
       {"info " + missing, "reconstruct " + missing + " -o " + Quote(dir / "run"),
        "detect " + missing + " --run " + Quote(dir.path()),
        "simulate " + missing + " -o " + Quote(dir / "bag") + " --truth " + Quote(dir / "t"),
        "import carmen " + missing + " -o " + Quote(dir / "bag"),
        "survey " + missing + " --site " + Quote(dir / "s.gpkg"),
        "ingest " + Quote(dir / "s.gpkg") + " " + missing,
        "eval trajectory " + missing + " " + missing}) {
    const test::CommandResult result = RunLittermap("-q " + command);
    EXPECT_EQ(result.exit_code, 2) << command << "\n" << result.output;
    EXPECT_NE(FirstLine(result.output).find((dir / "missing").string()), std::string::npos)
        << command << "\n"
        << result.output;
  }
  EXPECT_FALSE(std::filesystem::exists(dir / "run"));
  EXPECT_FALSE(std::filesystem::exists(dir / "bag"));
}

// Naming the .db3 file instead of the bag folder reads the bag, with a note: it used to warn that
// metadata.yaml was missing or out of date, as after a crash. Stamps are printed from the
// integer nanoseconds, not through a double (1700000000.123456789 became ...123456716).
TEST(CommandLineCli, ABagFileIsReadAsItsBagAndStampsKeepTheirNanoseconds) {
  test::TempDir dir;
  {
    bag::BagWriter writer(dir / "bag");
    writer.AddTopic<msg::String>("/notes", bag::TopicQos::kReliable);
    writer.WriteMessage("/notes", 1'700'000'000'123'456'789LL, msg::String{"note"});
    writer.WriteMessage("/notes", 1'700'000'001'000'000'001LL, msg::String{"note"});
  }
  const test::CommandResult result = RunLittermap("info " + Quote(dir / "bag" / "bag_0.db3"));
  EXPECT_EQ(result.exit_code, 0) << result.output;
  EXPECT_NE(result.output.find((dir / "bag" / "bag_0.db3").string() + ": one file of the bag " +
                               (dir / "bag").string() + "; the whole bag is shown"),
            std::string::npos)
      << result.output;
  EXPECT_EQ(result.output.find("metadata.yaml is missing"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("(1700000000.123456789)"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("(1700000001.000000001)"), std::string::npos) << result.output;
}

}  // namespace
}  // namespace littermap
