// Several processes ingest overlapping runs into one PostGIS site at once, with each of the two
// ways of keeping its writers apart (issue 34 asks which to take): the site's advisory lock, or
// SERIALIZABLE transactions that PostgreSQL aborts on a conflict and littermap runs again. For
// each way: the wall time of all runs (median and slowest of the repetitions), the transactions
// run again, the ingests that failed, and whether the site ends equal to one process ingesting
// the runs in order (every item's class, place and times seen; the number of detections).
//   site_concurrency_bench --postgis URL [--processes 8] [--runs-per-process 5]
//                          [--items-per-run 400] [--repetitions 3]
// Overlapping runs: run k drives along y = 10 m and sees every shared item j with
// (j + k) % 3 == 0 on a 1 m lattice beside it, and 10 items no other run sees (1 m apart, 1.5 m
// from the shared ones); so any two runs share items. Then the same runs each in a strip of its
// own (y = 10 + 5k m), where no item is seen twice: the case where transactions could overlap. Not
// pinned to one core: the processes and the server run side by side.

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

#include "db/postgres_connection.hpp"
#include "db/site_database.hpp"
#include "site/run_ingest.hpp"

namespace {

using namespace littermap;

struct Workload {
  bool strips = false;  // each run in a strip of its own: no item seen by two runs
  int processes = 8;
  int runs_per_process = 5;
  int items_per_run = 400;
  int runs() const { return processes * runs_per_process; }
};

site::RunInput SurveyRun(int k, const Workload& load) {
  site::RunInput run;
  run.name = "run " + std::to_string(k);
  run.source_digest = "concurrency-" + std::to_string(k);
  run.start_time_s = 1.7e9 + 86400.0 * k;
  const int shared = 3 * load.items_per_run;
  run.end_time_s = run.start_time_s + shared;
  const double y_m = load.strips ? 10.0 + 5.0 * k : 10.0;
  for (int i = 0; i <= 2 * shared; ++i) run.T_site_base.push_back({0.5 * i, y_m, 0.0});
  const char* classes[] = {"bottle", "can", "cup", "carton"};
  for (int j = 0; j < shared; ++j) {
    if ((j + k) % 3 != 0) continue;
    run.items.push_back(
        {"s" + std::to_string(j), classes[j % 4], {1.0 * j, y_m + 0.5}, 0.0, 0.1, 0.9});
  }
  for (int u = 0; u < 10; ++u) {
    run.items.push_back(
        {"u" + std::to_string(u), "plastic_bag", {10.0 * k + u + 0.5, y_m - 1.0}, 0.0, 0.2, 0.8});
  }
  return run;
}

using ItemKey = std::tuple<std::string, double, double, int>;

struct SiteOutcome {
  std::vector<ItemKey> items;
  std::size_t detections = 0;
  bool operator==(const SiteOutcome&) const = default;
};

SiteOutcome Outcome(db::SiteDatabase& site) {
  SiteOutcome outcome;
  for (const db::ItemRecord& item : site.Items()) {
    outcome.items.emplace_back(item.class_name, item.site_xy.x, item.site_xy.y, item.times_seen);
  }
  std::sort(outcome.items.begin(), outcome.items.end());
  outcome.detections = site.AllDetections().size();
  return outcome;
}

db::SiteDatabase NewSite(const db::SiteLocator& where) {
  db::SiteDatabase::Remove(where);
  db::SiteOptions options;
  options.name = "Concurrency park";
  options.epsg_code = 32633;
  options.origin_easting_m = 500000;
  options.origin_northing_m = 5000000;
  return db::SiteDatabase::Create(where, options);
}

double SecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

struct Repetition {
  double wall_s = 0;
  std::size_t retried = 0;
  int failed = 0;  // processes that exited with an error
  bool equal = false;
};

// One repetition: the processes ingest their runs (process p: runs p, p + P, p + 2P, ...).
Repetition RunAtOnce(const db::SiteLocator& where, db::PostgresWriteSerialisation mode,
                     const Workload& load, const SiteOutcome& expected) {
  NewSite(where);
  std::vector<std::pair<pid_t, int>> children;  // pid, read end of its pipe
  const auto start = std::chrono::steady_clock::now();
  for (int p = 0; p < load.processes; ++p) {
    int pipe_ends[2];
    if (pipe(pipe_ends) != 0) throw std::runtime_error("pipe failed");
    const pid_t pid = fork();
    if (pid == 0) {
      close(pipe_ends[0]);
      int code = 0;
      std::size_t retried = 0;
      try {
        db::SiteDatabase site = db::SiteDatabase::Open(where);
        dynamic_cast<db::PostgresConnection&>(site.sql()).set_write_serialisation(mode);
        for (int k = p; k < load.runs(); k += load.processes) {
          site::IngestRun(site, SurveyRun(k, load), {});
        }
        retried = site.conflicts_retried();
      } catch (const std::exception& e) {
        std::fprintf(stderr, "process %d: %s\n", p, e.what());
        code = 1;
      }
      if (write(pipe_ends[1], &retried, sizeof retried) != sizeof retried) code = 2;
      _exit(code);
    }
    close(pipe_ends[1]);
    children.emplace_back(pid, pipe_ends[0]);
  }
  Repetition repetition;
  for (const auto& [pid, read_end] : children) {
    std::size_t retried = 0;
    if (read(read_end, &retried, sizeof retried) == sizeof retried) repetition.retried += retried;
    close(read_end);
    int status = 0;
    waitpid(pid, &status, 0);
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) ++repetition.failed;
  }
  repetition.wall_s = SecondsSince(start);
  db::SiteDatabase site = db::SiteDatabase::Open(where);
  repetition.equal = Outcome(site) == expected;
  return repetition;
}

