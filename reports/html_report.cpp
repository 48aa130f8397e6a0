#include "reports/html_report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>
#include <utility>

#include "core/output_file.hpp"
#include "core/time.hpp"
#include "reports/class_palette.hpp"
#include "reports/html_text.hpp"
#include "reports/plain_words.hpp"
#include "reports/svg_charts.hpp"

namespace littermap::reports {
namespace {

constexpr const char* kNewColour = "#D55E00";
constexpr const char* kStillThereColour = "#0072B2";
constexpr const char* kEffortColour = "#009E73";

constexpr const char* kStyle = R"css(
:root { --ink: #1e1e1e; --muted: #5b5b5b; --line: #d0d0d0; --panel: #f4f5f2; --accent: #2f6b3a; }
* { box-sizing: border-box; }
body { margin: 0; font: 15px/1.45 system-ui, -apple-system, "Segoe UI", Roboto, sans-serif;
  color: var(--ink); background: #fff; }
main { max-width: 1100px; margin: 0 auto; padding: 16px 20px 40px; }
header { border-bottom: 3px solid var(--accent); margin-bottom: 14px; }
h1 { font-size: 1.7em; margin: 0.2em 0 0.1em; }
h2 { font-size: 1.25em; margin: 1.6em 0 0.4em; color: var(--accent); }
p.sub, .muted { color: var(--muted); }
.cards { display: grid; grid-template-columns: repeat(6, 1fr); gap: 8px; margin: 12px 0; }
.card { background: var(--panel); border-radius: 6px; padding: 8px 10px; }
.card b { display: block; font-size: 1.45em; }
.card span { color: var(--muted); font-size: 0.85em; }
.summary { background: var(--panel); border-left: 4px solid var(--accent); padding: 8px 12px; }
figure { margin: 0; }
figure img.map { width: 100%; height: auto; border: 1px solid var(--line); }
.legend { display: flex; flex-wrap: wrap; gap: 6px 18px; align-items: center; margin: 6px 0;
  font-size: 0.9em; }
.swatch { display: inline-block; width: 13px; height: 13px; border: 1px solid #333;
  vertical-align: -2px; margin-right: 4px; }
.dot { border-radius: 50%; }
.ramp { display: inline-block; width: 140px; height: 12px; vertical-align: -1px; margin: 0 4px;
  background: linear-gradient(to right, #440154, #3b528b, #21918c, #5ec962, #fde725); }
.table-wrap { overflow-x: auto; }
table { border-collapse: collapse; width: 100%; margin: 6px 0; font-size: 0.92em; }
th, td { border-bottom: 1px solid var(--line); padding: 5px 7px; text-align: left;
  vertical-align: top; }
th { background: var(--panel); font-weight: 600; }
td.n, th.n { text-align: right; white-space: nowrap; }
td img.close-up { width: 110px; height: 110px; display: block; }
td.where { min-width: 200px; }
.bar { display: inline-block; height: 10px; background: var(--accent); vertical-align: 0; }
.charts { display: grid; grid-template-columns: repeat(3, 1fr); gap: 12px; }
.chart { width: 100%; height: auto; font-size: 11px; }
.chart text { fill: var(--ink); }
.chart .unit { fill: var(--muted); }
.chart .grid { stroke: #e4e4e4; }
.chart .axis { stroke: #888; }
.spark path { fill: none; stroke: var(--accent); stroke-width: 1.5; }
.spark circle { fill: var(--accent); }
.spark line.base { stroke: #bbbbbb; stroke-width: 1; }
.spark text { fill: #555555; }
ul.warnings { margin: 0; padding-left: 1.1em; color: #8a4b00; }
.phone-only { display: none; }
footer { margin-top: 2em; color: var(--muted); font-size: 0.85em; }
@media screen and (max-width: 760px) {
  main { padding: 10px; }
  .cards { grid-template-columns: repeat(2, 1fr); }
  .charts { grid-template-columns: 1fr; }
  /* Each row a card: the cells stacked, each with its column's name, nothing to scroll. */
  table.cards-on-phone thead { display: none; }
  table.cards-on-phone, table.cards-on-phone tbody, table.cards-on-phone tr,
  table.cards-on-phone td { display: block; width: 100%; }
  table.cards-on-phone tr { border: 1px solid var(--line); border-radius: 6px; margin: 0 0 10px;
    padding: 4px 8px; }
  table.cards-on-phone td { border: none; padding: 3px 0; text-align: left; white-space: normal;
    min-width: 0; }
  table.cards-on-phone td[data-label]::before { content: attr(data-label) ": ";
    color: var(--muted); font-size: 0.9em; }
  table.cards-on-phone td.close-up-cell { float: right; margin-left: 8px; }
  .phone-only { display: inline; }
  td img.close-up { width: 96px; height: 96px; }
}
@page { size: A4; margin: 12mm; }
@media print {
  body { font-size: 10pt; -webkit-print-color-adjust: exact; print-color-adjust: exact; }
  main { max-width: none; padding: 0; }
  .cards { grid-template-columns: repeat(6, 1fr); }
  h2 { break-after: avoid; margin-top: 1.1em; }
  tr, figure, .card, .chart, .charts, details, .closing { break-inside: avoid; }
  figure img.map { max-height: 150mm; width: auto; max-width: 100%; }
  .table-wrap { overflow: visible; }
  /* The three charts side by side, a third of the page high at most. */
  .charts { grid-template-columns: repeat(3, 1fr); }
  .chart { max-height: 80mm; }
  td img.close-up { width: 80px; height: 80px; }
}
)css";

std::string Fixed(double value, int decimals) { return FormatNumber(value, decimals); }

std::string Count(std::size_t n) { return FormatNumber(static_cast<double>(n), 0); }

std::string Area(double m2) {
  return m2 >= 10000 ? Fixed(m2 / 10000, 2) + " ha" : Fixed(m2, 0) + " m²";
}

std::string Distance(double m) {
  return m >= 1000 ? Fixed(m / 1000, 2) + " km" : Fixed(m, 0) + " m";
}

std::string Date(double unix_s) { return FormatUtc(unix_s, "%Y-%m-%d %H:%M"); }

std::string Img(const cv::Mat& image, const std::string& alt, const char* css_class,
                const std::string& attributes = "") {
  const std::vector<unsigned char> png = EncodePng(image);
  return "<img class=\"" + std::string(css_class) + "\" src=\"data:image/png;base64," +
         Base64(png) + "\" width=\"" + std::to_string(image.cols) + "\" height=\"" +
         std::to_string(image.rows) + "\" alt=\"" + EscapeHtml(alt) + "\"" + attributes + ">";
}

// Short run labels for chart axes: the date, with the time when two runs share a day.
std::vector<std::string> RunLabels(const std::vector<RunFigures>& runs) {
  std::map<std::string, int> per_day;
  for (const RunFigures& run : runs) ++per_day[FormatUtc(run.start_time_s, "%d %b")];
  std::vector<std::string> labels;
  for (const RunFigures& run : runs) {
    const std::string day = FormatUtc(run.start_time_s, "%d %b");
    labels.push_back(per_day[day] > 1 ? FormatUtc(run.start_time_s, "%d %b %H:%M") : day);
  }
  return labels;
}

std::string ClassLabel(const std::string& class_name) {
  const ClassStyle style = StyleOf(class_name);
  return "<span class=\"swatch dot\" style=\"background:" + style.hex + "\"></span>" +
         EscapeHtml(style.label);
}

// "3 bottles, 1 can" most first.
std::string ClassList(const ClassCounts& counts) {
  std::vector<std::pair<std::string, int>> sorted(counts.begin(), counts.end());
  std::stable_sort(sorted.begin(), sorted.end(),
                   [](const auto& a, const auto& b) { return a.second > b.second; });
  std::string text;
  for (const auto& [name, count] : sorted) {
    if (!text.empty()) text += ", ";
    text += EscapeHtml(ClassCount(name, static_cast<std::size_t>(count)));
  }
  return text.empty() ? "none" : text;
}

std::string Location(const SiteReport& report, const HotspotFigures& h) {
  std::string text = FromTheDock(h.site_xy.x, h.site_xy.y, 1);
  if (report.frame.georeferenced()) {
    text += "<br><span class=\"muted\">EPSG:" + std::to_string(report.frame.epsg_code) + " E " +
            Fixed(h.crs.x, 1) + ", N " + Fixed(h.crs.y, 1) + "</span>";
  }
  if (h.wgs84) {
    char gps[96];
    std::snprintf(gps, sizeof gps, "%.6f° %c, %.6f° %c", std::abs(h.wgs84->lat_deg),
                  h.wgs84->lat_deg >= 0 ? 'N' : 'S', std::abs(h.wgs84->lon_deg),
                  h.wgs84->lon_deg >= 0 ? 'E' : 'W');
    text += "<br>GPS " + std::string(gps);
  }
  return text;
}

std::string Period(const SiteReport& report) {
  std::string text;
  if (report.from_time_s || report.to_time_s) {
    text = "Runs starting ";
    if (report.from_time_s) text += "on or after " + FormatUtc(*report.from_time_s, "%Y-%m-%d");
    if (report.from_time_s && report.to_time_s) text += " and ";
    if (report.to_time_s) text += "before " + FormatUtc(*report.to_time_s, "%Y-%m-%d");
    return text + " · ";
  }
  if (report.runs.empty()) return text;
  return FormatUtc(report.runs.front().start_time_s, "%Y-%m-%d") + " to " +
         FormatUtc(report.runs.back().start_time_s, "%Y-%m-%d") + " · ";
}

std::string NoHotspotsBecause(const SiteReport& report) {
  return report.items == 0 ? "the surveys found no litter."
                           : "no place has enough litter, surveyed often enough, to be one.";
}

void KeyFigures(const SiteReport& report, std::string& html) {
  const RunFigures* latest = report.runs.empty() ? nullptr : &report.runs.back();
  const auto card = [&](const std::string& value, const std::string& label) {
    html += "<div class=\"card\"><b>" + value + "</b><span>" + label + "</span></div>";
  };
  html += "<section class=\"cards\" aria-label=\"Key figures\">";
  card(Count(report.items), "litter items found");
  card(Count(report.runs.size()), report.runs.size() == 1 ? "survey run" : "survey runs");
  card(Area(report.surveyed_area_m2), "ground surveyed");
  card(Distance(report.length_m), "driven");
  card(latest ? Count(latest->new_items) : "–", "new in the latest run");
  card(Count(report.hotspots.size()), report.hotspots.size() == 1 ? "hotspot" : "hotspots");
  html += "</section>";

  html += "<p class=\"summary\">";
  if (report.min_confidence > 0.0) {
    html += "Counting only litter detected with a confidence of at least " +
            Fixed(100.0 * report.min_confidence, 0) + "&nbsp;%. ";
  }
  if (!report.hotspots.empty()) {
    const HotspotFigures& top = report.hotspots.front();
    html += "Clean first at <b>hotspot 1</b>, " + FromTheDock(top.site_xy.x, top.site_xy.y, 0) +
            ": " + Fixed(top.density_per_100m2, 1) + " items per 100 m² each survey, mostly " +
            EscapeHtml(StyleOf(top.dominant_class).many) + ". ";
  } else {
    html += "No hotspots: " + NoHotspotsBecause(report) + " ";
  }
  if (latest) {
    html += "The latest run (" + EscapeHtml(latest->name) + ", " + Date(latest->start_time_s) +
            ") found " + CountOf(latest->items_found, "item", "items") + ", " +
            Count(latest->new_items) + " of them new, on " + Area(latest->observed_area_m2) + " (" +
            FormatPercent(latest->coverage_fraction) + " of the surveyed ground).";
  }
  html += "</p>";
}

void MapSection(const SiteReport& report, const SiteMapFigure& figure, std::string& html) {
  html += "<section id=\"map\"><h2>Site map</h2><figure>";
  // The hotspot numbers' boxes on the image (x,y,w,h;...), for checks of the figure.
  std::string boxes;
  for (const cv::Rect& box : figure.label_boxes) {
    boxes += std::to_string(box.x) + "," + std::to_string(box.y) + "," + std::to_string(box.width) +
             "," + std::to_string(box.height) + ";";
  }
  html += Img(figure.map,
              "Map of " + report.site_name +
                  ": litter density in colour, items as dots, hotspots outlined and numbered",
              "map", " data-label-boxes=\"" + boxes + "\"");
  html +=
      "<figcaption class=\"legend\"><span>Litter density, items per 100 m² per survey: "
      "0<span class=\"ramp\"></span>" +
      Fixed(figure.peak_density_per_100m2, 1) + "</span>";
  html += "<span><span class=\"swatch\" style=\"background:#d7d7d7\"></span>not surveyed</span>";
  if (report.site_map) {
    html +=
        "<span><span class=\"swatch\" style=\"background:#eeeeee\"></span>mapped, not "
        "surveyed</span><span><span class=\"swatch\" style=\"background:#2d2d2d\"></span>"
        "trees, walls, fences</span>";
  }
  html +=
      "<span>◯ hotspot: within " + Fixed(report.bandwidth_m, 0) + " m of its densest places</span>";
  std::set<std::string> classes;
  for (const db::ItemRecord& item : report.heatmap.items) classes.insert(item.class_name);
  for (const std::string& name : classes) html += "<span>" + ClassLabel(name) + "</span>";
  html +=
      "</figcaption></figure><p class=\"muted\">North is up. Positions are in metres from "
      "the robot's dock";
  html += report.frame.georeferenced()
              ? " and in EPSG:" + std::to_string(report.frame.epsg_code) + "."
              : std::string(".");
  html +=
      " Density counts every time a survey finds an item, divided by how often the ground "
      "was surveyed, so often-surveyed paths do not look dirtier than they are.</p>";
  html += "</section>";
}

void HotspotSection(const SiteReport& report, const SiteMapFigure& figure, std::string& html) {
  html += "<section id=\"hotspots\"><h2>Where to clean first</h2>";
  if (report.hotspots.empty()) {
    html += "<p>No hotspots: " + NoHotspotsBecause(report) + "</p></section>";
    return;
  }
  html += "<p class=\"muted\">A hotspot is a place with at least " +
          CountOf(static_cast<std::size_t>(report.hotspot_min_items), "item", "items") +
          " within " + Fixed(report.bandwidth_m, 0) + " m, on ground " +
          (report.hotspot_min_surveys >= 2
               ? "at least " + Fixed(report.hotspot_min_surveys, 0) + " runs surveyed"
               : std::string("the run surveyed")) +
          "; dense places closer than " + Fixed(2 * report.bandwidth_m, 0) +
          " m are one hotspot. Ranked by litter density. Items nearby: its distinct items. "
          "Trend: the mean density each run found within that radius, oldest run first, from "
          "the first run's value (left) to the latest's (right); the grey line is zero.</p>";
  html +=
      "<div class=\"table-wrap\"><table id=\"hotspot-table\" "
      "class=\"cards-on-phone\"><thead><tr><th>#</th>"
      "<th>Close-up</th><th>Location</th><th class=\"n\">Density<br>per 100 m²</th>"
      "<th>Mostly</th><th>Items nearby</th><th>Trend</th></tr></thead><tbody>";
  for (std::size_t i = 0; i < report.hotspots.size(); ++i) {
    const HotspotFigures& h = report.hotspots[i];
    double peak = 0;
    for (const auto& v : h.density_by_run) peak = std::max(peak, v.value_or(0.0));
    html += "<tr><td class=\"n\"><b><span class=\"phone-only\">Hotspot </span>" +
            std::to_string(h.rank) + "</b></td><td class=\"close-up-cell\">" +
            Img(figure.close_ups[i], "Close-up of hotspot " + std::to_string(h.rank), "close-up") +
            "</td><td class=\"where\">" + Location(report, h) +
            "</td><td class=\"n\" data-label=\"Density per 100 m²\">" +
            Fixed(h.density_per_100m2, 1) + "</td><td data-label=\"Mostly\">" +
            ClassLabel(h.dominant_class) + "</td><td data-label=\"Items nearby\">" +
            ClassList(h.items_by_class) + "</td><td data-label=\"Trend\">" +
            Sparkline(h.density_by_run, peak, 96, 42) + "</td></tr>";
  }
  html += "</tbody></table></div></section>";
}

void ClassSection(const SiteReport& report, std::string& html) {
  html += "<section id=\"classes\"><h2>What litter</h2>";
  std::vector<std::pair<std::string, int>> sorted(report.items_by_class.begin(),
                                                  report.items_by_class.end());
  std::stable_sort(sorted.begin(), sorted.end(),
                   [](const auto& a, const auto& b) { return a.second > b.second; });
  const int most = sorted.empty() ? 1 : std::max(1, sorted.front().second);
  html +=
      "<div class=\"table-wrap\"><table id=\"class-table\"><thead><tr><th>Kind</th>"
      "<th class=\"n\">Items</th><th class=\"n\">Share</th><th></th></tr></thead><tbody>";
  for (const auto& [name, count] : sorted) {
    const double share =
        report.items > 0 ? static_cast<double>(count) / static_cast<double>(report.items) : 0;
    html += "<tr><td>" + ClassLabel(name) + "</td><td class=\"n\">" + std::to_string(count) +
            "</td><td class=\"n\">" + FormatPercent(share) +
            "</td><td><span class=\"bar\" style=\"width:" + std::to_string(160 * count / most) +
            "px\"></span></td></tr>";
  }
  html += "<tr><th>All litter</th><th class=\"n\">" + Count(report.items) +
          "</th><th class=\"n\">100 %</th><th></th></tr></tbody></table></div>";
  html +=
      "<p class=\"muted\">Distinct items: an item found again by later runs counts once. "
      "Per hotspot, see the table above.</p></section>";
}

void ChangeSection(const SiteReport& report, std::string& html) {
  html += "<section id=\"change\"><h2>Change over time</h2>";
  const std::vector<std::string> labels = RunLabels(report.runs);
  std::vector<double> fresh, still, area, rate;
  for (const RunFigures& run : report.runs) {
    fresh.push_back(static_cast<double>(run.new_items));
    still.push_back(static_cast<double>(run.items_still_there));
    area.push_back(run.observed_area_m2);
    rate.push_back(run.items_per_100m2);
  }
  html += "<div class=\"charts\">";
  html += StackedBarChart(labels,
                          {{"new", kNewColour, fresh}, {"still there", kStillThereColour, still}},
                          {"Litter items found per run", "items found", 360, 220, 0});
  html += StackedBarChart(labels, {{"area", kEffortColour, area}},
                          {"Ground surveyed per run", "m² surveyed (effort)", 360, 220, 0});
  html += StackedBarChart(
      labels, {{"per 100 m²", "#555555", rate}},
      {"Items found per 100 m² surveyed", "items per 100 m² surveyed", 360, 220, 1});
  html +=
      "</div><p class=\"muted\">A run that covers less ground finds fewer items without the "
      "park being cleaner: compare items per 100 m², not totals. <i>Gone</i>: items a run "
      "looked for where they were and did not find (picked up, or missed).</p>";
  html +=
      "<div class=\"table-wrap\"><table id=\"run-table\" "
      "class=\"cards-on-phone\"><thead><tr><th>Started (UTC)</th>"
      "<th>Run</th><th class=\"n\">Driven</th><th class=\"n\">Surveyed</th>"
      "<th class=\"n\">Coverage</th><th class=\"n\">Found</th><th class=\"n\">New</th>"
      "<th class=\"n\">Still there</th><th class=\"n\">Gone</th>"
      "<th class=\"n\">Per 100 m²</th></tr></thead><tbody>";
  for (const RunFigures& run : report.runs) {
    const auto cell = [&](const char* label, const std::string& value) {
      html += std::string("<td class=\"n\" data-label=\"") + label + "\">" + value + "</td>";
    };
    html +=
        "<tr><td>" + Date(run.start_time_s) + "</td><td><b>" + EscapeHtml(run.name) + "</b></td>";
    cell("Driven", Distance(run.length_m));
    cell("Surveyed", Area(run.observed_area_m2));
    cell("Coverage", FormatPercent(run.coverage_fraction));
    cell("Found", Count(run.items_found));
    cell("New", Count(run.new_items));
    cell("Still there", Count(run.items_still_there));
    cell("Gone", Count(run.items_gone));
    cell("Per 100 m²", Fixed(run.items_per_100m2, 2));
    html += "</tr>";
  }
  html += "</tbody></table></div></section>";
}

std::string Routines(const RunQuality& quality) {
  if (!quality.known || quality.scans == 0) return "unknown";
  std::string text;
  for (const auto& [name, count] : quality.routines) {
    if (count == 0) continue;
    if (!text.empty()) text += ", ";
    text += EscapeHtml(name) + " " + FormatPercent(static_cast<double>(count) / quality.scans);
  }
  return text;
}

// How sure we are where the robot was, in a phrase: by the share of its way that only the wheel
// odometry placed (the laser and the camera place the rest to centimetres).
std::string Certainty(const RunFigures& run) {
  const RunQuality& quality = run.quality;
  if (!quality.known || quality.scans == 0) return "not known (no reconstruction record)";
  const double share = quality.OdometryOnlyShare();
  std::string text;
  if (share > 0.05) {
    text = std::string("<b>") + (share > 0.2 ? "unsure" : "fairly sure") + "</b>: for " +
           FormatPercent(share) + " of the way only the wheels told where the robot was";
  } else {
    text =
        "<b>sure</b>: the laser or the camera placed " + FormatPercent(1 - share) + " of the way";
  }
  if (quality.loop_closures_accepted > 0) {
    text += "; " +
            CountOf(static_cast<std::size_t>(quality.loop_closures_accepted),
                    "return to a known place", "returns to known places") +
            " corrected the drift";
  }
  return text;
}

// A warning's kind: its text without the figures, so that "60 scans ..." in one run and "58
// scans ..." in the next are shown once.
std::string WarningKind(const std::string& warning) {
  std::string kind;
  for (const char c : warning) {
    const bool digit = c >= '0' && c <= '9';
    if (!digit || kind.empty() || kind.back() != '#') kind += digit ? '#' : c;
  }
  return kind;
}

void QualitySection(const SiteReport& report, std::string& html) {
  html += "<section id=\"quality\"><h2>Survey quality</h2>";
  html +=
      "<p class=\"muted\">How sure we are where the robot was on each run: litter is placed on "
      "the map by the robot's path, so an unsure path places litter less exactly.</p>";
  html += "<ul class=\"certainty\">";
  for (const RunFigures& run : report.runs) {
    html += "<li>" + EscapeHtml(run.name) + ": " + Certainty(run) + "</li>";
  }
  html += "</ul>";

  // Each warning once, with the runs it concerns.
  std::vector<std::pair<std::string, std::vector<std::string>>> warnings;  // text, runs
  std::map<std::string, std::size_t> index_of_kind;
  for (const RunFigures& run : report.runs) {
    for (const std::string& warning : run.warnings) {
      const auto [it, added] = index_of_kind.emplace(WarningKind(warning), warnings.size());
      if (added) warnings.push_back({warning, {}});
      warnings[it->second].second.push_back(run.name);
    }
  }
  if (!warnings.empty()) {
    html += "<ul class=\"warnings\">";
    for (const auto& [warning, runs] : warnings) {
      std::string names;
      for (const std::string& name : runs) names += (names.empty() ? "" : ", ") + name;
      html += "<li>" + EscapeHtml(warning) +
              (runs.size() == 1 ? " (run " : " (" + Count(runs.size()) + " runs: ") +
              EscapeHtml(names) + ")</li>";
    }
    html += "</ul>";
  }
  for (const std::string& warning : report.warnings) {
    html += "<p class=\"muted\">" + EscapeHtml(warning) + "</p>";
  }

  html +=
      "<details><summary>Technical details</summary><p class=\"muted\">The share of laser "
      "scans placed by each tracking routine (global scan matching, the key-frame buffer, the "
      "RGB-D camera, odometry alone), loop closures accepted of those found, and how well the "
      "run's map matched the site map.</p>";
  html +=
      "<div class=\"table-wrap\"><table id=\"quality-table\" "
      "class=\"cards-on-phone\"><thead><tr><th>Run</th>"
      "<th>Scans placed by</th><th class=\"n\">Loop closures</th>"
      "<th class=\"n\">Site-map match</th><th class=\"n\">Coverage</th></tr></thead><tbody>";
  for (const RunFigures& run : report.runs) {
    html += "<tr><td><b>" + EscapeHtml(run.name) + "</b></td><td data-label=\"Scans placed by\">" +
            Routines(run.quality) + "</td><td class=\"n\" data-label=\"Loop closures\">" +
            (run.quality.known ? std::to_string(run.quality.loop_closures_accepted) + " of " +
                                     std::to_string(run.quality.loop_closures_found)
                               : std::string("–")) +
            "</td><td class=\"n\" data-label=\"Site-map match\">" +
            (run.registration_quality ? FormatPercent(*run.registration_quality)
                                      : std::string("defines the map")) +
            "</td><td class=\"n\" data-label=\"Coverage\">" + FormatPercent(run.coverage_fraction) +
            "</td></tr>";
  }
  html += "</tbody></table></div></details></section>";
}

}  // namespace

std::string HtmlReport(const SiteReport& report, const SiteMapFigure& figure,
                       const HtmlReportOptions& options) {
  std::string html =
      "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">"
      "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">"
      "<meta http-equiv=\"Content-Security-Policy\" content=\"default-src 'none'; "
      "img-src data:; style-src 'unsafe-inline'\">"
      "<title>Litter report: " +
      EscapeHtml(report.site_name) + "</title><style>" + kStyle + "</style></head><body><main>";
  html += "<header><h1>Litter report: " + EscapeHtml(report.site_name) + "</h1><p class=\"sub\">" +
          Period(report) + CountOf(report.runs.size(), "survey run", "survey runs") +
          " · generated " + EscapeHtml(options.generated_utc) + " UTC</p></header>";
  KeyFigures(report, html);
  MapSection(report, figure, html);
  HotspotSection(report, figure, html);
  ClassSection(report, html);
  // Printed, the last two sections stay together: the last page is never a stub of a few lines.
  html += "<div class=\"closing\">";
  ChangeSection(report, html);
  QualitySection(report, html);
  html += "</div>";
  html += "<footer>Made by littermap " + EscapeHtml(options.version) +
          ". The same figures are in report.json; the site database (a GeoPackage) and the "
          "density GeoTIFFs of <code>littermap heatmap</code> open in QGIS.</footer>";
  html += "</main></body></html>\n";
  return html;
}

void WriteHtmlReport(const std::filesystem::path& file, const SiteReport& report,
                     const SiteMapFigure& figure, const HtmlReportOptions& options) {
  WriteFileAtomically(file, HtmlReport(report, figure, options));
}

}  // namespace littermap::reports
