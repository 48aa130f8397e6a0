// Every command that writes a run's or a site's outputs, on a disk that fills up. A file size
// limit (ulimit -f, in 512-byte blocks) makes every write beyond it fail with EFBIG, as a full
// disk fails with ENOSPC. Each command either completes or exits 4 naming what it could not
// write; the outputs it leaves are whole (the bytes a run with room writes), never truncated
// files that look finished; no temporary file stays behind; and the site database passes
// PRAGMA integrity_check, holding the run wholly or not at all. (capture: capture_cli_test.cpp.)

#include <gtest/gtest.h>

#include <filesystem>
#include <functional>
#include <set>
#include <string>

#include <nlohmann/json.hpp>

#include "core/sqlite_database.hpp"
#include "support/run_command.hpp"
#include "support/temp_dir.hpp"
#include "support/test_files.hpp"

namespace littermap {
namespace {

namespace fs = std::filesystem;
using test::CommandResult;
using test::Quote;
using test::RunLittermap;
using test::Slurp;

// File size limits that stop each command at a different file: 0.5 kB, 8 kB and 64 kB.
constexpr int kLimitsBlocks[] = {1, 16, 128};

std::string SiteText(const fs::path& site, const std::string& sql) {
  SqliteDatabase database(site, SqliteDatabase::Mode::kReadOnly);
  SqliteStatement query = database.Prepare(sql);
  return query.Step() ? query.ColumnText(0) : "<no row>";
}

// Files whose contents carry the time they were made: whole when they parse to the end.
bool StampedFileIsWhole(const fs::path& file) {
  const std::string text = Slurp(file);
  if (file.extension() == ".json") return nlohmann::json::accept(text);
  if (file.extension() == ".html") return text.ends_with("</html>\n");
  return false;
}

bool IsStamped(const fs::path& file) {
  const std::string name = file.filename().string();
  return name == "quality.json" || name == "report.json" || name == "index.html";
}

// A command under a limit: exit 0, or exit 4 with a message naming a file of `out`; whatever it
// left in `out` is whole.
void ExpectWholeOrFailed(const CommandResult& result, const fs::path& good, const fs::path& out,
                         const std::string& what) {
  SCOPED_TRACE(what);
  ASSERT_TRUE(result.exit_code == 0 || result.exit_code == 4) << result.output;
  if (result.exit_code == 4) {
    EXPECT_NE(result.output.find(out.parent_path().string()), std::string::npos) << result.output;
  }
  if (!fs::exists(out)) return;
  for (const fs::directory_entry& entry : fs::recursive_directory_iterator(out)) {
    if (!entry.is_regular_file()) continue;
    const fs::path relative = fs::relative(entry.path(), out);
    EXPECT_NE(entry.path().extension(), ".tmp") << relative << " left behind";
    if (entry.path().extension() == ".tmp" || entry.path().extension() == ".gpkg") continue;
    ASSERT_TRUE(fs::exists(good / relative)) << relative << " is not an output";
    if (IsStamped(entry.path())) {
      EXPECT_TRUE(StampedFileIsWhole(entry.path())) << relative << " is cut short";
    } else {
      EXPECT_EQ(Slurp(entry.path()), Slurp(good / relative)) << relative << " differs";
    }
  }
}

// Copies a run folder without the files detect writes.
void CopyReconstruction(const fs::path& from, const fs::path& to) {
  fs::create_directories(to);
  for (const fs::directory_entry& entry : fs::directory_iterator(from)) {
    const std::string name = entry.path().filename().string();
    if (name == "items.csv" || name == "detections.csv") continue;
    fs::copy(entry.path(), to / name, fs::copy_options::recursive);
  }
}

TEST(FullDiskCli, EveryCommandCompletesOrFailsLeavingOnlyWholeFiles) {
  test::TempDir d;
  const auto bag = d / "bag";
  auto result = RunLittermap("simulate " + Quote(test::SampleWorld()) + " -o " + Quote(bag) +
                             " --truth " + Quote(d / "truth") + " --duration 15 --quiet");
  ASSERT_EQ(result.exit_code, 0) << result.output;

  // With room: the outputs every limited command is compared with.
  const auto good = d / "good";
  const std::string init = " --name p --crs EPSG:32633 --origin 500000 5000000";
  const std::function<std::string(const fs::path&)> commands[] = {
      [&](const fs::path& dir) {
        return "reconstruct " + Quote(bag) + " -o " + Quote(dir / "run");
      },
      [&](const fs::path& dir) {
        return "detect " + Quote(bag) + " --run " + Quote(dir / "run") + " --every 3";
      },
      [&](const fs::path& dir) { return "site init " + Quote(dir / "site.gpkg") + init; },
      [&](const fs::path& dir) {
        return "ingest " + Quote(dir / "site.gpkg") + " " + Quote(dir / "run") + " --name week1";
      },
      [&](const fs::path& dir) {
        return "heatmap " + Quote(dir / "site.gpkg") + " -o " + Quote(dir / "maps");
      },
      [&](const fs::path& dir) {
        return "report " + Quote(dir / "site.gpkg") + " -o " + Quote(dir / "report");
      }};
  for (const auto& command : commands) {
    result = RunLittermap("-q " + command(good));
    ASSERT_EQ(result.exit_code, 0) << command(good) << "\n" << result.output;
  }
  ASSERT_EQ(SiteText(good / "site.gpkg", "SELECT count(*) FROM runs"), "1");

  std::set<int> failed_exit_codes;
  for (const int blocks : kLimitsBlocks) {
    const auto dir = d / ("limit" + std::to_string(blocks));
    const std::string limit = " at " + std::to_string(blocks * 512) + " bytes";
    fs::create_directories(dir);

    result = RunLittermap("-q " + commands[0](dir), blocks);
    ExpectWholeOrFailed(result, good / "run", dir / "run", "reconstruct" + limit);
    failed_exit_codes.insert(result.exit_code);

    // detect on the whole reconstruction: only its own files are limited.
    fs::remove_all(dir / "run");
    CopyReconstruction(good / "run", dir / "run");
    result = RunLittermap("-q " + commands[1](dir), blocks);
    ExpectWholeOrFailed(result, good / "run", dir / "run", "detect" + limit);
    failed_exit_codes.insert(result.exit_code);

    // ingest of the whole run into a new site: the run is in the site wholly or not at all.
    fs::remove_all(dir / "run");
    fs::copy(good / "run", dir / "run", fs::copy_options::recursive);
    ASSERT_EQ(RunLittermap("-q " + commands[2](dir)).exit_code, 0);
    result = RunLittermap("-q " + commands[3](dir), blocks);
    ASSERT_TRUE(result.exit_code == 0 || result.exit_code == 4) << "ingest" << limit << "\n"
                                                                << result.output;
    failed_exit_codes.insert(result.exit_code);
    EXPECT_EQ(SiteText(dir / "site.gpkg", "PRAGMA integrity_check"), "ok") << "ingest" << limit;
    EXPECT_EQ(SiteText(dir / "site.gpkg", "SELECT count(*) FROM runs"),
              result.exit_code == 0 ? "1" : "0")
        << "ingest" << limit;
    EXPECT_EQ(SiteText(dir / "site.gpkg", "SELECT count(*) FROM litter_items"),
              result.exit_code == 0
                  ? SiteText(good / "site.gpkg", "SELECT count(*) FROM litter_items")
                  : "0")
        << "ingest" << limit;

    // heatmap and report of the whole site (heatmap stores the hotspots in it).
    fs::copy_file(good / "site.gpkg", dir / "site.gpkg", fs::copy_options::overwrite_existing);
    result = RunLittermap("-q " + commands[4](dir), blocks);
    ExpectWholeOrFailed(result, good / "maps", dir / "maps", "heatmap" + limit);
    failed_exit_codes.insert(result.exit_code);
    EXPECT_EQ(SiteText(dir / "site.gpkg", "PRAGMA integrity_check"), "ok") << "heatmap" << limit;
    fs::copy_file(good / "site.gpkg", dir / "site.gpkg", fs::copy_options::overwrite_existing);
    result = RunLittermap("-q " + commands[5](dir), blocks);
    ExpectWholeOrFailed(result, good / "report", dir / "report", "report" + limit);
    failed_exit_codes.insert(result.exit_code);
  }
  // The limits are small enough that the commands do fail, not only complete.
  EXPECT_TRUE(failed_exit_codes.contains(4));
}

}  // namespace
}  // namespace littermap
