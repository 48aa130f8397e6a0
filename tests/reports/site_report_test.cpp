// The figures of a report from a small synthetic site whose answer is known by construction:
// three runs along one straight path, the third shorter, with litter that stays, goes and
// appears between runs.

#include "reports/site_report.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "reports/fixture_site.hpp"
#include "site/run_ingest.hpp"
#include "support/temp_dir.hpp"

namespace littermap::reports {
namespace {

using test::TempDir;

TEST(SiteReport, CountsNewStillThereAndGoneItemsPerRun) {
  TempDir dir;
  db::SiteDatabase site = CreateFixtureSite(dir / "park.gpkg", "Park");
  const SiteReport report = BuildSiteReport(site, {});

  ASSERT_EQ(report.runs.size(), 3u);
  EXPECT_EQ(report.runs[0].name, "week 1");  // by start time, not by ingestion order
  EXPECT_EQ(report.runs[2].name, "week 3");
  // Week 1 finds A, B, C.
  EXPECT_EQ(report.runs[0].items_found, 3u);
  EXPECT_EQ(report.runs[0].new_items, 3u);
  EXPECT_EQ(report.runs[0].items_gone, 0u);
  // Week 2 finds A and C again and D new; B, which it looked at, is gone.
  EXPECT_EQ(report.runs[1].items_found, 3u);
  EXPECT_EQ(report.runs[1].new_items, 1u);
  EXPECT_EQ(report.runs[1].items_still_there, 2u);
  EXPECT_EQ(report.runs[1].items_gone, 1u);
  // Week 3 drives 6 m only: A again, E new; C and D lie beyond its camera, so are not gone.
  EXPECT_EQ(report.runs[2].items_found, 2u);
  EXPECT_EQ(report.runs[2].new_items, 1u);
  EXPECT_EQ(report.runs[2].items_still_there, 1u);
  EXPECT_EQ(report.runs[2].items_gone, 0u);

  EXPECT_EQ(report.items, 5u);
  EXPECT_EQ(report.detections, 8u);
  EXPECT_EQ(report.items_by_class, (ClassCounts{{"bottle", 2}, {"can", 1}, {"cup", 2}}));
  EXPECT_EQ(report.runs[1].items_by_class, (ClassCounts{{"bottle", 2}, {"cup", 1}}));
}

// --min-confidence: an unsure detection is left out of every figure, as if never made.
TEST(SiteReport, AMinimumConfidenceCountsOnlyTheSurerDetections) {
  TempDir dir;
  db::SiteOptions options;
  options.name = "Park";
  db::SiteDatabase site = db::SiteDatabase::Create(dir / "park.gpkg", options);
  const site::RunItem sure{"a", "bottle", {5, 0}, 0, 0.2, 0.9};
  const site::RunItem unsure{"b", "can", {10, 0}, 0, 0.1, 0.3};
  site::IngestRun(site, FixtureRun(1, 20, {sure, unsure}), {});
  site::IngestRun(site, FixtureRun(2, 20, {sure}), {});

  const SiteReport all = BuildSiteReport(site, {});
  EXPECT_EQ(all.items, 2u);
  EXPECT_EQ(all.runs[1].items_gone, 1u);  // the can, which week 2 did not see
  SiteReportOptions sure_only;
  sure_only.heatmap.min_confidence = 0.5;
  const SiteReport report = BuildSiteReport(site, sure_only);
  EXPECT_EQ(report.min_confidence, 0.5);
  EXPECT_EQ(report.items, 1u);
  EXPECT_EQ(report.detections, 2u);
  EXPECT_EQ(report.items_by_class, (ClassCounts{{"bottle", 1}}));
  ASSERT_EQ(report.runs.size(), 2u);
  EXPECT_EQ(report.runs[0].items_found, 1u);
  EXPECT_EQ(report.runs[0].detections, 1u);
  EXPECT_EQ(report.runs[1].items_still_there, 1u);
  EXPECT_EQ(report.runs[1].items_gone, 0u);  // the can never counted
}

TEST(SiteReport, PutsEffortBesideCountsAndFlagsWeakRuns) {
  TempDir dir;
  db::SiteDatabase site = CreateFixtureSite(dir / "park.gpkg", "Park");
  const SiteReport report = BuildSiteReport(site, {});
  const RunFigures& full = report.runs[0];
  const RunFigures& short_run = report.runs[2];
  EXPECT_NEAR(full.length_m, 20.0, 0.2);
  EXPECT_NEAR(short_run.length_m, 6.0, 0.2);
  EXPECT_NEAR(full.coverage_fraction, 1.0, 0.02);
  EXPECT_LT(short_run.coverage_fraction, 0.5);
  EXPECT_NEAR(short_run.items_per_100m2, 100.0 * 2 / short_run.observed_area_m2, 1e-9);
  EXPECT_NEAR(report.surveyed_area_m2, full.observed_area_m2, 0.05 * full.observed_area_m2);

  // Week 1 came with reconstruct's quality: 20 of 110 scans placed by odometry alone.
  EXPECT_TRUE(full.quality.known);
  EXPECT_EQ(full.quality.scans, 110);
  EXPECT_EQ(full.quality.loop_closures_accepted, 2);
  const auto mentions = [](const RunFigures& run, const std::string& text) {
    return std::any_of(run.warnings.begin(), run.warnings.end(),
                       [&](const std::string& w) { return w.find(text) != std::string::npos; });
  };
  EXPECT_TRUE(mentions(full, "18 % of the laser scans were placed by wheel odometry"));
  EXPECT_TRUE(mentions(full, "reconstruction: 3 scans had too few valid ranges"));
  EXPECT_TRUE(mentions(short_run, "covered "));
  EXPECT_TRUE(mentions(short_run, "no reconstruction quality on record"));
  EXPECT_FALSE(mentions(report.runs[1], "covered "));
}

TEST(SiteReport, RanksHotspotsAndFollowsEachAcrossRuns) {
  TempDir dir;
  db::SiteDatabase site = CreateFixtureSite(dir / "park.gpkg", "Park");
  SiteReportOptions options;
  options.hotspot_min_items = 1;  // the fixture's litter lies one or two items per place
  const SiteReport report = BuildSiteReport(site, options);
  ASSERT_GE(report.hotspots.size(), 2u);
  EXPECT_EQ(BuildSiteReport(site, {}).hotspots.size(), 0u) << "3 items make a hotspot";
  // C (found twice) and D, 2 m apart, were surveyed twice: 3 finds in 2 surveys beat A (found
  // three times) and E near the start, 4 finds in 3 surveys. Density is per survey.
  const HotspotFigures& top = report.hotspots[0];
  EXPECT_EQ(top.rank, 1);
  EXPECT_GT(top.site_xy.x, 12.5);
  EXPECT_LT(top.site_xy.x, 15.5);
  EXPECT_FALSE(top.wgs84);  // a local site
  ASSERT_EQ(top.density_by_run.size(), 3u);
  EXPECT_TRUE(top.density_by_run[0]);
  EXPECT_TRUE(top.density_by_run[1]);
  EXPECT_FALSE(top.density_by_run[2]);  // beyond the short run's camera
  const auto start = std::find_if(report.hotspots.begin(), report.hotspots.end(),
                                  [](const HotspotFigures& h) { return h.site_xy.x < 6.5; });
  ASSERT_NE(start, report.hotspots.end());
  for (const auto& density : start->density_by_run) EXPECT_TRUE(density);
  for (std::size_t i = 1; i < report.hotspots.size(); ++i) {
    EXPECT_LE(report.hotspots[i].density_per_100m2, report.hotspots[i - 1].density_per_100m2);
  }
}

TEST(SiteReport, APeriodSelectsRunsButItemHistoryStartsAtTheFirstRun) {
  TempDir dir;
  db::SiteDatabase site = CreateFixtureSite(dir / "park.gpkg", "Park");
  SiteReportOptions options;
  options.from_time_s = kFixtureStart_s + 6 * 86400.0;  // weeks 2 and 3
  const SiteReport report = BuildSiteReport(site, options);
  ASSERT_EQ(report.runs.size(), 2u);
  EXPECT_EQ(report.runs[0].name, "week 2");
  EXPECT_EQ(report.runs[0].new_items, 1u);  // A and C were found in week 1, before the period
  EXPECT_EQ(report.runs[0].items_gone, 1u);
  EXPECT_EQ(report.items, 4u);  // A, C, D, E

  options.from_time_s = kFixtureStart_s + 100 * 86400.0;
  EXPECT_THROW(BuildSiteReport(site, options), BadInputError);
}

}  // namespace
}  // namespace littermap::reports
