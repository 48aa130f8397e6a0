// The report files of the fixture site: one self-contained page that escapes what people typed,
// and report.json with the same figures.

#include <gtest/gtest.h>

#include <cctype>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "reports/fixture_site.hpp"
#include "reports/report_files.hpp"
#include "reports/site_map_figure.hpp"
#include "support/temp_dir.hpp"
#include "support/test_files.hpp"

namespace littermap::reports {
namespace {

using test::TempDir;

using test::Slurp;

// Occurrences of a plain substring (std::regex recurses per character: the page's base64 images
// would overflow the stack).
std::size_t Occurrences(const std::string& text, const std::string& needle) {
  std::size_t count = 0;
  for (std::size_t at = text.find(needle); at != std::string::npos;
       at = text.find(needle, at + needle.size())) {
    ++count;
  }
  return count;
}

TEST(HtmlReport, IsOneSelfContainedPageThatEscapesNames) {
  TempDir dir;
  db::SiteDatabase site =
      CreateFixtureSite(dir / "park.gpkg", "<script>alert('x')</script> & \"Park\"");
  ReportFilesOptions options;
  options.figures.hotspot_min_items = 1;  // the fixture's litter lies one or two items per place
  options.html.generated_utc = "2026-11-27 12:00";
  options.html.version = "test";
  const SiteReport report = WriteReportFiles(site, dir / "report", options);
  const std::string html = Slurp(dir / "report" / "index.html");

  EXPECT_EQ(html.find("<script"), std::string::npos);
  EXPECT_NE(html.find("&lt;script&gt;alert(&#39;x&#39;)&lt;/script&gt; &amp; &quot;Park&quot;"),
            std::string::npos);
  // Nothing to fetch: every image inline, no URL but the SVG namespace.
  EXPECT_EQ(Occurrences(html, "<img "), 1 + report.hotspots.size());
  EXPECT_EQ(Occurrences(html, "src=\"data:image/png;base64,"), 1 + report.hotspots.size());
  EXPECT_EQ(Occurrences(html, "src="), 1 + report.hotspots.size());
  EXPECT_EQ(Occurrences(html, "http://"),
            Occurrences(html, "xmlns=\"http://www.w3.org/2000/svg\""));
  EXPECT_EQ(Occurrences(html, "https://"), 0u);
  for (const char* fetch : {"<link", "<script", "@import", "url(", "<iframe", "<object"}) {
    EXPECT_EQ(Occurrences(html, fetch), 0u) << fetch;
  }
  // One hotspot row each, every section there, A4 print rules.
  EXPECT_EQ(Occurrences(html, "<img class=\"close-up\""), report.hotspots.size());
  for (const char* section :
       {"id=\"map\"", "id=\"hotspots\"", "id=\"classes\"", "id=\"change\"", "id=\"quality\""}) {
    EXPECT_NE(html.find(section), std::string::npos) << section;
  }
  EXPECT_NE(html.find("@page { size: A4"), std::string::npos);
  EXPECT_NE(html.find("name=\"viewport\""), std::string::npos);
  EXPECT_EQ(Occurrences(html, "<tr><td>2026-11-"), 3u);  // one row per run in the change table
}

// Plain language for park staff: directions instead of signed metres, kinds in lower case
// mid-sentence, each warning once, the tracking figures folded away, trends with their values.
TEST(HtmlReport, SpeaksPlainly) {
  TempDir dir;
  db::SiteDatabase site = CreateFixtureSite(dir / "park.gpkg", "Park");
  ReportFilesOptions options;
  options.figures.hotspot_min_items = 1;  // the fixture's litter lies one or two items per place
  options.html.generated_utc = "2026-11-27 12:00";
  options.html.version = "test";
  WriteReportFiles(site, dir / "report", options);
  const std::string html = Slurp(dir / "report" / "index.html");
  EXPECT_EQ(html.find(" m east, "), std::string::npos) << "signed metres east and north";
  EXPECT_NE(html.find(" of the dock"), std::string::npos);
  for (std::size_t at = html.find("mostly "); at != std::string::npos;
       at = html.find("mostly ", at + 1)) {
    EXPECT_TRUE(std::islower(static_cast<unsigned char>(html[at + 7]))) << html.substr(at, 30);
  }
  EXPECT_EQ(Occurrences(html, "<details><summary>Technical details</summary>"), 1u);
  EXPECT_LE(Occurrences(html, "<ul class=\"warnings\">"), 1u);
  EXPECT_NE(html.find("<ul class=\"certainty\">"), std::string::npos);
  EXPECT_EQ(Occurrences(html, "<line class=\"base\""), Occurrences(html, "<svg class=\"spark\""));
}

// The hotspot numbers on the map cover none of each other, however close the hotspots: here
// every place with one item is a hotspot, several of them a few metres apart.
TEST(HtmlReport, HotspotNumbersCoverNoOther) {
  TempDir dir;
  db::SiteDatabase site = CreateFixtureSite(dir / "park.gpkg", "Park");
  SiteReportOptions options;
  options.hotspot_min_items = 1;
  options.heatmap.density.kernel.bandwidth_m = 1.0;  // more, smaller hotspots
  const SiteReport report = BuildSiteReport(site, options);
  ASSERT_GE(report.hotspots.size(), 3u);
  const SiteMapFigure figure = DrawSiteMap(report, {});
  ASSERT_EQ(figure.label_boxes.size(), report.hotspots.size());
  const cv::Rect map(0, 0, figure.map.cols, figure.map.rows);
  for (std::size_t i = 0; i < figure.label_boxes.size(); ++i) {
    const cv::Rect& box = figure.label_boxes[i];
    EXPECT_EQ(box & map, box) << "number " << i + 1 << " leaves the map";
    for (std::size_t j = 0; j < i; ++j) {
      EXPECT_EQ((box & figure.label_boxes[j]).area(), 0) << j + 1 << " and " << i + 1;
    }
  }
}

TEST(HtmlReport, TheSummaryLineCountsInWords) {
  SiteReport report;
  report.site_name = "P";
  report.runs.resize(1);
  report.items = 1;
  report.hotspots.resize(1);
  EXPECT_EQ(ReportSummary(report, "out"),
            "Report of P: 1 run, 1 litter item, 1 hotspot\nout/index.html");
  report.runs.resize(3);
  report.items = 21;
  report.hotspots.clear();
  EXPECT_EQ(ReportSummary(report, "out"),
            "Report of P: 3 runs, 21 litter items, 0 hotspots\nout/index.html");
}

TEST(HtmlReport, ReportJsonCarriesTheSameFigures) {
  TempDir dir;
  db::SiteDatabase site = CreateFixtureSite(dir / "park.gpkg", "Park");
  ReportFilesOptions options;
  options.figures.hotspot_min_items = 1;  // the fixture's litter lies one or two items per place
  const SiteReport report = WriteReportFiles(site, dir / "report", options);
  const auto json = nlohmann::json::parse(Slurp(dir / "report" / "report.json"));
  EXPECT_EQ(json["site"]["name"], "Park");
  EXPECT_TRUE(json["site"]["epsg_code"].is_null());
  EXPECT_EQ(json["totals"]["runs"], 3);
  EXPECT_EQ(json["totals"]["items"], report.items);
  EXPECT_EQ(json["totals"]["detections"], report.detections);
  EXPECT_EQ(json["items_by_class"]["cup"], 2);
  ASSERT_EQ(json["runs"].size(), 3u);
  EXPECT_EQ(json["runs"][1]["name"], "week 2");
  EXPECT_EQ(json["runs"][1]["items_gone"], 1);
  EXPECT_EQ(json["runs"][0]["start"]["utc"], "2026-11-01T09:20:00Z");
  EXPECT_EQ(json["runs"][0]["reconstruction"]["routines"]["odometry-only"], 20);
  ASSERT_EQ(json["hotspots"].size(), report.hotspots.size());
  ASSERT_FALSE(report.hotspots.empty());
  EXPECT_EQ(json["hotspots"][0]["rank"], 1);
  EXPECT_DOUBLE_EQ(json["hotspots"][0]["density_per_100m2"].get<double>(),
                   report.hotspots[0].density_per_100m2);
  EXPECT_EQ(json["hotspots"][0]["density_by_run"].size(), 3u);
}

TEST(HtmlReport, AnOutputFolderBelowAFileIsBadInput) {
  TempDir dir;
  db::SiteDatabase site = CreateFixtureSite(dir / "park.gpkg", "Park");
  std::ofstream(dir / "blocker") << "a file, not a directory";
  try {
    WriteReportFiles(site, dir / "blocker" / "report", {});
    ADD_FAILURE() << "a report was written below a file";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::kBadInput) << e.what();
  }
}

}  // namespace
}  // namespace littermap::reports