struct Column {
  std::string name;
  std::vector<Repetition> repetitions;
  double Median() const {
    std::vector<double> walls;
    for (const Repetition& r : repetitions) walls.push_back(r.wall_s);
    std::sort(walls.begin(), walls.end());
    return walls[walls.size() / 2];
  }
  double Slowest() const {
    double slowest = 0;
    for (const Repetition& r : repetitions) slowest = std::max(slowest, r.wall_s);
    return slowest;
  }
  template <typename Field>
  double Mean(Field field) const {
    double sum = 0;
    for (const Repetition& r : repetitions) sum += static_cast<double>(r.*field);
    return sum / static_cast<double>(repetitions.size());
  }
  int Equal() const {
    return static_cast<int>(
        std::count_if(repetitions.begin(), repetitions.end(), [](auto& r) { return r.equal; }));
  }
};

}  // namespace

int main(int argc, char** argv) {
  Workload load;
  int repetitions = 3;
  std::string postgis;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string key = argv[i];
    const int number = std::atoi(argv[i + 1]);
    if (key == "--postgis") postgis = argv[i + 1];
    if (key == "--processes") load.processes = number;
    if (key == "--runs-per-process") load.runs_per_process = number;
    if (key == "--items-per-run") load.items_per_run = number;
    if (key == "--repetitions") repetitions = number;
  }
  if (postgis.empty() || load.processes < 1 || load.runs_per_process < 1 || repetitions < 1) {
    std::fprintf(stderr,
                 "usage: site_concurrency_bench --postgis URL [--processes N] "
                 "[--runs-per-process N] [--items-per-run N] [--repetitions N]\n"
                 "(scripts/postgis.sh start gives a URL)\n");
    return 2;
  }
  const db::SiteLocator where = db::ParseSiteLocator(postgis + "?site=concurrency_bench");
  for (const bool strips : {false, true}) {
    load.strips = strips;
    std::vector<Column> columns = {{"advisory lock", {}}, {"SERIALIZABLE, run again", {}}};
    const db::PostgresWriteSerialisation modes[] = {
        db::PostgresWriteSerialisation::kAdvisoryLock,
        db::PostgresWriteSerialisation::kSerializableTransactions};
    double sequential_s = 0;
    try {
      SiteOutcome expected;
      {
        db::SiteDatabase site = NewSite(where);
        const auto start = std::chrono::steady_clock::now();
        for (int k = 0; k < load.runs(); ++k) site::IngestRun(site, SurveyRun(k, load), {});
        sequential_s = SecondsSince(start);
        expected = Outcome(site);
      }
      for (int r = 0; r < repetitions; ++r) {
        for (std::size_t m = 0; m < columns.size(); ++m) {
          columns[m].repetitions.push_back(RunAtOnce(where, modes[m], load, expected));
          std::fprintf(stderr, "%s: repetition %d, %.2f s\n", columns[m].name.c_str(), r + 1,
                       columns[m].repetitions.back().wall_s);
        }
      }
      db::SiteDatabase::Remove(where);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "site_concurrency_bench: %s\n", e.what());
      return 1;
    }
    std::printf(
        "%s: %d processes x %d runs, %d items each (one process, the runs in order: %.2f s)\n\n"
        "| | %s | %s |\n|---|---|---|\n",
        strips ? "Runs in strips of their own" : "Overlapping runs", load.processes,
        load.runs_per_process, load.items_per_run, sequential_s, columns[0].name.c_str(),
        columns[1].name.c_str());
    const auto row = [&](const char* name, const auto& cell) {
      std::printf("| %s | %s | %s |\n", name, cell(columns[0]).c_str(), cell(columns[1]).c_str());
    };
    const auto format = [](const char* pattern, double value) {
      char text[32];
      std::snprintf(text, sizeof text, pattern, value);
      return std::string(text);
    };
    row("wall time, median", [&](const Column& c) { return format("%.2f s", c.Median()); });
    row("wall time, slowest", [&](const Column& c) { return format("%.2f s", c.Slowest()); });
    row("transactions run again (mean)",
        [&](const Column& c) { return format("%.1f", c.Mean(&Repetition::retried)); });
    row("processes failed (mean)",
        [&](const Column& c) { return format("%.1f", c.Mean(&Repetition::failed)); });
    row("site equal to the sequential ingest", [&](const Column& c) {
      return std::to_string(c.Equal()) + " of " + std::to_string(repetitions);
    });
    std::printf("\n");
  }
  return 0;
}
