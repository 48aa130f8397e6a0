// Ingest into a site database, on both engines: idempotency, item persistence across runs,
// coverage, and the site heatmap built from what was ingested.

#include "site/run_ingest.hpp"

#include <gtest/gtest.h>

#include <fstream>

#include "core/error.hpp"
#include "heatmap/site_heatmap.hpp"
#include "support/site_engines.hpp"
#include "support/temp_dir.hpp"

namespace littermap::site {
namespace {

using littermap::test::SiteEngine;
using littermap::test::TempDir;
using littermap::test::TestSite;

// A run driving east along y = 10 from x = 0 to x = 30 (10 cm steps).
RunInput EastRun(const std::string& digest, double start_time_s) {
  RunInput run;
  run.name = digest;
  run.source_digest = digest;
  run.start_time_s = start_time_s;
  run.end_time_s = start_time_s + 60.0;
  for (int i = 0; i <= 300; ++i) run.T_site_base.push_back({0.1 * i, 10.0, 0.0});
  return run;
}

RunItem Item(const std::string& id, const std::string& class_name, double x, double y) {
  RunItem item;
  item.id = id;
  item.class_name = class_name;
  item.xy = {x, y};
  item.size_m = 0.1;
  return item;
}

class RunIngestTest : public ::testing::TestWithParam<SiteEngine> {
 protected:
  db::SiteDatabase Site() {
    db::SiteOptions options;
    options.name = "test";
    return db::SiteDatabase::Create(site_.locator(), options);
  }
  TempDir dir_;
  TestSite site_{GetParam(), dir_.path(), "site"};
};

INSTANTIATE_TEST_SUITE_P(Engines, RunIngestTest,
                         ::testing::Values(SiteEngine::kGeoPackage, SiteEngine::kPostgis),
                         littermap::test::SiteEngineName);

TEST_P(RunIngestTest, IngestingARunTwiceChangesNothing) {
  db::SiteDatabase site = Site();
  RunInput run = EastRun("run-a", 1000.0);
  run.items = {Item("1", "can", 10.0, 11.0), Item("2", "bottle", 20.0, 9.5)};
  const IngestResult first = IngestRun(site, run, {});
  EXPECT_FALSE(first.already_ingested);
  EXPECT_EQ(first.new_items, 2u);
  EXPECT_EQ(first.detections, 2u);
  EXPECT_NEAR(first.length_m, 30.0, 1e-9);
  EXPECT_GT(first.observed_area_m2, 30.0 * 3.0);
  const IngestResult second = IngestRun(site, run, {});
  EXPECT_TRUE(second.already_ingested);
  EXPECT_EQ(second.run_id, first.run_id);
  EXPECT_EQ(site.Runs().size(), 1u);
  EXPECT_EQ(site.Items().size(), 2u);
  EXPECT_EQ(site.DetectionCount(first.run_id), 2u);
  EXPECT_EQ(site.Coverages().size(), 1u);
  EXPECT_EQ(site.RunTracks().size(), 1u);
}

TEST_P(RunIngestTest, AnItemSeenAgainIsTheSameItem) {
  db::SiteDatabase site = Site();
  RunInput a = EastRun("run-a", 1000.0);
  a.items = {Item("1", "can", 10.0, 11.0)};
  RunInput b = EastRun("run-b", 2000.0);
  b.items = {Item("7", "carton", 10.2, 11.1),  // the can, 0.22 m off, classified otherwise
             Item("9", "can", 25.0, 11.0)};    // a new can
  IngestRun(site, a, {});
  const IngestResult result = IngestRun(site, b, {});
  EXPECT_EQ(result.items_seen_again, 1u);
  EXPECT_EQ(result.new_items, 1u);
  const auto items = site.Items();
  ASSERT_EQ(items.size(), 2u);
  EXPECT_EQ(items[0].times_seen, 2);
  EXPECT_EQ(items[0].first_run_id, 1);
  EXPECT_EQ(items[0].last_run_id, 2);
  EXPECT_EQ(items[0].class_name, "can");  // the item keeps its first class ...
  const auto detections = site.Detections({2});
  ASSERT_EQ(detections.size(), 2u);
  EXPECT_EQ(detections[0].class_name, "carton");  // ... each detection its own
  EXPECT_EQ(items[1].times_seen, 1);
}

TEST_P(RunIngestTest, NearestPairsMatchFirst) {
  db::SiteDatabase site = Site();
  RunInput a = EastRun("run-a", 1000.0);
  a.items = {Item("1", "can", 10.0, 11.0), Item("2", "can", 10.6, 11.0)};
  IngestRun(site, a, {});
  // The first item of run b is 0.4 m from can 1 and 0.2 m from can 2; the second lies on can 2.
  // In run order the first would take can 2 and leave the second can 1, 0.6 m off; nearest
  // pairs first, each takes the can it lies on or nearest to.
  RunInput b = EastRun("run-b", 2000.0);
  b.items = {Item("1", "can", 10.4, 11.0), Item("2", "can", 10.6, 11.0)};
  const IngestResult result = IngestRun(site, b, {});
  EXPECT_EQ(result.items_seen_again, 2u);
  EXPECT_EQ(result.new_items, 0u);
  const auto detections = site.Detections({2});
  ASSERT_EQ(detections.size(), 2u);
  EXPECT_EQ(*detections[0].item_fid, 1);
  EXPECT_EQ(*detections[1].item_fid, 2);
}

TEST_P(RunIngestTest, CloseItemsOfOneRunStayTwoItems) {
  db::SiteDatabase site = Site();
  RunInput a = EastRun("run-a", 1000.0);
  a.items = {Item("1", "can", 10.0, 11.0), Item("2", "can", 10.3, 11.0)};
  EXPECT_EQ(IngestRun(site, a, {}).new_items, 2u);
  // A later run sees both again: each matches one of them, not the same one twice.
  RunInput b = EastRun("run-b", 2000.0);
  b.items = {Item("1", "can", 10.1, 11.0), Item("2", "can", 10.2, 11.0)};
  const IngestResult result = IngestRun(site, b, {});
  EXPECT_EQ(result.items_seen_again, 2u);
  EXPECT_EQ(result.new_items, 0u);
}

TEST_P(RunIngestTest, TruthItemsOutsideTheCameraCoverageAreSkipped) {
  db::SiteDatabase site = Site();
  RunInput run = EastRun("run-a", 1000.0);
  run.items = {Item("1", "can", 10.0, 10.5), Item("2", "can", 10.0, 30.0),  // 20 m to the side
               Item("3", "cup", 5.0, 10.0)};
  IngestOptions options;
  options.drop_unobserved_items = true;
  const IngestResult result = IngestRun(site, run, options);
  EXPECT_EQ(result.items_unobserved, 1u);
  EXPECT_EQ(result.new_items, 2u);
}

TEST_P(RunIngestTest, RefusesARunWithoutATrajectory) {
  db::SiteDatabase site = Site();
  RunInput run = EastRun("run-a", 0.0);
  run.T_site_base.resize(1);
  EXPECT_THROW(IngestRun(site, run, {}), BadInputError);
  IngestOptions options;
  options.same_item_radius_m = 0.0;
  EXPECT_THROW(IngestRun(site, EastRun("run-b", 0.0), options), UsageError);
  EXPECT_TRUE(site.Runs().empty());
}

TEST_P(RunIngestTest, SiteHeatmapSumsEffortAndSelectsRuns) {
  db::SiteDatabase site = Site();
  RunInput a = EastRun("run-a", 1000.0);
  a.items = {Item("1", "can", 10.0, 11.0), Item("2", "cup", 20.0, 11.0)};
  RunInput b = EastRun("run-b", 5000.0);
  b.items = {Item("3", "can", 15.0, 11.0)};
  IngestRun(site, a, {});
  IngestRun(site, b, {});

  heatmap::SiteHeatmapOptions options;
  heatmap::SiteHeatmap all = heatmap::ComputeSiteHeatmap(site, options);
  float max_effort = 0.0f;
  for (float v : all.effort.values) max_effort = std::max(max_effort, v);
  EXPECT_EQ(max_effort, 2.0f);  // the two runs overlap
  EXPECT_EQ(all.items.size(), 3u);
  EXPECT_EQ(all.run_ids.size(), 2u);

  options.class_name = "can";
  EXPECT_EQ(heatmap::ComputeSiteHeatmap(site, options).items.size(), 2u);
  options.class_name.clear();
  options.to_time_s = 2000.0;  // only run a
  const heatmap::SiteHeatmap early = heatmap::ComputeSiteHeatmap(site, options);
  EXPECT_EQ(early.run_ids.size(), 1u);
  EXPECT_EQ(early.items.size(), 2u);
  options.from_time_s = 9000.0;
  options.to_time_s.reset();
  EXPECT_THROW(heatmap::ComputeSiteHeatmap(site, options), BadInputError);
}

TEST_P(RunIngestTest, StaticLitterKeepsItsDensityWhenSurveyedMoreOften) {
  db::SiteDatabase site = Site();
  RunInput a = EastRun("run-a", 1000.0);
  a.items = {Item("1", "can", 10.0, 11.0)};
  RunInput b = EastRun("run-b", 5000.0);
  b.items = {Item("1", "can", 10.0, 11.0)};  // still there
  IngestRun(site, a, {});
  IngestRun(site, b, {});
  heatmap::SiteHeatmapOptions options;
  const heatmap::SiteHeatmap both = heatmap::ComputeSiteHeatmap(site, options);
  options.to_time_s = 2000.0;
  const heatmap::SiteHeatmap first = heatmap::ComputeSiteHeatmap(site, options);
  EXPECT_EQ(both.items.size(), 1u);
  EXPECT_EQ(both.detections, 2u);
  EXPECT_NEAR(both.density.max_density, first.density.max_density,
              1e-4 * first.density.max_density);
  EXPECT_GT(first.density.max_density, 0.0f);
}

}  // namespace
}  // namespace littermap::site
